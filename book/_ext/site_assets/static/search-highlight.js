/* A page opened from a search result (?highlight=word) marks the word where it stands, with
 * Sphinx's own scripts (doctools.js, sphinx_highlight.js). Every other visit skips them: they
 * weigh 3.6 kB gzip and do nothing else here (page_context.py leaves them out of the page). */
(function () {
  "use strict";
  if (!/[?&]highlight=/.test(window.location.search)) return;
  var root = document.documentElement.getAttribute("data-content_root") || "";
  ["doctools.js", "sphinx_highlight.js"].forEach(function (name) {
    var script = document.createElement("script");
    script.src = root + "_static/" + name;
    script.async = false; // in this order: the highlighter uses doctools' words
    document.head.appendChild(script);
  });
})();
