/* The mock test's draws and clock (pure: it runs under Node for the tests too). A test is drawn
 * from the site's variants (the build's index: each template's key, type, marks, kinds and how
 * many site variants it has), types weighted by their exam counts with the draws the sheet
 * builder uses (question-draw.js: chooseTemplates, seededOrder), so a seed gives the same test
 * again. mock-test.js is the page. */
(function (root) {
  "use strict";

  var Draw = typeof module !== "undefined" && module.exports ? require("./question-draw.js") : root.QuestionDraw;
  // each part kind names the paper that asks it (static/question-kinds.js: mockPaper)
  var Kinds = typeof module !== "undefined" && module.exports ? require("./question-kinds.js") : root.QuestionKinds;

  /* 9702's pace: Paper 1, 1.875 minutes a multiple-choice question (40 in 75 minutes); Paper 2,
   * 1.25 minutes a mark (60 in 75 minutes). Paper 1's sizes count questions, Paper 2's marks. */
  var PAPERS = {
    1: { name: "Paper 1", minutesEach: 1.875, sizes: [10, 20], unit: ["question", "questions"] },
    2: {
      name: "Paper 2",
      minutesEach: 1.25,
      sizes: [15, 20, 30],
      unit: ["mark", "marks"],
    },
  };

  function paperOf(paper) {
    var found = PAPERS[paper];
    Draw.check(!!found, "paper", paper, 'must be "1" or "2"');
    return found;
  }

  /* A template a paper asks: Paper 1 its multiple-choice ones, Paper 2 those whose every part
   * is a value (or read from a graph). */
  function asks(paper, template) {
    paperOf(paper);
    // an explanation is self-marked by its ticks: no paper asks it (no score a test can count on)
    return template.kinds.every(function (kind) {
      return Kinds.get(kind).mockPaper === paper;
    });
  }

  function minutesFor(paper, size) {
    return size * paperOf(paper).minutesEach;
  }

  /* Each template up to `most` times (its copies), never more than it has variants: a test
   * longer than the templates allow asks some again, with other numbers (draw() allows as few
   * copies as the test needs). A type's copies are tried round by round (every template's
   * first copy, in the seed's order, then every second copy...), so a template comes twice only
   * when its type has no other left. Paper 1 counts questions: each copy weighs 1. */
  function copies(index, paper, most) {
    var out = [];
    index.templates.forEach(function (template) {
      if (!asks(paper, template)) return;
      for (var copy = 0; copy < Math.min(most, template.variants); copy++) {
        out.push({ key: template.key, type: template.type, marks: paper === "1" ? 1 : template.marks, copy: copy });
      }
    });
    return out;
  }

  function roundByRound(group, seed) {
    var keys = [];
    group.forEach(function (item) {
      if (keys.indexOf(item.key) < 0) keys.push(item.key);
    });
    var rank = Draw.seededOrder(keys, "mock-templates", seed);
    return group.slice().sort(function (a, b) {
      return a.copy - b.copy || rank.indexOf(a.key) - rank.indexOf(b.key);
    });
  }

  /* A test: {paper, size, seed, minutes, questions: [{question, type, variant}]}, the questions
   * in the seed's order, each copy of a template with its own variant (the site's: index into
   * the template's data file). Throws Draw.DrawError when the size cannot be made. */
  function draw(index, paper, size, seed) {
    paper = String(paper);
    Draw.check(
      paperOf(paper).sizes.indexOf(size) >= 0,
      "size",
      size,
      "must be one of " + paperOf(paper).sizes.join(", ") + " " + paperOf(paper).unit[1],
    );
    Draw.check(Draw.isWhole(seed) && seed >= 0, "seed", seed, "must be a whole number, 0 or more");
    var chosen = null;
    var most = Math.max.apply(
      null,
      index.templates.map(function (t) {
        return t.variants;
      }),
    );
    // each template once if the size can be made so, else twice, and so on
    for (var times = 1; !chosen; times++) {
      try {
        chosen = Draw.chooseTemplates(index, copies(index, paper, times), size, seed, roundByRound);
      } catch (error) {
        if (!(error instanceof Draw.DrawError) || times >= most) throw error;
      }
    }
    var counts = {};
    var total = {};
    index.templates.forEach(function (template) {
      total[template.key] = template.variants;
    });
    var asked = chosen.map(function (item) {
      var nth = (counts[item.key] = (counts[item.key] || 0) + 1) - 1;
      var all = [];
      for (var v = 0; v < total[item.key]; v++) all.push(v);
      var variant = Draw.seededOrder(all, "mock-variants:" + item.key, seed)[nth];
      return { question: item.key, type: item.type, variant: variant, copy: item.copy };
    });
    var questions = Draw.seededOrder(asked, "mock-order", seed, function (item) {
      return item.question + "#" + item.copy;
    }).map(function (item) {
      return { question: item.question, type: item.type, variant: item.variant };
    });
    return { paper: paper, size: size, seed: seed, minutes: minutesFor(paper, size), questions: questions };
  }

  // ------------------------------------------------------------------------------ the clock

  /* Milliseconds left of a test started at `at` (ms) with `minutes` allowed, at `now`. */
  function timeLeft(test, now) {
    return Math.max(0, test.at + test.minutes * 60000 - now);
  }

  /* "18:45": minutes and seconds left, a part second counted as a whole one (the clock reads
   * 0:00 only when time is up). */
  function clockText(ms) {
    var seconds = Math.ceil(ms / 1000);
    var rest = seconds % 60;
    return Math.floor(seconds / 60) + ":" + (rest < 10 ? "0" : "") + rest;
  }

  /* The warnings a screen reader hears, once each: at 5 minutes left and at 1 minute left. */
  var WARNINGS = [
    { at: 300000, text: "5 minutes left." },
    { at: 60000, text: "1 minute left." },
  ];

  /* The warning due at `ms` left, given those already given (their `at`s): the latest passed,
   * once (a test resumed at 30 s left hears "1 minute left." only), or null. */
  function warningDue(ms, given) {
    var due = null;
    WARNINGS.forEach(function (warning) {
      if (ms <= warning.at && given.indexOf(warning.at) < 0) due = warning;
    });
    return due;
  }

  // ------------------------------------------------------------------------------ the result

  /* The type a test's result shows weakest, for its "What next": the lowest share of its marks
   * (questions: [{type, earned, available}], the mock as the store keeps it); on a tie, the one
   * that lost more marks, then the first in the book (types: the index's, in book order).
   * {type (the index's entry), earned, available}, or null when every mark was earned. */
  function weakestType(types, questions) {
    var byType = {};
    questions.forEach(function (q) {
      var line = (byType[q.type] = byType[q.type] || { earned: 0, available: 0 });
      line.earned += q.earned;
      line.available += q.available;
    });
    var weakest = null;
    types.forEach(function (type) {
      var line = byType[type.key];
      if (!line || line.earned >= line.available) return;
      var share = line.earned / line.available,
        lost = line.available - line.earned;
      if (!weakest || share < weakest.share || (share === weakest.share && lost > weakest.lost)) {
        weakest = { type: type, earned: line.earned, available: line.available, share: share, lost: lost };
      }
    });
    return weakest && { type: weakest.type, earned: weakest.earned, available: weakest.available };
  }

  var api = {
    PAPERS: PAPERS,
    WARNINGS: WARNINGS,
    asks: asks,
    minutesFor: minutesFor,
    draw: draw,
    timeLeft: timeLeft,
    clockText: clockText,
    warningDue: warningDue,
    weakestType: weakestType,
    DrawError: Draw.DrawError,
  };
  if (typeof module !== "undefined" && module.exports) module.exports = api;
  else root.MockDraw = api;
})(this);
