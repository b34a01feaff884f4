/* Spaced review: when each card (a template, or a definition of the self-test) is due again,
 * worked out by FSRS (ts-fsrs, the scheduler Anki uses, vendored as _static/ts-fsrs.js) from
 * the ratings the store gave the student's attempts (progress-store.js). ts-fsrs defaults with
 * request retention 0.9 (CLARIFICATIONS, Plan). Only the pages that plan load this and ts-fsrs.
 *
 * The schedule is a replay of every attempt in time order, so it follows the record: an
 * imported file's attempts, or a later build's, give the same due dates again. */
(function (root) {
  "use strict";

  var FSRS = root.FSRS || require("ts-fsrs");
  var Store = root.ProgressStore || require("./progress-store.js");

  var REQUEST_RETENTION = 0.9;

  function scheduler() {
    return FSRS.fsrs(FSRS.generatorParameters({ request_retention: REQUEST_RETENTION }));
  }

  // A card as the store keeps it: plain JSON, times in ms.
  function plain(card) {
    var out = {};
    Object.keys(card).forEach(function (field) {
      var value = card[field];
      out[field] = value instanceof Date ? value.getTime() : value;
    });
    return out;
  }

  /* {cardId: card}: each card's FSRS state after all its reviews (due, stability, state...). */
  function replay(progress) {
    var f = scheduler(),
      out = {};
    Store.cards(progress).forEach(function (c) {
      var card = FSRS.createEmptyCard(new Date(c.reviews[0].at));
      c.reviews.forEach(function (review) {
        card = f.next(card, new Date(review.at), review.rating).card;
      });
      out[c.id] = plain(card);
    });
    return out;
  }

  // The end of the student's day (local midnight to come): "due today" runs until then.
  function endOfDay(now) {
    var day = new Date(now);
    day.setHours(24, 0, 0, 0);
    return day.getTime();
  }

  // FSRS's states: a card in its learning or relearning steps comes back in minutes.
  var REVIEW = 2;

  /* Every reviewed card, soonest due first: [{id, type, due, state, reps, today, soon}].
   * today: to do today, as a student expects: due already, or a review (an interval of days)
   * that falls due before the day ends (as Anki, a day's reviews can be done in the morning).
   * soon: a card in its learning steps (again in 1 or 10 minutes, FSRS's steps) that comes
   * back later today: not due yet, and not "due today". The schedule is replayed, so it is
   * never stale. */
  function cardsByDue(progress, now) {
    var schedule = replay(progress),
      until = endOfDay(now);
    return Store.cards(progress)
      .map(function (c) {
        var card = schedule[c.id];
        var today = card.due <= now || (card.due < until && card.state === REVIEW);
        return {
          id: c.id,
          type: c.type,
          due: card.due,
          state: card.state,
          reps: card.reps,
          today: today,
          soon: !today && card.due < until,
        };
      })
      .sort(function (a, b) {
        return a.due - b.due;
      });
  }

  /* When a card that is coming back later today returns, as a student reads it: "in 5
   * minutes" (a part minute counts as a whole one), else "at 14:05" (the local time). */
  function backText(due, now) {
    var minutes = Math.ceil((due - now) / 60000);
    if (minutes < 60) return "in " + minutes + (minutes === 1 ? " minute" : " minutes");
    var at = new Date(due);
    return "at " + at.getHours() + ":" + (at.getMinutes() < 10 ? "0" : "") + at.getMinutes();
  }

  function due(progress, now) {
    return cardsByDue(progress, now).filter(function (c) {
      return c.today;
    });
  }

  var api = {
    REQUEST_RETENTION: REQUEST_RETENTION,
    replay: replay,
    cardsByDue: cardsByDue,
    due: due,
    endOfDay: endOfDay,
    backText: backText,
  };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.Schedule = api;
})(this);
