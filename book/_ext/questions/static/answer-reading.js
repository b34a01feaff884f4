/* Reading what a student types: a number as students write it (with its significant
 * figures), a unit as symbols or words (into SI scale and dimensions), a unit in the wrong
 * case, a value typed with its unit. Plain JavaScript, offline; runs under Node for the tests.
 * The numeric part kind (question-kinds/numeric.js) marks with it. */
(function (root) {
  "use strict";

  var SUPERSCRIPTS = {
    "⁰": "0",
    "¹": "1",
    "²": "2",
    "³": "3",
    "⁴": "4",
    "⁵": "5",
    "⁶": "6",
    "⁷": "7",
    "⁸": "8",
    "⁹": "9",
    "⁻": "-",
    "⁺": "+",
  };

  // Unicode minus and dashes become "-", a run of superscripts becomes "^n".
  function normalise(text) {
    return String(text)
      .replace(/[\u2212\u2012\u2013\u2014]/g, "-")
      .replace(/[⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺]+/g, function (run) {
        return (
          "^" +
          run
            .split("")
            .map(function (c) {
              return SUPERSCRIPTS[c];
            })
            .join("")
        );
      })
      .replace(/\*\*/g, "^")
      .trim();
  }

  // ---------------------------------------------------------------- numbers

  var NUMBER =
    /^([+-]?)(\d+\.?\d*|\.\d+)(?:[eE]([+-]?\d+)|\s*[x×X*·]\s*10(?:\s*\^\s*(?:\(\s*([+-]?\d+)\s*\)|([+-]?\d+)))?)?$/;
  var POWER_ONLY = /^([+-]?)10\s*\^\s*\(?\s*([+-]?\d+)\s*\)?$/;

  function refuse(message) {
    return { ok: false, message: message };
  }

  /* What a typed number's form refuses before it is read: commas, and "10-3" for a power of ten. */
  function refuseForm(t) {
    if (t.indexOf(",") >= 0) {
      if (/^[+-]?\d{1,3}(,\d{3})+(\.\d*)?$/.test(t)) {
        return refuse(
          "Write " + t + " without the comma: " + t.replace(/,/g, "") + " (or in standard form, e.g. 1.5 × 10^3).",
        );
      }
      return refuse("Use a decimal point, not a comma (write 1.5, not 1,5), and no commas between thousands.");
    }
    if (/(^|[x×X*·\s])10\s*-\s*\d+$/.test(t)) {
      return refuse('"' + t + '" reads as ten minus a number. Write a power of ten as 10^-3, or use e: 1.5e-3.');
    }
    return null;
  }

  /* Sign, mantissa and power of ten of a typed number, or null: "1.5e3", "1.5 × 10^3", "1.5 x 10"
   * (10 to the first) and "10^-3" (the mantissa 1) are read. */
  function numberParts(t) {
    var m = NUMBER.exec(t);
    if (m) {
      // e3, 10^(3) or 10^3; a bare "× 10" is 10 to the first
      var written = m[3] !== undefined ? m[3] : m[4] !== undefined ? m[4] : m[5];
      if (written === undefined) written = /[x×X*·]/.test(t.slice(m[1].length + m[2].length)) ? 1 : 0;
      return { sign: m[1], mantissa: m[2], exponent: +written };
    }
    m = POWER_ONLY.exec(t);
    return m ? { sign: m[1], mantissa: "1", exponent: +m[2] } : null;
  }

  /* Read a number as a student writes it. Significant figures are counted as
   * written: a whole number's trailing zeros are ambiguous (1500 has 2 to 4). */
  function parseNumber(text) {
    var t = normalise(text).replace(/^([+-])\s+(?=[\d.])/, "$1"); // "- 1.0" is -1.0
    if (t === "") return refuse("Type a number, for example 7.5, -0.25 or 1.5e3.");
    var refused = refuseForm(t);
    if (refused) return refused;
    var parts = numberParts(t);
    if (!parts) {
      return refuse(
        "I can't read \"" + String(text).trim() + '" as a number. Write it like 7.5, -0.25, 1.5e3 or 1.5 × 10^3.',
      );
    }
    var mantissa = parts.mantissa,
      exponent = parts.exponent;
    var point = mantissa.indexOf(".");
    var whole = point < 0 ? mantissa : mantissa.slice(0, point);
    var fraction = point < 0 ? "" : mantissa.slice(point + 1);
    var digits = (whole + fraction).replace(/^0+/, "");
    var value = parseFloat(parts.sign + mantissa + "e" + exponent);
    var sfMax, sfMin, lead;
    if (digits === "") {
      // zero: only the decimal places written say anything
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
    g: [1e-3, [1, 0, 0, 0]],
    m: [1, [0, 1, 0, 0]],
    s: [1, [0, 0, 1, 0]],
    N: [1, [1, 1, -2, 0]],
    J: [1, [1, 2, -2, 0]],
    W: [1, [1, 2, -3, 0]],
    Pa: [1, [1, -1, -2, 0]],
    Hz: [1, [0, 0, -1, 0]],
  };
  var UNPREFIXED = {
    // symbols that take no prefix
    h: [3600, [0, 0, 1, 0]],
    min: [60, [0, 0, 1, 0]],
    sec: [1, [0, 0, 1, 0]],
    t: [1000, [1, 0, 0, 0]],
    "°": [1, [0, 0, 0, 1]],
    deg: [1, [0, 0, 0, 1]],
    rad: [180 / Math.PI, [0, 0, 0, 1]],
    "%": [0.01, [0, 0, 0, 0]],
  };
  // Unit names written as words ("newtons", "metres per second squared", "degrees").
  var UNIT_WORDS = {
    newton: "N",
    newtons: "N",
    joule: "J",
    joules: "J",
    watt: "W",
    watts: "W",
    kilogram: "kg",
    kilograms: "kg",
    gram: "g",
    grams: "g",
    metre: "m",
    metres: "m",
    meter: "m",
    meters: "m",
    kilometre: "km",
    kilometres: "km",
    kilometer: "km",
    kilometers: "km",
    centimetre: "cm",
    centimetres: "cm",
    centimeter: "cm",
    centimeters: "cm",
    second: "s",
    seconds: "s",
    millisecond: "ms",
    milliseconds: "ms",
    hour: "h",
    hours: "h",
    degree: "°",
    degrees: "°",
    radian: "rad",
    radians: "rad",
    per: "/",
  };

  function unitWords(text) {
    return text.replace(/\s*\bsquared\b/gi, "^2").replace(/[A-Za-z]+/g, function (word) {
      var symbol = UNIT_WORDS[word.toLowerCase()];
      return symbol === undefined ? word : symbol;
    });
  }
  var PREFIXES = { G: 1e9, M: 1e6, k: 1e3, c: 1e-2, m: 1e-3, µ: 1e-6, μ: 1e-6, u: 1e-6, n: 1e-9 };
  var QUANTITIES = [
    ["momentum", [1, 1, -1, 0]],
    ["force", [1, 1, -2, 0]],
    ["energy", [1, 2, -2, 0]],
    ["power", [1, 2, -3, 0]],
    ["velocity", [0, 1, -1, 0]],
    ["acceleration", [0, 1, -2, 0]],
    ["mass", [1, 0, 0, 0]],
    ["length", [0, 1, 0, 0]],
    ["time", [0, 0, 1, 0]],
    ["pressure", [1, -1, -2, 0]],
    ["frequency", [0, 0, -1, 0]],
    ["angle", [0, 0, 0, 1]],
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
      segmentations(run.slice(symbol.length)).forEach(function (rest) {
        found.push([unit].concat(rest));
      });
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
    return [
      Math.pow(unit[0], exponent),
      unit[1].map(function (d) {
        return d * exponent;
      }),
    ];
  }

  function times(a, b) {
    return [
      a[0] * b[0],
      a[1].map(function (d, i) {
        return d + b[1][i];
      }),
    ];
  }

  var FACTOR = /^([A-Za-zµμ°%]+)(?:\^\(?\s*([+-]?\d+)\s*\)?|([+-]?\d+))?/;

  /* The readings of one symbol run with its power ("kms^-1" may be km s⁻¹ or k m s⁻¹), as
   * {options, used}: used is how many characters it took. Null if it reads as no unit. */
  function symbolsFactor(rest) {
    var m = FACTOR.exec(rest);
    if (!m) return null;
    var exponent = m[2] !== undefined ? +m[2] : m[3] !== undefined ? +m[3] : 1;
    var options = segmentations(m[1]).map(function (symbols) {
      var last = symbols.length - 1;
      return {
        unit: symbols.reduce(
          function (acc, u, i) {
            return times(acc, i === last ? power(u, exponent) : u);
          },
          [1, [0, 0, 0, 0]],
        ),
        symbols: symbols.length,
      };
    });
    return options.length ? { options: options, used: m[0].length } : null;
  }

  /* The readings of a bracket after "/" ("J/(kg K)"), as symbolsFactor; null if unreadable. */
  function bracketFactor(rest) {
    var close = rest.indexOf(")");
    if (close < 0) return null;
    var inner = parseUnit(rest.slice(1, close));
    if (!inner.ok || inner.empty) return null;
    var options = inner.readings.map(function (r) {
      return { unit: [r.scale, r.dims], symbols: r.symbols };
    });
    return { options: options, used: close + 1 };
  }

  /* Every reading so far times every reading of the next factor. */
  function combineReadings(readings, options) {
    var next = [];
    readings.forEach(function (r) {
      options.forEach(function (o) {
        next.push({ unit: times(r.unit, o.unit), symbols: r.symbols + o.symbols });
      });
    });
    return next;
  }

  /* Read a unit typed as text into SI scale and dimensions. Returns every
   * reading (a list of {scale, dims}, fewest symbols first) or an error. */
  function parseUnit(text) {
    var t = unitWords(normalise(text)).replace(/([A-Za-z°%)])\s*[.·⋅*]\s*(?=[A-Za-zµμ(])/g, "$1 ");
    if (t === "") return { ok: true, empty: true, readings: [] };
    var readings = [{ unit: [1, [0, 0, 0, 0]], symbols: 0 }];
    var rest = t,
      divide = false;
    while (rest.length) {
      var space = /^\s+/.exec(rest);
      if (space) {
        rest = rest.slice(space[0].length);
        continue;
      }
      if (rest[0] === "/") {
        if (divide) return unreadableUnit(text);
        divide = true;
        rest = rest.slice(1);
        continue;
      }
      var factor = rest[0] === "(" && divide ? bracketFactor(rest) : symbolsFactor(rest);
      if (!factor) return unreadableUnit(text);
      rest = rest.slice(factor.used);
      var options = factor.options;
      if (divide) {
        options = options.map(function (o) {
          return { unit: power(o.unit, -1), symbols: o.symbols };
        });
        divide = false;
      }
      readings = combineReadings(readings, options);
    }
    if (divide) return unreadableUnit(text);
    readings.sort(function (a, b) {
      return a.symbols - b.symbols;
    });
    return {
      ok: true,
      empty: false,
      readings: readings.map(function (r) {
        return { scale: r.unit[0], dims: r.unit[1], symbols: r.symbols };
      }),
    };
  }

  function unreadableUnit(text) {
    return refuse(
      "I can't read the unit \"" +
        String(text).trim() +
        '". Use symbols such as kg, m, s, N, J, with powers written s^-1 or s-1: for example N s, kg m s^-1 or m/s.',
    );
  }

  /* Units are case-sensitive: "Kg", "M/S", "KG M S^-1" are not units, or not this one. The
   * same text with its letters re-cased into symbols that give the expected dimensions
   * (fewest letters changed, then the expected unit's own scale), or null. */
  function recasedUnit(text, expectedDims, expectedScale) {
    var t = normalise(text),
      runs = t.match(/[A-Za-z]+/g) || [];
    if (
      !runs.length ||
      runs.some(function (r) {
        return r.length > 6;
      })
    )
      return null;
    function casings(run) {
      // every casing of the run that reads as unit symbols
      var out = [];
      for (var bits = 0; bits < 1 << run.length; bits++) {
        var c = "",
          changed = 0;
        for (var i = 0; i < run.length; i++) {
          var ch = bits & (1 << i) ? run[i].toUpperCase() : run[i].toLowerCase();
          if (ch !== run[i]) changed += 1;
          c += ch;
        }
        if (UNIT_WORDS[c.toLowerCase()] !== undefined || segmentations(c).length)
          out.push({ text: c, changed: changed });
      }
      return out;
    }
    var candidates = [{ text: "", rest: t, changed: 0 }];
    for (var r = 0; r < runs.length; r++) {
      var options = casings(runs[r]),
        next = [];
      if (!options.length) return null;
      candidates.forEach(function (c) {
        var at = c.rest.indexOf(runs[r]);
        options.forEach(function (o) {
          next.push({
            text: c.text + c.rest.slice(0, at) + o.text,
            rest: c.rest.slice(at + runs[r].length),
            changed: c.changed + o.changed,
          });
        });
      });
      if (next.length > 256) return null;
      candidates = next;
    }
    var best = null;
    candidates.forEach(function (c) {
      if (!c.changed) return;
      var full = c.text + c.rest,
        parsed = parseUnit(full);
      if (!parsed.ok || parsed.empty) return;
      var fits = parsed.readings.filter(function (reading) {
        return sameDims(reading.dims, expectedDims);
      });
      if (!fits.length) return;
      var exact = fits.some(function (reading) {
        return Math.abs(reading.scale / expectedScale - 1) < 1e-9;
      });
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

  /* An answer's value and unit boxes, read as typed: a unit typed in the value box ("3.2 kg"
   * with the unit box empty) is split off. */
  function typedAnswer(answer) {
    var valueText = answer.value || "",
      unitText = answer.unit || "";
    if (!normalise(unitText) && /[A-Za-zµμ°%]/.test(normalise(valueText).replace(/[eExX×]/g, ""))) {
      var split = splitValueAndUnit(valueText);
      valueText = split[0];
      unitText = split[1];
    }
    return { valueText: valueText, unitText: unitText, direction: answer.direction || "" };
  }

  /* A unit typed in the wrong case (MS for ms; unit: parseUnit's reading of unitText): the unit
   * meant (partUnit's own form, where it is that), or false where the unit fits or no recasing does. */
  function unitMeant(unitText, unit, expected, partUnit) {
    var fits = unit.ok && unit.readings.some((r) => sameDims(r.dims, expected.dims));
    var recased = !fits && recasedUnit(unitText, expected.dims, expected.scale);
    if (recased && recased.replace(/\s+/g, "") === normalise(partUnit).replace(/\s+/g, ""))
      recased = normalise(partUnit);
    return recased;
  }

  function superscript(unitText) {
    return String(unitText).replace(/\^(-?\d+)/g, function (_, n) {
      return n.replace(/-/g, "⁻").replace(/\d/g, function (d) {
        return "⁰¹²³⁴⁵⁶⁷⁸⁹"[d];
      });
    });
  }

  var reading = {
    normalise: normalise,
    parseNumber: parseNumber,
    parseUnit: parseUnit,
    quantityOf: quantityOf,
    sameDims: sameDims,
    recasedUnit: recasedUnit,
    splitValueAndUnit: splitValueAndUnit,
    typedAnswer: typedAnswer,
    unitMeant: unitMeant,
    superscript: superscript,
    // the reader's own tables: the Moodle export declares each unit's forms from them
    tables: { base: BASE_UNITS, unprefixed: UNPREFIXED, words: UNIT_WORDS, prefixes: PREFIXES },
  };
  if (typeof module === "object" && module.exports) module.exports = reading;
  else root.AnswerReading = reading;
})(this);
