/* A mock test's questions (mock-test.js is the page): each question's section, built from its
 * template's form (form.py's, from the data file) and its variant's words, numbers and graph;
 * the answers as typed, read and filled in as questions.js does; and, at the end, each part's
 * feedback and marks from the engine (marking.js) with the worked answer. */
(function (root) {
  "use strict";

  var engine = root.QuestionMarking,
    Notation = root.Notation,
    Kinds = root.QuestionKinds; // each part's kind reads and fills its own fieldset

  function contentRoot() {
    return document.documentElement.getAttribute("data-content_root") || "";
  }

  /* The form's ids made this question's (a template asked twice has two forms). */
  function ownIds(section, prefix) {
    Array.prototype.forEach.call(section.querySelectorAll("[id], [for], [name], [aria-describedby]"), function (el) {
      ["id", "for", "name"].forEach(function (name) {
        if (el.hasAttribute(name)) el.setAttribute(name, prefix + el.getAttribute(name));
      });
      var described = el.getAttribute("aria-describedby");
      if (described) {
        el.setAttribute(
          "aria-describedby",
          described
            .split(" ")
            .map(function (id) {
              return prefix + id;
            })
            .join(" "),
        );
      }
    });
  }

  function graphButton(graph, enlarge) {
    var button = document.createElement("button");
    button.type = "button";
    button.className = "q-graph-open";
    button.setAttribute("aria-haspopup", "dialog");
    button.setAttribute("data-square", graph.square || "");
    if (graph.cursor) button.setAttribute("data-cursor", JSON.stringify(graph.cursor)); // read without sight
    var image = document.createElement("img");
    image.className = "q-graph";
    image.src = contentRoot() + "_static/questions/" + graph.src;
    image.alt = graph.alt;
    var hint = document.createElement("span");
    hint.className = "q-graph-hint";
    hint.textContent = enlarge;
    button.appendChild(image);
    button.appendChild(hint);
    return button;
  }

  /* Question i of a test: its heading and marks, its variant's text and graph, and the form
   * of its template (formHtml, as form.py writes it) relabelled with the variant's words, with
   * `answers` filled in. `enlarge`: the graph button's hint. */
  function questionSection(question, variant, formHtml, i, answers, enlarge) {
    var section = document.createElement("section");
    section.className = "q mock-q";
    section.setAttribute("data-index", String(i));
    section.setAttribute("data-question", question.question);
    section.setAttribute("aria-labelledby", "mock-q" + i + "-title");
    var marks = variant.marks.length;
    section.innerHTML =
      '<h2 class="mock-q-title" id="mock-q' +
      i +
      '-title" tabindex="-1">Question ' +
      (i + 1) +
      ' <span class="mock-q-marks">[' +
      marks +
      (marks === 1 ? " mark" : " marks") +
      ']</span></h2><div class="q-text"></div>' +
      formHtml;
    section.querySelector(".q-text").innerHTML = variant.text;
    if (variant.graph) {
      var opener = graphButton(variant.graph, enlarge);
      section.insertBefore(opener, section.querySelector("form"));
      if (variant.graph.cursor && root.GraphCursor) root.GraphCursor.add(opener);
    }
    if (variant.diagram) {
      var diagram = document.createElement("img");
      diagram.className = "q-diagram";
      diagram.src = contentRoot() + "_static/questions/" + variant.diagram.src;
      diagram.alt = variant.diagram.alt;
      section.insertBefore(diagram, section.querySelector("form"));
    }
    var form = section.querySelector("form.q-form");
    // marked at the end only: no Check, New numbers, Clear or score line during the test; and,
    // as in the exam, no help (Show a step)
    Array.prototype.forEach.call(form.querySelectorAll(".q-buttons, .q-score, .q-help"), function (el) {
      el.remove();
    });
    form.setAttribute("data-variant", String(question.variant));
    ownIds(section, "mock-q" + i + "-");
    root.QuestionRelabel.relabel(form, variant);
    fill(form, variant, answers);
    return section;
  }

  function partBox(form, part) {
    return form.querySelector('[data-part="' + part.id + '"]');
  }

  /* The answers as questions.js gives them to the engine, by part. */
  function answersOf(form, variant) {
    var out = {};
    variant.parts.forEach(function (part) {
      out[part.id] = Kinds.of(part).read(partBox(form, part), part);
    });
    return out;
  }

  function fill(form, variant, answers) {
    variant.parts.forEach(function (part) {
      Kinds.of(part).fill(partBox(form, part), part, answers[part.id] || {});
    });
  }

  // A part's answer has something in it (a choice, a value or a unit: as its kind says).
  function partAnswered(part, a) {
    return Kinds.of(part).answered(a || {});
  }

  function answered(variant, answers) {
    return variant.parts.some(function (part) {
      return partAnswered(part, answers[part.id]);
    });
  }

  /* A part's feedback at the end of a test: "Not answered" for a blank (not the engine's
   * prompt to choose or type, which is for a question still being answered), else the
   * engine's message with what was lost; a multiple-choice part not right says the right
   * letter, as the worked answer would. */
  function feedbackText(m, part, right) {
    var r = m.marked.results[part.id];
    var blank = !partAnswered(part, m.answers[part.id]);
    var lost = blank ? "" : engine.lostText(m.variant, m.marked.marks, part.id);
    var text = (right ? "✓ " : "✗ ") + (blank ? "Not answered." : Notation.joinUnits(r.message));
    if (lost) text += " " + lost;
    var missed = Kinds.of(part).missedNote;
    if (missed && !right) text += missed(part); // e.g. the right letter, as the worked answer would
    return text;
  }

  /* A question's marks, each part's feedback and its worked answer, under its answers. */
  function showMarks(form, m) {
    var section = form.closest(".mock-q");
    m.variant.parts.forEach(function (part) {
      var partBoxEl = partBox(form, part),
        r = m.marked.results[part.id],
        got = m.marked.marks.byPart[part.id];
      var right = got[0] === got[1] && r.code !== "wrong";
      var feedback = partBoxEl.querySelector(".q-feedback");
      feedback.textContent = feedbackText(m, part, right);
      feedback.className = "q-feedback " + (right ? "q-right" : "q-wrong");
      feedback.setAttribute("data-code", r.code);
      if (m.variant.parts.length > 1) {
        partBoxEl.querySelector(".q-part-marks").textContent = engine.marksText(got[0], got[1]);
      }
      partBoxEl.disabled = true;
    });
    var score = document.createElement("p");
    score.className = "q-score mock-q-score";
    score.textContent = engine.marksText(m.marked.marks.earned, m.marked.marks.available);
    form.appendChild(score);
    var worked = document.createElement("details");
    worked.className = "q-worked";
    worked.innerHTML = "<summary>Worked answer and mark scheme</summary>" + m.variant.scheme;
    var scheme = worked.querySelector("ul");
    if (scheme) scheme.className = "q-scheme";
    section.appendChild(worked);
  }

  root.MockQuestions = {
    questionSection: questionSection,
    answersOf: answersOf,
    answered: answered,
    showMarks: showMarks,
  };
})(this);
