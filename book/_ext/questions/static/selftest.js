/* Definitions to learn, tested: a box of definitions (an admonition with class "self-test",
 * a list of "**Term:** definition") becomes cards. The student hides the definitions, says
 * each one, reveals it and marks it known or not yet. Native buttons only: it works by
 * keyboard. Plain JavaScript, offline.
 *
 * Storage: with the rest of the student's progress, in localStorage "dynamics-progress-v1"
 * (questions.js, progress.js), as a versioned field of that object:
 *   {version: 1, attempts: [...], definitions: {version: 1, cards: {slug: {mark, at}}}}
 * mark is "known" or "not-yet"; slug is the term in lower case with hyphens ("newton-s-first-law").
 * A store of another version (or a definitions field of another version) is left untouched. */
(function (root) {
  "use strict";

  var STORE = "dynamics-progress-v1";
  var VERSION = 1; // of the definitions field
  var MARKS = { known: "Known", "not-yet": "Not yet" };

  function slug(term) {
    return term
      .toLowerCase()
      .replace(/[^a-z0-9]+/g, "-")
      .replace(/^-|-$/g, "");
  }

  /* The cards' marks kept in this browser: {slug: {mark, at}}; {} when none or unreadable. */
  function readCards(text) {
    try {
      var progress = JSON.parse(text);
      var d = progress && progress.version === 1 && progress.definitions;
      return d && d.version === VERSION && d.cards && typeof d.cards === "object" ? d.cards : {};
    } catch {
      return {};
    }
  }

  /* The store with one card's mark set (text), or null when the store is not one to write into. */
  function withMark(text, key, mark, at) {
    var progress;
    try {
      progress = text ? JSON.parse(text) : { version: 1, attempts: [] };
    } catch {
      return null;
    }
    if (!progress || progress.version !== 1 || !Array.isArray(progress.attempts)) return null;
    var d = progress.definitions;
    if (d === undefined) d = progress.definitions = { version: VERSION, cards: {} };
    if (!d || d.version !== VERSION || typeof d.cards !== "object") return null;
    d.cards[key] = { mark: mark, at: at };
    return JSON.stringify(progress);
  }

  var api = { slug: slug, readCards: readCards, withMark: withMark };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.DefinitionsSelfTest = api;

  if (typeof document === "undefined") return;

  function stored() {
    try {
      return localStorage.getItem(STORE);
    } catch {
      return null;
    }
  }

  function setUp(box, index) {
    var items = box.querySelectorAll(":scope > ul > li, :scope > ol > li");
    if (!items.length) return;
    var bar = box.querySelector(".st-bar"); // in the page (the build puts it there): no layout shift
    var toggle = bar.querySelector(".st-toggle");
    var status = bar.querySelector(".st-status");

    var cards = Array.prototype.map.call(items, function (item, i) {
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
    });

    function render() {
      var marks = readCards(stored()),
        known = 0;
      cards.forEach(function (card) {
        var mark = marks[card.key] && marks[card.key].mark;
        if (mark === "known") known += 1;
        card.item.setAttribute("data-mark", mark || "");
        card.kept.textContent = MARKS[mark] ? " (" + MARKS[mark].toLowerCase() + ")" : "";
        Array.prototype.forEach.call(card.buttons, function (b) {
          b.setAttribute("aria-pressed", String(b.getAttribute("data-mark") === mark));
        });
      });
      status.textContent = "Known: " + known + " of " + cards.length + " definitions.";
    }

    function show(card, shown) {
      card.definition.hidden = !shown;
      card.reveal.setAttribute("aria-expanded", String(shown));
      card.reveal.hidden = shown;
      card.controls.querySelector(".st-say").hidden = shown;
      card.marking.hidden = !shown;
    }

    toggle.addEventListener("click", function () {
      var testing = toggle.getAttribute("aria-pressed") !== "true";
      toggle.setAttribute("aria-pressed", String(testing));
      toggle.textContent = testing ? "Stop testing: show every definition" : "Test yourself: hide the definitions";
      box.classList.toggle("st-testing", testing);
      cards.forEach(function (card) {
        card.controls.hidden = !testing;
        show(card, !testing);
        if (!testing) card.marking.hidden = true;
      });
      if (testing) cards[0].reveal.focus();
    });

    cards.forEach(function (card, i) {
      card.reveal.addEventListener("click", function () {
        show(card, true);
        card.buttons[0].focus();
      });
      Array.prototype.forEach.call(card.buttons, function (button) {
        button.addEventListener("click", function () {
          var text = withMark(stored(), card.key, button.getAttribute("data-mark"), Date.now());
          if (text === null) {
            status.textContent = "Your marks cannot be kept: the progress stored in this browser is in another format.";
            return;
          }
          try {
            localStorage.setItem(STORE, text);
          } catch {
            status.textContent = "This browser does not let the page keep your marks (private mode?).";
            return;
          }
          render();
          var next = cards[i + 1];
          if (next && !next.controls.hidden) (next.reveal.hidden ? next.buttons[0] : next.reveal).focus();
          else toggle.focus();
        });
      });
    });

    window.addEventListener("storage", function (event) {
      if (event.key === STORE || event.key === null) render();
    });
    render();
  }

  function start() {
    Array.prototype.forEach.call(document.querySelectorAll(".admonition.self-test"), setUp);
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
