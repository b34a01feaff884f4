/* The marking engine: questions marked like an examiner. Plain JavaScript, no dependencies,
 * offline; pure, so it runs under Node for the tests. Each part kind marks its answer
 * (static/question-kinds/), and the rule table says what the outcome earns, line by line,
 * with error carried forward. The page (static/questions.js) only calls markQuestion. */
(function (root) {
  "use strict";

  /* The rule table (physics_figures/marking_rules.json): what each outcome loses of a part's
   * mark lines, by their roles. A page carries it once (script.q-rules, from the build);
   * under Node the engine reads the file itself. This engine has no marking rule of its own. */
  var rulesCache = null;
  function rules() {
    if (rulesCache) return rulesCache;
    if (typeof document !== "undefined") {
      var script = document.querySelector("script.q-rules");
      rulesCache = script ? JSON.parse(script.textContent) : null;
    } else {
      var table = require("../../../../physics_figures/marking_rules.json"),
        losses = {};
      Object.keys(table.outcomes).forEach(function (code) {
        if (Array.isArray(table.outcomes[code].loses)) losses[code] = table.outcomes[code].loses;
      });
      var slips = {};
      Object.keys(table.slips.names).forEach(function (name) {
        table.slips.names[name].outcomes.forEach(function (code) {
          slips[code] = name;
        });
      });
      rulesCache = { outcomes: losses, sigFigs: table.sig_figs, slips: slips, names: table.mark_names };
    }
    return rulesCache;
  }

  /* The part kinds, each its own script (static/question-kinds/), registered in QuestionKinds
   * (static/question-kinds.js: in a page before this script runs; under Node it loads them). */
  var Kinds = root.QuestionKinds || require("./question-kinds.js");

  /* Mark one answer to one part: its kind's marker gives the outcome (code, message). The
   * marker gets the rule table's figures too: its feedback on too few figures is the table's. */
  function mark(part, answer) {
    var kind = Kinds.of(part);
    var figures = rules().sigFigs; // the rule table's, where a part does not say otherwise
    if (part.minSf === undefined || part.checkSf === undefined) {
      part = Object.assign({ minSf: figures.min, checkSf: figures.check }, part);
    }
    return kind.mark(part, answer || {}, figures);
  }

  // ------------------------------------------------------------ marks, as an exam awards them

  /* The roles of a part's mark lines that an outcome loses: a named mistake's own, else the
   * rule table's; a direction chosen wrong loses the direction's mark whatever else. */
  function lostRoles(result) {
    var table = rules().outcomes;
    var lost = result.loses || table[result.code] || table.wrong;
    return result.directionWrong ? lost.concat(["direction"]) : lost;
  }

  /* The marks earned: each line of data.marks ({part, code, roles}) counts in its one part and
   * is earned unless that part's outcome loses a role it plays (a self-marked line: when
   * ticked). Returns {earned, available, byPart: {id: [earned, available]}, lines: [bool]}. */
  function award(data, results) {
    var byPart = {},
      earned = 0,
      lines = [];
    data.parts.forEach(function (part) {
      byPart[part.id] = [0, 0];
    });
    data.marks.forEach(function (line, index) {
      var part = data.parts.filter(function (p) {
        return p.id === line.part;
      })[0];
      var result = results[line.part] || { code: "wrong" };
      var ok = Kinds.of(part).selfMarked
        ? ticked(data, result, index)
        : !line.roles.some(function (role) {
            return lostRoles(result).indexOf(role) >= 0;
          });
      byPart[line.part][1] += 1;
      if (ok) {
        byPart[line.part][0] += 1;
        earned += 1;
      }
      lines.push(ok);
    });
    return { earned: earned, available: data.marks.length, byPart: byPart, lines: lines };
  }

  /* A self-marked line counts when ticked, and when the line it needs (a dependent A1's M1,
   * from the build) is ticked too. */
  function ticked(data, result, index) {
    var list = (result && result.ticked) || [];
    var needs = data.marks[index].needs;
    return list.indexOf(index) >= 0 && (needs === undefined || needs === null || list.indexOf(needs) >= 0);
  }

  /* What a part lost, in words, each code glossed by what the line is for: "2/3 marks: the
   * accuracy mark (A1) is lost; the method mark (C1) and the direction mark (B1) stand." Lines
   * of one kind go together: "both method marks (C1) stand". */
  function lostText(data, awarded, partId) {
    var lost = [],
      kept = [];
    data.marks.forEach(function (line, i) {
      if (line.part === partId) (awarded.lines[i] ? kept : lost).push(line);
    });
    if (!lost.length || !kept.length) return "";
    function names(lines) {
      return lines.map(markName);
    }
    // a kind on both sides: "one method mark (C1) is lost; the other method mark (C1) stands"
    function list(lines, others, first) {
      var order = [],
        codes = {};
      lines.forEach(function (line) {
        var name = markName(line);
        if (!codes[name]) {
          codes[name] = [];
          order.push(name);
        }
        codes[name].push(line.code);
      });
      var phrases = order.map(function (name) {
        return glossed(name, codes[name], others.indexOf(name) >= 0, first);
      });
      return phrases.length === 1
        ? phrases[0]
        : phrases.slice(0, -1).join(", ") + " and " + phrases[phrases.length - 1];
    }
    return (
      marksText(kept.length, kept.length + lost.length) +
      ": " +
      list(lost, names(kept), true) +
      (lost.length === 1 ? " is" : " are") +
      " lost; " +
      list(kept, names(lost), false) +
      (kept.length === 1 ? " stands." : " stand.")
    );
  }

  /* What a mark line is for, in a student's words (marking_rules.json "mark_names"): by its
   * code, but a line that only gives a direction is the direction mark. */
  function markName(line) {
    var names = rules().names || {};
    if (line.roles.length === 1 && line.roles[0] === "direction") return names.direction;
    return names[line.code] || "mark";
  }

  /* "the method mark (C1)", "both method marks (C1)", "the three method marks (C1, M1, C1)";
   * of a kind the other side has too (shared; first: the lost side): "one method mark (C1)",
   * "the other two method marks (C1)". */
  function glossed(name, codes, shared, first) {
    var same = codes.every(function (code) {
      return code === codes[0];
    });
    var n = codes.length,
      word = NUMBER_WORDS[n] || String(n);
    var shown = " (" + (same ? codes[0] : codes.join(", ")) + ")";
    if (shared && first) return word + " " + name + (n === 1 ? "" : "s") + shown;
    if (shared) return "the other " + (n === 1 ? name : word + " " + name + "s") + shown;
    if (n === 1) return "the " + name + shown;
    return (n === 2 ? "both " : "the " + word + " ") + name + "s" + shown;
  }
  var NUMBER_WORDS = { 1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six" };

  function marksText(earned, available) {
    return earned + "/" + available + " mark" + (available === 1 ? "" : "s");
  }

  /* Mark every part of a question, carrying an error forward: a later part with ecf methods
   * (physics_figures.questions.Ecf, printed by sympy) is also marked against the student's
   * own earlier answers by each method, and earns its marks if it follows from them. A right
   * answer is right whatever the earlier parts say. */
  function markQuestion(data, answers) {
    var results = {};
    data.parts.forEach(function (part) {
      var result = mark(part, answers[part.id] || {});
      var methods = part.ecf || [];
      if (result.code !== "correct" && result.code !== "alternative" && methods.length) {
        result = carried(part, methods, answers[part.id] || {}, results, data) || result;
      }
      // a direction asked for and chosen wrong (or not chosen) never earns the direction's
      // mark, and a right one earns it whatever the size (a B mark stands on its own)
      result.directionWrong =
        part.direction === "choice" && (answers[part.id] || {}).direction !== part.answerDirection;
      results[part.id] = result;
    });
    return { results: results, marks: award(data, results) };
  }

  function carried(part, methods, answer, earlier, data) {
    var partial = null;
    for (var m = 0; m < methods.length; m++) {
      var found = carriedBy(part, methods[m], answer, earlier, data);
      if (found && (found.code === "correct" || found.code === "ecf")) return found;
      partial = partial || found;
    }
    return partial;
  }

  /* The earlier answers a later part may be worked from: each as typed, or (where it matched a
   * value: the key, a named mistake, a slip) that value with all its figures, as a student's
   * working carries it (CLARIFICATIONS, "ecf after a named mistake"). Every combination, the
   * typed one first: [{id: SI value}], or null when an earlier answer has no value in SI. */
  function earlierValues(uses, earlier) {
    var sets = [{}];
    for (var i = 0; i < uses.length; i++) {
      var before = earlier[uses[i]];
      if (!before || before.si === null || before.si === undefined) return null;
      var forms = [before.si];
      if (typeof before.exact === "number" && before.exact !== before.si) forms.push(before.exact);
      var grown = [];
      sets.forEach(function (set) {
        forms.forEach(function (value) {
          var next = Object.assign({}, set);
          next[uses[i]] = value;
          grown.push(next);
        });
      });
      sets = grown;
    }
    return sets;
  }

  function carriedBy(part, ecf, answer, earlier, data) {
    var sets = earlierValues(ecf.uses, earlier);
    if (!sets) return null;
    var partial = null;
    for (var s = 0; s < sets.length; s++) {
      var found = carriedFrom(part, ecf, answer, earlier, data, sets[s]);
      if (found && (found.code === "correct" || found.code === "ecf")) return found;
      partial = partial || found;
    }
    return partial;
  }

  function carriedFrom(part, ecf, answer, earlier, data, known) {
    var uses = ecf.uses;
    // A reading of a graph may be right yet not exact (half a small square either way): a
    // later part is then worked from the student's own reading, and is simply right.
    var fromReadings = uses.some(function (id) {
      return data.parts.some(function (p) {
        return p.id === id && !!Kinds.of(p).readsGraph;
      });
    });
    var allRight = uses.every(function (id) {
      return earlier[id].valueRight;
    });
    if (allRight && !fromReadings) return null;
    var args = ecf.args.map(function (name) {
      return name in known ? known[name] : ecf.values[name];
    });
    var value = formula(ecf).apply(null, args);
    if (!isFinite(value)) return null;
    // a difference that cancels (kinetic energy kept, none lost) is zero, not rounding's 1e-17
    if (Math.abs(value) < 1e-12 * Math.max.apply(null, args.map(Math.abs))) value = 0;
    var own = {};
    Object.keys(part).forEach(function (k) {
      own[k] = part[k];
    });
    own.value = part.direction === "signed" ? value : Math.abs(value);
    own.mistakes = [];
    own.gNineEight = null;
    own.roundedPartWay = [];
    own.alternatives = [];
    own.band = null; // marked against the student's own earlier answers, not the graph's
    var result = mark(own, answer);
    var outcome = Kinds.of(part).outcome; // the part's kind builds its outcomes (a kind with ecf)
    if (result.code === "correct" && allRight) {
      return outcome("correct", "Correct: it follows from your readings of the graph.", {
        si: result.si,
        exact: result.exact,
        valueRight: true,
      });
    }
    if (allRight) return null;
    if (result.code === "correct") {
      return outcome(
        "ecf",
        "Follows correctly from your answer to (" +
          uses.join("), (") +
          "): error carried forward (ecf), so this part earns its marks.",
        { si: result.si, exact: result.exact, valueRight: false },
      );
    }
    // follows from the earlier answer, but with a slip of its own (direction, unit, s.f.)
    if (result.code === "wrong" || /^unreadable/.test(result.code)) return null;
    result.message = "Follows from your answer to (" + uses.join("), (") + ") (ecf), but: " + result.message;
    return result;
  }

  /* Where feedback sends the student back to, as the question's data names it (never guessed
   * from its words): a named mistake's own section, else its part's; a wrong answer, its
   * part's; any other outcome, the rule table's row for it ("rule:" + code). The page turns
   * the id into a link; an id it has no link for gives none. */
  function sectionFor(part, result) {
    if (result.code === "mistake") return result.see || part.see || null;
    if (result.code === "wrong") return part.see || null;
    return "rule:" + result.code;
  }

  var formulas = {};
  function formula(ecf) {
    var key = ecf.args.join(",") + ":" + ecf.js;
    if (!formulas[key]) formulas[key] = new Function(ecf.args.join(","), "return " + ecf.js + ";");
    return formulas[key];
  }

  /* The slip an outcome is, by the name a student's record keeps (marking_rules.json "slips":
   * a sign error, a missing unit and a 1 s.f. answer count as mistakes; CLARIFICATIONS, Plan),
   * or undefined. */
  function slipName(code) {
    return rules().slips[code];
  }

  // What reads a typed answer, for the tests and scripts that drive the engine under Node.
  var Reading = root.AnswerReading || require("./answer-reading.js");
  var engine = {
    parseNumber: Reading.parseNumber,
    parseUnit: Reading.parseUnit,
    splitValueAndUnit: Reading.splitValueAndUnit,
    recasedUnit: Reading.recasedUnit,
    superscript: Reading.superscript,
    mark: mark,
    markQuestion: markQuestion,
    award: award,
    lostText: lostText,
    marksText: marksText,
    sectionFor: sectionFor,
    slipName: slipName,
  };

  if (typeof module === "object" && module.exports) module.exports = engine;
  else root.QuestionMarking = engine;
})(this);
