/* "Your practice", the plan at the top: how many cards are due today with one Start button,
 * the weakest type and the most frequent named mistake (with a link to its section), and the
 * self-test's record. A card is a template (a question with new numbers each time) or a
 * definition of the self-test; schedule.js (FSRS) says when each is due, from the attempts the
 * store keeps (progress-store.js). Plain JavaScript, offline, no physics. The pure part (top)
 * runs under Node for the tests; the page code (bottom) in a browser.
 *
 * Start keeps a review queue in localStorage ProgressStore.KEYS.review:
 *   {version: 1, home: URL of Your practice, at (ms), position: index of the card served,
 *    cards: [{id, type, url}]}
 * the cards due today, then the next ones (new cards from every type in turn, then the soonest
 * due), each run interleaved across types (never two of a type together while another waits).
 * review.js, on the pages that serve the cards, moves along it. */
(function (root) {
  "use strict";

  var Progress = root.PracticeProgress || require("./progress.js");

  // After the cards due today, Start serves this many more: enough for a session, not a list.
  var NEXT = 5;
  var DEFINITION = "definition:";
  var count = Progress.count;

  function plural(n, one, many) {
    return count(n) + " " + (n === 1 ? one : many);
  }

  /* Cards in an order that never puts two of one type together while another type has cards
   * left (CLARIFICATIONS, "Start's queue"): each turn takes the type with the most cards left
   * that is not the last one served, and its first card in the given order. Looking ahead
   * like this leaves no clump of one type at the end that a mix could have avoided; only
   * when one type has more than half the cards do two of it come together, and then at the
   * end. On a tie, the type whose next card comes first. lastType: the type served just
   * before. */
  function interleave(cards, lastType) {
    var byType = {},
      types = [],
      out = [];
    cards.forEach(function (card, at) {
      if (!byType[card.type]) {
        byType[card.type] = [];
        types.push(card.type);
      }
      byType[card.type].push({ card: card, at: at });
    });
    function better(a, b) {
      var left = byType[a].length - byType[b].length;
      return left > 0 || (left === 0 && byType[a][0].at < byType[b][0].at);
    }
    while (out.length < cards.length) {
      var take = null;
      types.forEach(function (type) {
        if (!byType[type].length || type === lastType) return;
        if (take === null || better(type, take)) take = type;
      });
      if (take === null) take = lastType; // no other type has a card left
      out.push(byType[take].shift().card);
      lastType = take;
    }
    return out;
  }

  /* The new cards Start serves, `most` of them, from every type in turn: each turn takes a card
   * of the type with the fewest cards tried so far (those in `tried`, and those taken here), on
   * a tie the type with the most new cards left, then the first in the book; its first new
   * card in book order. So a fresh student meets every type before a second card of any.
   * fresh: the cards never tried, in book order. */
  function pickNew(fresh, tried, most) {
    var byType = {},
      types = [],
      done = {},
      out = [];
    fresh.forEach(function (card) {
      if (!byType[card.type]) {
        byType[card.type] = [];
        types.push(card.type);
      }
      byType[card.type].push(card);
    });
    tried.forEach(function (card) {
      done[card.type] = (done[card.type] || 0) + 1;
    });
    while (out.length < most && out.length < fresh.length) {
      var take = null;
      types.forEach(function (type) {
        if (!byType[type].length) return;
        var fewer = (done[type] || 0) - (done[take] || 0);
        if (take === null || fewer < 0 || (fewer === 0 && byType[type].length > byType[take].length)) take = type;
      });
      out.push(byType[take].shift());
      done[take] = (done[take] || 0) + 1;
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

  /* What Start serves: the cards due today (soonest due first), then NEXT more (new cards from
   * every type in turn, pickNew; when none is left, the soonest due of the rest), each run
   * interleaved across types. Cards coming back later today (schedule.js: soon) wait for
   * their time. byDue: Schedule.cardsByDue(progress, now). Cards the build cannot serve are
   * left out. */
  function queue(data, byDue) {
    var cards = servable(data);
    var tried = {};
    byDue.forEach(function (c) {
      tried[c.id] = true;
    });
    function servableOf(list) {
      return list
        .filter(function (c) {
          return cards.byId[c.id];
        })
        .map(function (c) {
          return cards.byId[c.id];
        });
    }
    var due = servableOf(
      byDue.filter(function (c) {
        return c.today;
      }),
    );
    var fresh = cards.order
      .filter(function (id) {
        return !tried[id];
      })
      .map(function (id) {
        return cards.byId[id];
      });
    var later = servableOf(
      byDue.filter(function (c) {
        return !c.today && !c.soon;
      }),
    );
    var next = pickNew(fresh, servableOf(byDue), NEXT);
    next = next.concat(later.slice(0, NEXT - next.length));
    var first = interleave(due, null);
    return {
      due: first.length,
      cards: first.concat(interleave(next, first.length ? first[first.length - 1].type : null)),
    };
  }

  /* The plan's first line: the cards Start serves (served: queue()), then those coming back
   * later today (byDue's soon ones: not due yet, so not "due today"), with when the next one
   * does (backText(due, now): schedule.js's "in 5 minutes", "at 14:05"). */
  function dueLine(served, byDue, now, backText) {
    var more = served.cards.length - served.due;
    var soon = byDue.filter(function (c) {
      return c.soon;
    });
    var text = served.due
      ? plural(served.due, "card", "cards") + " due today" + (more ? ", then " + count(more) + " more" : "") + "."
      : (soon.length ? "Nothing due yet" : "No cards due today") +
        (more ? ": Start serves " + count(more) + " new." : ".");
    if (!soon.length) return text;
    var next = backText(soon[0].due, now);
    return (
      text +
      " " +
      (soon.length === 1
        ? "1 card comes back " + next + "."
        : count(soon.length) + " cards come back later today, the next " + next + ".")
    );
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
    NEXT: NEXT,
    interleave: interleave,
    pickNew: pickNew,
    servable: servable,
    queue: queue,
    weakestType: weakestType,
    mostFrequentMistake: mostFrequentMistake,
    mistakeSection: mistakeSection,
    definitionsRecord: definitionsRecord,
    dueLine: dueLine,
  };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.PracticePlan = api;

  // ------------------------------------------------------------------ page

  if (typeof document === "undefined" || !root.ProgressStore || !root.Schedule) return;
  var Store = root.ProgressStore;
  var Schedule = root.Schedule;
  var QUEUE = Store.KEYS.review;

  function link(href, text) {
    var a = document.createElement("a");
    a.href = href;
    a.textContent = text;
    return a;
  }

  /* The plan on the page (page): its box, data, plan and Start button, and what Start serves,
   * as last worked out (served). */
  function line(page, selector, parts) {
    var p = page.plan.querySelector(selector) || page.box.querySelector(selector);
    p.textContent = "";
    parts.forEach(function (part) {
      p.appendChild(typeof part === "string" ? document.createTextNode(part) : part);
    });
  }

  function renderWeakest(page, progress) {
    var weakest = weakestType(page.data.types, progress.attempts);
    line(
      page,
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
  }

  function renderMistake(page, progress) {
    var mistake = mostFrequentMistake(progress.attempts);
    var section = mistake && mistakeSection(page.data, mistake);
    line(
      page,
      ".pp-often",
      mistake
        ? ["Most frequent mistake: " + mistake.name + " (" + Progress.times(mistake.count) + ")."].concat(
            section ? [" Revisit: ", link(section.href, section.title), "."] : [],
          )
        : [progress.attempts.length ? "No named mistakes so far." : "Most frequent mistake: none yet."],
    );
  }

  function renderDefinitions(page, progress, byDue) {
    var data = page.data;
    var defs = definitionsRecord(data, progress, byDue);
    if (data.definitions) {
      line(page, ".pp-defs-line", [
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

  function render(page) {
    var read = Store.load();
    var progress = read.ok ? read.progress : Store.empty();
    var now = Date.now();
    var byDue = Schedule.cardsByDue(progress, now);
    page.served = queue(page.data, byDue);
    line(page, ".pp-due-text", [dueLine(page.served, byDue, now, Schedule.backText)]);
    page.startButton.disabled = !page.served.cards.length;
    renderWeakest(page, progress);
    renderMistake(page, progress);
    renderDefinitions(page, progress, byDue);
  }

  /* From disk (file://) Chromium at times gives two pages two apart localStorage areas (about
   * 1 visit in 10 without --allow-file-access-from-files), so there the link carries the queue
   * too, in ?review= (review.js reads it first). */
  function carried(url, queue) {
    if (location.protocol !== "file:") return url;
    var to = new URL(url);
    to.searchParams.set("review", JSON.stringify(queue));
    return to.href;
  }

  // Start: the queue served, kept for the review pages, and its first card opened.
  function startReview(page) {
    var served = page.served;
    if (!served || !served.cards.length) return;
    var cards = served.cards.map(function (c) {
      return { id: c.id, type: c.type, url: new URL(c.url, location.href).href };
    });
    var kept = { version: 1, home: location.href.split("#")[0], at: Date.now(), position: 0, cards: cards };
    try {
      localStorage.setItem(QUEUE, JSON.stringify(kept));
    } catch {
      line(page, ".pp-due-text", ["This browser does not let the page keep the queue (private mode?)."]);
      return;
    }
    location.href = carried(cards[0].url, kept);
  }

  function start() {
    var box = document.querySelector(".pp");
    if (!box) return;
    var plan = box.querySelector(".pp-plan");
    var page = {
      box: box,
      data: JSON.parse(box.querySelector("script.pp-data").textContent),
      plan: plan,
      startButton: plan.querySelector(".pp-start"),
      served: null,
    };
    page.startButton.addEventListener("click", function () {
      startReview(page);
    });

    // A link to a type opens its details.
    box.addEventListener("click", function (event) {
      var a = event.target.closest && event.target.closest('a[href^="#pp-type-"]');
      var target = a && document.getElementById(a.getAttribute("href").slice(1));
      if (target) target.open = true;
    });
    box.addEventListener("pp-changed", function () {
      render(page);
    });
    try {
      render(page);
    } finally {
      // shown now, filled: progress.css keeps the plan and the types unseen until then, so
      // their words arriving move nothing a reader sees (no layout shift)
      document.documentElement.classList.add("pp-planned");
    }
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
