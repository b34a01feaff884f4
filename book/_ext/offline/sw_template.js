/* The book's service worker, written by book/_ext/offline when the site is built. Every
 * page and every file a page uses is kept in a cache named for this build's contents, so
 * the book works offline after one visit, and a new build is a new cache.
 * The downloads (the book's PDFs, the teacher's kit and its Moodle file) stay out of that
 * first install (2 MB at most); each is kept once it has been opened (OPENED). */
"use strict";
var VERSION = "__VERSION__";
// The book's caches are named by its own prefix (physics_figures/topics.py storage_keys), so
// two books on one host never drop each other's.
var BOOK_CACHES = "__BOOK_CACHES__";
var CACHE = BOOK_CACHES + VERSION;
var PRECACHE = __PRECACHE__;
// Downloads opened online, for offline. Online, the network always answers (a rebuilt PDF
// replaces the kept one); a new build of the pages drops them with the old pages.
var OPENED = BOOK_CACHES + "opened-" + VERSION;
// Under the site's root (the worker's scope): the downloads offline/__init__.py leaves out of
// PRECACHE (NOT_PRECACHED), but the zip: the whole book, to keep on disk, not in a cache. The
// sheet builder's data (teachers/sheet-data.js, several hundred KB) is kept the same way, once
// a teacher has made sheets online; and the README its page links.
var KEPT_WHEN_OPENED = /^(pdf|teachers)\/[^/]+\.(pdf|xml|js|txt)$/;

self.addEventListener("install", function (event) {
  // cache: "reload" skips the browser's HTTP cache: a host that lets files be reused for a
  // while (GitHub Pages: 10 minutes) would otherwise fill the new cache with old files.
  event.waitUntil(
    caches.open(CACHE).then(function (cache) {
      return cache.addAll(
        PRECACHE.map(function (path) {
          return new Request(path, { cache: "reload" });
        }),
      );
    }),
  );
});

self.addEventListener("activate", function (event) {
  event.waitUntil(
    caches
      .keys()
      .then(function (names) {
        return Promise.all(
          names
            .filter(function (name) {
              return name.indexOf(BOOK_CACHES) === 0 && name !== CACHE && name !== OPENED;
            })
            .map(function (name) {
              return caches.delete(name);
            }),
        );
      })
      .then(function () {
        return self.clients.claim();
      }),
  );
});

// The page's Reload button (offline.js): this version takes over.
self.addEventListener("message", function (event) {
  if (event.data === "skip-waiting") self.skipWaiting();
});

// A download: the network first (a new PDF replaces the kept one), the kept copy offline. Only
// a whole file is kept: 200 (not a range's 206, which a cache refuses), not an opaque reply.
function networkFirst(event) {
  var request = event.request;
  return caches.open(OPENED).then(function (cache) {
    return fetch(request).then(
      function (response) {
        if (response.status === 200 && response.type !== "opaque") {
          event.waitUntil(cache.put(request, response.clone()));
        }
        return response;
      },
      function (offline) {
        return cache.match(request, { ignoreSearch: true }).then(function (kept) {
          if (kept) return kept;
          throw offline; // never opened online: the browser's own offline error
        });
      },
    );
  });
}

self.addEventListener("fetch", function (event) {
  var request = event.request;
  if (request.method !== "GET" || new URL(request.url).origin !== self.location.origin) return;
  var scope = new URL(self.registration.scope).pathname;
  var path = new URL(request.url).pathname;
  if (path.indexOf(scope) === 0 && KEPT_WHEN_OPENED.test(path.slice(scope.length))) {
    event.respondWith(networkFirst(event));
    return;
  }
  event.respondWith(
    caches.open(CACHE).then(function (cache) {
      // ?new=KEY, ?highlight=... and ?v=hash name the same file
      return cache.match(request, { ignoreSearch: true }).then(function (hit) {
        if (hit) return hit;
        var url = new URL(request.url);
        if (url.pathname.slice(-1) === "/") {
          return cache.match(url.pathname + "index.html").then(function (page) {
            return page || fetch(request);
          });
        }
        return fetch(request);
      });
    }),
  );
});
