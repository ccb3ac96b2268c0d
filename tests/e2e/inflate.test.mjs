// Inflating patterns in the browser: the Mylar example from the menu streams its shape, ends with the
// compression overlay and figures, and shows its two panels; an imported pattern file does the same;
// a broken pattern gets a message and the last good result stays.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { serve, launch, openPage, openDesignFixture, screenshot, paintedFraction, useBrowser } from './harness.mjs';

const env = useBrowser();

const waitInflated = (page) =>
  page.waitForFunction(() => /^Inflated/.test(document.querySelector('#status').textContent), null, { timeout: 60000 });

test('the Mylar example inflates: shape, wrinkle overlay, figures and two labelled panels', async () => {
  const page = await openPage(env.context, env.server.url);
  const progress = [];
  await page.exposeFunction('recordStatus', (t) => progress.push(t));
  await page.evaluate(() => new MutationObserver(() => window.recordStatus(document.querySelector('#status').textContent))
    .observe(document.querySelector('#status'), { childList: true, characterData: true, subtree: true }));
  await page.selectOption('#example-select', 'pattern:mylar');
  await waitInflated(page);
  assert.ok(progress.some((t) => /Inflating .*step \d+/.test(t)), `progress was shown: ${progress.slice(0, 5)}`);
  const volume = await page.textContent('#inflated-stats dd[data-stat="volume"]');
  const liters = parseFloat(volume);
  // Two discs of radius 0.3 m: Paulsen's balloon holds about 0.0329 m3 (rim 0.229 m, thickness 0.274 m).
  assert.ok(liters > 28 && liters < 38, `volume ${volume}`);
  assert.ok(await page.isVisible('#pane-inflated .legend'));
  const labels = await page.$$eval('.panel-label', (els) => els.map((e) => e.textContent));
  assert.equal(labels.length, 2);
  await page.waitForTimeout(200);
  assert.ok((await paintedFraction(page, '#pane-inflated .pane-body')) > 0.03, 'the inflated shape is drawn');
  assert.ok((await paintedFraction(page, '#pane-pattern .pane-body')) > 0.03, 'the panels are drawn');
  await screenshot(page, 'inflate-mylar');
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('an imported pattern file inflates; a broken one gets a message and the last result stays', async () => {
  const page = await openPage(env.context, env.server.url);
  const text = await page.evaluate(async () => (await window.billow.test.request('examplePattern', { name: 'pillow', triangles: 800 })).patternText);
  await page.setInputFiles('#file-input', { name: 'pillow.json', mimeType: 'application/json', buffer: Buffer.from(text) });
  await waitInflated(page);
  const volume = await page.textContent('#inflated-stats dd[data-stat="volume"]');
  const broken = JSON.parse(text);
  broken.stitches[0][1] = 99999; // a stitch to a vertex that does not exist
  await page.setInputFiles('#file-input', { name: 'broken.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(broken)) });
  const message = await page.locator('.message.error', { hasText: 'broken.json' }).textContent();
  assert.match(message, /could not be inflated/);
  assert.equal(await page.textContent('#inflated-stats dd[data-stat="volume"]'), volume, 'the last good result stays');
  await page.setInputFiles('#file-input', { name: 'junk.json', mimeType: 'application/json', buffer: Buffer.from('{"format": "billow-pattern", "version": 7}') });
  await page.locator('.message.error', { hasText: 'junk.json' }).waitFor();
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('a design with an equator seam becomes two panels that inflate like a Mylar balloon', async () => {
  const page = await openPage(env.context, env.server.url);
  await openDesignFixture(page, 'sphere-equator.billow.json');
  await page.waitForFunction(() => /1 seam, 2 segments/.test(document.querySelector('#seam-panel .summary')?.textContent));
  await waitInflated(page);
  const labels = await page.$$eval('.panel-label', (els) => els.map((e) => e.firstChild.textContent)); // its name (then its size)
  assert.deepEqual(labels, ['Panel 1', 'Panel 2']); // the numbers of their segments on the model
  // Two flat discs with the equator's length as their rims (radius 0.25 m) inflate to Paulsen's lens:
  // 0.0329 m3 x (0.25 / 0.3)^3 = 19 L (the panels are meshed, so allow a margin).
  const liters = parseFloat(await page.textContent('#inflated-stats dd[data-stat="volume"]'));
  assert.ok(liters > 15 && liters < 70, `volume ${liters} L`);
  await screenshot(page, 'design-equator-inflated');
  // Compare with the panels before optimization (paper Fig. 8): two flat discs, Paulsen's lens of ~19 L.
  await page.click('#show-flattened');
  await page.waitForFunction(() => /^Inflated the flattened panels/.test(document.querySelector('#status').textContent), null, { timeout: 60000 });
  const flatLiters = parseFloat(await page.textContent('#inflated-stats dd[data-stat="volume"]'));
  assert.ok(flatLiters > 15 && flatLiters < 24, `flattened volume ${flatLiters} L`);
  assert.equal(await page.getAttribute('#show-flattened', 'aria-pressed'), 'true');
  await page.click('#show-optimized');
  await page.waitForFunction(() => /^Inflated the optimized panels/.test(document.querySelector('#status').textContent), null, { timeout: 60000 });
  assert.equal(parseFloat(await page.textContent('#inflated-stats dd[data-stat="volume"]')), liters);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('material and pressure are part of the design: the panels are made again, saved, and undone at once', async () => {
  const page = await openPage(env.context, env.server.url);
  await openDesignFixture(page, 'sphere-equator.billow.json');
  await page.waitForFunction(() => /1 seam, 2 segments/.test(document.querySelector('#seam-panel .summary')?.textContent));
  await waitInflated(page);
  assert.equal(await page.inputValue('#material-select'), 'foil');
  assert.equal(await page.textContent('#inflated-stats dd[data-stat="pressure"]'), '1.00 kPa');
  const foilStress = parseFloat(await page.textContent('#inflated-stats dd[data-stat="peak-stress"]'));

  // Each pane's draws from here on: the panels' optimization streams its iterates to the inflated pane alone.
  await page.evaluate(() => {
    window.drawn = { target: 0, inflated: 0 };
    for (const name of Object.keys(window.drawn)) {
      const pane = window.billow.test.panes[name];
      const render = pane.render.bind(pane);
      pane.render = (...args) => (window.drawn[name]++, render(...args));
    }
  });
  await page.selectOption('#material-select', 'pvc');
  await page.fill('#pressure-input', '2');
  await page.press('#pressure-input', 'Enter');
  await page.waitForFunction(
    () => document.querySelector('#inflated-stats dd[data-stat="pressure"]')?.textContent === '2.00 kPa' &&
      /^Inflated the optimized panels/.test(document.querySelector('#status').textContent),
    null,
    { timeout: 90000 },
  );
  const drawn = await page.evaluate(() => window.drawn);
  assert.ok(drawn.inflated >= 3 && drawn.target <= drawn.inflated / 2, `the target drawn ${drawn.target} times, the inflated shape ${drawn.inflated}`);
  // The same shape at twice the pressure: the sheet's tension doubles; PVC is 12x thicker than foil, so
  // its stress is about 2/12 of the foil's (membrane stress ~ p r / h).
  const pvcStress = parseFloat(await page.textContent('#inflated-stats dd[data-stat="peak-stress"]'));
  assert.ok(pvcStress < foilStress / 2, `PVC stress ${pvcStress} MPa vs foil ${foilStress} MPa`);

  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-button')]);
  const saved = JSON.parse(readFileSync(await download.path(), 'utf8'));
  assert.equal(saved.material.name, 'pvc');
  assert.equal(saved.material.thickness, 0.3e-3);
  assert.equal(saved.pressure, 2000);

  await page.click('#undo-button'); // the pressure
  assert.equal(await page.inputValue('#pressure-input'), '1');
  // Undone to foil at 1 kPa: the panels made for it come back at once, not optimized again. The statuses are
  // watched from the undo's click on, in one step: the PVC panels at 1 kPa, which the first undo set optimizing,
  // report their steps until the second undo stops them.
  await page.evaluate(() => {
    const status = document.querySelector('#status');
    window.statusSeen = [];
    new MutationObserver(() => window.statusSeen.push(status.textContent)).observe(status, { childList: true, characterData: true, subtree: true });
    document.querySelector('#undo-button').click(); // the material
  });
  assert.equal(await page.inputValue('#material-select'), 'foil');
  await page.waitForFunction(() => window.billow.test.resultShown && document.querySelector('#inflated-stats dd[data-stat="pressure"]')?.textContent === '1.00 kPa', null, { timeout: 20000 });
  const seen = await page.evaluate(() => window.statusSeen);
  assert.ok(!seen.some((text) => /^(Making|Optimizing) the panels/.test(text)), JSON.stringify(seen));
  assert.equal(parseFloat(await page.textContent('#inflated-stats dd[data-stat="peak-stress"]')), foilStress, 'the same panels');

  await page.fill('#pressure-input', '-5');
  await page.press('#pressure-input', 'Enter');
  await page.locator('.message.warning', { hasText: 'pressure must be between' }).waitFor();
  assert.equal(await page.inputValue('#pressure-input'), '1');
  assert.deepEqual(page.errors, []);
  await page.close();
});
