/* A sketch part's pad: the student draws a line on the printed axes by pointer or touch, or
 * builds it from segments by keyboard (a start value, then rising, falling or level, straight,
 * steeper or less steep, and steps), each step announced. Both make one line, [[t, y], ...] in
 * the axes' own units, which the sketch kind marks (question-kinds/sketch.js). Loaded only on
 * pages that have a sketch part. */
(function (root) {
  "use strict";

  var SVG = "http://www.w3.org/2000/svg";
  // Points along a curved segment, as physics_figures/bank/sketches.py _curve draws one.
  var CURVE_STEPS = 12;
  // A pen must move this far (SVG units) before the next point is kept.
  var MIN_MOVE = 1.5;

  function numbers(text) {
    return String(text || "")
      .trim()
      .split(/\s+/)
      .map(Number);
  }

  /* Between the SVG's plot area (data-plot: left top right bottom, in its units) and the axes'
   * ranges (data-t, data-y). */
  function mapping(svg) {
    var plot = numbers(svg.getAttribute("data-plot")),
      t = numbers(svg.getAttribute("data-t")),
      y = numbers(svg.getAttribute("data-y"));
    return {
      toGraph: function (x, v) {
        return [
          t[0] + ((x - plot[0]) / (plot[2] - plot[0])) * (t[1] - t[0]),
          y[0] + ((plot[3] - v) / (plot[3] - plot[1])) * (y[1] - y[0]),
        ];
      },
      toBox: function (point) {
        return [
          plot[0] + ((point[0] - t[0]) / (t[1] - t[0])) * (plot[2] - plot[0]),
          plot[3] - ((point[1] - y[0]) / (y[1] - y[0])) * (plot[3] - plot[1]),
        ];
      },
      t: t,
      y: y,
    };
  }

  function rounded(value) {
    return Math.round(value * 1e6) / 1e6;
  }

  // A segment from (t0, y0) to (t1, y1): straight, "steeper" (gradient grows) or "less" steep.
  function segment(from, to, shape) {
    if (shape !== "steeper" && shape !== "less") return [to];
    var out = [];
    for (var i = 1; i <= CURVE_STEPS; i++) {
      var u = i / CURVE_STEPS,
        share = shape === "steeper" ? u * u : 1 - (1 - u) * (1 - u);
      out.push([rounded(from[0] + (to[0] - from[0]) * u), rounded(from[1] + (to[1] - from[1]) * share)]);
    }
    return out;
  }

  var SHAPE_WORDS = { straight: "straight", steeper: "getting steeper", less: "getting less steep" };

  /* One pad (pad state s): its axes (svg, map), the y unit, the status line that says what
   * happened, the line drawn (points [t, y]), its history for Undo, and the polyline drawn. */
  function say(s, text) {
    if (s.status) s.status.textContent = text;
  }

  // a point as announced: a value within a thousandth of its axis of zero is zero
  function where(s, point) {
    var near = function (v, range) {
      return Math.abs(v) < (range[1] - range[0]) / 1000 ? 0 : v;
    };
    return "t = " + fmt(near(point[0], s.map.t)) + " s, " + fmt(near(point[1], s.map.y)) + " " + s.unit;
  }

  function renderLine(s) {
    s.drawn.setAttribute(
      "points",
      s.line
        .map(function (point) {
          var p = s.map.toBox(point);
          return Math.round(p[0] * 10) / 10 + "," + Math.round(p[1] * 10) / 10;
        })
        .join(" "),
    );
  }

  function lineChanged(s) {
    renderLine(s);
    if (s.options && s.options.onChange) s.options.onChange(s.line.slice());
  }

  function remember(s) {
    s.history.push(s.line.slice());
  }

  // What the page asks of a pad: its line, set it, Undo and Clear.
  function padApi(s) {
    return {
      line: function () {
        return s.line.slice();
      },
      set: function (points) {
        s.line = (points || []).map(function (p) {
          return [Number(p[0]), Number(p[1])];
        });
        s.history = [];
        renderLine(s);
      },
      undo: function () {
        if (!s.history.length) return say(s, "Nothing to undo.");
        s.line = s.history.pop();
        lineChanged(s);
        say(
          s,
          s.line.length
            ? "Undone. The line now ends at " + where(s, s.line[s.line.length - 1]) + "."
            : "Undone: no line.",
        );
      },
      clear: function () {
        if (s.line.length) remember(s);
        s.line = [];
        lineChanged(s);
        say(s, "Line cleared.");
      },
    };
  }

  // A stroke of the pointer: a new stroke redraws the line from where it starts, left to right.
  function strokes(s) {
    return {
      begin: function (point) {
        remember(s);
        s.line = s.line.filter(function (p) {
          return p[0] < point[0];
        });
        s.line.push(point);
        renderLine(s);
      },
      move: function (point) {
        var last = s.line[s.line.length - 1];
        if (point[0] >= last[0]) {
          s.line.push(point);
          renderLine(s);
        }
      },
      end: function () {
        lineChanged(s);
        if (s.line.length)
          say(s, "Line drawn from " + where(s, s.line[0]) + " to " + where(s, s.line[s.line.length - 1]) + ".");
      },
    };
  }

  function addSegment(s, kind, shape, until, to) {
    if (!s.line.length) s.line = [[s.map.t[0], 0]];
    var from = s.line[s.line.length - 1];
    var problem = segmentProblem(kind, from, until, to, s.map);
    if (problem) return say(s, problem);
    remember(s);
    var end = kind === "level" ? [until, from[1]] : kind.indexOf("step") === 0 ? [from[0], to] : [until, to];
    s.line = s.line.concat(segment(from, end, kind === "level" || kind.indexOf("step") === 0 ? "straight" : shape));
    lineChanged(s);
    var words = kind.indexOf("step") === 0 ? kind.replace("-", " ") : kind;
    if (kind === "rising" || kind === "falling") words += ", " + SHAPE_WORDS[shape];
    say(s, "Added " + words + ", from " + where(s, from) + " to " + where(s, end) + ".");
  }

  function attach(box, options) {
    var svg = box.querySelector("svg.q-sketch-axes");
    var s = {
      svg: svg,
      map: mapping(svg),
      unit: box.getAttribute("data-unit") || "",
      status: box.querySelector(".q-sketch-status"),
      options: options,
      line: [],
      history: [],
      drawn: document.createElementNS(SVG, "polyline"),
    };
    s.drawn.setAttribute("class", "q-sketch-line");
    s.drawn.setAttribute("fill", "none");
    svg.appendChild(s.drawn);

    var pad = padApi(s);
    drawing(svg, s.map, strokes(s));
    keyboard(box, s.map, {
      start: function (value) {
        remember(s);
        s.line = [[s.map.t[0], value]];
        lineChanged(s);
        say(s, "The line starts at " + where(s, s.line[0]) + ".");
      },
      add: function (kind, shape, until, to) {
        return addSegment(s, kind, shape, until, to);
      },
    });
    buttons(box, pad);
    return pad;
  }

  // Why a segment cannot be added, in words, or "" when it can.
  function segmentProblem(kind, from, until, to, map) {
    var step = kind.indexOf("step") === 0;
    if (!step && !(until > from[0])) return "Give a time after t = " + fmt(from[0]) + " s for the segment to run to.";
    if (!step && until > map.t[1]) return "The time axis ends at t = " + fmt(map.t[1]) + " s.";
    if (kind === "level") return "";
    if (!isFinite(to)) return "Give the value the segment goes to.";
    if (to < map.y[0] || to > map.y[1]) return "The axis runs from " + fmt(map.y[0]) + " to " + fmt(map.y[1]) + ".";
    var up = kind === "rising" || kind === "step-up";
    if (up ? !(to > from[1]) : !(to < from[1])) {
      return "A " + kind.replace("-", " ") + " segment must go " + (up ? "up" : "down") + " from " + fmt(from[1]) + ".";
    }
    return "";
  }

  // A time or value as it is announced: as the book writes it, to 3 significant figures.
  function fmt(value) {
    return value === 0 ? "0" : root.Notation.formatNumber(value, 3);
  }

  // Pointer Events on the axes: one stroke from pointerdown to pointerup, in graph units.
  function drawing(svg, map, on) {
    var active = false,
      lastBox = null;
    function boxPoint(event) {
      var matrix = svg.getScreenCTM().inverse();
      var p = new DOMPoint(event.clientX, event.clientY).matrixTransform(matrix);
      return [p.x, p.y];
    }
    function graphPoint(p) {
      var g = map.toGraph(p[0], p[1]);
      return [
        rounded(Math.min(Math.max(g[0], map.t[0]), map.t[1])),
        rounded(Math.min(Math.max(g[1], map.y[0]), map.y[1])),
      ];
    }
    svg.addEventListener("pointerdown", function (event) {
      if (event.button !== 0) return;
      active = true;
      svg.setPointerCapture(event.pointerId);
      lastBox = boxPoint(event);
      on.begin(graphPoint(lastBox));
      event.preventDefault();
    });
    svg.addEventListener("pointermove", function (event) {
      if (!active) return;
      var p = boxPoint(event);
      if (Math.hypot(p[0] - lastBox[0], p[1] - lastBox[1]) < MIN_MOVE) return;
      lastBox = p;
      on.move(graphPoint(p));
    });
    function stop() {
      if (!active) return;
      active = false;
      on.end();
    }
    svg.addEventListener("pointerup", stop);
    svg.addEventListener("pointercancel", stop);
  }

  function keyboard(box, map, on) {
    var field = function (name) {
      return box.querySelector(".q-sketch-" + name);
    };
    var kind = field("kind"),
      shape = field("shape");
    function sync() {
      var curved = kind.value === "rising" || kind.value === "falling";
      shape.disabled = !curved;
      field("until").disabled = kind.value.indexOf("step") === 0;
      field("to").disabled = kind.value === "level";
    }
    kind.addEventListener("change", sync);
    sync();
    field("set-start").addEventListener("click", function () {
      on.start(Number(field("start").value) || 0);
    });
    field("add").addEventListener("click", function () {
      on.add(kind.value, shape.value, Number(field("until").value), Number(field("to").value));
    });
    // Enter in a box adds what it is for (it would otherwise submit the form: Check)
    [
      ["start", "set-start"],
      ["until", "add"],
      ["to", "add"],
    ].forEach(function (pair) {
      field(pair[0]).addEventListener("keydown", function (event) {
        if (event.key !== "Enter") return;
        event.preventDefault();
        field(pair[1]).click();
      });
    });
  }

  function buttons(box, pad) {
    box.querySelector(".q-sketch-undo").addEventListener("click", pad.undo);
    box.querySelector(".q-sketch-clear").addEventListener("click", pad.clear);
  }

  /* A sketch part's fieldset holds one pad, made when the page starts (or on first use); a
   * variant with other numbers brings its own axes (the kind, question-kinds/sketch.js, asks). */
  function padOf(box) {
    if (!box.sketchPad) box.sketchPad = attach(box.querySelector(".q-sketch-pad"), { onChange: changed(box) });
    return box.sketchPad;
  }
  function changed(box) {
    return function () {
      // the form keeps the answer as it keeps a typed one (questions.js listens for input)
      box.dispatchEvent(new Event("input", { bubbles: true }));
    };
  }
  function relabel(box, part) {
    var holder = box.querySelector(".q-sketch-draw");
    if (!part.svg || !holder) return;
    holder.innerHTML = part.svg;
    box.sketchPad = null;
    padOf(box);
  }

  var api = { attach: attach, segment: segment, segmentProblem: segmentProblem, padOf: padOf, relabel: relabel };
  if (typeof module === "object" && module.exports) module.exports = api;
  else {
    // every sketch part's pad is ready for the pen from the start
    var ready = function () {
      Array.prototype.forEach.call(document.querySelectorAll(".q-sketch-pad"), function (pad) {
        padOf(pad.closest("fieldset.q-part"));
      });
    };
    if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", ready);
    else ready();
    root.SketchPad = api;
  }
})(this);
