// Hashigo's service worker: after the first visit the page works with no
// network. The build (scripts/no-inline-script.py) writes the release's
// files and a version into FILES and VERSION; a new release installs a
// new cache and the old one is deleted when it takes over.
const VERSION = "__VERSION__";
const FILES = ["__FILES__"];
const CACHE = `hashigo-${VERSION}`;

// Two files at a time, not all at once: the page is not this worker's
// yet on a first visit, and its own requests (a machine chosen while the
// files are kept) must find a free connection and most of a slow link
// (issue #53). Any file that does not come fails the install, as
// `addAll` would.
const AT_ONCE = 2;

function keepAll(cache) {
  const queue = [...FILES];
  const worker = async () => {
    while (queue.length > 0) {
      await cache.add(queue.shift());
    }
  };
  return Promise.all(Array.from({ length: AT_ONCE }, worker));
}

self.addEventListener("install", (event) => {
  event.waitUntil(caches.open(CACHE).then(keepAll).then(() => self.skipWaiting()));
});

self.addEventListener("activate", (event) => {
  event.waitUntil(
    caches.keys()
      .then((keys) => Promise.all(keys.filter((k) => k.startsWith("hashigo-") && k !== CACHE).map((k) => caches.delete(k))))
      .then(() => self.clients.claim()),
  );
});

// The page itself: the network first (a new release shows at once),
// the cache when offline. Its files have hashed names: the cache first.
self.addEventListener("fetch", (event) => {
  const request = event.request;
  if (request.method !== "GET" || new URL(request.url).origin !== self.location.origin) {
    return;
  }
  if (request.mode === "navigate") {
    event.respondWith(
      fetch(request).catch(() => caches.open(CACHE).then((cache) => cache.match("/index.html"))),
    );
    return;
  }
  // The start screen and the guide are not in FILES (the first visit
  // does not fetch them all): each is kept when first fetched, and a
  // fresh copy is asked for while online.
  const path = new URL(request.url).pathname;
  if (path.startsWith("/start/") || path.startsWith("/guide/")) {
    event.respondWith(
      caches.open(CACHE).then((cache) =>
        fetch(request)
          .then((response) => {
            if (response.ok) {
              cache.put(request, response.clone());
            }
            return response;
          })
          .catch(() => cache.match(request).then((hit) => hit || Response.error())),
      ),
    );
    return;
  }
  event.respondWith(caches.match(request).then((hit) => hit || fetch(request)));
});
