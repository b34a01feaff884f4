// The pure part of book/_ext/questions/static/progress.js ("Your practice"), run with `node --test tests/js`.
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const P = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "progress.js"));

function attempt(question, earned, at, mistakes, extra) {
  return Object.assign(
    { question, type: "drag", variant: 0, earned, available: 4, at, mistakes: mistakes || [] },
    extra,
  );
}
const kind = {
  type: "drag",
  name: "Drag",
  templates: [
    { key: "d1", title: "Drag 1", marks: 4, page: "p1.html" },
    { key: "d2", title: "Drag 2", marks: 4, page: "p2.html" },
    { key: "d3", title: "Drag 3", marks: 4, page: null }, // in the bank, on no page yet
  ],
};

test("nothing stored reads as empty progress, format 1", () => {
  assert.deepEqual(P.readProgress(null), { ok: true, progress: { version: 1, attempts: [] } });
});

test("a good file is read whole, unknown fields kept", () => {
  const text = JSON.stringify({ version: 1, attempts: [attempt("d1", 3, 10, ["g = 10"])], note: "kept" });
  const read = P.readProgress(text);
  assert.equal(read.ok, true);
  assert.equal(read.progress.note, "kept");
  assert.equal(read.progress.attempts.length, 1);
});

test("a bad file is refused with what is wrong", () => {
  const cases = [
    ["not json {", /not JSON/],
    ["[1, 2]", /no format version/],
    ['{"attempts": []}', /no format version/],
    ['{"version": 2, "attempts": []}', /newer version of the book \(format 2\)/],
    ['{"version": "x", "attempts": []}', /format version \(x\)/],
    ['{"version": 1}', /no list of attempts/],
    [
      JSON.stringify({ version: 1, attempts: [attempt("d1", 3, 1), { question: "d2" }] }),
      /attempt 2 of 2 has no question type/,
    ],
    [JSON.stringify({ version: 1, attempts: [attempt("d1", 5, 1)] }), /attempt 1 of 1 has marks earned/],
    [JSON.stringify({ version: 1, attempts: [attempt("d1", 3, 1, [7])] }), /no list of mistakes/],
  ];
  for (const [text, message] of cases) {
    const read = P.readProgress(text);
    assert.equal(read.ok, false, text);
    assert.match(read.message, message, text);
  }
});

test("merging adds each attempt once, oldest first", () => {
  const kept = [attempt("d1", 1, 5), attempt("d1", 4, 20)];
  const incoming = [attempt("d1", 4, 20), attempt("d2", 2, 10)];
  const merged = P.mergeAttempts(kept, incoming);
  assert.equal(merged.added, 1);
  assert.equal(merged.already, 1);
  assert.deepEqual(
    merged.attempts.map((a) => a.at),
    [5, 10, 20],
  );
  assert.equal(P.mergeAttempts(merged.attempts, incoming).added, 0);
});

test("a type's summary: templates tried, best marks per template, mistakes most often", () => {
  const attempts = [
    attempt("d1", 1, 1, ["drag as resultant"]),
    attempt("d1", 3, 2, ["g = 10"]),
    attempt("d2", 2, 3, ["g = 10"]),
    attempt("other", 0, 4, ["not this type"]),
  ];
  const s = P.summarise(kind, attempts);
  assert.equal(s.tried, 2);
  assert.equal(s.inBank, 3);
  assert.equal(s.earned, 3 + 2); // the best attempt at d1 (3), d2's only one (2)
  assert.equal(s.available, 8);
  assert.deepEqual(s.mistakes, [
    { name: "g = 10", count: 2 },
    { name: "drag as resultant", count: 1 },
  ]);
  assert.equal(s.templates.d1.attempts, 2);
  assert.equal(s.templates.d3.best, null);
});

test("practise this type: untried first, then last answered wrongly (longest ago), then longest ago", () => {
  const next = (attempts) => P.nextTemplate(kind, P.summarise(kind, attempts)).key;
  assert.equal(next([]), "d1");
  assert.equal(next([attempt("d1", 4, 1)]), "d2");
  // d3 is on no page, so it is never served
  assert.equal(next([attempt("d1", 4, 1), attempt("d2", 2, 2)]), "d2");
  assert.equal(next([attempt("d1", 2, 1), attempt("d2", 1, 2)]), "d1");
  assert.equal(next([attempt("d1", 2, 1), attempt("d1", 4, 5), attempt("d2", 1, 2)]), "d2");
  assert.equal(next([attempt("d1", 4, 3), attempt("d2", 4, 2)]), "d2");
  assert.equal(P.nextTemplate({ templates: [] }, P.summarise({ templates: [] }, [])), null);
});

test("the link asks the question's page for new numbers and lands on the question", () => {
  assert.equal(
    P.practiseUrl({ key: "quick-check-1", page: "quick-check.html" }),
    "quick-check.html?new=quick-check-1#question-quick-check-1",
  );
});

test("marks and counts are written as the book writes them", () => {
  assert.equal(P.marksText(3, 4), "3/4 marks");
  assert.equal(P.marksText(1, 1), "1/1 mark");
  assert.equal(P.times(1), "once");
  assert.equal(P.times(12), "12 times");
});
