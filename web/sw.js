// Billow's service worker: the app works offline after its first load (docs/hosting.md).
//
// This file is a template. The build (the billow-service-worker plugin in web/vite.config.js) writes
// web/dist/sw.js: this file preceded by one line, `self.BILLOW_PRECACHE = { version, files }`, where files
// maps every file of the built site (paths relative to this script: the page, the JS, CSS and wasm bundles,
// the example meshes) to the SHA-256 of its content, and version is a hash of them all.
//
// - install: fetches every file (revalidating with the server, so no stale HTTP cache gets in), checks its
//   hash, and stores it in the cache "billow-precache:<scope path>:<version>". A file that does not match
//   (a half-finished deployment, a proxy serving an older copy) fails the install: the browser tries again
//   on a later load, and the page keeps working from the network meanwhile.
// - activate: deletes this scope's caches of other versions, and takes control of open pages that have no
//   service worker yet (the first visit), so the rest of that visit already works offline.
// - fetch: cache first for the precached files and for navigations to the page itself (its query is
//   ignored); anything else goes to the network as if there were no service worker.
// - updates: a new deployment has a new version, so a new sw.js; the browser installs it next to the
//   running one and it waits (no skipWaiting: a page must never get files of two versions) until every
//   page of the old version is closed. The page shows a quiet notice meanwhile (web/src/app/offline.js).
// - Without the build's manifest (this template served as is, e.g. by the Vite dev server, or deployed on
//   purpose to retire offline use) the worker removes itself and its caches.
/* eslint-env serviceworker */
const MANIFEST = self.BILLOW_PRECACHE;
const SCOPE = new URL('./', self.location);
const PREFIX = `billow-precache:${SCOPE.pathname}:`;
const CACHE = MANIFEST ? PREFIX + MANIFEST.version : null;

// Absolute URL (no query) -> the file's path in the manifest.
const PRECACHED = new Map(Object.keys(MANIFEST?.files ?? {}).map((path) => [new URL(path, SCOPE).href, path]));
const PAGE = new URL('index.html', SCOPE).href;

const TYPES = { '.wasm': 'application/wasm' };

async function sha256(buffer) {
  const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', buffer));
  return Array.from(digest, (b) => b.toString(16).padStart(2, '0')).join('');
}

// One file of the manifest, fetched, checked and stored. The stored response carries the server's
// headers, except that a .wasm file always gets application/wasm (streaming compilation needs it).
async function precacheFile(cache, url, path) {
  const response = await fetch(new Request(url, { cache: 'no-cache', credentials: 'same-origin' }));
  if (!response.ok) throw new Error(`${path}: HTTP ${response.status}`);
  const body = await response.arrayBuffer();
  const hash = await sha256(body);
  if (hash !== MANIFEST.files[path]) throw new Error(`${path}: the server sent another version of this file`);
  const headers = new Headers(response.headers);
  const type = TYPES[path.slice(path.lastIndexOf('.'))];
  if (type) headers.set('content-type', type);
  await cache.put(url, new Response(body, { status: 200, statusText: 'OK', headers }));
}

async function precache() {
  const cache = await caches.open(CACHE);
  try {
    await Promise.all(Array.from(PRECACHED, ([url, path]) => precacheFile(cache, url, path)));
  } catch (error) {
    await caches.delete(CACHE); // a later attempt starts clean
    throw error;
  }
}

async function removeOtherVersions() {
  for (const name of await caches.keys()) if (name.startsWith(PREFIX) && name !== CACHE) await caches.delete(name);
}

async function removeSelf() {
  for (const name of await caches.keys()) if (name.startsWith(PREFIX)) await caches.delete(name);
  await self.registration.unregister();
}

self.addEventListener('install', (event) => {
  if (!MANIFEST) {
    self.skipWaiting();
    return;
  }
  event.waitUntil(precache());
});

self.addEventListener('activate', (event) => {
  event.waitUntil(MANIFEST ? removeOtherVersions().then(() => self.clients.claim()) : removeSelf());
});

// The cached file for a request, or null when the network should answer it.
function cachedUrl(request) {
  if (request.method !== 'GET') return null;
  const url = new URL(request.url);
  if (url.origin !== SCOPE.origin) return null;
  url.search = '';
  url.hash = '';
  if (request.mode === 'navigate') return url.href === SCOPE.href || url.href === PAGE ? PAGE : null;
  return PRECACHED.has(url.href) ? url.href : null;
}

async function cacheFirst(request, url) {
  const cache = await caches.open(CACHE);
  const hit = await cache.match(url);
  return hit ?? fetch(request); // evicted by the browser: the network, as without a service worker
}

self.addEventListener('fetch', (event) => {
  if (!MANIFEST) return;
  const url = cachedUrl(event.request);
  if (url) event.respondWith(cacheFirst(event.request, url));
});
