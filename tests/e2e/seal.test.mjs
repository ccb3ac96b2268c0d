// Heat-sealed foil and fill valves in the browser. A new design is foil, so its pieces are heat sealed: the
// allowance is the seal band, drawn on the pieces; a fill valve is placed by a click on a seam in the pattern
// pane and marked at the same place on both pieces, with its width, in the pane and the cut file; valves are
// edited, undone, saved; one on a seam that is gone is said so, with a way to remove it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { autosaveHolds, openFreshPage, screenshot, useBrowser } from './harness.mjs';

const env = useBrowser();

const waitInflated = (page) =>
  page.waitForFunction(() => /^Inflated/.test(document.querySelector('#status').textContent), null, { timeout: 90000 });

async function cutFile(page) {
  await page.click('#export-menu summary');
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-export="svg"]')]);
  return readFileSync(await download.path(), 'utf8');
}

// A point of seam `id` in the pattern pane, `share` of the way along its first run, in client pixels.
const seamPoint = (page, id, share) =>
  page.evaluate(([seam, share]) => {
    const pane = window.billow.test.panes.pattern;
    const run = pane.seams.runs.get(seam)[0];
    const [x0, y0, x1, y1] = run.segments[Math.floor(share * run.segments.length)];
    const p = pane.camera.position.clone().set((x0 + x1) / 2, (y0 + y1) / 2, 0).project(pane.camera);
    const r = pane.element.getBoundingClientRect();
    return { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
  }, [id, share]);

// The centres of the valve marks drawn in the pattern pane, in client pixels.
const markCentres = (page) =>
  page.evaluate(() => {
    const pane = window.billow.test.panes.pattern;
    const r = pane.element.getBoundingClientRect();
    return pane.cut.valves.flatMap((marks, i) =>
      marks.map((mark) => {
        const place = pane.placement(i);
        let x = 0, y = 0;
        for (let k = 0; k < mark.length; k += 2) {
          const [px, py] = place(mark[k], mark[k + 1]);
          x += px, y += py;
        }
        const p = pane.camera.position.clone().set((2 * x) / mark.length, (2 * y) / mark.length, 0).project(pane.camera);
        return { panel: i, x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
      }),
    );
  });

test('a foil balloon is heat sealed: the seal band is drawn, a fill valve goes where the seam is clicked, on both pieces', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.selectOption('#example-select', 'pattern:mylar');
  await waitInflated(page);
  await page.waitForFunction(() => window.billow.test.cutStatistics && window.billow.test.panes.pattern.sealBands);
  // The header says what the allowance is: a 5 mm seal band, tinted around both discs.
  assert.match(await page.textContent('label:has(#allowance-input)'), /^Seal band/);
  assert.equal(await page.inputValue('#allowance-input'), '5');
  assert.equal(await page.evaluate(() => window.billow.test.panes.pattern.sealBands.userData.count), 2);
  assert.equal(await page.evaluate(() => window.billow.test.cutStatistics.joining), 'sealed');
  let svg = await cutFile(page);
  assert.match(svg, /<g id="seal-band"/);
  assert.doesNotMatch(svg, /<g id="sew"/);

  // Add a fill valve, then click the seam a quarter of the way along the first disc's rim.
  await page.click('#seams-button');
  assert.equal(await page.inputValue('#seam-allowance-panel-joining'), 'sealed');
  await page.click('.valve-head button');
  assert.equal(await page.getAttribute('.valve-head button', 'aria-pressed'), 'true');
  const at = await seamPoint(page, 0, 0.25);
  await page.mouse.move(at.x, at.y);
  assert.match(await page.getAttribute('#pane-pattern .pane-body', 'title'), /click to place the fill valve here/);
  await page.mouse.click(at.x, at.y);
  await page.waitForFunction(() => window.billow.test.design.fabrication.valves?.length === 1);
  await page.waitForFunction(() => window.billow.test.panes.pattern.valveMarks?.userData.count === 2);
  assert.equal(await page.getAttribute('.valve-head button', 'aria-pressed'), 'false');
  assert.match(await page.textContent('.valve-list li'), /^On S1 at \d+ %, gap/);
  // Its gap is drawn where the seam was clicked, and on the other disc too (the same place once sealed).
  const centres = await markCentres(page);
  assert.deepEqual(centres.map((c) => c.panel).sort(), [0, 1]);
  const near = centres.find((c) => Math.hypot(c.x - at.x, c.y - at.y) < 12);
  assert.ok(near, `a valve mark at the click (${at.x}, ${at.y}): ${JSON.stringify(centres)}`);
  svg = await cutFile(page);
  assert.equal([...svg.matchAll(/<path data-panel="\d+" d="M/g)].length > 0, true);
  const valveLayer = svg.slice(svg.indexOf('<g id="valves"'), svg.indexOf('</g>', svg.indexOf('<g id="valves"')));
  assert.equal([...valveLayer.matchAll(/<path /g)].length, 2);
  assert.equal([...svg.matchAll(/valve 20 mm/g)].length, 2);

  // A wider gap, typed; undone like any edit; kept through a reload.
  await page.fill('.valve-list input', '35');
  await page.press('.valve-list input', 'Enter');
  await page.waitForFunction(() => window.billow.test.design.fabrication.valves[0].width === 35);
  await page.waitForFunction(() => window.billow.test.cutStatistics.valves[0].width_mm === 35);
  await screenshot(page, 'seal-band-and-valve');
  assert.equal([...(await cutFile(page)).matchAll(/valve 35 mm/g)].length, 2);
  await page.click('#undo-button');
  await page.waitForFunction(() => window.billow.test.design.fabrication.valves[0].width === 20);
  await autosaveHolds(page, (design) => design?.fabrication?.valves?.[0]?.width === 20);
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  assert.deepEqual((await page.evaluate(() => window.billow.test.design.fabrication.valves)).map((v) => v.width), [20]);

  // A valve on a seam the pattern does not have: said so, and removed in one click.
  await page.evaluate(() => window.billow.test.addValve(5, 0.5));
  await page.selectOption('#example-select', 'pattern:mylar');
  await waitInflated(page);
  const lost = page.locator('.message.warning', { hasText: 'S6, which this pattern does not have' });
  await lost.waitFor();
  await lost.locator('button', { hasText: 'Remove it' }).click();
  await page.waitForFunction(() => window.billow.test.design.fabrication.valves?.length === 1);
  await page.locator('.message.warning', { hasText: 'which this pattern does not have' }).waitFor({ state: 'detached' });

  // Sewn instead: the allowance is a sewing allowance again (10 mm), with a sewing line and no band.
  await page.click('#seams-button');
  await page.selectOption('#seam-allowance-panel-joining', 'sewn');
  await page.waitForFunction(() => window.billow.test.cutStatistics?.joining === 'sewn' && !window.billow.test.panes.pattern.sealBands);
  assert.match(await page.textContent('label:has(#allowance-input)'), /^Allowance/);
  assert.equal(await page.inputValue('#allowance-input'), '10');
  svg = await cutFile(page);
  assert.match(svg, /<g id="sew"/);
  assert.match(svg, /<g id="valves"/, 'a sewn seam keeps its valve gap');
  // Removing the valve.
  await page.click('.valve-list .reset');
  await page.waitForFunction(() => !('valves' in window.billow.test.design.fabrication));
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('the material sets the joining: ripstop is sewn with a 10 mm allowance, foil sealed with a 5 mm band', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.selectOption('#material-select', 'ripstop');
  await page.waitForFunction(() => window.billow.test.design.fabrication.joining === 'sewn');
  assert.equal(await page.inputValue('#allowance-input'), '10');
  assert.match(await page.textContent('label:has(#allowance-input)'), /^Allowance/);
  await page.selectOption('#material-select', 'foil');
  await page.waitForFunction(() => window.billow.test.design.fabrication.joining === 'sealed');
  assert.equal(await page.inputValue('#allowance-input'), '5');
  // One step of the history each: undo goes back to ripstop and its sewing allowance.
  await page.click('#undo-button');
  await page.waitForFunction(() => window.billow.test.design.material.name === 'ripstop');
  assert.equal(await page.inputValue('#allowance-input'), '10');
  assert.deepEqual(page.errors, []);
  await page.close();
});
