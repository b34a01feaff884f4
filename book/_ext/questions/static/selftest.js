/* Definitions to learn, tested: a box of definitions (an admonition with class "self-test",
 * a list of "**Term:** definition") becomes cards. The student hides the definitions, says
 * each one, reveals it and marks it known or not yet. Native buttons only: it works by
 * keyboard. Plain JavaScript, offline.
 *
 * Storage: with the rest of the student's progress, in the progress store (progress-store.js,
 * format 2): ProgressStore.recordDefinition keeps each mark in definitions.cards ({slug: {mark,
 * at}}, mark "known" or "not-yet") and as an attempt at the card "definition:SLUG", which the
 * spaced review (schedule.js) rates. slug is the term in lower case with hyphens
 * ("newton-s-first-law"); the build names the cards the same way (questions/progress.py).
 *
 * One card: PAGE?card=SLUG (Your practice's Start, review.js) opens the test at that card. A
 * mark dispatches a bubbling "st-marked" event ({slug, known}) from the card. */
(function (root) {
  "use strict";

  var MARKS = { known: "Known", "not-yet": "Not yet" };

  function slug(term) {
    return term
      .toLowerCase()
      .replace(/[^a-z0-9]+/g, "-")
      .replace(/^-|-$/g, "");
  }

  /* The cards' marks in a progress object (format 2): {slug: {mark, at}}; {} when none. */
  function readCards(progress) {
    var d = progress && progress.definitions;
    return d && d.cards && typeof d.cards === "object" ? d.cards : {};
  }

  var api = { slug: slug, readCards: readCards };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.DefinitionsSelfTest = api;

  if (typeof document === "undefined" || !root.ProgressStore) return;
  var Store = root.ProgressStore;

  function stored() {
    var read = Store.load();
    return read.ok ? read.progress : null;
  }

  /* One list item made a card: its definition in a span that hides, and its controls
   * (reveal, the two marks, what is kept). */
  function makeCard(item, i, index) {
    var paragraph = item.querySelector("p") || item;
    var strong = paragraph.querySelector("strong");
    var term = strong ? strong.textContent.replace(/:\s*$/, "").trim() : "Definition " + (i + 1);
    var definition = document.createElement("span");
    definition.className = "st-definition";
    definition.id = "st-" + index + "-" + i;
    var node = strong ? strong.nextSibling : paragraph.firstChild;
    while (node) {
      var next = node.nextSibling;
      definition.appendChild(node);
      node = next;
    }
    paragraph.appendChild(definition);
    var controls = document.createElement("span");
    controls.className = "st-controls";
    controls.hidden = true;
    controls.innerHTML =
      '<span class="st-say">Say it, then </span>' +
      '<button type="button" class="st-reveal" aria-expanded="false"></button>' +
      '<span class="st-marking" hidden><button type="button" class="st-mark" data-mark="known" aria-pressed="false">' +
      'I knew it</button><button type="button" class="st-mark" data-mark="not-yet" aria-pressed="false">' +
      "Not yet</button></span>" +
      '<span class="st-kept"></span>';
    item.appendChild(controls);
    var reveal = controls.querySelector(".st-reveal");
    var named = /^Newton/.test(term) ? term : term.charAt(0).toLowerCase() + term.slice(1);
    reveal.textContent = "Show the definition of " + named;
    reveal.setAttribute("aria-controls", definition.id);
    item.classList.add("st-card");
    item.id = "st-card-" + slug(term);
    return {
      item: item,
      key: slug(term),
      term: term,
      definition: definition,
      controls: controls,
      reveal: reveal,
      marking: controls.querySelector(".st-marking"),
      kept: controls.querySelector(".st-kept"),
      buttons: controls.querySelectorAll(".st-mark"),
    };
  }

  /* One box's test (test): its cards, its Test yourself toggle and its status line. */
  function render(test) {
    var marks = readCards(stored()),
      known = 0;
    test.cards.forEach(function (card) {
      var mark = marks[card.key] && marks[card.key].mark;
      if (mark === "known") known += 1;
      card.item.setAttribute("data-mark", mark || "");
      card.kept.textContent = MARKS[mark] ? " (" + MARKS[mark].toLowerCase() + ")" : "";
      Array.prototype.forEach.call(card.buttons, function (b) {
        b.setAttribute("aria-pressed", String(b.getAttribute("data-mark") === mark));
      });
    });
    test.status.textContent = "Known: " + known + " of " + test.cards.length + " definitions.";
  }

  function show(card, shown) {
    card.definition.hidden = !shown;
    card.reveal.setAttribute("aria-expanded", String(shown));
    card.reveal.hidden = shown;
    card.controls.querySelector(".st-say").hidden = shown;
    card.marking.hidden = !shown;
  }

  function toggleTesting(test) {
    var toggle = test.toggle;
    var testing = toggle.getAttribute("aria-pressed") !== "true";
    toggle.setAttribute("aria-pressed", String(testing));
    toggle.textContent = testing ? "Stop testing: show every definition" : "Test yourself: hide the definitions";
    test.box.classList.toggle("st-testing", testing);
    test.cards.forEach(function (card) {
      card.controls.hidden = !testing;
      show(card, !testing);
      if (!testing) card.marking.hidden = true;
    });
    if (testing) test.cards[0].reveal.focus();
  }

  // A mark given to card i: kept, shown, announced, and the focus on to the next card.
  function markCard(test, i, button) {
    var card = test.cards[i];
    var known = button.getAttribute("data-mark") === "known";
    if (!stored()) {
      test.status.textContent = "Your marks cannot be kept: the progress stored in this browser is in another format.";
      return;
    }
    if (!Store.recordDefinition(card.key, known, Date.now())) {
      test.status.textContent = "This browser does not let the page keep your marks (private mode?).";
      return;
    }
    render(test);
    card.item.dispatchEvent(new CustomEvent("st-marked", { bubbles: true, detail: { slug: card.key, known: known } }));
    var next = test.cards[i + 1];
    if (next && !next.controls.hidden) (next.reveal.hidden ? next.buttons[0] : next.reveal).focus();
    else test.toggle.focus();
  }

  function setUp(box, index) {
    var items = box.querySelectorAll(":scope > ul > li, :scope > ol > li");
    if (!items.length) return;
    var bar = box.querySelector(".st-bar"); // in the page (the build puts it there): no layout shift
    var test = {
      box: box,
      toggle: bar.querySelector(".st-toggle"),
      status: bar.querySelector(".st-status"),
      cards: Array.prototype.map.call(items, function (item, i) {
        return makeCard(item, i, index);
      }),
    };
    var cards = test.cards;
    test.toggle.addEventListener("click", function () {
      toggleTesting(test);
    });

    cards.forEach(function (card, i) {
      card.reveal.addEventListener("click", function () {
        show(card, true);
        card.buttons[0].focus();
      });
      Array.prototype.forEach.call(card.buttons, function (button) {
        button.addEventListener("click", function () {
          markCard(test, i, button);
        });
      });
    });

    window.addEventListener("storage", function (event) {
      if (event.key === Store.STORE || event.key === Store.OLD_STORE || event.key === null) render(test);
    });
    render(test);

    // One card asked for (?card=SLUG): the test opens, at that card.
    var asked = new URLSearchParams(location.search).get("card");
    var one = cards.filter(function (card) {
      return card.key === asked;
    })[0];
    if (one) {
      test.toggle.click();
      one.item.scrollIntoView({ block: "center" });
      one.reveal.focus({ preventScroll: true });
    }
  }

  function start() {
    Array.prototype.forEach.call(document.querySelectorAll(".admonition.self-test"), setUp);
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
