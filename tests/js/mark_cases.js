// Marks a batch of answers with the browser's engine: JSON [{part, answer}] on stdin,
// JSON [{code, mistake, message}] on stdout. Used by tests/no_site/test_questions_engine.py.
"use strict";
const jsonFilter = require("./json_filter.js");
const path = require("node:path");
const { mark } = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "marking.js"));

jsonFilter((cases) => cases.map(({ part, answer }) => mark(part, answer)));
