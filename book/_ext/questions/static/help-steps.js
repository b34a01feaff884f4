/* Help before the answer: a numeric part's working, one step at a time, before the whole
 * worked answer. The steps come from what the question already stores: the part's revisit
 * hint, then its own mark lines, less the line that gives its final answer and any line
 * that gives its direction or holds its value, so that no step gives the answer away; an
 * earlier part's answer in a line reads "your answer to (a)".
 * The selection (steps) is pure and runs under Node for the tests; attach() is the page's:
 * a "Show a step" button and the list of the steps shown so far, under each part
 * (form.py writes them), the number shown kept per question and numbers. */
(function (root) {
  "use strict";

  var Reading = root.AnswerReading || require("./answer-reading.js");
  // a part's kind says whether it offers steps (static/question-kinds.js: helpSteps)
  var Kinds = root.QuestionKinds || require("./question-kinds.js");

  // A mark line's words: a power in a unit ("s<sup>−2</sup>") kept apart from the numbers.
  function plain(html) {
    return String(html)
      .replace(/<sup>(.*?)<\/sup>/g, "^($1)")
      .replace(/<[^>]*>/g, "")
      .replace(/&lt;/g, "<")
      .replace(/&gt;/g, ">")
      .replace(/&quot;/g, '"')
      .replace(/&#0?39;|&#x27;/g, "'")
      .replace(/&amp;/g, "&");
  }

  // A number as the book prints it: digit groups (80 000), a decimal point, × 10ⁿ.
  var NUMBER =
    /(\^\(?[\u2212-]?)?(\d{1,3}(?:[ \u202f]\d{3})+(?:\.\d+)?|\d+(?:\.\d+)?|\.\d+)(\s*×\s*10(?:[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+|\^\([\u2212-]?\d+\)))?/g;

  function numbersIn(text) {
    var found = [],
      match;
    NUMBER.lastIndex = 0;
    while ((match = NUMBER.exec(text))) {
      if (match[1]) continue; // a unit's power
      var number = Reading.parseNumber(match[2].replace(/[ \u202f]/g, "") + (match[3] || ""));
      if (number.ok) found.push(number);
    }
    return found;
  }

  /* Does a number, as written, give a value away: the value rounds to it at its own last
   * digit, with 2 or more significant figures (a 1 s.f. "2" says little about 2.4)? */
  function gives(number, value) {
    for (var sf = Math.max(2, number.sfMin); sf <= number.sfMax; sf++) {
      var half = 0.5 * Math.pow(10, number.lead - sf + 1);
      if (Math.abs(Math.abs(number.value) - Math.abs(value)) <= half * (1 + 1e-9)) return true;
    }
    return false;
  }

  // A number in a mark line's HTML, with the minus sign before it: not a power (<sup>), nor
  // the digits of a character reference (&#39;).
  var HTML_NUMBER =
    /(<sup>[\u2212-]?|&#x?)?([\u2212-])?(\d{1,3}(?:[ \u202f]\d{3})+(?:\.\d+)?|\d+(?:\.\d+)?|\.\d+)(\s*×\s*10(?:[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+|<sup>[\u2212-]?\d+<\/sup>))?/g;

  /* A later part's line with each earlier part's answer in it put as "your answer to (a)":
   * help on (c) must not give away (a) and (b) (the mark scheme's line for (c) works from
   * their keys). earlier: the parts before this one that have a value. A given of the
   * earlier part's unit with its value is that answer (the mass in (a), the same on the
   * Moon); a given of another unit with its value (a 3.0 kg mass where (a) is 3.0 m s⁻¹)
   * leaves the number in doubt, so the line is no step (null): it would either give (a)
   * away or call the mass "your answer to (a)". */
  function withoutEarlier(html, earlier, givens) {
    var doubt = false;
    var out = html.replace(HTML_NUMBER, function (all, skip, minus, digits, power, at) {
      if (skip) return all;
      var number = Reading.parseNumber(
        digits.replace(/[ \u202f]/g, "") + (power || "").replace(/<sup>(.*?)<\/sup>/, "^($1)"),
      );
      if (!number.ok) return all;
      var unit = (html.slice(at + all.length).match(UNIT_AFTER) || [])[1];
      var matching = earlier.filter(function (p) {
        // a number with a unit of its own (0.90 J) is not an answer in another unit
        if (unit && String(p.unit).split(" ")[0] !== unit) return false;
        // an earlier answer of 1 s.f. (a reading of −0.5 N s) is given away by itself too
        return answersOf(p).some(function (value) {
          return typeof value === "number" && value !== 0 && (gives(number, value) || same(number, value));
        });
      });
      // of two answers of one size (0.6 and −0.6 N s), the one with the sign written
      var part =
        matching.filter(function (p) {
          return !minus === p.value > 0;
        })[0] || matching[0];
      if (!part) return all;
      doubt =
        doubt ||
        givens.some(function (given) {
          return (
            given.unit !== part.unit && given.value !== 0 && (gives(number, given.value) || same(number, given.value))
          );
        });
      // a minus sign that is the answer's own sign goes with it; a subtraction's stays
      var sign = minus && part.value > 0 ? minus : "";
      return sign + "your answer to (" + part.id + ")";
    });
    return doubt ? null : out;
  }

  // The unit written after a number in a mark line ("0.90 J", "2.4 N s"): its first symbol.
  var UNIT_AFTER = /^\s*(kg|g|m|s|N|J|W|kW|Pa|cm|mm|km|ms|rad|°)(?![A-Za-z])/;

  function same(number, value) {
    return Math.abs(Math.abs(number.value) - Math.abs(value)) <= 1e-9 * Math.abs(value);
  }

  // The values that answer a part: its key and the values its scheme also accepts.
  function answersOf(part) {
    return [part.value].concat(
      (part.alternatives || []).map(function (alt) {
        return alt.value;
      }),
    );
  }

  function lastIndex(list, test) {
    for (var i = list.length - 1; i >= 0; i--) if (test(list[i])) return i;
    return -1;
  }

  /* A part's steps, in order: [{text}] for its revisit hint, [{html}] for a mark line. A part
   * that is not numeric (or a graph's reading) has none. */
  function steps(data, part) {
    if (!Kinds.of(part).helpSteps) return [];
    var lines = data.marks.filter(function (m) {
      return m.part === part.id;
    });
    // the line that gives the final answer: the part's last A1 (else its last answer line)
    var final = lastIndex(lines, function (m) {
      return m.code === "A1";
    });
    if (final < 0) {
      final = lastIndex(lines, function (m) {
        return m.roles.indexOf("answer") >= 0;
      });
    }
    var answers = answersOf(part);
    var before = data.parts.map(function (p) {
      return p.id;
    });
    var earlier = data.parts.slice(0, before.indexOf(part.id)).filter(function (p) {
      return !!Kinds.of(p).helpSteps && typeof p.value === "number" && p.value !== 0;
    });
    var out = part.revisit ? [{ text: part.revisit }] : [];
    lines.forEach(function (m, i) {
      if (i === final || m.roles.indexOf("direction") >= 0) return;
      var holds = numbersIn(plain(m.html)).some(function (number) {
        return answers.some(function (value) {
          return typeof value === "number" && value !== 0 && gives(number, value);
        });
      });
      var html = holds ? null : withoutEarlier(m.html, earlier, data.givens || []);
      if (html !== null) out.push({ html: html });
    });
    return out;
  }

  function count(shown) {
    return Object.keys(shown).reduce(function (sum, id) {
      return sum + shown[id];
    }, 0);
  }

  /* The page's side, for one question's form. keep: {load(id), save(id, value)}, the
   * question's own memory (questions.js). show(data, id, fresh) puts the steps of these
   * numbers in place (id: where their help is kept; fresh: new numbers, so no help yet);
   * used() is how many steps were shown on these numbers, all parts. */
  function attach(form, keep) {
    var data = null,
      id = null,
      shown = {};

    function parts() {
      return data.parts.filter(function (part) {
        return form.querySelector('[data-part="' + part.id + '"] .q-help');
      });
    }

    function draw(part, focus) {
      var help = form.querySelector('[data-part="' + part.id + '"] .q-help');
      var list = help.querySelector(".q-steps"),
        button = help.querySelector("button.q-step");
      var all = steps(data, part),
        n = Math.min(shown[part.id] || 0, all.length);
      while (list.children.length > n) list.removeChild(list.lastChild);
      for (var i = list.children.length; i < n; i++) {
        var item = document.createElement("li");
        if (all[i].html) item.innerHTML = all[i].html;
        else {
          item.className = "q-step-hint";
          item.textContent = all[i].text;
        }
        list.appendChild(item);
      }
      var left = all.length - n;
      button.textContent = "Show a step (" + left + " left)";
      button.hidden = left === 0;
      // the last step shown: on to the answer boxes, as the button is gone
      if (focus && left === 0) form.querySelector('[data-part="' + part.id + '"] .q-value').focus();
    }

    form.addEventListener("click", function (event) {
      var button = event.target.closest && event.target.closest("button.q-step");
      if (!button || !data) return;
      var partId = button.closest("[data-part]").getAttribute("data-part");
      var part = data.parts.filter(function (p) {
        return p.id === partId;
      })[0];
      shown[partId] = (shown[partId] || 0) + 1;
      keep.save(id, { shown: shown });
      draw(part, true);
    });

    return {
      show: function (newData, newId, fresh) {
        data = newData;
        id = newId;
        shown = fresh ? {} : Object.assign({}, (keep.load(id) || {}).shown);
        if (fresh) keep.save(id, { shown: shown });
        parts().forEach(function (part) {
          draw(part, false);
        });
      },
      used: function () {
        return count(shown);
      },
    };
  }

  var api = { steps: steps, plain: plain, numbersIn: numbersIn, attach: attach };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.HelpSteps = api;
})(this);
