/* How the book writes a number, in the browser: the twin of physics_figures/notation.py.
 * tests/notation_cases.json is run against both (tests/js/notation.test.js and
 * tests/test_notation.py), so a read-out, a feedback message and a figure label agree.
 * Rounding is half away from zero on the shortest decimal form of the number (as Python's
 * repr and JavaScript's String both give it): 0.125 -> 0.13, 2.85 -> 2.9. */
(function (root) {
  "use strict";
  var MINUS = "\u2212",
    GROUP = "\u202f",
    TIMES = "\u00d7";
  var SUPERSCRIPTS = {
    "-": "\u207b",
    0: "\u2070",
    1: "\u00b9",
    2: "\u00b2",
    3: "\u00b3",
    4: "\u2074",
    5: "\u2075",
    6: "\u2076",
    7: "\u2077",
    8: "\u2078",
    9: "\u2079",
  };

  function zeros(n) {
    return n > 0 ? new Array(n + 1).join("0") : "";
  }

  /* |x| as {digits, point}: x = 0.digits × 10^point, first digit not 0 (null for 0). */
  function decimalDigits(size) {
    var m = /^(\d+)(?:\.(\d+))?(?:e([+-]\d+))?$/.exec(String(size));
    var digits = m[1] + (m[2] || ""),
      point = m[1].length + (m[3] ? parseInt(m[3], 10) : 0);
    var lead = /^0*/.exec(digits)[0].length;
    digits = digits.slice(lead).replace(/0+$/, "");
    return digits ? { digits: digits, point: point - lead } : null;
  }

  /* Keep `keep` digits, rounding half away from zero (on the size). */
  function roundDigits(d, keep) {
    if (keep < 0 || (keep === 0 && d.digits[0] < "5")) return null;
    if (keep === 0) return { digits: "1", point: d.point + 1 }; // 0.06 to 1 place -> 0.1
    if (d.digits.length <= keep) return { digits: d.digits + zeros(keep - d.digits.length), point: d.point };
    var kept = d.digits.slice(0, keep),
      point = d.point;
    if (d.digits[keep] >= "5") {
      var out = kept.split(""),
        i = out.length - 1;
      while (i >= 0 && out[i] === "9") {
        out[i] = "0";
        i -= 1;
      }
      if (i >= 0) out[i] = String(Number(out[i]) + 1);
      else {
        out.unshift("1");
        point += 1;
      }
      kept = out.join("");
      if (kept.length > keep) kept = kept.slice(0, keep); // 9.99 -> 10.0: one more place before the point
    }
    return { digits: kept, point: point };
  }

  function group(whole) {
    return whole.length < 5 ? whole : whole.replace(/\B(?=(\d{3})+(?!\d))/g, GROUP);
  }

  function superscript(digits) {
    return String(digits)
      .split("")
      .map(function (c) {
        return SUPERSCRIPTS[c];
      })
      .join("");
  }

  /** Rounded digits (not zero) written out: in standard form when the first digit's place is
   *  10⁵ or more or 10⁻⁴ or less, else as a plain number with its thousands grouped. */
  function writeDigits(rounded) {
    var digits = rounded.digits,
      point = rounded.point;
    if (point >= 6 || point <= -3) {
      var mantissa = digits[0] + (digits.length > 1 ? "." + digits.slice(1) : "");
      return mantissa + " " + TIMES + " 10" + superscript(point - 1);
    }
    if (point <= 0) return "0." + zeros(-point) + digits;
    if (point >= digits.length) return group(digits + zeros(point - digits.length));
    return group(digits.slice(0, point)) + "." + digits.slice(point);
  }

  function refuseFormatArguments(x, sigFigs, decimals) {
    if ((sigFigs === undefined || sigFigs === null) === (decimals === undefined)) {
      throw new Error("formatNumber: give exactly one of sigFigs and opts.decimals");
    }
    if (typeof x !== "number" || !isFinite(x)) throw new Error("formatNumber: x must be a finite number, got " + x);
  }

  /** x to `sigFigs` significant figures, or to opts.decimals places; opts.plus writes "+" before
   *  a positive number. formatNumber(-30012, 2) -> "−30 000"; formatNumber(150000, 2) -> "1.5 × 10⁵". */
  function formatNumber(x, sigFigs, opts) {
    opts = opts || {};
    var decimals = opts.decimals;
    refuseFormatArguments(x, sigFigs, decimals);
    var d = decimalDigits(Math.abs(x));
    var rounded = d && roundDigits(d, decimals === undefined ? sigFigs : d.point + decimals);
    if (!rounded) {
      // an exact zero is 0 at any s.f.; a value rounded to zero keeps its places
      var places = decimals !== undefined ? decimals : d ? sigFigs - 1 : 0;
      return places > 0 ? "0." + zeros(places) : "0";
    }
    return (x < 0 ? MINUS : opts.plus ? "+" : "") + writeDigits(rounded);
  }

  /* A number is joined to its unit, and a unit's symbols to each other, by a no-break space
   * (U+00A0), so "50 m s⁻¹" never breaks across lines (CLARIFICATIONS, Reading). */
  var UNIT_SPACE = "\u00a0",
    UNSPACED = { "\u00b0": true, "%": true, "": true };

  /** A unit as text, symbols joined and powers raised: unitText("m s^-1") -> "m\u00a0s⁻¹". */
  function unitText(unit) {
    var raised = String(unit).replace(/\^(-?\d+)/g, function (m, power) {
      return superscript(power);
    });
    return raised.split(/\s+/).filter(Boolean).join(UNIT_SPACE);
  }

  /** A value with its unit, never split by a line break: formatQuantity(50, 2, "m s^-1")
   *  -> "50\u00a0m\u00a0s⁻¹"; formatQuantity(30, 2, "°") -> "30°". opts as formatNumber. */
  function formatQuantity(x, sigFigs, unit, opts) {
    var written = unitText(unit);
    return formatNumber(x, sigFigs, opts).replace(/ /g, UNIT_SPACE) + (UNSPACED[written] ? "" : UNIT_SPACE) + written;
  }

  /* Prose: the twin of join_units in physics_figures/notation.py (the same unit symbols). */
  var SYMBOLS = [
    "kg",
    "g",
    "m",
    "km",
    "cm",
    "mm",
    "s",
    "ms",
    "h",
    "min",
    "N",
    "kN",
    "J",
    "kJ",
    "W",
    "kW",
    "Pa",
    "kPa",
    "K",
    "mol",
    "rad",
    "Hz",
  ].sort(function (a, b) {
    return b.length - a.length;
  });
  var SYMBOL = "(?:" + SYMBOLS.join("|") + ")(?:\u207b?[\u2070\u00b9\u00b2\u00b3\u2074-\u2079]+)?(?![A-Za-z0-9])";
  var UNITS = SYMBOL + "(?:(?:[ \\t\\n\u00a0\u202f]+|/)" + SYMBOL + ")*";
  var NUMBER =
    "(?<![\\w.])\u2212?(?:\\d{1,3}(?:[ \u202f]\\d{3})+(?![\\d.])|\\d+(?:\\.\\d+)?)" +
    "(?:[ \u00a0\u202f]?\u00d7[ \u00a0\u202f]?10\u207b?[\u2070\u00b9\u00b2\u00b3\u2074-\u2079]+)?";
  var VALUE_WITH_UNIT = new RegExp("(" + NUMBER + ")([ \\t\\n\u00a0]+)(" + UNITS + ")", "g");
  var LEADING_UNIT = new RegExp("^([ \\t\\n]*)(" + UNITS + ")");

  function joinRun(units) {
    return units.replace(/[ \t\n]+/g, UNIT_SPACE);
  }

  /** Prose with every number joined to its unit by no-break spaces: "at 50 m s⁻¹" ->
   *  "at 50\u00a0m\u00a0s⁻¹". afterNumber: a unit at the very start follows a number. */
  function joinUnits(text, afterNumber) {
    text = String(text).replace(VALUE_WITH_UNIT, function (m, number, space, units) {
      return number.replace(/(\d) (?=\d{3})/g, "$1" + GROUP).replace(/ /g, UNIT_SPACE) + UNIT_SPACE + joinRun(units);
    });
    if (afterNumber)
      text = text.replace(LEADING_UNIT, function (m, space, units) {
        return (space ? UNIT_SPACE : "") + joinRun(units);
      });
    return text;
  }

  var api = {
    formatNumber: formatNumber,
    formatQuantity: formatQuantity,
    unitText: unitText,
    joinUnits: joinUnits,
    MINUS: MINUS,
    GROUP: GROUP,
    UNIT_SPACE: UNIT_SPACE,
  };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.Notation = api;
})(this);
