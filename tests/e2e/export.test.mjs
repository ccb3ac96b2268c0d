// Fabrication in the browser: a design's panels get cut lines with the seam allowance and pattern figures;
// every export downloads a file that is checked (SVG/DXF outlines against the pattern to 0.01 mm, PDF pages
// and scale box, OBJ/STL/GLB/PNG structure); changing the allowance and the units updates the pane.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { openPage, openDesignFixture, screenshot, useBrowser } from './harness.mjs';

const env = useBrowser({ before, after });
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
  const status = await page.evaluate(() => window.billow.app.optimized.status);
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
  assert.ok(pages >= 3, `${pages} pages: an overview and true-scale tiles`);
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
  await page.waitForFunction(() => window.billow.app.panes.pattern.cutLines && document.querySelector('#pattern-stats dd[data-stat="panels"]')?.textContent === '2');
  const area = async () => parseFloat(await stat(page, 'pattern', 'material'));
  const cutLength = () => page.evaluate(() => window.billow.app.panes.pattern.cutLines.geometry.attributes.position.count);
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
