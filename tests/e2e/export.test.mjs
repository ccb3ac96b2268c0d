// Fabrication in the browser: a design's panels get cut lines with the seam allowance and pattern figures;
// every export downloads a file that is checked (SVG/DXF outlines against the pattern to 0.01 mm, PDF pages
// and scale box, OBJ/STL/GLB/PNG structure); changing the allowance and the units updates the pane.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { autosaveHolds, openPage, openFreshPage, openDesignFixture, screenshot, useBrowser } from './harness.mjs';

const env = useBrowser();
const stat = (page, pane, name) => page.textContent(`#${pane}-stats dd[data-stat="${name}"]`);

async function exportFile(page, kind) {
  await page.click('#export-menu summary');
  const [download] = await Promise.all([page.waitForEvent('download'), page.click(`[data-export="${kind}"]`)]);
  return { name: download.suggestedFilename(), bytes: readFileSync(await download.path()) };
}

// Perimeter of a closed polyline given as [x0, y0, x1, y1, ...].
function perimeter(xy) {
  let sum = 0;
  for (let i = 0; i < xy.length; i += 2) {
    const j = (i + 2) % xy.length;
    sum += Math.hypot(xy[j] - xy[i], xy[j + 1] - xy[i + 1]);
  }
  return sum;
}

// Sewing-line perimeters of a pattern's panels [mm]: the boundary edges (used by one triangle).
function patternPerimeters(pattern) {
  return pattern.panels.map((panel) => {
    const count = new Map();
    for (const t of panel.triangles)
      for (let k = 0; k < 3; k++) {
        const a = t[k], b = t[(k + 1) % 3];
        const key = a < b ? `${a},${b}` : `${b},${a}`;
        count.set(key, (count.get(key) ?? 0) + 1);
      }
    let sum = 0;
    for (const [key, n] of count) {
      if (n !== 1) continue;
      const [a, b] = key.split(',').map(Number);
      sum += 1000 * Math.hypot(panel.vertices[a][0] - panel.vertices[b][0], panel.vertices[a][1] - panel.vertices[b][1]);
    }
    return sum;
  });
}

test('the panels of a design export to every format, checked file by file', async () => {
  const page = await openPage(env.context, env.server.url);
  await openDesignFixture(page, 'sphere-equator.billow.json');
  await page.waitForFunction(() => /^Inflated the optimized panels/.test(document.querySelector('#status').textContent), null, { timeout: 90000 });
  await page.waitForFunction(() => document.querySelector('#pattern-stats dd[data-stat="panels"]')?.textContent === '2');
  // The optimized panels are sewable: stitched edges of equal length (paper Sec. 5.1), no pucker warning.
  const status = await page.evaluate(() => window.billow.test.optimized.status);
  assert.ok(status.seamMismatch < 1e-4, `seam mismatch ${status.seamMismatch} (${status.message})`);
  assert.equal(await page.locator('.message', { hasText: 'pucker' }).count(), 0);
  // Balloon figures: a 0.5 m sphere of 25 µm foil floats on helium.
  assert.match(await stat(page, 'inflated', 'helium-lift'), /floats/);
  assert.match(await stat(page, 'inflated', 'envelope-mass'), /^\d+(\.\d)? g$/);
  assert.match(await stat(page, 'inflated', 'safety-factor'), /^\d+\.\d/);

  const pattern = JSON.parse((await exportFile(page, 'pattern')).bytes.toString('utf8'));
  assert.equal(pattern.format, 'billow-pattern');
  assert.equal(pattern.panels.length, 2);
  const expected = patternPerimeters(pattern);

  const svg = await exportFile(page, 'svg');
  assert.match(svg.name, /^sphere-pattern\.svg$/);
  const svgText = svg.bytes.toString('utf8');
  assert.match(svgText, /<svg[^>]* width="1000mm"/);
  const sewLayer = svgText.slice(svgText.indexOf('<g id="sew"'), svgText.indexOf('</g>', svgText.indexOf('<g id="sew"')));
  const sewPaths = [...sewLayer.matchAll(/<path data-panel="(\d+)" d="M([^"Z]+)Z"/g)];
  assert.equal(sewPaths.length, 2);
  for (const [, panel, d] of sewPaths) {
    const xy = d.trim().split(/\s+/).map(Number);
    assert.ok(Math.abs(perimeter(xy) - expected[panel]) < 0.01, `panel ${panel}: SVG ${perimeter(xy)} mm, pattern ${expected[panel]} mm`);
  }

  const dxf = (await exportFile(page, 'dxf')).bytes.toString('latin1').split(/\r?\n/).map((l) => l.trim());
  assert.equal(dxf[dxf.length - 1] === 'EOF' || dxf[dxf.length - 2] === 'EOF', true);
  for (const layer of ['CUT', 'SEW', 'NOTCH']) assert.ok(dxf.includes(layer), `DXF layer ${layer}`);
  // The SEW polylines' vertices (group codes 10/20 after each VERTEX) give the same perimeters.
  const sewPerimeters = [];
  for (let i = 0; i < dxf.length; i++) {
    if (dxf[i] !== 'POLYLINE') continue;
    const layer = dxf[dxf.indexOf('8', i) + 1];
    const xy = [];
    let j = i + 1;
    for (; dxf[j] !== 'SEQEND'; j++)
      if (dxf[j] === 'VERTEX') {
        const x = dxf.indexOf('10', j), y = dxf.indexOf('20', j);
        xy.push(Number(dxf[x + 1]), Number(dxf[y + 1]));
      }
    if (layer === 'SEW') sewPerimeters.push(perimeter(xy));
    i = j;
  }
  assert.equal(sewPerimeters.length, 2);
  for (const p of sewPerimeters) assert.ok(expected.some((e) => Math.abs(e - p) < 0.01), `DXF sew line ${p} mm`);

  const pdf = (await exportFile(page, 'pdf-a4')).bytes.toString('latin1');
  assert.ok(pdf.startsWith('%PDF-1.'));
  assert.ok(pdf.trimEnd().endsWith('%%EOF'));
  const pages = (pdf.match(/\/Type\s*\/Page[^s]/g) ?? []).length;
  // The overview, then one page per tile with something to cut, labelled with its place in the grid; the
  // overview counts the tiles left out (the round pieces leave some of the grid empty).
  const printed = new Set(pdf.match(/\(row \d+, column \d+\)/g) ?? []).size;
  const skipped = pdf.match(/\((\d+) of (\d+) tiles have nothing to cut and are not printed/);
  assert.ok(skipped, 'the overview says how many tiles are not printed');
  assert.equal(pages, 1 + Number(skipped[2]) - Number(skipped[1]), `${pages} pages: the overview and the printed tiles`);
  assert.equal(printed, pages - 1, 'every printed tile keeps its row and column');
  assert.ok(printed >= 2, `${printed} true-scale tiles`);
  // The 50 mm scale box is drawn on every page: 50 mm = 141.73 pt.
  assert.ok((pdf.match(/141\.73/g) ?? []).length >= pages - 1, 'scale box on the tiles');
  const letter = (await exportFile(page, 'pdf-letter')).bytes.toString('latin1');
  assert.match(letter, /\/MediaBox \[0 0 612 792\]/);

  const obj = (await exportFile(page, 'obj')).bytes.toString('utf8');
  const vertices = (obj.match(/^v /gm) ?? []).length;
  const faces = (obj.match(/^f /gm) ?? []).length;
  assert.ok(vertices > 100 && faces === 2 * vertices - 4, `closed OBJ: ${vertices} vertices, ${faces} faces`);
  const stl = (await exportFile(page, 'stl')).bytes;
  assert.equal(stl.length, 84 + 50 * stl.readUInt32LE(80));
  assert.equal(stl.readUInt32LE(80), faces);
  const glb = (await exportFile(page, 'glb')).bytes;
  assert.equal(glb.toString('latin1', 0, 4), 'glTF');
  assert.equal(glb.readUInt32LE(8), glb.length);

  const png = await exportFile(page, 'png-inflated');
  assert.match(png.name, /inflated\.png$/);
  assert.equal(png.bytes.subarray(1, 4).toString('latin1'), 'PNG');
  const paneBox = await page.locator('#pane-inflated .pane-body').boundingBox();
  assert.ok(Math.abs(png.bytes.readUInt32BE(16) - paneBox.width) <= 2, 'the picture is the pane, at page scale');
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('the seam allowance and the units change the cut outline and the figures at once', async () => {
  const page = await openPage(env.context, env.server.url);
  await openDesignFixture(page, 'sphere-equator.billow.json');
  await page.waitForFunction(() => /^Inflated the optimized panels/.test(document.querySelector('#status').textContent), null, { timeout: 90000 });
  await page.waitForFunction(() => window.billow.test.panes.pattern.cutLines && document.querySelector('#pattern-stats dd[data-stat="panels"]')?.textContent === '2');
  const area = async () => parseFloat(await stat(page, 'pattern', 'material'));
  // The cut lines are redrawn (and briefly absent) whenever the panels or the settings change: wait for them.
  const cutLength = async () => (await page.waitForFunction(() => window.billow.test.panes.pattern.cutLines?.geometry.attributes.position.count)).jsonValue();
  const with10 = await area();
  assert.ok((await cutLength()) > 0, 'cut lines are drawn');
  await page.fill('#allowance-input', '0');
  await page.press('#allowance-input', 'Enter');
  await page.waitForFunction((before) => parseFloat(document.querySelector('#pattern-stats dd[data-stat="material"]').textContent) < before, with10);
  await page.fill('#allowance-input', '25');
  await page.press('#allowance-input', 'Enter');
  await page.waitForFunction((before) => parseFloat(document.querySelector('#pattern-stats dd[data-stat="material"]').textContent) > before, with10);
  await screenshot(page, 'export-allowance-25mm');
  await page.selectOption('#units-select', 'in');
  await page.waitForFunction(() => / in /.test(document.querySelector('#pattern-stats dd[data-stat="sheet"]').textContent));
  assert.equal(await page.inputValue('#allowance-input'), String(+(25 / 25.4).toFixed(3)));
  await page.fill('#sheet-input', '2');
  await page.press('#sheet-input', 'Enter');
  await page.locator('.message.warning', { hasText: 'sheet width must be between' }).waitFor();
  // Fabrication settings are part of the design: saved with it, undone like any edit.
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-button')]);
  const saved = JSON.parse(readFileSync(await download.path(), 'utf8'));
  assert.deepEqual(saved.fabrication, { allowance: 25, sheet_width: 1000, units: 'in' });
  await page.click('#undo-button');
  assert.equal(await page.inputValue('#units-select'), 'mm');
  assert.equal(await page.inputValue('#allowance-input'), '25');
  assert.deepEqual(page.errors, []);
  await page.close();
});

// Per seam id (-1: free edges), the median distance [mm] from the middles of its outline edges (away from its
// ends) to the cut line drawn in the pattern pane.
const paneWidths = (page) =>
  page.evaluate(() => {
    const pane = window.billow.test.panes.pattern;
    const lines = pane.cutLines?.userData.lines;
    if (!pane.seams || !lines) return null;
    const widths = {};
    pane.seams.outlines.forEach(({ loop, seams }, p) => {
      const n = loop.length;
      const xy = lines[p];
      for (let e = 0; e < n; e++) {
        if ([-2, -1, 1, 2].some((k) => seams[(e + k + n) % n] !== seams[e])) continue;
        const [ax, ay] = pane.pattern.panels[p].vertices[loop[e]], [bx, by] = pane.pattern.panels[p].vertices[loop[(e + 1) % n]];
        const [x, y] = [(ax + bx) / 2, (ay + by) / 2];
        let best = Infinity;
        for (let i = 0; i < xy.length; i += 2) {
          const j = (i + 2) % xy.length;
          const [cx, cy, dx, dy] = [xy[i], xy[i + 1], xy[j], xy[j + 1]];
          const len2 = (dx - cx) ** 2 + (dy - cy) ** 2;
          const t = len2 > 0 ? Math.min(1, Math.max(0, ((x - cx) * (dx - cx) + (y - cy) * (dy - cy)) / len2)) : 0;
          best = Math.min(best, Math.hypot(x - cx - t * (dx - cx), y - cy - t * (dy - cy)));
        }
        (widths[seams[e]] ??= []).push(1000 * best);
      }
    });
    return Object.fromEntries(Object.entries(widths).map(([id, list]) => [id, +list.sort((a, b) => a - b)[list.length >> 1].toFixed(2)]));
  });

// Waits until the pane's cut line lies at these widths [mm] from the sewing line, seam by seam.
async function waitWidths(page, expected) {
  let last = null;
  for (let k = 0; k < 150; k++) {
    last = await paneWidths(page);
    if (last && Object.keys(expected).every((id) => Math.abs(last[id] - expected[id]) < 0.05) && Object.keys(last).length === Object.keys(expected).length) return last;
    await page.waitForTimeout(100);
  }
  assert.fail(`cut line widths ${JSON.stringify(last)}, expected ${JSON.stringify(expected)}`);
}

// Screen point of the middle of seam `id` on its first panel in the pattern pane.
const seamPoint = (page, id) =>
  page.evaluate((seam) => {
    const pane = window.billow.test.panes.pattern;
    const run = pane.seams.runs.get(seam)[0];
    const [x0, y0, x1, y1] = run.segments[run.segments.length >> 1];
    const p = pane.camera.position.clone().set((x0 + x1) / 2, (y0 + y1) / 2, 0).project(pane.camera);
    const r = pane.element.getBoundingClientRect();
    return { x: r.left + ((p.x + 1) / 2) * r.width, y: r.top + ((1 - p.y) / 2) * r.height };
  }, id);

const waitInflated = (page) =>
  page.waitForFunction(() => /^Inflated/.test(document.querySelector('#status').textContent), null, { timeout: 90000 });

// Cut-line perimeters per panel number in the exported SVG [mm] (rotation on the sheet does not change them).
async function svgCutPerimeters(page) {
  const svg = (await exportFile(page, 'svg')).bytes.toString('utf8');
  const layer = svg.slice(svg.indexOf('<g id="cut"'), svg.indexOf('</g>', svg.indexOf('<g id="cut"')));
  return Object.fromEntries([...layer.matchAll(/<path data-panel="(\d+)" d="M([^"Z]+)Z"/g)].map(([, panel, d]) => [panel, perimeter(d.trim().split(/\s+/).map(Number))]));
}

test('one seam gets its own allowance by a click on it: only its cut line moves; undo, grain and reload', async () => {
  const page = await openFreshPage(env.context, env.server.url); // the other tests' autosaved settings are not this test's
  await page.evaluate(() => window.billow.test.setJoining('sewn')); // a new design is foil, heat sealed: sewn here
  await page.selectOption('#example-select', 'pattern:sphere3');
  await waitInflated(page);
  await waitWidths(page, { 0: 10, 1: 10, 2: 10 });
  const statistics = await page.evaluate(() => window.billow.test.cutStatistics);
  const s2 = statistics.seams[1];
  assert.equal(s2.label, 'S2');
  const before = await svgCutPerimeters(page);

  // A click on seam S2 opens the list of seams at its row, its field ready to type into.
  const at = await seamPoint(page, 1);
  await page.mouse.move(at.x, at.y);
  assert.match(await page.getAttribute('#pane-pattern .pane-body', 'title'), /^Seam S2, panels \d and \d: allowance 10 mm \(the seam allowance\)/);
  await page.mouse.click(at.x, at.y);
  await page.locator('#seam-allowance-panel').waitFor();
  assert.equal(await page.getAttribute('#seams-button', 'aria-expanded'), 'true');
  assert.equal(await page.evaluate(() => document.activeElement.closest('tr')?.dataset.seam), '1');
  assert.deepEqual(await page.$$eval('#seam-allowance-panel tbody tr', (rows) => rows.map((r) => r.querySelector('.name').textContent)), ['S1', 'S2', 'S3']);
  assert.equal(await page.locator('.seam-label', { hasText: 'S2' }).count(), 2, 'S2 is labelled on both of its panels');
  await page.keyboard.type('0');
  await page.keyboard.press('Enter');
  await waitWidths(page, { 0: 10, 1: 0, 2: 10 });
  assert.match(await page.getAttribute('#seam-allowance-panel tr[data-seam="1"]', 'class'), /\bown\b/);
  assert.doesNotMatch(await page.getAttribute('#seam-allowance-panel tr[data-seam="0"]', 'class'), /\bown\b/);
  assert.equal(await page.textContent('#seams-button'), 'Seams (1 own)');
  assert.deepEqual(await page.evaluate(() => window.billow.test.design.fabrication.seam_allowance), { 1: 0 });
  // The cut file: the two panels sewn at S2 lose its allowance along it, the third panel is as it was.
  const after = await svgCutPerimeters(page);
  for (const panel of [0, 1, 2]) {
    const onS2 = s2.panels.includes(panel + 1);
    if (onS2) assert.ok(after[panel] < before[panel] - 10, `panel ${panel + 1}: ${before[panel]} -> ${after[panel]} mm`);
    else assert.ok(Math.abs(after[panel] - before[panel]) < 0.01, `panel ${panel + 1} keeps its cut line`);
  }
  await screenshot(page, 'export-seam-allowance-s2-heat-sealed');

  // The seam allowance of the header changes the other seams, not S2.
  await page.fill('#allowance-input', '15');
  await page.press('#allowance-input', 'Enter');
  await waitWidths(page, { 0: 15, 1: 0, 2: 15 });
  // Undo and redo, like any edit.
  await page.click('#undo-button');
  await waitWidths(page, { 0: 10, 1: 0, 2: 10 });
  await page.click('#undo-button');
  await waitWidths(page, { 0: 10, 1: 10, 2: 10 });
  assert.equal(await page.textContent('#seams-button'), 'Seams');
  await page.click('#redo-button');
  await waitWidths(page, { 0: 10, 1: 0, 2: 10 });

  // Grain. On a 1700 mm sheet the nesting turns one gore by 90 degrees when the panels may turn freely;
  // kept along the roll they are turned 0 or 180 degrees only (a longer sheet); as drawn, not at all.
  const rotations = () => page.evaluate(() => window.billow.test.cutStatistics.panels.map((p) => Math.round(Math.abs(p.rotation_deg))));
  const sheetLength = () => page.evaluate(() => window.billow.test.cutStatistics.totals.sheet_length_mm);
  await page.fill('#sheet-input', '1700');
  await page.press('#sheet-input', 'Enter');
  await page.waitForFunction(() => window.billow.test.cutStatistics.totals.sheet_width_mm === 1700);
  assert.ok((await rotations()).includes(90), `turned freely: ${await rotations()}`);
  const freeLength = await sheetLength();
  const freeSheet = await stat(page, 'pattern', 'sheet');
  await page.selectOption('#grain-select', 'grain');
  await page.waitForFunction(() => window.billow.test.design.fabrication.grain_lock === true && !('rotate' in window.billow.test.design.fabrication));
  await page.waitForFunction(() => window.billow.test.cutStatistics.panels.every((p) => [0, 180].includes(Math.round(Math.abs(p.rotation_deg)))));
  assert.ok((await sheetLength()) > freeLength + 100, `grain kept: ${await sheetLength()} mm of sheet, turned freely ${freeLength} mm`);
  assert.notEqual(await stat(page, 'pattern', 'sheet'), freeSheet, 'the Sheet figure follows');
  await screenshot(page, 'export-keep-grain');
  await page.selectOption('#grain-select', 'fixed');
  await page.waitForFunction(() => window.billow.test.design.fabrication.rotate === false && !('grain_lock' in window.billow.test.design.fabrication));
  await page.waitForFunction(() => window.billow.test.cutStatistics.panels.every((p) => Math.abs(p.rotation_deg) < 1e-9));
  await page.selectOption('#grain-select', 'grain');
  // (As drawn, every panel is turned 0 degrees too: wait for the setting itself before the autosave.)
  await page.waitForFunction(() => window.billow.test.design.fabrication.grain_lock === true);
  await page.waitForFunction(() => window.billow.test.cutStatistics.panels.every((p) => [0, 180].includes(Math.round(Math.abs(p.rotation_deg)))));

  // Saved with the design: a reload keeps S2's own allowance and the grain, for this pattern again.
  await autosaveHolds(page, (design) => design?.fabrication?.grain_lock === true && design?.fabrication?.seam_allowance?.[1] === 0);
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30000 });
  assert.deepEqual(await page.evaluate(() => window.billow.test.design.fabrication), { allowance: 10, sheet_width: 1700, units: 'mm', joining: 'sewn', seam_allowance: { 1: 0 }, grain_lock: true });
  assert.equal(await page.inputValue('#grain-select'), 'grain');
  assert.equal(await page.textContent('#seams-button'), 'Seams (1 own)');
  await page.selectOption('#example-select', 'pattern:sphere3');
  await waitInflated(page);
  await waitWidths(page, { 0: 10, 1: 0, 2: 10 });
  // Back to the seam allowance with the keyboard: the list from its button, S2's ↺.
  await page.focus('#seams-button');
  await page.keyboard.press('Enter');
  await page.locator('#seam-allowance-panel tr[data-seam="1"] .reset').focus();
  await page.keyboard.press('Enter');
  await waitWidths(page, { 0: 10, 1: 10, 2: 10 });
  assert.equal(await page.evaluate(() => 'seam_allowance' in window.billow.test.design.fabrication), false);
  // A typed value out of range is refused with a message, and the field shows the allowance again.
  await page.fill('#seam-allowance-panel tr[data-seam="2"] input', '500');
  await page.press('#seam-allowance-panel tr[data-seam="2"] input', 'Enter');
  await page.locator('.message.warning', { hasText: 'allowance of seam S3 must be between 0 and 100 mm' }).waitFor();
  assert.equal(await page.inputValue('#seam-allowance-panel tr[data-seam="2"] input'), '10');
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('free edges get their own allowance; own allowances of seams that are gone are listed and removable', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  // The sphere of three gores with an internal panel whose two tips are left unsewn: free edges inside.
  // (Those tips are floppy flaps without pressure: at 500-1000 triangles Newton creeps near the tolerance and
  // stops after 1000 iterations, issue 3; at 1200 it settles in ~210.)
  const pattern = JSON.parse(await page.evaluate(async () => (await window.billow.test.request('examplePattern', { name: 'sphere3-internal', triangles: 1200 })).patternText));
  const xs = pattern.panels[3].vertices.map(([x]) => x);
  const [lo, hi] = [Math.min(...xs), Math.max(...xs)];
  const tip = (panel, v) => panel === 3 && Math.abs(pattern.panels[3].vertices[v][0] - (lo + hi) / 2) > 0.35 * (hi - lo);
  pattern.stitches = pattern.stitches.filter(([pa, va, pb, vb]) => !tip(pa, va) && !tip(pb, vb));
  await page.evaluate(() => window.billow.test.setJoining('sewn')); // a new design is foil, heat sealed: sewn here
  await page.evaluate(() => window.billow.test.setSeamAllowance(7, 3)); // a seam this pattern does not have
  await page.setInputFiles('#file-input', { name: 'open-tips.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(pattern)) });
  await waitInflated(page);
  await page.waitForFunction(() => window.billow.test.cutStatistics?.totals.free_edge_mm > 0);
  await page.click('#seams-button');
  const free = page.locator('#seam-allowance-panel tr[data-seam="-1"]');
  assert.match(await free.textContent(), /Free edges/);
  const gone = page.locator('#seam-allowance-panel tr[data-seam="7"]');
  assert.match(await gone.textContent(), /S8.*not in this pattern/);
  const seamIds = Object.keys(await paneWidths(page)).filter((id) => id !== '-1');
  await free.locator('input').fill('25');
  await free.locator('input').press('Enter');
  await waitWidths(page, { '-1': 25, ...Object.fromEntries(seamIds.map((id) => [id, 10])) });
  assert.equal(await page.evaluate(() => window.billow.test.design.fabrication.free_edge_allowance), 25);
  await screenshot(page, 'export-free-edges');
  await gone.locator('.reset').click();
  await page.waitForFunction(() => !window.billow.test.design.fabrication.seam_allowance);
  assert.equal(await gone.count(), 0);
  await free.locator('.reset').click();
  await waitWidths(page, { '-1': 10, ...Object.fromEntries(seamIds.map((id) => [id, 10])) });
  assert.deepEqual(page.errors, []);
  await page.close();
});

// Per panel, the points of its path in one layer of an exported SVG, in sheet millimetres (y up, as the
// pattern pane draws the sheet: the SVG's y runs down from the sheet's far end).
function svgLayerPaths(svg, layer) {
  const start = svg.indexOf(`<g id="${layer}"`);
  const text = svg.slice(start, svg.indexOf('</g>', start));
  const length = parseFloat(svg.match(/height="([\d.]+)mm"/)[1]);
  return [...text.matchAll(/<path data-panel="(\d+)" d="M([^"Z]*)/g)].map(([, panel, d]) => {
    const numbers = d.trim().split(/\s+/).map(Number);
    const points = [];
    for (let i = 0; i < numbers.length; i += 2) points.push([numbers[i], length - numbers[i + 1]]);
    return { panel: Number(panel), points };
  });
}

test('the sheet view shows the pieces nested as the cut file has them, with their notches; N switches views', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await openDesignFixture(page, 'sphere-equator.billow.json');
  await page.waitForFunction(() => /^Inflated the optimized panels/.test(document.querySelector('#status').textContent), null, { timeout: 90000 });
  await page.waitForFunction(() => window.billow.test.panes.pattern.cutLines && document.querySelector('#pattern-stats dd[data-stat="panels"]')?.textContent === '2');
  await page.fill('#sheet-input', '800');
  await page.press('#sheet-input', 'Enter');
  await page.waitForFunction(() => /^800 mm/.test(document.querySelector('#pattern-stats dd[data-stat="sheet"]')?.textContent ?? ''));
  await page.click('#pattern-view [data-view="sheet"]');
  assert.equal(await page.getAttribute('#pattern-view [data-view="sheet"]', 'aria-pressed'), 'true');
  assert.equal(await page.getAttribute('#pattern-view [data-view="panels"]', 'aria-pressed'), 'false');
  await page.waitForFunction(() => window.billow.test.panes.pattern.sheetMesh && window.billow.test.panes.pattern.cutLines);
  const shown = await page.evaluate(() => {
    const pane = window.billow.test.panes.pattern;
    const placed = (lines) =>
      lines.map((line, i) => {
        const place = pane.placement(i);
        const out = [];
        for (let k = 0; k + 1 < line.length; k += 2) out.push(place(line[k], line[k + 1]).map((v) => 1000 * v));
        return out;
      });
    return {
      sheet: pane.sheetMesh.userData.sheet,
      cut: placed(pane.cutLines.userData.lines),
      notches: pane.notches.userData.count,
      captions: [...document.querySelectorAll('#pane-pattern .sheet-label')].map((l) => l.textContent),
    };
  });
  assert.equal(shown.sheet.width, 0.8, 'the sheet is as wide as set');
  assert.ok(shown.captions.some((c) => /800 mm/.test(c)) && shown.captions.some((c) => /roll .* used/.test(c)), shown.captions.join(' | '));
  // Every piece lies on the sheet, and no two overlap (their boxes are apart: the nesting keeps a gap).
  const boxes = shown.cut.map((points) => ({
    x0: Math.min(...points.map((p) => p[0])), x1: Math.max(...points.map((p) => p[0])),
    y0: Math.min(...points.map((p) => p[1])), y1: Math.max(...points.map((p) => p[1])),
  }));
  for (const b of boxes) {
    assert.ok(b.x0 >= -0.01 && b.x1 <= 800.01, `across the sheet: ${b.x0} .. ${b.x1}`);
    assert.ok(b.y0 >= -0.01 && b.y1 <= 1000 * shown.sheet.length + 0.01, `along the sheet: ${b.y0} .. ${b.y1}`);
  }
  assert.ok(boxes[0].x1 < boxes[1].x0 || boxes[1].x1 < boxes[0].x0 || boxes[0].y1 < boxes[1].y0 || boxes[1].y1 < boxes[0].y0, 'pieces apart');
  // The pane's pieces are where the cut file puts them (to 0.01 mm), with as many notches.
  const svg = (await exportFile(page, 'svg')).bytes.toString('utf8');
  const cut = svgLayerPaths(svg, 'cut');
  assert.equal(cut.length, 2);
  for (const { panel, points } of cut) {
    assert.equal(points.length, shown.cut[panel].length, `panel ${panel + 1}: cut line points`);
    const worst = Math.max(...points.map((p, i) => Math.hypot(p[0] - shown.cut[panel][i][0], p[1] - shown.cut[panel][i][1])));
    assert.ok(worst < 0.01, `panel ${panel + 1}: the pane's cut line is ${worst} mm from the SVG's`);
  }
  assert.equal(shown.notches, svgLayerPaths(svg, 'notches').length, 'the same notches as the SVG');
  // Each piece is labelled with its size as it lies on the sheet.
  const sizes = await page.$$eval('#pane-pattern .panel-label .panel-size', (els) => els.map((e) => e.textContent));
  assert.equal(sizes.length, 2);
  for (const { panel, points } of cut) {
    const w = Math.max(...points.map((p) => p[0])) - Math.min(...points.map((p) => p[0]));
    const h = Math.max(...points.map((p) => p[1])) - Math.min(...points.map((p) => p[1]));
    assert.equal(sizes[panel], `${w.toFixed(0)} × ${h.toFixed(0)} mm`);
  }
  assert.ok(shown.notches > 4);
  await screenshot(page, 'pattern-sheet-view');
  // N (not in a field) goes back to the panels side by side; the choice is remembered on this device.
  await page.evaluate(() => document.activeElement?.blur());
  await page.keyboard.press('n');
  await page.waitForFunction(() => window.billow.test.panes.pattern.view === 'panels' && !window.billow.test.panes.pattern.sheetMesh);
  assert.equal(await page.getAttribute('#pattern-view [data-view="panels"]', 'aria-pressed'), 'true');
  assert.equal(await page.evaluate(() => localStorage.getItem('billow.patternView')), 'panels');
  assert.ok(await page.evaluate(() => window.billow.test.panes.pattern.notches?.userData.count > 4), 'notches in the panels view too');
  assert.deepEqual(page.errors, []);
  await page.close();
});
