// The text part kind's marker (book/_ext/questions/static/question-kinds/text.js), run with
// `node --test tests/js`: how it reads typed words (CLARIFICATIONS, Papers). The parts here are
// small, written for each rule; the templates' own rules are marked against the typed answers of
// tests/fixtures/text_answers.json by tests/no_site/test_text_marking.py.
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const text = require(
  path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "question-kinds", "text.js"),
);

// Define force [1], 9702/21/M/J/16 Q3(b)(i): "rate of change of momentum".
const force = {
  kind: "text",
  points: [
    {
      text: "Force is the rate of change of momentum",
      code: "B1",
      accept: ["rate δ momentum", "δ momentum /|rate time"],
      reject: [{ wording: "force mass acceleration", why: "F = ma is not the definition", source: "syllabus 3.1.4" }],
    },
  ],
};
// The conservation principle, M1 A1 (9702/23/M/J/25).
const conservation = {
  kind: "text",
  points: [
    {
      text: "total momentum constant",
      code: "M1",
      accept: ["total|sum momentum constant|same"],
      reject: [{ wording: "momentum constant", why: "total", source: "9702/23/M/J/13" }],
    },
    { text: "isolated system", code: "A1", needs: 0, accept: ["isolated", "no|zero external force"], reject: [] },
  ],
};
// Define momentum [2]: a contradiction loses the point.
const momentum = {
  kind: "text",
  points: [
    {
      text: "mass × velocity",
      code: "B1",
      accept: ["mass ×|product velocity"],
      reject: [
        { wording: "mass ×|product speed", why: "speed is a scalar", source: "syllabus 3.1.3", contradicts: true },
      ],
    },
    { text: "a vector", code: "B1", accept: ["vector"], reject: [] },
  ],
};

function marks(part, answer, ticked) {
  const result = text.mark(part, { text: answer, ticked: ticked || [] });
  return result.earned.filter(Boolean).length;
}

test("case, punctuation and word order within a point do not matter", () => {
  assert.equal(marks(force, "Force is the rate of change of momentum."), 1);
  assert.equal(marks(force, "FORCE: THE RATE OF CHANGE OF MOMENTUM!!!"), 1);
  assert.equal(marks(force, "the momentum's rate of change"), 1);
  assert.equal(marks(conservation, "Constant is the total momentum, when isolated."), 2);
});

test("accepted symbols: Δp/Δt, dp/dt, ×, =, p = mv", () => {
  assert.equal(marks(force, "F = Δp/Δt"), 1);
  assert.equal(marks(force, "F = ∆p / ∆t"), 1);
  assert.equal(marks(force, "F = dp/dt"), 1);
  assert.equal(marks(momentum, "p = mv, a vector"), 2);
  assert.equal(marks(momentum, "momentum = m × v (vector)"), 2);
  assert.equal(marks(momentum, "momentum = mass x velocity, vector"), 2);
});

test("a word of 5 or more letters one edit away counts; a shorter word or two edits do not", () => {
  assert.equal(marks(force, "rate of change of momentun"), 1); // a letter changed
  assert.equal(marks(force, "rate of change of momentm"), 1); // a letter dropped
  assert.equal(marks(force, "rate of change of momenttum"), 1); // a letter added
  assert.equal(marks(force, "rate of change of mometnum"), 1); // two letters swapped
  assert.equal(marks(force, "rate of change of mumentun"), 0); // two edits
  assert.equal(marks(force, "rote of change of momentum"), 0); // "rate" has 4 letters: exact only
  assert.equal(text.editDistance("vector", "vectr", 1), 1);
  assert.equal(text.editDistance("vector", "victer", 1), 2);
});

test("'not' or 'no' before a key word negates it", () => {
  assert.equal(marks(force, "Force is not the rate of change of momentum."), 0);
  assert.equal(marks(momentum, "mass × velocity; it is not a vector"), 1);
  // a negator that is one of the point's own words negates nothing
  assert.equal(marks(conservation, "The total momentum is constant if no external force acts."), 2);
  const result = text.mark(force, { text: "It is not the rate of change of momentum" });
  assert.equal(result.points[0].state, "negated");
});

test("a point contradicted elsewhere in the answer is lost", () => {
  assert.equal(marks(momentum, "Momentum is mass × velocity, a vector."), 2);
  assert.equal(marks(momentum, "Momentum is mass × velocity. It is also mass × speed. A vector."), 1);
  assert.equal(marks(momentum, "Momentum is mass × velocity, not mass × speed. A vector."), 2);
  // said and unsaid
  assert.equal(
    marks(force, "Force is the rate of change of momentum. Force is not the rate of change of momentum."),
    0,
  );
  assert.equal(text.mark(momentum, { text: "mass × velocity or mass × speed" }).points[0].state, "contradicted");
});

test("a rejected wording earns nothing and the feedback says why, citing the scheme", () => {
  const result = text.mark(force, { text: "Force is mass times acceleration" });
  assert.equal(result.points[0].state, "rejected");
  assert.equal(result.earned[0], false);
  assert.match(
    result.message,
    /Not credited: Force is the rate of change of momentum \(B1\): F = ma is not the definition \(syllabus 3\.1\.4\)/,
  );
});

test("M1 A1: the A1 counts only with its M1", () => {
  assert.equal(marks(conservation, "The total momentum of an isolated system is constant."), 2);
  assert.equal(marks(conservation, "The total momentum stays the same."), 1);
  const alone = text.mark(conservation, { text: "for an isolated system" });
  assert.equal(alone.points[1].state, "made");
  assert.deepEqual(alone.earned, [false, false]);
  assert.match(alone.message, /Made, but it needs the point before it: isolated system \(A1\)/);
});

test("the feedback names each point made and each missing", () => {
  const result = text.mark(momentum, { text: "mass × velocity" });
  assert.equal(result.message, "Made: mass × velocity (B1). Missing: a vector (B1).");
});

test("words of a point all there but apart: the marker cannot decide, the student ticks it, self-marked", () => {
  const answer = "The total momentum. That stays constant.";
  const unticked = text.mark(conservation, { text: answer });
  assert.equal(unticked.points[0].state, "undecided");
  assert.deepEqual(unticked.undecided, [0]);
  assert.equal(unticked.code, "text-marked");
  assert.match(unticked.message, /Cannot tell whether your answer makes this point/);
  const ticked = text.mark(conservation, { text: answer, ticked: [0] });
  assert.deepEqual(ticked.earned, [true, false]);
  assert.equal(ticked.code, "self-marked");
  // a tick on a point the marker decided changes nothing
  assert.deepEqual(text.mark(force, { text: "F = ma", ticked: [0] }).earned, [false]);
});

test("a clause opened by 'it' is about the subject of the one before", () => {
  assert.deepEqual(text.clauses(text.tokenise("Mass resists change; it is a scalar. Weight is a force.")), [
    ["mass", "resists", "δ"],
    ["mass", "scalar"],
    ["weight", "force"],
  ]);
});

test("an empty answer is not marked", () => {
  assert.equal(text.mark(force, { text: "   " }).code, "no-answer");
});
