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

  /* The part's fieldset: radio buttons .q-choice, values A to D (form: ChoicePart.form_html). */
  function read(box) {
    var chosen = box.querySelector(".q-choice:checked");
    return { choice: chosen ? chosen.value : "" };
  }

  function fill(box, part, answer) {
    Array.prototype.forEach.call(box.querySelectorAll(".q-choice"), function (c) {
      c.checked = c.value === answer.choice;
    });
  }

  function relabel(box, part) {
    var choices = box.querySelectorAll(".q-choice");
    part.options.forEach(function (option, i) {
      choices[i].parentNode.querySelector(".q-option-text").innerHTML = option.html;
    });
  }

  var kind = {
    kinds: ["mcq"],
    mark: function (part, answer) {
      return markChoice(part, answer.choice || "");
    },
    read: read,
    fill: fill,
    answered: function (answer) {
      return !!answer.choice;
    },
    relabel: relabel,
    mockPaper: "1",
    // a test's end says the right letter, as the worked answer would
    missedNote: function (part) {
      return " The answer is " + part.answer + ".";
    },
  };
  if (typeof module === "object" && module.exports) module.exports = kind;
  else
    kind.kinds.forEach(function (name) {
      root.QuestionKinds.register(name, kind);
    });
})(this);
