/* Momentum-time graph reader: move along the car's graph (pointer or keyboard) and read
 * the time, momentum, velocity = p / m and gradient = resultant force.
 * Physics: ExplorableModels.momentumHistory (twin of physics_figures.models.MomentumHistory). */
(function () {
  "use strict";
  var X = window.Explorables;
  var M = window.ExplorableModels;
  var el = X.el,
    svg = X.svg,
    fmt = X.fmt;

  var P = "kg m s\u207b\u00b9",
    MS = "m s\u207b\u00b9",
    MS2 = "m s\u207b\u00b2";

  /* What a constant resultant force does to the car, in words. */
  function motionUnder(f) {
    if (f > 0) return "a constant resultant force of " + fmt(f) + " N forwards, so the car speeds up";
    if (f < 0) return "a constant resultant force of " + fmt(-f) + " N backwards, so the car slows down";
    return "zero resultant force, so the car keeps a constant velocity";
  }

  /* The reading at time t in words: p, v = p / m, and the gradient of the straight piece ta..tb. */
  function describeReading(reading, mass, ta, tb) {
    return (
      "At t = " +
      fmt(reading.t) +
      " s the momentum is " +
      fmt(reading.p) +
      " " +
      P +
      ", so the velocity is " +
      fmt(reading.p) +
      " \u00f7 " +
      fmt(mass) +
      " = " +
      fmt(reading.v) +
      " " +
      MS +
      ". From " +
      fmt(ta) +
      " s to " +
      fmt(tb) +
      " s the graph is a straight line with gradient " +
      fmt(reading.f) +
      " N: " +
      motionUnder(reading.f) +
      "."
    );
  }

  /* The cursor at (t, p): a vertical line, the point and its gradient, labelled on the side with room. */
  function drawCursor(plot, cursor, reading) {
    X.clear(cursor);
    var x = plot.x(reading.t),
      y = plot.y(reading.p);
    cursor.appendChild(svg("line", { class: "ex-cursor", x1: x, x2: x, y1: plot.box.top, y2: plot.box.bottom }));
    cursor.appendChild(svg("circle", { class: "ex-point", cx: x, cy: y, r: 5 }));
    var right = x < (plot.box.left + plot.box.right) / 2;
    plot.keepInside(
      cursor.appendChild(
        svg(
          "text",
          {
            class: "ex-point-label",
            x: x + (right ? 10 : -10),
            y: Math.max(plot.box.top + 14, y - 12),
            "text-anchor": right ? "start" : "end",
          },
          "gradient " + fmt(reading.f) + "\u00a0N",
        ),
      ),
    );
  }

  /* The index of the straight piece of the graph that holds time t. */
  function segmentOf(times, t) {
    for (var i = 0; i < times.length - 2; i++) if (t < times[i + 1]) return i;
    return times.length - 2;
  }

  /* The panel: title, hint, the graph, the time slider, the read-outs and the description. */
  function readerPanel(mass, title, plot, time, readouts, description) {
    return el("section", { class: "ex-panel", "aria-labelledby": title.id }, [
      title,
      el(
        "p",
        { class: "ex-hint" },
        X.joinUnits(
          "The " +
            fmt(mass) +
            " kg car. Move along the graph with the slider (arrow keys) or by pointing at the graph.",
        ),
      ),
      plot.svg,
      el("div", { class: "ex-controls" }, [time.element]),
      el("div", { class: "ex-readouts" }, readouts),
      description.element,
    ]);
  }

  function build(root, data) {
    var history = M.momentumHistory(data.times, data.momenta);
    var mass = data.mass;
    var t0 = data.times[0],
      t1 = data.times[data.times.length - 1];
    var title = el("p", { class: "ex-title", id: X.nextId("title") }, "Explore: reading the momentum\u2013time graph");
    var time = new X.Quantity({
      label: "Time along the graph",
      unit: "s",
      unitSpoken: "seconds",
      min: t0,
      max: t1,
      step: 0.1,
      value: (data.times[0] + data.times[1]) / 2,
      onChange: show,
    });
    var r = X.nameReadouts({
      t: new X.Readout("Time t", "s"),
      p: new X.Readout("Momentum p", P),
      v: new X.Readout("Velocity v = p / m", MS),
      f: new X.Readout("Gradient = resultant force F", "N"),
      a: new X.Readout("Acceleration a = F / m", MS2),
    });
    var pMax = Math.max.apply(null, data.momenta),
      pMin = Math.min(0, Math.min.apply(null, data.momenta));
    var plot = new X.Plot({
      width: X.widthFor(root),
      height: 280,
      margin: [16, 16, 44, 72],
      xLabel: "time t / s",
      yLabel: "momentum p / kg m s\u207b\u00b9",
      label: "Momentum of the " + fmt(mass) + " kg car against time",
    });
    var description = new X.Description();

    var readouts = [r.t.element, r.p.element, r.v.element, r.f.element, r.a.element];
    root.appendChild(readerPanel(mass, title, plot, time, readouts, description));
    plot.setDomain(t0, t1, pMin, pMax * 1.15, { yTicks: 4 });
    plot.data.appendChild(svg("path", { class: "ex-line ex-a", d: plot.path(data.times, data.momenta) }));
    var highlight = plot.data.appendChild(svg("path", { class: "ex-segment" }));
    var cursor = plot.marks.appendChild(svg("g"));
    plot.scrub(function (t) {
      time.set(Math.round(t * 10) / 10);
    });

    function show() {
      var t = time.value;
      var reading = { t: t, p: history.momentumAt(t), v: history.velocityAt(t, mass), f: history.forceAt(t) };
      r.t.set(t);
      r.p.set(reading.p);
      r.v.set(reading.v);
      r.f.set(reading.f);
      r.a.set(reading.f / mass);
      var i = segmentOf(data.times, t);
      var ta = data.times[i],
        tb = data.times[i + 1];
      highlight.setAttribute("d", plot.path([ta, tb], [data.momenta[i], data.momenta[i + 1]]));
      drawCursor(plot, cursor, reading);
      description.set(describeReading(reading, mass, ta, tb));
    }

    show();
  }

  X.register("momentum-time-reader", build);
})();
