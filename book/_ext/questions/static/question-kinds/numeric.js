/* The numeric part kind (a calculated value, or a reading from a graph): numbers as students
 * write them, significant figures, units, direction, named mistakes, alternatives. Marks one
 * part's answer to an outcome (code, message); what an outcome earns is the rule table's
 * (physics_figures/marking_rules.json), applied by questions.js. Its Python twins are Part and
 * GraphPart (physics_figures/parts/numeric.py and graph.py). */
(function (root) {
  "use strict";

  // How numbers are written (book/_ext/notation): loaded before this script in a page.
  var Notation = root.Notation || require("../../../notation/static/notation.js");

  var SUPERSCRIPTS = { "⁰": "0", "¹": "1", "²": "2", "³": "3", "⁴": "4", "⁵": "5",
    "⁶": "6", "⁷": "7", "⁸": "8", "⁹": "9", "⁻": "-", "⁺": "+" };

  // Unicode minus and dashes become "-", a run of superscripts becomes "^n".
  function normalise(text) {
    return String(text)
      .replace(/[\u2212\u2012\u2013\u2014]/g, "-")
      .replace(/[⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺]+/g, function (run) {
        return "^" + run.split("").map(function (c) { return SUPERSCRIPTS[c]; }).join("");
      })
      .replace(/\*\*/g, "^")
      .trim();
  }

  // ---------------------------------------------------------------- numbers

  var NUMBER = /^([+-]?)(\d+\.?\d*|\.\d+)(?:[eE]([+-]?\d+)|\s*[x×X*·]\s*10(?:\s*\^\s*(?:\(\s*([+-]?\d+)\s*\)|([+-]?\d+)))?)?$/;
  var POWER_ONLY = /^([+-]?)10\s*\^\s*\(?\s*([+-]?\d+)\s*\)?$/;

  function refuse(message) { return { ok: false, message: message }; }

  /* Read a number as a student writes it. Significant figures are counted as
   * written: a whole number's trailing zeros are ambiguous (1500 has 2 to 4). */
  function parseNumber(text) {
    var t = normalise(text).replace(/^([+-])\s+(?=[\d.])/, "$1"); // "- 1.0" is -1.0
    if (t === "") return refuse("Type a number, for example 7.5, -0.25 or 1.5e3.");
    if (t.indexOf(",") >= 0) {
      if (/^[+-]?\d{1,3}(,\d{3})+(\.\d*)?$/.test(t)) {
        return refuse("Write " + t + " without the comma: " + t.replace(/,/g, "") +
          " (or in standard form, e.g. 1.5 × 10^3).");
      }
      return refuse("Use a decimal point, not a comma (write 1.5, not 1,5), and no commas between thousands.");
    }
    if (/(^|[x×X*·\s])10\s*-\s*\d+$/.test(t)) {
      return refuse("\"" + t + "\" reads as ten minus a number. Write a power of ten as 10^-3, or use e: 1.5e-3.");
    }
    var mantissa, sign, exponent, m = NUMBER.exec(t);
    if (m) {
      sign = m[1];
      mantissa = m[2];
      exponent = m[3] !== undefined ? +m[3] : m[4] !== undefined ? +m[4] : m[5] !== undefined ? +m[5] :
        /[x×X*·]/.test(t.slice(m[1].length + m[2].length)) ? 1 : 0;
    } else if ((m = POWER_ONLY.exec(t))) {
      sign = m[1];
      mantissa = "1";
      exponent = +m[2];
    } else {
      return refuse("I can't read \"" + String(text).trim() + "\" as a number. Write it like 7.5, -0.25, 1.5e3 or 1.5 × 10^3.");
    }
    var point = mantissa.indexOf(".");
    var whole = point < 0 ? mantissa : mantissa.slice(0, point);
    var fraction = point < 0 ? "" : mantissa.slice(point + 1);
    var digits = (whole + fraction).replace(/^0+/, "");
    var value = parseFloat(sign + mantissa + "e" + exponent);
    var sfMax, sfMin, lead;
    if (digits === "") { // zero: only the decimal places written say anything
      sfMax = sfMin = Math.max(1, fraction.length);
      lead = -fraction.length + sfMax - 1 + exponent;
    } else {
      sfMax = digits.length;
      sfMin = point < 0 ? Math.max(1, digits.replace(/0+$/, "").length) : sfMax;
      var wholeDigits = whole.replace(/^0+/, "");
      lead = (wholeDigits ? wholeDigits.length - 1 : -(fraction.match(/^0*/)[0].length + 1)) + exponent;
    }
    // lead: power of ten of the first significant digit (the last digit is at lead - sf + 1)
    return { ok: true, value: value, sfMin: sfMin, sfMax: sfMax, lead: lead };
  }

  // ------------------------------------------------------------------ units

  // Dimensions: [mass, length, time, angle].
  var BASE_UNITS = {
    g: [1e-3, [1, 0, 0, 0]], m: [1, [0, 1, 0, 0]], s: [1, [0, 0, 1, 0]],
    N: [1, [1, 1, -2, 0]], J: [1, [1, 2, -2, 0]], W: [1, [1, 2, -3, 0]],
    Pa: [1, [1, -1, -2, 0]], Hz: [1, [0, 0, -1, 0]]
  };
  var UNPREFIXED = { // symbols that take no prefix
    h: [3600, [0, 0, 1, 0]], min: [60, [0, 0, 1, 0]], sec: [1, [0, 0, 1, 0]], t: [1000, [1, 0, 0, 0]],
    "°": [1, [0, 0, 0, 1]], deg: [1, [0, 0, 0, 1]], rad: [180 / Math.PI, [0, 0, 0, 1]],
    "%": [0.01, [0, 0, 0, 0]]
  };
  // Unit names written as words ("newtons", "metres per second squared", "degrees").
  var UNIT_WORDS = {
    newton: "N", newtons: "N", joule: "J", joules: "J", watt: "W", watts: "W",
    kilogram: "kg", kilograms: "kg", gram: "g", grams: "g", metre: "m", metres: "m", meter: "m",
    meters: "m", kilometre: "km", kilometres: "km", kilometer: "km", kilometers: "km",
    centimetre: "cm", centimetres: "cm", centimeter: "cm", centimeters: "cm", second: "s",
    seconds: "s", millisecond: "ms", milliseconds: "ms", hour: "h", hours: "h",
    degree: "°", degrees: "°", radian: "rad", radians: "rad", per: "/"
  };

  function unitWords(text) {
    return text
      .replace(/\s*\bsquared\b/gi, "^2")
      .replace(/[A-Za-z]+/g, function (word) {
        var symbol = UNIT_WORDS[word.toLowerCase()];
        return symbol === undefined ? word : symbol;
      });
  }
  var PREFIXES = { G: 1e9, M: 1e6, k: 1e3, c: 1e-2, m: 1e-3, "µ": 1e-6, "μ": 1e-6, u: 1e-6, n: 1e-9 };
  var QUANTITIES = [
    ["momentum", [1, 1, -1, 0]], ["force", [1, 1, -2, 0]], ["energy", [1, 2, -2, 0]],
    ["power", [1, 2, -3, 0]], ["velocity", [0, 1, -1, 0]], ["acceleration", [0, 1, -2, 0]],
    ["mass", [1, 0, 0, 0]], ["length", [0, 1, 0, 0]], ["time", [0, 0, 1, 0]],
    ["pressure", [1, -1, -2, 0]], ["frequency", [0, 0, -1, 0]], ["angle", [0, 0, 0, 1]]
  ];

  function sameDims(a, b) {
    for (var i = 0; i < 4; i++) if (a[i] !== b[i]) return false;
    return true;
  }

  function quantityOf(dims) {
    for (var i = 0; i < QUANTITIES.length; i++) if (sameDims(QUANTITIES[i][1], dims)) return QUANTITIES[i][0];
    return null;
  }

  // Every way to read a run of letters as unit symbols ("ms": millisecond, or metre second).
  function segmentations(run) {
    if (run === "") return [[]];
    var found = [];
    function extend(symbol, unit) {
      segmentations(run.slice(symbol.length)).forEach(function (rest) { found.push([unit].concat(rest)); });
    }
    Object.keys(UNPREFIXED).forEach(function (symbol) {
      if (run.indexOf(symbol) === 0) extend(symbol, UNPREFIXED[symbol]);
    });
    Object.keys(BASE_UNITS).forEach(function (symbol) {
      if (run.indexOf(symbol) === 0) extend(symbol, BASE_UNITS[symbol]);
      Object.keys(PREFIXES).forEach(function (prefix) {
        if (run.indexOf(prefix + symbol) === 0) {
          extend(prefix + symbol, [PREFIXES[prefix] * BASE_UNITS[symbol][0], BASE_UNITS[symbol][1]]);
        }
      });
    });
    return found;
  }

  function power(unit, exponent) {
    return [Math.pow(unit[0], exponent), unit[1].map(function (d) { return d * exponent; })];
  }

  function times(a, b) {
    return [a[0] * b[0], a[1].map(function (d, i) { return d + b[1][i]; })];
  }

  var FACTOR = /^([A-Za-zµμ°%]+)(?:\^\(?\s*([+-]?\d+)\s*\)?|([+-]?\d+))?/;

  /* Read a unit typed as text into SI scale and dimensions. Returns every
   * reading (a list of {scale, dims}, fewest symbols first) or an error. */
  function parseUnit(text) {
    var t = unitWords(normalise(text)).replace(/([A-Za-z°%)])\s*[.·⋅*]\s*(?=[A-Za-zµμ(])/g, "$1 ");
    if (t === "") return { ok: true, empty: true, readings: [] };
    var readings = [{ unit: [1, [0, 0, 0, 0]], symbols: 0 }];
    var rest = t, divide = false;
    while (rest.length) {
      var space = /^\s+/.exec(rest);
      if (space) { rest = rest.slice(space[0].length); continue; }
      if (rest[0] === "/") {
        if (divide) return unreadableUnit(text);
        divide = true; rest = rest.slice(1); continue;
      }
      var options;
      if (rest[0] === "(" && divide) {
        var close = rest.indexOf(")");
        if (close < 0) return unreadableUnit(text);
        var inner = parseUnit(rest.slice(1, close));
        if (!inner.ok || inner.empty) return unreadableUnit(text);
        options = inner.readings.map(function (r) { return { unit: [r.scale, r.dims], symbols: r.symbols }; });
        rest = rest.slice(close + 1);
      } else {
        var m = FACTOR.exec(rest);
        if (!m) return unreadableUnit(text);
        var exponent = m[2] !== undefined ? +m[2] : m[3] !== undefined ? +m[3] : 1;
        options = segmentations(m[1]).map(function (symbols) {
          var last = symbols.length - 1;
          return {
            unit: symbols.reduce(function (acc, u, i) { return times(acc, i === last ? power(u, exponent) : u); },
              [1, [0, 0, 0, 0]]),
            symbols: symbols.length
          };
        });
        if (!options.length) return unreadableUnit(text);
        rest = rest.slice(m[0].length);
      }
      if (divide) {
        options = options.map(function (o) { return { unit: power(o.unit, -1), symbols: o.symbols }; });
        divide = false;
      }
      var next = [];
      readings.forEach(function (r) {
        options.forEach(function (o) { next.push({ unit: times(r.unit, o.unit), symbols: r.symbols + o.symbols }); });
      });
      readings = next;
    }
    if (divide) return unreadableUnit(text);
    readings.sort(function (a, b) { return a.symbols - b.symbols; });
    return {
      ok: true, empty: false,
      readings: readings.map(function (r) { return { scale: r.unit[0], dims: r.unit[1], symbols: r.symbols }; })
    };
  }

  function unreadableUnit(text) {
    return refuse("I can't read the unit \"" + String(text).trim() +
      "\". Use symbols such as kg, m, s, N, J, with powers written s^-1 or s-1: for example N s, kg m s^-1 or m/s.");
  }

  /* Units are case-sensitive: "Kg", "M/S", "KG M S^-1" are not units, or not this one. The
   * same text with its letters re-cased into symbols that give the expected dimensions
   * (fewest letters changed, then the expected unit's own scale), or null. */
  function recasedUnit(text, expectedDims, expectedScale) {
    var t = normalise(text), runs = t.match(/[A-Za-z]+/g) || [];
    if (!runs.length || runs.some(function (r) { return r.length > 6; })) return null;
    function casings(run) { // every casing of the run that reads as unit symbols
      var out = [];
      for (var bits = 0; bits < (1 << run.length); bits++) {
        var c = "", changed = 0;
        for (var i = 0; i < run.length; i++) {
          var ch = bits & (1 << i) ? run[i].toUpperCase() : run[i].toLowerCase();
          if (ch !== run[i]) changed += 1;
          c += ch;
        }
        if (UNIT_WORDS[c.toLowerCase()] !== undefined || segmentations(c).length) out.push({ text: c, changed: changed });
      }
      return out;
    }
    var candidates = [{ text: "", rest: t, changed: 0 }];
    for (var r = 0; r < runs.length; r++) {
      var options = casings(runs[r]), next = [];
      if (!options.length) return null;
      candidates.forEach(function (c) {
        var at = c.rest.indexOf(runs[r]);
        options.forEach(function (o) {
          next.push({ text: c.text + c.rest.slice(0, at) + o.text, rest: c.rest.slice(at + runs[r].length),
            changed: c.changed + o.changed });
        });
      });
      if (next.length > 256) return null;
      candidates = next;
    }
    var best = null;
    candidates.forEach(function (c) {
      if (!c.changed) return;
      var full = c.text + c.rest, parsed = parseUnit(full);
      if (!parsed.ok || parsed.empty) return;
      var fits = parsed.readings.filter(function (reading) { return sameDims(reading.dims, expectedDims); });
      if (!fits.length) return;
      var exact = fits.some(function (reading) { return Math.abs(reading.scale / expectedScale - 1) < 1e-9; });
      var rank = c.changed * 2 + (exact ? 0 : 1);
      if (!best || rank < best.rank) best = { text: full, rank: rank };
    });
    return best && best.text;
  }

  /* A value typed with its unit in the number box ("15 N s") is split in two. */
  function splitValueAndUnit(text) {
    var t = normalise(text);
    for (var i = 0; i < t.length; i++) {
      var c = t[i];
      if (!/[A-Za-zµμ°%×]/.test(c)) continue;
      if (/[eE]/.test(c) && /^[+-]?\d/.test(t.slice(i + 1)) && /\d\s*$/.test(t.slice(0, i))) continue;
      if (/[xX×]/.test(c) && /^\s*10/.test(t.slice(i + 1))) continue;
      return [t.slice(0, i).trim(), t.slice(i).trim()];
    }
    return [t, ""];
  }

  // ---------------------------------------------------------------- marking

  // Whole numbers of steps of 10^place nearest x; both neighbours on a tie.
  function steps(x, place) {
    var q = x / Math.pow(10, place), n = Math.floor(q), f = q - n;
    if (Math.abs(f - 0.5) < 1e-7) return [n, n + 1];
    return [f < 0.5 ? n : n + 1];
  }

  function stepsApart(typed, target, place) {
    var best = Infinity;
    steps(typed, place).forEach(function (a) {
      steps(target, place).forEach(function (b) { best = Math.min(best, Math.abs(a - b)); });
    });
    return best;
  }

  /* Is value the target rounded to sf significant figures (60 for 56.0 at 1 s.f.; not 10 for 7.5)? */
  function roundsTo(value, target, sf) {
    var place = Math.floor(Math.log10(Math.abs(target)) + 1e-12) - sf + 1, scaled = value / Math.pow(10, place);
    return steps(Math.abs(target), place).some(function (n) {
      return Math.abs(Math.abs(scaled) - n) < 1e-7 * Math.max(1, n);
    }) && (value < 0) === (target < 0);
  }

  /* Compare a typed number with a target (in the same unit) at every reading
   * of its significant figures. The comparison is at the student's last digit,
   * but never finer than checkSf figures of the target: the key is only
   * trusted that far, so rounding intermediate values to 3 s.f. still passes.
   * match: right to minSf or more. matchFewSf: the key rounded to fewer figures
   * (60 for 56.0: right to 1 s.f.). */
  function compare(number, target, minSf, checkSf) {
    var result = { match: false, matchFewSf: false };
    if (target === 0) { result.match = number.value === 0; return result; } // zero has no significant figures
    var checkPlace = Math.floor(Math.log10(Math.abs(target)) + 1e-12) - checkSf + 1;
    for (var sf = number.sfMax; sf >= number.sfMin; sf--) {
      if (sf >= minSf) {
        if (stepsApart(number.value, target, Math.max(number.lead - sf + 1, checkPlace)) === 0) result.match = true;
      } else if (roundsTo(number.value, target, sf)) {
        result.matchFewSf = true;
      }
    }
    if (result.match) result.matchFewSf = false;
    return result;
  }

  function superscript(unitText) {
    return String(unitText).replace(/\^(-?\d+)/g, function (_, n) {
      return n.replace(/-/g, "⁻").replace(/\d/g, function (d) { return "⁰¹²³⁴⁵⁶⁷⁸⁹"[d]; });
    });
  }

  function outcome(code, message, extra) {
    var result = { code: code, correct: code === "correct", message: message };
    if (extra) Object.keys(extra).forEach(function (k) { result[k] = extra[k]; });
    return result;
  }

  /* Mark one answer to one part of a question.
   * part: {value (SI, signed when direction is "signed"), unit, units, quantity,
   *        minSf, checkSf, direction: "none" | "signed" | "choice", positive,
   *        choices, answerDirection, mistakes: [{value, unit, direction, feedback}], revisit}
   * answer: {value: text, unit: text, direction: text} */
  function mark(part, answer) {
    var valueText = answer.value || "", unitText = answer.unit || "", direction = answer.direction || "";
    if (!normalise(unitText) && /[A-Za-zµμ°%]/.test(normalise(valueText).replace(/[eExX×]/g, ""))) {
      var split = splitValueAndUnit(valueText);
      valueText = split[0]; unitText = split[1];
    }
    var number = parseNumber(valueText);
    if (!number.ok) return outcome("unreadable-number", number.message);
    var unit = parseUnit(unitText);
    var expected = parseUnit(part.unit).readings[0];
    // A unit in the wrong case: say so, and mark the answer as if it were written right.
    var fits = unit.ok && unit.readings.some(function (r) { return sameDims(r.dims, expected.dims); });
    var recased = !fits && !answer.recased && recasedUnit(unitText, expected.dims, expected.scale);
    if (recased) {
      if (recased.replace(/\s+/g, "") === normalise(part.unit).replace(/\s+/g, "")) recased = normalise(part.unit);
      var asMeant = mark(part, { value: valueText, unit: recased, direction: direction, recased: true });
      var caseNote = "Units are case-sensitive: " + superscript(normalise(unitText)) + " is not " +
        (unit.ok ? "a unit of " + part.quantity : "a unit") + ". You probably meant " + superscript(recased) + ".";
      if (asMeant.code === "correct") {
        return outcome("unit-case", caseNote + " With that unit the answer is right.",
          { si: asMeant.si, valueRight: true, meant: recased });
      }
      asMeant.message = caseNote + " " + asMeant.message;
      asMeant.meant = recased;
      return asMeant;
    }
    if (!unit.ok) return outcome("unreadable-unit", unit.message);

    var minSf = part.minSf, checkSf = part.checkSf; // from the rule table, with the part's data
    var mode = part.direction || "none";
    var quantity = part.quantity, units = superscript(part.units || part.unit);
    var typed = number.value;
    var size = mode === "signed" ? typed : Math.abs(typed);
    var target = mode === "signed" ? part.value : Math.abs(part.value);

    // The reading of the unit: the one with the right dimensions and the right value, if any.
    var readings = unit.empty ? [expected] : unit.readings;
    var fitting = readings.filter(function (r) { return sameDims(r.dims, expected.dims); });
    function against(value, scale) {
      if (part.tolerance) { // read from a graph: right within half a small square either way
        var near = Math.abs(size - value / scale) <= (part.tolerance / scale) * (1 + 1e-9);
        return { match: near, matchFewSf: false };
      }
      var n = { value: size, sfMin: number.sfMin, sfMax: number.sfMax, lead: number.lead };
      return compare(n, value / scale, minSf, checkSf);
    }
    var reading = fitting.filter(function (r) { return against(target, r.scale).match; })[0] ||
      fitting[0] || readings[0];
    // Every outcome carries the answer in SI (for error carried forward) when its unit fits.
    var si = sameDims(reading.dims, expected.dims) ? size * reading.scale : null;
    function out(code, message, extra) {
      var result = outcome(code, message, extra);
      result.si = si;
      result.valueRight = !!alternative || against(target, reading.scale).match || against(target, 1).match;
      return result;
    }

    function namedMistake(dims, scale) {
      var mistakes = part.mistakes || [];
      for (var i = 0; i < mistakes.length; i++) {
        var mistake = mistakes[i];
        var mistakeDims = mistake.unit ? parseUnit(mistake.unit).readings[0].dims : expected.dims;
        if (!sameDims(mistakeDims, dims)) continue;
        if (mistake.direction && mistake.direction !== direction) continue;
        var value = mode === "signed" ? mistake.value : Math.abs(mistake.value);
        if ((number.sfMax >= 2 || value === 0) && against(value, scale).match) {
          return out("mistake", mistake.feedback, { mistake: mistake.name, loses: mistake.loses });
        }
      }
      return null;
    }

    if (!sameDims(reading.dims, expected.dims)) {
      var found = namedMistake(reading.dims, reading.scale);
      if (found) return found;
      var other = quantityOf(reading.dims);
      return out(against(target, 1).match ? "wrong-unit" : "wrong", (against(target, 1).match ? "The number is right, but " : "") +
        superscript(normalise(unitText)) + (other && other !== quantity ?
          " is a unit of " + other + ", not of " + quantity + "." : " is not a unit of " + quantity + ".") +
        " Give " + quantity + " in " + units + ".");
    }

    // A size typed with a minus sign: ignored where the direction is asked separately (the
    // schemes' "ignore sign"), right where the part says what the sign means, else a slip.
    var signed = mode !== "signed" && typed < 0;
    var signIgnored = signed && mode === "choice";
    var sign = signed && !part.signMeans && !signIgnored;
    var result = against(target, reading.scale);
    // A value the scheme also accepts (another route, or its own rounded working).
    var alternative = null;
    if (!result.match) {
      (part.alternatives || []).some(function (alt) {
        var byAlt = against(mode === "signed" ? alt.value : Math.abs(alt.value), reading.scale);
        if (byAlt.match) { result = byAlt; alternative = alt; }
        return byAlt.match;
      });
    }
    var directionRight = mode !== "choice" || direction === part.answerDirection;

    if (result.match && !sign && directionRight) {
      if (unit.empty) return out("missing-unit", "The number is right. Now give the unit: " + units + ".");
      if (alternative) return out("alternative", "Accepted: " + alternative.why + ".");
      if (signIgnored) return out("ignore-sign", "Correct: the minus sign is ignored, as the direction is given separately.");
      return out("correct", signed ? "Correct: the minus sign says " + part.signMeans + "." : "Correct.");
    }
    if (result.match && !sign && mode === "choice" && !direction) {
      return out("missing-direction", "The size is right. Now give the direction.");
    }

    var named = namedMistake(reading.dims, reading.scale);
    if (named) return named;

    if (!unit.empty && reading.scale !== 1 && against(target, 1).match && sameDims(expected.dims, [0, 0, 0, 1])) {
      return out("angle-unit", "That number is right in degrees, but " + superscript(normalise(unitText)) +
        " is not degrees: 1 rad = 57.3°. Give the angle in ° (degrees).");
    }
    if (!unit.empty && reading.scale !== 1 && against(target, 1).match) {
      return out("prefix", "Check the prefix: " + Notation.formatNumber(typed, number.sfMax) + " " + superscript(part.unit) +
        " would be right, but 1 " + superscript(normalise(unitText)) + " = " + Notation.formatNumber(reading.scale, 1) + " " +
        superscript(part.unit) + ". Convert g to kg, ms to s, cm to m.");
    }

    if (sign && result.match) {
      return out("sign-on-size", "The size is right, but a " + quantity +
        " here is a size with no sign: leave out the minus sign.");
    }
    if (mode === "signed" && target !== 0 && compare(
      { value: -typed, sfMin: number.sfMin, sfMax: number.sfMax, lead: number.lead },
      target / reading.scale, minSf, checkSf).match) {
      return out("sign", "The size is right but the sign is wrong. Positive is " + part.positive +
        (target < 0 ? ", and this points the other way, so it is negative." :
          ", and this points that way, so it is positive."));
    }
    if (result.match && !directionRight) {
      return out("direction", "The size is right but the direction is wrong." +
        (part.directionHint ? " " + part.directionHint : ""));
    }
    if (result.matchFewSf) {
      var few = Math.min(number.sfMax, minSf - 1);
      return out("too-few-sf", few + " s.f.: the A1 needs " + minSf + " or more" +
        (number.sfMin < number.sfMax ? " (zeros at the end of a whole number may not count: write 7.0 × 10², not 700)." : "."));
    }
    // Slips computed from the working (physics_figures.questions): nothing else is called rounding.
    if (number.sfMax >= 2 && typeof part.gNineEight === "number" && against(part.gNineEight, reading.scale).match) {
      return out("g-9.8", "That is the answer with g = 9.8 m s⁻². The data give g = 9.81 m s⁻²: use it, " +
        "and keep every figure until the end.");
    }
    var partWay = part.roundedPartWay || [];
    for (var i = 0; i < partWay.length; i++) {
      if (number.sfMax >= 2 && against(partWay[i].value, reading.scale).match) {
        return out("rounded-part-way", "Close, but that is what rounding " + partWay[i].rounded +
          " part-way through gives. Keep the full calculator value until the end, then round only the answer.");
      }
    }
    return out("wrong", "Not right. " + (part.revisit || "Check your method and your arithmetic."));
  }

  var kind = { kinds: ["numeric", "graph"], mark: mark, parseNumber: parseNumber, parseUnit: parseUnit, splitValueAndUnit: splitValueAndUnit,
    recasedUnit: recasedUnit, superscript: superscript };
  if (typeof module === "object" && module.exports) module.exports = kind;
  else kind.kinds.forEach(function (name) { (root.QuestionKinds = root.QuestionKinds || {})[name] = kind; });
})(this);
