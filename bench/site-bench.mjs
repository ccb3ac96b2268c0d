// Site benchmark: the production bundle sizes (gzipped) and the time until the first example is
// interactive in headless Chromium, with web/dist served by a plain static server under a sub-path
// (tests/e2e/static-server.mjs: loopback, no compression, no special headers).
//   node bench/site-bench.mjs [--runs 3] [--json]        (needs web/dist: npm run build)
// Interactive = the app reports the example loaded (body[data-ready], set once the worker has loaded the
// wasm module and the example target is validated and in the target pane, as the e2e tests wait for),
// timed from navigation start (performance.now() in the page); "frame" is the first frame drawn after it.
// First visit: a fresh browser context each run (empty HTTP cache, no service worker). Repeat visit: one
// context whose service worker has precached the site, reloaded each run. Medians of --runs loads.
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { chromium } from 'playwright-core';
import { siteSizes, kB } from '../scripts/site-report.mjs';
import { serveStatic, DIST } from '../tests/e2e/static-server.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
};
const runs = Number(option('--runs', '3'));
const asJson = args.includes('--json');
const BASE = '/sub/path/billow/';
const GOAL_MS = 2000;

if (!existsSync(join(DIST, 'index.html'))) {
  console.error('web/dist is missing: run npm run build first');
  process.exit(1);
}

// Records, in the page, when body[data-ready] appears and the first frame after it.
function markReady() {
  const mark = () => {
    if (window.__billowReady || document.body?.dataset.ready !== 'true') return;
    window.__billowReady = performance.now();
    requestAnimationFrame(() => requestAnimationFrame(() => (window.__billowFrame = performance.now())));
  };
  new MutationObserver(mark).observe(document, { subtree: true, attributes: true, attributeFilter: ['data-ready'] });
}

async function newContext(browser) {
  const context = await browser.newContext({ viewport: { width: 1400, height: 900 }, serviceWorkers: 'allow' });
  await context.addInitScript(markReady);
  return context;
}

// Loads (or reloads) the page and returns { ready, frame } in ms from navigation start.
async function timeLoad(page, url) {
  const errors = [];
  const onError = (e) => errors.push(e.message);
  page.on('pageerror', onError);
  await (url ? page.goto(url) : page.reload());
  await page.waitForFunction(() => window.__billowFrame, null, { timeout: 60000 });
  page.off('pageerror', onError);
  if (errors.length) throw new Error(`the page failed: ${errors.join('; ')}`);
  const file = await page.textContent('#target-stats dd[data-stat="file"]');
  if (!/\.obj$/.test(file ?? '')) throw new Error(`no example shown (${file})`);
  return page.evaluate(() => ({ ready: window.__billowReady, frame: window.__billowFrame }));
}

const median = (values) => {
  const s = [...values].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};
const summary = (loads) => ({
  readyMs: Math.round(median(loads.map((l) => l.ready))),
  frameMs: Math.round(median(loads.map((l) => l.frame))),
  minMs: Math.round(Math.min(...loads.map((l) => l.ready))),
  maxMs: Math.round(Math.max(...loads.map((l) => l.ready))),
});

const sizes = siteSizes(DIST);
const server = await serveStatic({ base: BASE });
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--enable-unsafe-swiftshader'],
});
let first, repeat;
try {
  const cold = [];
  for (let i = 0; i < runs; i++) {
    const context = await newContext(browser);
    cold.push(await timeLoad(await context.newPage(), server.url));
    await context.close();
  }
  first = summary(cold);

  const context = await newContext(browser);
  const page = await context.newPage();
  await timeLoad(page, server.url);
  await page.waitForFunction(() => navigator.serviceWorker.controller?.state === 'activated', null, { timeout: 60000 });
  const warm = [];
  for (let i = 0; i < runs; i++) warm.push(await timeLoad(page));
  if (!(await page.evaluate(() => !!navigator.serviceWorker.controller))) throw new Error('the service worker did not control the page');
  repeat = summary(warm);
  await context.close();
} finally {
  await browser.close();
  await server.close();
}

const gz = (k) => sizes[k].gzip;
if (asJson) {
  const bytes = Object.fromEntries(['js', 'wasm', 'css', 'page', 'total', 'examples'].map((k) => [k, { raw: sizes[k].raw, gzip: gz(k) }]));
  console.log(JSON.stringify({ sizes: bytes, runs, firstVisit: first, repeatVisit: repeat, goalMs: GOAL_MS }, null, 2));
} else {
  console.log(`bundle sizes, gzipped: JS ${kB(gz('js'))}, wasm ${kB(gz('wasm'))}, CSS ${kB(gz('css'))}, ` +
    `HTML + service worker ${kB(gz('page'))}; total ${kB(gz('total'))} (raw ${kB(sizes.total.raw)}); example meshes ${kB(gz('examples'))}`);
  console.log(`first example interactive, headless Chromium, static server on loopback under ${BASE}, median of ${runs}:`);
  const row = (label, s) => console.log(`  ${label.padEnd(40)} ${String(s.readyMs).padStart(5)} ms  (${s.minMs}-${s.maxMs}; first frame after it ${s.frameMs} ms)`);
  row('first visit (empty cache)', first);
  row('repeat visit (from the service worker)', repeat);
  const ok = Math.max(first.readyMs, repeat.readyMs) < GOAL_MS;
  console.log(`  goal < ${GOAL_MS} ms: ${ok ? 'met' : 'NOT met'}`);
}
