// A designer's own shape: figures that do not mislead and problems that say where. The distance to the
// target is measured both ways, and a part of the target the inflated shape leaves out is a warning that
// turns the view to it and shows it (the target's uncovered parts, translucent, in the distance colors).
// Segments carry the numbers of their panels on the model; a problem in the seam panel, clicked, shows its
// place. A run stopped at its limit says so.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openFreshPage, openDesignFixture, optimizedResultShown, screenshot, useBrowser } from './harness.mjs';
import { capsuleMesh } from '../node/capsule-mesh.mjs';

const env = useBrowser();

test('two discs for a sphere: distance both ways, the parts left out shown where they are', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  const statuses = [];
  await page.exposeFunction('recordStatus', (s) => statuses.push(s));
  await page.evaluate(() => new MutationObserver(() => window.recordStatus(document.querySelector('#status').textContent))
    .observe(document.querySelector('#status'), { childList: true, subtree: true, characterData: true }));
  await openDesignFixture(page, 'sphere-equator.billow.json');
  await optimizedResultShown(page);
  // Every optimizing status gives both ways, the worse first.
  const steps = statuses.filter((s) => /^Optimizing the panels: step [1-9]/.test(s));
  assert.ok(steps.length > 0, statuses.slice(-5).join(' | '));
  for (const s of steps) assert.match(s, /distance [\d.]+ % (target → inflated|inflated → target), [\d.]+ % (inflated → target|target → inflated)/);
  const status = await page.evaluate(() => window.billow.test.optimized.status);
  assert.ok(status.targetDistanceRms > status.distanceRms, `two flat discs miss the sphere's poles: ${JSON.stringify(status)}`);
  assert.match(steps.at(-1), /distance [\d.]+ % target → inflated, [\d.]+ % inflated → target/, 'the worse way leads');
  // The end says how the optimizer ended.
  await page.waitForFunction(() => /^Inflated the optimized panels: (settled after \d+ steps?|stopped at the optimizer's limit)/.test(document.querySelector('#status').textContent));

  // Segments 1 and 2 on the model, panels 1 and 2 in the pattern.
  assert.deepEqual(await page.$$eval('#pane-target .segment-label, .segment-label', (els) => els.map((e) => e.textContent).sort()), ['1', '2']);
  assert.ok(await page.$$eval('.segment-label', (els) => els.some((e) => !e.hidden)), 'a segment number is in view');
  assert.deepEqual(await page.$$eval('.panel-label', (els) => els.map((e) => e.firstChild.textContent).sort()), ['Panel 1', 'Panel 2']);

  // What the discs leave out of the sphere: a warning that says where and shows it.
  const warning = page.locator('.message.warning', { hasText: /of the target/ }).first();
  await warning.waitFor({ timeout: 30000 });
  const text = await warning.textContent();
  assert.match(text, /near the (top|bottom|left|right|front|back|middle)/);
  // Judged from the result: two flat discs are too flat for a round body, the poles lie off their flat sides.
  assert.match(text, /too flat for part of the target/);
  assert.match(text, /A gusset \(a strip sewn in along the seam\) or more panels let the balloon grow thicker/);
  // The stack shows the newest on top: the largest part left out is put in last, so it leads.
  const areas = await page.$$eval('.message.warning', (els) => els.map((e) => e.textContent)
    .filter((t) => /of the target/.test(t)).map((t) => Number(t.match(/([\d.]+) % of its surface/)[1])));
  assert.equal(areas.at(-1), Math.max(...areas), `the largest leads: ${areas}`);
  assert.equal(await page.inputValue('#color-select'), 'wrinkles');
  await warning.locator('button.locate').click();
  assert.equal(await page.inputValue('#color-select'), 'distance', 'showing it picks the distance colors');
  const shown = await page.evaluate(() => {
    const t = window.billow.test;
    const ghost = t.panes.inflated.uncoveredMesh;
    return { mark: Boolean(t.panes.target.placeMark), ghost: Boolean(ghost?.visible), triangles: ghost ? ghost.geometry.index.count / 3 : 0,
      note: document.querySelector('#pane-inflated .legend .note').textContent };
  });
  assert.ok(shown.mark, 'the place is marked on the target');
  const outside = await page.evaluate(() => {
    const pane = window.billow.test.panes.inflated;
    const Vector3 = pane.camera.position.constructor;
    const mesh = pane.uncoveredMesh, positions = mesh.geometry.attributes.position, index = mesh.geometry.index;
    mesh.updateMatrixWorld(true);
    let far = 0;
    for (let i = 0; i < index.count; i++) {
      const p = new Vector3().fromBufferAttribute(positions, index.getX(i)).applyMatrix4(mesh.matrixWorld).project(pane.camera);
      far = Math.max(far, Math.abs(p.x), Math.abs(p.y));
    }
    return far;
  });
  assert.ok(outside <= 1.05, `the parts left out are framed in the inflated pane (${outside.toFixed(2)} of the half-width)`);
  assert.ok(shown.ghost && shown.triangles > 10, `the uncovered target is drawn (${shown.triangles} triangles)`);
  assert.match(shown.note, /target → inflated.*inflated → target|inflated → target.*target → inflated/);
  assert.match(shown.note, /Translucent blue: parts of the target the inflated shape leaves out/);
  assert.match(shown.note, /What helps near the (top|bottom)[a-z ]*: a gusset or more panels/, 'the one-line hint');
  await page.waitForTimeout(100);
  await screenshot(page, 'designer-shape-uncovered');
  // Back to wrinkles: the ghost goes with the distance colors.
  await page.selectOption('#color-select', 'wrinkles');
  assert.equal(await page.evaluate(() => window.billow.test.panes.inflated.uncoveredMesh.visible), false);
  // A new seam layout takes the warning away with its cause until the new result says otherwise.
  await page.evaluate(() => window.billow.test.warnUncovered([]));
  assert.equal(await page.locator('.message.warning', { hasText: /of the target/ }).count(), 0);

  // A seam that makes the layout unpatternable (a slit inside the top disc): the panels shown are marked out of
  // date, and the status says why, until an undo brings panels back.
  const slit = { name: 'slit', closed: false, weight: 1, points: [[0.3, 0.9, 0.3], [-0.3, 0.9, 0.3]] };
  await page.evaluate((seam) => window.billow.test.addSeam(seam), slit);
  await page.waitForFunction(() => document.querySelector('#pane-inflated').hasAttribute('data-stale'), null, { timeout: 30000 });
  assert.ok(await page.evaluate(() => document.querySelector('#pane-pattern').hasAttribute('data-stale')));
  assert.match(await page.textContent('#status'), /These seams make no panels yet/);
  await screenshot(page, 'designer-shape-outdated');
  await page.click('#undo-button').catch(() => page.evaluate(() => window.billow.test.undo()));
  await page.waitForFunction(() => !document.querySelector('#pane-inflated').hasAttribute('data-stale'), null, { timeout: 30000 });
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('a problem in the seam panel, clicked, turns the view to its place and selects its seam', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  // A seam across the sphere that does not close: it cuts a slit, not a panel.
  const design = {
    format: 'billow-design', version: 1, target: { example: 'sphere' }, size: { height: 0.5 },
    seams: [{ name: 'slit', closed: false, weight: 1, points: [[1, 0, 0], [0, 0, 1], [-1, 0, 0]] }],
  };
  await page.setInputFiles('#file-input', { name: 'slit.billow.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(design)) });
  const problem = page.locator('#seam-panel .problem .problem-text').first();
  await problem.waitFor({ timeout: 30000 });
  const texts = await page.$$eval('#seam-panel .problem', (els) => els.map((e) => e.textContent));
  assert.equal(new Set(texts).size, texts.length, `no two problems share a text: ${texts.join(' | ')}`);
  assert.ok(texts.some((t) => /^(Segment 1, near|Seam 1 )/.test(t)), texts.join(' | '));
  const before = await page.evaluate(() => window.billow.test.panes.target.viewDirection().toArray());
  await page.locator('#seam-panel .problem .problem-text', { hasText: 'Seam 1' }).first().click();
  const after = await page.evaluate(() => ({
    direction: window.billow.test.panes.target.viewDirection().toArray(),
    mark: window.billow.test.panes.target.placeMark?.position.toArray() ?? null,
    selection: window.billow.test.selection,
  }));
  assert.ok(after.mark, 'the place is marked');
  assert.equal(after.selection?.seam, 0, 'its seam is selected');
  // The view looks at the mark from outside: the direction from the centre to the mark.
  const turned = Math.hypot(...after.direction.map((d, i) => d - before[i]));
  assert.ok(turned > 0.01 || Math.hypot(...after.mark) > 0, `the view turned (${turned})`);
  await screenshot(page, 'designer-shape-problem');
  // Panels the builder refuses (a segment that would overlap itself laid flat): each problem is its own message
  // with "Show where", and new panels take them away.
  await page.evaluate(() => window.billow.test.showPanelProblems({
    code: 'pattern.not-built', message: 'two problems',
    details: { problems: [
      { code: 'pattern.overlaps', severity: 'error', message: 'Segment 1 would overlap itself when laid flat, near the top of the shape: a seam across it there lets it lie flat as two panels.', location: [0, 1, 0] },
      { code: 'pattern.not-sewn', severity: 'error', message: 'Panel 2 would be sewn to itself near the left of the shape: its seams touch there.', location: [-1, 0, 0] },
    ] },
  }));
  const refused = page.locator('.message.error', { hasText: 'The panels could not be made from these seams' });
  assert.equal(await refused.count(), 2);
  await refused.filter({ hasText: 'Panel 2' }).locator('button.locate').click();
  const mark = await page.evaluate(() => window.billow.test.panes.target.placeMark?.position.toArray());
  assert.deepEqual(mark, [-1, 0, 0], 'the mark is at the place the problem names');
  await page.evaluate(() => window.billow.test.resolveMessages('pattern', { prefix: true }));
  assert.equal(await refused.count(), 0);
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('a segment that folds when laid flat is a warning with its place, and the panels are still made', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  // A sausage eight times as long as it is round, one seam near its left end: the long part is a closed-ended tube,
  // which no single flat panel covers (tests/native: PatternBuild.ASegmentThatFoldsWhenLaidFlatIsAWarningPlacedWhereItFolds).
  const r = 0.05, length = 8 * 2 * Math.PI * r, x0 = -length / 2 + 0.02;
  const { positions, indices } = capsuleMesh(12, r, length);
  const vertices = [], triangles = [];
  for (let i = 0; i < positions.length; i += 3) vertices.push([positions[i], positions[i + 1], positions[i + 2]]);
  for (let i = 0; i < indices.length; i += 3) triangles.push([indices[i], indices[i + 1], indices[i + 2]]);
  const design = {
    format: 'billow-design', version: 1, target: { vertices, triangles }, size: { height: 0.2 },
    seams: [{ name: 'near the end', closed: true, weight: 1, points: [0.3, 2.4, 4.5].map((a) => [x0, r * Math.cos(a), r * Math.sin(a)]) }],
  };
  await page.setInputFiles('#file-input', { name: 'sausage.billow.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(design)) });
  const warning = page.locator('.message.warning', { hasText: 'cannot be laid flat without folding over itself' });
  await warning.waitFor({ timeout: 60000 });
  assert.match(await warning.textContent(), /^Segment \d cannot be laid flat without folding over itself near the .*A seam across it there lets it lie flat as two panels\./);
  await page.waitForFunction(() => window.billow.test.panes.pattern.pattern?.panels?.length === 2, null, { timeout: 60000 });
  await warning.locator('button.locate').click();
  const mark = await page.evaluate(() => window.billow.test.panes.target.placeMark?.position.toArray());
  assert.ok(mark, 'the place is marked on the target');
  assert.ok(mark[0] > x0 + 0.25 * length, `on the tube, past the seam: ${mark}`);
  // Seen straight on, across the tube, not end-on from the centre's side behind the sausage's own end.
  const seen = await page.evaluate((m) => {
    const pane = window.billow.test.panes.target;
    const Vector3 = pane.camera.position.constructor;
    const local = pane.viewDirection().clone().transformDirection(pane.mesh.matrixWorld.clone().invert());
    return { visible: pane.isVisible(new Vector3(...m)), along: Math.abs(local.x) };
  }, mark);
  assert.ok(seen.visible, 'the marked place is in view');
  assert.ok(seen.along < 0.2, `the view looks across the tube (${seen.along.toFixed(2)} along it)`);
  await screenshot(page, 'designer-shape-folded-segment');
  // A second seam around the tube leaves a ring between the two, no panel: the warning goes with the panels it was about.
  await page.evaluate(() => window.billow.test.addSeam({ name: 'middle', closed: true, weight: 1, points: [[0, 0.05, 0], [0, -0.025, 0.0433], [0, -0.025, -0.0433]] }));
  await page.waitForFunction(() => ![...document.querySelectorAll('.message.warning')].some((m) => /folding over itself/.test(m.textContent)), null, { timeout: 60000 });
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('the wheel zooms towards the point under the cursor, in the target and the pattern', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await page.waitForFunction(() => window.billow.test.panes.target.mesh);
  const box = await page.locator('#pane-target').boundingBox();
  // Off the centre of the view, on the model: the point there stays under the cursor as the view closes in.
  const at = await page.evaluate(({ left, top, width, height }) => {
    const pane = window.billow.test.panes.target;
    for (let dy = -0.2; dy <= 0.2; dy += 0.05)
      for (let dx = 0.25; dx >= 0.08; dx -= 0.03) {
        const x = left + width * (0.5 + dx), y = top + height * (0.5 + dy);
        const hit = pane.pick({ clientX: x, clientY: y });
        if (hit) return { x, y, position: hit.position };
      }
    return null;
  }, { left: box.x, top: box.y, width: box.width, height: box.height });
  assert.ok(at, 'a point of the model off the centre');
  const distance = () => page.evaluate(() => {
    const pane = window.billow.test.panes.target;
    return pane.camera.position.distanceTo(pane.controls.target);
  });
  const before = await distance();
  await page.mouse.move(at.x, at.y);
  for (let i = 0; i < 4; i++) await page.mouse.wheel(0, -200);
  await page.waitForTimeout(200);
  assert.ok(await distance() < 0.8 * before, 'the view closed in');
  const drift = await page.evaluate(({ x, y, position }) => {
    const pane = window.billow.test.panes.target;
    const p = pane.mesh.localToWorld(new (pane.camera.position.constructor)(...position)).project(pane.camera);
    const r = pane.element.getBoundingClientRect();
    return Math.hypot(r.left + (p.x + 1) / 2 * r.width - x, r.top + (1 - p.y) / 2 * r.height - y);
  }, at);
  assert.ok(drift < 8, `the point under the cursor stays there (${drift.toFixed(1)} px)`);
  // The pattern pane too: the sheet point under the cursor stays.
  const pattern = await page.locator('#pane-pattern').boundingBox();
  const px = pattern.x + pattern.width * 0.3, py = pattern.y + pattern.height * 0.4;
  const sheetPoint = (x, y) => page.evaluate(({ x, y }) => {
    const pane = window.billow.test.panes.pattern;
    const r = pane.element.getBoundingClientRect();
    const v = new (pane.camera.position.constructor)(((x - r.left) / r.width) * 2 - 1, 1 - ((y - r.top) / r.height) * 2, 0).unproject(pane.camera);
    return [v.x, v.y];
  }, { x, y });
  const p0 = await sheetPoint(px, py);
  await page.mouse.move(px, py);
  for (let i = 0; i < 3; i++) await page.mouse.wheel(0, -200);
  await page.waitForTimeout(200);
  const p1 = await sheetPoint(px, py);
  const zoom = await page.evaluate(() => window.billow.test.panes.pattern.camera.zoom);
  assert.ok(zoom > 1.2, `the pattern closed in (zoom ${zoom})`);
  const span = await page.evaluate(() => { const c = window.billow.test.panes.pattern.camera; return (c.right - c.left) / c.zoom; });
  assert.ok(Math.hypot(p1[0] - p0[0], p1[1] - p0[1]) < 0.01 * span, `the sheet point under the cursor stays (${p0} -> ${p1})`);
  assert.deepEqual(page.errors, []);
  await page.close();
});
