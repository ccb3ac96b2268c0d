// Suggested seam layouts in the app itself (headless Chromium, web/dist): a mesh opened as a designer opens a file,
// Suggest seams at `--panels`, timed from the click until the first card shows and until the status says the layouts
// were tried, with the page's own main-thread work over that time (Chromium's task time: the cards, the progress, the
// frames; the workers' is not in it), as the issue's goal is set in the app (bench/README.md "Suggested seam layouts").
//   node bench/suggest-bench-app.mjs [--panels 12] [--meshes koala,spot,blub] [--json]   (needs web/dist: npm run build)
// A mesh named with a slash is a mesh file's path; one with holes has them closed (the refusal's "Close the holes").
import { readFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import { serve, launch, openFreshPage, MESHES } from '../tests/e2e/harness.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const panels = arg('--panels', '12');
const meshes = arg('--meshes', 'koala,spot,blub').split(',');
const asJson = process.argv.includes('--json');
// Polled, not on every frame (Playwright's default): a frame of the page takes CPU from the workers.
const POLL = { polling: 250 };

const server = await serve();
const context = await launch();
const rows = [];
try {
  for (const given of meshes) {
    const path = given.includes('/') ? given : join(MESHES, `${given}.obj`);
    const name = basename(path);
    const page = await openFreshPage(context, server.url);
    await page.setInputFiles('#file-input', { name, mimeType: 'text/plain', buffer: readFileSync(path) });
    // A mesh with holes is refused with an offer to close them: taken, as a designer takes it (one click).
    const shown = () => page.waitForFunction((n) => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === n, name, { timeout: 120000, ...POLL });
    const offer = page.locator('.message.error button.action', { hasText: /Close the/ });
    await Promise.race([shown(), offer.waitFor({ timeout: 120000 })]);
    if (await offer.count()) {
      await offer.click();
      await shown();
    }
    await page.click('#suggest-button');
    // Its mirror plane found first, as a designer who reads the panel before asking sees the symmetry offered.
    await page.waitForSelector('dialog.suggest-dialog[open][data-symmetry-known]');
    await page.fill('.suggest-panels', panels);
    const cdp = await context.newCDPSession(page);
    await cdp.send('Performance.enable');
    const taskSeconds = async () => (await cdp.send('Performance.getMetrics')).metrics.find((m) => m.name === 'TaskDuration').value;
    const task0 = await taskSeconds();
    const t0 = Date.now();
    await page.click('.suggest-go');
    await page.waitForSelector('.suggest-card', { timeout: 300000 });
    const first = (Date.now() - t0) / 1000;
    await page.waitForFunction(() => /layouts tried/.test(document.querySelector('.suggest-status').textContent), null, { timeout: 900000, ...POLL });
    const all = (Date.now() - t0) / 1000;
    const mainThread = (await taskSeconds()) - task0;
    const status = await page.$eval('.suggest-status', (e) => e.textContent);
    const best = await page.$eval('.suggest-card[data-rank="1"]', (el) => ({
      name: el.querySelector('h3').title,
      panels: Number(el.querySelector('[data-figure="panels"]').textContent),
      distance: el.querySelector('[data-figure="distance"]').textContent,
    }));
    if (page.errors.length) throw new Error(`${name}: ${page.errors.join('; ')}`);
    rows.push({ mesh: name.replace(/\.[^.]*$/, ''), panels: Number(panels), first, all, mainThread, tried: Number(status.match(/^(\d+)/)?.[1]), best });
    await page.close();
  }
} finally {
  await context.close();
  await server.close();
}
if (asJson) console.log(JSON.stringify(rows, null, 2));
else {
  console.log('| mesh | panels asked | first card s | all s | page main thread s | layouts tried | best layout | panels | distance |');
  console.log('|---|---|---|---|---|---|---|---|---|');
  for (const r of rows)
    console.log(`| ${r.mesh} | ${r.panels} | ${r.first.toFixed(1)} | ${r.all.toFixed(1)} | ${r.mainThread.toFixed(1)} | ${r.tried} | ${r.best.name} | ${r.best.panels} | ${r.best.distance} |`);
}
