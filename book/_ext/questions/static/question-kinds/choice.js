/* The multiple-choice part kind: the key, or the named mistake a wrong option stands for.
 * Its Python twin is ChoicePart (physics_figures/parts/choice.py). */
(function (root) {
  "use strict";

  function markChoice(part, letter) {
    var option = (part.options || []).filter(function (o) {
      return o.letter === letter;
    })[0];
    if (!option) return { code: "no-choice", message: "Choose one of the options A to D." };
    if (letter === part.answer) return { code: "correct", correct: true, message: "Correct." };
    // the option's feedback names the idea already
    return { code: "mistake", message: option.feedback, mistake: option.mistake, loses: option.loses, see: option.see };
  }

  var kind = {
    kinds: ["mcq"],
    mark: function (part, answer) {
      return markChoice(part, answer.choice || "");
    },
  };
  if (typeof module === "object" && module.exports) module.exports = kind;
  else
    kind.kinds.forEach(function (name) {
      (root.QuestionKinds = root.QuestionKinds || {})[name] = kind;
    });
})(this);
