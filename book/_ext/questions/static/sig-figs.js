/* The engine's one judge of significant figures: is a typed number the key to enough figures,
 * or the key rounded to too few? Every number of the rule (the figures the A1 needs, the
 * figures the key is trusted to, the fewest that count as too few, how a whole number's zeros
 * count) is the rule table's (physics_figures/marking_rules.json "sig_figs"), passed in. Its
 * Python twin is physics_figures.marking.judge_sig_figs; tests/fixtures/sig_fig_cases.json runs
 * through both. */
(function (root) {
  "use strict";

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

  function leadingPlace(x) {
    return Math.floor(Math.log10(Math.abs(x)) + 1e-12);
  }

  /* Is value the target rounded to sf significant figures (60 for 56.0 at 1 s.f.; not 10 for 7.5)? */
  function roundsTo(value, target, sf) {
    var place = leadingPlace(target) - sf + 1,
      scaled = value / Math.pow(10, place);
    return (
      steps(Math.abs(target), place).some(function (n) {
        return Math.abs(Math.abs(scaled) - n) < 1e-7 * Math.max(1, n);
      }) && value < 0 === target < 0
    );
  }

  /* Equal to the target at the typed last figure, at some reading of its figures (minSf or more),
   * where that figure is no coarser than the target's minSf-th ("1.0" is 0.97 to 1 s.f., not 2)
   * and never finer than its checkSf-th (the key is trusted that far, so rounding intermediate
   * values to 3 s.f. still passes). */
  function equalAtItsFigures(number, target, minSf, checkSf) {
    var targetLead = leadingPlace(target);
    for (var sf = number.sfMax; sf >= Math.max(number.sfMin, minSf); sf--) {
      var place = Math.max(number.lead - sf + 1, targetLead - checkSf + 1);
      if (place <= targetLead - minSf + 1 && stepsApart(number.value, target, place) === 0) return true;
    }
    return false;
  }

  /* The target rounded to minSf or more figures where rounding carries into a new digit
   * ("1.0" for 0.997 to 2 s.f.), written with that many figures. */
  function carriedRounding(number, target, minSf, checkSf) {
    if (Math.abs(number.value) < Math.pow(10, leadingPlace(target) + 1)) return false;
    for (var more = minSf; more <= checkSf; more++) {
      if (number.sfMin <= more && more <= number.sfMax && roundsTo(number.value, target, more)) return true;
    }
    return false;
  }

  /* Compare a typed number with a target (in the same unit). match: right to minSf or more.
   * matchFewSf: the key rounded to fewer figures than the A1 needs, from the rule table's
   * fewest, however many zeros follow it (60, 60. and 6.0e1 for 64 are each 64 to 1 s.f.): too
   * few figures, not wrong physics; fewSf: the most figures it is the key to. */
  function compare(number, target, minSf, checkSf, fewest) {
    var result = { match: false, matchFewSf: false };
    if (target === 0) {
      result.match = number.value === 0; // zero has no significant figures
      return result;
    }
    result.match = equalAtItsFigures(number, target, minSf, checkSf) || carriedRounding(number, target, minSf, checkSf);
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

  var judge = { compare: compare, fewSfMessage: fewSfMessage, countedZeros: countedZeros, roundsTo: roundsTo };
  if (typeof module === "object" && module.exports) module.exports = judge;
  else root.SigFigs = judge;
})(this);
