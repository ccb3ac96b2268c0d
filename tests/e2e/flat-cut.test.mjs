// Flat-cut layouts in one action. The section tool: the plane through the clicked point, across the model's
// x, y or z as it stands or across the view, previewed under the pointer; a click lays the loop through that
// point as an ordinary seam (control points, undo, saved with the design), or a gusset band's two and the seam
// across its strip; a band's width changed in the seam panel lays it again in one undo step. The outline as
// seen, for a front and a back panel, or with a band width a gusset band around it. A sheet narrower than a
// piece is offered the width that fits.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openFreshPage, screenshot, useBrowser } from './harness.mjs';
import { implicitMesh } from '../node/implicit-mesh.mjs';

const env = useBrowser();

// The client point at the middle of the target pane's framed square (on the model for the examples).
const middleOfView = (page) => page.evaluate(() => {
  const s = window.billow.test.panes.target.square;
  return { x: s.left + s.side / 2, y: s.top + s.side / 2 };
});

// Turns the target pane's view to look at the model from `direction` (its own axes, as it stands).
const lookFrom = (page, direction) =>
  page.evaluate((direction) => {
    const pane = window.billow.test.panes.target;
    const distance = pane.camera.position.distanceTo(pane.controls.target);
    pane.camera.position.copy(pane.controls.target).addScaledVector(new (pane.camera.position.constructor)(...direction), distance);
    pane.controls.update();
    pane.controls.dispatchEvent({ type: 'change' });
  }, direction);

// The control points of seam i, as positions in the target's own units, once traced.
const controls = (page, i) => page.waitForFunction((i) => {
  const trace = window.billow.test.seamTraces()[i];
  if (!trace) return null;
  const c = Array.from(trace.controls);
  return Array.from({ length: c.length / 3 }, (_, k) => c.slice(3 * k, 3 * k + 3));
}, i, { timeout: 30000 }).then((h) => h.jsonValue());

// The segmentation shown now, and the next one once an edit is cut anew (not the one before it, still shown
// while the new one is made).
const markSegmentation = (page) => page.evaluate(() => (window.shownSegmentation = window.billow.test.segmentation));
const newSegmentation = (page) => page.waitForFunction(() => {
  const s = window.billow.test.segmentation;
  return s && s !== window.shownSegmentation && { segments: s.segments.map((x) => ({ isDisk: x.isDisk })), problems: s.problems.map((p) => ({ message: p.message })) };
}, null, { timeout: 30000 }).then((h) => h.jsonValue());

test('a section seam is laid in one click, across the model or the view, and undone like any seam', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.waitForFunction(() => window.billow.test.panes.target.mesh);
  await lookFrom(page, [0.32, 0.27, 0.91]); // the cow from behind: the middle of the view on its body
  assert.equal(await page.isVisible('.section-axis'), false, 'the plane is chosen only for sections');
  await page.keyboard.press('s');
  assert.equal(await page.getAttribute('#seam-panel button[data-tool="section"]', 'aria-pressed'), 'true');
  assert.equal(await page.isVisible('.section-axis'), true);
  await page.selectOption('.section-axis', 'y');
  const at = await middleOfView(page);
  await page.mouse.move(at.x + 3, at.y);
  await page.mouse.move(at.x, at.y);
  const preview = await page.evaluate(() => window.billow.test.seamPreview?.[0]?.length ?? 0);
  assert.ok(preview > 3 * 20, `the loop is previewed under the pointer (${preview / 3} points)`);
  await screenshot(page, 'flat-cut-section-preview');
  await page.mouse.move(5, 5); // out of the pane: no section previewed there
  assert.equal(await page.evaluate(() => window.billow.test.seamPreview), null, 'the preview goes with the pointer');
  await page.mouse.move(at.x, at.y);
  await page.mouse.click(at.x, at.y);
  await page.waitForFunction(() => window.billow.test.segmentation?.segments?.length === 2, null, { timeout: 30000 });
  const seam = await page.evaluate(() => window.billow.test.design.seams[0]);
  assert.equal(seam.closed, true);
  assert.equal(seam.smooth, false, 'surface paths between the points follow the section');
  assert.ok(seam.points.length >= 12 && seam.points.every((p) => Number.isInteger(p.face) && p.bary.length === 3), JSON.stringify(seam.points[0]));
  assert.deepEqual(await page.$$eval('#seam-panel .problem', (els) => els.map((e) => e.textContent)), [], 'a clean cut: no problem');
  // Across Y as the model stands (Y up here): every control point at one height.
  const ys = (await controls(page, 0)).map((p) => p[1]);
  assert.ok(Math.max(...ys) - Math.min(...ys) < 1e-6, `one plane: heights ${Math.min(...ys)} to ${Math.max(...ys)}`);
  assert.equal(await page.evaluate(() => window.billow.test.seamPreview), null, 'the preview gives way to the seam');
  await page.waitForTimeout(300);
  await screenshot(page, 'flat-cut-section-laid');

  // Undo takes it away, redo brings it back.
  await page.click('#undo-button');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 0);
  await page.click('#redo-button');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 1);

  // Across the view: a plane facing the viewer through the clicked point, the front/back split as seen.
  await page.selectOption('.section-axis', 'view');
  const side = { x: at.x + 8, y: at.y - 40 };
  await page.mouse.move(side.x, side.y);
  const normal = await page.evaluate(() => {
    const pane = window.billow.test.panes.target;
    const n = pane.viewDirection().transformDirection(pane.mesh.matrixWorld.clone().invert());
    return n.toArray();
  });
  await page.mouse.click(side.x, side.y);
  await page.waitForFunction(() => window.billow.test.design.seams.length === 2);
  const heights = (await controls(page, 1)).map((p) => p[0] * normal[0] + p[1] * normal[1] + p[2] * normal[2]);
  assert.ok(Math.max(...heights) - Math.min(...heights) < 1e-5, `one plane across the view: ${Math.min(...heights)} to ${Math.max(...heights)}`);
  // Esc goes back to viewing, the plane's choice with it.
  await page.keyboard.press('Escape');
  assert.equal(await page.isVisible('.section-axis'), false);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('the outline as seen is laid in one action: a front and a back panel, and a note on what it joined', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.waitForFunction(() => window.billow.test.panes.target.mesh);
  // Spot seen from its side (+x), as a foil balloon of a cow is drawn.
  await lookFrom(page, [1, 0, 0]);
  await page.click('#seam-panel button.outline');
  await page.waitForFunction(() => window.billow.test.segmentation?.segments?.length === 2, null, { timeout: 30000 });
  const seam = await page.evaluate(() => window.billow.test.design.seams[0]);
  assert.equal(seam.closed, true);
  assert.deepEqual(await page.$$eval('#seam-panel .problem', (els) => els.map((e) => e.textContent)), [], 'a clean cut: no problem');
  // Front and back: two halves of about the same area, the seam where the surface turns away (x near the
  // middle plane of a cow seen from its side: its control points face neither way).
  const areas = await page.evaluate(() => window.billow.test.segmentation.segments.map((s) => s.area));
  assert.ok(Math.min(...areas) > 0.3 * (areas[0] + areas[1]), `front and back halves: ${areas}`);
  const note = page.locator('.message.notice', { hasText: 'Outline seam laid as seen from here' });
  await note.waitFor({ timeout: 10000 });
  assert.match(await note.textContent(), /parts? turned away .* went with the panel around/);
  await page.waitForTimeout(300);
  await screenshot(page, 'flat-cut-outline');
  // Laid again from the front: a second seam, and the note of the first gives way to the second's.
  await page.keyboard.press('o');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 2);
  assert.ok(await note.count() <= 1);
  await page.click('#undo-button');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 1);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('the View menu and keys 1, 3, 7 and 9 turn the target straight on; an outline laid at an angle names the straight view that turns less away', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.waitForFunction(() => window.billow.test.panes.target.mesh);
  const directions = () => page.evaluate(() => {
    const { target, inflated } = window.billow.test.panes;
    return [target.viewDirection().toArray(), inflated.viewDirection().toArray(), target.namedView('front', target.group).toArray()];
  });
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  await page.selectOption('#view-select', 'front');
  let [view, inflated, front] = await directions();
  assert.ok(dot(view, front) > 0.9999 && Math.abs(view[1]) < 1e-6, `front: ${view} against ${front}`);
  assert.ok(dot(view, inflated) > 0.9999, 'the inflated pane turns with it');
  assert.equal(await page.inputValue('#view-select'), '', 'the menu goes back to its title, to be chosen again');
  await page.keyboard.press('3');
  [view] = await directions();
  assert.ok(Math.abs(dot(view, front)) < 1e-6 && Math.abs(view[1]) < 1e-6, `right: ${view}`);
  const right = view;
  await page.keyboard.press('9');
  [view] = await directions();
  assert.ok(dot(view, right) < -0.9999, `the opposite side: ${view}`);
  await page.keyboard.press('7');
  [view] = await directions();
  assert.ok(view[1] > 0.9999, `from above: ${view}`);
  // The cow seen from behind and above: its far side's parts go with the front, the largest a share the note names,
  // with the straight view that turns less away.
  await lookFrom(page, [0.33, 0.28, -0.9]);
  await page.keyboard.press('o');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 1);
  const note = page.locator('.message.notice', { hasText: 'Outline seam laid as seen from here' });
  await note.waitFor({ timeout: 10000 });
  const text = await note.textContent();
  const named = text.match(/the largest (\d+) % of the surface.*seen straight from the (front|right|top) \(View menu, or key ([137])\) (?:the largest part turned away is (under 1|\d+) %|no part turns away)/);
  assert.ok(named, text);
  await screenshot(page, 'outline-at-an-angle');
  // Turned as the note says and laid again: the largest part that goes with the other side is as the note said.
  await page.click('#undo-button');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 0);
  await page.keyboard.press(named[3]);
  await page.keyboard.press('o');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 1);
  await page.waitForFunction((before) => [...document.querySelectorAll('.message.notice')].every((m) => m.textContent !== before), text);
  const again = (await note.count()) ? await note.textContent() : '';
  const share = again.match(/, (?:the largest )?(\d+) % of the surface/);
  if (named[4] === undefined || named[4] === 'under 1') assert.equal(share, null, again);
  else assert.equal(share?.[1], named[4], again);
  assert.ok(Number(named[1]) >= 2 * (Number(named[4]) || 0), text);
  await screenshot(page, 'outline-straight-on');
  assert.deepEqual(page.errors, []);
  await page.close();
});

// A ring (a torus about z) as OBJ text, n x m quads.
function ringObj(R = 1, r = 0.35, n = 64, m = 24) {
  const lines = [];
  for (let i = 0; i < n; i++)
    for (let j = 0; j < m; j++) {
      const [u, v] = [(2 * Math.PI * i) / n, (2 * Math.PI * j) / m];
      lines.push(`v ${(R + r * Math.cos(v)) * Math.cos(u)} ${(R + r * Math.cos(v)) * Math.sin(u)} ${r * Math.sin(v)}`);
    }
  const at = (i, j) => (i % n) * m + (j % m) + 1;
  for (let i = 0; i < n; i++) for (let j = 0; j < m; j++) lines.push(`f ${at(i, j)} ${at(i + 1, j)} ${at(i + 1, j + 1)} ${at(i, j + 1)}`);
  return lines.join('\n');
}

// The file `name` (OBJ text `obj`) opened, seen face on along z and outlined: `segments` panels, every one a disk,
// the seams `names`, no problem, a note matching `noteText`; one step of the history, undo takes them all away.
async function expectOutlinedFaceOn(name, obj, segments, names, noteText, shot) {
  const page = await openFreshPage(env.context, env.server.url);
  await page.setInputFiles('#file-input', { name, mimeType: 'text/plain', buffer: Buffer.from(obj) });
  await page.waitForFunction((n) => window.billow.test.target?.fileName === n && window.billow.test.panes.target.mesh, name);
  await lookFrom(page, [0, 0, 1]);
  await page.keyboard.press('o');
  await page.waitForFunction((n) => window.billow.test.segmentation?.segments?.length === n, segments, { timeout: 60000 });
  assert.deepEqual(await page.evaluate(() => window.billow.test.design.seams.map((s) => s.name)), names);
  assert.equal(await page.evaluate(() => window.billow.test.segmentation.segments.every((s) => s.isDisk)), true);
  assert.deepEqual(await page.$$eval('#seam-panel .problem', (els) => els.map((e) => e.textContent)), []);
  const note = page.locator('.message.notice', { hasText: 'Outline seam laid as seen from here' });
  await note.waitFor({ timeout: 10000 });
  assert.match(await note.textContent(), noteText);
  await screenshot(page, shot);
  await page.click('#undo-button');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 0);
  assert.deepEqual(page.errors, []);
  await page.close();
}

test('the outline of a ring seen face on: its rim, its hole and two seams across cut it into four panels, and say so', () =>
  expectOutlinedFaceOn('ring.obj', ringObj(), 4, ['Outline', 'Outline, hole 1', 'Across the ring 1', 'Across the ring 2'],
    /has a handle.*the rim of each hole was laid too.*two seams across the ring/, 'flat-cut-outline-ring'));

// A foil number 8 (tests/node/implicit-mesh.mjs): a flat stroke with rounded edges round two loops, genus 2, as an OBJ.
function eightObj() {
  const loop = (x, y, cy, r) => Math.abs(Math.hypot(x, y - cy) - r);
  const stroke = (x, y) => Math.min(loop(x, y, 0.42, 0.36), loop(x, y, -0.42, 0.42)) - 0.12;
  const f = (x, y, z) => {
    const a = stroke(x, y), b = Math.abs(z) - 0.12;
    return Math.hypot(Math.max(a, 0), Math.max(b, 0)) + Math.min(Math.max(a, b), 0) - 0.04;
  };
  return objText(implicitMesh(f, -1.1, 1.1, 48));
}

// A mesh ({ positions, indices }, flat arrays) as the text of an OBJ file.
function objText({ positions, indices }) {
  const lines = [];
  for (let i = 0; i < positions.length; i += 3) lines.push(`v ${positions[i]} ${positions[i + 1]} ${positions[i + 2]}`);
  for (let i = 0; i < indices.length; i += 3) lines.push(`f ${indices[i] + 1} ${indices[i + 1] + 1} ${indices[i + 2] + 1}`);
  return lines.join('\n');
}

// A hole's sections run straight across the stroke where the ring is narrowest and opposite, each around the ring once.
test('the outline of a number 8 seen face on: its rim, both holes and two seams across each ring make six panels', () =>
  expectOutlinedFaceOn('eight.obj', eightObj(), 6, ['Outline', 'Outline, hole 1', 'Outline, hole 2', ...[1, 2, 3, 4].map((k) => `Across the ring ${k}`)],
    /2 handles.*3 loops.*the rim of each hole was laid too.*two seams across the ring \(/, 'flat-cut-outline-eight'));

// A mug (tests/node/implicit-mesh.mjs): a rounded body with a handle at its side, genus 1, as an OBJ file.
function mugObj() {
  const body = (x, y, z) => Math.hypot(x / 0.6, y, z / 0.6) - 1;
  const handle = (x, y, z) => Math.hypot(Math.hypot(x - 0.75, y) - 0.45, z) - 0.14;
  const blend = (a, b, k = 0.08) => Math.min(a, b) - (Math.max(k - Math.abs(a - b), 0) / k) ** 2 * (k / 4);
  return objText(implicitMesh((x, y, z) => blend(body(x, y, z), handle(x, y, z)), -1.35, 1.35, 36));
}

// The generated mug opened and seen with its handle towards the viewer.
async function mugSeenAlongItsHandle() {
  const page = await openFreshPage(env.context, env.server.url);
  await page.setInputFiles('#file-input', { name: 'mug.obj', mimeType: 'text/plain', buffer: Buffer.from(mugObj()) });
  await page.waitForFunction(() => window.billow.test.target?.fileName === 'mug.obj' && window.billow.test.panes.target.mesh);
  await lookFrom(page, [1, 0, 0]);
  return page;
}

// After `laid` seams were laid in one action: the seams that open its parts follow them, every part is a panel, the
// note `noteText` says what was added, and one undo takes them all away.
async function expectOpenedIntoPanels(page, laid, noteText, shot) {
  await page.waitForFunction((n) => window.billow.test.design.seams.length > n && window.billow.test.segmentation?.segments?.every((s) => s.isDisk), laid, { timeout: 60000 });
  const names = await page.evaluate(() => window.billow.test.design.seams.map((s) => s.name ?? ''));
  assert.ok(names.slice(laid).every((n) => /^A (cut that opens a tube|seam around a handle)$/.test(n)), names.join(', '));
  assert.deepEqual(await page.$$eval('#seam-panel .problem', (els) => els.map((e) => e.textContent)), []);
  const note = page.locator('.message.notice', { hasText: noteText });
  await note.waitFor({ timeout: 10000 });
  assert.match(await note.textContent(), /to make every part a panel: .*(tube|handle)/);
  await screenshot(page, shot);
  await page.click('#undo-button');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 0);
  assert.deepEqual(page.errors, []);
  await page.close();
}

test('the outline of a mug seen with its handle towards the viewer comes with the seams that make every part a panel, in one step', async () => {
  const page = await mugSeenAlongItsHandle();
  await page.keyboard.press('o');
  await expectOpenedIntoPanels(page, 1, 'Outline seam laid as seen from here', 'flat-cut-outline-mug');
});

test('a band laid around the outline of a mug comes with the seams that make every part a panel, in one step', async () => {
  const page = await mugSeenAlongItsHandle();
  await page.fill('.section-band input', '40');
  await page.press('.section-band input', 'Enter');
  await page.click('#seam-panel button.outline');
  // Before, the band alone: the front and the back, tubes that no seam opened, and a note that said one would.
  await page.waitForFunction(() => window.billow.test.design.seams.length >= 3);
  const band = await page.evaluate(() => window.billow.test.design.seams.slice(0, 3).map((s) => s.name ?? ''));
  assert.ok(band.every((n) => /^Band 40 mm/.test(n)), band.join(', '));
  await expectOpenedIntoPanels(page, 3, 'to make every part a panel', 'flat-cut-outline-band-mug');
});

// A gusseted number 8: the band follows the outline's outer loop, the holes' rims part the front from the back there,
// and cuts open the rings; before, the front and the back met through the holes, one panel with a seam around a handle.
test('a band laid around the outline of a number 8 comes with both holes\' rims and the cuts that open its rings', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.setInputFiles('#file-input', { name: 'eight.obj', mimeType: 'text/plain', buffer: Buffer.from(eightObj()) });
  await page.waitForFunction(() => window.billow.test.target?.fileName === 'eight.obj' && window.billow.test.panes.target.mesh);
  await lookFrom(page, [0, 0, 1]);
  await page.fill('.section-band input', '30');
  await page.press('.section-band input', 'Enter');
  await page.click('#seam-panel button.outline');
  await page.waitForFunction(() => window.billow.test.design.seams.length >= 5);
  const laid = await page.evaluate(() => window.billow.test.design.seams.slice(0, 5).map((s) => s.name ?? ''));
  assert.deepEqual(laid, ['Band 30 mm, front side', 'Band 30 mm, back side', 'Band 30 mm, across', 'Outline, hole 1', 'Outline, hole 2']);
  await expectOpenedIntoPanels(page, 5, 'the rim of each hole was laid too', 'flat-cut-outline-band-eight');
});

test('a sheet narrower than a piece: the pattern pane offers the width that fits, in one click', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.evaluate(() => window.billow.test.openGalleryDesign('koala'));
  await page.waitForFunction(() => window.billow.test.panes.pattern.cutLines, null, { timeout: 60000 });
  await page.fill('#sheet-input', '150');
  await page.press('#sheet-input', 'Enter');
  const warning = page.locator('.message.warning', { hasText: 'The cut outline could not be drawn' });
  await warning.waitFor({ timeout: 30000 });
  assert.match(await warning.textContent(), /at its narrowest; the sheet leaves/);
  const offer = warning.locator('button.action');
  const label = await offer.textContent();
  const width = Number(label.match(/Use a (\d+) mm sheet/)?.[1]);
  assert.ok(width > 150 && width <= 1000, label);
  // The pattern's figures stay, the sheet's row saying what it needs.
  await page.waitForFunction((w) => document.querySelector('#pattern-stats')?.textContent.includes(`needs ${w} mm; this one is 150 mm`), width, { timeout: 30000 });
  assert.match(await page.textContent('#pattern-stats'), /Panels\s*\d+.*Material\s*[\d.]+ m².*Seams\s*[\d.]+ m/s);
  await screenshot(page, 'flat-cut-sheet-offer');
  await offer.click();
  await page.waitForFunction((w) => window.billow.test.cutStatistics?.totals.sheet_width_mm === w, width, { timeout: 30000 });
  assert.equal(await page.inputValue('#sheet-input'), String(width));
  assert.equal(await warning.count(), 0, 'the warning goes with its cause');
  assert.ok(await page.evaluate(() => Boolean(window.billow.test.panes.pattern.cutLines)), 'the cut outline is drawn');
  assert.deepEqual(page.errors, []);
  await page.close();
});

// A fresh page on the sphere, the section tool across y with a 40 mm band.
async function bandOnTheSphere() {
  const page = await openFreshPage(env.context, env.server.url);
  await page.selectOption('#example-select', 'sphere');
  await page.waitForFunction(() => window.billow.test.design.target.example === 'sphere' && window.billow.test.panes.target.mesh);
  await page.click('#seam-panel button[data-tool="section"]');
  await page.selectOption('.section-axis', 'y');
  await page.fill('.section-band input', '40');
  await page.press('.section-band input', 'Enter');
  return page;
}

test('a gusset band: one click lays two sections the chosen width apart and a seam across the strip, undone at once', async () => {
  const page = await bandOnTheSphere();
  const at = await middleOfView(page);
  await page.mouse.move(at.x + 3, at.y);
  await page.mouse.move(at.x, at.y);
  assert.equal(await page.evaluate(() => window.billow.test.seamPreview?.length), 2, 'both seams of the band are previewed');
  await page.mouse.click(at.x, at.y);
  await page.waitForFunction(() => window.billow.test.design.seams.length === 3 && window.billow.test.segmentation?.segments?.length === 3, null, { timeout: 30000 });
  const names = await page.evaluate(() => window.billow.test.design.seams.map((s) => s.name));
  assert.deepEqual(names, ['Band 40 mm, side 1', 'Band 40 mm, side 2', 'Band 40 mm, across']);
  // The strip is one panel: a disk once the seam across opens it, its ends on both sides.
  const across = await page.evaluate(() => window.billow.test.design.seams[2]);
  assert.deepEqual(across.points.map((p) => p.on), [0, 1]);
  assert.ok(await page.evaluate(() => window.billow.test.segmentation.segments.every((s) => s.isDisk)));
  assert.deepEqual(await page.$$eval('#seam-panel .problem', (els) => els.map((e) => e.textContent)), []);
  // 40 mm apart on the model at its height: the planes' heights differ by 40 mm over the scale.
  const [a, b] = [(await controls(page, 0))[0][1], (await controls(page, 1))[0][1]];
  const unitsPerMm = await page.evaluate(() => 1 / (1000 * window.billow.test.scale));
  assert.ok(Math.abs(Math.abs(a - b) - 40 * unitsPerMm) < 1e-6, `${Math.abs(a - b)} units apart, ${40 * unitsPerMm} asked`);
  await page.waitForTimeout(300);
  await screenshot(page, 'flat-cut-band');
  await page.click('#undo-button');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 0);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('a band\'s width is changed in the seam panel: its sides and the seam across are laid again, undone in one step', async () => {
  const page = await bandOnTheSphere();
  const at = await middleOfView(page);
  await page.mouse.move(at.x, at.y);
  await page.mouse.click(at.x, at.y);
  await page.waitForFunction(() => window.billow.test.segmentation?.segments?.length === 3, null, { timeout: 30000 });
  const before = await page.evaluate(() => window.billow.test.design);
  const heightsOf = async () => [(await controls(page, 0))[0][1], (await controls(page, 1))[0][1]];
  const [a0, b0] = await heightsOf();
  // The seam across is selected once laid: its row offers the band's width.
  const width = page.locator('#seam-panel .seam.selected .band-width input');
  assert.equal(await width.inputValue(), '40');
  await markSegmentation(page);
  await width.fill('80');
  await width.press('Enter');
  await page.waitForFunction(() => window.billow.test.design.seams[0].name === 'Band 80 mm, side 1', null, { timeout: 30000 });
  await newSegmentation(page);
  assert.deepEqual(await page.evaluate(() => window.billow.test.design.seams.map((s) => s.name)), ['Band 80 mm, side 1', 'Band 80 mm, side 2', 'Band 80 mm, across']);
  const unitsPerMm = await page.evaluate(() => 1 / (1000 * window.billow.test.scale));
  await page.waitForFunction((y) => Math.abs(Array.from(window.billow.test.seamTraces()[0]?.controls ?? [0, y])[1] - y) > 1e-6, a0);
  const [a, b] = await heightsOf();
  assert.ok(Math.abs(Math.abs(a - b) - 80 * unitsPerMm) < 1e-6, `${Math.abs(a - b)} units apart, ${80 * unitsPerMm} asked (${Math.abs(a0 - b0)} before)`);
  assert.ok(Math.abs((a + b) / 2 - (a0 + b0) / 2) < 1e-6, 'about the same middle');
  assert.ok(await page.evaluate(() => window.billow.test.segmentation.segments.every((s) => s.isDisk)));
  assert.deepEqual(await page.$$eval('#seam-panel .problem', (els) => els.map((e) => e.textContent)), []);
  assert.equal(await page.locator('#seam-panel .seam.selected .band-width input').inputValue(), '80');
  await page.waitForTimeout(300);
  await screenshot(page, 'flat-cut-band-width');
  // One step of the history: undo gives the 40 mm band back, as it was.
  await page.click('#undo-button');
  await page.waitForFunction(() => window.billow.test.design.seams[0].name === 'Band 40 mm, side 1');
  assert.deepEqual(await page.evaluate(() => window.billow.test.design), before);
  assert.deepEqual(page.errors, []);
  await page.close();
});

// The outline seen from one side is its own front and back; its mirror image (the outline seen from the other side)
// lay over it along the body and cut slivers off where they part at the legs: 49 segments and no panels.
test('with the design\'s symmetry on, the Outline seen across the mirror plane lays one outline, no mirrored twin', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.waitForFunction(() => window.billow.test.panes.target.mesh);
  await page.selectOption('#seam-panel select.symmetry', 'x');
  // Spot seen from its side (+x), across its mirror plane.
  await lookFrom(page, [1, 0, 0]);
  await page.click('#seam-panel button.outline');
  await page.waitForFunction(() => window.billow.test.design.seams.length > 0 && window.billow.test.segmentation?.segments?.length > 0, null, { timeout: 30000 });
  assert.deepEqual(await page.evaluate(() => window.billow.test.design.seams.map((s) => s.name)), ['Outline']);
  assert.equal(await page.evaluate(() => window.billow.test.segmentation.segments.length), 2);
  assert.deepEqual(await page.$$eval('#seam-panel .problem', (els) => els.map((e) => e.textContent)), []);
  // Nor is one offered: a twin would lie over most of it.
  assert.equal(await page.$$eval('#seam-panel .seam-list .mirror', (els) => els.length), 0);
  await screenshot(page, 'flat-cut-outline-symmetry');
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('with a band width, Outline lays a band around the outline as seen: front, back and a strip between', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.waitForFunction(() => window.billow.test.panes.target.mesh);
  // Spot seen from its side (+x).
  await lookFrom(page, [1, 0, 0]);
  await page.fill('.section-band input', '30');
  await page.press('.section-band input', 'Enter');
  await page.click('#seam-panel button.outline');
  await page.waitForFunction(() => window.billow.test.design.seams.length === 3 && window.billow.test.segmentation?.segments?.length === 3, null, { timeout: 30000 });
  const seams = await page.evaluate(() => window.billow.test.design.seams);
  assert.deepEqual(seams.map((s) => s.name), ['Band 30 mm, front side', 'Band 30 mm, back side', 'Band 30 mm, across']);
  assert.deepEqual(seams.map((s) => [s.band.kind, s.band.part, s.band.width_mm]), [['outline', 'side 1', 30], ['outline', 'side 2', 30], ['outline', 'across', 30]]);
  assert.ok(await page.evaluate(() => window.billow.test.segmentation.segments.every((s) => s.isDisk)));
  assert.deepEqual(await page.$$eval('#seam-panel .problem', (els) => els.map((e) => e.textContent)), [], 'a clean cut: no problem');
  await page.waitForTimeout(300);
  await screenshot(page, 'flat-cut-outline-band');
  // Laid again wider from the seam panel, in one step: still a front, a back and a strip, and nothing else.
  await markSegmentation(page);
  await page.locator('#seam-panel .seam.selected .band-width input').fill('50');
  await page.press('#seam-panel .seam.selected .band-width input', 'Enter');
  await page.waitForFunction(() => window.billow.test.design.seams[0].name === 'Band 50 mm, front side', null, { timeout: 30000 });
  const wider = await newSegmentation(page);
  assert.equal(wider.segments.length, 3);
  assert.deepEqual(wider.problems.map((p) => p.message), []);
  await page.click('#undo-button');
  await page.waitForFunction(() => window.billow.test.design.seams[0].name === 'Band 30 mm, front side');
  assert.deepEqual(page.errors, []);
  await page.close();
});
