/* Start's review, on the pages that serve its cards (a question's page, the self-test's): the
 * card being served says "Card 2 of 7" at its top from the start; after its Check
 * (questions.js's "q-checked") or its self-test mark (selftest.js's "st-marked"), a line
 * below it offers the next card, or, after the last, the way back to Your practice. The queue
 * is progress-plan.js's, in localStorage ProgressStore.KEYS.review ({home, position, cards: [{id,
 * type, url}]}). Plain JavaScript, offline. */
(function () {
  "use strict";

  var QUEUE = window.ProgressStore.KEYS.review;
  var DEFINITION = "definition:";

  /* The queue this page was sent with (from disk, the link carries it: progress-plan.js's
   * carried), kept in this page's storage too; else the stored one. */
  function read() {
    try {
      var sent = new URLSearchParams(location.search).get("review");
      var queue = JSON.parse(sent || localStorage.getItem(QUEUE));
      if (sent) keep(queue);
      return queue && queue.version === 1 && Array.isArray(queue.cards) ? queue : null;
    } catch {
      return null;
    }
  }

  function keep(queue) {
    try {
      localStorage.setItem(QUEUE, JSON.stringify(queue));
    } catch {
      /* private mode: the links still carry it on */
    }
  }

  function carried(url, queue) {
    if (location.protocol !== "file:") return url;
    var to = new URL(url, location.href);
    to.searchParams.set("review", JSON.stringify(queue));
    return to.href;
  }

  function start() {
    var queue = read();
    var card = queue && queue.cards[queue.position];
    if (!card || new URL(card.url, location.href).pathname !== location.pathname) return;
    var definition = card.id.indexOf(DEFINITION) === 0;
    var slug = card.id.slice(DEFINITION.length);
    var place = definition
      ? document.getElementById("st-card-" + slug)
      : document.querySelector('form.q-form[data-question="' + CSS.escape(card.id) + '"]');
    if (!place) return;
    if (!definition) place = place.closest("section.q") || place;
    var which = "Card " + (queue.position + 1) + " of " + queue.cards.length;
    var top = document.createElement("p");
    top.className = "rv-count";
    top.textContent = which;
    place.insertAdjacentElement("afterbegin", top);

    function show() {
      var last = queue.position + 1 >= queue.cards.length;
      var bar = document.querySelector(".rv-bar") || document.createElement("p");
      bar.className = "rv-bar";
      bar.textContent = which + " · ";
      var go = document.createElement("a");
      go.className = "rv-next";
      var next = Object.assign({}, queue, { position: queue.position + 1 }); // the last one done: used up
      go.href = last ? queue.home : carried(queue.cards[next.position].url, next);
      go.textContent = last ? "Back to Your practice" : "Next card";
      go.addEventListener("click", function () {
        keep(next);
      });
      bar.appendChild(go);
      place.insertAdjacentElement(definition ? "beforeend" : "afterend", bar);
    }

    document.addEventListener(definition ? "st-marked" : "q-checked", function (event) {
      if (definition ? event.detail.slug === slug : place.contains(event.target)) show();
    });
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
