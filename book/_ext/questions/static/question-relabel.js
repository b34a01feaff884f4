/* A question's form with another variant's words: its prompts (the time a graph is read at,
 * say), options and marking points change with its numbers. The form is the one form.py
 * writes; questions.js (New numbers) and the mock test (mock-test.js) both relabel it. A
 * signed part's note names the positive direction with the variant's own numbers ("the 0.80 kg
 * ball"): its .q-positive span (form.py) takes the variant's words. */
(function (root) {
  "use strict";

  function relabel(form, data) {
    data.parts.forEach(function (part) {
      var box = form.querySelector('[data-part="' + part.id + '"]');
      var legend = box.querySelector("legend");
      var prompt = part.prompt.charAt(0).toUpperCase() + part.prompt.slice(1);
      legend.textContent = root.Notation.joinUnits((data.parts.length > 1 ? "(" + part.id + ") " : "") + prompt);
      var positive = box.querySelector(".q-note .q-positive");
      if (positive && part.direction === "signed") positive.textContent = root.Notation.joinUnits(part.positive);
      if (part.kind === "mcq") {
        var choices = box.querySelectorAll(".q-choice");
        part.options.forEach(function (option, i) {
          choices[i].parentNode.querySelector(".q-option-text").innerHTML = option.html;
        });
      } else if (part.kind === "explain") {
        var lines = data.marks.filter(function (m) {
          return m.part === part.id;
        });
        Array.prototype.forEach.call(box.querySelectorAll(".q-tick"), function (tick, i) {
          tick.value = String(data.marks.indexOf(lines[i]));
          tick.parentNode.querySelector(".q-point-text").innerHTML = lines[i].html;
        });
        box.querySelector(".q-points .q-model-text").innerHTML = part.model;
      } else if (part.kind === "text") {
        Array.prototype.forEach.call(box.querySelectorAll(".q-point-text"), function (text, i) {
          text.textContent = part.points[i].text;
        });
        box.querySelector(".q-points .q-model-text").innerHTML = part.model;
      }
    });
  }

  root.QuestionRelabel = { relabel: relabel };
})(this);
