// Share links with the designer's own mesh in the browser: a 16k-triangle mesh travels in its link and
// the seams come back where they were; a mesh too large for a link leaves a link that asks for its file,
// refuses another file and goes onto that one.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { launch, openPage, useBrowser, MESHES } from './harness.mjs';

const env = useBrowser();

const fileShown = (page, name, timeout = 60000) =>
  page.waitForFunction((n) => document.querySelector('#target-stats dd[data-stat="file"]')?.textContent === n, name, { timeout });

async function openMesh(page, name, buffer) {
  await page.setInputFiles('#file-input', { name, mimeType: 'text/plain', buffer });
}

// A design on the mesh file `file` with one open seam through three triangles.
async function openDesignOn(page, file, faces) {
  const design = {
    format: 'billow-design', version: 1, target: { file }, size: { height: 0.6 },
    seams: [{ name: 'palm', closed: false, weight: 1, points: faces.map((face, i) => ({ face, bary: [0.2 + 0.1 * i, 0.3, 0.5 - 0.1 * i] })) }],
  };
  await page.setInputFiles('#file-input', { name: 'palm.billow.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(design)) });
  await page.waitForFunction(() => window.billow.test.design.seams.length === 1);
}

// The seams' control points in space, on the page's own target.
const places = () =>
  window.billow.test.design.seams.map((seam) =>
    seam.points.map(({ face, bary }) => {
      const { positions, indices } = window.billow.test.target;
      return [0, 1, 2].map((a) => bary.reduce((sum, w, c) => sum + w * positions[3 * indices[3 * face + c] + a], 0));
    }),
  );

// Each triangle split into four at its edges' midpoints, as OBJ text.
function subdividedObj(text) {
  const v = [];
  const f = [];
  for (const line of text.split('\n')) {
    const p = line.trim().split(/\s+/);
    if (p[0] === 'v') v.push([+p[1], +p[2], +p[3]]);
    else if (p[0] === 'f') f.push(p.slice(1, 4).map((c) => parseInt(c, 10) - 1));
  }
  const middle = new Map();
  const mid = (a, b) => {
    const key = `${Math.min(a, b)} ${Math.max(a, b)}`;
    if (!middle.has(key)) middle.set(key, v.push(v[a].map((x, i) => (x + v[b][i]) / 2)) - 1);
    return middle.get(key);
  };
  const faces = [];
  for (const [a, b, c] of f) {
    const [ab, bc, ca] = [mid(a, b), mid(b, c), mid(c, a)];
    faces.push([a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]);
  }
  return `${v.map((p) => `v ${p.join(' ')}`).join('\n')}\n${faces.map((t) => `f ${t.map((i) => i + 1).join(' ')}`).join('\n')}\n`;
}

test('a design on hand.obj (15,982 triangles) travels with its mesh; its seam comes back where it was', async () => {
  const page = await openPage(env.context, env.server.url);
  await openMesh(page, 'hand.obj', readFileSync(join(MESHES, 'hand.obj')));
  await fileShown(page, 'hand.obj');
  await openDesignOn(page, 'hand.obj', [4000, 4100, 4200]);
  const url = await page.evaluate(() => window.billow.test.shareLink());
  assert.match(url, /#design=[A-Za-z0-9_-]+&mesh=[A-Za-z0-9_-]+$/);
  assert.ok(url.length < 61000, `${url.length} characters`);
  const other = await launch();
  try {
    const fresh = await openPage(other, url);
    await fileShown(fresh, 'hand.obj');
    await fresh.waitForFunction(() => window.billow.test.design.seams.length === 1);
    assert.equal(await fresh.evaluate(() => window.billow.test.target.indices.length), 15982 * 3);
    const sent = await page.evaluate(places);
    const received = await fresh.evaluate(places);
    sent[0].forEach((p, k) => {
      // The grid's step on hand.obj is 1/64 of its 0.0112 mean edge: a point moves by at most 0.00015.
      const d = Math.hypot(...p.map((x, a) => x - received[0][k][a]));
      assert.ok(d < 0.0002, `point ${k} moved ${d}`);
    });
    assert.deepEqual(fresh.errors, []);
  } finally {
    await other.close();
  }
  assert.deepEqual(page.errors, []);
  await page.close();
});

test('a mesh too large for a link: the link asks for its file, another file is refused, that file takes the design', async () => {
  const hand = readFileSync(join(MESHES, 'hand.obj'));
  const big = Buffer.from(subdividedObj(hand.toString('utf8')));
  const page = await openPage(env.context, env.server.url);
  await openMesh(page, 'big hand.obj', big);
  await fileShown(page, 'big hand.obj', 120000);
  await openDesignOn(page, 'big hand.obj', [40000, 40400, 40800]);
  const url = await page.evaluate(() => window.billow.test.shareLink());
  assert.match(url, /#design=[A-Za-z0-9_-]+&target=63928\.\d+\.[0-9a-f]{8}$/);
  await page.locator('.message.notice', { hasText: 'send the file along' }).waitFor();
  const sent = await page.evaluate(() => window.billow.test.design.seams);

  const other = await launch();
  try {
    const fresh = await openPage(other, url);
    const waiting = fresh.locator('.message.warning', { hasText: 'big hand.obj' });
    assert.match(await waiting.textContent(), /drawn on your mesh "big hand\.obj" \(63,928 triangles\).*Open that file/);

    await openMesh(fresh, 'hand.obj', hand);
    await fileShown(fresh, 'hand.obj');
    await fresh.locator('.message.warning', { hasText: 'is not the mesh the shared design was drawn on' }).waitFor();
    assert.equal(await fresh.evaluate(() => window.billow.test.design.seams.length), 0, 'another file opens on its own');

    await openMesh(fresh, 'big hand.obj', big);
    await fileShown(fresh, 'big hand.obj', 120000);
    await fresh.waitForFunction(() => window.billow.test.design.seams.length === 1);
    assert.deepEqual(await fresh.evaluate(() => window.billow.test.design.seams), sent, 'the same seam on the same triangles');
    assert.equal(await fresh.locator('.message.warning', { hasText: 'shared design' }).count(), 0, 'nothing waits any more');
    assert.deepEqual(fresh.errors, []);
  } finally {
    await other.close();
  }
  assert.deepEqual(page.errors, []);
  await page.close();
});
