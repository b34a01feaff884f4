// The shared s.f. case table (tests/fixtures/sig_fig_cases.json) through the browser's engine:
// each written answer gets the case's judgement; physics_figures.marking.judge_sig_figs gets the
// same (tests/no_site/test_sig_fig_judge.py runs both and compares them case by case).
"use strict";
const test = require("node:test");
const assert = require("node:assert");
const path = require("node:path");
const { markCases } = require("./sig_fig_cases.js");

const table = require(path.join(__dirname, "..", "fixtures", "sig_fig_cases.json"));

test("the engine judges every written answer of the s.f. case table as the table says", () => {
  assert.ok(table.cases.length >= 40, "at least 40 cases");
  const marked = markCases(table.cases);
  table.cases.forEach((row, i) => {
    const code = marked[i].code === "unreadable-number" ? "unreadable" : marked[i].code;
    assert.strictEqual(code, row.judgement, `${row.written} against ${row.key}: ${marked[i].message}`);
    if (row.judgement === "too-few-sf") {
      assert.ok(marked[i].message.startsWith(`${row.few} s.f.: `), marked[i].message);
      assert.strictEqual(/zeros written after it/.test(marked[i].message), row.padded, marked[i].message);
    }
  });
});
