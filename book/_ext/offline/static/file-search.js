/* Search in a copy of the book opened from disk (file://). Sphinx's search fetches each
 * result's page to show a snippet, and a browser refuses fetch() of a local file; here
 * those fetches are answered from _static/search-texts.js (each page's words, written by
 * book/_ext/offline), which a <script> element may load. Online this does nothing. */
(function () {
  "use strict";
  if (location.protocol !== "file:") return;
  var root = new URL(document.documentElement.getAttribute("data-content_root") || "./", location.href).href;
  var ready = new Promise(function (resolve) {
    var script = document.createElement("script");
    script.src = root + "_static/search-texts.js";
    script.onload = script.onerror = function () {
      resolve(window.SearchTexts || {});
    };
    document.head.appendChild(script);
  });
  var fetchFromNetwork = window.fetch;
  window.fetch = function (resource) {
    var url = new URL(typeof resource === "string" ? resource : resource.url, location.href);
    var page = url.href.split(/[?#]/)[0];
    if (page.indexOf(root) !== 0) return fetchFromNetwork.apply(window, arguments);
    var args = arguments;
    return ready.then(function (texts) {
      var text = texts[page.slice(root.length)];
      if (text === undefined) return fetchFromNetwork.apply(window, args);
      return new Response(text, { headers: { "Content-Type": "text/html; charset=utf-8" } });
    });
  };
})();
