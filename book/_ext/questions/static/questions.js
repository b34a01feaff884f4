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

  var STORE = root.ProgressStore.KEYS.answers;

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

  /* One question on the page (q): its section, form, data (the variant on screen), worked
   * answer, score line and buttons; the help by steps; what Clear cleared (undone, until Undo
   * clear or another change); when these numbers came on screen (shownAt). */
  function questionOf(section) {
    var form = section.querySelector("form.q-form");
    // Help before the answer (static/help-steps.js), and when these numbers came on screen.
    var help = root.HelpSteps
      ? root.HelpSteps.attach(form, { load: load, save: save })
      : {
          show: function () {},
          used: function () {
            return 0;
          },
        }; // a page without the help script
    return {
      section: section,
      data: JSON.parse(section.querySelector("script.q-data").textContent),
      form: form,
      worked: section.querySelector(".q-worked"),
      score: form.querySelector(".q-score"),
      newButton: form.querySelector("button.q-new"),
      undoButton: form.querySelector("button.q-undo"),
      undone: null,
      key: form.getAttribute("data-question"),
      help: help,
      shownAt: Date.now(),
    };
  }

  function storeId(q) {
    return q.data.id + (q.key ? "@" + q.form.getAttribute("data-variant") : "");
  }

  function fields(q, part) {
    var box = q.form.querySelector('[data-part="' + part.id + '"]');
    return {
      box: box,
      feedback: box.querySelector(".q-feedback"),
      marks: box.querySelector(".q-part-marks"),
      points: box.querySelector(".q-points"),
    };
  }

  // each part's kind reads its own fieldset (static/question-kinds.js)
  function answerOf(q, part) {
    return Kinds.of(part).read(fields(q, part).box, part);
  }

  function answers(q) {
    var out = {};
    q.data.parts.forEach(function (part) {
      out[part.id] = answerOf(q, part);
    });
    return out;
  }

  function fill(q, part, a) {
    Kinds.of(part).fill(fields(q, part).box, part, a);
  }

  /* On a Check, a kind may tick in its part what its marker found, for the student to confirm
   * (an explain part with rules: preTick, true when it ticked any). */
  function preTick(q, marked) {
    var ticked = false;
    q.data.parts.forEach(function (part) {
      var kind = Kinds.of(part);
      if (kind.preTick) ticked = kind.preTick(fields(q, part).box, marked.results[part.id]) || ticked;
    });
    return ticked;
  }

  /* One part's feedback after a Check: ✓ or ✗ with the marker's message, what it lost, a
   * section to revisit, and its marks. */
  function showPartResult(q, part, marked) {
    var f = fields(q, part),
      result = marked.results[part.id],
      got = marked.marks.byPart[part.id];
    // ✓ only for a part that earned every one of its marks; a part that lost some says which
    var right = got[0] === got[1] && result.code !== "wrong";
    var selfMarked = result.code === "self-marked";
    if (f.points && selfMarked) f.points.hidden = false;
    if (Kinds.of(part).show) Kinds.of(part).show(f.box, result); // what the marker found (text)
    var lost = engine.lostText(q.data, marked.marks, part.id);
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
    if (f.marks && q.data.parts.length > 1) {
      f.marks.textContent = marksText(got[0], got[1]) + (result.code === "ecf" ? " (ecf)" : "");
    }
    f.feedback.className = "q-feedback " + (right ? "q-right" : "q-wrong");
    f.feedback.setAttribute("data-code", result.code);
  }

  /* The Check's attempt, for Your practice. record: true for a Check, "ticks" for a marking
   * point ticked; confirmed: the marker's ticks were there to confirm. */
  function recordCheck(q, marked, record, confirmed) {
    var data = q.data,
      form = q.form;
    var attempt = {
      question: q.key,
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
    if (confirmed || (record === "ticks" && load("confirm:" + storeId(q)))) attempt.selfConfirmed = true;
    if (record === true) save("confirm:" + storeId(q), confirmed);
    // A tick re-scores its Check's attempt, which keeps the help, time and first try it had.
    if (record !== "ticks") {
      attempt.help = q.help.used();
      attempt.seconds = Math.round((Date.now() - q.shownAt) / 1000);
      attempt.first = !load("tried:" + storeId(q));
      save("tried:" + storeId(q), true);
    }
    recordAttempt(attempt, record === "ticks");
  }

  /* record: a Check (a new attempt); "ticks": a marking point ticked (updates it). */
  function check(q, record) {
    var marked = markQuestion(q.data, answers(q));
    var confirmed = record === true && preTick(q, marked);
    if (confirmed) marked = markQuestion(q.data, answers(q));
    q.data.parts.forEach(function (part) {
      showPartResult(q, part, marked);
    });
    // marks earned with help say so ("4/4 marks, with 3 steps of help"), as the record does
    var steps = q.help.used();
    if (q.score) {
      q.score.textContent =
        marksText(marked.marks.earned, marked.marks.available) +
        (steps ? ", with " + steps + (steps === 1 ? " step" : " steps") + " of help" : "");
    }
    if (q.worked) q.worked.hidden = false;
    // Others listen for an attempt (a worked example's solution opens on it, below).
    q.section.dispatchEvent(
      new CustomEvent("q-checked", {
        bubbles: true,
        detail: { question: q.data.id, earned: marked.marks.earned, available: marked.marks.available },
      }),
    );
    save(storeId(q), { answers: answers(q), checked: true });
    // A Check with nothing written is no attempt: it is not kept.
    var tried = q.data.parts.some(function (part) {
      return Kinds.of(part).answered(answerOf(q, part));
    });
    if (record && q.key && tried) recordCheck(q, marked, record, confirmed);
  }

  function clear(q) {
    q.data.parts.forEach(function (part) {
      var f = fields(q, part);
      fill(q, part, {});
      if (f.points) f.points.hidden = true;
      f.feedback.textContent = "";
      f.feedback.className = "q-feedback";
      if (f.marks) f.marks.textContent = "";
    });
    if (q.score) q.score.textContent = "";
    if (q.worked) {
      q.worked.open = false;
      q.worked.hidden = true;
    }
    dropUndo(q);
  }

  function dropUndo(q) {
    q.undone = null;
    if (q.undoButton) q.undoButton.hidden = true;
  }

  function restore(q) {
    var saved = load(storeId(q));
    if (!saved || !saved.answers) return;
    q.data.parts.forEach(function (part) {
      fill(q, part, saved.answers[part.id] || {});
    });
    if (saved.checked) check(q, false);
  }

  /* A variant's own graph and diagram, drawn from its numbers. */
  function showFigures(section, variant) {
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
  }

  /* fresh: New numbers pressed (not the numbers a student had, brought back): no help yet. */
  function show(q, index, variant, fresh) {
    q.data = { id: q.data.id, parts: variant.parts, marks: variant.marks };
    q.section.querySelector(".q-text").innerHTML = variant.text;
    showFigures(q.section, variant);
    var scheme = q.worked && q.worked.querySelector(".q-scheme");
    if (scheme) scheme.outerHTML = variant.scheme.replace("<ul>", '<ul class="' + scheme.className + '">');
    q.form.setAttribute("data-variant", String(index));
    save("variant:" + q.key, { variant: index });
    q.shownAt = Date.now();
    q.help.show(q.data, "help:" + storeId(q), !!fresh);
    // A variant's prompts, options and marking points (question-relabel.js, shared with the mock test).
    root.QuestionRelabel.relabel(q.form, q.data);
    clear(q);
    restore(q);
  }

  /* Check, typing, a ticked marking point, and Clear my answers (which can be undone: the
   * cleared answers come back, until the next change). */
  function listenToForm(q) {
    var form = q.form;
    form.addEventListener("submit", function (event) {
      event.preventDefault();
      check(q, true);
    });
    form.addEventListener("input", function () {
      dropUndo(q);
      save(storeId(q), { answers: answers(q), checked: !!(load(storeId(q)) || {}).checked });
    });
    form.addEventListener("change", function (event) {
      // a ticked marking point re-scores at once
      if (event.target.classList.contains("q-tick")) check(q, "ticks");
    });
    form.addEventListener("reset", function (event) {
      event.preventDefault();
      var before = load(storeId(q));
      forget(storeId(q));
      clear(q);
      if (before && q.undoButton) {
        q.undone = before;
        q.undoButton.hidden = false;
        q.undoButton.focus();
        if (q.score) q.score.textContent = "Your answers are cleared. Undo clear brings them back.";
      }
    });
  }

  function listenToButtons(q) {
    if (q.undoButton) {
      q.undoButton.addEventListener("click", function () {
        var state = q.undone;
        dropUndo(q);
        if (!state) return;
        save(storeId(q), state);
        if (q.score) q.score.textContent = "";
        restore(q);
        q.form.querySelector("button.q-clear").focus();
      });
    }
    if (q.newButton) {
      q.newButton.addEventListener("click", function () {
        q.newButton.disabled = true;
        loadVariants(q.key, function (variants) {
          q.newButton.disabled = false;
          if (!variants) {
            q.score.textContent = "New numbers could not be loaded.";
            return;
          }
          var index = nextVariant(q.key, variants.length, Number(q.form.getAttribute("data-variant")));
          show(q, index, variants[index], true);
          q.section.querySelector(".q-text").focus();
        });
      });
    }
  }

  /* "Practise this type" (progress.js) links to page.html?new=KEY#question-KEY: this
   * question, with new numbers at once and focus in it. The request is used up, so a
   * reload keeps the numbers on screen. */
  function arrive(q, text, fresh) {
    if (!fresh) return;
    var params = new URLSearchParams(location.search);
    params.delete("new");
    var query = params.toString();
    history.replaceState(history.state, "", location.pathname + (query ? "?" + query : "") + location.hash);
    if (q.newButton) q.newButton.click();
    else if (text) text.focus();
  }

  function setUp(section) {
    var q = questionOf(section);
    listenToForm(q);
    listenToButtons(q);
    var text = section.querySelector(".q-text");
    if (text) text.setAttribute("tabindex", "-1"); // New numbers moves focus to the new text

    var fresh = !!q.key && new URLSearchParams(location.search).get("new") === q.key;
    q.help.show(q.data, "help:" + storeId(q), false);
    // A student who had new numbers comes back to the same numbers.
    var last = q.key && load("variant:" + q.key);
    if (last && last.variant) {
      loadVariants(q.key, function (variants) {
        if (variants && variants[last.variant]) show(q, last.variant, variants[last.variant]);
        else restore(q);
        arrive(q, text, fresh);
      });
    } else {
      restore(q);
      arrive(q, text, fresh);
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
