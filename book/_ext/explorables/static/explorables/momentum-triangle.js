/* 2D momentum triangle: the incoming momentum is fixed, the reader sets P's momentum
 * after (size and angle); Q's follows from conservation along and across the line and
 * is drawn tip to tail. Physics: ExplorableModels.missingMomentum (twin of
 * physics_figures.models.missing_momentum). */
(function () {
  "use strict";
  var X = window.Explorables;
  var M = window.ExplorableModels;
  var el = X.el,
    svg = X.svg,
    fmt = X.fmt;

  var NS = "N s";
  var PAD = 46;

  function triangleReadouts() {
    return X.nameReadouts({
      pAlong: new X.Readout("P along the line", NS),
      pAcross: new X.Readout("P across the line", NS),
      qAlong: new X.Readout("Q along the line", NS),
      qAcross: new X.Readout("Q across the line (other side)", NS),
      q: new X.Readout("Momentum of Q", NS),
      phi: new X.Readout("Angle of Q to the line (other side)", "\u00b0"),
    });
  }

  /* The panel: title, the two hints, the sliders, the drawing, the read-outs, the energy verdict
   * and the description. */
  function trianglePanel(pIn, title, controls, picture, r, energy, description) {
    return el("section", { class: "ex-panel", "aria-labelledby": title.id }, [
      title,
      el(
        "p",
        { class: "ex-hint" },
        X.joinUnits(
          "Puck P (momentum " +
            fmt(pIn) +
            " " +
            NS +
            ") hits puck Q at rest. Set P\u2019s momentum afterwards; Q\u2019s follows from conservation of momentum along and across the original line.",
        ),
      ),
      el(
        "p",
        { class: "ex-hint ex-energy-note" },
        "Momentum alone allows every setting here, even ones in which the pucks would leave with more kinetic energy than P brought in. A real collision cannot gain kinetic energy (only an explosion, with energy from a store, can), so those outcomes never happen. Which ones they are depends on the masses: the line below works it out for pucks of equal mass.",
      ),
      el("div", { class: "ex-controls" }, controls),
      picture,
      el("div", { class: "ex-readouts" }, [
        r.pAlong.element,
        r.pAcross.element,
        r.qAlong.element,
        r.qAcross.element,
        r.q.element,
        r.phi.element,
      ]),
      energy,
      description.element,
    ]);
  }

  /* The energy verdict for pucks of equal mass m: E_k = p^2 / 2m, so the kinetic energy after
   * over before is (p_P^2 + p_Q^2) / p_before^2. */
  function showEnergy(energy, pIn, p, q) {
    var kept = (p * p + q.magnitude * q.magnitude) / (pIn * pIn);
    var gains = kept > 1 + 1e-9;
    energy.className = "ex-verdict ex-energy" + (gains ? " ex-refused" : "");
    // announced (ui.js) when the verdict changes: possible, elastic or impossible
    energy.setAttribute("data-announce", gains ? "gains" : kept > 1 - 1e-9 ? "elastic" : "possible");
    energy.textContent = X.joinUnits(
      "If P and Q had equal masses, the kinetic energy after would be " +
        fmt(100 * kept) +
        "% of that before: " +
        (gains
          ? "more than there was, so no real collision could end like this."
          : kept > 1 - 1e-9
            ? "all of it, an elastic collision (P and Q move off at right angles)."
            : "possible, an inelastic collision."),
    );
  }

  /* Conservation along and across the line, worked in words, then the energy verdict. */
  function describeTriangle(pIn, known, q, energyText) {
    return (
      "Along the line: " +
      fmt(pIn) +
      " = " +
      fmt(known[0]) +
      " + " +
      fmt(q.along) +
      ", so Q has " +
      fmt(q.along) +
      " " +
      NS +
      " along it. Across the line: 0 = " +
      fmt(known[1]) +
      " \u2212 " +
      fmt(q.across) +
      ", so Q has " +
      fmt(q.across) +
      " " +
      NS +
      " across it, on the other side. Q's momentum is " +
      fmt(q.magnitude) +
      " " +
      NS +
      " at " +
      fmt(q.angleDeg) +
      "\u00b0 to the line. Drawn tip to tail, P's and Q's arrows end where the arrow before ends: it is their resultant. " +
      energyText
    );
  }

  /* Where O (the tail), T (the tip of the momentum before) and K (the tip of P's) are drawn: the
   * triangle scaled to fit the picture and centred in it. */
  function trianglePoints(view, pIn, known) {
    var W = view.W,
      H = view.H,
      kx = known[0],
      ky = known[1];
    var x0 = Math.min(0, kx),
      x1 = pIn,
      y1 = Math.max(ky, 0.45 * pIn),
      y0 = -0.12 * pIn;
    var s = Math.min((W - PAD - view.padRight) / (x1 - x0), (H - 2 * PAD) / (y1 - y0));
    var ox = PAD + (W - PAD - view.padRight - s * (x1 - x0)) / 2 - s * x0;
    var oy = H - PAD + s * y0 - (H - 2 * PAD - s * (y1 - y0)) / 2;
    function at(x, y) {
      return [ox + s * x, oy - s * y];
    }
    return { O: at(0, 0), T: at(pIn, 0), K: at(kx, ky) };
  }

  /* The three arrows, tip to tail, with their labels (short ones on a phone). */
  function drawArrows(picture, view, pts, pIn, pSize, q) {
    var O = pts.O,
      T = pts.T,
      K = pts.K;
    picture.appendChild(X.arrow(O[0], O[1] + 22, T[0], T[1] + 22, "ex-ink", 12));
    picture.appendChild(
      svg(
        "text",
        { class: "ex-arrow-label", x: (O[0] + T[0]) / 2, y: O[1] + 42, "text-anchor": "middle" },
        "before: " + fmt(pIn) + " " + NS,
      ),
    );
    picture.appendChild(X.arrow(O[0], O[1], K[0], K[1], "ex-a", 12));
    picture.appendChild(X.arrow(K[0], K[1], T[0], T[1], "ex-b", 12));
    var pLeft = (O[0] + K[0]) / 2 > (view.narrow ? 30 : 110); // P's label left of its arrow if there is room
    picture.appendChild(
      svg(
        "text",
        {
          class: "ex-arrow-label ex-a-text",
          x: (O[0] + K[0]) / 2 + (pLeft ? -10 : 10),
          y: (O[1] + K[1]) / 2 - 8,
          "text-anchor": pLeft ? "end" : "start",
        },
        view.narrow ? "P" : "P " + fmt(pSize) + " " + NS,
      ),
    );
    picture.appendChild(
      svg(
        "text",
        { class: "ex-arrow-label ex-b-text", x: (K[0] + T[0]) / 2 + 10, y: (K[1] + T[1]) / 2 - 8 },
        view.narrow ? "Q" : "Q " + fmt(q.magnitude) + " " + NS,
      ),
    );
  }

  /* Q's components along and across, labelled beside the dashed lines. */
  function labelComponents(picture, pts, q) {
    var T = pts.T,
      K = pts.K;
    var my = (K[1] + T[1]) / 2; // written down the dashed line, so it needs little room
    picture.appendChild(
      svg(
        "text",
        {
          class: "ex-tick",
          x: T[0] + 6,
          y: my,
          "text-anchor": "middle",
          transform: "rotate(90 " + (T[0] + 6) + " " + my + ")",
        },
        "across " + fmt(q.across),
      ),
    );
    picture.appendChild(
      svg(
        "text",
        { class: "ex-tick", x: (K[0] + T[0]) / 2, y: K[1] - 6, "text-anchor": "middle" },
        "along " + fmt(q.along),
      ),
    );
  }

  // an arc at centre c from angle a0 to a1 (degrees, anticlockwise, y up) with a label
  function drawArc(picture, c, radius, a0, a1, label, side) {
    var p0 = [c[0] + radius * Math.cos((a0 * Math.PI) / 180), c[1] - radius * Math.sin((a0 * Math.PI) / 180)];
    var p1 = [c[0] + radius * Math.cos((a1 * Math.PI) / 180), c[1] - radius * Math.sin((a1 * Math.PI) / 180)];
    var large = a1 - a0 > 180 ? 1 : 0;
    picture.appendChild(
      svg("path", {
        class: "ex-arc",
        d: "M" + p0[0] + " " + p0[1] + "A" + radius + " " + radius + " 0 " + large + " 0 " + p1[0] + " " + p1[1],
      }),
    );
    var mid = (((a0 + a1) / 2) * Math.PI) / 180;
    picture.appendChild(
      svg(
        "text",
        {
          class: "ex-tick",
          x: c[0] + (radius + 8) * Math.cos(mid) + (side > 0 ? 4 : -4),
          y: c[1] - (radius + 8) * Math.sin(mid) - 2,
          "text-anchor": side > 0 ? "start" : "end",
        },
        label,
      ),
    );
  }

  /* The whole drawing for P's momentum pSize at theta and Q's momentum q. */
  function drawTriangle(picture, view, pIn, pSize, theta, known, q) {
    X.clear(picture);
    var pts = trianglePoints(view, pIn, known);
    var O = pts.O,
      T = pts.T,
      K = pts.K;
    picture.appendChild(svg("line", { class: "ex-guide", x1: 4, x2: view.W - 4, y1: O[1], y2: O[1] }));
    // Q's components, tip to tail: along then across
    picture.appendChild(svg("path", { class: "ex-component", d: "M" + K[0] + " " + K[1] + "H" + T[0] + "V" + T[1] }));
    drawArrows(picture, view, pts, pIn, pSize, q);
    if (known[1] > 1e-9) labelComponents(picture, pts, q);
    var narrow = view.narrow;
    if (pSize > 0 && theta > 0)
      drawArc(picture, O, 34, 0, theta, narrow ? "\u03b8" : "\u03b8 = " + fmt(theta) + "\u00b0", 1);
    if (q.magnitude > 0 && q.angleDeg > 0)
      drawArc(picture, T, 40, 180 - q.angleDeg, 180, narrow ? "\u03c6" : "\u03c6 = " + fmt(q.angleDeg) + "\u00b0", -1);
    picture.appendChild(svg("circle", { class: "ex-point", cx: O[0], cy: O[1], r: 3 }));
  }

  function build(root, data) {
    var pIn = data.momentumBefore;
    var W = X.widthFor(root),
      H = Math.round(Math.max(260, W * 0.52));
    // on a phone the drawing keeps short labels (the numbers are in the read-outs below)
    var narrow = W < 480;
    var view = { W: W, H: H, narrow: narrow, padRight: narrow ? 30 : 100 };
    var title = el("p", { class: "ex-title", id: X.nextId("title") }, "Explore: the momentum triangle");
    var size = new X.Quantity({
      label: "Momentum of P after",
      unit: NS,
      unitSpoken: "newton seconds",
      min: 0,
      max: pIn,
      step: 0.01,
      value: data.momentumKnown,
      onChange: update,
    });
    var angle = new X.Quantity({
      label: "Angle of P to its old line",
      unit: "\u00b0",
      unitSpoken: "degrees",
      min: 0,
      max: 180,
      step: 1,
      value: data.angleKnown,
      onChange: update,
    });
    var r = triangleReadouts();
    var picture = svg("svg", {
      viewBox: "0 0 " + W + " " + H,
      class: "ex-plot ex-triangle",
      role: "img",
      "aria-label": "Momentum before, and the momenta of P and Q after, drawn tip to tail",
    });
    var description = new X.Description();
    var energy = el("p", { class: "ex-verdict ex-energy", "data-announce": "" });
    var controls = [size.element, angle.element];
    root.appendChild(trianglePanel(pIn, title, controls, picture, r, energy, description));

    function update() {
      var p = size.value,
        theta = angle.value;
      var known = M.components(p, theta);
      var q = M.missingMomentum(pIn, p, theta);
      r.pAlong.set(known[0]);
      r.pAcross.set(known[1]);
      r.qAlong.set(q.along);
      r.qAcross.set(q.across);
      r.q.set(q.magnitude);
      r.phi.set(q.angleDeg);
      drawTriangle(picture, view, pIn, p, theta, known, q);
      showEnergy(energy, pIn, p, q);
      description.set(describeTriangle(pIn, known, q, energy.textContent));
    }

    update();
  }

  X.register("momentum-triangle", build);
})();
