/* "Your practice", the record: what a student has done with the bank, by question type (a
 * line each: marks, tried, due; its questions folded beneath), the mock tests, and moving the
 * record to and from a file. Plain JavaScript, offline, no physics. The plan at the top of
 * the page is progress-plan.js's. This file is the pure part, which the tests run under Node
 * (and the class page reads); the page code, in a browser, is progress-page.js.
 *
 * Storage: the progress store (progress-store.js, format 2, "dynamics-progress-v2"; a format 1
 * store is upgraded on reading and never deleted). A store of a format this page does not know
 * is left exactly as it is (Export still copies it out whole) and nothing is written over it.
 * Export writes format 2 with the student's name (asked once, kept in the store), the schedule
 * (schedule.js), the book's id and a checksum of the attempts (progress-file.js, for the
 * teacher's class page), to dynamics-progress-NAME-DATE.json; Import reads formats 1 and 2 as
 * the class page does (an older export is read, not checked; another book's, or an edited one,
 * is refused) and adds each attempt once. */
(function (root) {
  "use strict";

  var Notation = root.Notation || require("../../notation/static/notation.js");

  var MONTHS = ["Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"];

  function count(n) {
    return Notation.formatNumber(n, null, { decimals: 0 });
  }
  function marksText(earned, available) {
    return count(earned) + "/" + count(available) + " mark" + (available === 1 ? "" : "s");
  }
  function times(n) {
    return n === 1 ? "once" : n === 2 ? "twice" : count(n) + " times";
  }

  /* When a card is due, as a student reads it: "due today" up to the end of today (dayEnds,
   * local midnight), else "due 28 Nov" (with the year when it is not this one). */
  function dueText(due, now, dayEnds) {
    if (due < dayEnds) return "due today";
    var day = new Date(due);
    var year = day.getFullYear() === new Date(now).getFullYear() ? "" : " " + day.getFullYear();
    return "due " + day.getDate() + " " + MONTHS[day.getMonth()] + year;
  }

  /* One type's progress. kind: {type, name, templates: [{key, title, marks, page}]} (the
   * build's list). Attempts count by their question's key, so a template the bank no longer
   * has is kept in the store but not shown. Marks: the best attempt at each template tried.
   * withHelp: the attempts that used help before their Check. */
  function summarise(kind, attempts) {
    var byKey = {},
      mistakes = {},
      order = [];
    kind.templates.forEach(function (t) {
      byKey[t.key] = { template: t, attempts: [] };
    });
    attempts.forEach(function (a) {
      var entry = byKey[a.question];
      if (!entry) return;
      entry.attempts.push(a);
      a.mistakes.forEach(function (name) {
        if (!mistakes[name]) {
          mistakes[name] = 0;
          order.push(name);
        }
        mistakes[name] += 1;
      });
    });
    var tried = 0,
      earned = 0,
      available = 0,
      templates = {};
    kind.templates.forEach(function (t) {
      var entry = byKey[t.key],
        best = null,
        last = null,
        withHelp = 0;
      entry.attempts.forEach(function (a) {
        if (!best || a.earned / a.available > best.earned / best.available) best = a;
        if (!last || a.at >= last.at) last = a;
        if (a.help > 0) withHelp += 1;
      });
      templates[t.key] = { attempts: entry.attempts.length, best: best, last: last, withHelp: withHelp };
      if (best) {
        tried += 1;
        earned += best.earned;
        available += best.available;
      }
    });
    var often = order
      .map(function (name) {
        return { name: name, count: mistakes[name] };
      })
      .sort(function (a, b) {
        return b.count - a.count;
      }); // stable: first made first on a tie
    return {
      tried: tried,
      inBank: kind.templates.length,
      earned: earned,
      available: available,
      mistakes: often,
      templates: templates,
    };
  }

  /* The template "Practise this type" serves: the first untried one (bank order); else one
   * whose last attempt lost marks, the longest ago first; else the longest ago. Only
   * templates a page places can be served; null if none is. */
  function nextTemplate(kind, summary) {
    var placed = kind.templates.filter(function (t) {
      return t.page;
    });
    var untried = placed.filter(function (t) {
      return !summary.templates[t.key].last;
    });
    if (untried.length) return untried[0];
    function lastAt(t) {
      return summary.templates[t.key].last.at;
    }
    function oldestFirst(list) {
      return list.slice().sort(function (a, b) {
        return lastAt(a) - lastAt(b);
      })[0];
    }
    var wrong = placed.filter(function (t) {
      var last = summary.templates[t.key].last;
      return last.earned < last.available;
    });
    return (wrong.length ? oldestFirst(wrong) : oldestFirst(placed)) || null;
  }

  function practiseUrl(template) {
    var key = encodeURIComponent(template.key);
    return template.page + "?new=" + key + "#question-" + key;
  }

  /* A type's line: "3/8 marks · 2 of 9 tried · 1 due" (due: its cards due today). */
  function typeLine(summary, dueToday) {
    if (!summary.inBank) return "not in the bank yet";
    var parts = [
      summary.tried ? marksText(summary.earned, summary.available) : "no marks yet",
      count(summary.tried) + " of " + count(summary.inBank) + " tried",
    ];
    if (dueToday) parts.push(count(dueToday) + " due");
    return parts.join(" · ");
  }

  /* A mock test as Your practice lists it: "Paper 1, 26 Nov 2026: 14/20 marks (70 %)". */
  function mockText(mock) {
    var day = new Date(mock.at);
    var share = mock.available ? Math.round((100 * mock.earned) / mock.available) : 0;
    return (
      "Paper " +
      mock.paper +
      ", " +
      day.getDate() +
      " " +
      MONTHS[day.getMonth()] +
      " " +
      day.getFullYear() +
      ": " +
      marksText(mock.earned, mock.available) +
      " (" +
      count(share) +
      "\u202f%)" +
      (mock.ended === "time" ? ", ended when time ran out" : "")
    );
  }

  var api = {
    summarise: summarise,
    nextTemplate: nextTemplate,
    practiseUrl: practiseUrl,
    marksText: marksText,
    times: times,
    dueText: dueText,
    typeLine: typeLine,
    mockText: mockText,
    count: count,
  };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.PracticeProgress = api;
})(this);
