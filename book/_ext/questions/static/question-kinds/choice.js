/* The multiple-choice part kind: the key, or the named mistake a wrong option stands for.
 * Its Python twin is ChoicePart (physics_figures/questions.py). */
(function (root) {
  "use strict";

  function outcome(code, message, extra) {
    var result = { code: code, correct: code === "correct", message: message };
    if (extra) Object.keys(extra).forEach(function (k) { result[k] = extra[k]; });
    return result;
  }

  /* A multiple-choice part: the key, or the named mistake its wrong option stands for. */
  function markChoice(part, letter) {
    var option = (part.options || []).filter(function (o) { return o.letter === letter; })[0];
    if (!option) return outcome("no-choice", "Choose one of the options A to D.");
    if (letter === part.answer) return outcome("correct", "Correct.");
    return outcome("mistake", option.feedback, { mistake: option.mistake, loses: option.loses }); // it names the idea already
  }

  var kind = { kinds: ["mcq"], mark: function (part, answer) { return markChoice(part, answer.choice || ""); } };
  if (typeof module === "object" && module.exports) module.exports = kind;
  else kind.kinds.forEach(function (name) { (root.QuestionKinds = root.QuestionKinds || {})[name] = kind; });
})(this);
