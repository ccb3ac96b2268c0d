// Offline use: registers the service worker that the build writes next to the page (dist/sw.js, from
// web/sw.js; docs/hosting.md). Only in a production build served over http(s) where the browser allows
// service workers (https, or http on localhost); never in the Vite dev server. The worker is registered
// relative to the page, so the site works from any sub-path, and only once the app has started, so
// precaching does not compete with the first load.
//
// ?sw=0 in the page's address skips the registration and removes a service worker already installed
// for this page, with its cache (for debugging, or a host that cannot serve sw.js; the browser tests
// block service workers instead, see tests/e2e/harness.mjs).
const SCRIPT = './sw.js';
const SCOPE = './';
const READY_TIMEOUT_MS = 15000;

// Resolves when main.js marks the page ready (body[data-ready]), or after READY_TIMEOUT_MS at the latest.
function appStarted() {
  return new Promise((resolve) => {
    const ready = () => document.body.dataset.ready === 'true';
    if (ready()) return resolve();
    const observer = new MutationObserver(() => ready() && done());
    const timer = setTimeout(() => done(), READY_TIMEOUT_MS);
    function done() {
      observer.disconnect();
      clearTimeout(timer);
      resolve();
    }
    observer.observe(document.body, { attributes: true, attributeFilter: ['data-ready'] });
  });
}

// The cache names of this page's service worker (see PREFIX in web/sw.js).
const cachePrefix = () => `billow-precache:${new URL(SCOPE, document.baseURI).pathname}:`;

async function removeServiceWorker() {
  const registration = await navigator.serviceWorker.getRegistration(SCOPE);
  await registration?.unregister();
  if (typeof caches !== 'undefined')
    for (const name of await caches.keys()) if (name.startsWith(cachePrefix())) await caches.delete(name);
}

// Calls onUpdate() once when a new version has been installed and waits for the old one's pages to close.
function watchUpdates(registration, onUpdate) {
  let told = false;
  const tell = () => {
    if (told || !navigator.serviceWorker.controller) return; // a first install is no update
    told = true;
    onUpdate();
  };
  if (registration.waiting) tell();
  registration.addEventListener('updatefound', () => {
    const worker = registration.installing;
    worker?.addEventListener('statechange', () => worker.state === 'installed' && tell());
  });
}

// Registers the service worker; resolves with its registration, or null when there is none.
// onUpdate: called when a new version is ready; it takes over once every Billow tab has been closed.
export async function registerServiceWorker({ onUpdate = () => {} } = {}) {
  if (!import.meta.env.PROD || !/^https?:$/.test(location.protocol) || !('serviceWorker' in navigator)) return null;
  try {
    if (new URLSearchParams(location.search).get('sw') === '0') {
      await removeServiceWorker();
      return null;
    }
    await appStarted();
    const registration = await navigator.serviceWorker.register(SCRIPT, { scope: SCOPE });
    if (!registration) return null; // blocked (Playwright's serviceWorkers: 'block' resolves with nothing)
    watchUpdates(registration, onUpdate);
    return registration;
  } catch (error) {
    // The app works without it, from the network; not worth an error for the designer.
    console.warn(`Billow will not work offline: ${error?.message || error}`);
    return null;
  }
}

// What the page says when a new version is waiting.
export function updateReadyMessage() {
  return 'A new version of Billow has been downloaded. It starts the next time you open Billow, once every Billow tab has been closed.';
}
