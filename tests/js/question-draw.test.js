// The worksheet draw (book/_ext/questions/static/question-draw.js), the one the sheet builder, the
// mock test and the command line (physics_figures/worksheets/draw.py) run. Run: node --test tests/js
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const Draw = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "question-draw.js"));

test("the seeded order hashes by 32-bit FNV-1a: the hash's published test values", () => {
  // the FNV authors' test vectors (www.isthe.com/chongo/tech/comp/fnv: FNV-1a 32, "", "a", "foobar")
  assert.deepEqual([Draw.fnv1a(""), Draw.fnv1a("a"), Draw.fnv1a("foobar")], [0x811c9dc5, 0xe40c292c, 0xbf9cf968]);
});

// a small index of its own: two types, exam counts 3 and 1
const data = {
  types: [
    { key: "a", examCount: 3 },
    { key: "b", examCount: 1 },
  ],
  templates: [
    { key: "a1", type: "a", marks: 2, oneWording: false, reserve: [0, 1, 2, 3] },
    { key: "a2", type: "a", marks: 3, oneWording: false, reserve: [4, 5, 6] },
    { key: "b1", type: "b", marks: 1, oneWording: true, reserve: [0] },
  ],
};

test("a kit never takes a template's variant twice, and a one-wording statement once", () => {
  const kit = {
    seed: 7,
    versions: 2,
    sheets: [{ templates: ["a1", "b1"] }, { templates: ["a1", "a2", "b1"], fitting: true }],
  };
  const drawn = Draw.drawKit(data, kit);
  assert.deepEqual(drawn.sheets[0].variants[1], [0, 0]);
  assert.deepEqual(drawn.sheets[1].templates, ["a1", "a2"]); // b1 used up
  const a1 = [...drawn.sheets[0].variants[0], ...drawn.sheets[1].variants[0]];
  assert.equal(new Set(a1).size, 4);
  assert.equal(a1[3], 0, "the book's printed variant comes last");
  assert.deepEqual(drawn.left, { a1: 0, a2: 1, b1: 0 });
});

test("a refusal names the field, the value and the rule", () => {
  const ask =
    (sheet, versions = 2) =>
    () =>
      Draw.drawKit(data, { seed: 1, versions, sheets: [sheet] });
  assert.throws(ask({ templates: ["a2"] }, 4), { field: "versions", message: /a2 has 3 the site does not show/ });
  assert.throws(ask({ templates: ["a1", "a2"], marks: 4 }), {
    field: "marks",
    nearest: [3, 5],
    message: /the nearest totals that can are 3 and 5 \(got marks=4\)$/,
  });
  assert.throws(ask({ templates: [] }), {
    field: "templates",
    message: "templates must hold at least one template (got templates=[])",
  });
});

test("a template's variants come in the seed's order, the avoided ones after the others, the printed one last", () => {
  const a1 = data.templates[0];
  for (let seed = 0; seed < 20; seed++) {
    const order = Draw.variantOrder(a1, seed, { 2: "Worksheet: A, version A" });
    assert.deepEqual([...order].sort(), [0, 1, 2, 3], `seed ${seed}`);
    assert.deepEqual(order.slice(2), [2, 0], `seed ${seed}`);
  }
  const orders = new Set([0, 1, 2, 3, 4, 5].map((seed) => Draw.variantOrder(a1, seed).join()));
  assert.ok(orders.size > 1, "the seed changes the order");
});
