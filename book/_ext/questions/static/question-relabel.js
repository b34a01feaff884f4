/* A question's form with another variant's words: its prompts (the time a graph is read at,
 * say), options and marking points change with its numbers. The form is the one form.py
 * writes; questions.js (New numbers) and the mock test (mock-test.js) both relabel it: the
 * legend here, the rest by each part's kind (static/question-kinds.js, relabel). */
(function (root) {
  "use strict";

  function relabel(form, data) {
    data.parts.forEach(function (part) {
      var box = form.querySelector('[data-part="' + part.id + '"]');
      var legend = box.querySelector("legend");
      var prompt = part.prompt.charAt(0).toUpperCase() + part.prompt.slice(1);
      legend.textContent = root.Notation.joinUnits((data.parts.length > 1 ? "(" + part.id + ") " : "") + prompt);
      // the rest (options, marking points, a signed part's note) is the part's kind's own
      root.QuestionKinds.of(part).relabel(box, part, data);
    });
  }

  root.QuestionRelabel = { relabel: relabel };
})(this);
