// The sketch kind's features, read from a line in the graph's own units, and its marks
// (book/_ext/questions/static/question-kinds/sketch.js). Run: node --test tests/js
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const sketch = require(
  path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "question-kinds", "sketch.js"),
);

// Axes 0 to 10 s, 0 to 50 N s; tolerances as parts/sketch.py's defaults.
const axes = { t: [0, 10], y: [-50, 50] };
const tolerance = { value: 0.05, time: 0.04, step: 0.2, curve: 0.3 };
const size = sketch.features.scales({ axes, tolerance });

function holds(cond, line) {
  return sketch.features.holds(cond, sketch.features.cleanLine(line, axes), size, axes);
}

// y = f(t) drawn through n points from a to b, as a pen draws it
function drawn(f, a, b, n = 40) {
  const out = [];
  for (let i = 0; i <= n; i++) out.push([a + ((b - a) * i) / n, f(a + ((b - a) * i) / n)]);
  return out;
}

test("where the line starts: zero, above or below, and only from t = 0", () => {
  assert.ok(
    holds({ is: "start", value: "zero" }, [
      [0, 1],
      [5, 20],
    ]),
  );
  assert.ok(
    holds({ is: "start", value: "positive" }, [
      [0, 20],
      [5, 20],
    ]),
  );
  assert.ok(
    holds({ is: "start", value: "negative" }, [
      [0, -20],
      [5, -20],
    ]),
  );
  assert.ok(
    !holds({ is: "start", value: "zero" }, [
      [3, 0],
      [5, 20],
    ]),
    "a line drawn from t = 3 s starts nowhere",
  );
});

test("rising, falling and level, with the gradient's trend", () => {
  const straight = drawn((t) => 4 * t, 0, 10);
  const steeper = drawn((t) => 0.45 * t * t, 0, 10);
  const lessSteep = drawn((t) => 45 * (1 - Math.exp(-t / 2.5)), 0, 10);
  assert.ok(holds({ is: "rising", from: 0, to: 10, gradient: "constant" }, straight));
  assert.ok(!holds({ is: "rising", from: 0, to: 10, gradient: "increasing" }, straight));
  assert.ok(holds({ is: "rising", from: 0, to: 10, gradient: "increasing" }, steeper));
  assert.ok(holds({ is: "rising", from: 0, to: 10, gradient: "decreasing" }, lessSteep));
  assert.ok(
    holds(
      { is: "falling", from: 0, to: 10 },
      drawn((t) => 40 - 4 * t, 0, 10),
    ),
  );
  assert.ok(
    holds({ is: "level", from: 0, to: 10, at: 20 }, [
      [0, 20],
      [10, 21],
    ]),
  );
  assert.ok(
    !holds({ is: "level", from: 0, to: 10, at: 30 }, [
      [0, 20],
      [10, 21],
    ]),
    "level, but at 20, not 30",
  );
  assert.ok(!holds({ is: "level", from: 0, to: 10 }, straight));
});

test("a straight line with a corner, then level, is not a curve of decreasing gradient", () => {
  const corner = [
    [0, 0],
    [5, 40],
    [10, 40],
  ];
  assert.ok(!holds({ is: "rising", from: 0, to: 10, gradient: "decreasing" }, corner));
  const curve = drawn((t) => 40 * Math.tanh(t / 5), 0, 10);
  assert.ok(holds({ is: "rising", from: 0, to: 10, gradient: "decreasing" }, curve));
});

test("a hand's wobble does not turn a straight line into a curve", () => {
  const wobbly = drawn((t) => 4 * t + 0.8 * Math.sin(7 * t), 0, 10);
  assert.ok(holds({ is: "rising", from: 0, to: 10, gradient: "constant" }, wobbly));
});

test("a stretch the line does not cover is not drawn", () => {
  assert.ok(
    !holds({ is: "level", from: 0, to: 10 }, [
      [0, 20],
      [5, 20],
    ]),
  );
});

test("steps: near the time, the right way, and sudden", () => {
  const stepDown = [
    [0, 30],
    [4, 30],
    [4, 10],
    [10, 10],
  ];
  assert.ok(holds({ is: "step", at: 4, way: "down" }, stepDown));
  assert.ok(!holds({ is: "step", at: 4, way: "up" }, stepDown));
  assert.ok(!holds({ is: "step", at: 7, way: "down" }, stepDown), "the step is at 4 s, not 7 s");
  assert.ok(
    !holds(
      { is: "step", at: 4 },
      drawn((t) => 30 - 2 * t, 0, 10),
    ),
    "a slope is no step",
  );
});

test("changes of sign, the end, and the peak", () => {
  const through = [
    [0, 20],
    [5, -20],
    [10, -20],
  ];
  assert.ok(holds({ is: "sign-change" }, through));
  assert.ok(holds({ is: "sign-change", count: 1 }, through));
  assert.ok(
    !holds({ is: "sign-change" }, [
      [0, 20],
      [10, 1],
    ]),
    "down to zero is no change of sign",
  );
  assert.ok(
    holds({ is: "end", value: "zero" }, [
      [0, 20],
      [10, 1],
    ]),
  );
  assert.ok(
    holds({ is: "peak", above: 30 }, [
      [0, 0],
      [5, 35],
      [10, 0],
    ]),
  );
  assert.ok(
    !holds({ is: "peak", above: 45 }, [
      [0, 0],
      [5, 35],
      [10, 0],
    ]),
  );
});

test("a line that goes back in time keeps only what runs forward", () => {
  assert.deepEqual(
    sketch.features.cleanLine(
      [
        [0, 0],
        [2, 1],
        [1, 5],
        [3, 2],
      ],
      axes,
    ),
    [
      [0, 0],
      [2, 1],
      [3, 2],
    ],
  );
});

const part = {
  kind: "sketch",
  axes,
  tolerance,
  points: [
    { text: "starts at zero", needs: [{ is: "start", value: "zero" }] },
    { text: "straight line up to 4 s", needs: [{ is: "rising", from: 0, to: 4, gradient: "constant" }] },
    {
      text: "level at 20 N s after 4 s",
      needs: [{ is: "level", from: 4, to: 10, at: 20 }],
      loses: [{ is: "sign-change" }],
    },
  ],
};

test("each point is a B1: earned when its features hold and none that loses it does", () => {
  const right = sketch.mark(part, {
    line: [
      [0, 0],
      [4, 20],
      [10, 20],
    ],
  });
  assert.deepEqual(right.earned, [true, true, true]);
  assert.equal(right.code, "correct");
  const curved = sketch.mark(part, { line: drawn((t) => (t < 4 ? 1.25 * t * t : 20), 0, 10) });
  assert.deepEqual(curved.earned, [true, false, true]);
  assert.equal(curved.code, "partial");
  assert.match(curved.message, /2 of the 3/);
  assert.match(curved.message, /✗ straight line up to 4 s/);
});

test("a feature that loses a point loses it whatever else is right", () => {
  const crossing = { ...part, points: [{ ...part.points[2], needs: [{ is: "start", value: "zero" }] }] };
  assert.deepEqual(
    sketch.mark(crossing, {
      line: [
        [0, 0],
        [2, -20],
        [4, 20],
        [10, 20],
      ],
    }).earned,
    [false],
  );
});

test("no line: nothing to mark", () => {
  assert.equal(sketch.mark(part, { line: [] }).code, "no-answer");
  assert.equal(sketch.mark(part, {}).code, "no-answer");
});
