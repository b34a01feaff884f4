/* The enlarged view of a question's graph: a tap, a click or Enter on the graph (a button,
 * button.q-graph-open, written by form.py around img.q-graph) opens the same SVG in a
 * full-screen <dialog class="q-graph-view">, zoomed until half a small square is big enough
 * to read a value from, with − and + to zoom, the browser's own pinch-zoom, and Close or
 * Escape to return to the graph's button. The button's data-square gives a small square's
 * width and height as fractions of the image's width (physics_figures/figures/question_graph.py,
 * small_square). No library: the SVG stays sharp at any zoom. Opening it dispatches
 * "q-graph-opened" on the graph's button (detail.dialog): the graph cursor (graph-cursor.js)
 * draws its marker in .q-graph-frame and writes its reading in .q-graph-reading-large. */
(function () {
  "use strict";

  // Half a small square is drawn at least this many CSS px when the view opens: 6 is what a
  // reading to half a square needs on a 390 px phone (issue 25); the rest is room for rounding.
  var READ_HALF_SQUARE_PX = 6.5;
  var STEP = 1.25; // each press of − or + zooms by this factor
  var MOST = 8; // at most this many times the screen's width

  var dialog, pane, image, zoomOut, zoomText, opener;
  var fitWidth = 0,
    zoom = 1;

  function build() {
    dialog = document.createElement("dialog");
    dialog.className = "q-graph-view";
    dialog.setAttribute("aria-label", "The graph, enlarged");
    dialog.innerHTML =
      '<div class="q-graph-bar">' +
      '<button type="button" class="q-graph-out" aria-label="Zoom out">−</button>' +
      '<span class="q-graph-zoom" aria-live="polite"></span>' +
      '<button type="button" class="q-graph-in" aria-label="Zoom in">+</button>' +
      '<button type="button" class="q-graph-close">Close</button>' +
      "</div>" +
      // the graph cursor's reading (graph-cursor.js): a tap on the graph moves the cursor there
      '<p class="q-graph-reading-large"></p>' +
      '<div class="q-graph-pane" tabindex="0" role="group" aria-label="The graph: scroll or drag to move across it">' +
      '<div class="q-graph-frame"><img class="q-graph-large" alt=""></div></div>';
    document.body.appendChild(dialog);
    pane = dialog.querySelector(".q-graph-pane");
    image = dialog.querySelector(".q-graph-large");
    zoomOut = dialog.querySelector(".q-graph-out");
    zoomText = dialog.querySelector(".q-graph-zoom");
    zoomOut.addEventListener("click", function () {
      setZoom(zoom / STEP);
    });
    dialog.querySelector(".q-graph-in").addEventListener("click", function () {
      setZoom(zoom * STEP);
    });
    dialog.querySelector(".q-graph-close").addEventListener("click", function () {
      dialog.close();
    });
    dialog.addEventListener("keydown", function (event) {
      if (event.key === "+" || event.key === "=") setZoom(zoom * STEP);
      else if (event.key === "-") setZoom(zoom / STEP);
      else return;
      event.preventDefault();
    });
    // Escape (the dialog's own cancel) and Close both end here: back to the graph's button
    dialog.addEventListener("close", function () {
      if (opener) opener.focus();
    });
  }

  /* The zoom, as a multiple of the screen's width, that draws half the smaller side of a
   * small square READ_HALF_SQUARE_PX wide. */
  function readingZoom(button) {
    var sides = (button.getAttribute("data-square") || "").split(/\s+/).map(Number);
    var smallest = Math.min.apply(
      null,
      sides.filter(function (side) {
        return side > 0;
      }),
    );
    if (!isFinite(smallest) || !fitWidth) return 1;
    return Math.max(1, (2 * READ_HALF_SQUARE_PX) / (smallest * fitWidth));
  }

  /* Zoom about the middle of what is in view, so the part being read stays in view. */
  function setZoom(next) {
    var middleX = (pane.scrollLeft + pane.clientWidth / 2) / (pane.scrollWidth || 1),
      middleY = (pane.scrollTop + pane.clientHeight / 2) / (pane.scrollHeight || 1);
    zoom = Math.min(MOST, Math.max(1, next));
    image.style.width = Math.floor(fitWidth * zoom) + "px";
    pane.scrollLeft = middleX * pane.scrollWidth - pane.clientWidth / 2;
    pane.scrollTop = middleY * pane.scrollHeight - pane.clientHeight / 2;
    zoomOut.disabled = zoom <= 1;
    zoomText.textContent = "Zoom " + Math.round(zoom * 100) + " %";
  }

  function open(button) {
    if (!dialog) build();
    opener = button;
    var graph = button.querySelector("img.q-graph");
    image.src = graph.currentSrc || graph.src;
    image.alt = graph.alt;
    dialog.showModal();
    // the full width of the screen, inside the pane's padding
    var style = getComputedStyle(pane);
    fitWidth = pane.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight);
    zoom = 1;
    setZoom(readingZoom(button));
    pane.scrollLeft = 0;
    pane.scrollTop = 0;
    // the graph cursor draws its marker here (graph-cursor.js)
    button.dispatchEvent(new CustomEvent("q-graph-opened", { bubbles: true, detail: { dialog: dialog } }));
  }

  document.addEventListener("click", function (event) {
    var button = event.target.closest && event.target.closest("button.q-graph-open");
    if (button) open(button);
  });
})();
