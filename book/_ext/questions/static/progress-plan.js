/* "Your practice", the plan at the top: how many cards are due today with one Start button,
 * the weakest type and the most frequent named mistake (with a link to its section), and the
 * self-test's record. A card is a template (a question with new numbers each time) or a
 * definition of the self-test; schedule.js (FSRS) says when each is due, from the attempts the
 * store keeps (progress-store.js). Plain JavaScript, offline, no physics. The pure part (top)
 * runs under Node for the tests; the page code (bottom) in a browser.
 *
 * Start keeps a review queue in localStorage "dynamics-review-v1":
 *   {version: 1, home: URL of Your practice, at (ms), position: index of the card served,
 *    cards: [{id, type, url}]}
 * the cards due today, then the next ones (new cards never tried, then the soonest due), each
 * run interleaved across types. review.js, on the pages that serve the cards, moves along it. */
(function (root) {
  "use strict";

  var Progress = root.PracticeProgress || require("./progress.js");

  var QUEUE = "dynamics-review-v1";
  // After the cards due today, Start serves this many more: enough for a session, not a list.
  var NEXT = 5;
  var DEFINITION = "definition:";

  /* Cards in an order that never puts two of one type together while another type is still
   * to come: each turn takes the first card (in the given order) of a type other than the
   * last one served; only when none is left does a type follow itself. lastType: the type
   * served just before. */
  function interleave(cards, lastType) {
    var left = cards.slice(),
      out = [];
    while (left.length) {
      var i = 0;
      while (i < left.length && left[i].type === lastType) i += 1;
      if (i === left.length) i = 0;
      var card = left.splice(i, 1)[0];
      out.push(card);
      lastType = card.type;
    }
    return out;
  }

  /* Every card the build can serve: {id: {id, type, url, title}} in bank order (templates a page
   * places, by type; then the self-test's definitions). url is relative to Your practice. */
  function servable(data) {
    var out = {},
      order = [];
    data.types.forEach(function (kind) {
      kind.templates.forEach(function (t) {
        if (!t.page) return;
        out[t.key] = { id: t.key, type: kind.type, url: Progress.practiseUrl(t), title: t.title };
        order.push(t.key);
      });
    });
    if (data.definitions) {
      data.definitions.cards.forEach(function (c) {
        var id = DEFINITION + c.slug;
        var url = data.definitions.page + "?card=" + encodeURIComponent(c.slug) + "#st-card-" + c.slug;
        out[id] = { id: id, type: "definitions", url: url, title: c.term };
        order.push(id);
      });
    }
    return { byId: out, order: order };
  }

  /* What Start serves: the cards due today (soonest due first), then NEXT more (cards never
   * tried, in bank order, then the soonest due), each run interleaved across types.
   * byDue: Schedule.cardsByDue(progress, now). Cards the build cannot serve are left out. */
  function queue(data, byDue) {
    var cards = servable(data);
    var tried = {};
    byDue.forEach(function (c) {
      tried[c.id] = true;
    });
    function card(c) {
      return cards.byId[c.id];
    }
    var due = byDue
      .filter(function (c) {
        return c.today && cards.byId[c.id];
      })
      .map(card);
    var fresh = cards.order
      .filter(function (id) {
        return !tried[id];
      })
      .map(function (id) {
        return cards.byId[id];
      });
    var later = byDue
      .filter(function (c) {
        return !c.today && cards.byId[c.id];
      })
      .map(card);
    // Taken before interleaving, so the new cards come from every type and not the first few.
    var next = interleave(fresh.concat(later), null).slice(0, NEXT);
    var first = interleave(due, null);
    return {
      due: first.length,
      cards: first.concat(interleave(next, first.length ? first[first.length - 1].type : null)),
    };
  }

  /* The type with the lowest share of marks over its tried templates (the best attempt at
   * each, as its line shows); on a tie, the first in the book. null when nothing is tried. */
  function weakestType(types, attempts) {
    var weakest = null;
    types.forEach(function (kind) {
      var s = Progress.summarise(kind, attempts);
      if (!s.tried) return;
      var share = s.earned / s.available;
      if (!weakest || share < weakest.share) weakest = { kind: kind, summary: s, share: share };
    });
    return weakest;
  }

  /* The named mistake made most often over every attempt (the engine's own sign, unit and
   * 1 s.f. slips included): {name, count, question (the latest attempt that made it)};
   * on a tie, the one made first. null when there is none. */
  function mostFrequentMistake(attempts) {
    var counts = {},
      order = [];
    attempts.forEach(function (a) {
      a.mistakes.forEach(function (name) {
        if (!counts[name]) {
          counts[name] = { name: name, count: 0, question: null };
          order.push(counts[name]);
        }
        counts[name].count += 1;
        counts[name].question = a.question;
      });
    });
    var top = null;
    order.forEach(function (m) {
      if (!top || m.count > top.count) top = m;
    });
    return top;
  }

  /* Where a mistake sends the student ({href, title}), as the question's feedback does: the
   * engine's own slips to their rule, a named mistake to its template's section (the one the
   * student made it in, else any template naming it). null when the build knows none. */
  function mistakeSection(data, mistake) {
    var id = data.generic[mistake.name] || null;
    var templates = [];
    data.types.forEach(function (kind) {
      templates = templates.concat(kind.templates);
    });
    templates.sort(function (a, b) {
      return (b.key === mistake.question) - (a.key === mistake.question);
    });
    for (var i = 0; !id && i < templates.length; i++) id = templates[i].see[mistake.name] || null;
    return (id && data.sections[id]) || null;
  }

  /* The self-test's record: {known, notYet, cards, due} over the build's definitions. */
  function definitionsRecord(data, progress, byDue) {
    var out = { known: 0, notYet: 0, cards: data.definitions ? data.definitions.cards.length : 0, due: 0 };
    if (!data.definitions) return out;
    var marks = progress.definitions.cards;
    data.definitions.cards.forEach(function (c) {
      var mark = marks[c.slug] && marks[c.slug].mark;
      if (mark === "known") out.known += 1;
      else if (mark === "not-yet") out.notYet += 1;
    });
    byDue.forEach(function (c) {
      if (c.today && c.id.indexOf(DEFINITION) === 0) out.due += 1;
    });
    return out;
  }

  var api = {
    QUEUE: QUEUE,
    NEXT: NEXT,
    interleave: interleave,
    servable: servable,
    queue: queue,
    weakestType: weakestType,
    mostFrequentMistake: mostFrequentMistake,
    mistakeSection: mistakeSection,
    definitionsRecord: definitionsRecord,
  };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.PracticePlan = api;

  // ------------------------------------------------------------------ page

  if (typeof document === "undefined" || !root.ProgressStore || !root.Schedule) return;
  var Store = root.ProgressStore;
  var Schedule = root.Schedule;
  var count = Progress.count;

  function plural(n, one, many) {
    return count(n) + " " + (n === 1 ? one : many);
  }

  function start() {
    var box = document.querySelector(".pp");
    if (!box) return;
    var data = JSON.parse(box.querySelector("script.pp-data").textContent);
    var plan = box.querySelector(".pp-plan");
    var startButton = plan.querySelector(".pp-start");
    var served = null; // what Start serves, as last worked out

    function link(href, text) {
      var a = document.createElement("a");
      a.href = href;
      a.textContent = text;
      return a;
    }

    function line(selector, parts) {
      var p = plan.querySelector(selector) || box.querySelector(selector);
      p.textContent = "";
      parts.forEach(function (part) {
        p.appendChild(typeof part === "string" ? document.createTextNode(part) : part);
      });
    }

    function render() {
      var read = Store.load();
      var progress = read.ok ? read.progress : Store.empty();
      var now = Date.now();
      var byDue = Schedule.cardsByDue(progress, now);
      served = queue(data, byDue);
      var more = served.cards.length - served.due;
      line(".pp-due-text", [
        served.due
          ? plural(served.due, "card", "cards") + " due today" + (more ? ", then " + count(more) + " more" : "") + "."
          : "No cards due today" + (more ? ": Start serves " + count(more) + " new." : "."),
      ]);
      startButton.disabled = !served.cards.length;
      var weakest = weakestType(data.types, progress.attempts);
      line(
        ".pp-weakest",
        weakest
          ? [
              "Weakest type: ",
              link("#pp-type-" + weakest.kind.type, weakest.kind.name),
              ", " +
                Progress.marksText(weakest.summary.earned, weakest.summary.available) +
                " (" +
                count(Math.round(weakest.share * 100)) +
                "\u202f%): the lowest share of the marks over the questions you tried.",
            ]
          : ["Weakest type: none yet. It shows once you have checked an answer."],
      );
      var mistake = mostFrequentMistake(progress.attempts);
      var section = mistake && mistakeSection(data, mistake);
      line(
        ".pp-often",
        mistake
          ? ["Most frequent mistake: " + mistake.name + " (" + Progress.times(mistake.count) + ")."].concat(
              section ? [" Revisit: ", link(section.href, section.title), "."] : [],
            )
          : [progress.attempts.length ? "No named mistakes so far." : "Most frequent mistake: none yet."],
      );
      var defs = definitionsRecord(data, progress, byDue);
      if (data.definitions) {
        line(".pp-defs-line", [
          "known " +
            count(defs.known) +
            ", not yet " +
            count(defs.notYet) +
            ", of " +
            count(defs.cards) +
            (defs.due ? "; " + count(defs.due) + " due" : "") +
            " (",
          link(data.definitions.page, "the self-test"),
          ").",
        ]);
      }
    }

    startButton.addEventListener("click", function () {
      if (!served || !served.cards.length) return;
      var cards = served.cards.map(function (c) {
        return { id: c.id, type: c.type, url: new URL(c.url, location.href).href };
      });
      var kept = { version: 1, home: location.href.split("#")[0], at: Date.now(), position: 0, cards: cards };
      try {
        localStorage.setItem(QUEUE, JSON.stringify(kept));
      } catch {
        line(".pp-due-text", ["This browser does not let the page keep the queue (private mode?)."]);
        return;
      }
      location.href = cards[0].url;
    });

    // A link to a type opens its details.
    box.addEventListener("click", function (event) {
      var a = event.target.closest && event.target.closest('a[href^="#pp-type-"]');
      var target = a && document.getElementById(a.getAttribute("href").slice(1));
      if (target) target.open = true;
    });
    box.addEventListener("pp-changed", render);
    try {
      render();
    } finally {
      // shown now, filled: progress.css keeps the plan and the types unseen until then, so
      // their words arriving move nothing a reader sees (no layout shift)
      document.documentElement.classList.add("pp-planned");
    }
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
