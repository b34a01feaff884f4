// The definitions self-test's store (book/_ext/questions/static/selftest.js), run with `node --test tests/js`.
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const { slug, readCards } = require(
  path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "selftest.js"),
);

test("a term's key is its name in lower case with hyphens", () => {
  assert.equal(slug("Newton’s first law"), "newton-s-first-law");
  assert.equal(slug("Principle of conservation of momentum"), "principle-of-conservation-of-momentum");
});

test("the marks are read from the progress store's definitions, none when it has none", () => {
  const cards = { mass: { mark: "known", at: 5 } };
  assert.deepEqual(readCards({ version: 2, attempts: [], definitions: { version: 1, cards } }), cards);
  assert.deepEqual(readCards({ version: 2, attempts: [] }), {});
  assert.deepEqual(readCards(null), {});
});
