/* The describe-and-explain part kind, self-marked: the student ticks the marking points made.
 * Its Python twin is ExplainPart (physics_figures/questions.py). */
(function (root) {
  "use strict";

  function outcome(code, message, extra) {
    var result = { code: code, correct: code === "correct", message: message };
    if (extra) Object.keys(extra).forEach(function (k) { result[k] = extra[k]; });
    return result;
  }

  /* A describe-and-explain part is self-marked: the student ticks the marking points made. */
  function markExplanation(part, answer) {
    if (!String(answer.text || "").trim()) {
      return outcome("no-answer", "Write your answer first, then compare it with the marking points.");
    }
    return outcome("self-marked", "Now tick each marking point your answer makes: your marks follow.",
      { ticked: answer.ticked || [] });
  }

  var kind = { kinds: ["explain"], mark: markExplanation };
  if (typeof module === "object" && module.exports) module.exports = kind;
  else kind.kinds.forEach(function (name) { (root.QuestionKinds = root.QuestionKinds || {})[name] = kind; });
})(this);
