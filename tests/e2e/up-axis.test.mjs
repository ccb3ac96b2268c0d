// The target's up axis in the browser: the koala written Z up (as CAD and 3D-printing tools write it) opens
// standing on its feet with a notice, Height measured along Z; the Up select turns it, undo turns it back,
// seams drawn on it stay on their triangles, picking works in the turned frame, and a reload keeps the axis.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { openFreshPage, openPage, screenshot, useBrowser, MESHES } from './harness.mjs';
import { surfaceScreenPoints } from './seams-helpers.mjs';

const env = useBrowser();

// koala.obj (Y up) as a Z-up tool writes it: (x, y, z) -> (x, -z, y).
function koalaZUp() {
  const lines = readFileSync(join(MESHES, 'koala.obj'), 'utf8').split('\n');
  return lines
    .map((line) => {
      const [v, x, y, z] = line.trim().split(/\s+/);
      return v === 'v' ? `v ${x} ${-Number(z)} ${y}` : line;
    })
    .join('\n');
}

// The target stats' width, height and depth in meters.
async function statSize(page) {
  const text = await page.textContent('#target-stats dd[data-stat="size"]');
  return text.split('×').map((s) => {
    const [value, unit] = s.trim().split(/\s+/);
    return Number(value) * { m: 1, cm: 0.01, mm: 0.001 }[unit];
  });
}

// How the target stands in its pane: its on-screen width and height in pixels, the screen height of its top
// and bottom along its own axis `axis` (2, z: the koala's head and feet in the Z-up file), which world
// direction its own z axis points to, and whether the inflated pane is turned the same way.
function standing(page, axis = 2) {
  return page.evaluate((k) => {
    const pane = window.billow.test.panes.target;
    const mesh = pane.mesh;
    const Vector3 = mesh.position.constructor;
    const position = mesh.geometry.getAttribute('position');
    const rect = pane.element.getBoundingClientRect();
    let [left, right, top, bottom] = [Infinity, -Infinity, Infinity, -Infinity];
    let head = null;
    let feet = null;
    const v = new Vector3();
    for (let i = 0; i < position.count; i++) {
      v.fromBufferAttribute(position, i);
      const z = v.getComponent(k);
      mesh.localToWorld(v).project(pane.camera);
      const x = ((v.x + 1) / 2) * rect.width;
      const y = ((1 - v.y) / 2) * rect.height;
      [left, right, top, bottom] = [Math.min(left, x), Math.max(right, x), Math.min(top, y), Math.max(bottom, y)];
      if (!head || z > head.z) head = { z, y };
      if (!feet || z < feet.z) feet = { z, y };
    }
    const zAxis = new Vector3(0, 0, 1).transformDirection(mesh.matrixWorld);
    const inflated = window.billow.test.panes.inflated.group.quaternion;
    return {
      width: right - left, height: bottom - top, headY: head.y, feetY: feet.y, zAxis: [zAxis.x, zAxis.y, zAxis.z],
      sameTurn: Math.abs(inflated.dot(pane.group.quaternion)) > 1 - 1e-9,
    };
  }, axis);
}

// Picks the target at the screen point of its own point `position` and returns the pick (null: nothing there).
function pickAt(page, position) {
  return page.evaluate((p) => {
    const pane = window.billow.test.panes.target;
    const world = pane.mesh.localToWorld(new pane.mesh.position.constructor(...p)).project(pane.camera);
    const rect = pane.element.getBoundingClientRect();
    const event = { clientX: rect.left + ((world.x + 1) / 2) * rect.width, clientY: rect.top + ((1 - world.y) / 2) * rect.height };
    return pane.pick(event);
  }, position);
}

const near = (a, b, tolerance, what) => assert.ok(Math.abs(a - b) <= tolerance, `${what}: ${a} is not ${b} ± ${tolerance}`);
const waitSegments = (page, n) =>
  page.waitForFunction((count) => window.billow.test.segmentation?.segments.length === count, n, { timeout: 30000 });

test('a Z-up file opens standing Z up; Up turns it, undo turns it back, Height follows the axis', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.setInputFiles('#file-input', { name: 'koala-zup.obj', mimeType: 'text/plain', buffer: Buffer.from(koalaZUp()) });
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'koala-zup.obj');

  // The guess: Z up, said in a notice that names the way to change it.
  assert.equal(await page.inputValue('#up-select'), '+z');
  const notice = await page.locator('.message.notice', { hasText: 'koala-zup.obj' }).textContent();
  assert.match(notice, /Z up.*Height along Z.*choose another axis in Up/);
  const height = Number(await page.inputValue('#height-input'));
  // koala.obj is 3.76 wide, 5.34 high and 9.21 long in its own units: standing, its height is the 5.34.
  let [w, h, d] = await statSize(page);
  near(h, height, 0.001, 'H is the height');
  near(w / h, 3.76012 / 5.33893, 0.01, 'W / H standing Z up');
  near(d / h, 9.21337 / 5.33893, 0.01, 'D / H standing Z up');
  // The classroom's figure for the target reads its height as it stands too.
  const classroomHeight = await page.evaluate(() => window.billow.test.classroomFigures('target')[0][1]);
  assert.equal(classroomHeight, `${Math.round(100 * height)} cm`);
  const upright = await standing(page);
  assert.ok(upright.zAxis[1] > 0.999, `the file's z axis points up on screen: ${upright.zAxis}`);
  assert.ok(upright.headY < upright.feetY - 0.5 * upright.height, `the head is above the feet: ${JSON.stringify(upright)}`);
  assert.ok(upright.sameTurn, 'the inflated pane stands the same way');
  await screenshot(page, 'up-axis-z-up');

  // A seam on its front, drawn in the turned frame: its points are the target's triangles.
  await page.click('#pane-target .pane-body'); // focus out of the file field: shortcuts apply to the page
  await page.keyboard.press('d');
  const points = await surfaceScreenPoints(page, [[0.5, -1, 0.6], [-0.5, -1, 0.6], [0, -1, -0.2]]);
  for (const p of [...points, points[0]]) {
    await page.mouse.move(p.x, p.y);
    await page.waitForTimeout(60);
    await page.mouse.click(p.x, p.y);
    await page.waitForTimeout(120);
  }
  await waitSegments(page, 2);
  const seams = await page.evaluate(() => JSON.stringify(window.billow.test.design.seams));
  await page.keyboard.press('v');

  // Y up, the file's own: the koala stands on its tail, Height along its length.
  await page.selectOption('#up-select', '+y');
  await page.waitForFunction(() => window.billow.test.design.target.up === undefined);
  [w, h, d] = await statSize(page);
  near(h, height, 0.001, 'H is the height');
  near(w / h, 3.76012 / 9.21337, 0.01, 'W / H standing Y up');
  const onTail = await standing(page);
  assert.ok(onTail.zAxis[2] > 0.999, `the file's z axis points to the viewer: ${onTail.zAxis}`);
  assert.ok(onTail.height / onTail.width > 1.3 * (upright.height / upright.width), `taller on its tail: ${JSON.stringify(onTail)}`);
  assert.ok(onTail.sameTurn, 'the inflated pane stands the same way');
  assert.equal(await page.locator('.message.notice', { hasText: 'koala-zup.obj' }).count(), 0, 'the guess notice goes');
  assert.equal(await page.evaluate(() => JSON.stringify(window.billow.test.design.seams)), seams, 'the seams are where they were');
  await waitSegments(page, 2);

  // Undo: Z up again, the seam still on the same triangles; then Height applies along Z.
  await page.click('#undo-button');
  assert.equal(await page.inputValue('#up-select'), '+z');
  [w, h] = await statSize(page);
  near(w / h, 3.76012 / 5.33893, 0.01, 'W / H after undo');
  assert.ok((await standing(page)).zAxis[1] > 0.999, 'standing Z up after undo');
  assert.equal(await page.evaluate(() => JSON.stringify(window.billow.test.design.seams)), seams);
  // Picking in the turned frame: the seam's first point, placed from its {face, bary}, is found there.
  const first = await page.evaluate(() => {
    const { face, bary } = window.billow.test.design.seams[0].points[0];
    const pane = window.billow.test.panes.target;
    const pos = pane.mesh.geometry.getAttribute('position');
    const index = pane.mesh.geometry.index.array;
    const corner = (c, k) => pos.array[3 * index[3 * face + c] + k];
    return { face, position: [0, 1, 2].map((k) => bary[0] * corner(0, k) + bary[1] * corner(1, k) + bary[2] * corner(2, k)) };
  });
  const picked = await pickAt(page, first.position);
  assert.ok(picked, 'something is under the seam point');
  picked.position.forEach((x, k) => near(x, first.position[k], 0.01, `picked point axis ${k}`));
  await page.fill('#height-input', '1.2');
  await page.press('#height-input', 'Enter');
  [w, h] = await statSize(page);
  near(h, 1.2, 0.001, 'H after a new height');
  near(w, (1.2 * 3.76012) / 5.33893, 0.002, 'W follows the height along Z');
  await screenshot(page, 'up-axis-undo');
  assert.deepEqual(page.errors, []);

  // A reload keeps the axis (autosave), with no guess made again.
  const again = await openPage(env.context, env.server.url);
  await again.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'koala-zup.obj');
  assert.equal(await again.inputValue('#up-select'), '+z');
  assert.ok((await standing(again)).zAxis[1] > 0.999, 'standing Z up after a reload');
  assert.equal(await again.locator('.message.notice', { hasText: 'looks made' }).count(), 0);
  assert.deepEqual(again.errors, []);
  await again.close();
  await page.close();
});

test('a Y-up file opens Y up with no notice', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.setInputFiles('#file-input', { name: 'koala.obj', mimeType: 'text/plain', buffer: readFileSync(join(MESHES, 'koala.obj')) });
  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === 'koala.obj');
  assert.equal(await page.inputValue('#up-select'), '+y');
  assert.equal(await page.locator('.message.notice', { hasText: 'looks made' }).count(), 0);
  const [w, h] = await statSize(page);
  near(w / h, 3.76012 / 5.33893, 0.01, 'W / H');
  const shown = await standing(page, 1);
  assert.ok(shown.headY < shown.feetY - 0.5 * shown.height, `standing on its feet: ${JSON.stringify(shown)}`);
  assert.deepEqual(page.errors, []);
  await page.close();
});
