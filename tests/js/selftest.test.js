// The definitions self-test's store (book/_ext/questions/static/selftest.js), run with `node --test tests/js`.
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const { slug, readCards, withMark } = require(
  path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "selftest.js"),
);

test("a term's key is its name in lower case with hyphens", () => {
  assert.equal(slug("Newton’s first law"), "newton-s-first-law");
  assert.equal(slug("Principle of conservation of momentum"), "principle-of-conservation-of-momentum");
});

test("a mark is kept beside the attempts, as a versioned field of the progress store", () => {
  const attempts = [
    { question: "quick-check-1", type: "force-momentum", variant: 0, earned: 4, available: 4, at: 1, mistakes: [] },
  ];
  const text = withMark(JSON.stringify({ version: 1, attempts: attempts }), "mass", "known", 5);
  const stored = JSON.parse(text);
  assert.deepEqual(stored.attempts, attempts); // the practice is untouched
  assert.deepEqual(stored.definitions, { version: 1, cards: { mass: { mark: "known", at: 5 } } });
  assert.deepEqual(readCards(text), { mass: { mark: "known", at: 5 } });
  const again = JSON.parse(withMark(text, "mass", "not-yet", 6));
  assert.equal(again.definitions.cards.mass.mark, "not-yet");
  // Nothing stored yet: a new store of format 1.
  assert.deepEqual(JSON.parse(withMark(null, "weight", "known", 7)).attempts, []);
});

test("a store of another format is never written into", () => {
  assert.equal(withMark(JSON.stringify({ version: 2, attempts: [] }), "mass", "known", 1), null);
  assert.equal(
    withMark(JSON.stringify({ version: 1, attempts: [], definitions: { version: 2, cards: {} } }), "mass", "known", 1),
    null,
  );
  assert.equal(withMark("not json", "mass", "known", 1), null);
  assert.deepEqual(
    readCards(JSON.stringify({ version: 1, attempts: [], definitions: { version: 2, cards: { mass: {} } } })),
    {},
  );
});
