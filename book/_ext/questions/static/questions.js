/* The question on the page: answer boxes, Check, New numbers, Clear and Undo, the worked
 * answer after an attempt, what this browser keeps of each attempt (for Your practice), and
 * Print with answers. The marking is the engine's (static/marking.js, loaded first). */
(function (root) {
  "use strict";

  var engine = root.QuestionMarking,
    markQuestion = engine.markQuestion,
    marksText = engine.marksText;
  var Notation = root.Notation;
  var Kinds = root.QuestionKinds; // each part's kind reads, fills and relabels its own fieldset

  var STORE = "dynamics-questions:";

  function load(id) {
    try {
      return JSON.parse(localStorage.getItem(STORE + id)) || null;
    } catch {
      return null;
    }
  }

  function save(id, state) {
    try {
      localStorage.setItem(STORE + id, JSON.stringify(state));
    } catch {
      /* private mode: no memory */
    }
  }

  function forget(id) {
    try {
      localStorage.removeItem(STORE + id);
    } catch {
      /* nothing stored */
    }
  }

  /* Every checked attempt, for "Your practice": kept by the progress store
   * (static/progress-store.js, format 2). A self-marked part is scored by the ticks that follow
   * its Check (retick): those update the question's latest attempt instead of adding another. */
  function recordAttempt(attempt, retick) {
    if (root.ProgressStore) root.ProgressStore.recordAttempt(attempt, retick);
  }

  /* New numbers: each template's variants come in one small script (loaded on the first
   * press, so a first visit carries only variant 0). They are shown in a shuffled order that
   * shows every variant once before any comes again. */
  function contentRoot() {
    return document.documentElement.getAttribute("data-content_root") || "";
  }

  function loadVariants(key, done) {
    var all = root.QuestionVariants || {};
    if (all[key]) return done(all[key]);
    var script = document.createElement("script");
    script.src = contentRoot() + "_static/questions/" + key + ".js";
    script.onload = function () {
      done((root.QuestionVariants || {})[key] || null);
    };
    script.onerror = function () {
      done(null);
    };
    document.head.appendChild(script);
  }

  function nextVariant(key, count, current) {
    var state = load("order:" + key) || {};
    var order = state.order || [];
    if (!order.length) {
      order = [];
      for (var i = 0; i < count; i++) if (i !== current) order.push(i);
      for (var j = order.length - 1; j > 0; j--) {
        // Fisher-Yates
        var k = Math.floor(Math.random() * (j + 1)),
          t = order[j];
        order[j] = order[k];
        order[k] = t;
      }
      order.push(current); // the one on screen comes last in the round
    }
    var next = order.shift();
    save("order:" + key, { order: order });
    return next;
  }

  /* The sections feedback links to, by id, as links from this page (script.q-sections, once
   * a page, from the build): where the question's data sends a student back to. */
  var sections = null;
  function sectionLink(part, result) {
    if (sections === null) {
      var script = document.querySelector("script.q-sections");
      try {
        sections = script ? JSON.parse(script.textContent) : {};
      } catch {
        sections = {};
      }
    }
    var id = engine.sectionFor(part, result);
    return (id && sections[id]) || null;
  }

  function setUp(section) {
    var data = JSON.parse(section.querySelector("script.q-data").textContent);
    var form = section.querySelector("form.q-form");
    var worked = section.querySelector(".q-worked");
    var score = form.querySelector(".q-score");
    var newButton = form.querySelector("button.q-new");
    var undoButton = form.querySelector("button.q-undo");
    var undone = null; // what Clear my answers cleared, until Undo clear or another change
    var key = form.getAttribute("data-question");
    // Help before the answer (static/help-steps.js), and when these numbers came on screen.
    var help = root.HelpSteps
      ? root.HelpSteps.attach(form, { load: load, save: save })
      : {
          show: function () {},
          used: function () {
            return 0;
          },
        }; // a page without the help script
    var shownAt = Date.now();

    function storeId() {
      return data.id + (key ? "@" + form.getAttribute("data-variant") : "");
    }

    function fields(part) {
      var box = form.querySelector('[data-part="' + part.id + '"]');
      return {
        box: box,
        feedback: box.querySelector(".q-feedback"),
        marks: box.querySelector(".q-part-marks"),
        points: box.querySelector(".q-points"),
      };
    }

    // each part's kind reads its own fieldset (static/question-kinds.js)
    function answerOf(part) {
      return Kinds.of(part).read(fields(part).box, part);
    }

    function answers() {
      var out = {};
      data.parts.forEach(function (part) {
        out[part.id] = answerOf(part);
      });
      return out;
    }

    function fill(part, a) {
      Kinds.of(part).fill(fields(part).box, part, a);
    }

    /* On a Check, a kind may tick in its part what its marker found, for the student to confirm
     * (an explain part with rules: preTick, true when it ticked any). */
    function preTick(marked) {
      var ticked = false;
      data.parts.forEach(function (part) {
        var kind = Kinds.of(part);
        if (kind.preTick) ticked = kind.preTick(fields(part).box, marked.results[part.id]) || ticked;
      });
      return ticked;
    }

    /* record: a Check (a new attempt); "ticks": a marking point ticked (updates it). */
    function check(record) {
      var marked = markQuestion(data, answers());
      var confirmed = record === true && preTick(marked);
      if (confirmed) marked = markQuestion(data, answers());
      data.parts.forEach(function (part) {
        var f = fields(part),
          result = marked.results[part.id],
          got = marked.marks.byPart[part.id];
        // ✓ only for a part that earned every one of its marks; a part that lost some says which
        var right = got[0] === got[1] && result.code !== "wrong";
        var selfMarked = result.code === "self-marked";
        if (f.points && selfMarked) f.points.hidden = false;
        if (Kinds.of(part).show) Kinds.of(part).show(f.box, result); // what the marker found (text)
        var lost = engine.lostText(data, marked.marks, part.id);
        // a value in the message stays on one line with its unit, as everywhere in the book
        f.feedback.textContent =
          (selfMarked ? "" : right ? "✓ " : "✗ ") + Notation.joinUnits(result.message) + (lost ? " " + lost : "");
        var idea = !right && !selfMarked && sectionLink(part, result);
        if (idea) {
          var link = document.createElement("a");
          link.className = "q-idea";
          link.href = idea.href;
          link.textContent = idea.title;
          f.feedback.appendChild(document.createTextNode(" Revisit: "));
          f.feedback.appendChild(link);
        }
        // One part alone: its marks are the question's, shown once in .q-score.
        if (f.marks && data.parts.length > 1) {
          f.marks.textContent = marksText(got[0], got[1]) + (result.code === "ecf" ? " (ecf)" : "");
        }
        f.feedback.className = "q-feedback " + (right ? "q-right" : "q-wrong");
        f.feedback.setAttribute("data-code", result.code);
      });
      // marks earned with help say so ("4/4 marks, with 3 steps of help"), as the record does
      var steps = help.used();
      if (score) {
        score.textContent =
          marksText(marked.marks.earned, marked.marks.available) +
          (steps ? ", with " + steps + (steps === 1 ? " step" : " steps") + " of help" : "");
      }
      if (worked) worked.hidden = false;
      // Others listen for an attempt (a worked example's solution opens on it, below).
      section.dispatchEvent(
        new CustomEvent("q-checked", {
          bubbles: true,
          detail: { question: data.id, earned: marked.marks.earned, available: marked.marks.available },
        }),
      );
      save(storeId(), { answers: answers(), checked: true });
      // A Check with nothing written is no attempt: it is not kept.
      var tried = data.parts.some(function (part) {
        return Kinds.of(part).answered(answerOf(part));
      });
      if (record && key && tried) {
        var attempt = {
          question: key,
          type: form.getAttribute("data-type"),
          variant: Number(form.getAttribute("data-variant")),
          earned: marked.marks.earned,
          available: marked.marks.available,
          at: Date.now(),
          // the template's named mistakes, and the sign, unit and 1 s.f. slips the engine names
          mistakes: data.parts
            .map(function (p) {
              var result = marked.results[p.id];
              return result.mistake || engine.slipName(result.code);
            })
            .filter(Boolean),
        };
        // marks the student gave themselves (ticks), and whether the marker's ticks were there to confirm
        if (data.parts.some((p) => marked.results[p.id].code === "self-marked")) attempt.selfMarked = true;
        if (confirmed || (record === "ticks" && load("confirm:" + storeId()))) attempt.selfConfirmed = true;
        if (record === true) save("confirm:" + storeId(), confirmed);
        // A tick re-scores its Check's attempt, which keeps the help, time and first try it had.
        if (record !== "ticks") {
          attempt.help = help.used();
          attempt.seconds = Math.round((Date.now() - shownAt) / 1000);
          attempt.first = !load("tried:" + storeId());
          save("tried:" + storeId(), true);
        }
        recordAttempt(attempt, record === "ticks");
      }
    }

    function clear() {
      data.parts.forEach(function (part) {
        var f = fields(part);
        fill(part, {});
        if (f.points) f.points.hidden = true;
        f.feedback.textContent = "";
        f.feedback.className = "q-feedback";
        if (f.marks) f.marks.textContent = "";
      });
      if (score) score.textContent = "";
      if (worked) {
        worked.open = false;
        worked.hidden = true;
      }
      dropUndo();
    }

    function dropUndo() {
      undone = null;
      if (undoButton) undoButton.hidden = true;
    }

    function restore() {
      var saved = load(storeId());
      if (!saved || !saved.answers) return;
      data.parts.forEach(function (part) {
        fill(part, saved.answers[part.id] || {});
      });
      if (saved.checked) check(false);
    }

    /* A variant's prompts, options and marking points (question-relabel.js, shared with the
     * mock test). */
    function relabel() {
      root.QuestionRelabel.relabel(form, data);
    }

    /* fresh: New numbers pressed (not the numbers a student had, brought back): no help yet. */
    function show(index, variant, fresh) {
      data = { id: data.id, parts: variant.parts, marks: variant.marks };
      section.querySelector(".q-text").innerHTML = variant.text;
      var graph = section.querySelector("img.q-graph");
      if (graph && variant.graph) {
        // its own graph, drawn from its numbers
        graph.src = contentRoot() + "_static/questions/" + variant.graph.src;
        graph.alt = variant.graph.alt;
        // its grid, for the enlarged view (static/graph-view.js)
        var opener = graph.closest(".q-graph-open");
        if (opener && variant.graph.square) opener.setAttribute("data-square", variant.graph.square);
        if (opener && variant.graph.cursor) opener.setAttribute("data-cursor", JSON.stringify(variant.graph.cursor));
      }
      var diagram = section.querySelector("img.q-diagram");
      if (diagram && variant.diagram) {
        // its own diagram, labelled with its numbers
        diagram.src = contentRoot() + "_static/questions/" + variant.diagram.src;
        diagram.alt = variant.diagram.alt;
      }
      var scheme = worked && worked.querySelector(".q-scheme");
      if (scheme) scheme.outerHTML = variant.scheme.replace("<ul>", '<ul class="' + scheme.className + '">');
      form.setAttribute("data-variant", String(index));
      save("variant:" + key, { variant: index });
      shownAt = Date.now();
      help.show(data, "help:" + storeId(), !!fresh);
      relabel();
      clear();
      restore();
    }

    form.addEventListener("submit", function (event) {
      event.preventDefault();
      check(true);
    });
    form.addEventListener("input", function () {
      dropUndo();
      save(storeId(), { answers: answers(), checked: !!(load(storeId()) || {}).checked });
    });
    form.addEventListener("change", function (event) {
      // a ticked marking point re-scores at once
      if (event.target.classList.contains("q-tick")) check("ticks");
    });
    // Clear my answers can be undone: the cleared answers come back (until the next change).
    form.addEventListener("reset", function (event) {
      event.preventDefault();
      var before = load(storeId());
      forget(storeId());
      clear();
      if (before && undoButton) {
        undone = before;
        undoButton.hidden = false;
        undoButton.focus();
        if (score) score.textContent = "Your answers are cleared. Undo clear brings them back.";
      }
    });
    if (undoButton) {
      undoButton.addEventListener("click", function () {
        var state = undone;
        dropUndo();
        if (!state) return;
        save(storeId(), state);
        if (score) score.textContent = "";
        restore();
        form.querySelector("button.q-clear").focus();
      });
    }
    if (newButton) {
      newButton.addEventListener("click", function () {
        newButton.disabled = true;
        loadVariants(key, function (variants) {
          newButton.disabled = false;
          if (!variants) {
            score.textContent = "New numbers could not be loaded.";
            return;
          }
          var index = nextVariant(key, variants.length, Number(form.getAttribute("data-variant")));
          show(index, variants[index], true);
          section.querySelector(".q-text").focus();
        });
      });
    }
    var text = section.querySelector(".q-text");
    if (text) text.setAttribute("tabindex", "-1"); // New numbers moves focus to the new text

    // "Practise this type" (progress.js) links to page.html?new=KEY#question-KEY: this
    // question, with new numbers at once and focus in it. The request is used up, so a
    // reload keeps the numbers on screen.
    var fresh = !!key && new URLSearchParams(location.search).get("new") === key;
    function arrive() {
      if (!fresh) return;
      var params = new URLSearchParams(location.search);
      params.delete("new");
      var query = params.toString();
      history.replaceState(history.state, "", location.pathname + (query ? "?" + query : "") + location.hash);
      if (newButton) newButton.click();
      else if (text) text.focus();
    }

    help.show(data, "help:" + storeId(), false);
    // A student who had new numbers comes back to the same numbers.
    var last = key && load("variant:" + key);
    if (last && last.variant) {
      loadVariants(key, function (variants) {
        if (variants && variants[last.variant]) show(last.variant, variants[last.variant]);
        else restore();
        arrive();
      });
    } else {
      restore();
      arrive();
    }
  }

  /* A worked example's solution (class "try-first", right after its try-first question)
   * opens once the student has tried: on their first Check. They can open it any time. */
  function openSolution(event) {
    var solution = event.target.nextElementSibling;
    if (!solution || !solution.classList.contains("try-first") || solution.hasAttribute("data-tried")) return;
    solution.setAttribute("data-tried", "");
    var button = solution.querySelector(".toggle-button");
    if (button && solution.classList.contains("toggle-hidden"))
      button.click(); // the toggle's own way
    else if (!button) solution.classList.add("toggle-shown"); // not made a toggle yet: stay open
  }

  /* Print with answers: the page prints its worked answers and mark schemes this once. */
  function printChoice() {
    var bar = document.querySelector(".q-print");
    if (!bar) return;
    var html = document.documentElement;
    bar.querySelector("button").addEventListener("click", function () {
      html.classList.add("q-print-answers");
      window.print();
    });
    window.addEventListener("afterprint", function () {
      html.classList.remove("q-print-answers");
    });
  }

  function start() {
    document.documentElement.classList.add("q-js");
    printChoice();
    document.addEventListener("q-checked", openSolution);
    Array.prototype.forEach.call(document.querySelectorAll("section.q[data-q]"), setUp);
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
