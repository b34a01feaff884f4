// What "due today" means on Your practice (book/_ext/questions/static/schedule.js), run with
// `node --test tests/js`: a card in FSRS's learning steps comes back in minutes (not "due
// today" until its time); a review, days apart, is due all of the day it falls on.
"use strict";
process.env.TZ = "UTC"; // the student's day, as the browser tests' Chromium keeps it
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const STATIC = path.join(__dirname, "..", "..", "book", "_ext", "questions", "static");
require("./book_storage.js"); // the storage keys a page of the book names
const Store = require(path.join(STATIC, "progress-store.js"));
const Schedule = require(path.join(STATIC, "schedule.js"));

const MORNING = Date.UTC(2026, 10, 26, 9, 0, 0);
const MINUTE = 60000;

function progress(attempts) {
  const p = Store.empty();
  attempts.forEach((a) => Store.addAttempt(p, Object.assign({ variant: 0, available: 4, mistakes: [] }, a)));
  return p;
}

function card(p, id, now) {
  return Schedule.cardsByDue(p, now).find((c) => c.id === id);
}

test("a card answered wrong comes back in minutes: not due today until then", () => {
  const p = progress([{ question: "q", type: "drag", earned: 0, at: MORNING }]);
  const due = card(p, "q", MORNING).due;
  assert.ok(due > MORNING && due < MORNING + 15 * MINUTE, due - MORNING); // FSRS's learning step
  const before = card(p, "q", MORNING + 10 * 1000);
  assert.equal(before.today, false);
  assert.equal(before.soon, true);
  const after = card(p, "q", due);
  assert.equal(after.today, true);
  assert.equal(after.soon, false);
  assert.deepEqual(
    Schedule.due(p, MORNING + 10 * 1000).map((c) => c.id),
    [],
  );
});

test("a review falling due later today is due today, from the morning", () => {
  // right at once (Easy) on an afternoon: its review falls days later, in the afternoon
  const p = progress([
    { question: "q", type: "drag", earned: 4, at: MORNING + 6 * 60 * MINUTE, first: true, seconds: 10 },
  ]);
  const due = card(p, "q", MORNING).due;
  const morning = due - 5 * 60 * MINUTE; // the same day, five hours before
  assert.equal(new Date(morning).getUTCDate(), new Date(due).getUTCDate());
  assert.equal(card(p, "q", morning).today, true);
  assert.equal(card(p, "q", morning).soon, false);
  const dayBefore = due - 24 * 60 * MINUTE;
  assert.deepEqual([card(p, "q", dayBefore).today, card(p, "q", dayBefore).soon], [false, false]);
});

test("when a card comes back, as a student reads it", () => {
  assert.equal(Schedule.backText(MORNING + 5 * MINUTE, MORNING), "in 5 minutes");
  assert.equal(Schedule.backText(MORNING + 30 * 1000, MORNING), "in 1 minute");
  assert.equal(Schedule.backText(MORNING + (5 * 60 + 7) * MINUTE, MORNING), "at 14:07");
});
