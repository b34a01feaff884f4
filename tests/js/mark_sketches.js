// Marks drawn lines with the sketch kind's marker: JSON [{part, line}] on stdin (part as the
// site ships it, line [[t, y], ...] in the axes' units), JSON [{code, earned}] on stdout.
// Used by tests/no_site/test_sketches.py.
"use strict";
const jsonFilter = require("./json_filter.js");
const path = require("node:path");
const sketch = require(
  path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "question-kinds", "sketch.js"),
);

jsonFilter((input) =>
  input.map(({ part, line }) => {
    const result = sketch.mark(part, { line: line });
    return { code: result.code, earned: result.earned || [] };
  }),
);
