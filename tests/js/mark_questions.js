// Marks whole questions with the browser's engine: JSON [{data, answers}] on stdin (data as
// the site ships it), JSON [{results, marks, lost}] on stdout, lost: each part's "what was
// lost" text. Used by tests/test_marks_rules.py.
"use strict";
const path = require("node:path");
const engine = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "marking.js"));

let input = "";
process.stdin.setEncoding("utf8");
process.stdin.on("data", (chunk) => {
  input += chunk;
});
process.stdin.on("end", () => {
  const out = JSON.parse(input).map(({ data, answers }) => {
    const marked = engine.markQuestion(data, answers);
    const lost = {};
    data.parts.forEach((part) => {
      lost[part.id] = engine.lostText(data, marked.marks, part.id);
    });
    return { results: marked.results, marks: marked.marks, lost: lost };
  });
  process.stdout.write(JSON.stringify(out));
});
