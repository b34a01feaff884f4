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
    recasedUnit = Reading.recasedUnit,
    splitValueAndUnit = Reading.splitValueAndUnit,
    superscript = Reading.superscript;

  // ---------------------------------------------------------------- marking

  // Whole numbers of steps of 10^place nearest x; both neighbours on a tie.
  function steps(x, place) {
    var q = x / Math.pow(10, place),
      n = Math.floor(q),
      f = q - n;
    if (Math.abs(f - 0.5) < 1e-7) return [n, n + 1];
    return [f < 0.5 ? n : n + 1];
  }

  function stepsApart(typed, target, place) {
    var best = Infinity;
    steps(typed, place).forEach(function (a) {
      steps(target, place).forEach(function (b) {
        best = Math.min(best, Math.abs(a - b));
      });
    });
    return best;
  }

  /* Is value the target rounded to sf significant figures (60 for 56.0 at 1 s.f.; not 10 for 7.5)? */
  function roundsTo(value, target, sf) {
    var place = Math.floor(Math.log10(Math.abs(target)) + 1e-12) - sf + 1,
      scaled = value / Math.pow(10, place);
    return (
      steps(Math.abs(target), place).some(function (n) {
        return Math.abs(Math.abs(scaled) - n) < 1e-7 * Math.max(1, n);
      }) && value < 0 === target < 0
    );
  }

  /* Compare a typed number with a target (in the same unit) at every reading
   * of its significant figures. The comparison is at the student's last digit,
   * but never finer than checkSf figures of the target: the key is only
   * trusted that far, so rounding intermediate values to 3 s.f. still passes.
   * match: right to minSf or more. matchFewSf: the key rounded to fewer figures, from the
   * rule table's fewest (60 for 56.0: right to 1 s.f.). Its Python twin is the one s.f. judge,
   * physics_figures.marking.judge_sig_figs (tests/fixtures/sig_fig_cases.json runs through both). */
  function compare(number, target, minSf, checkSf, fewest) {
    var result = { match: false, matchFewSf: false };
    if (target === 0) {
      result.match = number.value === 0;
      return result;
    } // zero has no significant figures
    var targetLead = Math.floor(Math.log10(Math.abs(target)) + 1e-12),
      checkPlace = targetLead - checkSf + 1;
    // Right: equal at the typed last figure, where that figure is no coarser than the target's
    // minSf-th ("1.0" is 0.97 to 1 s.f., not 2), or the target rounded to minSf or more figures
    // where rounding carries into a new digit ("1.0" for 0.997 to 2 s.f.).
    for (var sf = number.sfMax; sf >= number.sfMin; sf--) {
      var place = Math.max(number.lead - sf + 1, checkPlace);
      if (sf >= minSf && place <= targetLead - minSf + 1 && stepsApart(number.value, target, place) === 0) {
        result.match = true;
      }
    }
    var carried = Math.abs(number.value) >= Math.pow(10, targetLead + 1);
    for (var more = minSf; more <= checkSf && carried && !result.match; more++) {
      result.match = number.sfMin <= more && more <= number.sfMax && roundsTo(number.value, target, more);
    }
    // The key rounded to fewer figures than the A1 needs, however many zeros follow it (60,
    // 60. and 6.0e1 for 64 are each 64 to 1 s.f.): too few figures, not wrong physics.
    // fewSf: the most figures it is the key to.
    for (var few = fewest; few < minSf && !result.match; few++) {
      if (roundsTo(number.value, target, few)) {
        result.matchFewSf = true;
        result.fewSf = few;
      }
    }
    return result;
  }

  /* What a key given to too few figures reads (the rule table's texts, marking_rules.json
   * "sig_figs"; physics_figures.marking.too_few_sf_feedback fills them the same way): padded,
   * when it is written with more figures than it has (60. for 64 to 1 s.f.). */
  function fewSfMessage(figures, few, minSf, checkSf, padded) {
    return figures[padded ? "feedback_padded" : "feedback"]
      .replace(/\{few\}/g, String(few))
      .replace(/\{min\}/g, String(minSf))
      .replace(/\{work\}/g, String(Math.max(checkSf, minSf + 1)));
  }

  /* A whole number's trailing zeros as the rule table counts them ("whole_number_zeros"):
   * "ambiguous" (4500 has 2 to 4 figures, as the reader gives them) or "significant" (4). */
  function countedZeros(number, figures) {
    if (figures.whole_number_zeros === "significant") return Object.assign({}, number, { sfMin: number.sfMax });
    if (figures.whole_number_zeros !== "ambiguous") {
      throw new Error(
        "whole_number_zeros must be 'ambiguous' or 'significant' (got " + figures.whole_number_zeros + ")",
      );
    }
    return number;
  }

  function outcome(code, message, extra) {
    var result = { code: code, correct: code === "correct", message: message };
    if (extra)
      Object.keys(extra).forEach(function (k) {
        result[k] = extra[k];
      });
    return result;
  }

  /* Mark one answer to one part of a question.
   * part: {value (SI, signed when direction is "signed"), unit, units, quantity,
   *        minSf, checkSf, direction: "none" | "signed" | "choice", positive,
   *        choices, answerDirection, mistakes: [{value, unit, direction, feedback}], revisit}
   * answer: {value: text, unit: text, direction: text} */
  function mark(part, answer, figures) {
    var valueText = answer.value || "",
      unitText = answer.unit || "",
      direction = answer.direction || "";
    if (!normalise(unitText) && /[A-Za-zµμ°%]/.test(normalise(valueText).replace(/[eExX×]/g, ""))) {
      var split = splitValueAndUnit(valueText);
      valueText = split[0];
      unitText = split[1];
    }
    var number = parseNumber(valueText);
    if (!number.ok) return outcome("unreadable-number", number.message);
    number = countedZeros(number, figures);
    var unit = parseUnit(unitText);
    // A ratio or a fraction has no unit (part.unit ""): a bare number is whole, and "25 %" reads as 0.25.
    var dimensionless = !normalise(part.unit);
    var expected = dimensionless ? { scale: 1, dims: [0, 0, 0, 0] } : parseUnit(part.unit).readings[0];
    // A unit in the wrong case: say so, and mark the answer as if it were written right.
    var fits =
      unit.ok &&
      unit.readings.some(function (r) {
        return sameDims(r.dims, expected.dims);
      });
    var recased = !fits && !answer.recased && recasedUnit(unitText, expected.dims, expected.scale);
    if (recased) {
      if (recased.replace(/\s+/g, "") === normalise(part.unit).replace(/\s+/g, "")) recased = normalise(part.unit);
      var asMeant = mark(part, { value: valueText, unit: recased, direction: direction, recased: true }, figures);
      var caseNote =
        "Units are case-sensitive: " +
        superscript(normalise(unitText)) +
        " is not " +
        (unit.ok ? "a unit of " + part.quantity : "a unit") +
        ". You probably meant " +
        superscript(recased) +
        ".";
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
    if (!unit.ok) return outcome("unreadable-unit", unit.message);

    var minSf = part.minSf,
      checkSf = part.checkSf; // from the rule table, with the part's data
    var mode = part.direction || "none";
    var quantity = part.quantity,
      units = superscript(part.units || part.unit);
    var typed = number.value;
    var size = mode === "signed" ? typed : Math.abs(typed);
    var target = mode === "signed" ? part.value : Math.abs(part.value);

    // The reading of the unit: the one with the right dimensions and the right value, if any.
    var readings = unit.empty ? [expected] : unit.readings;
    var fitting = readings.filter(function (r) {
      return sameDims(r.dims, expected.dims);
    });
    function against(value, scale) {
      if (part.tolerance) {
        // read from a graph: right within half a small square either way
        var near = Math.abs(size - value / scale) <= (part.tolerance / scale) * (1 + 1e-9);
        return { match: near, matchFewSf: false };
      }
      var n = { value: size, sfMin: number.sfMin, sfMax: number.sfMax, lead: number.lead };
      return compare(n, value / scale, minSf, checkSf, figures.fewest);
    }
    /* Worked from readings of the graph: right where some answer that readings within half a
     * small square give (part.band, SI) rounds to what was typed, at each reading of its
     * significant figures (Part.band_takes in physics_figures/parts/numeric.py). */
    function withinBand(scale) {
      var found = { match: false, matchFewSf: false };
      if (!part.band || typed === 0) return found;
      var low = part.band[0] / scale,
        high = part.band[1] / scale,
        slack = 1e-9 * Math.max(Math.abs(low), Math.abs(high));
      for (var sf = number.sfMax; sf >= number.sfMin; sf--) {
        var half = 5 * Math.pow(10, Math.floor(Math.log10(Math.abs(size)) + 1e-12) - sf);
        if (size - half <= high + slack && size + half >= low - slack) {
          if (sf >= minSf) found.match = true;
          else found.matchFewSf = true;
        }
      }
      if (found.match) found.matchFewSf = false;
      return found;
    }
    var reading =
      fitting.filter(function (r) {
        return against(target, r.scale).match || withinBand(r.scale).match;
      })[0] ||
      fitting[0] ||
      readings[0];
    // Every outcome carries the answer in SI (for error carried forward) when its unit fits.
    var si = sameDims(reading.dims, expected.dims) ? size * reading.scale : null;
    /* The value the typed answer stands for, unrounded (SI), where it matched one: the key, an
     * alternative, a named mistake, the g = 9.8 slip, rounding part-way. A later part worked from
     * the student's earlier answer may be worked from all its figures, not the 2 or 3 typed
     * (markQuestion's error carried forward tries both). */
    function out(code, message, extra, exact) {
      var result = outcome(code, message, extra);
      result.si = si;
      if (si !== null && typeof exact === "number") result.exact = exact;
      result.valueRight =
        !!alternative || !!fromReadings || against(target, reading.scale).match || against(target, 1).match;
      return result;
    }

    /* keyValue: the value typed is the key's (at its own figures): then no mistake of the value
     * alone is what it shows (a g = 10 value that rounds to the key, say), only one of its
     * direction or its unit, so a wrong direction is never read as a slip. */
    function namedMistake(dims, scale, keyValue) {
      var mistakes = part.mistakes || [];
      for (var i = 0; i < mistakes.length; i++) {
        var mistake = mistakes[i];
        var mistakeDims = mistake.unit ? parseUnit(mistake.unit).readings[0].dims : expected.dims;
        if (!sameDims(mistakeDims, dims)) continue;
        if (mistake.direction && mistake.direction !== direction) continue;
        if (keyValue && !mistake.direction && !mistake.unit) continue;
        var value = mode === "signed" ? mistake.value : Math.abs(mistake.value);
        if ((number.sfMax >= figures.min || value === 0) && against(value, scale).match) {
          var meant = mistake.unit ? undefined : value;
          return out(
            "mistake",
            mistake.feedback,
            { mistake: mistake.name, loses: mistake.loses, see: mistake.see },
            meant,
          );
        }
      }
      return null;
    }

    if (!sameDims(reading.dims, expected.dims)) {
      var found = namedMistake(reading.dims, reading.scale);
      if (found) return found;
      var other = quantityOf(reading.dims);
      return out(
        against(target, 1).match ? "wrong-unit" : "wrong",
        (against(target, 1).match ? "The number is right, but " : "") +
          superscript(normalise(unitText)) +
          (other && other !== quantity
            ? " is a unit of " + other + ", not of " + quantity + "."
            : " is not a unit of " + quantity + ".") +
          " Give " +
          quantity +
          " in " +
          units +
          ".",
      );
    }

    // A size typed with a minus sign: ignored where the direction is asked separately (the
    // schemes' "ignore sign") or where the part's scheme allows it (allowMinus, its paper),
    // right where the part says what the sign means, else a slip.
    var signed = mode !== "signed" && typed < 0;
    var signIgnored = signed && (mode === "choice" || !!part.allowMinus);
    var sign = signed && !part.signMeans && !signIgnored;
    var result = against(target, reading.scale);
    // A value the scheme also accepts (another route, or its own rounded working).
    var alternative = null;
    if (!result.match) {
      (part.alternatives || []).some(function (alt) {
        var byAlt = against(mode === "signed" ? alt.value : Math.abs(alt.value), reading.scale);
        if (byAlt.match) {
          result = byAlt;
          alternative = alt;
        }
        return byAlt.match;
      });
    }
    // An answer worked from readings of the graph, each within half a small square.
    var fromReadings = false;
    if (!result.match) {
      var byBand = withinBand(reading.scale);
      fromReadings = byBand.match;
      if (byBand.match || byBand.matchFewSf) result = byBand;
    }
    var directionRight = mode !== "choice" || direction === part.answerDirection;
    // what a value matched at the key's size stands for: the key, or the alternative it matched
    var keySize = alternative ? (mode === "signed" ? alternative.value : Math.abs(alternative.value)) : target;
    if (fromReadings) keySize = undefined; // a reading of its own, not the drawn line's exact value

    if (result.match && !sign && directionRight) {
      if (unit.empty && !dimensionless)
        return out("missing-unit", "The number is right. Now give the unit: " + units + ".", null, keySize);
      if (alternative) return out("alternative", "Accepted: " + alternative.why + ".", null, keySize);
      if (fromReadings) return out("correct", "Correct: readings of the graph within half a small square give this.");
      if (signIgnored)
        return out(
          "ignore-sign",
          mode === "choice"
            ? "Correct: the minus sign is ignored, as the direction is given separately."
            : "Correct: the scheme allows the minus sign here (" + part.allowMinus + ").",
          null,
          keySize,
        );
      return out(
        "correct",
        signed ? "Correct: the minus sign says " + part.signMeans + "." : "Correct.",
        null,
        keySize,
      );
    }
    if (result.match && !sign && mode === "choice" && !direction) {
      return out("missing-direction", "The size is right. Now give the direction.", null, keySize);
    }

    var named = namedMistake(reading.dims, reading.scale, result.match);
    if (named) return named;

    if (!unit.empty && reading.scale !== 1 && against(target, 1).match && sameDims(expected.dims, [0, 0, 0, 1])) {
      return out(
        "angle-unit",
        "That number is right in degrees, but " +
          superscript(normalise(unitText)) +
          " is not degrees: 1 rad = 57.3°. Give the angle in ° (degrees).",
      );
    }
    if (!unit.empty && reading.scale !== 1 && against(target, 1).match) {
      return out(
        "prefix",
        "Check the prefix: " +
          Notation.formatNumber(typed, number.sfMax) +
          " " +
          superscript(part.unit) +
          " would be right, but 1 " +
          superscript(normalise(unitText)) +
          " = " +
          Notation.formatNumber(reading.scale, 1) +
          " " +
          superscript(part.unit) +
          ". Convert g to kg, ms to s, cm to m.",
      );
    }

    if (sign && result.match) {
      return out(
        "sign-on-size",
        "The size is right, but a " + quantity + " here is a size with no sign: leave out the minus sign.",
      );
    }
    if (
      mode === "signed" &&
      target !== 0 &&
      compare(
        { value: -typed, sfMin: number.sfMin, sfMax: number.sfMax, lead: number.lead },
        target / reading.scale,
        minSf,
        checkSf,
        figures.fewest,
      ).match
    ) {
      return out(
        "sign",
        "The size is right but the sign is wrong. Positive is " +
          part.positive +
          (target < 0
            ? ", and this points the other way, so it is negative."
            : ", and this points that way, so it is positive."),
        null,
        -target,
      );
    }
    if (result.match && !directionRight) {
      return out(
        "direction",
        "The size is right but the direction is wrong." + (part.directionHint ? " " + part.directionHint : ""),
        null,
        keySize,
      );
    }
    // The key to too few figures, as it may be read (60 for 64); written with zeros after it
    // (60. or 6.0e1), only where no slip below is what it is.
    function tooFewSf() {
      var few = Math.min(number.sfMax, result.fewSf || minSf - 1);
      return out("too-few-sf", fewSfMessage(figures, few, minSf, checkSf, number.sfMax > few));
    }
    if (result.matchFewSf && number.sfMin < minSf) return tooFewSf();
    // Slips computed from the working (physics_figures.questions): nothing else is called rounding.
    // a slip is named only on an answer of the figures the A1 needs (the table's min): 1 s.f. could be anything
    if (
      number.sfMax >= figures.min &&
      typeof part.gNineEight === "number" &&
      against(part.gNineEight, reading.scale).match
    ) {
      return out(
        "g-9.8",
        "That is the answer with g = 9.8 m s⁻². The data give g = 9.81 m s⁻²: use it, " +
          "and keep every figure until the end.",
        null,
        part.gNineEight,
      );
    }
    var partWay = part.roundedPartWay || [];
    for (var i = 0; i < partWay.length; i++) {
      if (number.sfMax >= figures.min && against(partWay[i].value, reading.scale).match) {
        return out(
          "rounded-part-way",
          "Close, but that is what rounding " +
            partWay[i].rounded +
            " part-way through gives. Keep the full calculator value until the end, then round only the answer.",
          null,
          partWay[i].value,
        );
      }
    }
    if (result.matchFewSf) return tooFewSf();
    return out("wrong", "Not right. " + (part.revisit || "Check your method and your arithmetic."));
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
