// The browser's number writer (book/_ext/notation/static/notation.js) against the case table
// that physics_figures/notation.py also runs (tests/no_site/test_notation.py). Run: node --test tests/js
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const { formatNumber } = require(path.join(__dirname, "..", "..", "book", "_ext", "notation", "static", "notation.js"));
const { cases } = require(path.join(__dirname, "..", "notation_cases.json"));

for (const c of cases) {
  test(`formatNumber(${c.value}, ${c.sig_figs ?? "decimals " + c.decimals}) -> ${c.text}`, () => {
    const opts = { plus: Boolean(c.plus) };
    if (c.decimals !== undefined) opts.decimals = c.decimals;
    assert.equal(formatNumber(c.value, c.sig_figs ?? null, opts), c.text, c.why || "");
  });
}

test("a bad precision or a value that is not a number is an error, not a wrong text", () => {
  assert.throws(() => formatNumber(1, 2, { decimals: 1 }), /exactly one of sigFigs and opts.decimals/);
  assert.throws(() => formatNumber(NaN, 2), /finite number/);
});

const { formatQuantity } = require(
  path.join(__dirname, "..", "..", "book", "_ext", "notation", "static", "notation.js"),
);
const { quantities } = require(path.join(__dirname, "..", "notation_cases.json"));

for (const c of quantities) {
  test(`formatQuantity(${c.value}, ${c.unit}) joins number and unit: ${c.text}`, () => {
    const opts = c.decimals !== undefined ? { decimals: c.decimals } : {};
    assert.equal(formatQuantity(c.value, c.sig_figs ?? null, c.unit, opts), c.text, c.why || "");
  });
}

const { joinUnits } = require(path.join(__dirname, "..", "..", "book", "_ext", "notation", "static", "notation.js"));
const { prose } = require(path.join(__dirname, "..", "notation_cases.json"));

for (const c of prose) {
  test(`joinUnits(${JSON.stringify(c.text)}) joins numbers to units as join_units does`, () => {
    assert.equal(joinUnits(c.text, Boolean(c.after_number)), c.joined, c.why || "");
  });
}
