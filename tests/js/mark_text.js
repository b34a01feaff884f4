// Marks typed answers to text parts with the browser's text marker: JSON [{part, answer}] on
// stdin (part as the site ships it), JSON [result] on stdout, each with the time it took (ms).
// Used by tests/no_site/test_text_marking.py.
"use strict";
const jsonFilter = require("./json_filter.js");
const path = require("node:path");
const text = require(
  path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "question-kinds", "text.js"),
);

jsonFilter((input) =>
  input.map(({ part, answer }) => {
    const start = process.hrtime.bigint();
    const result = text.mark(part, answer);
    result.ms = Number(process.hrtime.bigint() - start) / 1e6;
    return result;
  }),
);
