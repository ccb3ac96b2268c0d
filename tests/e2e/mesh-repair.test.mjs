// A designer's shape repaired in the browser. Thin handles (a boot's lace loops; here a wire hoop): the genus warning
// says they are too thin for a panel to follow and offers to cut through them; one click leaves the shape a handle
// fewer, the design marked so, undo puts the handle back, and a reload keeps it cut. A thick ring (a swim ring) is not offered the cut. Holes (a
// statue open at its base; here a bowl, the sphere open at its top): the refusal offers to close them, and the shape
// opens closed. A flat sheet (an outline drawn in 2D) is told it needs thickness instead.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { autosaveHolds, openFreshPage, openPage, screenshot, useBrowser, MESHES } from './harness.mjs';

const env = useBrowser();

const stat = (page, name) => page.textContent(`#target-stats dd[data-stat="${name}"]`);

// A ring around z as OBJ text: radius R to the tube's middle, tube radius r, faces outward.
function ringObj(R, r, nu, nv) {
  const lines = [];
  for (let i = 0; i < nu; i++)
    for (let j = 0; j < nv; j++) {
      const u = (2 * Math.PI * i) / nu, v = (2 * Math.PI * j) / nv;
      const rho = R + r * Math.cos(v);
      lines.push(`v ${rho * Math.cos(u)} ${r * Math.sin(v)} ${rho * Math.sin(u)}`);
    }
  const at = (i, j) => ((i % nu) * nv + (j % nv)) + 1;
  for (let i = 0; i < nu; i++)
    for (let j = 0; j < nv; j++) {
      lines.push(`f ${at(i, j)} ${at(i, j + 1)} ${at(i + 1, j + 1)}`);
      lines.push(`f ${at(i, j)} ${at(i + 1, j + 1)} ${at(i + 1, j)}`);
    }
  return lines.join('\n');
}

const open = (page, name, text) => page.setInputFiles('#file-input', { name, mimeType: 'text/plain', buffer: Buffer.from(text) });
const fileShown = (page, name) =>
  page.waitForFunction((n) => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === n, name, { timeout: 30000 });

test('a thin handle is offered a cut through it; the cut shape keeps its faces, is undone and redone, and stays cut after a reload', async () => {
  const page = await openFreshPage(env.context, env.server.url);

  // A swim ring: one handle, thick. The warning asks for a seam around it and offers no cut.
  await open(page, 'swim-ring.obj', ringObj(1, 0.4, 48, 24));
  await fileShown(page, 'swim-ring.obj');
  assert.equal(await stat(page, 'genus'), '1');
  const thick = page.locator('.message', { hasText: 'genus 1' });
  await thick.waitFor();
  assert.doesNotMatch(await thick.textContent(), /thin/);
  assert.equal(await thick.locator('button.action').count(), 0);

  // A wire hoop: its tube 2 pi 0.03 around, 6 % of its bounding box's diagonal.
  await open(page, 'hoop.obj', ringObj(1, 0.03, 120, 16));
  await fileShown(page, 'hoop.obj');
  assert.equal(await stat(page, 'genus'), '1');
  const warning = page.locator('.message.warning', { hasText: 'genus 1' });
  await warning.waitFor();
  assert.match(await warning.textContent(), /It is thin \([\d.]+ cm around, 6 % of the shape's size.*a sleeve only a few of the panels' edges around/);
  await screenshot(page, 'thin-handles-offered');
  const faces = await stat(page, 'triangles');
  await warning.locator('button.action', { hasText: 'Cut the thin handle' }).click();

  await page.waitForFunction(() => document.querySelector('#target-stats dd[data-stat="genus"]')?.textContent === '0', null, { timeout: 30000 });
  const notice = page.locator('.message.notice', { hasText: 'Cut through 1 thin handle' });
  await notice.waitFor();
  assert.equal(await page.locator('.message', { hasText: 'genus 1' }).count(), 0, 'the genus warning goes');
  // Both ends closed with a fan of 16 triangles; every face of the hoop kept.
  const count = (text) => Number(text.replace(/,/g, ''));
  assert.equal(count(await stat(page, 'triangles')), count(faces) + 32);
  assert.equal(await page.evaluate(() => window.billow.test.design.target.cutThinHandles), true);
  await screenshot(page, 'thin-handles-cut');

  // The cut is one undo step: undone, the hoop is whole again and the cut offered again; redone, cut again.
  const genus = (g) => page.waitForFunction((want) => document.querySelector('#target-stats dd[data-stat="genus"]')?.textContent === want, g, { timeout: 30000 });
  await page.click('#undo-button');
  await genus('1');
  assert.equal(await stat(page, 'triangles'), faces);
  assert.equal(await page.evaluate(() => Boolean(window.billow.test.design.target.cutThinHandles)), false);
  await page.locator('.message.warning', { hasText: 'genus 1' }).locator('button.action', { hasText: 'Cut the thin handle' }).waitFor();
  await page.click('#redo-button');
  await genus('0');
  assert.equal(count(await stat(page, 'triangles')), count(faces) + 32);
  assert.equal(await page.evaluate(() => window.billow.test.design.target.cutThinHandles), true);
  assert.equal(await page.locator('.message', { hasText: 'genus 1' }).count(), 0);
  assert.deepEqual(page.errors, []);
  await autosaveHolds(page, (design) => design?.target?.cutThinHandles === true);
  await page.close();

  // Reopened from the autosave: still cut, no warning again.
  const again = await openPage(env.context, env.server.url);
  await fileShown(again, 'hoop.obj');
  assert.equal(await stat(again, 'genus'), '0');
  assert.equal(count(await stat(again, 'triangles')), count(faces) + 32);
  assert.equal(await again.evaluate(() => window.billow.test.design.target.cutThinHandles), true);
  assert.equal(await again.locator('.message', { hasText: 'genus' }).count(), 0);
  assert.deepEqual(again.errors, []);
  await again.close();
});

// The shared sphere without its triangles above 0.8 of its radius, as OBJ text.
function bowlObj() {
  const lines = readFileSync(join(MESHES, 'sphere.obj'), 'utf8').split('\n');
  const ys = lines.filter((l) => l.startsWith('v ')).map((l) => Number(l.split(/\s+/)[2]));
  return lines.filter((l) => !l.startsWith('f ') || l.split(/\s+/).slice(1, 4).reduce((sum, c) => sum + ys[parseInt(c, 10) - 1], 0) / 3 < 0.8).join('\n');
}

test('an open mesh is refused with an offer to close its hole; closed, it opens as a target and stays closed', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  await open(page, 'bowl.obj', bowlObj());
  const refusal = page.locator('.message.error', { hasText: '"bowl.obj" cannot be used as a target' });
  await refusal.waitFor();
  assert.match(await refusal.textContent(), /1 hole: it must be closed to hold air/);
  assert.notEqual(await stat(page, 'file'), 'bowl.obj', 'the design on screen stays until the mesh is usable');
  await screenshot(page, 'mesh-repair-hole-offered');
  await refusal.locator('button.action', { hasText: 'Close the hole' }).click();

  await fileShown(page, 'bowl.obj');
  assert.equal(await stat(page, 'genus'), '0');
  await page.locator('.message.notice', { hasText: 'Closed its hole with a cap' }).waitFor();
  assert.equal(await page.inputValue('#example-select'), '', 'the designer\'s own file, no example');
  assert.equal(await page.evaluate(() => window.billow.test.design.target.closeHoles), true);
  await screenshot(page, 'mesh-repair-hole-closed');
  assert.deepEqual(page.errors, []);
  await autosaveHolds(page, (design) => design?.target?.closeHoles === true);
  await page.close();

  const again = await openPage(env.context, env.server.url);
  await fileShown(again, 'bowl.obj');
  assert.equal(await stat(again, 'genus'), '0');
  assert.equal(await again.locator('.message.error').count(), 0);
  assert.deepEqual(again.errors, []);
  await again.close();
});

test('a flat sheet (an outline drawn in 2D) is told it needs thickness, with no offer to close it, and changes nothing', async () => {
  const page = await openFreshPage(env.context, env.server.url);
  const before = await stat(page, 'file');
  // A letter-sized square sheet in the plane z = 0, 8 x 8 squares.
  const n = 8;
  const lines = [];
  for (let i = 0; i <= n; ++i) for (let j = 0; j <= n; ++j) lines.push(`v ${(0.3 * i) / n} ${(0.2 * j) / n} 0`);
  for (let i = 0; i < n; ++i)
    for (let j = 0; j < n; ++j) {
      const a = i * (n + 1) + j + 1;
      lines.push(`f ${a} ${a + n + 1} ${a + n + 2}`, `f ${a} ${a + n + 2} ${a + 1}`);
    }
  await open(page, 'sheet.obj', lines.join('\n'));
  const refusal = page.locator('.message.error', { hasText: '"sheet.obj" cannot be used as a target' });
  await refusal.waitFor();
  assert.match(await refusal.textContent(), /flat sheet with no thickness/);
  assert.match(await refusal.textContent(), /give the sheet thickness/);
  assert.equal(await refusal.locator('button.action', { hasText: /Close the hole/ }).count(), 0, 'capping a flat sheet would enclose nothing');
  assert.equal(await stat(page, 'file'), before, 'the design on screen stays');
  await screenshot(page, 'mesh-repair-flat-sheet');
  assert.deepEqual(page.errors, []);
  await page.close();
});
