// The plan of "Your practice" (book/_ext/questions/static/progress-plan.js), run with `node --test tests/js`.
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const STATIC = path.join(__dirname, "..", "..", "book", "_ext", "questions", "static");
const Plan = require(path.join(STATIC, "progress-plan.js"));

function attempt(question, type, earned, available, at, mistakes) {
  return { question, type, variant: 0, earned, available, at, mistakes: mistakes || [] };
}
const data = {
  types: [
    {
      type: "drag",
      name: "Drag",
      templates: [
        { key: "d1", title: "Drag 1", marks: 4, page: "p.html", see: { "g = 10": "skydiver" } },
        { key: "d2", title: "Drag 2", marks: 4, page: "p.html", see: {} },
        { key: "d3", title: "Drag 3", marks: 4, page: null, see: {} },
      ],
    },
    {
      type: "two-d",
      name: "Two dimensions",
      templates: [
        { key: "t1", title: "Two-d 1", marks: 3, page: "q.html", see: { "g = 10": "weight" } },
        { key: "t2", title: "Two-d 2", marks: 3, page: "q.html", see: {} },
      ],
    },
  ],
  generic: { "unit missing or wrong": "rule:missing-unit" },
  sections: {
    skydiver: { href: "drag.html#the-skydiver", title: "The skydiver" },
    weight: { href: "weight.html", title: "Weight" },
    "rule:missing-unit": { href: "marks.html#rule-missing-unit", title: "the rule" },
  },
  definitions: { page: "defs.html", cards: [{ slug: "mass", term: "Mass" }] },
};

function types(cards) {
  return cards.map((c) => c.type).join(" ");
}

test("interleaving never puts two of a type together while another type is left", () => {
  const cards = ["a", "a", "a", "b", "b", "c"].map((type, i) => ({ id: String(i), type }));
  const out = Plan.interleave(cards, null);
  assert.equal(types(out), "a b a b a c");
  assert.equal(types(Plan.interleave(cards, "a")), "b a b a c a");
  assert.equal(types(Plan.interleave([{ type: "a" }, { type: "a" }], null)), "a a"); // nothing else left
  assert.equal(out.length, cards.length);
});

test("Start serves the cards due today, interleaved, then the next ones: new first, then the soonest", () => {
  const byDue = [
    { id: "d1", type: "drag", due: 1, today: true },
    { id: "d2", type: "drag", due: 2, today: true },
    { id: "t1", type: "two-d", due: 3, today: true },
    { id: "gone", type: "drag", due: 4, today: true }, // no longer in the bank: not served
  ];
  const q = Plan.queue(data, byDue);
  assert.equal(q.due, 3);
  assert.deepEqual(
    q.cards.map((c) => c.id),
    ["d1", "t1", "d2", "t2", "definition:mass"],
  );
  assert.equal(q.cards[0].url, "p.html?new=d1#question-d1");
  assert.equal(q.cards[4].url, "defs.html?card=mass#st-card-mass");
  // nothing due: the new cards, then the soonest due of the rest; never more than NEXT
  const later = Plan.queue(data, [{ id: "t2", type: "two-d", due: 9, today: false }]);
  assert.equal(later.due, 0);
  assert.deepEqual(
    later.cards.map((c) => c.id),
    ["d1", "t1", "d2", "definition:mass", "t2"],
  );
  assert.ok(later.cards.length <= Plan.NEXT);
});

test("the weakest type: the lowest share of marks over its tried templates, best attempt each", () => {
  assert.equal(Plan.weakestType(data.types, []), null);
  const attempts = [
    attempt("d1", "drag", 1, 4, 1),
    attempt("d1", "drag", 3, 4, 2), // best 3/4
    attempt("t1", "two-d", 2, 3, 3), // 2/3 is less than 3/4
  ];
  const weakest = Plan.weakestType(data.types, attempts);
  assert.equal(weakest.kind.type, "two-d");
  assert.equal(weakest.summary.earned, 2);
});

test("the most frequent mistake counts the engine's own slips too, linked to its section", () => {
  assert.equal(Plan.mostFrequentMistake([attempt("d1", "drag", 4, 4, 1)]), null);
  const attempts = [
    attempt("t1", "two-d", 1, 3, 1, ["g = 10"]),
    attempt("d1", "drag", 1, 4, 2, ["g = 10", "unit missing or wrong"]),
    attempt("d2", "drag", 1, 4, 3, ["unit missing or wrong"]),
    attempt("d2", "drag", 1, 4, 4, ["unit missing or wrong"]),
  ];
  const top = Plan.mostFrequentMistake(attempts);
  assert.deepEqual(top, { name: "unit missing or wrong", count: 3, question: "d2" });
  assert.equal(Plan.mistakeSection(data, top).href, "marks.html#rule-missing-unit");
  // a named mistake: the section of the template it was last made in
  const g = Plan.mostFrequentMistake(attempts.slice(0, 2));
  assert.equal(g.question, "d1");
  assert.equal(Plan.mistakeSection(data, g).title, "The skydiver");
  assert.equal(Plan.mistakeSection(data, { name: "unknown", question: "d1" }), null);
});

test("the self-test's record: known, not yet, due today", () => {
  const progress = { definitions: { version: 1, cards: { mass: { mark: "not-yet", at: 1 } } } };
  const record = Plan.definitionsRecord(data, progress, [{ id: "definition:mass", today: true }]);
  assert.deepEqual(record, { known: 0, notYet: 1, cards: 1, due: 1 });
});
