/* Offline after one visit: register the book's service worker (book/_ext/offline), and when
 * a new version of the book has been downloaded, say so and offer to reload. */
(function () {
  "use strict";
  if (!("serviceWorker" in navigator) || location.protocol === "file:") return; // a copy on disk

  var root = document.documentElement.getAttribute("data-content_root") || "./";
  var reloading = false;

  function offer(worker) {
    if (document.querySelector(".offline-update")) return;
    var notice = document.createElement("div");
    notice.className = "offline-update";
    notice.setAttribute("role", "status");
    var text = document.createElement("span");
    text.textContent = "A new version of this book is ready.";
    var button = document.createElement("button");
    button.type = "button";
    button.textContent = "Reload";
    button.addEventListener("click", function () {
      reloading = true;
      button.disabled = true;
      worker.postMessage("skip-waiting");
    });
    notice.appendChild(text);
    notice.appendChild(button);
    document.body.appendChild(notice);
  }

  navigator.serviceWorker.addEventListener("controllerchange", function () {
    if (reloading) location.reload(); // the new version took over at the student's request
  });

  // After the page has loaded: the book's files then download behind it, not before it.
  function register() {
    navigator.serviceWorker
      .register(root + "sw.js")
      .then(watch)
      .catch(function () {
        /* no service worker: the site works online as before */
      });
  }
  if (document.readyState === "complete") register();
  else window.addEventListener("load", register);

  function watch(registration) {
    if (registration.waiting && navigator.serviceWorker.controller) offer(registration.waiting);
    registration.addEventListener("updatefound", function () {
      var worker = registration.installing;
      worker.addEventListener("statechange", function () {
        // installed while an older version controls the page: a new version is waiting
        if (worker.state === "installed" && navigator.serviceWorker.controller) offer(worker);
      });
    });
    registration.update().catch(function () {
      /* offline: the next visit checks again */
    });
  }
})();
