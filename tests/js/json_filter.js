// The runners' plumbing: read one JSON value on stdin, write answer(value) as JSON on stdout.
// The Python tests run each runner under Node (tests/support/engine.py, node_json).
"use strict";

module.exports = function jsonFilter(answer) {
  let input = "";
  process.stdin.setEncoding("utf8");
  process.stdin.on("data", (chunk) => {
    input += chunk;
  });
  process.stdin.on("end", () => process.stdout.write(JSON.stringify(answer(JSON.parse(input)))));
};
