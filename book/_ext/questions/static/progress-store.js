/* The student's progress, kept in this browser: every checked attempt, the definitions
 * self-test's marks and the mock tests, in one versioned object. Plain JavaScript, offline,
 * no physics. The pure part (top) runs under Node for the tests; the browser part (bottom)
 * reads and writes localStorage.
 *
 * Format 2, under localStorage KEYS.progress (the book's, from the page):
 *   {version: 2, book: BOOK, attempts: [attempt], definitions: {version: 1, cards: {slug:
 *    {mark, at}}}, mocks: [mock], schedule: {cardId: card}, student: "name"}
 * attempt: {question, type, variant, earned, available, at, mistakes: [names]} (format 1's
 *   fields) and help (working steps shown before the Check), seconds (from the numbers
 *   appearing to the Check), first (the first Check on these numbers), mock (the mock test it
 *   was answered in) and rating (1 Again, 2 Hard, 3 Good, 4 Easy: set here, from the rest).
 *   A definition of the self-test is a card too: question "definition:SLUG", type
 *   "definitions", 1 mark, earned 1 when the student knew it.
 * mock: {id, paper: "1" | "2", at, minutes, ended: "submitted" | "time", earned, available,
 *   questions: [{question, type, variant, earned, available}]}.
 * student: the student's name, asked once by Export (progress.js) and kept for the next
 *   export (absent until given; at most NAME_LENGTH characters).
 * schedule: each card's FSRS state as schedule.js last worked it out from the attempts (a
 *   copy for export: the attempts are the record, and the schedule is replayed from them).
 *
 * Format 1 (KEYS.oldProgress, attempts and definitions only) is upgraded on reading,
 * every attempt kept, and never deleted: an older build of the book still reads it. A store
 * of a version this page does not know is left exactly as it is and nothing is written over
 * it. */
(function (root) {
  "use strict";

  // The names this book keeps its records under, and its id: the build's (physics_figures/topics.py,
  // storage_keys), read from the page, so a book of another topic keeps its own.
  var KEYS = storageKeys();
  var STORE = KEYS.progress;
  var OLD_STORE = KEYS.oldProgress;
  var VERSION = 2;
  var BOOK = KEYS.book;
  var RATING = { again: 1, hard: 2, good: 3, easy: 4 };
  // Easy is full marks at the exam's pace or faster: 9702 Paper 2 gives 75 min for 60 marks,
  // 1.25 minutes a mark (CLARIFICATIONS, Plan).
  var SECONDS_A_MARK = 75;
  var DEFINITION = "definition:";
  var NAME_LENGTH = 80;

  /* The page's <meta name="book-storage"> (every page of the book has it); under Node, where
   * there is no page, the caller's globalThis.BOOK_STORAGE (tests/js/book_storage.js). */
  function storageKeys() {
    var meta = typeof document === "undefined" ? null : document.querySelector('meta[name="book-storage"]');
    if (meta) return JSON.parse(meta.content);
    if (typeof globalThis === "object" && globalThis.BOOK_STORAGE) return globalThis.BOOK_STORAGE;
    throw new Error('progress-store.js: no <meta name="book-storage"> names the book\'s storage keys');
  }

  function count(n) {
    return String(n);
  }

  /* The rating a Check earns its card (CLARIFICATIONS, Plan): no marks Again; part marks or
   * any help Hard; full marks Good, or Easy on the first try at these numbers, with no help,
   * within the exam's pace. */
  function rate(a) {
    if (a.earned <= 0) return RATING.again;
    if (a.earned < a.available || a.help > 0) return RATING.hard;
    var quick = typeof a.seconds === "number" && a.seconds <= SECONDS_A_MARK * a.available;
    return a.first === true && quick ? RATING.easy : RATING.good;
  }

  function isCount(n) {
    return Number.isInteger(n) && n >= 0;
  }

  /* An attempt's rules, in the order they are checked: [what is wrong, the test that finds it]
   * (a is an object, not an array, by the first rule). */
  var ATTEMPT_RULES = [
    ["names no question", (a) => typeof a.question !== "string" || !a.question],
    ["has no question type", (a) => typeof a.type !== "string"],
    ["has no variant number", (a) => !isCount(a.variant)],
    ["has no marks available", (a) => !Number.isInteger(a.available) || a.available < 1],
    [
      "has marks earned that are not between 0 and the marks available",
      (a) => !isCount(a.earned) || a.earned > a.available,
    ],
    ["has no time", (a) => typeof a.at !== "number" || !isFinite(a.at)],
    ["has no list of mistakes", (a) => !Array.isArray(a.mistakes) || a.mistakes.some((m) => typeof m !== "string")],
    ["has a help count that is not a whole number", (a) => "help" in a && !isCount(a.help)],
    ["has a time taken below 0", (a) => "seconds" in a && !(typeof a.seconds === "number" && a.seconds >= 0)],
    ["says neither yes nor no to first try", (a) => "first" in a && typeof a.first !== "boolean"],
    ["has a rating that is not 1 to 4", (a) => "rating" in a && [1, 2, 3, 4].indexOf(a.rating) < 0],
  ];

  // What is wrong with one attempt, or null.
  function attemptProblem(a) {
    if (!a || typeof a !== "object" || Array.isArray(a)) return "is not an attempt";
    var broken = ATTEMPT_RULES.filter((rule) => rule[1](a))[0];
    return broken ? broken[0] : null;
  }

  function mockProblem(m) {
    if (!m || typeof m !== "object" || Array.isArray(m)) return "is not a mock test";
    if (typeof m.id !== "string" || !m.id) return "has no id";
    if (m.paper !== "1" && m.paper !== "2") return "names no paper (1 or 2)";
    if (typeof m.at !== "number" || !isFinite(m.at)) return "has no time";
    if (!isCount(m.earned) || !isCount(m.available) || m.earned > m.available) {
      return "has marks earned that are not between 0 and the marks available";
    }
    if (!Array.isArray(m.questions)) return "has no list of questions";
    return null;
  }

  function empty() {
    return {
      version: VERSION,
      book: BOOK,
      attempts: [],
      definitions: { version: 1, cards: {} },
      mocks: [],
      schedule: {},
    };
  }

  function definitionAttempt(slug, known, at) {
    return {
      question: DEFINITION + slug,
      type: "definitions",
      variant: 0,
      earned: known ? 1 : 0,
      available: 1,
      at: at,
      mistakes: [],
    };
  }

  /* Format 1 as format 2: every attempt kept (rated from its marks, as format 1 kept no help
   * or time), and each definition's last mark as one review of its card. */
  function upgrade(old) {
    var progress = empty();
    progress.attempts = old.attempts.map(function (a) {
      return Object.assign({}, a, { rating: rate(a) });
    });
    var d = old.definitions;
    if (d && d.version === 1 && d.cards && typeof d.cards === "object") {
      progress.definitions = { version: 1, cards: Object.assign({}, d.cards) };
      Object.keys(d.cards).forEach(function (slug) {
        var card = d.cards[slug];
        if (!card || typeof card.at !== "number") return;
        var a = definitionAttempt(slug, card.mark === "known", card.at);
        a.rating = rate(a);
        progress.attempts.push(a);
      });
      progress.attempts.sort(byTime);
    }
    return progress;
  }

  function byTime(a, b) {
    return a.at - b.at;
  }

  function listProblem(list, what, problem) {
    for (var i = 0; i < list.length; i++) {
      var found = problem(list[i]);
      if (found) return what + " " + count(i + 1) + " of " + count(list.length) + " " + found + ".";
    }
    return null;
  }

  /* What is wrong with a progress file's head (its format version, book and student), or null. */
  function headerProblem(data) {
    if (!data || typeof data !== "object" || Array.isArray(data) || !("version" in data)) {
      return "it is not a progress file from this book (it has no format version).";
    }
    if (data.version !== 1 && data.version !== VERSION) {
      return typeof data.version === "number" && data.version > VERSION
        ? "it was saved by a newer version of the book (format " +
            count(data.version) +
            "); this page reads formats 1 and " +
            count(VERSION) +
            ". Open it in the newer book."
        : "its format version (" + String(data.version).slice(0, 20) + ") is not one this book wrote.";
    }
    if ("book" in data && data.book !== BOOK) {
      return "it is progress in another book (" + String(data.book).slice(0, 40) + ").";
    }
    if ("student" in data && typeof data.student !== "string") {
      return "its student's name is not text.";
    }
    return null;
  }

  /* Read stored or exported progress (text), format 1 or 2: {ok: true, progress, from} (from:
   * the format it was written in; format 1 comes back upgraded) or {ok: false, message}, the
   * message saying what is wrong. Nothing stored reads as empty progress. */
  function read(text) {
    if (text === null || text === undefined || text === "") return { ok: true, progress: empty(), from: VERSION };
    var data;
    try {
      data = JSON.parse(text);
    } catch {
      return { ok: false, message: "it is not a progress file from this book (it is not JSON)." };
    }
    var wrong = headerProblem(data);
    if (wrong) return { ok: false, message: wrong };
    if (!Array.isArray(data.attempts)) return { ok: false, message: "it has no list of attempts." };
    var problem = listProblem(data.attempts, "attempt", attemptProblem);
    if (problem) return { ok: false, message: problem };
    if (data.version === 1) return { ok: true, progress: upgrade(data), from: 1 };
    if (!Array.isArray(data.mocks)) return { ok: false, message: "it has no list of mock tests." };
    problem = listProblem(data.mocks, "mock test", mockProblem);
    if (problem) return { ok: false, message: problem };
    var progress = Object.assign(empty(), data);
    progress.attempts = data.attempts.map(function (a) {
      return "rating" in a ? a : Object.assign({}, a, { rating: rate(a) });
    });
    return { ok: true, progress: progress, from: VERSION };
  }

  function identity(a) {
    return JSON.stringify([a.question, a.variant, a.at, a.earned, a.available, a.mistakes]);
  }

  /* Both records in one, each attempt and mock test once, oldest first: importing the same
   * file twice adds nothing. A definition keeps its latest mark. The schedule is kept's until
   * schedule.js works it out again from the attempts. Returns {progress, added, already}. */
  function merge(kept, incoming) {
    var progress = Object.assign({}, kept),
      seen = {},
      added = 0;
    progress.attempts = kept.attempts.slice();
    kept.attempts.forEach(function (a) {
      seen[identity(a)] = true;
    });
    incoming.attempts.forEach(function (a) {
      var id = identity(a);
      if (seen[id]) return;
      seen[id] = true;
      progress.attempts.push(a);
      added += 1;
    });
    progress.attempts.sort(byTime);
    var mocks = {};
    progress.mocks = kept.mocks.slice();
    kept.mocks.forEach(function (m) {
      mocks[m.id] = true;
    });
    incoming.mocks.forEach(function (m) {
      if (!mocks[m.id]) progress.mocks.push(m);
      mocks[m.id] = true;
    });
    progress.mocks.sort(byTime);
    var cards = Object.assign({}, kept.definitions.cards);
    Object.keys(incoming.definitions.cards).forEach(function (slug) {
      var card = incoming.definitions.cards[slug];
      if (!cards[slug] || cards[slug].at < card.at) cards[slug] = card;
    });
    progress.definitions = { version: 1, cards: cards };
    // The name kept here stays; a file brings its name only where none is kept.
    if (!kept.student && incoming.student) progress.student = incoming.student;
    return { progress: progress, added: added, already: incoming.attempts.length - added };
  }

  /* Each card (a template, or a definition) with its reviews in time order: what the
   * scheduler replays. type: the card's question type, for interleaving. */
  function cards(progress) {
    var byId = {},
      out = [];
    progress.attempts
      .slice()
      .sort(byTime)
      .forEach(function (a) {
        var card = byId[a.question];
        if (!card) {
          card = byId[a.question] = { id: a.question, type: a.type, reviews: [] };
          out.push(card);
        }
        card.reviews.push({ at: a.at, rating: a.rating || rate(a) });
      });
    return out;
  }

  /* Add an attempt to progress (changed in place). A self-marked part is scored by the ticks
   * that follow its Check: with retick, the question's latest attempt on the same numbers is
   * updated instead (its time kept); ticks on numbers never checked here change nothing. */
  function addAttempt(progress, attempt, retick) {
    var list = progress.attempts,
      last = -1;
    for (var i = list.length - 1; i >= 0 && retick; i--) {
      if (list[i].question === attempt.question) {
        last = i;
        break;
      }
    }
    var kept = Object.assign({}, attempt);
    if (last >= 0 && list[last].variant === attempt.variant) {
      kept.at = list[last].at;
      ["help", "seconds", "first"].forEach(function (field) {
        if (field in list[last] && !(field in attempt)) kept[field] = list[last][field];
      });
      kept.rating = rate(kept);
      list[last] = kept;
      return true;
    }
    if (retick) return false;
    kept.rating = rate(kept);
    list.push(kept);
    return true;
  }

  var api = {
    KEYS: KEYS,
    STORE: STORE,
    OLD_STORE: OLD_STORE,
    VERSION: VERSION,
    BOOK: BOOK,
    RATING: RATING,
    DEFINITION: DEFINITION,
    NAME_LENGTH: NAME_LENGTH,
    rate: rate,
    attemptProblem: attemptProblem,
    empty: empty,
    upgrade: upgrade,
    read: read,
    merge: merge,
    cards: cards,
    addAttempt: addAttempt,
    definitionAttempt: definitionAttempt,
  };

  /* In the browser: the store in localStorage. load() reads format 2, or else upgrades the
   * format 1 store in memory ({ok: false} when the store is another version, or unreadable:
   * then nothing is written). Private mode keeps nothing, and says nothing. */
  function storage(name) {
    try {
      return root.localStorage.getItem(name);
    } catch {
      return null;
    }
  }

  function load() {
    var text = storage(STORE);
    if (text === null) text = storage(OLD_STORE);
    return read(text);
  }

  function save(progress) {
    try {
      root.localStorage.setItem(STORE, JSON.stringify(progress));
      return true;
    } catch {
      return false;
    }
  }

  // Change the store with change(progress) and keep it; false when it cannot be written.
  function update(change) {
    var loaded = load();
    if (!loaded.ok) return false;
    if (change(loaded.progress) === false) return false;
    return save(loaded.progress);
  }

  api.load = load;
  api.save = save;
  api.update = update;
  api.recordAttempt = function (attempt, retick) {
    return update(function (progress) {
      return addAttempt(progress, attempt, retick);
    });
  };
  api.recordMock = function (mock) {
    if (mockProblem(mock)) return false;
    return update(function (progress) {
      progress.mocks.push(mock);
    });
  };
  api.recordDefinition = function (slug, known, at) {
    return update(function (progress) {
      progress.definitions.cards[slug] = { mark: known ? "known" : "not-yet", at: at };
      addAttempt(progress, definitionAttempt(slug, known, at), false);
    });
  };

  if (typeof module === "object" && module.exports) module.exports = api;
  else root.ProgressStore = api;
})(this);
