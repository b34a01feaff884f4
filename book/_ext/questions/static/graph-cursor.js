/* The graph cursor: a question's graph read without sight, or by a tap on a phone. Beside each
 * graph (button.q-graph-open, whose data-cursor the build writes: both axes, the line's reading
 * at every half small square of time, the plot area; physics_figures/figures/question_graph.py,
 * cursor_data) a slider moves a cursor along the time axis: Left and Right one small square,
 * Shift with them one large square, Home and End to the ends. Each step says the reading at
 * the cursor, "t = 1.5 s, v = 12.5 m s⁻¹", through ONE polite live region: both values to the
 * nearest half small square, what a student with a ruler reads, and no more. In the enlarged
 * view (graph-view.js) a tap or click on the graph moves the cursor there and draws it: a line
 * up from the time axis, one across to the value axis, and above the graph the reading.
 * The view writes that reading only on request (Show the reading) or once the question's
 * parts read off the graph have values typed: a sighted student reads the graph first.
 * New numbers (questions.js) writes the new variant's data-cursor: the cursor starts again. */
(function (root) {
  "use strict";

  var Notation = root.Notation;
  var said; // the one live region: under body, or inside the enlarged view while it is open
  var states = new WeakMap(); // button.q-graph-open -> {text, data, index, slider}
  var shown = null; // {opener, dialog}: the enlarged view and the graph it shows

  function liveRegion() {
    if (!said) {
      said = document.createElement("p");
      said.className = "q-graph-said";
      said.setAttribute("aria-live", "polite");
      said.setAttribute("aria-atomic", "true");
      document.body.appendChild(said);
    }
    return said;
  }

  /* The opener's cursor; a new data-cursor (New numbers) starts it again at time 0. */
  function stateOf(opener) {
    var text = opener.getAttribute("data-cursor") || "";
    var state = states.get(opener);
    if (!state || state.text !== text) {
      var data = null;
      try {
        data = JSON.parse(text);
      } catch {
        data = null; // a graph without a cursor's data: the slider says so
      }
      // revealed: the student asked for the view's reading of this graph (Show the reading)
      state = { text: text, data: data, index: null, slider: state ? state.slider : null, revealed: false };
      states.set(opener, state);
    }
    return state;
  }

  function halfSquares(data) {
    return data.readings.length - 1;
  }

  function timeAt(data, index) {
    return data.time.min + (index * data.time.square) / 2;
  }

  /* A value as a ruler gives it: the places of a small square on its lines, of half a square
   * between them (12 or 12.5 on squares of 1; 1.20 or 1.225 on squares of 0.05). On an axis
   * labelled in a power of ten ("p / 10⁵ N s", axis.power 5, places counted in its labels'
   * numbers) the same figures in the book's notation: 1.15 × 10⁵ N s, 50 000 N s. */
  function written(axis, x) {
    var squares = (x - axis.min) / axis.square;
    var onLine = Math.abs(squares - Math.round(squares)) < 1e-6;
    var places = axis.places[onLine ? 0 : 1];
    if (!axis.power) return Notation.formatQuantity(x, null, axis.unit, { decimals: places });
    if (x === 0) return Notation.formatQuantity(0, 1, axis.unit);
    var lead = Math.floor(Math.log10(Math.abs(x)) + 1e-9);
    return Notation.formatQuantity(x, Math.max(1, lead - axis.power + places + 1), axis.unit);
  }

  function readingText(data, index) {
    var time = data.time.symbol + " = " + written(data.time, timeAt(data, index));
    var value = data.readings[index];
    if (value === null) return time + ", no line drawn here";
    return time + ", " + data.value.symbol + " = " + written(data.value, value);
  }

  function announce(text) {
    var region = liveRegion();
    // the same words again (a key pressed at an end) are still said: a region speaks on change
    region.textContent = region.textContent === text ? text + "\u00a0" : text;
  }

  function moveTo(opener, index, edge) {
    var state = stateOf(opener),
      data = state.data;
    if (!data) return;
    var last = halfSquares(data);
    var next = Math.max(0, Math.min(last, index));
    var atEnd = next !== index || (edge && state.index === next);
    state.index = next;
    var text = readingText(data, next);
    if (atEnd) text = (next === 0 ? "Start of the time axis: " : "End of the time axis: ") + text;
    if (state.slider) showOnSlider(state);
    if (shown && shown.opener === opener) drawMarker(shown.dialog, opener);
    announce(text);
  }

  function showOnSlider(state) {
    var slider = state.slider,
      data = state.data;
    if (!data) {
      slider.querySelector(".q-graph-reading").textContent = "no readings for this graph";
      return;
    }
    var index = state.index === null ? 0 : state.index;
    slider.setAttribute("aria-valuemin", String(data.time.min));
    slider.setAttribute("aria-valuemax", String(data.time.max));
    slider.setAttribute("aria-valuenow", String(timeAt(data, index)));
    slider.setAttribute("aria-valuetext", data.time.symbol + " = " + written(data.time, timeAt(data, index)));
    slider.querySelector(".q-graph-reading").textContent =
      state.index === null ? "press → to read the graph" : readingText(data, index);
  }

  var HINT =
    "← and → move the cursor one small square along the time axis, Shift with them one large " +
    "square, Home and End to the ends; each reading is read out.";

  var sliders = 0; // each slider's hint gets its own id
  function addSlider(opener) {
    var number = sliders++;
    var box = document.createElement("div");
    box.className = "q-graph-cursor";
    box.innerHTML =
      '<div class="q-graph-slider" role="slider" tabindex="0" aria-label="Graph cursor" ' +
      'aria-orientation="horizontal" aria-describedby="q-graph-hint-' +
      number +
      '">Graph cursor: <span class="q-graph-reading"></span></div>' +
      '<p class="q-graph-keys" id="q-graph-hint-' +
      number +
      '"></p>';
    box.querySelector(".q-graph-keys").textContent = HINT;
    opener.parentNode.insertBefore(box, opener.nextSibling);
    var state = stateOf(opener);
    state.slider = box.querySelector(".q-graph-slider");
    showOnSlider(state);
    state.slider.addEventListener("keydown", function (event) {
      var current = stateOf(opener);
      if (!current.data) return;
      var here = current.index === null ? 0 : current.index;
      var large = Math.round((2 * current.data.time.large) / current.data.time.square);
      var step = event.shiftKey ? large : 2; // in half squares
      var keys = {
        ArrowRight: here + step,
        ArrowUp: here + step,
        ArrowLeft: here - step,
        ArrowDown: here - step,
        PageUp: here + large,
        PageDown: here - large,
        Home: 0,
        End: halfSquares(current.data),
      };
      if (!(event.key in keys) || event.altKey || event.ctrlKey || event.metaKey) return;
      event.preventDefault();
      moveTo(opener, keys[event.key], true);
    });
    // New numbers writes a new data-cursor: the slider shows the new graph's axis at once
    new MutationObserver(function () {
      showOnSlider(stateOf(opener));
      if (shown && shown.opener === opener) drawMarker(shown.dialog, opener);
    }).observe(opener, { attributes: true, attributeFilter: ["data-cursor"] });
  }

  /* ------------------------------------------------------------- the enlarged view */

  function markerParts(dialog) {
    var frame = dialog.querySelector(".q-graph-frame");
    var across = frame.querySelector(".q-graph-marker-time");
    if (!across) {
      frame.insertAdjacentHTML(
        "beforeend",
        '<span class="q-graph-marker-time" aria-hidden="true" hidden></span>' +
          '<span class="q-graph-marker-value" aria-hidden="true" hidden></span>',
      );
    }
    return {
      time: frame.querySelector(".q-graph-marker-time"),
      value: frame.querySelector(".q-graph-marker-value"),
      reading: dialog.querySelector(".q-graph-reading-large"),
      show: dialog.querySelector(".q-graph-show-reading"),
    };
  }

  /* The reading is the student's to take: the view writes it only when asked (Show the
   * reading) or once every part of the question that is read off the graph has a value typed
   * (a sighted student practises reading to half a square first). */
  function readingOffered(opener, state) {
    if (state.revealed) return true;
    var question = opener.closest("section.q");
    var parts = question ? question.querySelectorAll("fieldset.q-part[data-kind]") : [];
    var typed = Array.prototype.filter
      .call(parts, function (part) {
        return !!root.QuestionKinds.get(part.getAttribute("data-kind")).readsGraph;
      })
      .map(function (part) {
        return part.querySelector("input.q-value");
      });
    return (
      typed.length > 0 &&
      Array.prototype.every.call(typed, function (box) {
        return box.value.trim() !== "";
      })
    );
  }

  function readingLine(data, state, offered) {
    if (!data) return "";
    if (state.index === null) return offered ? "Tap the graph to read it." : "Tap the graph to place the cursor.";
    if (!offered) return "Read the graph where the cursor crosses it.";
    return readingText(data, state.index);
  }

  function percent(fraction) {
    return fraction * 100 + "%";
  }

  function drawMarker(dialog, opener) {
    var state = stateOf(opener),
      parts = markerParts(dialog),
      data = state.data;
    var hide = !data || state.index === null;
    var offered = !!data && readingOffered(opener, state);
    parts.time.hidden = parts.value.hidden = hide;
    parts.reading.textContent = readingLine(data, state, offered);
    if (parts.show) parts.show.hidden = !data || offered;
    if (hide) return;
    var area = data.area,
      along = state.index / halfSquares(data);
    var x = area[0] + along * (area[2] - area[0]);
    parts.time.style.left = percent(x);
    parts.time.style.top = percent(area[1]);
    parts.time.style.height = percent(area[3] - area[1]);
    var value = data.readings[state.index];
    parts.value.hidden = value === null;
    if (value === null) return;
    var y = area[1] + ((data.value.max - value) / (data.value.max - data.value.min)) * (area[3] - area[1]);
    parts.value.style.top = percent(y);
    parts.value.style.left = percent(area[0]);
    parts.value.style.width = percent(x - area[0]);
  }

  /* A tap or click on the enlarged graph: the cursor to the nearest half small square of time. */
  function tapped(event) {
    if (!shown) return;
    var image = shown.dialog.querySelector("img.q-graph-large");
    var state = stateOf(shown.opener);
    if (!state.data || !event.target.closest(".q-graph-frame")) return;
    var box = image.getBoundingClientRect(),
      area = state.data.area;
    var along = ((event.clientX - box.left) / box.width - area[0]) / (area[2] - area[0]);
    moveTo(shown.opener, Math.round(along * halfSquares(state.data)), false);
  }

  /* Show the reading: the view writes the reading at the cursor from now on, for this graph. */
  function reveal() {
    if (!shown) return;
    stateOf(shown.opener).revealed = true;
    drawMarker(shown.dialog, shown.opener);
    shown.dialog.querySelector(".q-graph-pane").focus(); // the button is gone: focus stays in the view
  }

  function opened(event) {
    var dialog = event.detail.dialog;
    shown = { opener: event.target, dialog: dialog };
    if (!dialog.hasAttribute("data-cursor-ready")) {
      dialog.setAttribute("data-cursor-ready", "");
      dialog.querySelector(".q-graph-frame").addEventListener("click", tapped);
      var show = dialog.querySelector(".q-graph-show-reading");
      if (show) show.addEventListener("click", reveal);
      // the region speaks inside the modal view (the page behind it is inert), then returns
      dialog.addEventListener("close", function () {
        shown = null;
        document.body.appendChild(liveRegion());
      });
    }
    dialog.appendChild(liveRegion());
    drawMarker(dialog, event.target);
  }

  function start() {
    liveRegion();
    Array.prototype.forEach.call(document.querySelectorAll("button.q-graph-open[data-cursor]"), function (opener) {
      addSlider(opener);
    });
    document.addEventListener("q-graph-opened", opened);
  }

  // A page that draws its questions itself (the mock test) gives each graph its cursor so.
  root.GraphCursor = { add: addSlider };

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
