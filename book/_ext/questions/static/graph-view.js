/* The enlarged view of a question's graph: a tap, a click or Enter on the graph (a button,
 * button.q-graph-open, written by form.py around img.q-graph) opens the same SVG in a
 * full-screen <dialog class="q-graph-view">, as wide as the screen (on a wide screen, as
 * tall as the view), zoomed until half a small square is big enough to read a value from,
 * scrolled as near the middle of the plot as keeps both axes' numbers in view, with − and +
 * to zoom, the browser's own pinch-zoom, and Close or Escape to return to the graph's button. The button's data-square gives a small square's
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
    aspect = 0,
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
      // the graph cursor's reading (graph-cursor.js): a tap on the graph moves the cursor there,
      // and the reading shows on request or once the question's readings are typed
      '<div class="q-graph-read"><p class="q-graph-reading-large"></p>' +
      '<button type="button" class="q-graph-show-reading" hidden>Show the reading</button></div>' +
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
    // the height too, so the view can be scrolled before the image has loaded
    image.style.height = aspect > 0 ? Math.floor(fitWidth * zoom * aspect) + "px" : "auto";
    pane.scrollLeft = middleX * pane.scrollWidth - pane.clientWidth / 2;
    pane.scrollTop = middleY * pane.scrollHeight - pane.clientHeight / 2;
    zoomOut.disabled = zoom <= 1;
    zoomText.textContent = "Zoom " + Math.round(zoom * 100) + " %";
  }

  /* The graph's height over its width, from the graph on the page (the same SVG), or 0. */
  function aspectOf(graph) {
    var box = graph.getBoundingClientRect();
    if (box.width > 0 && box.height > 0) return box.height / box.width;
    return graph.naturalWidth > 0 ? graph.naturalHeight / graph.naturalWidth : 0;
  }

  /* From the graph cursor's data (question_graph.py, cursor_data): the plot area (left, top,
   * right, bottom) and where the axes' numbers end (left of the value axis's, foot of the time
   * axis's), as fractions of the image; else where a question's graph puts them, near enough. */
  function layoutOf(button) {
    try {
      var data = JSON.parse(button.getAttribute("data-cursor") || "null");
      if (data && data.area && data.numbers) return { area: data.area, numbers: data.numbers };
    } catch {
      // no cursor's data: the usual places
    }
    return { area: [0.2, 0.05, 0.95, 0.85], numbers: [0.05, 0.92] };
  }

  /* Scroll as near the middle of the plot as keeps both axes' numbers in view: the value
   * axis's at the left, the time axis's at the foot. A graph narrower than the pane stands in
   * its middle (questions.css). */
  function place(button) {
    var layout = layoutOf(button),
      area = layout.area,
      box = image.getBoundingClientRect(),
      style = getComputedStyle(pane),
      width = pane.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight),
      height = pane.clientHeight - parseFloat(style.paddingBottom),
      margin = 4; // CSS px of paper beyond the numbers
    var inset = parseFloat(style.paddingLeft); // the image's place in the pane's scrolled content
    var left = inset + ((area[0] + area[2]) / 2) * box.width - width / 2;
    var top = ((area[1] + area[3]) / 2) * box.height - height / 2;
    pane.scrollLeft = Math.max(0, Math.min(left, inset + layout.numbers[0] * box.width - margin));
    pane.scrollTop = Math.max(0, top, layout.numbers[1] * box.height + margin - height);
  }

  function open(button) {
    if (!dialog) build();
    opener = button;
    var graph = button.querySelector("img.q-graph");
    image.src = graph.currentSrc || graph.src;
    image.alt = graph.alt;
    aspect = aspectOf(graph);
    dialog.showModal();
    // the graph cursor writes its line above the graph first (graph-cursor.js): then the pane's size is final
    button.dispatchEvent(new CustomEvent("q-graph-opened", { bubbles: true, detail: { dialog: dialog } }));
    // the pane's width inside its padding, or less on a wide screen: the whole graph in its height
    var style = getComputedStyle(pane);
    fitWidth = pane.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight);
    var fitHeight = pane.clientHeight - parseFloat(style.paddingTop) - parseFloat(style.paddingBottom);
    if (aspect > 0) fitWidth = Math.min(fitWidth, Math.floor(fitHeight / aspect));
    zoom = 1;
    setZoom(readingZoom(button));
    place(button);
  }

  document.addEventListener("click", function (event) {
    var button = event.target.closest && event.target.closest("button.q-graph-open");
    if (button) open(button);
  });
})();
