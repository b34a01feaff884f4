// The mock test's "What next" (book/_ext/questions/static/mock-draw.js, weakestType), run with
// `node --test tests/js`: the type of a result with the lowest share of its marks.
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const Mock = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "mock-draw.js"));

const types = ["newton", "drag", "two-d"].map((key) => ({ key, title: key }));
const q = (type, earned, available) => ({ question: type, type, variant: 0, earned, available });

test("the weakest type: the lowest share, then the most marks lost, then the first in the book", () => {
  const weakest = Mock.weakestType(types, [q("newton", 3, 4), q("drag", 1, 4), q("drag", 2, 2), q("two-d", 2, 3)]);
  assert.deepEqual(weakest, { type: types[1], earned: 3, available: 6 }); // 50 % against 75 % and 67 %
  // a tie on the share: the one that lost more marks
  assert.equal(Mock.weakestType(types, [q("newton", 1, 2), q("two-d", 2, 4)]).type.key, "two-d");
  // a tie on both: the first in the book
  assert.equal(Mock.weakestType(types, [q("two-d", 1, 2), q("drag", 1, 2)]).type.key, "drag");
  // every mark: none
  assert.equal(Mock.weakestType(types, [q("newton", 2, 2)]), null);
});
