// The marking engine of book/_ext/questions/static/marking.js, run with `node --test tests/js`.
// Parts mirror the notes' Quick check (Notes, "Quick check" and "Answers").
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const { parseNumber, parseUnit, mark, splitValueAndUnit } = require(
  path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "marking.js"),
);

// Quick check 1(a): 15 N s, with named mistakes (values as physics_figures computes them).
const momentum = {
  value: 15,
  unit: "N s",
  units: "N s or kg m s^-1",
  quantity: "momentum",
  minSf: 2,
  checkSf: 3,
  direction: "none",
  revisit: "Force × time = change in momentum.",
  mistakes: [
    { name: "force divided by time", value: 5 / 3, feedback: "You divided the force by the time." },
    { name: "force times mass", value: 10, feedback: "You multiplied the force by the mass." },
    { name: "kinetic energy instead of momentum", value: 56.25, unit: "J", feedback: "That is the kinetic energy." },
  ],
};
// Quick check 3: 686.7 N and 11.619 m s^-2 upwards.
const drag = { value: 686.7, unit: "N", quantity: "force", direction: "none", revisit: "drag = weight", mistakes: [] };
const acceleration = {
  value: (1500 - 686.7) / 70,
  unit: "m s^-2",
  quantity: "acceleration",
  direction: "choice",
  choices: ["upwards", "downwards"],
  answerDirection: "upwards",
  revisit: "resultant = drag − weight",
  mistakes: [
    {
      name: "still falling",
      value: (1500 - 686.7) / 70,
      direction: "downwards",
      feedback: "She is still falling, but slowing down.",
    },
    { name: "drag as resultant", value: 1500 / 70, feedback: "You used the drag as the resultant force." },
  ],
};
// Quick check 4(a): -2.0 m s^-1, forwards positive.
const velocity = {
  value: -2.0,
  unit: "m s^-1",
  quantity: "velocity",
  direction: "signed",
  positive: "forwards",
  revisit: "momentum and relative speeds",
  mistakes: [{ name: "stops", value: 0, feedback: "It only stops for equal masses." }],
};
// Quick check 1(b) 7.5 m s^-1 and a time, for units and prefixes.
const speed = { value: 7.5, unit: "m s^-1", quantity: "speed", direction: "none", revisit: "v = p / m", mistakes: [] };
const time = { value: 3.0, unit: "s", quantity: "time", direction: "none", revisit: "Δt = Δp / F", mistakes: [] };
const mass = { value: 12, unit: "kg", quantity: "mass", direction: "none", revisit: "mass is the same", mistakes: [] };
const showThat = Object.assign({}, drag, { minSf: 3 });
// Notes, Momentum in two dimensions: Q moves off at 36.8° to the line.
const angle = {
  value: 36.8,
  unit: "°",
  units: "° (degrees)",
  quantity: "angle",
  direction: "none",
  revisit: "tan",
  mistakes: [],
};
// Quick check 2: the recoil speed, 1.0 m s^-1; the notes answer v = -1.0 (backwards).
const recoil = Object.assign({}, speed, { value: 1.0, signMeans: "it moves backwards" });
// Quick check 3(a) as physics_figures sends it: g = 10 named, g = 9.8 its own slip.
const dragG = Object.assign({}, drag, {
  mistakes: [{ name: "used g = 10 m s⁻²", value: 700, feedback: "You used g = 10 m s⁻²." }],
  gNineEight: 686.0,
});
// Practice 7(b): 14.3 N; the mass rounded to 1.5 kg part-way gives 14.7 N.
const rockWeight = {
  value: 14.3173,
  unit: "N",
  quantity: "weight",
  direction: "none",
  revisit: "W = mg",
  mistakes: [],
  roundedPartWay: [{ value: 14.715, rounded: "the mass to 1.5 kg" }],
};

function code(part, value, unit, direction) {
  return mark(part, { value: value, unit: unit, direction: direction }).code;
}

test("numbers in every usual form are read", () => {
  const forms = [
    ["1.5e3", 1500],
    ["1.5E3", 1500],
    ["1.5 x 10^3", 1500],
    ["1.5x10^3", 1500],
    ["1.5×10³", 1500],
    ["1.5 × 10^(3)", 1500],
    ["1.5*10**3", 1500],
    ["-0.25", -0.25],
    ["−0.25", -0.25],
    [".25", 0.25],
    ["+4.0", 4],
    ["2.5e-3", 0.0025],
    ["2.5 × 10⁻³", 0.0025],
    ["10^3", 1000],
    ["7.", 7],
  ];
  for (const [text, value] of forms) {
    const n = parseNumber(text);
    assert.equal(n.ok, true, text);
    assert.ok(Math.abs(n.value - value) < 1e-12 * Math.abs(value), `${text} -> ${n.value}`);
  }
});

test("refused forms get a message that says how to write them", () => {
  assert.match(parseNumber("1,500").message, /without the comma: 1500/);
  assert.match(parseNumber("1,5").message, /decimal point/);
  assert.match(parseNumber("10-3").message, /ten minus/);
  assert.match(parseNumber("1.5 x 10-3").message, /10\^-3/);
  assert.match(parseNumber("").message, /Type a number/);
  assert.match(parseNumber("about 5").message, /can't read/);
  assert.equal(code(momentum, "1,500", "N s"), "unreadable-number");
});

test("significant figures are counted as written", () => {
  const sf = (t) => {
    const n = parseNumber(t);
    return [n.sfMin, n.sfMax];
  };
  assert.deepEqual(sf("15"), [2, 2]);
  assert.deepEqual(sf("15.0"), [3, 3]);
  assert.deepEqual(sf("0.0250"), [3, 3]);
  assert.deepEqual(sf("1500"), [2, 4]); // trailing zeros of a whole number are ambiguous
  assert.deepEqual(sf("700"), [1, 3]);
  assert.deepEqual(sf("700."), [3, 3]);
  assert.deepEqual(sf("7.0e2"), [2, 2]);
  assert.deepEqual(sf("1.50 × 10^3"), [3, 3]);
  assert.deepEqual(sf("0.5"), [1, 1]);
});

test("the right answer passes in every usual form of its unit", () => {
  for (const unit of [
    "N s",
    "Ns",
    "N·s",
    "N*s",
    "kg m s^-1",
    "kg m/s",
    "kg m s⁻¹",
    "kg m s-1",
    "kgms-1",
    "kg ms^-1",
    "kg.m.s-1",
    "kg m s^(-1)",
  ]) {
    assert.equal(code(momentum, "15", unit), "correct", unit);
  }
  for (const unit of ["m s^-2", "m/s^2", "m/s²", "ms-2", "m s⁻²", "m/s/s"]) {
    assert.equal(code(acceleration, "11.6", unit, "upwards"), "correct", unit);
  }
  for (const unit of ["m s^-1", "m/s", "ms^-1", "ms-1", "m s⁻¹"])
    assert.equal(code(speed, "7.5", unit), "correct", unit);
  assert.equal(code(momentum, "15000", "g m s^-1"), "correct"); // a correct conversion is still correct
  assert.equal(code(momentum, "1.5e1", "N s"), "correct");
  assert.equal(code(momentum, "1.5 × 10^1", "N s"), "correct");
  assert.equal(code(momentum, "15 N s", ""), "correct"); // the unit typed into the value box
  assert.equal(code(speed, "27", "km h^-1"), "correct");
});

test("units are read into SI scale and dimensions", () => {
  const only = (t) => parseUnit(t).readings[0];
  assert.deepEqual(only("N s").dims, only("kg m/s").dims);
  assert.equal(only("g").scale, 1e-3);
  assert.equal(only("kN").scale, 1000);
  assert.deepEqual(
    parseUnit("ms").readings.map((r) => r.scale),
    [1e-3, 1],
  ); // millisecond, or metre second
  assert.equal(parseUnit("kg m//s").ok, false);
  assert.equal(parseUnit("furlongs").ok, false);
  assert.equal(parseUnit("").empty, true);
});

test("a prefix slip gets its own message", () => {
  const g = mark(momentum, { value: "15", unit: "g m s^-1" });
  assert.equal(g.code, "prefix");
  assert.match(g.message, /prefix/);
  assert.equal(code(time, "3.0", "ms"), "prefix");
  assert.equal(code(mass, "12", "g"), "prefix");
  assert.equal(code(drag, "687", "kN"), "prefix");
});

test("a unit of another quantity is named as such", () => {
  const joules = mark(momentum, { value: "15", unit: "J" });
  assert.equal(joules.code, "wrong-unit");
  assert.match(joules.message, /J is a unit of energy, not of momentum/);
  assert.match(joules.message, /number is right/);
  assert.match(mark(momentum, { value: "15", unit: "N" }).message, /N is a unit of force, not of momentum/);
  assert.match(mark(drag, { value: "687", unit: "kg" }).message, /kg is a unit of mass, not of force/);
  assert.match(mark(momentum, { value: "15", unit: "kg m" }).message, /kg m is not a unit of momentum/);
  assert.match(mark(momentum, { value: "15", unit: "newtons" }).message, /newtons is a unit of force, not of momentum/);
});

test("units written as words, and rad, are read", () => {
  const only = (t) => parseUnit(t).readings[0];
  for (const [words, symbols] of [
    ["newtons", "N"],
    ["newton", "N"],
    ["newton seconds", "N s"],
    ["metres per second", "m/s"],
    ["metre per second", "m/s"],
    ["meters per second", "m/s"],
    ["metres per second squared", "m/s^2"],
    ["degrees", "°"],
    ["degree", "°"],
    ["kilograms", "kg"],
  ]) {
    const a = only(words),
      b = only(symbols);
    assert.ok(a && Math.abs(a.scale - b.scale) < 1e-12 && a.dims.join() === b.dims.join(), words);
  }
  assert.ok(Math.abs(only("rad").scale - 180 / Math.PI) < 1e-12);
  assert.equal(code(drag, "687", "newtons"), "correct");
  assert.equal(code(speed, "7.5", "metres per second"), "correct");
  assert.equal(code(acceleration, "11.6", "metres per second squared", "upwards"), "correct");
  assert.equal(code(angle, "36.8", "degrees"), "correct");
  assert.equal(code(angle, "36.8", "degree"), "correct");
  assert.equal(code(angle, "36.8", "°"), "correct");
  assert.equal(code(angle, "36.8 degrees", ""), "correct");
  assert.equal(code(angle, "0.642", "rad"), "correct"); // 36.8° in radians
  assert.equal(code(angle, "36.8", "rad"), "angle-unit");
});

test("a missing unit is asked for", () => {
  const r = mark(momentum, { value: "15", unit: "" });
  assert.equal(r.code, "missing-unit");
  assert.equal(r.correct, false);
  assert.match(r.message, /N s or kg m s⁻¹/);
});

test("a ratio has no unit: a bare number is whole, a percentage with % is read as its fraction", () => {
  // Notes, "Elastic and inelastic collisions": 6.0 J of 24 J lost, a fraction 0.25 (25 %).
  const fraction = {
    value: 0.25,
    unit: "",
    units: "no unit (a fraction), or a percentage with %",
    quantity: "fraction",
    minSf: 2,
    checkSf: 3,
    direction: "none",
    revisit: "fraction lost = (E before − E after) / E before",
    mistakes: [{ name: "percentage without %", value: 25, feedback: "Write 25 % or 0.25." }],
  };
  assert.equal(code(fraction, "0.25", ""), "correct");
  assert.equal(code(fraction, "25", "%"), "correct");
  assert.equal(code(fraction, "25 %", ""), "correct");
  assert.equal(mark(fraction, { value: "25", unit: "" }).mistake, "percentage without %");
  assert.equal(code(fraction, "0.25", "J"), "wrong-unit"); // a fraction has no unit of energy
  assert.equal(code(fraction, "0.75", ""), "wrong");
});

test("default rule: 2 or more significant figures; fewer is wrong", () => {
  assert.equal(code(drag, "690", "N"), "correct"); // 2 s.f. (the zero may not count)
  assert.equal(code(drag, "687", "N"), "correct");
  assert.equal(code(drag, "686.7", "N"), "correct");
  assert.equal(code(drag, "686.70", "N"), "correct");
  assert.equal(code(acceleration, "12", "m s^-2", "upwards"), "correct");
  const few = mark(velocity, { value: "-2", unit: "m/s" });
  assert.equal(few.code, "too-few-sf");
  assert.equal(few.correct, false);
  assert.match(few.message, /^1 s\.f\.: the A1 needs 2 or more\./);
  const zeros = mark(Object.assign({}, drag, { value: 703.2 }), { value: "700", unit: "N" });
  assert.equal(zeros.code, "correct"); // 700 read as 2 s.f. is 703.2 rounded
});

test("a value right only to 1 s.f. is the key at 1 s.f.: too few figures, not wrong physics", () => {
  // 700, 7e2 and 7.0 × 10² are 686.7 to 1 s.f. (the last written with a zero after it); where
  // 700 is a named mistake's answer too (g = 10), the mistake is named (dragG below).
  for (const typed of ["700", "7e2", "7.0 × 10²"]) assert.equal(code(drag, typed, "N"), "too-few-sf", typed);
  for (const typed of ["60", "6e1"])
    assert.equal(code(Object.assign({}, drag, { value: 56.0 }), typed, "N"), "too-few-sf", typed);
  assert.equal(code(Object.assign({}, drag, { value: 225 }), "200", "N"), "too-few-sf");
  assert.equal(code(Object.assign({}, drag, { value: 0.275 }), "0.3", "N"), "too-few-sf");
  assert.equal(code(drag, "8e2", "N"), "wrong"); // not the key at any precision
  assert.equal(code(acceleration, "1e1", "m s^-2", "upwards"), "too-few-sf");
  assert.equal(code(dragG, "700", "N"), "mistake"); // 700 may be 3 s.f.: g = 10's answer, named
  assert.equal(mark(dragG, { value: "7.0 × 10²", unit: "N" }).mistake, "used g = 10 m s⁻²");
  assert.equal(code(dragG, "7e2", "N"), "too-few-sf"); // 1 s.f. is never read as a named mistake
});

test("the key to 1 s.f. written with a zero after it is the same 1 s.f. slip, with advice that leads on", () => {
  const force = Object.assign({}, drag, { value: 64.2 });
  for (const typed of ["60", "60.", "6.0e1", "6.0 × 10¹", "60.0"]) {
    const result = mark(force, { value: typed, unit: "N" });
    assert.equal(result.code, "too-few-sf", typed);
    assert.match(result.message, /^1 s\.f\.: the A1 needs 2 or more\. /, typed);
    assert.match(result.message, /Work to 3 s\.f\.; give 2 or more\.$/, typed);
    assert.doesNotMatch(result.message, /× 10|not 700/, typed); // no advice to add a zero
  }
  assert.match(mark(force, { value: "60.", unit: "N" }).message, /zeros written after it do not add figures/);
  assert.doesNotMatch(mark(force, { value: "6e1", unit: "N" }).message, /zeros/);
  assert.equal(code(force, "64", "N"), "correct");
  assert.equal(code(force, "70.", "N"), "wrong"); // not the key at any precision
  assert.equal(code(Object.assign({}, force, { value: 60.4 }), "60.", "N"), "correct"); // the key to 2 s.f.
});

test("a question can ask for more significant figures", () => {
  assert.equal(code(showThat, "687", "N"), "correct");
  assert.equal(code(showThat, "690", "N"), "too-few-sf"); // read as 2 s.f., not 3
  assert.match(mark(showThat, { value: "6.9e2", unit: "N" }).message, /^2 s\.f\.: the A1 needs 3 or more/);
});

test("intermediate values rounded to 3 s.f. still pass; only the working's own rounding is called rounding", () => {
  assert.equal(code(acceleration, "11.614", "m s^-2", "upwards"), "correct"); // 1500 − 687 then ÷ 70
  assert.equal(code(acceleration, "11.63", "m s^-2", "upwards"), "correct"); // g = 9.8, still 11.6
  // A last digit out by one is not, by itself, rounding: nothing in the working gives it.
  for (const [part, typed] of [
    [acceleration, "11.7"],
    [drag, "688"],
    [drag, "686.0"],
    [momentum, "16"],
  ]) {
    const r = mark(part, { value: typed, unit: part.unit, direction: "upwards" });
    assert.equal(r.code, "wrong", typed);
    assert.doesNotMatch(r.message, /round/i, typed);
  }
  const early = mark(rockWeight, { value: "14.7", unit: "N" });
  assert.equal(early.code, "rounded-part-way");
  assert.match(early.message, /rounding the mass to 1\.5 kg part-way/);
  assert.equal(code(rockWeight, "14.3", "N"), "correct");
  assert.equal(code(rockWeight, "14.9", "N"), "wrong");
  const nineEight = mark(dragG, { value: "686.0", unit: "N" });
  assert.equal(nineEight.code, "g-9.8");
  assert.match(nineEight.message, /g = 9\.8/);
  assert.doesNotMatch(nineEight.message, /part-way/);
  assert.equal(code(dragG, "686", "N"), "g-9.8");
  assert.equal(code(dragG, "687", "N"), "correct");
});

test("named mistakes are matched before generic feedback", () => {
  const r = mark(momentum, { value: "1.67", unit: "N s" });
  assert.equal(r.code, "mistake");
  assert.equal(r.mistake, "force divided by time");
  assert.match(r.message, /divided the force by the time/);
  assert.equal(mark(momentum, { value: "1.7", unit: "N s" }).mistake, "force divided by time");
  assert.equal(mark(momentum, { value: "10", unit: "kg m/s" }).mistake, "force times mass");
  // A mistake that gives another quantity is named by its own unit.
  assert.equal(mark(momentum, { value: "56", unit: "J" }).mistake, "kinetic energy instead of momentum");
  assert.equal(mark(acceleration, { value: "21.4", unit: "m/s^2", direction: "upwards" }).mistake, "drag as resultant");
  assert.equal(mark(velocity, { value: "0", unit: "m/s" }).mistake, "stops");
  assert.equal(code(momentum, "2", "N s"), "wrong"); // 1 s.f. is never read as a named mistake
});

test("direction: signed answers and sign slips", () => {
  assert.equal(code(velocity, "-2.0", "m s^-1"), "correct");
  assert.equal(code(velocity, "−2.0", "m/s"), "correct");
  assert.equal(code(velocity, "-2", "m/s"), "too-few-sf");
  const slip = mark(velocity, { value: "2.0", unit: "m s^-1" });
  assert.equal(slip.code, "sign");
  assert.match(slip.message, /sign is wrong. Positive is forwards/);
  assert.equal(code(speed, "-7.5", "m/s"), "sign-on-size"); // a speed is a size
  assert.equal(code(velocity, "- 2.0", "m s^-1"), "correct"); // a space after the minus sign
  assert.equal(code(velocity, "− 2.0", "m s^-1"), "correct");
});

test("a size whose sign the part explains takes the signed form too", () => {
  assert.equal(code(recoil, "1.0", "m/s"), "correct");
  const signed = mark(recoil, { value: "-1.0", unit: "m s^-1" });
  assert.equal(signed.code, "correct");
  assert.match(signed.message, /minus sign says it moves backwards/);
  assert.equal(code(recoil, "−1.0", "m/s"), "correct");
  assert.equal(code(recoil, "- 1.0", "m/s"), "correct");
});

test("direction: magnitude and direction answers", () => {
  assert.equal(code(acceleration, "11.6", "m s^-2", "upwards"), "correct");
  assert.equal(code(acceleration, "11.6", "m s^-2", ""), "missing-direction");
  const down = mark(acceleration, { value: "11.6", unit: "m s^-2", direction: "downwards" });
  assert.equal(down.code, "mistake"); // the named direction mistake
  assert.match(down.message, /still falling/);
  const plain = Object.assign({}, acceleration, { mistakes: [], directionHint: "Drag > weight." });
  const generic = mark(plain, { value: "11.6", unit: "m s^-2", direction: "downwards" });
  assert.equal(generic.code, "direction");
  assert.match(generic.message, /direction is wrong. Drag > weight./);
  // A size with a minus sign, its direction asked separately and right: "ignore sign".
  assert.equal(code(acceleration, "-11.6", "m s^-2", "upwards"), "ignore-sign");
  assert.equal(code(plain, "-11.6", "m s^-2", "downwards"), "direction");
});

test("a wrong method gets the idea to revisit", () => {
  const r = mark(momentum, { value: "42", unit: "N s" });
  assert.equal(r.code, "wrong");
  assert.match(r.message, /Force × time = change in momentum/);
});

test("the value box alone can hold the unit, in standard form too", () => {
  assert.deepEqual(splitValueAndUnit("1.5 x 10^3 kg m/s"), ["1.5 x 10^3", "kg m/s"]);
  assert.deepEqual(splitValueAndUnit("1.5e3 N s"), ["1.5e3", "N s"]);
  assert.deepEqual(splitValueAndUnit("11.6 m s⁻²"), ["11.6", "m s^-2"]);
  assert.equal(code(acceleration, "11.6 m s⁻²", "", "upwards"), "correct");
});

test("a unit in the wrong case says units are case-sensitive and what was meant", () => {
  const cases = [
    [mass, "12", "Kg", "kg"],
    [mass, "12", "KG", "kg"],
    [speed, "7.5", "M/S", "m/s"],
    [speed, "7.5", "M S^-1", "m s⁻¹"],
    [speed, "7.5", "Ms^-1", "m s⁻¹"],
    [momentum, "15", "n s", "N s"],
    [momentum, "15", "KG M/S", "kg m/s"],
  ];
  for (const [part, value, unit, meant] of cases) {
    const result = mark(part, { value: value, unit: unit });
    assert.equal(result.code, "unit-case", unit);
    assert.match(result.message, /^Units are case-sensitive: /, unit);
    assert.ok(result.message.includes("You probably meant " + meant + "."), unit + ": " + result.message);
  }
  // Marked as meant: a right value earns all but the A1; a wrong one is still wrong, with the note.
  const wrong = mark(mass, { value: "13", unit: "Kg" });
  assert.equal(wrong.code, "wrong");
  assert.match(wrong.message, /case-sensitive.*You probably meant kg\./);
  // Right case, a prefix slip or another quantity's unit: no case note.
  assert.equal(code(mass, "12", "kg"), "correct");
  assert.equal(code(mass, "12", "g"), "prefix");
  assert.equal(code(momentum, "15", "ms"), "wrong-unit");
  assert.doesNotMatch(mark(momentum, { value: "15", unit: "ms" }).message, /case-sensitive/);
});

test("a unit in the wrong case loses only the A1", () => {
  const data = {
    parts: [Object.assign({ id: "a" }, mass)],
    marks: [
      { part: "a", code: "C1", roles: ["method"] },
      { part: "a", code: "A1", roles: ["answer"] },
    ],
  };
  const { results, marks } = require(
    path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "marking.js"),
  ).markQuestion(data, { a: { value: "12", unit: "Kg" } });
  assert.equal(results.a.code, "unit-case");
  assert.equal(marks.earned, 1);
  assert.equal(marks.available, 2);
});
