/* The sketch part kind: a line drawn on the question's axes, marked on the features a scheme
 * names, each a B1 (CLARIFICATIONS, Papers: "Sketch marking is by features computed from the
 * drawn line in the graph's own units"). Pure: the line is [[t, y], ...] in the axes' units
 * (s, and the quantity's SI unit), from the drawing pad or the keyboard builder alike
 * (static/sketch-pad.js). Its Python twin is SketchPart (physics_figures/parts/sketch.py),
 * which writes each marking point's conditions and the tolerances as data. */
(function (root) {
  "use strict";

  /* The line as the marker reads it: finite points inside the axes, in time order. A point
   * that goes back in time (a pen that wavers left) is dropped; equal times are a step. */
  function cleanLine(points, axes) {
    var line = [];
    (points || []).forEach(function (point) {
      var t = Number(point[0]),
        y = Number(point[1]);
      if (!isFinite(t) || !isFinite(y)) return;
      t = Math.min(Math.max(t, axes.t[0]), axes.t[1]);
      y = Math.min(Math.max(y, axes.y[0]), axes.y[1]);
      if (line.length && t < line[line.length - 1][0]) return;
      line.push([t, y]);
    });
    return line;
  }

  /* The tolerances in the axes' units: a value within `value` of the y span is "at" it (and
   * |y| within it is zero), a time within `time` of the t span is "at" it, a change of more
   * than `step` of the y span within `time` is a step, and gradients that differ by more than
   * `curve` of the larger are "increasing" or "decreasing". */
  function scales(part) {
    var axes = part.axes,
      tol = part.tolerance;
    var ySpan = axes.y[1] - axes.y[0],
      tSpan = axes.t[1] - axes.t[0];
    return { y: tol.value * ySpan, t: tol.time * tSpan, step: tol.step * ySpan, curve: tol.curve };
  }

  // The line's value at time t (the later side of a step at exactly t); null off the line.
  function valueAt(line, t) {
    if (!line.length || t < line[0][0] || t > line[line.length - 1][0]) return null;
    for (var i = line.length - 1; i > 0; i--) {
      var a = line[i - 1],
        b = line[i];
      if (t >= a[0] && t <= b[0]) return b[0] === a[0] ? b[1] : a[1] + ((b[1] - a[1]) * (t - a[0])) / (b[0] - a[0]);
    }
    return line[0][1];
  }

  var SAMPLES = 24;

  /* The line's values through a window, kept clear of its ends by the time tolerance (a
   * feature "from 2 s" may start a little either side); null where the line does not cover it. */
  function samples(line, from, to, size) {
    var a = from + size.t,
      b = to - size.t;
    if (b <= a) a = b = (from + to) / 2;
    var out = [];
    for (var i = 0; i < SAMPLES; i++) {
      var value = valueAt(line, a + ((b - a) * i) / (SAMPLES - 1));
      if (value === null) return null;
      out.push(value);
    }
    return { ys: out, dt: b - a };
  }

  function monotone(ys, sign, slack) {
    var best = ys[0];
    for (var i = 1; i < ys.length; i++) {
      if (sign * (ys[i] - best) < -slack) return false;
      best = sign > 0 ? Math.max(best, ys[i]) : Math.min(best, ys[i]);
    }
    return true;
  }

  /* How the gradient changes through a window, from the chords' gradients over its four
   * quarters: "constant" when they agree within `curve` of the largest; "decreasing" when the
   * second is clearly below the first and none climbs back (a straight line with a corner
   * then level is not a curve: its first two quarters agree); "increasing", the same read
   * backwards; else "" (a wave). */
  function gradientTrend(window, size) {
    var ys = window.ys,
      q = ys.length - 1;
    var g = [0, 1, 2, 3].map(function (i) {
      return Math.abs(ys[Math.round(((i + 1) * q) / 4)] - ys[Math.round((i * q) / 4)]);
    });
    var most = Math.max.apply(null, g);
    if (most - Math.min.apply(null, g) <= size.curve * most) return "constant";
    if (easing(g, size.curve / 2)) return "decreasing";
    return easing(g.slice().reverse(), size.curve / 2) ? "increasing" : "";
  }

  function easing(g, margin) {
    if (!(g[1] < g[0] * (1 - margin))) return false;
    for (var i = 1; i < g.length; i++) if (g[i] > g[i - 1] * (1 + margin)) return false;
    return true;
  }

  /* What the line does through [from, to]: "rising", "falling", "level" or "" (wavers, or
   * not drawn there), with its gradient's trend and its mean value. */
  function shapeOver(line, from, to, size) {
    var window = samples(line, from, to, size);
    if (!window) return { shape: "" };
    var ys = window.ys,
      net = ys[ys.length - 1] - ys[0];
    var high = Math.max.apply(null, ys),
      low = Math.min.apply(null, ys);
    var mean =
      ys.reduce(function (sum, y) {
        return sum + y;
      }, 0) / ys.length;
    if (high - low <= 2 * size.y) return { shape: "level", mean: mean };
    var sign = net > 0 ? 1 : -1;
    if (Math.abs(net) < 2 * size.y || !monotone(ys, sign, size.y)) return { shape: "", mean: mean };
    return { shape: sign > 0 ? "rising" : "falling", trend: gradientTrend(window, size), mean: mean };
  }

  /* A step near `at`: two points of the line within the time tolerance of each other (and
   * within twice it of `at`) whose values differ by more than the step size, either way
   * (way "up" or "down"), or any way when none is given. */
  function stepNear(line, at, way, size) {
    var sign = way === "down" ? -1 : 1;
    for (var i = 0; i < line.length; i++) {
      if (Math.abs(line[i][0] - at) > 2 * size.t) continue;
      for (var j = i + 1; j < line.length && line[j][0] - line[i][0] <= size.t; j++) {
        var rise = line[j][1] - line[i][1];
        if ((way ? sign * rise : Math.abs(rise)) >= size.step) return true;
      }
    }
    return false;
  }

  // How often the line crosses from above zero to below it, or back (the "zero" band between).
  function signChanges(line, size) {
    var last = 0,
      count = 0;
    line.forEach(function (point) {
      var sign = point[1] > size.y ? 1 : point[1] < -size.y ? -1 : 0;
      if (sign && last && sign !== last) count += 1;
      if (sign) last = sign;
    });
    return count;
  }

  function valueClass(y, size) {
    return Math.abs(y) <= size.y ? "zero" : y > 0 ? "positive" : "negative";
  }

  /* Whether one condition holds for the line (the template's data, parts/sketch.py):
   * start/end: the line's first or last value is "zero", "positive" or "negative" (start
   * also: drawn from t = 0); rising/falling/level from..to, with gradient and value (at);
   * step at a time (way up or down); sign-change (count: exactly so many, else at least one);
   * peak: the largest value is at least `above`. */
  function holds(cond, line, size, axes) {
    if (!line.length) return false;
    var first = line[0],
      last = line[line.length - 1];
    switch (cond.is) {
      case "start":
        return first[0] - axes.t[0] <= size.t && valueClass(first[1], size) === cond.value;
      case "end":
        return axes.t[1] - last[0] <= size.t && valueClass(last[1], size) === cond.value;
      case "step":
        return stepNear(line, cond.at, cond.way, size);
      case "sign-change":
        return cond.count === undefined ? signChanges(line, size) > 0 : signChanges(line, size) === cond.count;
      case "peak":
        return (
          Math.max.apply(
            null,
            line.map(function (point) {
              return point[1];
            }),
          ) >=
          cond.above - size.y
        );
      default:
        return shapeHolds(cond, line, size);
    }
  }

  function shapeHolds(cond, line, size) {
    var found = shapeOver(line, cond.from, cond.to, size);
    if (found.shape !== cond.is) return false;
    if (cond.gradient && found.trend !== cond.gradient) return false;
    return cond.at === undefined || Math.abs(found.mean - cond.at) <= (cond.within || 1) * size.y;
  }

  /* Each marking point (a B1) is earned when every condition it needs holds and none that
   * loses it does. */
  function markSketch(part, answer) {
    var line = cleanLine(answer.line, part.axes);
    if (line.length < 2) {
      return { code: "no-answer", message: "Draw your line on the axes first (or build it from segments)." };
    }
    var size = scales(part);
    var test = function (cond) {
      return holds(cond, line, size, part.axes);
    };
    var earned = part.points.map(function (point) {
      return point.needs.every(test) && !(point.loses || []).some(test);
    });
    var count = earned.filter(Boolean).length;
    var lines = part.points.map(function (point, i) {
      return (earned[i] ? "✓ " : "✗ ") + point.text;
    });
    return {
      code: count === earned.length ? "correct" : count ? "partial" : "wrong",
      correct: count === earned.length,
      earned: earned,
      message: "Your line shows " + count + " of the " + earned.length + " features: " + lines.join("; ") + ".",
    };
  }

  /* The part on the page: its fieldset holds the pad (static/sketch-pad.js, loaded with the
   * page's sketch parts: SketchAxes' page_assets), whose line is the answer. */
  function pad(box) {
    return root.SketchPad.padOf(box);
  }

  var kind = {
    kinds: ["sketch"],
    mark: markSketch,
    read: function (box) {
      return { line: pad(box).line() };
    },
    fill: function (box, part, answer) {
      pad(box).set(answer.line || []);
    },
    answered: function (answer) {
      return (answer.line || []).length >= 2;
    },
    relabel: function (box, part) {
      root.SketchPad.relabel(box, part);
    },
    features: { cleanLine: cleanLine, valueAt: valueAt, shapeOver: shapeOver, scales: scales, holds: holds },
  };
  if (typeof module === "object" && module.exports) module.exports = kind;
  else
    kind.kinds.forEach(function (name) {
      root.QuestionKinds.register(name, kind);
    });
})(this);
