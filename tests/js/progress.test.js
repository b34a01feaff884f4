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
  assert.equal(s.templates.d1.withHelp, 0);
  assert.equal(P.summarise(kind, [attempt("d1", 2, 1, [], { help: 2 }), attempt("d1", 4, 2)]).templates.d1.withHelp, 1);
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

test("a type's line: marks, tried, due today", () => {
  const s = P.summarise(kind, [attempt("d1", 3, 1), attempt("d2", 1, 2)]);
  assert.equal(P.typeLine(s, 1), "4/8 marks · 2 of 3 tried · 1 due");
  assert.equal(P.typeLine(P.summarise(kind, []), 0), "no marks yet · 0 of 3 tried");
  assert.equal(P.typeLine({ inBank: 0 }, 0), "not in the bank yet");
});

test("due dates read as a student says them", () => {
  const now = new Date(2026, 10, 26, 9).getTime();
  const ends = new Date(2026, 10, 27).getTime();
  assert.equal(P.dueText(now - 1000, now, ends), "due today");
  assert.equal(P.dueText(new Date(2026, 10, 28, 9).getTime(), now, ends), "due 28 Nov");
  assert.equal(P.dueText(new Date(2027, 0, 3).getTime(), now, ends), "due 3 Jan 2027");
});

test("a mock test's result: paper, date, score", () => {
  const mock = { paper: "1", at: new Date(2026, 10, 26, 9).getTime(), earned: 14, available: 20, ended: "submitted" };
  assert.equal(P.mockText(mock), "Paper 1, 26 Nov 2026: 14/20 marks (70\u202f%)");
  assert.match(P.mockText({ ...mock, ended: "time" }), /ended when time ran out$/);
});
