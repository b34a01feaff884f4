// Marks a batch of answers with the browser's engine: JSON [{part, answer}] on stdin,
// JSON [{code, mistake, message}] on stdout. Used by tests/test_questions_engine.py.
"use strict";
const path = require("node:path");
const { mark } = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "marking.js"));

let input = "";
process.stdin.setEncoding("utf8");
process.stdin.on("data", (chunk) => {
  input += chunk;
});
process.stdin.on("end", () => {
  const results = JSON.parse(input).map(({ part, answer }) => mark(part, answer));
  process.stdout.write(JSON.stringify(results));
});
