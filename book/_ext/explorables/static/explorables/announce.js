/* What an explorable says to a screen reader (issue 28): the directive's paragraph on what it
 * models, which the panel names with aria-describedby, and one polite live region that says
 * in words what a reader's change did: "Mass of the skydiver 70 kilograms. Terminal velocity,
 * falling freely 50.0 m s⁻¹." Numbers are the read-outs' own text (notation.js).
 * ui.js calls Explorables.speakFor(container) once an explorable is built. */
(function () {
  "use strict";
  var X = window.Explorables;
  var Notation = window.Notation;

  // At most one announcement per ANNOUNCE_GAP_MS while a control moves, and one more (the
  // whole change since the control was picked up) once it has been still that long.
  var ANNOUNCE_GAP_MS = 500;

  function now() {
    return window.performance.now();
  }

  /** Every visible read-out and announced note of `container`: a Map from element to
   *  {key, spoken}. Read-outs are <output data-label> ("Terminal velocity 52 m s⁻¹", with
   *  data-unit when the text has no unit); notes are [data-announce] paragraphs, compared by
   *  their data-announce key (or their text) and said when they have text. */
  function readState(container) {
    var state = new Map();
    container.querySelectorAll("output[data-label], [data-announce]").forEach(function (node) {
      if (node.closest("[hidden]")) return;
      var text = node.textContent.trim();
      if (node.tagName === "OUTPUT") {
        if (node.getAttribute("data-value") === "") return; // no value: the notes say why
        var unit = node.getAttribute("data-unit");
        text =
          node.getAttribute("data-label") + " " + text + (unit ? Notation.UNIT_SPACE + Notation.unitText(unit) : "");
        state.set(node, { key: text, spoken: text });
      } else state.set(node, { key: node.getAttribute("data-announce") || text, spoken: text });
    });
    return state;
  }

  /** Polite announcements, in words, of what a reader's change did (issue 28): the control's
   *  new value ("Mass of the skydiver 70 kilograms") and each read-out that changed. */
  function Announcer(container) {
    this.container = container;
    this.element = X.el("p", { class: "ex-sr ex-announcer", "aria-live": "polite", "aria-atomic": "true" });
    this.said = readState(container); // what the reader has heard (or saw on arrival)
    this.start = null; // the state when the control was picked up
    this.subject = null;
    this.moved = false;
    this.lastInput = -Infinity;
    this.lastSaid = -Infinity;
    this.timer = null;
    var self = this;
    function heard(event) {
      self.heard(event.target);
    }
    // "input" only: sliders, number boxes and radio buttons all send it for each change (a
    // number box's "change" on leaving it would repeat what was said)
    container.addEventListener("input", heard);
    container.addEventListener("click", function (event) {
      if (event.target.closest("button")) self.heard(null);
    });
  }

  /** What a control is now, in words: a slider or its number box as "Mass of the skydiver
   *  70 kilograms" (its printed label and the slider's aria-valuetext, ui.js's Quantity), a radio
   *  button by its label; a button (the skydiver's "Go to") names no value: null. */
  function subjectOf(control) {
    var quantity = control && control.closest(".ex-quantity");
    if (quantity) {
      var slider = quantity.querySelector("input[type=range]");
      return quantity.querySelector("label").firstChild.textContent + " " + slider.getAttribute("aria-valuetext");
    }
    if (control && control.type === "radio" && control.labels && control.labels[0])
      return control.labels[0].textContent;
    return null;
  }

  /** A control changed: say so at once if nothing was said lately, else when the gap is up. */
  Announcer.prototype.heard = function (control) {
    this.subject = subjectOf(control);
    this.moved = true;
    this.lastInput = now();
    if (!this.start) this.start = this.said;
    if (!this.timer && now() - this.lastSaid >= ANNOUNCE_GAP_MS) this.say(this.said);
    this.wake();
  };

  Announcer.prototype.wake = function () {
    if (this.timer) return;
    var self = this;
    var wait = Math.max(this.lastSaid, this.lastInput) + ANNOUNCE_GAP_MS - now();
    this.timer = setTimeout(
      function () {
        self.tick();
      },
      Math.ceil(Math.max(0, wait)) + 1, // a timer may round down: never sooner than the gap
    );
  };

  Announcer.prototype.tick = function () {
    this.timer = null;
    if (now() - this.lastInput >= ANNOUNCE_GAP_MS) {
      // still: the final value and everything that changed since the control was picked up
      var text = this.words(this.start);
      this.start = null;
      this.moved = false;
      if (text && text !== this.element.textContent) this.speak(text);
      else this.said = readState(this.container); // heard already, in the last announcement
      // the control is still and its last word said (what a test of the announcements waits for)
      this.element.dispatchEvent(new CustomEvent("announcer-settled"));
      return;
    }
    if (this.moved) this.say(this.said);
    this.wake();
  };

  /** Say the subject's value and what differs from `since`. */
  Announcer.prototype.say = function (since) {
    this.moved = false;
    var text = this.words(since);
    if (text) this.speak(text);
  };

  Announcer.prototype.speak = function (text) {
    this.said = readState(this.container);
    this.lastSaid = now();
    this.element.textContent = text;
  };

  Announcer.prototype.words = function (since) {
    var parts = [];
    if (this.subject) parts.push(this.subject.trim());
    readState(this.container).forEach(function (item, node) {
      var before = since.get(node);
      if (item.spoken && (!before || before.key !== item.key)) parts.push(item.spoken);
    });
    return Notation.joinUnits(
      parts
        .map(function (part) {
          return /[.!?]$/.test(part) ? part : part + ".";
        })
        .join(" "),
    );
  };

  /** Put the directive's "what it models" paragraph under the title, as the panel's description. */
  function describe(container) {
    var about = container.querySelector(".ex-about"),
      panel = container.querySelector(".ex-panel");
    if (!about || !panel) return;
    var title = panel.querySelector(".ex-title");
    panel.insertBefore(about, title ? title.nextSibling : panel.firstChild);
    panel.setAttribute("aria-describedby", about.id);
  }

  /** Give a built explorable its description and its live region. */
  X.speakFor = function (container) {
    describe(container);
    var panel = container.querySelector(".ex-panel") || container;
    panel.appendChild(new Announcer(container).element);
  };
})();
