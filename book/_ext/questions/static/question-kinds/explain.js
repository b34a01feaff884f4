/* The describe-and-explain part kind, self-marked: the student ticks the marking points made.
 * Where the part carries rules for its points (the text kind's, ExplainPart.points), the text
 * marker finds the points the words make (`found`, the part's own point indices), and the page
 * ticks them for the student to confirm or change (preTick; CLARIFICATIONS, Papers). Its Python
 * twin is ExplainPart (physics_figures/parts/explain.py). */
(function (root) {
  "use strict";

  function textKind() {
    if (typeof module === "object" && module.exports) return require("./text.js");
    return root.QuestionKinds.get("text");
  }

  function markExplanation(part, answer) {
    if (!String(answer.text || "").trim()) {
      return { code: "no-answer", message: "Write your answer first, then compare it with the marking points." };
    }
    var result = {
      code: "self-marked",
      message: "Now tick each marking point your answer makes: your marks follow.",
      ticked: answer.ticked || [],
    };
    if (part.points && part.points.length) {
      var judged = textKind().mark(part, { text: answer.text });
      result.found = judged.points
        .map(function (p, i) {
          return p.state === "made" ? i : -1;
        })
        .filter(function (i) {
          return i >= 0;
        });
      result.message =
        "The points your answer makes as the marker reads it are ticked: confirm or change them, and your marks follow.";
    }
    return result;
  }

  /* After a Check whose answer has no tick yet: the points the marker found, ticked for the
   * student to confirm or change. True when it ticked any. */
  function preTick(box, result) {
    var ticks = box.querySelectorAll(".q-tick");
    if (!result.found || !result.found.length || Array.prototype.some.call(ticks, (t) => t.checked)) return false;
    Array.prototype.forEach.call(ticks, function (t, i) {
      t.checked = result.found.indexOf(i) >= 0; // the part's ticks, in the order of its points
    });
    return true;
  }

  /* The part's fieldset: a textarea .q-explain and, after Check, the points' ticks .q-tick, each
   * the index of its line in the question's marks (form: ExplainPart.form_html). */
  function read(box) {
    return {
      text: box.querySelector(".q-explain").value,
      ticked: Array.prototype.filter
        .call(box.querySelectorAll(".q-tick"), function (t) {
          return t.checked;
        })
        .map(function (t) {
          return Number(t.value);
        }),
    };
  }

  function fill(box, part, answer) {
    box.querySelector(".q-explain").value = answer.text || "";
    Array.prototype.forEach.call(box.querySelectorAll(".q-tick"), function (t) {
      t.checked = (answer.ticked || []).indexOf(Number(t.value)) >= 0;
    });
  }

  /* Another variant's points: each tick's line index and words, and the model answer. */
  function relabel(box, part, data) {
    var lines = data.marks.filter(function (m) {
      return m.part === part.id;
    });
    Array.prototype.forEach.call(box.querySelectorAll(".q-tick"), function (tick, i) {
      tick.value = String(data.marks.indexOf(lines[i]));
      tick.parentNode.querySelector(".q-point-text").innerHTML = lines[i].html;
    });
    box.querySelector(".q-points .q-model-text").innerHTML = part.model;
  }

  var kind = {
    kinds: ["explain"],
    mark: markExplanation,
    read: read,
    fill: fill,
    answered: function (answer) {
      return !!String(answer.text || "").trim();
    },
    relabel: relabel,
    selfMarked: true,
    preTick: preTick,
  };
  if (typeof module === "object" && module.exports) module.exports = kind;
  else
    kind.kinds.forEach(function (name) {
      root.QuestionKinds.register(name, kind);
    });
})(this);
