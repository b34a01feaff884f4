// The progress store (progress-store.js, format 2) and the schedule (schedule.js), run with
// `node --test tests/js`. The schedule is checked against ts-fsrs called directly.
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const FSRS = require("ts-fsrs");
const STATIC = path.join(__dirname, "..", "..", "book", "_ext", "questions", "static");
require("./book_storage.js"); // the storage keys a page of the book names
const Store = require(path.join(STATIC, "progress-store.js"));
const Schedule = require(path.join(STATIC, "schedule.js"));

const T0 = Date.UTC(2026, 10, 26, 9, 0, 0);
function attempt(question, earned, at, extra) {
  return Object.assign({ question, type: "drag", variant: 0, earned, available: 4, at, mistakes: [] }, extra);
}

test("ratings follow CLARIFICATIONS (Plan)", () => {
  const R = Store.RATING;
  assert.equal(Store.rate(attempt("q", 0, T0)), R.again);
  assert.equal(Store.rate(attempt("q", 0, T0, { help: 2 })), R.again);
  assert.equal(Store.rate(attempt("q", 2, T0)), R.hard);
  assert.equal(Store.rate(attempt("q", 4, T0, { help: 1, first: true, seconds: 10 })), R.hard);
  assert.equal(Store.rate(attempt("q", 4, T0)), R.good);
  assert.equal(Store.rate(attempt("q", 4, T0, { first: false, seconds: 10 })), R.good);
  // 1.25 minutes a mark: 4 marks in 300 s is Easy, in 301 s Good
  assert.equal(Store.rate(attempt("q", 4, T0, { first: true, help: 0, seconds: 300 })), R.easy);
  assert.equal(Store.rate(attempt("q", 4, T0, { first: true, help: 0, seconds: 301 })), R.good);
});

test("a format 1 file is upgraded with every attempt and definition kept", () => {
  const v1 = {
    version: 1,
    attempts: [attempt("a", 4, T0), attempt("b", 1, T0 + 5, { mistakes: ["used g = 10 m s⁻²"] })],
    definitions: {
      version: 1,
      cards: { momentum: { mark: "known", at: T0 + 1 }, newton: { mark: "not-yet", at: T0 + 2 } },
    },
  };
  const read = Store.read(JSON.stringify(v1));
  assert.equal(read.ok, true);
  assert.equal(read.from, 1);
  const p = read.progress;
  assert.equal(p.version, 2);
  assert.equal(p.book, "dynamics");
  assert.deepEqual(
    p.attempts.map((a) => [a.question, a.earned, a.rating]),
    [
      ["a", 4, 3],
      ["definition:momentum", 1, 3],
      ["definition:newton", 0, 1],
      ["b", 1, 2],
    ],
  );
  assert.deepEqual(p.attempts[3].mistakes, ["used g = 10 m s⁻²"]);
  assert.deepEqual(p.definitions.cards, v1.definitions.cards);
  assert.deepEqual(p.mocks, []);
});

test("a file that is not this book's progress is refused with the reason", () => {
  const bad = (data) => Store.read(typeof data === "string" ? data : JSON.stringify(data));
  assert.match(bad("{not json").message, /not JSON/);
  assert.match(bad({ attempts: [] }).message, /no format version/);
  assert.match(bad({ version: 3, attempts: [] }).message, /newer version of the book \(format 3\)/);
  assert.match(bad({ version: 2, book: "kinematics", attempts: [], mocks: [] }).message, /another book/);
  assert.match(bad({ version: 2, attempts: [attempt("a", 5, T0)], mocks: [] }).message, /attempt 1 of 1 has marks/);
  assert.match(bad({ version: 2, attempts: [attempt("a", 4, T0, { help: -1 })], mocks: [] }).message, /help count/);
  assert.match(bad({ version: 2, attempts: [] }).message, /no list of mock tests/);
  assert.match(bad({ version: 2, attempts: [], mocks: [{ id: "m", paper: "3", at: T0 }] }).message, /mock test 1 of 1/);
  assert.equal(Store.read(null).ok, true);
});

test("a Check appends, ticks update the last attempt on the same numbers, and each is rated", () => {
  const p = Store.empty();
  assert.equal(Store.addAttempt(p, attempt("e", 0, T0, { help: 1, first: true, seconds: 20 }), false), true);
  assert.equal(Store.addAttempt(p, attempt("e", 4, T0 + 9), "ticks"), true);
  assert.equal(p.attempts.length, 1);
  assert.equal(p.attempts[0].at, T0); // the Check's time is kept
  assert.equal(p.attempts[0].help, 1); // and what it knew of help
  assert.equal(p.attempts[0].rating, Store.RATING.hard);
  assert.equal(Store.addAttempt(p, attempt("never", 1, T0), "ticks"), false);
  assert.equal(p.attempts.length, 1);
});

test("merging adds each attempt and mock once; a definition keeps its latest mark", () => {
  const mock = { id: "m1", paper: "1", at: T0, minutes: 18.75, ended: "time", earned: 3, available: 10, questions: [] };
  const a = Object.assign(Store.empty(), { attempts: [attempt("a", 4, T0)] });
  a.definitions.cards.momentum = { mark: "not-yet", at: T0 };
  const b = Object.assign(Store.empty(), { attempts: [attempt("a", 4, T0), attempt("b", 2, T0 - 5)], mocks: [mock] });
  b.definitions.cards.momentum = { mark: "known", at: T0 + 1 };
  const once = Store.merge(a, b);
  assert.equal(once.added, 1);
  assert.equal(once.already, 1);
  assert.deepEqual(
    once.progress.attempts.map((x) => x.question),
    ["b", "a"],
  );
  assert.equal(once.progress.definitions.cards.momentum.mark, "known");
  const twice = Store.merge(once.progress, b);
  assert.equal(twice.added, 0);
  assert.equal(twice.progress.mocks.length, 1);
});

test("the schedule is what ts-fsrs gives for the same ratings, and the wrong one is due first", () => {
  const p = Store.empty();
  Store.addAttempt(p, attempt("right", 4, T0, { first: true, help: 0, seconds: 500 }), false);
  Store.addAttempt(p, attempt("partly", 2, T0 + 60e3), false);
  Store.addAttempt(p, attempt("wrong", 0, T0 + 120e3), false);
  Store.addAttempt(p, attempt("right", 4, T0 + 86400e3, { first: true, help: 0, seconds: 30 }), false);
  const schedule = Schedule.replay(p);
  const f = FSRS.fsrs(FSRS.generatorParameters({ request_retention: 0.9 }));
  const direct = (reviews) => {
    let card = FSRS.createEmptyCard(new Date(reviews[0][0]));
    for (const [at, rating] of reviews) card = f.next(card, new Date(at), rating).card;
    return card;
  };
  const expected = {
    right: direct([
      [T0, FSRS.Rating.Good],
      [T0 + 86400e3, FSRS.Rating.Easy],
    ]),
    partly: direct([[T0 + 60e3, FSRS.Rating.Hard]]),
    wrong: direct([[T0 + 120e3, FSRS.Rating.Again]]),
  };
  for (const id of Object.keys(expected)) {
    assert.equal(schedule[id].due, expected[id].due.getTime(), id);
    assert.equal(schedule[id].stability, expected[id].stability, id);
    assert.equal(schedule[id].reps, expected[id].reps, id);
  }
  const now = T0 + 86400e3 + 1000;
  const byDue = Schedule.cardsByDue(p, now).map((c) => c.id);
  assert.deepEqual(byDue.slice(0, 2), ["wrong", "partly"]);
  assert.deepEqual(
    Schedule.due(p, now).map((c) => c.id),
    ["wrong", "partly"],
  );
});

test("the student's name is kept in the store, read back, and kept over an imported file's", () => {
  const named = Object.assign(Store.empty(), { student: "Amira Khan" });
  const read = Store.read(JSON.stringify(named));
  assert.equal(read.ok, true, read.message);
  assert.equal(read.progress.student, "Amira Khan");
  assert.match(Store.read(JSON.stringify({ ...named, student: 7 })).message, /name is not text/);
  const other = Object.assign(Store.empty(), { student: "Ben" });
  assert.equal(Store.merge(named, other).progress.student, "Amira Khan");
  assert.equal(Store.merge(Store.empty(), other).progress.student, "Ben");
  assert.equal("student" in Store.merge(Store.empty(), Store.empty()).progress, false);
});
