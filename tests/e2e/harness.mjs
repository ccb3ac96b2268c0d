// End-to-end harness: serves the built site (web/dist) with a plain static server on a free loopback
// port, and drives Debian's Chromium through playwright-core. Every page fails its test on any console
// error or uncaught exception.
import { createServer } from 'node:http';
import { readFile, mkdtemp, mkdir, rm } from 'node:fs/promises';
import { existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, extname, normalize, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';
import { before, after, afterEach } from 'node:test';
import { chromium } from 'playwright-core';

export const ROOT = fileURLToPath(new URL('../..', import.meta.url));
export const DIST = process.env.BILLOW_DIST || join(ROOT, 'web/dist');
export const SHOTS = join(ROOT, 'build/screenshots');
export const MESHES = join(ROOT, '../shared/meshes');

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript', '.css': 'text/css',
  '.wasm': 'application/wasm', '.json': 'application/json', '.obj': 'text/plain', '.md': 'text/markdown',
  '.png': 'image/png', '.svg': 'image/svg+xml',
};

// An empty page of the server's origin (not part of the site), where a test clears the origin's storage.
const BLANK = '__blank__.html';

// A static file server for DIST, optionally under a sub-path (e.g. '/billow/'), and the blank page.
export async function serve({ base = '/' } = {}) {
  const server = createServer(async (req, res) => {
    try {
      let path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
      if (path === `/${BLANK}`) {
        res.writeHead(200, { 'content-type': TYPES['.html'] }).end('<!doctype html><title>blank</title><link rel="icon" href="data:,">');
        return;
      }
      if (!path.startsWith(base)) throw new Error('outside');
      path = normalize(path.slice(base.length));
      if (path.startsWith('..')) throw new Error('outside');
      if (path === '.' || path.endsWith('/')) path = join(path, 'index.html');
      const body = await readFile(join(DIST, path));
      res.writeHead(200, { 'content-type': TYPES[extname(path)] || 'application/octet-stream' });
      res.end(body);
    } catch {
      res.writeHead(404).end('not found');
    }
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const url = `http://127.0.0.1:${server.address().port}${base}`;
  return { url, close: () => new Promise((r) => server.close(r)) };
}

// A fresh browser profile. Service workers are blocked unless asked for (serviceWorkers: 'allow'): the
// page's offline cache (web/src/app/offline.js) is tested on its own in site.test.mjs, and would otherwise
// serve the other tests' pages from its cache and precache the site while they run.
export async function launch({ serviceWorkers = 'block' } = {}) {
  if (!existsSync(join(DIST, 'index.html'))) throw new Error('web/dist is missing: run npm run build first');
  const profile = await mkdtemp(join(tmpdir(), 'billow-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    serviceWorkers,
    viewport: { width: 1400, height: 900 },
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--enable-unsafe-swiftshader'],
  });
  // The profile goes with the browser (tens of MB each: a run left hundreds in the temporary folder).
  const close = context.close.bind(context);
  context.close = async (options) => {
    await close(options);
    await rm(profile, { recursive: true, force: true });
  };
  return context;
}

// Opens url in a new page of context and collects console errors; assertNoErrors() fails on any.
// fresh: the origin's autosave is deleted first (on the blank page, so the app loads once).
export async function openPage(context, url, { fresh = false } = {}) {
  const page = await context.newPage();
  const errors = [];
  page.on('console', (m) => m.type() === 'error' && errors.push(`console: ${m.text()}`));
  page.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()}`));
  page.errors = errors;
  if (fresh) {
    await page.goto(new URL(`/${BLANK}`, url).href);
    await page.evaluate(
      () => new Promise((resolve, reject) => {
        const request = indexedDB.deleteDatabase('billow');
        request.onsuccess = resolve;
        request.onerror = () => reject(request.error);
      }),
    );
  }
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  return page;
}

// A page with no autosaved design: the app starts on its default example.
export function openFreshPage(context, url) {
  return openPage(context, url, { fresh: true });
}

// The design in the autosave record every new tab opens (IndexedDB 'billow', store 'autosave', key 'current'), or null.
export function autosavedDesign(page) {
  return page.evaluate(
    () => new Promise((resolve, reject) => {
      const open = indexedDB.open('billow', 1);
      open.onerror = () => reject(open.error);
      open.onsuccess = () => {
        const get = open.result.transaction('autosave', 'readonly').objectStore('autosave').get('current');
        get.onsuccess = () => {
          open.result.close();
          resolve(get.result?.design ?? null);
        };
        get.onerror = () => reject(get.error);
      };
    }),
  );
}

// Waits until that design satisfies `holds`: the app saves on every change, but its write ends after the change
// is shown, so a page closed at once (a test's next step) can leave the record one change behind.
export async function autosaveHolds(page, holds, timeout = 10000) {
  const end = Date.now() + timeout;
  while (!holds(await autosavedDesign(page))) {
    if (Date.now() > end) throw new Error('the autosave did not come to hold the design on screen');
    await page.waitForTimeout(100);
  }
}

// Opens a design file of tests/data with the file picker, as a designer would.
export async function openDesignFixture(page, fileName) {
  const buffer = await readFile(join(ROOT, 'tests/data', fileName));
  await page.setInputFiles('#file-input', { name: fileName, mimeType: 'application/json', buffer });
}

// Waits until the panels of the current design are optimized and shown (nothing running, nothing stale).
export function optimizedResultShown(page, timeout = 180000) {
  return page.waitForFunction(() => window.billow.test.resultShown, null, { timeout });
}

// The panels of the design on screen are made and an optimizer's iterate of them is inflated in its pane (a new
// shape since `serial`, window.billow.test.inflatedSerial before the edit); the optimization then stops. Tests of
// what makes a design use it where the optimized result would only add time. Looked at on a timer, not a frame: a
// loaded machine's software renderer may draw no frame for seconds while the iterates stream; a short
// optimization may end between two looks, and its result shown counts as well.
export async function panelsInflated(page, serial, timeout = 120000) {
  await page.waitForFunction((since) => {
    const t = window.billow.test;
    return (t.inflatedSerial ?? 0) > (since ?? 0) && t.panes.inflated.shape && t.panes.pattern.pattern
      && (/^Optimizing the panels: step/.test(document.querySelector('#status').textContent) || t.resultShown);
  }, serial, { timeout, polling: 100 }).catch(async (error) => {
    const state = await page.evaluate(() => {
      const t = window.billow.test;
      return { serial: t.inflatedSerial, shape: Boolean(t.panes.inflated.shape), pattern: Boolean(t.panes.pattern.pattern),
        optimizing: t.optimizing, status: document.querySelector('#status').textContent };
    });
    throw new Error(`no iterate of the panels was inflated since shape ${serial}: ${JSON.stringify(state)} (${error.message})`);
  });
  await page.evaluate(() => window.billow.test.stopWork());
}

export async function screenshot(page, name) {
  await mkdir(SHOTS, { recursive: true });
  const path = join(SHOTS, `${name}.png`);
  await page.screenshot({ path });
  return path;
}

// Fraction of pixels in the element's box that differ from its background color, from a screenshot.
export async function paintedFraction(page, selector) {
  return page.evaluate(async (sel) => {
    const el = document.querySelector(sel);
    const r = el.getBoundingClientRect();
    const canvas = document.getElementById('viewport');
    const c = canvas.getBoundingClientRect();
    const scale = canvas.width / c.width;
    const gl = canvas.getContext('webgl2');
    const w = Math.floor(r.width * scale), h = Math.floor(r.height * scale);
    const x = Math.floor((r.left - c.left) * scale), y = Math.floor((c.bottom - r.bottom) * scale);
    const pixels = new Uint8Array(w * h * 4);
    gl.readPixels(x, y, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const bg = pixels.slice(0, 3); // a corner pixel: the pane's clear color
    let differ = 0;
    for (let i = 0; i < pixels.length; i += 4)
      if (Math.abs(pixels[i] - bg[0]) + Math.abs(pixels[i + 1] - bg[1]) + Math.abs(pixels[i + 2] - bg[2]) > 24) differ++;
    return differ / (w * h);
  }, selector);
}

// Starts a static server and a browser for the tests of one file (node:test hooks of the file that calls it);
// returns an object whose server and context are set once the hooks have run.
export function useBrowser() {
  const env = { server: null, context: null };
  before(async () => {
    env.server = await serve();
    env.context = await launch();
  });
  // A test that fails leaves its page open: closed here, or its tab would hold the autosave (a later test's page
  // would open as a second tab, with that message) and keep its worker busy.
  afterEach(async () => {
    for (const page of env.context?.pages() ?? []) await page.close();
  });
  after(async () => {
    await env.context?.close();
    await env.server?.close();
  });
  return env;
}

export { dirname };
