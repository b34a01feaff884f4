// Marks as an exam awards them, and error carried forward, in the browser's engine
// (book/_ext/questions/static/marking.js). Run: node --test tests/js
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const { markQuestion } = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "marking.js"));

// Quick check 1's shape: (a) momentum = F t; (b) a velocity with a direction, (a) / mass.
const data = {
  id: "q",
  parts: [
    {
      id: "a",
      value: 15,
      unit: "N s",
      units: "N s",
      quantity: "momentum",
      direction: "none",
      mistakes: [],
      revisit: "r",
    },
    {
      id: "b",
      value: 7.5,
      unit: "m s^-1",
      units: "m s^-1",
      quantity: "velocity",
      direction: "choice",
      choices: ["forwards", "backwards"],
      answerDirection: "forwards",
      mistakes: [],
      revisit: "r",
      ecf: [{ js: "a/mass", args: ["a", "mass"], uses: ["a"], values: { mass: 2 } }],
    },
  ],
  marks: [
    { part: "a", code: "C1", roles: ["method"] },
    { part: "a", code: "A1", roles: ["answer"] },
    { part: "b", code: "C1", roles: ["method"] },
    { part: "b", code: "A1", roles: ["answer"] },
    { part: "b", code: "B1", roles: ["direction"] },
  ],
};
const ask = (a, b, dir) =>
  markQuestion(data, { a: { value: a, unit: "N s" }, b: { value: b, unit: "m/s", direction: dir } });

test("right answers earn every mark", () => {
  assert.equal(ask("15", "7.5", "forwards").marks.earned, 5);
});

test("a later part worked from a wrong earlier answer earns its marks as ecf", () => {
  const r = ask("22", "11", "forwards");
  assert.equal(r.results.b.code, "ecf");
  assert.deepEqual(r.marks.byPart, { a: [0, 2], b: [3, 3] });
});

test("a named mistake carried forward earns ecf, worked from its typed or its full value", () => {
  // (a)'s named mistake is 15.55 N s, typed to 2 s.f. as 16; (b) = (a) / 2 from 15.55 is 7.775
  const named = JSON.parse(JSON.stringify(data));
  named.parts[0].mistakes = [{ name: "slip", value: 15.55, feedback: "f", loses: ["method", "answer"] }];
  const mark = (a, b) =>
    markQuestion(named, { a: { value: a, unit: "N s" }, b: { value: b, unit: "m/s", direction: "forwards" } });
  [
    ["16", "7.78"],
    ["16", "8.0"],
    ["15.6", "7.78"],
    ["15.6", "7.8"],
  ].forEach(([a, b]) => {
    const r = mark(a, b);
    assert.equal(r.results.a.mistake, "slip");
    assert.equal(r.results.b.code, "ecf", a + " then " + b);
    assert.deepEqual(r.marks.byPart.b, [3, 3]);
  });
  assert.equal(mark("16", "7.70").results.b.code, "wrong"); // from neither 16 nor 15.55
});

test("ecf in the wrong direction loses only the direction's B1", () => {
  const r = ask("22", "11", "backwards");
  assert.equal(r.results.b.code, "direction");
  assert.match(r.results.b.message, /ecf/);
  assert.deepEqual(r.marks.byPart.b, [2, 3]);
});

test("an earlier answer right to 2 s.f. is not an error: nothing is carried from it", () => {
  const r = ask("15.0", "10", "forwards");
  assert.equal(r.results.a.code, "correct");
  assert.notEqual(r.results.b.code, "ecf");
  assert.deepEqual(r.marks.byPart.b, [1, 3]); // only the direction's B1: a B mark stands on its own
  assert.deepEqual(ask("15.0", "10", "backwards").marks.byPart.b, [0, 3]);
});

test("a self-marked explanation: an A1 counts only with the M1 before it", () => {
  const explain = {
    id: "e",
    parts: [{ id: "a", kind: "explain" }],
    marks: [
      { part: "a", code: "B1", roles: ["answer"] },
      { part: "a", code: "M1", roles: ["method"] },
      { part: "a", code: "A1", roles: ["answer"], needs: 1 },
    ],
  };
  const marks = (ticked) => markQuestion(explain, { a: { text: "drag grows", ticked } }).marks.earned;
  assert.equal(marks([0, 2]), 1);
  assert.equal(marks([0, 1, 2]), 3);
  assert.equal(markQuestion(explain, { a: { text: " ", ticked: [0] } }).results.a.code, "no-answer");
});

// A graph question's shape: (a) a reading, right within half a small square (0.25 m/s);
// (b) worked from it, v²-style so a small difference in the reading shows at 2 s.f.
const graph = {
  id: "g",
  parts: [
    {
      id: "a",
      kind: "graph",
      value: 20,
      tolerance: 0.25,
      unit: "m s^-1",
      units: "m s^-1",
      quantity: "velocity",
      minSf: 1,
      direction: "none",
      mistakes: [],
      revisit: "r",
    },
    {
      id: "b",
      value: 0.49,
      unit: "kg m^-1",
      units: "kg m^-1",
      quantity: "drag constant",
      direction: "none",
      mistakes: [],
      revisit: "r",
      ecf: [{ js: "196/Math.pow(a, 2)", args: ["a"], uses: ["a"], values: {} }],
    },
  ],
  marks: [
    { part: "a", code: "B1", roles: ["answer"] },
    { part: "b", code: "C1", roles: ["method"] },
    { part: "b", code: "A1", roles: ["answer"] },
  ],
};
const read = (a, b) => markQuestion(graph, { a: { value: a, unit: "m/s" }, b: { value: b, unit: "kg/m" } });

test("a reading within half a small square is right; just outside it is not", () => {
  assert.equal(read("20.25", "").results.a.code, "correct");
  assert.equal(read("19.8", "").results.a.code, "correct");
  assert.equal(read("20", "").results.a.code, "correct"); // no particular significant figures
  assert.equal(read("20.3", "").results.a.code, "wrong");
  assert.equal(read("19.7", "").results.a.code, "wrong");
});

test("a later part worked from a right but inexact reading is right, not ecf", () => {
  // 196 / 20.2² = 0.480, which is not the key 0.49 at 2 s.f.: it follows from the reading
  const r = read("20.2", "0.480");
  assert.equal(r.results.b.code, "correct");
  assert.match(r.results.b.message, /readings of the graph/);
  assert.equal(r.marks.earned, 3);
});

test("a later part worked from a wrong reading earns its marks as ecf", () => {
  const r = read("28", "0.25");
  assert.equal(r.results.a.code, "wrong");
  assert.equal(r.results.b.code, "ecf");
  assert.deepEqual(r.marks.byPart, { a: [0, 1], b: [2, 2] });
});

test("feedback links the section the data names: a mistake's own, else its part's; a rule's row", () => {
  const { sectionFor } = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "marking.js"));
  const part = { see: "momentum" };
  assert.equal(sectionFor(part, { code: "mistake", see: "third-law" }), "third-law");
  assert.equal(sectionFor(part, { code: "mistake" }), "momentum");
  assert.equal(sectionFor(part, { code: "wrong" }), "momentum");
  assert.equal(sectionFor({}, { code: "wrong" }), null);
  assert.equal(sectionFor(part, { code: "too-few-sf" }), "rule:too-few-sf");
});

test("what a part lost glosses each code by what its mark is for, and names two of a code once", () => {
  const { lostText } = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "marking.js"));
  const data = {
    parts: [{ id: "b", kind: "numeric" }],
    marks: [
      { part: "b", code: "C1", roles: ["method"] },
      { part: "b", code: "C1", roles: ["method"] },
      { part: "b", code: "A1", roles: ["answer"] },
      { part: "b", code: "B1", roles: ["direction"] },
    ],
  };
  const lost = (lines) => lostText(data, { lines: lines }, "b");
  assert.equal(
    lost([true, true, false, true]),
    "3/4 marks: the accuracy mark (A1) is lost; both method marks (C1) and the direction mark (B1) stand.",
  );
  assert.equal(
    lost([false, false, false, true]),
    "1/4 marks: both method marks (C1) and the accuracy mark (A1) are lost; the direction mark (B1) stands.",
  );
  assert.equal(
    lost([true, false, true, true]),
    "3/4 marks: one method mark (C1) is lost; the other method mark (C1), the accuracy mark (A1) and the " +
      "direction mark (B1) stand.",
  );
  assert.equal(lost([true, true, true, true]), ""); // nothing lost: nothing to say
  for (const text of [lost([true, true, false, true]), lost([true, false, true, true])]) {
    assert.doesNotMatch(text, /C1 and C1|the [ABCM]1\b/); // every code glossed, none twice in a row
  }
});
