// Runs the mock test's draw (book/_ext/questions/static/mock-draw.js) on cases read as JSON from
// stdin: {index, cases: [{paper, size, seed}]}. Prints, per case, the test drawn (paper, size,
// seed, minutes, questions) or the error's message, as JSON for tests/no_site/test_mock_draw.py.
"use strict";
const jsonFilter = require("./json_filter.js");
const path = require("node:path");
const Mock = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "mock-draw.js"));

jsonFilter((request) => {
  const tests = request.cases.map((c) => {
    try {
      return Mock.draw(request.index, c.paper, c.size, c.seed);
    } catch (error) {
      if (!(error instanceof Mock.DrawError)) throw error;
      return { error: error.message };
    }
  });
  const clock = (request.clock || []).map((ms) => Mock.clockText(ms));
  const warnings = (request.warnings || []).map((w) => Mock.warningDue(w.ms, w.given));
  return { tests, clock, warnings };
});
