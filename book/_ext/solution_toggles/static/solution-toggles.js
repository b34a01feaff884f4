/* The header of a worked example's solution is the whole toggle (book/_ext/solution_toggles).
 * sphinx-togglebutton has already put its chevron <button class="toggle-button"> in the
 * header; the link back to the question goes, and the button takes the whole header with a
 * name that says what it opens: "Show the solution to Example 2" ("Hide ..." when open). */
(function () {
  "use strict";

  function exampleName() {
    var heading = document.querySelector("main h1, article h1, h1");
    var match = heading && /Example\s+(\d+)/.exec(heading.textContent);
    return match ? "Example " + match[1] : null;
  }

  function setUp(solution, fallback) {
    var title = solution.querySelector(":scope > .admonition-title");
    var button = title && title.querySelector(".toggle-button");
    if (!button || button.hasAttribute("data-solution-toggle")) return;
    var link = title.querySelector("a");
    var exercise = link ? /Exercise\s+\d+/.exec(link.textContent) : null;
    var what = fallback || (exercise ? exercise[0] : "this example");
    // the header holds only the button now: no link to click by mistake
    Array.prototype.slice.call(title.childNodes).forEach(function (node) {
      if (node !== button) title.removeChild(node);
    });
    var label = document.createElement("span");
    label.className = "solution-toggle-label";
    button.insertBefore(label, button.firstChild);
    button.removeAttribute("aria-label"); // the name is the visible text
    button.setAttribute("aria-controls", solution.id);
    button.setAttribute("data-solution-toggle", "");
    function name() {
      var open = !solution.classList.contains("toggle-hidden");
      label.textContent = (open ? "Hide" : "Show") + " the solution to " + what;
    }
    name();
    new MutationObserver(name).observe(solution, { attributes: true, attributeFilter: ["class"] });
  }

  function start() {
    var fallback = exampleName();
    Array.prototype.forEach.call(document.querySelectorAll(".solution.dropdown"), function (solution) {
      setUp(solution, fallback);
    });
  }

  // togglebutton.js adds its buttons when the document is parsed (at once if deferred, on
  // DOMContentLoaded otherwise): try now and at each later moment; setUp runs once a header.
  start();
  document.addEventListener("DOMContentLoaded", start);
  window.addEventListener("load", start);
})();
