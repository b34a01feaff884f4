/* The text part kind: a define or state part marked from the typed words, by the rules the part
 * carries (its points, each with the wordings an examiner accepts and those the schemes reject).
 * Its Python twin is TextPart (physics_figures/parts/text.py: the rule syntax). Pure: it runs
 * under Node for the tests. How an answer is read (CLARIFICATIONS, Papers):
 * - case, punctuation and word order within a point do not matter; a point's words must be said
 *   together, in one clause of the answer;
 * - a word of 5 or more letters one edit away (a letter added, dropped, changed, or two swapped)
 *   counts; "not" or "no" just before a key word negates it;
 * - a point contradicted elsewhere in the answer is lost (9702's "a contradiction loses the mark");
 * - an A1 counts only with the M1 it depends on;
 * - a point's words all there but in different clauses: the marker cannot decide, says so, and
 *   the student ticks that point (kept as self-marked). */
(function (root) {
  "use strict";

  // One spelling for the words and symbols an answer may use for one idea: "words > spelling".
  var CANON = {};
  (
    "* x times multiplied multiply product > ×; ÷ per over divided > /; equals equal > =; " +
    "∆ delta change changes changing > δ; p momenta > momentum; f forces > force; m > mass; " +
    "v velocities > velocity; t > time; bodies object objects particle particles > body; " +
    "conserved unchanged preserved > constant; net unbalanced > resultant; without > no; " +
    "kilogram kilograms > kg; one > 1; w > weight"
  )
    .split("; ")
    .forEach(function (rule) {
      var sides = rule.split(" > ");
      sides[0].split(" ").forEach(function (word) {
        CANON[word] = sides[1];
      });
    });
  // Symbols that stand for several words.
  var EXPAND = {
    mv: ["mass", "×", "velocity"],
    ma: ["mass", "×", "acceleration"],
    ke: ["kinetic", "energy"],
    ek: ["kinetic", "energy"],
    dp: ["δ", "momentum"],
    dt: ["δ", "time"],
  };
  // Words that carry no meaning for a point (dropped from answers and wordings alike).
  var STOP = {};
  (
    "a an the of is are was were be been its it their his her in to that which this these there " +
    "by and or as for with has have had will would can may does do s any"
  )
    .split(" ")
    .forEach(function (w) {
      STOP[w] = true;
    });
  var NEGATORS = { not: true, no: true, never: true };
  // Words that start a new clause: a point's words must be together in one clause.
  var CLAUSE_WORDS = { but: true, however: true, whereas: true, although: true, though: true, whilst: true };
  var BOUNDARY = "|",
    PRONOUN = "^",
    PRONOUN_MARK = "zzpronoun";
  // The subjects a point may be about: "weight>varies" is not made by "mass … varies".
  var RIVALS = { mass: true, weight: true };
  var TOKEN = /(\d+(?:\.\d+)?)|(δ)|([a-zà-ÿ]+)|([=×*/÷+\-−])|([.;!?\n])/g;

  // Optimal string alignment distance, at most `limit` + 1 (enough to say "one edit away").
  function editDistance(a, b, limit) {
    if (Math.abs(a.length - b.length) > limit) return limit + 1;
    var prev2 = null,
      prev = [],
      i,
      j;
    for (j = 0; j <= b.length; j++) prev[j] = j;
    for (i = 1; i <= a.length; i++) {
      var row = [i],
        best = i;
      for (j = 1; j <= b.length; j++) {
        var cost = a[i - 1] === b[j - 1] ? 0 : 1;
        var d = Math.min(prev[j] + 1, row[j - 1] + 1, prev[j - 1] + cost);
        if (prev2 && i > 1 && j > 1 && a[i - 1] === b[j - 2] && a[i - 2] === b[j - 1])
          d = Math.min(d, prev2[j - 2] + 1);
        row[j] = d;
        if (d < best) best = d;
      }
      if (best > limit) return limit + 1;
      prev2 = prev;
      prev = row;
    }
    return prev[b.length];
  }

  // A typed word of 5 or more letters one edit from a canonical word is that word.
  var LONG_CANON = Object.keys(CANON).filter(function (w) {
    return w.length >= 5;
  });
  function canonical(word) {
    if (Object.prototype.hasOwnProperty.call(CANON, word)) return [CANON[word]];
    if (Object.prototype.hasOwnProperty.call(EXPAND, word)) return EXPAND[word];
    if (word.length >= 5) {
      for (var i = 0; i < LONG_CANON.length; i++) {
        if (editDistance(word, LONG_CANON[i], 1) <= 1) return [CANON[LONG_CANON[i]]];
      }
    }
    return [word];
  }

  /* The answer's words, canonical, stop words dropped, a BOUNDARY between clauses. */
  function tokenise(text) {
    var prepared = String(text || "")
      .normalize("NFKC")
      .replace(/∆/g, "Δ")
      // bodies named A and B ("A exerts a force on B"), told from the article "A" that opens a
      // sentence ("A body …")
      .replace(/(^|[.;!?]\s*)A\b(?!\s+(?:exerts|pushes|pulls|acts|applies|and)\b)/g, "$1a")
      .replace(/\b([AB])\b(?!\s*=)/g, " body$1 ")
      .toLowerCase()
      .replace(/[’‘`]/g, "'")
      .replace(/\b(?:k\.e\.?|e\.g\.?|i\.e\.?)/g, function (m) {
        return m.replace(/\./g, "");
      })
      .replace(/\b(can)'?t\b|\bcannot\b/g, "can not")
      .replace(/\bwon'?t\b/g, "will not")
      .replace(/n't\b/g, " not")
      // "…; it is a scalar": a clause opened by a pronoun is about the subject of the one before
      .replace(/([.;!?\n])\s*(?:it|this|they)\b/g, "$1 " + PRONOUN_MARK)
      .replace(/'s?\b/g, " ");
    var out = [],
      match;
    TOKEN.lastIndex = 0;
    while ((match = TOKEN.exec(prepared))) {
      if (match[3] === PRONOUN_MARK) out.push(PRONOUN);
      else if (match[5] !== undefined) out.push(BOUNDARY);
      else if (match[4] !== undefined) out.push(canonical(match[4] === "−" ? "-" : match[4])[0]);
      else if (match[2] !== undefined || match[1] !== undefined) out.push(match[0]);
      else if (CLAUSE_WORDS[match[3]]) out.push(BOUNDARY);
      else if (!STOP[match[3]]) Array.prototype.push.apply(out, canonical(match[3]));
    }
    return out;
  }

  function clauses(tokens) {
    var list = [[]];
    tokens.forEach(function (t) {
      var last = list[list.length - 1];
      if (t === BOUNDARY) {
        if (last.length) list.push([]);
      } else if (t === PRONOUN) {
        var before = list[list.length - 2];
        if (!last.length && before) last.push(before[0]);
      } else last.push(t);
    });
    return list.filter(function (c) {
      return c.length;
    });
  }

  /* A wording in the rule syntax (TextPart): words separated by spaces, each a term that must be
   * present; "a|b" gives a term's alternatives; "(word)" is optional (dropped); "a_b" is a phrase
   * whose words come together, in order. Compiled once per wording. */
  var compiled = new Map();
  function compile(wording) {
    var terms = compiled.get(wording);
    if (terms) return terms;
    terms = wording
      .replace(/\([^)]*\)/g, " ")
      .split(/\s+/)
      .filter(Boolean)
      .map(function (term) {
        return term.indexOf(">") > 0 ? orderedTerm(term) : alternatives(term);
      })
      .filter(function (alternatives) {
        return alternatives.length;
      });
    compiled.set(wording, terms);
    return terms;
  }

  function alternatives(words) {
    return words
      .split("|")
      .map(function (alternative) {
        return tokenise(alternative.replace(/_/g, " ")).filter(function (t) {
          return t !== BOUNDARY;
        });
      })
      .filter(function (list) {
        return list.length;
      });
  }

  /* "weight>varies|depends": a word, then one of the others after it in its clause, with no
   * other subject between (so that "mass resists change …, weight is …" gives weight nothing). */
  function orderedTerm(term) {
    var halves = term.split(">");
    var ordered = [{ first: alternatives(halves[0]), then: alternatives(halves[1]) }];
    ordered.ordered = true;
    return ordered;
  }

  var same = new Map();
  function sameWord(typed, wanted) {
    if (typed === wanted) return true;
    if (typed.length < 5 || wanted.length < 5) return false;
    var key = typed + " " + wanted,
      known = same.get(key);
    if (known === undefined) {
      known = editDistance(typed, wanted, 1) <= 1;
      same.set(key, known);
    }
    return known;
  }

  function phraseAt(words, clause, s) {
    if (s + words.length > clause.length) return false;
    for (var k = 0; k < words.length; k++) if (!sameWord(clause[s + k], words[k])) return false;
    return true;
  }

  function orderedOccurrences(pair, clause) {
    var found = [];
    for (var s = 0; s < clause.length; s++) {
      pair.first.forEach(function (words) {
        if (!phraseAt(words, clause, s)) return;
        for (var e = s + words.length; e < clause.length; e++) {
          pair.then.forEach(function (next) {
            // placed where its second word is (a point is said near its verb), its subject kept
            if (phraseAt(next, clause, e)) found.push({ start: e, length: next.length, head: s });
          });
          if (RIVALS[clause[e]] && clause[e] !== clause[s]) break;
        }
      });
    }
    return found;
  }

  // Where in a clause a term's alternatives begin: [{start, length}].
  function occurrences(term, clause) {
    if (term.ordered) return orderedOccurrences(term[0], clause);
    var found = [];
    term.forEach(function (words) {
      for (var s = 0; s + words.length <= clause.length; s++) {
        if (phraseAt(words, clause, s)) found.push({ start: s, length: words.length });
      }
    });
    return found;
  }

  /* How a wording stands in one clause: "said" (every term, none negated), "negated" (every
   * term, one only after "not"/"no"), or "" (a term absent). A negator that is itself a word of
   * the wording ("no resultant external force") negates nothing. */
  function inClause(terms, clause) {
    var found = terms.map(function (term) {
      return occurrences(term, clause);
    });
    if (
      found.some(function (f) {
        return !f.length;
      })
    )
      return "";
    var own = {};
    found.forEach(function (list) {
      list.forEach(function (o) {
        for (var k = 0; k < o.length; k++) own[o.start + k] = true;
        if (o.head !== undefined) own[o.head] = true;
      });
    });
    function negated(o) {
      for (var back = 1; back <= 2; back++) {
        var at = o.start - back;
        if (at >= 0 && !own[at] && NEGATORS[clause[at]]) return true;
      }
      return false;
    }
    // The point as said: its tightest window. "not" just before its first word negates the
    // whole of it ("not mass × speed"), and just before any of its words, that word.
    var best = tightestWindow(found, 3 * terms.length + 2);
    if (!best) return "";
    return negated({ start: best.first }) || best.chosen.some(negated) ? "negated" : "said";
  }

  /* The tightest window holding one occurrence of every term, within `limit` words (a point is
   * said together, not made of words scattered over a long clause): from each occurrence, the
   * nearest of every other term after it. {span, first, chosen} or null. */
  function tightestWindow(found, limit) {
    var best = null;
    found.forEach(function (anchors) {
      anchors.forEach(function (anchor) {
        var end = anchor.start,
          chosen = [];
        var complete = found.every(function (list) {
          var nearest = null;
          list.forEach(function (o) {
            if (o.start >= anchor.start && (!nearest || o.start + o.length < nearest.start + nearest.length))
              nearest = o;
          });
          if (!nearest) return false;
          chosen.push(nearest);
          end = Math.max(end, nearest.start + nearest.length);
          return true;
        });
        var span = end - anchor.start;
        if (complete && span <= limit && (!best || span < best.span)) {
          best = { span: span, first: anchor.head === undefined ? anchor.start : anchor.head, chosen: chosen };
        }
      });
    });
    return best;
  }

  // A wording across the whole answer: "said" in one clause, "negated", "both" (said in one
  // clause, negated in another), "split" (every term said, but not together: the marker cannot
  // decide), or "".
  function wordingState(wording, answerClauses) {
    var terms = compile(wording),
      said = false,
      negated = false;
    answerClauses.forEach(function (clause) {
      var here = inClause(terms, clause);
      said = said || here === "said";
      negated = negated || here === "negated";
    });
    if (said || negated) return said && negated ? "both" : said ? "said" : "negated";
    if (answerClauses.length < 2) return "";
    var everyTerm = terms.every(function (term) {
      return answerClauses.some(function (clause) {
        return occurrences(term, clause).length;
      });
    });
    return everyTerm ? "split" : "";
  }

  /* One marking point: {state, why, source}. state: "made", "contradicted", "rejected",
   * "negated", "undecided" or "missing". */
  function judgePoint(point, answerClauses) {
    var states = (point.accept || []).map(function (w) {
      return wordingState(w, answerClauses);
    });
    var said = states.indexOf("said") >= 0 || states.indexOf("both") >= 0,
      negated = states.indexOf("negated") >= 0 || states.indexOf("both") >= 0;
    var rejects = (point.reject || []).filter(function (r) {
      var state = wordingState(r.wording, answerClauses);
      return state === "said" || state === "both";
    });
    var contradiction = rejects.filter(function (r) {
      return r.contradicts;
    })[0];
    if (contradiction) return { state: "contradicted", why: contradiction.why, source: contradiction.source };
    if (said && negated) return { state: "contradicted", why: "the answer says it and also says it is not so" };
    if (said) return { state: "made" };
    if (rejects.length) return { state: "rejected", why: rejects[0].why, source: rejects[0].source };
    if (negated) return { state: "negated", why: "the answer says it is not so" };
    if (states.indexOf("split") >= 0) return { state: "undecided" };
    return { state: "missing" };
  }

  /* The student's ticks, the indices of the part's points: the page's ticks hold the lines'
   * indices in the question's marks (answer.lines lists the part's lines in order). */
  function tickedPoints(answer) {
    var ticked = (answer && answer.ticked) || [],
      lines = answer && answer.lines;
    return lines ? ticked.map((line) => lines.indexOf(line)) : ticked;
  }

  /* Mark a text part's answer: each point judged, then the marks: a point counts when made, or
   * when the marker could not decide and the student ticked it; an A1 (or any point with
   * `needs`) counts only with the point it needs. ticked: indices of the part's points. */
  function markText(part, answer) {
    var text = String((answer && answer.text) || "");
    if (!text.trim()) return { code: "no-answer", message: "Write your answer first." };
    var answerClauses = clauses(tokenise(text)),
      ticked = tickedPoints(answer);
    var points = (part.points || []).map(function (point) {
      return judgePoint(point, answerClauses);
    });
    var counts = points.map(function (p, i) {
      return p.state === "made" || (p.state === "undecided" && ticked.indexOf(i) >= 0);
    });
    var earned = counts.map(function (c, i) {
      var needs = part.points[i].needs;
      return c && (needs === undefined || needs === null || counts[needs]);
    });
    var selfMarked = points.some(function (p, i) {
      return p.state === "undecided" && ticked.indexOf(i) >= 0;
    });
    // the part's lines in the question's marks (the page's ticks say them; alone, its points')
    var lines = (answer && answer.lines) || part.points.map((p, i) => i);
    return {
      code: selfMarked ? "self-marked" : "text-marked",
      message: feedback(part, points, earned),
      points: points,
      earned: earned,
      undecided: points
        .map(function (p, i) {
          return p.state === "undecided" ? i : -1;
        })
        .filter(function (i) {
          return i >= 0;
        }),
      selfMarked: selfMarked,
      // the lines earned, as the engine counts a kind's ticked lines (marking.js, award)
      ticked: lines.filter(function (line, i) {
        return earned[i];
      }),
    };
  }

  /* "Made: … (B1). Missing: … (B1). Not credited: … ." One sentence a point, in order. */
  function feedback(part, points, earned) {
    return points
      .map(function (p, i) {
        var point = part.points[i],
          name = point.text + " (" + point.code + ")";
        if (p.state === "made" && earned[i]) return "Made: " + name + ".";
        if (p.state === "made") return "Made, but it needs the point before it: " + name + ".";
        if (p.state === "undecided")
          return (
            "Cannot tell whether your answer makes this point (its words are there, but apart): " +
            name +
            ". Tick it if it does."
          );
        if (p.state === "missing") return "Missing: " + name + ".";
        return "Not credited: " + name + ": " + p.why + (p.source ? " (" + p.source + ")" : "") + ".";
      })
      .join(" ");
  }

  /* A text part's points after Check: each says what the marker found (data-state, shown by
   * questions.css); only a point it could not decide can be ticked, and only by the student. */
  function show(box, result) {
    var points = box.querySelector(".q-points");
    if (!points || !result.points) return;
    points.hidden = false;
    Array.prototype.forEach.call(box.querySelectorAll(".q-tick"), function (t, i) {
      var state = result.points[i].state;
      t.disabled = state !== "undecided";
      if (t.disabled) t.checked = false;
      t.parentNode.setAttribute("data-state", state);
    });
  }

  /* The part's fieldset: its one textarea, and after Check its points' ticks, each the index of
   * its line in the question's marks (form: TextPart.form_html). */
  function read(box) {
    var ticks = box.querySelectorAll(".q-tick");
    function lines(only) {
      return Array.prototype.filter.call(ticks, only).map(function (t) {
        return Number(t.value);
      });
    }
    return {
      text: box.querySelector(".q-explain").value,
      ticked: lines(function (t) {
        return t.checked;
      }),
      lines: lines(function () {
        return true;
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
    var lines = [];
    data.marks.forEach(function (m, i) {
      if (m.part === part.id) lines.push(i);
    });
    Array.prototype.forEach.call(box.querySelectorAll(".q-tick"), function (tick, i) {
      tick.value = String(lines[i]);
      tick.parentNode.querySelector(".q-point-text").textContent = part.points[i].text;
    });
    box.querySelector(".q-points .q-model-text").innerHTML = part.model;
  }

  var kind = {
    kinds: ["text"],
    mark: markText,
    read: read,
    fill: fill,
    answered: function (answer) {
      return !!String(answer.text || "").trim();
    },
    relabel: relabel,
    // its lines count when ticked: by the marker, or by the student where it could not decide
    selfMarked: true,
    show: show,
    tokenise: tokenise,
    editDistance: editDistance,
    judgePoint: judgePoint,
    clauses: clauses,
  };
  if (typeof module === "object" && module.exports) module.exports = kind;
  else
    kind.kinds.forEach(function (name) {
      root.QuestionKinds.register(name, kind);
    });
})(this);
