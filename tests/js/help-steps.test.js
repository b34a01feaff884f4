// Help before the answer's step selection (book/_ext/questions/static/help-steps.js) and the
// slips the engine names as mistakes (marking.js slipName), run with `node --test tests/js`.
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const STATIC = path.join(__dirname, "..", "..", "book", "_ext", "questions", "static");
const { steps, numbersIn, plain } = require(path.join(STATIC, "help-steps.js"));
const engine = require(path.join(STATIC, "marking.js"));

function line(part, code, roles, html) {
  return { part: part, code: code, roles: roles, html: html };
}

// A wall bounce, as the bank writes it: a C1, the A1 with the answer, the direction's B1.
const bounce = {
  id: "bounce",
  parts: [
    { id: "a", kind: "numeric", value: 4.0, revisit: "Take one direction as positive.", alternatives: [] },
    { id: "b", kind: "numeric", value: 200.0, revisit: "", alternatives: [] },
    { id: "c", kind: "mcq", options: [] },
  ],
  marks: [
    line("a", "C1", ["method"], "Δp = mv − mu = 0.16 × 10 − 0.16 × (−15)"),
    line("a", "A1", ["answer"], "= 4.0 N s"),
    line("a", "B1", ["direction"], "away from the wall"),
    line("b", "C1", ["method"], "F = Δp / Δt = 4.0 / 0.020"),
    line("b", "C1", ["method"], "so F = 200 N on the ball"),
    line("b", "A1", ["answer"], "= 2.0 × 10² N"),
    line("c", "B1", ["answer"], "C"),
  ],
};

test("a part's steps are its revisit hint, then its mark lines but the answer's and the direction's", () => {
  assert.deepEqual(steps(bounce, bounce.parts[0]), [
    { text: "Take one direction as positive." },
    { html: "Δp = mv − mu = 0.16 × 10 − 0.16 × (−15)" },
  ]);
});

test("a line that holds the part's answer is left out, so no step gives it away", () => {
  // "so F = 200 N" is the answer before its A1: not a step; (a)'s 4.0 in (b)'s line is (a)'s
  assert.deepEqual(steps(bounce, bounce.parts[1]), [{ html: "F = Δp / Δt = your answer to (a) / 0.020" }]);
});

// A momentum-time graph, as the bank writes it: two readings, then the force from them.
const graph = {
  id: "graph",
  parts: [
    { id: "a", kind: "graph", value: 2.4, unit: "N s", revisit: "" },
    { id: "b", kind: "graph", value: -1.6, unit: "N s", revisit: "" },
    { id: "c", kind: "numeric", value: 133.3, unit: "N", revisit: "F = Δp / Δt", alternatives: [] },
  ],
  marks: [
    line("a", "B1", ["answer"], "2.4 N s"),
    line("b", "B1", ["answer"], "−1.6 N s (negative: away from the wall)"),
    line("c", "C1", ["method"], "F = Δp / Δt = (−1.6 − 2.4) / 0.030"),
    line("c", "A1", ["answer"], "= 130 N"),
  ],
  givens: [{ value: 0.03, unit: "s" }],
};

test("a later part's steps never print an earlier part's answer: they say 'your answer to (a)'", () => {
  assert.deepEqual(steps(graph, graph.parts[2]), [
    { text: "F = Δp / Δt" },
    { html: "F = Δp / Δt = (your answer to (b) − your answer to (a)) / 0.030" },
  ]);
  // of two answers of one size, the one whose sign is written; a reading of 1 s.f. too
  const same = JSON.parse(JSON.stringify(graph));
  same.parts[0].value = 0.5;
  same.parts[1].value = -0.5;
  same.marks[2].html = "F = Δp / Δt = (−0.5 − 0.5) / 0.030";
  assert.equal(steps(same, same.parts[2])[1].html, "F = Δp / Δt = (your answer to (b) − your answer to (a)) / 0.030");
  // a number with another unit of its own is not the earlier answer
  const energy = JSON.parse(JSON.stringify(graph));
  energy.marks[2].html = "after = ½ × 0.50 × 2.4<sup>2</sup> = 2.4 J";
  assert.equal(steps(energy, energy.parts[2])[1].html, "after = ½ × 0.50 × your answer to (a)<sup>2</sup> = 2.4 J");
});

test("a number that is an earlier answer and a given of another unit is in doubt: no step", () => {
  const doubt = JSON.parse(JSON.stringify(graph));
  doubt.givens.push({ value: 2.4, unit: "kg" }); // a 2.4 kg mass: which is the 2.4 in the line?
  assert.deepEqual(steps(doubt, doubt.parts[2]), [{ text: "F = Δp / Δt" }]);
  const moon = JSON.parse(JSON.stringify(graph));
  moon.givens.push({ value: 2.4, unit: "N s" }); // a given of (a)'s own unit is (a)'s answer
  assert.equal(steps(moon, moon.parts[2])[1].html, "F = Δp / Δt = (your answer to (b) − your answer to (a)) / 0.030");
});

test("a choice, an explanation, or a part with nothing to show has no steps", () => {
  assert.deepEqual(steps(bounce, bounce.parts[2]), []);
  const alone = {
    parts: [{ id: "a", kind: "graph", value: 3.2, revisit: "" }],
    marks: [line("a", "B1", ["answer"], "3.2 m")],
  };
  assert.deepEqual(steps(alone, alone.parts[0]), []); // its one line is the answer (a B1 that gives it)
});

test("the answer, by its last A1, is left out even where an earlier line is an answer line too", () => {
  const two = {
    parts: [{ id: "a", kind: "numeric", value: -2.4, revisit: "", alternatives: [{ value: 7.77 }] }],
    marks: [
      line("a", "B1", ["answer"], "relative speed = 4.5 m s<sup>−1</sup>"),
      line("a", "C1", ["method"], "v = 7.77 − 5.0"), // the accepted alternative: a give-away too
      line("a", "C1", ["method"], "−2.40 is what A does"), // its value, to 3 s.f., with its sign
      line("a", "A1", ["answer", "direction"], "v<sub>A</sub> = −2.4 m s<sup>−1</sup>"),
    ],
  };
  assert.deepEqual(steps(two, two.parts[0]), [{ html: "relative speed = 4.5 m s<sup>−1</sup>" }]);
});

test("numbers are read as the book prints them, never a unit's power", () => {
  const read = numbersIn(plain("U = 920 × 0.80 × 10<sup>−6</sup> = 7.4 × 10⁻⁶ m<sup>3</sup>; 80 000 / 4000"));
  assert.deepEqual(
    read.map((n) => n.value),
    [920, 0.8e-6, 7.4e-6, 80000, 4000],
  );
});

test("the engine's sign, unit and 1 s.f. outcomes each have a name for the record", () => {
  const part = {
    kind: "numeric",
    value: -2.0,
    unit: "m s^-1",
    quantity: "velocity",
    direction: "signed",
    positive: "to the right",
    mistakes: [],
  };
  const name = (answer) => engine.slipName(engine.mark(part, answer).code);
  assert.equal(name({ value: "2.0", unit: "m s^-1" }), "sign or direction");
  assert.equal(name({ value: "-2.0", unit: "" }), "unit missing or wrong");
  assert.equal(name({ value: "-2.0", unit: "kg" }), "unit missing or wrong");
  assert.equal(name({ value: "-2.0", unit: "M S^-1" }), "unit missing or wrong");
  const size = Object.assign({}, part, { value: 2.04, direction: "none" });
  assert.equal(engine.slipName(engine.mark(size, { value: "2", unit: "m s^-1" }).code), "1 s.f. answer");
  assert.equal(engine.slipName(engine.mark(size, { value: "2.0", unit: "m s^-1" }).code), undefined);
  const table = require(path.join(__dirname, "..", "..", "physics_figures", "marking_rules.json"));
  assert.deepEqual(Object.keys(table.slips.names).sort(), [
    "1 s.f. answer",
    "sign or direction",
    "unit missing or wrong",
  ]);
});
