// Marks whole questions with the browser's engine: JSON [{data, answers}] on stdin (data as
// the site ships it), JSON [{results, marks, lost}] on stdout, lost: each part's "what was
// lost" text. Used by tests/no_site/test_marks_rules.py.
"use strict";
const jsonFilter = require("./json_filter.js");
const path = require("node:path");
const engine = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "marking.js"));

jsonFilter((input) =>
  input.map(({ data, answers }) => {
    const marked = engine.markQuestion(data, answers);
    const lost = {};
    data.parts.forEach((part) => {
      lost[part.id] = engine.lostText(data, marked.marks, part.id);
    });
    return { results: marked.results, marks: marked.marks, lost: lost };
  }),
);
