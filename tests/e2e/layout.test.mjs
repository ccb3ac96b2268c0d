// The layout stays put and clear. A long status is cut short in the top bar, its full text in its tooltip, and
// moves no pane, at three window sizes. The boxes docked over the panes (seams and problems, figures, the
// legend, the messages) never cover what the panes frame: the target, the inflated shape, the pattern's
// pieces; a box closed to its title stays closed after a reload. No two labels of the pattern's sheet view
// overlap, with the seams' labels shown too and at other zooms.
// A target whose file origin lies far from it is framed whole and large.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openFreshPage, screenshot, useBrowser } from './harness.mjs';

const env = useBrowser();

const LONG_STATUSES = [
  'Optimizing the panels: step 12, distance 6.70 % target → inflated, 0.35 % inflated → target, light seams sliding…',
  "Inflated the optimized panels: stopped at the optimizer's limit (150 steps) before settling; the panels may fit a little better than shown",
  `Opening ${'a-scan-of-the-parade-float-with-every-detail-'.repeat(6)}final.obj: reading…`,
];
const SIZES = [[1400, 900], [1024, 768], [1920, 1080]];

// The top bar's and every pane's rectangles with the status set to `text`, measured at once (layout is
// synchronous), so nothing the app does meanwhile can change the status first.
const layoutWith = (page, text) => page.evaluate((t) => {
  window.billow.test.setStatus(t);
  const box = (el) => {
    const r = el.getBoundingClientRect();
    return [r.left, r.top, r.width, r.height].map((v) => Math.round(v * 10) / 10);
  };
  const status = document.querySelector('#status');
  return {
    topbar: box(document.querySelector('.topbar')),
    panes: Object.fromEntries([...document.querySelectorAll('.pane')].flatMap((p) => [[p.id, box(p)], [`${p.id} view`, box(p.querySelector('.pane-body'))]])),
    status: { text: status.textContent, title: status.title, height: status.getBoundingClientRect().height, lineHeight: parseFloat(getComputedStyle(status).lineHeight) || 20,
      cut: status.scrollWidth > status.clientWidth, ellipsis: getComputedStyle(status).textOverflow },
  };
}, text);

test('a long status is cut short with its full text as its tooltip, and no pane moves', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  for (const [width, height] of SIZES) {
    await page.setViewportSize({ width, height });
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const short = await layoutWith(page, 'Ready');
    for (const text of LONG_STATUSES) {
      const long = await layoutWith(page, text);
      assert.deepEqual(long.topbar, short.topbar, `${width}x${height}: the top bar keeps its place and height`);
      assert.deepEqual(long.panes, short.panes, `${width}x${height}: the panes keep their places`);
      assert.equal(long.status.text, text);
      // The tooltip follows the text by a MutationObserver, once the script that set it has run.
      const tooltip = await page.evaluate(() => [document.querySelector('#status').title, document.querySelector('#status').textContent]);
      assert.equal(tooltip[0], tooltip[1], 'the full status is its tooltip');
      assert.ok(tooltip[0].length > 40, tooltip[0]);
      assert.ok(long.status.height < 1.5 * long.status.lineHeight, `${width}x${height}: one line (${long.status.height} px)`);
      assert.equal(long.status.ellipsis, 'ellipsis');
      // The status has a row's rest to itself: the optimizer's status is whole from 1400 px on, longer ones cut.
      // The status has the rest of a row to itself: the optimizer's is whole, a long file name's is cut.
      if (text === LONG_STATUSES[0]) assert.ok(!long.status.cut, `${width}x${height}: the optimizer's status is shown whole`);
      if (text === LONG_STATUSES[2]) assert.ok(long.status.cut, `${width}x${height}: the long status is cut short`);
    }
    await page.evaluate((t) => window.billow.test.setStatus(t), LONG_STATUSES[0]);
    await screenshot(page, `layout-status-${width}x${height}`);
  }
  await page.setViewportSize({ width: 1400, height: 900 });
  assert.deepEqual(page.errors, []);
  await page.close();
});

// Client rectangles { left, top, right, bottom } of what a pane frames and of the boxes over the panes.
const framing = (page) => page.evaluate(() => {
  const panes = window.billow.test.panes;
  const Vector3 = panes.target.camera.position.constructor;
  // The screen box of the world-space box `box` seen by `camera` in the pane whose view is `body`.
  const screenBox = (box, camera, body) => {
    const r = body.getBoundingClientRect();
    let left = Infinity, top = Infinity, right = -Infinity, bottom = -Infinity;
    for (const x of [box.min.x, box.max.x]) for (const y of [box.min.y, box.max.y]) for (const z of [box.min.z, box.max.z]) {
      const p = new Vector3(x, y, z).project(camera);
      const sx = r.left + ((p.x + 1) / 2) * r.width, sy = r.top + ((1 - p.y) / 2) * r.height;
      left = Math.min(left, sx); right = Math.max(right, sx); top = Math.min(top, sy); bottom = Math.max(bottom, sy);
    }
    return { left, top, right, bottom };
  };
  const worldBox = (meshes) => {
    let box = null;
    for (const mesh of meshes) {
      mesh.updateMatrixWorld(true);
      mesh.geometry.computeBoundingBox();
      const b = mesh.geometry.boundingBox.clone().applyMatrix4(mesh.matrixWorld);
      box = box ? box.union(b) : b;
    }
    return box;
  };
  const rect = (el) => {
    const r = el.getBoundingClientRect();
    return { left: r.left, top: r.top, right: r.right, bottom: r.bottom, name: el.id || el.className };
  };
  const shown = (el) => el.getClientRects().length > 0 && getComputedStyle(el).visibility !== 'hidden';
  const boxesOver = (id) => [...document.querySelectorAll(`#${id} .dock > *`)].filter(shown).map(rect);
  const body = (id) => document.querySelector(`#${id} .pane-body`);
  const pattern = panes.pattern;
  const pieces = pattern.content.children.filter((c) => c.isMesh || c.isLineSegments);
  return {
    target: { model: screenBox(worldBox([panes.target.mesh]), panes.target.camera, body('pane-target')), view: rect(body('pane-target')), boxes: boxesOver('pane-target') },
    inflated: { model: screenBox(worldBox([panes.inflated.outerMesh]), panes.inflated.camera, body('pane-inflated')), view: rect(body('pane-inflated')), boxes: boxesOver('pane-inflated') },
    pattern: { model: screenBox(worldBox(pieces), pattern.camera, body('pane-pattern')), view: rect(body('pane-pattern')),
      boxes: [...boxesOver('pane-pattern'), ...[...document.querySelectorAll('.messages .message')].filter(shown).map(rect)] },
  };
});

const overlap = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
const round = (r) => [r.left, r.top, r.right, r.bottom].map(Math.round).join(', ');

function assertClear(seen, label) {
  for (const [pane, { model, view, boxes }] of Object.entries(seen)) {
    assert.ok(model.right > model.left && model.bottom > model.top, `${label}: the ${pane} pane shows something`);
    assert.ok(model.left >= view.left - 1 && model.right <= view.right + 1 && model.top >= view.top - 1 && model.bottom <= view.bottom + 1,
      `${label}: the ${pane} pane's content (${round(model)}) lies in its view (${round(view)})`);
    for (const box of boxes) assert.ok(!overlap(model, box), `${label}: ${box.name} (${round(box)}) covers the ${pane} pane's content (${round(model)})`);
  }
}

// assertClear once the panes have settled: looked at each frame for up to 10 s (a loaded machine draws the pieces'
// new cut lines and frames them a few frames later), then asserted.
async function clearWithin(page, label) {
  for (const start = Date.now(); Date.now() - start < 10000; await nextFrames(page)) {
    try {
      return assertClear(await framing(page), label);
    } catch {
      // not yet
    }
  }
  assertClear(await framing(page), label);
}

const nextFrames = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

// The koala of the gallery, its stored result shown in every pane (its live optimization runs on).
async function openKoala(page) {
  await page.evaluate(() => window.billow.test.openGalleryDesign('koala'));
  // The stored result in every pane, with the figures beside it.
  await page.waitForFunction(() => {
    const t = window.billow.test;
    return t.panes.inflated.shape && t.panes.pattern.cutLines && t.design.seams.length === 7
      && document.querySelector('#inflated-stats').childElementCount && document.querySelector('#target-stats').childElementCount;
  }, null, { timeout: 60000 });
}

test('the docked boxes and the messages leave the target, the inflated shape and the pieces clear', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await openKoala(page);
  await page.evaluate(() => {
    const t = window.billow.test;
    t.showMessage('warning', 'Seam "left ear" is shorter on one panel than on the other by 3 mm: the panels are eased together when sewn.');
    t.showMessage('notice', 'This tab autosaves your design again.');
    t.showMessage('error', 'The solver stopped unexpectedly and was restarted. Your design is safe.');
  });
  for (const [width, height] of SIZES) {
    await page.setViewportSize({ width, height });
    await page.evaluate(() => window.billow.test.setStatus(
      "Inflated the optimized panels: stopped at the optimizer's limit (150 steps) before settling; the panels may fit a little better than shown"));
    await nextFrames(page);
    assertClear(await framing(page), `${width}x${height}`);
    await screenshot(page, `layout-koala-${width}x${height}`);
  }
  // A wide allowance: the cut lines, drawn after the pieces, stand out past the margin they were framed with, and
  // the view takes them in.
  await page.setViewportSize({ width: 1400, height: 900 });
  await page.fill('#allowance-input', '100');
  await page.press('#allowance-input', 'Enter');
  await page.waitForFunction(() => Math.max(...window.billow.test.cutStatistics.seams.map((s) => s.allowance_mm)) === 100, null, { timeout: 30000 });
  await clearWithin(page, 'a 100 mm allowance');
  await screenshot(page, 'layout-koala-wide-allowance');
  // Newest first: the error came last, and is on top of the stack.
  assert.match(await page.locator('.messages .message').last().textContent(), /solver stopped/);
  assert.ok(await page.evaluate(() => {
    const m = [...document.querySelectorAll('.messages .message')];
    return m.at(-1).getBoundingClientRect().top < m[0].getBoundingClientRect().top;
  }), 'the newest message is on top of the stack');
  await page.evaluate(() => window.billow.test.clearMessages());
  await page.setViewportSize({ width: 1024, height: 768 });
  await nextFrames(page);

  // The target's figures start closed to their title (looked at now and then), the seams open. Both closed: in
  // a small window the target is shown larger, still clear of them; remembered.
  const seams = '.box[data-box="seams"] > .box-toggle';
  const figures = '.box[data-box="target-figures"] > .box-toggle';
  assert.equal(await page.getAttribute(figures, 'aria-expanded'), 'false');
  assert.equal(await page.getAttribute(seams, 'aria-expanded'), 'true');
  const before = await framing(page);
  await page.click(seams);
  assert.equal(await page.getAttribute(seams, 'aria-expanded'), 'false');
  assert.equal(await page.isVisible('#seam-panel'), false);
  // The pattern pane frames its pieces again for the narrower window a few frames later on a loaded machine, and the
  // target pane its model (the koala's live optimization keeps the worker and the page busy).
  await clearWithin(page, 'target boxes closed');
  const size = (r) => Math.max(r.right - r.left, r.bottom - r.top);
  let closed = await framing(page);
  for (const start = Date.now(); Date.now() - start < 10000 && !(size(closed.target.model) > size(before.target.model) * 1.05); ) {
    await nextFrames(page);
    closed = await framing(page);
  }
  assert.ok(size(closed.target.model) > size(before.target.model) * 1.05, `the target has more room: ${round(before.target.model)} -> ${round(closed.target.model)}`);
  await screenshot(page, 'layout-koala-target-boxes-closed');
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await page.getAttribute(seams, 'aria-expanded'), 'false', 'remembered');
  await page.click(figures);
  assert.equal(await page.isVisible('#target-stats'), true, 'the figures open from their title');
  await page.click(seams);
  assert.equal(await page.isVisible('#seam-panel'), true);
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  assert.equal(await page.isVisible('#target-stats'), true, 'opened, remembered');
  await page.click(figures);
  await page.setViewportSize({ width: 1400, height: 900 });
  assert.deepEqual(page.errors, []);
  await page.close();
});

// Every label shown over the pattern pane (not hidden as crowded), as text and client rectangle.
const shownLabels = (page) => page.$$eval('#pane-pattern .pane-labels > *', (els) => els
  .filter((e) => e.getClientRects().length > 0 && getComputedStyle(e).visibility !== 'hidden')
  .map((e) => {
    const r = e.getBoundingClientRect();
    return { text: e.firstChild?.textContent ?? '', kind: e.className, left: r.left, top: r.top, right: r.right, bottom: r.bottom };
  }));

function assertApart(labels, label) {
  for (let i = 0; i < labels.length; i++)
    for (let j = i + 1; j < labels.length; j++)
      assert.ok(!overlap(labels[i], labels[j]), `${label}: "${labels[i].text}" and "${labels[j].text}" overlap`);
}

// A cube whose file coordinates lie far from its own origin, as a part exported from a CAD assembly does.
function offsetCubeObj([ox, oy, oz], side) {
  const v = [];
  for (const x of [0, side]) for (const y of [0, side]) for (const z of [0, side]) v.push(`v ${ox + x} ${oy + y} ${oz + z}`);
  // Corners numbered 1 + 4x + 2y + z; each face two triangles, outward.
  const faces = [[1, 2, 4, 3], [5, 7, 8, 6], [1, 5, 6, 2], [3, 4, 8, 7], [1, 3, 7, 5], [2, 6, 8, 4]];
  const f = faces.flatMap(([a, b, c, d]) => [`f ${a} ${b} ${c}`, `f ${a} ${c} ${d}`]);
  return [...v, ...f].join('\n') + '\n';
}

test('a target whose file origin lies far from it is framed whole and large in its pane', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.setInputFiles('#file-input', { name: 'far-part.obj', mimeType: 'text/plain', buffer: Buffer.from(offsetCubeObj([30, 40, -20], 1)) });
  await page.waitForFunction(() => window.billow.test.panes.target.mesh, null, { timeout: 60000 });
  await nextFrames(page);
  const seen = await page.evaluate(() => {
    const pane = window.billow.test.panes.target;
    const Vector3 = pane.camera.position.constructor;
    const r = pane.element.getBoundingClientRect();
    const box = pane.mesh.geometry.boundingBox.clone().applyMatrix4(pane.mesh.matrixWorld);
    let left = Infinity, top = Infinity, right = -Infinity, bottom = -Infinity;
    for (const x of [box.min.x, box.max.x]) for (const y of [box.min.y, box.max.y]) for (const z of [box.min.z, box.max.z]) {
      const p = new Vector3(x, y, z).project(pane.camera);
      const sx = r.left + ((p.x + 1) / 2) * r.width, sy = r.top + ((1 - p.y) / 2) * r.height;
      left = Math.min(left, sx); right = Math.max(right, sx); top = Math.min(top, sy); bottom = Math.max(bottom, sy);
    }
    return { model: { left, top, right, bottom }, square: pane.square };
  });
  const { model, square } = seen;
  const inSquare = model.left >= square.left - 1 && model.right <= square.left + square.side + 1
    && model.top >= square.top - 1 && model.bottom <= square.top + square.side + 1;
  assert.ok(inSquare, `the cube (${round(model)}) lies in the framed square (${round({ left: square.left, top: square.top, right: square.left + square.side, bottom: square.top + square.side })})`);
  // The cube's bounding sphere spans the square: its screen box about 0.6 of the side (before, 0.1 in a corner).
  assert.ok(Math.max(model.right - model.left, model.bottom - model.top) > 0.4 * square.side, `the cube is framed large: ${round(model)} in a square of ${Math.round(square.side)} px`);
  const centre = [(model.left + model.right) / 2 - square.left - square.side / 2, (model.top + model.bottom) / 2 - square.top - square.side / 2];
  assert.ok(Math.hypot(...centre) < 0.1 * square.side, `the cube is framed in the middle (off by ${centre.map(Math.round)} px)`);
  await screenshot(page, 'layout-far-origin');
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('no two labels of the sheet view overlap: the pieces\', the sheet\'s and the seams\'', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await openKoala(page);
  // The live optimization stops: its result would replace the pieces and their labels while they are measured. It
  // starts after the stored result is shown (once the seams are traced), so it is waited for before it is stopped.
  await page.waitForFunction(() => window.billow.test.optimizing || window.billow.test.optimized, null, { timeout: 60000 });
  await page.evaluate(() => window.billow.test.stopWork());
  await page.click('#pattern-view [data-view="sheet"]');
  await page.waitForFunction(() => window.billow.test.panes.pattern.sheetMesh, null, { timeout: 30000 });
  await nextFrames(page);
  const panels = await page.evaluate(() => window.billow.test.panes.pattern.pattern.panels.length);
  const labels = await shownLabels(page);
  const pieces = labels.filter((l) => /panel-label/.test(l.kind));
  assert.ok(pieces.length >= panels / 2, `${pieces.length} of ${panels} piece labels shown`);
  assert.equal(labels.filter((l) => /sheet-label/.test(l.kind)).length, 2, 'the sheet\'s width and length are always shown');
  assertApart(labels, 'sheet');
  for (const l of pieces.filter((p) => /compact/.test(p.kind))) assert.match(l.text, /^\d+$/, 'a crowded piece shows its number');
  await screenshot(page, 'layout-koala-sheet');

  // With the seams' labels (S1, S2, ...) and at other zooms.
  await page.click('#seams-button');
  for (const zoom of [1, 0.6, 1.8]) {
    await page.evaluate((z) => {
      const pane = window.billow.test.panes.pattern;
      pane.camera.zoom = z;
      pane.camera.updateProjectionMatrix();
      pane.viewport.requestRender();
    }, zoom);
    await nextFrames(page);
    const withSeams = await shownLabels(page);
    // Zoomed out, the pieces' numbers may leave no room for any seam's label.
    if (zoom >= 1) assert.ok(withSeams.some((l) => /seam-label/.test(l.kind)), `zoom ${zoom}: some seam labels shown`);
    assertApart(withSeams, `seams shown, zoom ${zoom}`);
  }
  await screenshot(page, 'layout-koala-sheet-seams');
  assert.deepEqual(page.errors, []);
  await page.close();
});
