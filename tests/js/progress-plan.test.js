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
  // then the new ones, the least practised type first (no definition tried yet)
  assert.deepEqual(
    q.cards.map((c) => c.id),
    ["d1", "t1", "d2", "definition:mass", "t2"],
  );
  assert.equal(q.cards[0].url, "p.html?new=d1#question-d1");
  assert.equal(q.cards[3].url, "defs.html?card=mass#st-card-mass");
  // nothing due: the new cards, then the soonest due of the rest; never more than NEXT
  const later = Plan.queue(data, [{ id: "t2", type: "two-d", due: 9, today: false }]);
  assert.equal(later.due, 0);
  assert.deepEqual(
    later.cards.map((c) => c.id),
    ["d1", "t1", "definition:mass", "d2", "t2"],
  );
  // a card coming back in minutes is neither due nor one of the next: it waits for its time
  const soon = Plan.queue(data, [{ id: "t2", type: "two-d", due: 9, today: false, soon: true }]);
  assert.ok(!soon.cards.some((c) => c.id === "t2"));
  assert.ok(later.cards.length <= Plan.NEXT);
});

// A book of seven types in book order, as the Dynamics bank has them (the first two largest
// but one), and the self-test's definitions sharing the "definitions" type.
const SIZES = {
  newton: 14,
  drag: 15,
  "force-momentum": 13,
  definitions: 9,
  "momentum-line": 7,
  elastic: 9,
  "two-d": 7,
};
const book = {
  types: Object.entries(SIZES).map(([type, n]) => ({
    type,
    name: type,
    templates: Array.from({ length: n }, (_, i) => ({
      key: `${type}-${i}`,
      title: "",
      marks: 3,
      page: "p.html",
      see: {},
    })),
  })),
  generic: {},
  sections: {},
  definitions: { page: "defs.html", cards: Array.from({ length: 8 }, (_, i) => ({ slug: `def-${i}`, term: "" })) },
};

// Adjacent pairs of one type: never more than the fewest any order of these cards can have.
function clumps(cards) {
  return cards.filter((c, i) => i > 0 && c.type === cards[i - 1].type).length;
}
function fewestClumps(cards) {
  const n = {};
  cards.forEach((c) => (n[c.type] = (n[c.type] || 0) + 1));
  const most = Math.max(0, ...Object.values(n));
  return Math.max(0, most - (cards.length - most) - 1);
}

test("a fresh student's new cards come from every type, session after session", () => {
  const served = [];
  let byDue = [];
  const types = Object.keys(SIZES);
  for (let session = 0; session < 4; session++) {
    const q = Plan.queue(book, byDue);
    assert.equal(q.due, 0);
    assert.equal(q.cards.length, Plan.NEXT);
    assert.equal(clumps(q.cards), 0, q.cards.map((c) => c.type).join(" "));
    served.push(...q.cards);
    // the student does them all; they come back days later (reviews, not due today)
    byDue = byDue.concat(q.cards.map((c) => ({ id: c.id, type: c.type, due: 1e15, today: false, soon: false })));
  }
  assert.deepEqual(new Set(served.slice(0, types.length).map((c) => c.type)), new Set(types));
  assert.equal(new Set(served.map((c) => c.id)).size, served.length); // each new card once
  // no type has two more cards served than another
  const n = {};
  served.forEach((c) => (n[c.type] = (n[c.type] || 0) + 1));
  assert.ok(Math.max(...Object.values(n)) - Math.min(...Object.values(n)) <= 1, JSON.stringify(n));
});

test("the queue looks ahead: the type with most cards left goes first, so the end does not clump", () => {
  const cards = ["b", "c", "a", "a"].map((type, i) => ({ id: String(i), type }));
  assert.equal(types(Plan.interleave(cards, null)), "a b c a");
  // due cards in due order ending in a clump of one type are served mixed
  const byDue = ["t1", "d1", "d2"].map((id, i) => ({
    id,
    type: id[0] === "t" ? "two-d" : "drag",
    due: i,
    today: true,
  }));
  assert.deepEqual(
    Plan.queue(data, byDue)
      .cards.slice(0, 3)
      .map((c) => c.id),
    ["d1", "t1", "d2"],
  );
  // and over many shuffled lists: never a clump that another order avoids, nothing lost
  let seed = 7;
  const random = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
  for (let trial = 0; trial < 500; trial++) {
    const list = Array.from({ length: 1 + Math.floor(random() * 12) }, (_, i) => ({
      id: String(i),
      type: "abcd"[Math.floor(random() * random() * 4)],
    }));
    const out = Plan.interleave(list, null);
    assert.equal(clumps(out), fewestClumps(list), `${types(list)} -> ${types(out)}`);
    assert.deepEqual(out.map((c) => c.id).sort(), list.map((c) => c.id).sort());
    for (const type of "abcd") {
      // within a type, the given order (soonest due first) is kept
      const ids = (l) => l.filter((c) => c.type === type).map((c) => c.id);
      assert.deepEqual(ids(out), ids(list));
    }
  }
});

test("the plan's line: cards coming back in minutes are not due today", () => {
  const back = (due, now) => `in ${(due - now) / 60000} minutes`;
  const served = { due: 1, cards: [{}, {}, {}] };
  const byDue = [
    { id: "a", due: 0, today: true, soon: false },
    { id: "b", due: 5 * 60000, today: false, soon: true },
    { id: "c", due: 6 * 60000, today: false, soon: true },
  ];
  assert.equal(
    Plan.dueLine(served, byDue, 0, back),
    "1 card due today, then 2 more. 2 cards come back later today, the next in 5 minutes.",
  );
  assert.equal(
    Plan.dueLine({ due: 0, cards: [{}] }, byDue.slice(2), 0, back),
    "Nothing due yet: Start serves 1 new. 1 card comes back in 6 minutes.",
  );
  assert.equal(Plan.dueLine({ due: 0, cards: [] }, [], 0, back), "No cards due today.");
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
