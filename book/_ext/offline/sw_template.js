/* The book's service worker, written by book/_ext/offline when the site is built. Every
 * page and every file a page uses is kept in a cache named for this build's contents, so
 * the book works offline after one visit, and a new build is a new cache. */
"use strict";
var VERSION = "__VERSION__";
var CACHE = "dynamics-" + VERSION;
var PRECACHE = __PRECACHE__;

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
              return name.indexOf("dynamics-") === 0 && name !== CACHE;
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

self.addEventListener("fetch", function (event) {
  var request = event.request;
  if (request.method !== "GET" || new URL(request.url).origin !== self.location.origin) return;
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
