// Drawing seams in the browser: a closed seam on the sphere gives two segments; a second seam snapped
// to it at both ends gives three; a control point drags; undo/redo; the design survives a reload and
// travels by link.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { serve, launch, openPage, screenshot, useBrowser, MESHES } from './harness.mjs';
import { surfaceScreenPoints, clickOnSeam } from './seams-helpers.mjs';

const env = useBrowser();

const summary = (page) => page.textContent('#seam-panel .summary');
// Waits for the seam panel's summary to match; a timeout says what it showed instead.
const waitSummary = (page, re) =>
  page
    .waitForFunction((source) => new RegExp(source).test(document.querySelector('#seam-panel .summary')?.textContent), re.source)
    .catch(async (error) => {
      throw new Error(`seam summary never matched ${re}; it shows "${await summary(page)}" (${error.message})`);
    });

async function openSphere(page) {
  await page.selectOption('#example-select', 'sphere');
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'sphere.obj');
  await page.waitForFunction(() => !window.billow.test.design.seams.length);
}

async function clickAt(page, p) {
  await page.mouse.move(p.x, p.y);
  await page.waitForTimeout(60);
  await page.mouse.click(p.x, p.y);
  await page.waitForTimeout(120);
}

// A closed triangle-shaped seam on the front of the sphere, then a seam across it snapped at both ends.
async function drawTwoSeams(page) {
  await page.keyboard.press('d');
  const [a, b, c] = await surfaceScreenPoints(page, [[0.5, 0.6, 1], [-0.3, 0.5, 1], [0.1, -0.3, 1]]);
  for (const p of [a, b, c]) await clickAt(page, p);
  // Before closing, the cursor over the first point shows the snap (orange).
  await page.mouse.move(a.x, a.y);
  const snapColor = () => window.billow.test.panes.target.seams.cursor.material.color.getHexString();
  // Wait for the cursor to turn (under load a frame may be late), then check it did.
  await page.waitForFunction(() => window.billow.test.panes.target.seams.cursor.material.color.getHexString() === 'd55e00', null, { timeout: 5000 }).catch(() => {});
  assert.equal(await page.evaluate(snapColor), 'd55e00');
  await clickAt(page, a);
  await waitSummary(page, /1 seam, 2 segments/);
  // Across the loop: from the middle of the curve a-b to the middle of b-c, so it snaps at both ends.
  await clickOnSeam(page, 0, 0);
  await clickOnSeam(page, 0, 1);
  await page.keyboard.press('Enter');
  await waitSummary(page, /2 seams, 3 segments/);
}

test('draw a closed seam (two segments), then a snapped seam across it (three)', async () => {
  const page = await openPage(env.context, env.server.url);
  await openSphere(page);
  await drawTwoSeams(page);
  const design = await page.evaluate(() => window.billow.test.design);
  assert.equal(design.seams.length, 2);
  assert.equal(design.seams[0].closed, true);
  assert.equal(design.seams[0].points.length, 3);
  assert.equal(design.seams[1].closed, false);
  for (const p of design.seams[1].points) assert.equal(typeof p.face, 'number');
  const seg = await page.evaluate(() => window.billow.test.segmentation);
  assert.equal(seg.segments.length, 3);
  assert.ok(seg.segments.every((s) => s.isDisk));
  assert.equal(seg.problems.filter((p) => p.severity === 'error').length, 0);
  await screenshot(page, 'seams-three-segments');
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('drag a control point, undo and redo, reload, and open the shared link', async () => {
  const page = await openPage(env.context, env.server.url);
  await openSphere(page);
  await drawTwoSeams(page);
  const before = await page.evaluate(() => window.billow.test.design.seams[0].points[2]);
  await page.keyboard.press('e');
  const [c, target] = await surfaceScreenPoints(page, [[0.1, -0.3, 1], [0.0, -0.6, 1]]);
  await page.mouse.move(c.x, c.y);
  await page.mouse.down();
  await page.mouse.move(target.x, target.y, { steps: 6 });
  await page.mouse.up();
  const moved = await page.evaluate(() => window.billow.test.design.seams[0].points[2]);
  assert.notDeepEqual(moved, before, 'the control point moved');
  await waitSummary(page, /2 seams, 3 segments/);
  await page.keyboard.press('Control+z');
  assert.deepEqual(await page.evaluate(() => window.billow.test.design.seams[0].points[2]), before, 'one undo step undoes the whole drag');
  await page.keyboard.press('Control+z');
  assert.equal(await page.evaluate(() => window.billow.test.design.seams.length), 1);
  await waitSummary(page, /1 seam, 2 segments/);
  await page.keyboard.press('Control+Shift+z');
  await page.keyboard.press('Control+Shift+z');
  assert.deepEqual(await page.evaluate(() => window.billow.test.design.seams[0].points[2]), moved);
  await waitSummary(page, /2 seams, 3 segments/);

  await page.waitForTimeout(300);
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]');
  await waitSummary(page, /2 seams, 3 segments/);

  const url = await page.evaluate(() => window.billow.test.shareLink());
  const other = await launch();
  try {
    const fresh = await openPage(other, url);
    await waitSummary(fresh, /2 seams, 3 segments/);
    assert.deepEqual(await fresh.evaluate(() => window.billow.test.design.seams), await page.evaluate(() => window.billow.test.design.seams));
    assert.deepEqual(fresh.errors, []);
  } finally {
    await other.close();
  }
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('a design on the designer\'s own mesh file travels by link with its mesh, a 16k-triangle one too', async () => {
  const page = await openPage(env.context, env.server.url);
  await page.setInputFiles('#file-input', { name: 'my ball.obj', mimeType: 'text/plain', buffer: readFileSync(join(MESHES, 'sphere.obj')) });
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'my ball.obj');
  await page.waitForFunction(() => !window.billow.test.design.seams.length);
  await drawTwoSeams(page);
  const url = await page.evaluate(() => window.billow.test.shareLink());
  assert.match(url, /#design=[A-Za-z0-9_-]+&mesh=[A-Za-z0-9_-]+$/);
  const other = await launch();
  try {
    const fresh = await openPage(other, url);
    await waitSummary(fresh, /2 seams, 3 segments/);
    assert.equal(await fresh.textContent('#target-stats dd[data-stat="file"]'), 'my ball.obj');
    assert.equal(await fresh.evaluate(() => window.billow.test.target.indices.length), 1280 * 3);
    // The same control points in space (the link renumbers the triangles, so faces and barycentrics differ).
    // The grid moves a point by at most 0.002 on this sphere (edges 0.15); a point snapped onto another seam
    // follows that seam as traced on the received mesh, a little further.
    const places = () => window.billow.test.design.seams.map((seam) => ({
      closed: seam.closed,
      points: seam.points.map(({ face, bary }) => {
        const { positions, indices } = window.billow.test.target;
        return [0, 1, 2].map((a) => bary.reduce((sum, w, c) => sum + w * positions[3 * indices[3 * face + c] + a], 0));
      }),
    }));
    const sent = await page.evaluate(places);
    const received = await fresh.evaluate(places);
    assert.equal(received.length, sent.length);
    sent.forEach((seam, i) => {
      assert.equal(received[i].closed, seam.closed);
      assert.equal(received[i].points.length, seam.points.length);
      seam.points.forEach((p, k) => {
        const d = Math.hypot(...p.map((x, a) => x - received[i].points[k][a]));
        assert.ok(d < 0.02, `seam ${i} point ${k} moved ${d}`);
      });
    });
    assert.deepEqual(fresh.errors, []);
  } finally {
    await other.close();
  }
  await page.setInputFiles('#file-input', { name: 'hand.obj', mimeType: 'text/plain', buffer: readFileSync(join(MESHES, 'hand.obj')) });
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'hand.obj', null, { timeout: 60000 });
  const handUrl = await page.evaluate(() => window.billow.test.shareLink());
  assert.match(handUrl, /#design=[A-Za-z0-9_-]+&mesh=[A-Za-z0-9_-]+$/, 'hand.obj (15,982 triangles) travels in its link');
  assert.ok(handUrl.length < 61000, `${handUrl.length} characters`);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('mirror symmetry: a seam drawn on one side gets a twin; dragging, undo and delete act on both', async () => {
  const page = await openPage(env.context, env.server.url);
  await openSphere(page);
  await page.selectOption('#seam-panel select.symmetry', 'x');
  await page.waitForFunction(() => window.billow.test.design.symmetry?.axis === 'x');
  await page.keyboard.press('d');
  const [a, b, c] = await surfaceScreenPoints(page, [[0.7, 0.4, 0.8], [0.3, 0.0, 1], [0.7, -0.4, 0.8]]);
  for (const p of [a, b, c]) await clickAt(page, p);
  await clickAt(page, a); // closes the loop
  await waitSummary(page, /2 seams, 3 segments/);
  const position = (seam, k) => page.evaluate(([i, j]) => window.billow.test.positionOf(window.billow.test.design.seams[i].points[j]), [seam, k]);
  const mirrorError = async () => {
    let worst = 0;
    for (let k = 0; k < 3; k++) {
      const [p, q] = [await position(0, k), await position(1, k)];
      worst = Math.max(worst, Math.hypot(p[0] + q[0], p[1] - q[1], p[2] - q[2])); // x -> -x on the sphere centred at 0
    }
    return worst;
  };
  assert.ok((await mirrorError()) < 0.02, 'the twin mirrors the seam across x = 0');
  assert.equal(await page.evaluate(() => window.billow.test.design.seams[1].mirror), 0);
  await screenshot(page, 'seams-mirror-symmetry');

  await page.keyboard.press('e');
  const [grab, to] = await surfaceScreenPoints(page, [[0.3, 0.0, 1], [0.45, 0.15, 1]]);
  const before = await position(1, 1);
  await page.mouse.move(grab.x, grab.y);
  await page.mouse.down();
  await page.mouse.move(to.x, to.y, { steps: 6 });
  await page.mouse.up();
  await waitSummary(page, /2 seams, 3 segments/);
  const after = await position(1, 1);
  assert.ok(Math.hypot(after[0] - before[0], after[1] - before[1], after[2] - before[2]) > 0.05, 'the twin point followed the drag');
  assert.ok((await mirrorError()) < 0.02, 'still mirrored');
  await page.keyboard.press('Control+z');
  const undone = await position(1, 1);
  assert.ok(Math.hypot(undone[0] - before[0], undone[1] - before[1], undone[2] - before[2]) < 1e-9, 'one undo restores both seams');
  await page.click('#seam-panel .seam-list .seam:first-child .delete');
  await waitSummary(page, /No seams yet/);
  await page.keyboard.press('Control+z');
  await waitSummary(page, /2 seams, 3 segments/);
  assert.deepEqual(page.errors, []);
  await page.close();
});

// A finger tap through the DevTools protocol (touch events, which the page receives as pointer events with
// pointerType "touch"), a little off the aimed point as fingers are.
async function touchTap(cdp, p, wobble = 0) {
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: p.x, y: p.y, radiusX: 8, radiusY: 8 }] });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ x: p.x + wobble, y: p.y + wobble, radiusX: 8, radiusY: 8 }] });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await new Promise((r) => setTimeout(r, 150));
}

test('touch: tapping points and "Close loop" draws a seam; a finger drags a control point', async () => {
  const page = await openPage(env.context, env.server.url);
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Emulation.setTouchEmulationEnabled', { enabled: true, maxTouchPoints: 5 });
  await openSphere(page);
  const kinds = [];
  await page.exposeFunction('recordPointer', (kind) => kinds.push(kind));
  await page.evaluate(() => window.billow.test.panes.target.element.addEventListener('pointerdown', (e) => window.recordPointer(e.pointerType)));
  await page.click('#seam-panel button[data-tool="draw"]');
  assert.equal(await page.isHidden('#seam-panel .drawbar'), true, 'no draw buttons before the first point');
  const [a, b, c] = await surfaceScreenPoints(page, [[0.5, 0.6, 1], [-0.3, 0.5, 1], [0.1, -0.3, 1]]);
  await touchTap(cdp, a, 5); // a finger wobbles a few pixels (7 px, more than a mouse may): still a tap
  await touchTap(cdp, b, 5);
  await page.waitForFunction(() => !document.querySelector('#seam-panel .drawbar').hidden);
  assert.equal(await page.isDisabled('#seam-panel .drawbar button:has-text("Close loop")'), true, 'two points cannot close a loop');
  await touchTap(cdp, c, 5);
  await page.waitForFunction(() => !document.querySelector('#seam-panel .drawbar button:nth-child(2)').disabled);
  assert.ok(kinds.length >= 3 && kinds.every((k) => k === 'touch'), `pointer types ${kinds}`);
  await page.tap('#seam-panel .drawbar button:has-text("Close loop")').catch(() => page.click('#seam-panel .drawbar button:has-text("Close loop")'));
  await waitSummary(page, /1 seam, 2 segments/);
  const seam = await page.evaluate(() => window.billow.test.design.seams[0]);
  assert.equal(seam.closed, true);
  assert.equal(seam.points.length, 3);
  assert.equal(await page.isHidden('#seam-panel .drawbar'), true);

  // Edit with a finger: grab the control point a little off target (touch reaches farther than a mouse).
  await page.click('#seam-panel button[data-tool="edit"]');
  const [to] = await surfaceScreenPoints(page, [[-0.5, 0.7, 1]]);
  // Where control point 1 is on screen now (where the tap put it), and 15 px off it: beyond a mouse's reach.
  const grip = await page.evaluate(() => {
    const t = window.billow.test;
    const pane = t.panes.target;
    const c = t.seamTraces()[0].controls;
    const p = pane.mesh.localToWorld(new pane.mesh.position.constructor(c[3], c[4], c[5])).project(pane.camera);
    const rect = pane.element.getBoundingClientRect();
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  });
  const start = { x: grip.x + 14, y: grip.y + 6 };
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: start.x, y: start.y }] });
  for (let k = 1; k <= 6; k++)
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ x: start.x + ((to.x - start.x) * k) / 6, y: start.y + ((to.y - start.y) * k) / 6 }] });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await page.waitForFunction((before) => JSON.stringify(window.billow.test.design.seams[0].points[1]) !== before, JSON.stringify(seam.points[1]));
  await waitSummary(page, /1 seam, 2 segments/);
  await screenshot(page, 'seams-touch');
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('Escape cancels a seam being drawn and Backspace removes its last point', async () => {
  const page = await openPage(env.context, env.server.url);
  await openSphere(page);
  await page.keyboard.press('d');
  const [a, b, c] = await surfaceScreenPoints(page, [[0.5, 0.6, 1], [-0.3, 0.5, 1], [0.1, -0.3, 1]]);
  await clickAt(page, a);
  await clickAt(page, b);
  await page.keyboard.press('Backspace');
  await clickAt(page, c);
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 1);
  assert.equal(await page.evaluate(() => window.billow.test.design.seams[0].points.length), 2, 'a and c');
  await clickAt(page, b);
  await page.keyboard.press('Escape');
  await page.waitForTimeout(200);
  assert.equal(await page.evaluate(() => window.billow.test.design.seams.length), 1, 'nothing added');
  assert.match(await summary(page), /1 seam/);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('a seam that would cross itself or cut off a tiny piece is shown as such while it is drawn', async () => {
  const page = await openPage(env.context, env.server.url);
  await openSphere(page);
  await page.keyboard.press('d');
  const note = page.locator('#pane-target ~ .pane-labels .draft-warning, .draft-warning').first();
  const previewColor = () => page.evaluate(() => window.billow.test.panes.target.seams.items.children.at(-1)?.material.color.getHexString());
  // A bow tie: a, b, c clicked, the cursor at d: the stretch c-d crosses a-b.
  const [a, b, c, d] = await surfaceScreenPoints(page, [[0.6, 0.6, 1], [-0.6, -0.6, 1], [0.6, -0.6, 1], [-0.6, 0.6, 1]]);
  for (const p of [a, b, c]) await clickAt(page, p);
  assert.equal(await note.isHidden(), true, 'three points that do not cross: no note');
  await page.mouse.move(d.x, d.y, { steps: 4 });
  await note.waitFor({ state: 'visible', timeout: 10000 });
  assert.equal(await note.textContent(), 'Crosses itself here');
  assert.equal(await previewColor(), 'c62828', 'the preview turns red');
  // The note sits by the crossing, between the four points on screen.
  const box = await note.boundingBox();
  assert.ok(box.x > Math.min(a.x, d.x) - 40 && box.x < Math.max(a.x, c.x) + 40, JSON.stringify({ box, a, c }));
  await screenshot(page, 'seams-draft-crossing');
  // Back off to a point that does not cross: the note goes.
  const [e] = await surfaceScreenPoints(page, [[0.9, -0.1, 1]]);
  await page.mouse.move(e.x, e.y, { steps: 4 });
  await note.waitFor({ state: 'hidden', timeout: 10000 });
  assert.equal(await previewColor(), '2f6fdd');
  await page.keyboard.press('Escape');

  // Zoomed in, a loop of three clicks a few pixels apart: closing it would cut off a tiny piece.
  const [centre] = await surfaceScreenPoints(page, [[0, 0, 1]]);
  await page.mouse.move(centre.x, centre.y);
  for (let k = 0; k < 4; k++) await page.mouse.wheel(0, -300);
  await page.waitForTimeout(300);
  const [m] = await surfaceScreenPoints(page, [[0.2, 0.1, 1]]);
  const loop = [{ x: m.x - 10, y: m.y + 8 }, { x: m.x + 10, y: m.y + 8 }, { x: m.x, y: m.y - 13 }];
  for (const p of loop) await clickAt(page, p);
  await page.mouse.move(loop[0].x, loop[0].y, { steps: 3 });
  await note.waitFor({ state: 'visible', timeout: 10000 });
  assert.equal(await note.textContent(), 'Closing here: cuts off a tiny piece');
  await page.keyboard.press('Escape');
  await note.waitFor({ state: 'hidden', timeout: 5000 });
  assert.equal(await page.evaluate(() => window.billow.test.design.seams.length), 0, 'nothing was committed');
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('an internal connection joins two seams: listed, drawn translucent, undoable and deletable', async () => {
  const page = await openPage(env.context, env.server.url);
  await openSphere(page);
  await page.keyboard.press('d');
  const [a, b, c, d] = await surfaceScreenPoints(page, [[0.6, 0.6, 1], [0.1, 0.7, 1], [-0.6, -0.2, 1], [-0.1, -0.5, 1]]);
  await clickAt(page, a);
  await clickAt(page, b);
  await page.keyboard.press('Enter');
  await clickAt(page, c);
  await clickAt(page, d);
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 2);
  await page.click('#seam-panel .seam:nth-child(1) .name');
  await page.click('#seam-panel .seam:nth-child(2) .connect');
  assert.deepEqual(await page.evaluate(() => window.billow.test.design.connections), [{ seams: [0, 1] }]);
  assert.match(await page.textContent('#seam-panel .connection'), /Internal panel: Seam 1 ↔ Seam 2/);
  assert.equal(await page.evaluate(() => window.billow.test.panes.target.connections.children.length), 1);
  await page.keyboard.press('Control+z');
  assert.equal(await page.evaluate(() => window.billow.test.design.connections.length), 0);
  await page.keyboard.press('Control+Shift+z');
  assert.equal(await page.evaluate(() => window.billow.test.design.connections.length), 1);
  await screenshot(page, 'seams-connection');
  await page.click('#seam-panel .connection .delete');
  assert.equal(await page.evaluate(() => window.billow.test.design.connections.length), 0);
  assert.equal(await page.evaluate(() => window.billow.test.panes.target.connections.children.length), 0);
  assert.deepEqual(page.errors, []);
  await page.close();
});
