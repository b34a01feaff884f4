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

  function build(root, data) {
    var g = data.g;
    var state = { t: 0 };
    var dive;

    var title = el("p", { class: "ex-title", id: X.nextId("title") }, "Explore: the skydiver");
    var mass = new X.Quantity({
      label: "Mass of the skydiver",
      unit: "kg",
      unitSpoken: "kilograms",
      min: 40,
      max: 120,
      step: 1,
      value: data.mass,
      onChange: update,
    });
    var bodyDrag = new X.Quantity({
      label: "Body\u2019s drag constant k (drag = k v\u00b2)",
      unit: "kg m\u207b\u00b9",
      unitSpoken: "kilograms per metre",
      min: 0.15,
      max: 1,
      step: 0.01,
      value: data.bodyDrag,
      onChange: update,
    });
    var chuteDrag = new X.Quantity({
      label: "Parachute\u2019s drag constant k",
      unit: "kg m\u207b\u00b9",
      unitSpoken: "kilograms per metre",
      min: 8,
      max: 80,
      step: 0.5,
      value: data.parachuteDrag,
      onChange: update,
    });
    var opens = new X.Quantity({
      label: "Parachute opens at time",
      unit: "s",
      unitSpoken: "seconds",
      min: 0.5,
      max: 60,
      step: 0.5,
      value: data.parachuteOpensAt,
      onChange: update,
    });
    var fills = new X.Quantity({
      label: "Time the parachute takes to open τ",
      unit: "s",
      unitSpoken: "seconds",
      min: 0.5,
      max: 5,
      step: 0.1,
      value: data.openingDuration,
      onChange: update,
    });
    var time = new X.Quantity({
      label: "Time along the graph",
      unit: "s",
      unitSpoken: "seconds",
      min: 0,
      max: 60,
      step: 0.1,
      value: 0,
      onChange: function (t) {
        state.t = t;
        showTime();
      },
    });
    // not live regions: the explorable's announcer says them when they change (ui.js)
    var note = el("p", { class: "ex-note", "data-announce": "" });
    var warning = el("p", { class: "ex-note ex-warning", "data-announce": "" });

    var buttons = {};
    var jumps = el(
      "div",
      { class: "ex-jumps", role: "group", "aria-label": "Go to a point on the graph" },
      [el("span", { "aria-hidden": "true" }, "Go to: ")].concat(
        LABELS.map(function (label) {
          var button = el("button", { type: "button", class: "ex-button" }, label);
          button.addEventListener("click", function () {
            time.set(dive.points[label][0]);
          });
          buttons[label] = button;
          return button;
        }),
      ),
    );

    var r = X.nameReadouts({
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
    var description = new X.Description();
    var timeDescription = new X.Description("ex-now");

    root.appendChild(
      el("section", { class: "ex-panel", "aria-labelledby": title.id }, [
        title,
        el(
          "p",
          { class: "ex-hint" },
          "Change the skydiver and the parachute, then move along the graph to see the forces. Down is positive.",
        ),
        el("div", { class: "ex-controls" }, [
          mass.element,
          bodyDrag.element,
          chuteDrag.element,
          opens.element,
          fills.element,
        ]),
        note,
        el("div", { class: "ex-readouts" }, [
          r.weight.element,
          r.vt1.element,
          r.d1.element,
          r.vt2.element,
          r.d2.element,
          r.decel.element,
          r.decelG.element,
        ]),
        warning,
        // the time slider sits right above the velocity graph it moves along
        el("div", { class: "ex-controls ex-time-controls" }, [time.element, jumps]),
        el("div", { class: "ex-figure-row" }, [
          el("div", { class: "ex-graphs" }, [vPlot.svg, fPlot.svg]),
          el("div", { class: "ex-side" }, [fbd]),
        ]),
        el("div", { class: "ex-readouts" }, [r.t.element, r.v.element, r.drag.element, r.force.element, r.acc.element]),
        timeDescription.element,
        description.element,
      ]),
    );
    vPlot.scrub(function (t) {
      time.set(t);
    });
    fPlot.scrub(function (t) {
      time.set(t);
    });

    function update() {
      // the parachute can open once the skydiver falls faster than its terminal velocity
      // (+1 %), so that it slows them down to it: the first half second after that
      var earliest =
        Math.floor(M.earliestParachuteOpening(mass.value, bodyDrag.value, chuteDrag.value, g) * 2) / 2 + 0.5;
      opens.setRange(earliest);
      if (opens.value < earliest) {
        opens.value = earliest;
        opens.show();
        note.textContent = X.joinUnits(
          "The parachute now opens at " +
            fmt(earliest) +
            " s: it can open only once the skydiver is falling faster than the parachute’s terminal velocity.",
        );
      } else note.textContent = X.joinUnits("");
      dive = M.skydive({
        mass: mass.value,
        bodyDrag: bodyDrag.value,
        parachuteDrag: chuteDrag.value,
        parachuteOpensAt: opens.value,
        openingDuration: fills.value,
        g: g,
      });
      var p = dive.points;
      var duration = Math.max(p.E[0] + 4, dive.parachuteOpensAt * 1.25);
      time.setRange(0, duration);
      if (state.t > duration) state.t = duration;
      time.value = state.t;
      time.show();

      r.weight.set(dive.weight);
      r.vt1.set(dive.terminalVelocityFreefall);
      r.d1.set(dive.dragAtFreefallTerminal);
      r.vt2.set(dive.terminalVelocityParachute);
      r.d2.set(dive.dragAtParachuteTerminal);
      var decel = -dive.pointAcceleration.D,
        inG = decel / g;
      r.decel.set(decel);
      r.decelG.set(inG);
      LABELS.forEach(function (label) {
        buttons[label].hidden = !(label in p);
      });
      // the words and the 15 g limit come from physics_figures.explorables, the numbers from the model
      warning.textContent = X.joinUnits(
        inG > data.unrealisticDecelerationInG ? X.fill(data.unrealisticOpening, M.openingJolt(dive)) : "",
      );

      drawGraphs(duration);
      var rise = p.C
        ? "The velocity rises from 0 with a gradient of g, less and less steeply, to a terminal velocity of " +
          fmt(dive.terminalVelocityFreefall) +
          " " +
          MS +
          " (C at " +
          fmt(p.C[0]) +
          " s). "
        : "The velocity rises from 0 with a gradient of g, less and less steeply, towards a terminal velocity of " +
          fmt(dive.terminalVelocityFreefall) +
          " " +
          MS +
          ", but the parachute opens before it gets there. ";
      description.set(
        rise +
          "The parachute opens at " +
          fmt(dive.parachuteOpensAt) +
          " s and takes " +
          fmt(dive.openingDuration, { sf: 2 }) +
          " s to fill: its drag grows quickly to more than the weight, so the resultant force is upwards. The deceleration is largest at D, " +
          fmt(p.D[0] - dive.parachuteOpensAt, { sf: 2 }) +
          " s after the opening: the drag is " +
          fmt(dive.pointDrag.D) +
          " N, " +
          fmt(dive.pointDrag.D / dive.weight, { sf: 2 }) +
          " times the weight, the resultant force " +
          fmt(-dive.pointAcceleration.D * dive.mass) +
          " N upwards and the deceleration " +
          fmt(decel) +
          " " +
          MS2 +
          " (" +
          fmt(inG, { sf: 2 }) +
          " g). The skydiver slows, still moving down, to a second terminal velocity of " +
          fmt(dive.terminalVelocityParachute) +
          " " +
          MS +
          " (E at " +
          fmt(p.E[0]) +
          " s). At both terminal velocities the drag equals the weight, " +
          fmt(dive.weight) +
          " N.",
      );
      showTime();
    }

    function drawGraphs(duration) {
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
      ts = ts.filter(function (t) {
        return t <= duration;
      });
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
        vPlot.keepInside(
          vPlot.marks.appendChild(
            svg(
              "text",
              {
                class: "ex-point-label",
                x: x + (label === "D" ? 8 : label === "A" ? 6 : -4),
                y: y + dy,
                "text-anchor": label === "C" ? "end" : "start",
              },
              label,
            ),
          ),
        );
      });

      // resultant force, down positive: W - D; a dip below -6 W is clipped
      var forceTs = ts;
      var forces = ts.map(dive.resultantForceAt);
      var fMin = Math.min.apply(null, forces);
      var low = Math.max(fMin, -FORCE_CLIP * dive.weight) * 1.05;
      fPlot.setDomain(0, duration, low, dive.weight * 1.15);
      X.clear(fPlot.data);
      X.clear(fPlot.marks);
      fPlot.data.appendChild(svg("path", { class: "ex-line ex-b", d: fPlot.path(forceTs, forces) }));
      if (fMin < low) {
        var xd = fPlot.x(dive.points.D[0]);
        // the label goes on whichever side of the spike has room
        var roomRight = fPlot.box.right - xd > 190,
          side = roomRight ? 1 : -1;
        fPlot.marks.appendChild(
          X.arrow(xd + 16 * side, fPlot.box.bottom - 34, xd + 16 * side, fPlot.box.bottom - 4, "ex-b"),
        );
        fPlot.keepInside(
          fPlot.marks.appendChild(
            svg(
              "text",
              {
                class: "ex-point-label",
                x: xd + 24 * side,
                y: fPlot.box.bottom - 14,
                "text-anchor": roomRight ? "start" : "end",
              },
              "D: " + fmt(fMin) + "\u00a0N, off the scale",
            ),
          ),
        );
      }
      fPlot.keepInside(
        fPlot.marks.appendChild(
          svg("text", { class: "ex-point-label", x: fPlot.box.left + 8, y: fPlot.y(dive.weight) - 6 }, "A: W"),
        ),
      );
    }

    function showTime() {
      var t = state.t;
      var v = dive.velocityAt(t),
        drag = dive.dragAt(t),
        force = dive.resultantForceAt(t),
        acc = dive.accelerationAt(t);
      r.t.set(t);
      r.v.set(v);
      r.drag.set(drag);
      r.force.set(Math.abs(force), direction(force));
      r.acc.set(Math.abs(acc), direction(acc));
      [vPlot, fPlot].forEach(function (plot) {
        var old = plot.svg.querySelector(".ex-cursor");
        if (old) old.parentNode.removeChild(old);
        var x = plot.x(t);
        plot.marks.appendChild(
          svg("line", { class: "ex-cursor", x1: x, x2: x, y1: plot.box.top, y2: plot.box.bottom }),
        );
      });
      drawFreeBody(t, drag);
      timeDescription.set(
        "At t = " +
          fmt(t) +
          " s the skydiver falls at " +
          fmt(v) +
          " " +
          MS +
          ". Weight " +
          fmt(dive.weight) +
          " N down, drag " +
          fmt(drag) +
          " N up, so the resultant force is " +
          (Math.abs(force) < 0.005 * dive.weight ? "about zero" : fmt(Math.abs(force)) + " N " + direction(force)) +
          " and the acceleration " +
          fmt(Math.abs(acc)) +
          " " +
          MS2 +
          " " +
          direction(acc) +
          ".",
      );
    }

    /** The round number (1, 2 or 5 x 10^n steps of a tenth) at or above v: 55 -> 60, 22 -> 25. */
    function roundUp(v) {
      var step = Math.pow(10, Math.floor(Math.log10(v))) / 2;
      return Math.ceil(v / step - 1e-9) * step;
    }

    function direction(x) {
      return Math.abs(x) < 1e-9 ? "" : x > 0 ? "down" : "up";
    }

    function drawFreeBody(t, drag) {
      X.clear(fbd);
      var cx = 100,
        cy = 165,
        unit = 60; // unit: the weight arrow's length
      var open = t >= dive.parachuteOpensAt;
      if (open) {
        // the canopy fills over the opening duration: drawn growing to full width
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
      fbd.appendChild(svg("rect", { class: "ex-body", x: cx - 14, y: cy - 18, width: 28, height: 36, rx: 10 }));
      fbd.appendChild(X.arrow(cx + 22, cy, cx + 22, cy + unit, "ex-weight", 11));
      fbd.appendChild(
        svg(
          "text",
          { class: "ex-fbd-label ex-weight-text", x: cx + 30, y: cy + unit / 2 + 4 },
          "W " + fmt(dive.weight) + " N",
        ),
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
      fbd.appendChild(
        svg(
          "text",
          { class: "ex-fbd-label ex-drag-text", x: cx - 30, y: cy - shown / 2 + 4, "text-anchor": "end" },
          "D " + fmt(drag) + " N",
        ),
      );
      var caption = ratio > 2.2 ? "drag = " + fmt(ratio, { sf: 2 }) + " \u00d7 W (not to scale)" : "lengths to scale";
      fbd.appendChild(svg("text", { class: "ex-fbd-label", x: 100, y: 292, "text-anchor": "middle" }, caption));
      fbd.appendChild(
        svg("text", { class: "ex-fbd-label", x: 100, y: 14, "text-anchor": "middle" }, "t = " + fmt(t) + " s"),
      );
    }

    update();
  }

  X.register("skydiver", build);
})();
