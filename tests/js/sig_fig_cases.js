// Marks each written answer of tests/fixtures/sig_fig_cases.json (or JSON cases on stdin) with
// the browser's engine, as a signed value in N against the case's key: JSON [{code, message}]
// on stdout. Used by tests/no_site/test_sig_fig_judge.py and tests/js/sig-figs.test.js.
"use strict";
const path = require("node:path");
const engine = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "marking.js"));

// One part of a question: a signed force, with no named mistakes, so that only the figures judge.
function markCase(row) {
  const part = { id: "a", kind: "numeric", value: row.key, unit: "N", units: "N", quantity: "force" };
  Object.assign(part, { direction: "signed", positive: "upwards", mistakes: [] });
  if (row.min_sf !== undefined) part.minSf = row.min_sf;
  if (row.check_sf !== undefined) part.checkSf = row.check_sf;
  const result = engine.mark(part, { value: row.written, unit: "N" });
  return { code: result.code, message: result.message };
}

function markCases(rows) {
  return rows.map(markCase);
}

if (require.main === module) require("./json_filter.js")(markCases);

module.exports = { markCases };
