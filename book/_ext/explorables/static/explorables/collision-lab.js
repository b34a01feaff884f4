/* Collision lab: two bodies on a line, A on the left and B on the right, right positive.
 * Physics: ExplorableModels.collisionLab (twin of physics_figures.explorables.collision_lab). */
(function () {
  "use strict";
  var X = window.Explorables;
  var M = window.ExplorableModels;
  var el = X.el,
    svg = X.svg,
    fmt = X.fmt;

  var MS = "m s\u207b\u00b9",
    P = "kg m s\u207b\u00b9";
  var KINDS = {
    elastic: "Elastic (kinetic energy kept)",
    stick: "Stick together",
    loss: "Lose a chosen percentage of the kinetic energy",
    explosion: "Explosion from rest (pushed apart)",
  };

  /* The radio buttons of the kinds of interaction; onPick(name) when the reader picks one. */
  function kindRadios(data, titleId, onPick) {
    var radios = el("fieldset", { class: "ex-kinds" }, [el("legend", {}, "Kind of interaction")]);
    data.kinds.forEach(function (name) {
      var id = X.nextId("kind");
      var input = el("input", {
        type: "radio",
        name: id.replace(/-\d+$/, "") + "-" + titleId,
        id: id,
        value: name,
        checked: name === data.kind,
      });
      input.addEventListener("change", function () {
        if (input.checked) onPick(name);
      });
      radios.appendChild(el("div", { class: "ex-radio" }, [input, el("label", { for: id }, KINDS[name])]));
    });
    return radios;
  }

  /* The sliders: both masses and velocities before, the energy lost and A's velocity after an explosion. */
  function labQuantities(data, onChange) {
    return {
      m1: new X.Quantity({
        label: "Mass of A",
        unit: "kg",
        unitSpoken: "kilograms",
        min: 0.1,
        max: 10,
        step: 0.1,
        value: data.m1,
        onChange: onChange,
      }),
      u1: new X.Quantity({
        label: "Velocity of A before (right +)",
        unit: MS,
        unitSpoken: "metres per second",
        min: -10,
        max: 10,
        step: 0.1,
        value: data.u1,
        onChange: onChange,
      }),
      m2: new X.Quantity({
        label: "Mass of B",
        unit: "kg",
        unitSpoken: "kilograms",
        min: 0.1,
        max: 10,
        step: 0.1,
        value: data.m2,
        onChange: onChange,
      }),
      u2: new X.Quantity({
        label: "Velocity of B before (right +)",
        unit: MS,
        unitSpoken: "metres per second",
        min: -10,
        max: 10,
        step: 0.1,
        value: data.u2,
        onChange: onChange,
      }),
      lost: new X.Quantity({
        label: "Kinetic energy lost",
        unit: "%",
        unitSpoken: "per cent",
        min: -20,
        max: 100,
        step: 1,
        value: 10,
        onChange: onChange,
      }),
      va: new X.Quantity({
        label: "Velocity of A after the explosion (right +)",
        unit: MS,
        unitSpoken: "metres per second",
        min: -10,
        max: 10,
        step: 0.1,
        value: data.velocityAAfter,
        onChange: onChange,
      }),
    };
  }

  // An explosion starts on the notes' spring trolleys (0.20 kg and 0.30 kg); going back to a
  // collision brings back the masses the reader had there.
  function massSwitcher(q, data) {
    var masses = { explosion: [data.explosionM1, data.explosionM2], collision: null };
    return function switchMasses(wasExplosion, isExplosion) {
      if (wasExplosion === isExplosion) return;
      var leaving = [q.m1.value, q.m2.value],
        coming = isExplosion ? masses.explosion : masses.collision;
      masses[isExplosion ? "collision" : "explosion"] = leaving;
      if (!coming) return;
      q.m1.value = coming[0];
      q.m1.show();
      q.m2.value = coming[1];
      q.m2.show();
    };
  }

  // the table's rows: the outputs' name, the quantity and its unit
  var ROWS = [
    ["pa", "Momentum of A", P],
    ["pb", "Momentum of B", P],
    ["p", "Total momentum", P],
    ["ea", "Kinetic energy of A", "J"],
    ["eb", "Kinetic energy of B", "J"],
    ["e", "Total kinetic energy", "J"],
    ["rel", "Relative speed (approach / separation)", MS],
  ];

  /* The table of each quantity before and after; out[name] is its pair of <output>s. */
  function beforeAfterTable() {
    var out = {};
    var tbody = el("tbody");
    ROWS.forEach(function (row) {
      // data-label and data-unit: how the announcer names the cell (ui.js)
      var before = el("output", {
        "aria-live": "off",
        name: row[0] + "-before",
        "data-label": row[1] + " before",
        "data-unit": row[2],
      });
      var after = el("output", {
        "aria-live": "off",
        name: row[0] + "-after",
        "data-label": row[1] + " after",
        "data-unit": row[2],
      });
      out[row[0]] = [before, after];
      tbody.appendChild(
        el("tr", {}, [
          el("th", { scope: "row" }, [row[1], el("span", { class: "ex-unit" }, " / " + row[2])]),
          el("td", {}, before),
          el("td", {}, after),
        ]),
      );
    });
    var table = el("table", { class: "ex-table" }, [
      el("caption", { class: "ex-sr" }, "Momentum, kinetic energy and relative speed before and after"),
      el(
        "thead",
        {},
        el("tr", {}, [
          el("th", { scope: "col" }, "Quantity"),
          el("th", { scope: "col" }, "Before"),
          el("th", { scope: "col" }, "After"),
        ]),
      ),
      tbody,
    ]);
    return { table: table, out: out };
  }

  function setPair(out, name, before, after, sf) {
    [before, after].forEach(function (value, i) {
      var o = out[name][i];
      o.setAttribute("data-value", value === null ? "" : String(value));
      o.textContent = X.joinUnits(fmt(value, { sf: sf || 3 }));
    });
  }

  /* Each body's momentum and kinetic energy, the totals and the relative speeds, before and after. */
  function fillTable(out, lab, m1, m2) {
    var a = lab.after || [null, null],
      b = lab.before;
    setPair(out, "pa", m1 * b[0], a[0] === null ? null : m1 * a[0]);
    setPair(out, "pb", m2 * b[1], a[1] === null ? null : m2 * a[1]);
    setPair(out, "p", lab.momentumBefore, lab.momentumAfter);
    setPair(out, "ea", 0.5 * m1 * b[0] * b[0], a[0] === null ? null : 0.5 * m1 * a[0] * a[0]);
    setPair(out, "eb", 0.5 * m2 * b[1] * b[1], a[1] === null ? null : 0.5 * m2 * a[1] * a[1]);
    setPair(out, "e", lab.kineticEnergyBefore, lab.kineticEnergyAfter);
    setPair(out, "rel", lab.approachSpeed, lab.separationSpeed);
  }

  /* What happens to the kinetic energy, in words: supplied (an explosion), kept or partly lost. */
  function energyStory(lab, explosion) {
    var e0 = lab.kineticEnergyBefore,
      e1 = lab.kineticEnergyAfter;
    if (explosion) {
      return (
        "Kinetic energy rises from 0 to " + fmt(e1) + " J, supplied by the energy stored in the spring or explosive."
      );
    }
    if (Math.abs(lab.percentLost) < 1e-9) {
      return (
        "Kinetic energy is kept (" +
        fmt(e0) +
        " J before and after), so the collision is elastic: the relative speed of separation equals that of approach, " +
        fmt(lab.approachSpeed) +
        " " +
        MS +
        "."
      );
    }
    return (
      "Kinetic energy falls from " +
      fmt(e0) +
      " J to " +
      fmt(e1) +
      " J (" +
      fmt(lab.percentLost, { decimals: 1 }) +
      "% transferred to other forms), so the collision is inelastic: the bodies separate at " +
      fmt(lab.separationSpeed) +
      " " +
      MS +
      ", slower than they approached at " +
      fmt(lab.approachSpeed) +
      " " +
      MS +
      "."
    );
  }

  /* The verdict (possible, or the refusal with its numbers); returns the description's text. */
  function showVerdict(verdict, lab, refusals, explosion) {
    verdict.setAttribute("data-announce", lab.refusal || "possible");
    if (lab.refusal) {
      verdict.className = "ex-verdict ex-refused";
      verdict.textContent = X.joinUnits(X.fill(refusals[lab.refusal], lab.numbers));
      return "Refused. " + verdict.textContent;
    }
    verdict.className = "ex-verdict";
    verdict.textContent = X.joinUnits(
      "Momentum is conserved: " +
        fmt(lab.momentumBefore) +
        " " +
        P +
        " before and after. " +
        energyStory(lab, explosion),
    );
    var after = lab.after || [null, null];
    return (
      "After: A moves at " +
      fmt(after[0]) +
      " " +
      MS +
      " and B at " +
      fmt(after[1]) +
      " " +
      MS +
      " (positive to the right). " +
      verdict.textContent
    );
  }

  /* The scene: the two bodies before (top) and after (bottom), or "Not possible". */
  function drawScene(view, lab, m1, m2) {
    var scene = view.scene,
      SW = view.width;
    X.clear(scene);
    var widths = [m1, m2].map(function (m) {
      return 26 + 34 * Math.sqrt(m / 10);
    });
    scene.appendChild(svg("text", { class: "ex-scene-label", x: 6, y: 22 }, "Before"));
    scene.appendChild(svg("text", { class: "ex-scene-label", x: 6, y: 122 }, "After"));
    [0, 100].forEach(function (y0) {
      scene.appendChild(svg("line", { class: "ex-track", x1: 0, x2: SW, y1: y0 + 78, y2: y0 + 78 }));
    });
    var gap = lab.kind === "explosion" ? 0 : Math.min(120, SW * 0.2);
    drawRow(view, 20, lab.before, widths, gap, lab.kind === "explosion" ? "at rest, pushed apart by a spring" : null);
    if (lab.after)
      drawRow(
        view,
        120,
        lab.after,
        widths,
        lab.kind === "stick" ? 0 : Math.min(120, SW * 0.2) + (lab.kind === "explosion" ? 40 : 0),
      );
    else
      scene.appendChild(
        svg(
          "text",
          { class: "ex-scene-label ex-refused-text", x: view.mid, y: 160, "text-anchor": "middle" },
          "Not possible (see the message above)",
        ),
      );
  }

  // one row of the scene: the blocks, with an arrow and a label for each velocity
  function drawRow(view, y0, velocities, widths, gap, note) {
    var scene = view.scene,
      MID = view.mid;
    var left = MID - gap / 2 - widths[0],
      right = MID + gap / 2;
    var together = gap === 0;
    [
      [left, widths[0], "A", "ex-a"],
      [right, widths[1], "B", "ex-b"],
    ].forEach(function (blk, i) {
      var h = 22 + widths[i] * 0.35;
      scene.appendChild(
        svg("rect", { class: "ex-block " + blk[3], x: blk[0], y: y0 + 58 - h, width: blk[1], height: h, rx: 3 }),
      );
      scene.appendChild(
        svg(
          "text",
          { class: "ex-block-label", x: blk[0] + blk[1] / 2, y: y0 + 63 - h / 2, "text-anchor": "middle" },
          blk[2],
        ),
      );
      if (!together) velocityArrow(view, blk[0] + blk[1] / 2, y0 + 10, velocities[i], blk[3]);
    });
    if (together) {
      if (note)
        scene.appendChild(svg("text", { class: "ex-arrow-label", x: MID, y: y0 + 4, "text-anchor": "middle" }, note));
      else velocityArrow(view, MID, y0 + 10, velocities[0], "ex-ink", " together");
    }
  }

  function velocityArrow(view, x, y, v, className, extra) {
    var LONGEST = view.longest;
    var len = Math.min(LONGEST, (Math.abs(v) * LONGEST) / 10);
    if (Math.abs(v) > 1e-9) view.scene.appendChild(X.arrow(x, y, x + (v > 0 ? len : -len), y, className, 9));
    view.scene.appendChild(
      svg(
        "text",
        { class: "ex-arrow-label", x: x, y: y - 6, "text-anchor": "middle" },
        Math.abs(v) > 1e-9 ? fmt(v) + " " + MS + (extra || "") : "at rest",
      ),
    );
  }

  function labPanel(title, radios, q, verdict, scene, table, readouts, description) {
    return el("section", { class: "ex-panel", "aria-labelledby": title.id }, [
      title,
      el(
        "p",
        { class: "ex-hint" },
        "A starts on the left of B. Velocities are positive to the right. Type a value or use the sliders.",
      ),
      radios,
      el("div", { class: "ex-controls" }, [
        q.m1.element,
        q.u1.element,
        q.m2.element,
        q.u2.element,
        q.lost.element,
        q.va.element,
      ]),
      verdict,
      scene,
      table,
      el("div", { class: "ex-readouts" }, readouts),
      description.element,
    ]);
  }

  function build(root, data) {
    var kind = data.kind;
    var title = el("p", { class: "ex-title", id: X.nextId("title") }, "Explore: a collision lab");
    var radios = kindRadios(data, title.id, function (name) {
      switchMasses(kind === "explosion", name === "explosion");
      kind = name;
      update();
    });
    var q = labQuantities(data, update);
    var switchMasses = massSwitcher(q, data);
    var tableParts = beforeAfterTable();
    var percent = new X.Readout("Kinetic energy lost", "%", { decimals: 1 });
    var most = new X.Readout("Most that can be lost (sticking together)", "%", { decimals: 1 });
    X.nameReadouts({ percent: percent, most: most });
    // not a live region: the announcer says it when the set-up turns possible or impossible
    // (its data-announce key is the refusal, ui.js)
    var verdict = el("p", { class: "ex-verdict", "data-announce": "possible" });
    var SW = X.widthFor(root);
    var scene = svg("svg", {
      viewBox: "0 0 " + SW + " 200",
      class: "ex-plot ex-scene",
      role: "img",
      "aria-label": "The two bodies before and after, with their velocities",
    });
    var view = { scene: scene, width: SW, mid: SW / 2, longest: Math.min(110, SW * 0.17) };
    var description = new X.Description();
    var readouts = [percent.element, most.element];
    root.appendChild(labPanel(title, radios, q, verdict, scene, tableParts.table, readouts, description));

    function update() {
      var explosion = kind === "explosion";
      q.u1.element.hidden = explosion;
      q.u2.element.hidden = explosion;
      q.va.element.hidden = !explosion;
      q.lost.element.hidden = kind !== "loss";
      var m1 = q.m1.value,
        m2 = q.m2.value;
      var lab = M.collisionLab({
        kind: kind,
        m1: m1,
        u1: q.u1.value,
        m2: m2,
        u2: q.u2.value,
        velocityAAfter: q.va.value,
        percentLost: q.lost.value,
      });
      fillTable(tableParts.out, lab, m1, m2);
      percent.set(lab.percentLost);
      most.set(lab.mostPercentLost);
      percent.element.hidden = explosion;
      most.element.hidden = explosion;
      drawScene(view, lab, m1, m2);
      description.set(showVerdict(verdict, lab, data.refusals, explosion));
    }

    update();
  }

  X.register("collision-lab", build);
})();
