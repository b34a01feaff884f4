/* The describe-and-explain part kind, self-marked: the student ticks the marking points made.
 * Its Python twin is ExplainPart (physics_figures/parts/explain.py). */
(function (root) {
  "use strict";

  function markExplanation(part, answer) {
    if (!String(answer.text || "").trim()) {
      return { code: "no-answer", message: "Write your answer first, then compare it with the marking points." };
    }
    return {
      code: "self-marked",
      message: "Now tick each marking point your answer makes: your marks follow.",
      ticked: answer.ticked || [],
    };
  }

  var kind = { kinds: ["explain"], mark: markExplanation };
  if (typeof module === "object" && module.exports) module.exports = kind;
  else
    kind.kinds.forEach(function (name) {
      (root.QuestionKinds = root.QuestionKinds || {})[name] = kind;
    });
})(this);
