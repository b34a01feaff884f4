/* Skydiver explorer: velocity-time and resultant force-time graphs with A to E, and a
 * free-body diagram that follows the time chosen on the graph. Down is positive. The
 * parachute opens at a chosen time and takes a chosen time to fill.
 * Physics: ExplorableModels.skydive (twin of physics_figures.models.skydive). */
(function () {
  "use strict";
  var X = window.Explorables;
  var M = window.ExplorableModels;
  var el = X.el,
    svg = X.svg,
    fmt = X.fmt;

  var MS = "m s\u207b\u00b9",
    MS2 = "m s\u207b\u00b2";
  var LABELS = ["A", "B", "C", "D", "E"];
  var FORCE_CLIP = 6; // the force graph shows down to -6 W; a harder opening runs off below

  var KG_PER_M = "kg m\u207b\u00b9";
  // The set-up's sliders, each named as the data's starting value: label, unit, unit spoken, min, max, step.
  var SLIDERS = [
    ["mass", "Mass of the skydiver", "kg", "kilograms", 40, 120, 1],
    ["bodyDrag", "Body\u2019s drag constant k (drag = k v\u00b2)", KG_PER_M, "kilograms per metre", 0.15, 1, 0.01],
    ["parachuteDrag", "Parachute\u2019s drag constant k", KG_PER_M, "kilograms per metre", 8, 80, 0.5],
    ["parachuteOpensAt", "Parachute opens at time", "s", "seconds", 0.5, 60, 0.5],
    ["openingDuration", "Time the parachute takes to open τ", "s", "seconds", 0.5, 5, 0.1],
  ];

  var SLIDER_NAMES = SLIDERS.map(function (row) {
    return row[0];
  });
  var TIME_SLIDER = ["time", "Time along the graph", "s", "seconds", 0, 60, 0.1];

  function slider(row, value, onChange) {
    return new X.Quantity({
      label: row[1],
      unit: row[2],
      unitSpoken: row[3],
      min: row[4],
      max: row[5],
      step: row[6],
      value: value,
      onChange: onChange,
    });
  }

  /* The skydiver's and the parachute's sliders (onChange), and the time along the graph (onTime). */
  function skydiverQuantities(data, onChange, onTime) {
    var q = {};
    SLIDERS.forEach(function (row) {
      q[row[0]] = slider(row, data[row[0]], onChange);
    });
    q.time = slider(TIME_SLIDER, 0, onTime);
    return q;
  }

  function elementsOf(things, names) {
    return names.map(function (name) {
      return things[name].element;
    });
  }

  /* The "Go to" buttons A to E; onJump(label) when one is pressed. */
  function jumpButtons(onJump) {
    var buttons = {};
    var element = el(
      "div",
      { class: "ex-jumps", role: "group", "aria-label": "Go to a point on the graph" },
      [el("span", { "aria-hidden": "true" }, "Go to: ")].concat(
        LABELS.map(function (label) {
          var button = el("button", { type: "button", class: "ex-button" }, label);
          button.addEventListener("click", function () {
            onJump(label);
          });
          buttons[label] = button;
          return button;
        }),
      ),
    );
    return { element: element, buttons: buttons };
  }

  function skydiverReadouts() {
    return X.nameReadouts({
      vt1: new X.Readout("Terminal velocity, falling freely", MS),
      d1: new X.Readout("Drag at that terminal velocity", "N"),
      vt2: new X.Readout("Terminal velocity, parachute open", MS),
      d2: new X.Readout("Drag at that terminal velocity", "N"),
      weight: new X.Readout("Weight W = mg", "N"),
      decel: new X.Readout("Largest deceleration (at D, upwards)", MS2),
      decelG: new X.Readout("Largest deceleration in g", "g", { sf: 2 }),
      t: new X.Readout("Time t", "s"),
      v: new X.Readout("Velocity (down)", MS),
      drag: new X.Readout("Drag (up)", "N"),
      force: new X.Readout("Resultant force", "N"),
      acc: new X.Readout("Acceleration", MS2),
    });
  }

  /* The velocity-time and force-time graphs and the free-body diagram. */
  function skydiverFigures(root) {
    var width = X.widthFor(root);
    var vPlot = new X.Plot({
      width: width,
      height: 250,
      xLabel: "time t / s",
      yLabel: "velocity v / m s\u207b\u00b9",
      label: "Velocity against time, with points A to E",
    });
    var fPlot = new X.Plot({
      width: width,
      height: 230,
      xLabel: "time t / s",
      yLabel: "resultant force / N",
      label: "Resultant force against time, down positive",
    });
    var fbd = svg("svg", {
      viewBox: "0 0 200 300",
      class: "ex-fbd",
      role: "img",
      "aria-label": "Free-body diagram: weight down, drag up",
    });
    return { vPlot: vPlot, fPlot: fPlot, fbd: fbd };
  }

  /* The panel: the set-up's sliders and read-outs, then the time slider, graphs and free body. */
  function skydiverPanel(title, q, note, warning, r, jumps, fig, timeDescription, description) {
    return el("section", { class: "ex-panel", "aria-labelledby": title.id }, [
      title,
      el(
        "p",
        { class: "ex-hint" },
        "Change the skydiver and the parachute, then move along the graph to see the forces. Down is positive.",
      ),
      el("div", { class: "ex-controls" }, elementsOf(q, SLIDER_NAMES)),
      note,
      el("div", { class: "ex-readouts" }, elementsOf(r, ["weight", "vt1", "d1", "vt2", "d2", "decel", "decelG"])),
      warning,
      // the time slider sits right above the velocity graph it moves along
      el("div", { class: "ex-controls ex-time-controls" }, [q.time.element, jumps]),
      el("div", { class: "ex-figure-row" }, [
        el("div", { class: "ex-graphs" }, [fig.vPlot.svg, fig.fPlot.svg]),
        el("div", { class: "ex-side" }, [fig.fbd]),
      ]),
      el("div", { class: "ex-readouts" }, elementsOf(r, ["t", "v", "drag", "force", "acc"])),
      timeDescription.element,
      description.element,
    ]);
  }

  /* The parachute can open once the skydiver falls faster than its terminal velocity (+1 %), so
   * that it slows them down to it: the first half second after that. A later opening is moved
   * there, and the note says so. */
  function keepOpeningPossible(q, note, g) {
    var earliest =
      Math.floor(M.earliestParachuteOpening(q.mass.value, q.bodyDrag.value, q.parachuteDrag.value, g) * 2) / 2 + 0.5;
    q.parachuteOpensAt.setRange(earliest);
    if (q.parachuteOpensAt.value < earliest) {
      q.parachuteOpensAt.value = earliest;
      q.parachuteOpensAt.show();
      note.textContent = X.joinUnits(
        "The parachute now opens at " +
          fmt(earliest) +
          " s: it can open only once the skydiver is falling faster than the parachute\u2019s terminal velocity.",
      );
    } else note.textContent = X.joinUnits("");
  }

  /* The model's dive for the sliders' set-up. */
  function diveOf(q, g) {
    var opts = { g: g };
    SLIDERS.forEach(function (row) {
      opts[row[0]] = q[row[0]].value;
    });
    return M.skydive(opts);
  }

  /* The dive's read-outs: the weight, both terminal velocities with their drag, the largest deceleration. */
  function showDiveReadouts(r, dive) {
    r.weight.set(dive.weight);
    r.vt1.set(dive.terminalVelocityFreefall);
    r.d1.set(dive.dragAtFreefallTerminal);
    r.vt2.set(dive.terminalVelocityParachute);
    r.d2.set(dive.dragAtParachuteTerminal);
    r.decel.set(-dive.pointAcceleration.D);
    r.decelG.set(-dive.pointAcceleration.D / dive.g);
  }

  /* The "Unrealistic" warning when the opening's deceleration at D is over the limit in g: the
   * words and the 15 g limit come from physics_figures.explorables, the numbers from the model. */
  function warnOfJolt(warning, dive, data) {
    var inG = -dive.pointAcceleration.D / dive.g;
    warning.textContent = X.joinUnits(
      inG > data.unrealisticDecelerationInG ? X.fill(data.unrealisticOpening, M.openingJolt(dive)) : "",
    );
  }

  /* Fill {name} in a text with values already written out. */
  function words(text, values) {
    return text.replace(/\{(\w+)\}/g, function (all, name) {
      return values[name];
    });
  }

  var RISE_TO_TERMINAL =
    "The velocity rises from 0 with a gradient of g, less and less steeply, to a terminal velocity of {vt1} " +
    MS +
    " (C at {tC} s). ";
  var RISE_CUT_SHORT =
    "The velocity rises from 0 with a gradient of g, less and less steeply, towards a terminal velocity of {vt1} " +
    MS +
    ", but the parachute opens before it gets there. ";
  var OPENING_AND_AFTER =
    "The parachute opens at {tOpen} s and takes {tau} s to fill: its drag grows quickly to more than the weight, " +
    "so the resultant force is upwards. The deceleration is largest at D, {afterOpening} s after the opening: " +
    "the drag is {dragD} N, {dragInW} times the weight, the resultant force {forceD} N upwards and the deceleration {decel} " +
    MS2 +
    " ({inG} g). The skydiver slows, still moving down, to a second terminal velocity of {vt2} " +
    MS +
    " (E at {tE} s). At both terminal velocities the drag equals the weight, {weight} N.";

  /* The whole dive in words, A to E. */
  function describeDive(dive) {
    var p = dive.points;
    var decel = -dive.pointAcceleration.D;
    var rise = words(p.C ? RISE_TO_TERMINAL : RISE_CUT_SHORT, {
      vt1: fmt(dive.terminalVelocityFreefall),
      tC: p.C ? fmt(p.C[0]) : "",
    });
    return (
      rise +
      words(OPENING_AND_AFTER, {
        tOpen: fmt(dive.parachuteOpensAt),
        tau: fmt(dive.openingDuration, { sf: 2 }),
        afterOpening: fmt(p.D[0] - dive.parachuteOpensAt, { sf: 2 }),
        dragD: fmt(dive.pointDrag.D),
        dragInW: fmt(dive.pointDrag.D / dive.weight, { sf: 2 }),
        forceD: fmt(-dive.pointAcceleration.D * dive.mass),
        decel: fmt(decel),
        inG: fmt(decel / dive.g, { sf: 2 }),
        vt2: fmt(dive.terminalVelocityParachute),
        tE: fmt(p.E[0]),
        weight: fmt(dive.weight),
      })
    );
  }

  /* The times the graphs are drawn at, up to duration: even before and during the opening,
   * dense after it where v drops fast, and D itself. */
  function graphTimes(dive, duration) {
    var tOpen = dive.parachuteOpensAt,
      tFull = dive.parachuteOpenAt;
    var n = 240,
      ts = [];
    for (var i = 0; i < n; i++) ts.push((tOpen * i) / n);
    for (var k = 0; k < n; k++) ts.push(tOpen + ((tFull - tOpen) * k) / n); // the opening
    if (tFull < duration) for (var j = 0; j <= n; j++) ts.push(tFull + (duration - tFull) * Math.pow(j / n, 2)); // dense where v drops fast
    ts.push(dive.points.D[0]);
    ts.sort(function (a, b) {
      return a - b;
    });
    return ts.filter(function (t) {
      return t <= duration;
    });
  }

  /* The velocity-time graph: the line, both terminal velocities as guides, the points A to E. */
  function drawVelocityGraph(vPlot, dive, ts, duration) {
    var vs = ts.map(dive.velocityAt);
    // the axis fits this run: its fastest speed and a tenth more, up to a round number
    var vMax = roundUp(Math.max.apply(null, vs.concat([dive.terminalVelocityFreefall])) * 1.1);
    vPlot.setDomain(0, duration, 0, vMax);
    X.clear(vPlot.data);
    X.clear(vPlot.marks);
    vPlot.data.appendChild(svg("path", { class: "ex-line ex-a", d: vPlot.path(ts, vs) }));
    [dive.terminalVelocityFreefall, dive.terminalVelocityParachute].forEach(function (vt) {
      vPlot.data.appendChild(
        svg("line", { class: "ex-guide", x1: vPlot.box.left, x2: vPlot.box.right, y1: vPlot.y(vt), y2: vPlot.y(vt) }),
      );
    });
    LABELS.filter(function (label) {
      return label in dive.points;
    }).forEach(function (label) {
      var pt = dive.points[label],
        x = vPlot.x(pt[0]),
        y = vPlot.y(pt[1]);
      vPlot.marks.appendChild(svg("circle", { class: "ex-point", cx: x, cy: y, r: 4 }));
      var dy = label === "E" || label === "A" ? -8 : label === "D" ? -8 : 16;
      var at = { class: "ex-point-label", x: x + (label === "D" ? 8 : label === "A" ? 6 : -4), y: y + dy };
      at["text-anchor"] = label === "C" ? "end" : "start";
      vPlot.keepInside(vPlot.marks.appendChild(svg("text", at, label)));
    });
  }

  /* The resultant force, down positive: W - D; a dip below -6 W is clipped, and D's arrow and
   * label say how far it goes. */
  function drawForceGraph(fPlot, dive, ts, duration) {
    var forces = ts.map(dive.resultantForceAt);
    var fMin = Math.min.apply(null, forces);
    var low = Math.max(fMin, -FORCE_CLIP * dive.weight) * 1.05;
    fPlot.setDomain(0, duration, low, dive.weight * 1.15);
    X.clear(fPlot.data);
    X.clear(fPlot.marks);
    fPlot.data.appendChild(svg("path", { class: "ex-line ex-b", d: fPlot.path(ts, forces) }));
    if (fMin < low) markOffScale(fPlot, dive, fMin);
    fPlot.keepInside(
      fPlot.marks.appendChild(
        svg("text", { class: "ex-point-label", x: fPlot.box.left + 8, y: fPlot.y(dive.weight) - 6 }, "A: W"),
      ),
    );
  }

  function markOffScale(fPlot, dive, fMin) {
    var xd = fPlot.x(dive.points.D[0]);
    // the label goes on whichever side of the spike has room
    var roomRight = fPlot.box.right - xd > 190,
      side = roomRight ? 1 : -1;
    fPlot.marks.appendChild(
      X.arrow(xd + 16 * side, fPlot.box.bottom - 34, xd + 16 * side, fPlot.box.bottom - 4, "ex-b"),
    );
    var at = { class: "ex-point-label", x: xd + 24 * side, y: fPlot.box.bottom - 14 };
    at["text-anchor"] = roomRight ? "start" : "end";
    fPlot.keepInside(fPlot.marks.appendChild(svg("text", at, "D: " + fmt(fMin) + "\u00a0N, off the scale")));
  }

  /* The cursor of time t on each graph (the old one removed). */
  function moveCursors(plots, t) {
    plots.forEach(function (plot) {
      var old = plot.svg.querySelector(".ex-cursor");
      if (old) old.parentNode.removeChild(old);
      var x = plot.x(t);
      plot.marks.appendChild(svg("line", { class: "ex-cursor", x1: x, x2: x, y1: plot.box.top, y2: plot.box.bottom }));
    });
  }

  var MOMENT =
    "At t = {t} s the skydiver falls at {v} " +
    MS +
    ". Weight {weight} N down, drag {drag} N up, so the resultant force is {force} and the acceleration {acc} " +
    MS2 +
    " {accDirection}.";

  /* The forces and the motion at one time, in words. */
  function describeMoment(dive, now) {
    var aboutZero = Math.abs(now.force) < 0.005 * dive.weight;
    return words(MOMENT, {
      t: fmt(now.t),
      v: fmt(now.v),
      weight: fmt(dive.weight),
      drag: fmt(now.drag),
      force: aboutZero ? "about zero" : fmt(Math.abs(now.force)) + " N " + direction(now.force),
      acc: fmt(Math.abs(now.acc)),
      accDirection: direction(now.acc),
    });
  }

  /** The round number (1, 2 or 5 x 10^n steps of a tenth) at or above v: 55 -> 60, 22 -> 25. */
  function roundUp(v) {
    var step = Math.pow(10, Math.floor(Math.log10(v))) / 2;
    return Math.ceil(v / step - 1e-9) * step;
  }

  function direction(x) {
    return Math.abs(x) < 1e-9 ? "" : x > 0 ? "down" : "up";
  }

  /* The canopy once it starts to open: it fills over the opening duration, drawn growing to full width. */
  function drawCanopy(fbd, dive, t) {
    var half = 48 * Math.min(1, Math.max(0.25, (t - dive.parachuteOpensAt) / dive.openingDuration));
    var left = 100 - half,
      right = 100 + half;
    fbd.appendChild(
      svg("path", { class: "ex-canopy", d: "M" + left + " 70 Q100 " + (70 - half) + " " + right + " 70 Z" }),
    );
    fbd.appendChild(
      svg("path", { class: "ex-lines", d: "M" + left + " 70L92 148M" + right + " 70L108 148M100 70L100 148" }),
    );
  }

  function fbdText(fbd, attributes, text) {
    fbd.appendChild(svg("text", attributes, text));
  }

  /* The free-body diagram at time t: weight down, drag up, to scale unless the drag is over 2.2 W. */
  function drawFreeBody(fbd, dive, t, drag) {
    X.clear(fbd);
    var cx = 100,
      cy = 165,
      unit = 60; // unit: the weight arrow's length
    if (t >= dive.parachuteOpensAt) drawCanopy(fbd, dive, t);
    fbd.appendChild(svg("rect", { class: "ex-body", x: cx - 14, y: cy - 18, width: 28, height: 36, rx: 10 }));
    fbd.appendChild(X.arrow(cx + 22, cy, cx + 22, cy + unit, "ex-weight", 11));
    fbdText(
      fbd,
      { class: "ex-fbd-label ex-weight-text", x: cx + 30, y: cy + unit / 2 + 4 },
      "W " + fmt(dive.weight) + " N",
    );
    var ratio = drag / dive.weight,
      shown = Math.min(ratio, 2.2) * unit;
    fbd.appendChild(X.arrow(cx - 22, cy, cx - 22, cy - shown, "ex-drag", 11));
    if (ratio > 2.2)
      fbd.appendChild(
        svg("path", {
          class: "ex-break",
          d: "M" + (cx - 30) + " " + (cy - 60) + "l16 -5M" + (cx - 30) + " " + (cy - 54) + "l16 -5",
        }),
      );
    var dragAt = { class: "ex-fbd-label ex-drag-text", x: cx - 30, y: cy - shown / 2 + 4, "text-anchor": "end" };
    fbdText(fbd, dragAt, "D " + fmt(drag) + " N");
    var caption = ratio > 2.2 ? "drag = " + fmt(ratio, { sf: 2 }) + " \u00d7 W (not to scale)" : "lengths to scale";
    fbdText(fbd, { class: "ex-fbd-label", x: 100, y: 292, "text-anchor": "middle" }, caption);
    fbdText(fbd, { class: "ex-fbd-label", x: 100, y: 14, "text-anchor": "middle" }, "t = " + fmt(t) + " s");
  }

  function build(root, data) {
    var g = data.g;
    var state = { t: 0 };
    var dive;

    var title = el("p", { class: "ex-title", id: X.nextId("title") }, "Explore: the skydiver");
    var q = skydiverQuantities(data, update, function (t) {
      state.t = t;
      showTime();
    });
    // not live regions: the explorable's announcer says them when they change (ui.js)
    var note = el("p", { class: "ex-note", "data-announce": "" });
    var warning = el("p", { class: "ex-note ex-warning", "data-announce": "" });
    var jumps = jumpButtons(function (label) {
      q.time.set(dive.points[label][0]);
    });
    var r = skydiverReadouts();
    var fig = skydiverFigures(root);
    var description = new X.Description();
    var timeDescription = new X.Description("ex-now");
    root.appendChild(skydiverPanel(title, q, note, warning, r, jumps.element, fig, timeDescription, description));
    [fig.vPlot, fig.fPlot].forEach(function (plot) {
      plot.scrub(function (t) {
        q.time.set(t);
      });
    });

    function update() {
      keepOpeningPossible(q, note, g);
      dive = diveOf(q, g);
      var duration = Math.max(dive.points.E[0] + 4, dive.parachuteOpensAt * 1.25);
      q.time.setRange(0, duration);
      if (state.t > duration) state.t = duration;
      q.time.value = state.t;
      q.time.show();
      showDiveReadouts(r, dive);
      LABELS.forEach(function (label) {
        jumps.buttons[label].hidden = !(label in dive.points);
      });
      warnOfJolt(warning, dive, data);
      var ts = graphTimes(dive, duration);
      drawVelocityGraph(fig.vPlot, dive, ts, duration);
      drawForceGraph(fig.fPlot, dive, ts, duration);
      description.set(describeDive(dive));
      showTime();
    }

    function showTime() {
      var t = state.t;
      var now = {
        t: t,
        v: dive.velocityAt(t),
        drag: dive.dragAt(t),
        force: dive.resultantForceAt(t),
        acc: dive.accelerationAt(t),
      };
      r.t.set(t);
      r.v.set(now.v);
      r.drag.set(now.drag);
      r.force.set(Math.abs(now.force), direction(now.force));
      r.acc.set(Math.abs(now.acc), direction(now.acc));
      moveCursors([fig.vPlot, fig.fPlot], t);
      drawFreeBody(fig.fbd, dive, t, now.drag);
      timeDescription.set(describeMoment(dive, now));
    }

    update();
  }

  X.register("skydiver", build);
})();
