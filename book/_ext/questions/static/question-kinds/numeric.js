/* The numeric part kind (a calculated value, or a reading from a graph): numbers as students
 * write them, significant figures, units, direction, named mistakes, alternatives. Marks one
 * part's answer to an outcome (code, message); what an outcome earns is the rule table's
 * (physics_figures/marking_rules.json), applied by marking.js. Its Python twins are Part and
 * GraphPart (physics_figures/parts/numeric.py and graph.py). */
(function (root) {
  "use strict";

  // Reading what the student typed (static/answer-reading.js): loaded before this script in a page.
  var Reading = root.AnswerReading || require("../answer-reading.js");
  var Notation = root.Notation || require("../../../notation/static/notation.js");
  var normalise = Reading.normalise,
    parseNumber = Reading.parseNumber,
    parseUnit = Reading.parseUnit,
    quantityOf = Reading.quantityOf,
    sameDims = Reading.sameDims,
    typedAnswer = Reading.typedAnswer,
    unitMeant = Reading.unitMeant,
    superscript = Reading.superscript;
  // The s.f. judge (static/sig-figs.js): loaded before this script in a page.
  var SigFigs = root.SigFigs || require("../sig-figs.js");
  var compare = SigFigs.compare,
    fewSfMessage = SigFigs.fewSfMessage,
    countedZeros = SigFigs.countedZeros;

  // ---------------------------------------------------------------- marking

  function outcome(code, message, extra) {
    var result = { code: code, correct: code === "correct", message: message };
    if (extra)
      Object.keys(extra).forEach(function (k) {
        result[k] = extra[k];
      });
    return result;
  }

  // A ratio or a fraction has no unit (part.unit ""): a bare number is whole, and "25 %" reads as 0.25.
  function expectedUnit(part) {
    return !normalise(part.unit) ? { scale: 1, dims: [0, 0, 0, 0] } : parseUnit(part.unit).readings[0];
  }

  /* A unit in the wrong case: say so, and mark the answer as if it were written right. */
  function markRecased(part, typed, unit, recased, figures) {
    var asMeant = mark(
      part,
      { value: typed.valueText, unit: recased, direction: typed.direction, recased: true },
      figures,
    );
    var notA = unit.ok ? "a unit of " + part.quantity : "a unit";
    var caseNote = `Units are case-sensitive: ${superscript(normalise(typed.unitText))} is not ${notA}. You probably meant ${superscript(recased)}.`;
    if (asMeant.code === "correct") {
      return outcome("unit-case", caseNote + " With that unit the answer is right.", {
        si: asMeant.si,
        valueRight: true,
        meant: recased,
      });
    }
    asMeant.message = caseNote + " " + asMeant.message;
    asMeant.meant = recased;
    return asMeant;
  }

  /* The typed value against value (SI) in a unit of the given scale. */
  function against(c, value, scale) {
    if (c.part.tolerance) {
      // read from a graph: right within half a small square either way
      var near = Math.abs(c.size - value / scale) <= (c.part.tolerance / scale) * (1 + 1e-9);
      return { match: near, matchFewSf: false };
    }
    var n = { value: c.size, sfMin: c.number.sfMin, sfMax: c.number.sfMax, lead: c.number.lead };
    return compare(n, value / scale, c.minSf, c.checkSf, c.figures.fewest);
  }

  /* Worked from readings of the graph: right where some answer that readings within half a
   * small square give (part.band, SI) rounds to what was typed, at each reading of its
   * significant figures (Part.band_takes in physics_figures/parts/numeric.py). */
  function withinBand(c, scale) {
    var found = { match: false, matchFewSf: false };
    if (!c.part.band || c.typed === 0) return found;
    var low = c.part.band[0] / scale,
      high = c.part.band[1] / scale,
      slack = 1e-9 * Math.max(Math.abs(low), Math.abs(high));
    for (var sf = c.number.sfMax; sf >= c.number.sfMin; sf--) {
      var half = 5 * Math.pow(10, Math.floor(Math.log10(Math.abs(c.size)) + 1e-12) - sf);
      if (c.size - half <= high + slack && c.size + half >= low - slack) {
        if (sf >= c.minSf) found.match = true;
        else found.matchFewSf = true;
      }
    }
    if (found.match) found.matchFewSf = false;
    return found;
  }

  // A value of the part (the key, an alternative, a mistake) at the size the mode compares.
  function sized(c, value) {
    return c.mode === "signed" ? value : Math.abs(value);
  }

  /* What the marker knows of one answer before it picks an outcome: the part, the number and
   * unit read, and the reading of the unit (the one with the right dimensions and the right
   * value, if any). */
  function answerFacts(part, typed, number, unit, figures) {
    var mode = part.direction || "none";
    var c = {
      part: part,
      figures: figures,
      number: number,
      unit: unit,
      unitText: typed.unitText,
      direction: typed.direction,
      mode: mode,
      minSf: part.minSf, // from the rule table, with the part's data
      checkSf: part.checkSf,
      dimensionless: !normalise(part.unit),
      expected: expectedUnit(part),
      quantity: part.quantity,
      units: superscript(part.units || part.unit),
      typed: number.value,
      size: mode === "signed" ? number.value : Math.abs(number.value),
      target: mode === "signed" ? part.value : Math.abs(part.value),
    };
    var readings = unit.empty ? [c.expected] : unit.readings;
    var fitting = readings.filter((r) => sameDims(r.dims, c.expected.dims));
    var right = fitting.filter((r) => against(c, c.target, r.scale).match || withinBand(c, r.scale).match);
    c.reading = right[0] || fitting[0] || readings[0];
    c.unitFits = sameDims(c.reading.dims, c.expected.dims);
    // Every outcome carries the answer in SI (for error carried forward) when its unit fits.
    c.si = c.unitFits ? c.size * c.reading.scale : null;
    c.alternative = null;
    c.fromReadings = false;
    if (c.unitFits) matchFacts(c);
    return c;
  }

  /* A size typed with a minus sign: ignored where the direction is asked separately (the
   * schemes' "ignore sign") or where the part's scheme allows it (allowMinus, its paper),
   * right where the part says what the sign means, else a slip. And the direction chosen. */
  function signFacts(c) {
    c.signed = c.mode !== "signed" && c.typed < 0;
    c.signIgnored = c.signed && (c.mode === "choice" || !!c.part.allowMinus);
    c.sign = c.signed && !c.part.signMeans && !c.signIgnored;
    c.directionRight = c.mode !== "choice" || c.direction === c.part.answerDirection;
  }

  /* How the value matches, in a unit that fits: the key, an alternative, readings of the graph;
   * the sign and the direction. */
  function matchFacts(c) {
    signFacts(c);
    c.result = against(c, c.target, c.reading.scale);
    // A value the scheme also accepts (another route, or its own rounded working).
    var byAlt = (alt) => against(c, sized(c, alt.value), c.reading.scale);
    c.alternative = (!c.result.match && (c.part.alternatives || []).find((alt) => byAlt(alt).match)) || null;
    if (c.alternative) c.result = byAlt(c.alternative);
    // An answer worked from readings of the graph, each within half a small square.
    if (!c.result.match) {
      var byBand = withinBand(c, c.reading.scale);
      c.fromReadings = byBand.match;
      if (byBand.match || byBand.matchFewSf) c.result = byBand;
    }
    // what a value matched at the key's size stands for: the key, or the alternative it matched;
    // for readings, a reading of its own, not the drawn line's exact value
    c.keySize = c.fromReadings ? undefined : c.alternative ? sized(c, c.alternative.value) : c.target;
  }

  /* An outcome with the answer in SI, and exact: the value it stands for, unrounded, where it
   * matched one (the key, an alternative, a named mistake, a slip). A later part may be worked
   * from all its figures, not the 2 or 3 typed (markQuestion's error carried forward tries both). */
  function out(c, code, message, extra, exact) {
    var result = outcome(code, message, extra);
    result.si = c.si;
    if (c.si !== null && typeof exact === "number") result.exact = exact;
    result.valueRight =
      !!c.alternative ||
      !!c.fromReadings ||
      against(c, c.target, c.reading.scale).match ||
      against(c, c.target, 1).match;
    return result;
  }

  /* The part's named mistake the answer shows, or null. keyValue: the value typed is the key's
   * (at its own figures): then no mistake of the value alone is what it shows (a g = 10 value
   * that rounds to the key, say), only one of its direction or its unit, so a wrong direction
   * is never read as a slip. */
  function namedMistake(c, keyValue) {
    var mistakes = c.part.mistakes || [];
    for (var i = 0; i < mistakes.length; i++) {
      var mistake = mistakes[i];
      var mistakeDims = mistake.unit ? parseUnit(mistake.unit).readings[0].dims : c.expected.dims;
      if (!sameDims(mistakeDims, c.reading.dims)) continue;
      if (mistake.direction && mistake.direction !== c.direction) continue;
      if (keyValue && !mistake.direction && !mistake.unit) continue;
      var value = sized(c, mistake.value);
      if ((c.number.sfMax >= c.figures.min || value === 0) && against(c, value, c.reading.scale).match) return mistake;
    }
    return null;
  }

  function mistakeOutcome(c, mistake) {
    var meant = mistake.unit ? undefined : sized(c, mistake.value);
    return out(
      c,
      "mistake",
      mistake.feedback,
      { mistake: mistake.name, loses: mistake.loses, see: mistake.see },
      meant,
    );
  }

  function wrongUnitOutcome(c) {
    var numberRight = against(c, c.target, 1).match;
    var other = quantityOf(c.reading.dims);
    var whose = other && other !== c.quantity ? `a unit of ${other}, not of` : "not a unit of";
    var says = `${superscript(normalise(c.unitText))} is ${whose} ${c.quantity}. Give ${c.quantity} in ${c.units}.`;
    return out(c, numberRight ? "wrong-unit" : "wrong", (numberRight ? "The number is right, but " : "") + says);
  }

  // The value right, with no slip of sign or direction.
  function allRight(c) {
    return c.result.match && !c.sign && c.directionRight;
  }

  // A unit with a prefix or another scale (km, g, rad) under which the number is the key's.
  function rightInTheKeyUnit(c) {
    return !c.unit.empty && c.reading.scale !== 1 && against(c, c.target, 1).match;
  }

  // The key to too few figures, as it may be read (60 for 64); written with zeros after it
  // (60. or 6.0e1), only where no slip below is what it is.
  function tooFewSf(c) {
    var few = Math.min(c.number.sfMax, c.result.fewSf || c.minSf - 1);
    return out(c, "too-few-sf", fewSfMessage(c.figures, few, c.minSf, c.checkSf, c.number.sfMax > few));
  }

  function keySize(c) {
    return c.keySize;
  }

  // The size right and the sign wrong, on a signed part.
  function signWrong(c) {
    var flipped = { value: -c.typed, sfMin: c.number.sfMin, sfMax: c.number.sfMax, lead: c.number.lead };
    return (
      c.mode === "signed" &&
      c.target !== 0 &&
      compare(flipped, c.target / c.reading.scale, c.minSf, c.checkSf, c.figures.fewest).match
    );
  }

  // The value that rounding an intermediate part-way gives (a slip computed from the working).
  function roundedPartWay(c) {
    var slips = c.part.roundedPartWay || [];
    return c.number.sfMax >= c.figures.min && slips.filter((slip) => against(c, slip.value, c.reading.scale).match)[0];
  }

  var ANGLE = [0, 0, 0, 1];

  /* The outcomes of an answer, in the order they are tried: the first case whose test (when)
   * finds something gives its outcome: code, what it says and the value it stands for (exact),
   * each given what the test found; or a whole outcome of its own. The last always applies. */
  var CASES = [
    { when: (c) => !c.unitFits && namedMistake(c), outcome: mistakeOutcome }, // a unit of a named mistake
    { when: (c) => !c.unitFits, outcome: wrongUnitOutcome },
    {
      when: (c) => allRight(c) && c.unit.empty && !c.dimensionless,
      code: "missing-unit",
      says: (c) => "The number is right. Now give the unit: " + c.units + ".",
      exact: keySize,
    },
    {
      when: (c) => allRight(c) && c.alternative,
      code: "alternative",
      says: (c) => "Accepted: " + c.alternative.why + ".",
      exact: keySize,
    },
    {
      when: (c) => allRight(c) && c.fromReadings,
      code: "correct",
      says: () => "Correct: readings of the graph within half a small square give this.",
    },
    {
      when: (c) => allRight(c) && c.signIgnored,
      code: "ignore-sign",
      says: (c) =>
        c.mode === "choice"
          ? "Correct: the minus sign is ignored, as the direction is given separately."
          : "Correct: the scheme allows the minus sign here (" + c.part.allowMinus + ").",
      exact: keySize,
    },
    {
      when: allRight,
      code: "correct",
      says: (c) => (c.signed ? "Correct: the minus sign says " + c.part.signMeans + "." : "Correct."),
      exact: keySize,
    },
    {
      when: (c) => c.result.match && !c.sign && c.mode === "choice" && !c.direction,
      code: "missing-direction",
      says: () => "The size is right. Now give the direction.",
      exact: keySize,
    },
    { when: (c) => namedMistake(c, c.result.match), outcome: mistakeOutcome },
    {
      when: (c) => rightInTheKeyUnit(c) && sameDims(c.expected.dims, ANGLE),
      code: "angle-unit",
      says: (c) =>
        `That number is right in degrees, but ${superscript(normalise(c.unitText))} is not degrees: 1 rad = 57.3°. Give the angle in ° (degrees).`,
    },
    { when: rightInTheKeyUnit, code: "prefix", says: prefixMessage },
    {
      when: (c) => c.sign && c.result.match,
      code: "sign-on-size",
      says: (c) => "The size is right, but a " + c.quantity + " here is a size with no sign: leave out the minus sign.",
    },
    {
      when: signWrong,
      code: "sign",
      says: (c) =>
        `The size is right but the sign is wrong. Positive is ${c.part.positive}, and this points ` +
        (c.target < 0 ? "the other way, so it is negative." : "that way, so it is positive."),
      exact: (c) => -c.target,
    },
    {
      when: (c) => c.result.match && !c.directionRight,
      code: "direction",
      says: (c) =>
        "The size is right but the direction is wrong." + (c.part.directionHint ? " " + c.part.directionHint : ""),
      exact: keySize,
    },
    { when: (c) => c.result.matchFewSf && c.number.sfMin < c.minSf, outcome: tooFewSf },
    {
      when: (c) =>
        c.number.sfMax >= c.figures.min &&
        typeof c.part.gNineEight === "number" &&
        against(c, c.part.gNineEight, c.reading.scale).match,
      code: "g-9.8",
      says: () =>
        "That is the answer with g = 9.8 m s⁻². The data give g = 9.81 m s⁻²: use it, " +
        "and keep every figure until the end.",
      exact: (c) => c.part.gNineEight,
    },
    {
      when: roundedPartWay,
      code: "rounded-part-way",
      says: (c, slip) =>
        `Close, but that is what rounding ${slip.rounded} part-way through gives. Keep the full calculator value until the end, then round only the answer.`,
      exact: (c, slip) => slip.value,
    },
    { when: (c) => c.result.matchFewSf, outcome: tooFewSf },
    {
      when: () => true,
      code: "wrong",
      says: (c) => "Not right. " + (c.part.revisit || "Check your method and your arithmetic."),
    },
  ];

  function prefixMessage(c) {
    var typed = Notation.formatNumber(c.typed, c.number.sfMax),
      scale = Notation.formatNumber(c.reading.scale, 1),
      unit = superscript(c.part.unit);
    return `Check the prefix: ${typed} ${unit} would be right, but 1 ${superscript(normalise(c.unitText))} = ${scale} ${unit}. Convert g to kg, ms to s, cm to m.`;
  }

  // The outcome of the first case that applies.
  function firstCase(c) {
    for (var i = 0; i < CASES.length; i++) {
      var rule = CASES[i],
        found = rule.when(c);
      if (found && rule.outcome) return rule.outcome(c, found);
      if (found) return out(c, rule.code, rule.says(c, found), null, rule.exact && rule.exact(c, found));
    }
  }

  /* Mark one answer to one part of a question.
   * part: {value (SI, signed when direction is "signed"), unit, units, quantity,
   *        minSf, checkSf, direction: "none" | "signed" | "choice", positive,
   *        choices, answerDirection, mistakes: [{value, unit, direction, feedback}], revisit}
   * answer: {value: text, unit: text, direction: text} */
  function mark(part, answer, figures) {
    var typed = typedAnswer(answer);
    var number = parseNumber(typed.valueText);
    if (!number.ok) return outcome("unreadable-number", number.message);
    number = countedZeros(number, figures);
    var unit = parseUnit(typed.unitText);
    var recased = !answer.recased && unitMeant(typed.unitText, unit, expectedUnit(part), part.unit);
    if (recased) return markRecased(part, typed, unit, recased, figures);
    if (!unit.ok) return outcome("unreadable-unit", unit.message);
    return firstCase(answerFacts(part, typed, number, unit, figures));
  }

  /* The part's fieldset: boxes .q-value and .q-unit, and a .q-direction select for a direction
   * to choose (form: Part.form_html). */
  function read(box) {
    var direction = box.querySelector(".q-direction");
    return {
      value: box.querySelector(".q-value").value,
      unit: box.querySelector(".q-unit").value,
      direction: direction ? direction.value : "",
    };
  }

  function fill(box, part, answer) {
    box.querySelector(".q-value").value = answer.value || "";
    box.querySelector(".q-unit").value = answer.unit || "";
    var direction = box.querySelector(".q-direction");
    if (direction) direction.value = answer.direction || "";
  }

  /* A signed part's note names the positive direction with the variant's own numbers ("the
   * 0.80 kg ball"): its .q-positive span takes the variant's words. */
  function relabel(box, part) {
    var positive = box.querySelector(".q-note .q-positive");
    if (positive && part.direction === "signed") positive.textContent = Notation.joinUnits(part.positive);
  }

  var numeric = {
    kinds: ["numeric"],
    mark: mark,
    outcome: outcome,
    read: read,
    fill: fill,
    answered: function (answer) {
      return !!((answer.value || "").trim() || (answer.unit || "").trim());
    },
    relabel: relabel,
    helpSteps: true,
    mockPaper: "2",
  };
  // a value read off the question's graph: marked as a value, within the part's tolerance
  var graph = Object.assign({}, numeric, { kinds: ["graph"], readsGraph: true });
  var kinds = [numeric, graph];
  if (typeof module === "object" && module.exports) module.exports = kinds;
  else
    kinds.forEach(function (kind) {
      kind.kinds.forEach(function (name) {
        root.QuestionKinds.register(name, kind);
      });
    });
})(this);
