// The gallery's stored results (web/public/gallery/<id>.result.json, web/src/app/stored-result.js): each
// design has one, made from the design as it is now (else the app would compute it live, and this fails
// with the command that makes it again), and its panels inflate, through the worker's handlers, to the
// shape stored with them.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { loadApi } from './load-module.mjs';
import { createHandlers } from '../../web/src/worker/handlers.js';
import { parseDesign } from '../../web/src/app/design.js';
import { findExample } from '../../web/src/app/examples.js';
import { patternForDisplay } from '../../web/src/app/pattern-session.js';
import { canonicalJson, hashBytes, parseStoredResult, resultKey, DEFAULT_RESOLUTION, RESULT_VERSION } from '../../web/src/app/stored-result.js';

const GALLERY = new URL('../../web/public/gallery/', import.meta.url);
const read = (name) => readFileSync(new URL(name, GALLERY), 'utf8');
const designs = readdirSync(GALLERY).filter((f) => f.endsWith('.billow.json')).sort();
const meshOf = (design) => readFileSync(new URL(`../examples/${findExample(design.target.example).file}`, GALLERY));
const regenerate = (id) => `make it again: node scripts/make-gallery.mjs results ${id} (after building the wasm module: bash scripts/build.sh wasm)`;

function finish(steps) {
  let step = steps.next();
  while (!step.done) step = steps.next();
  return step.value;
}

test('the gallery has designs to check', () => {
  assert.ok(designs.length >= 4, `${designs.length} designs in web/public/gallery`);
});

for (const file of designs) {
  const id = file.replace(/\.billow\.json$/, '');
  test(`${id}: its stored result was made from the design as it is now`, () => {
    const resultFile = `${id}.result.json`;
    assert.ok(existsSync(new URL(resultFile, GALLERY)), `${resultFile} is missing: ${regenerate(id)}`);
    const stored = parseStoredResult(read(resultFile));
    assert.ok(stored, `${resultFile} is not a stored result the app can read: ${regenerate(id)}`);
    assert.equal(stored.triangles, DEFAULT_RESOLUTION, `${resultFile} was made at another resolution than the app opens with: ${regenerate(id)}`);
    const { design } = parseDesign(JSON.parse(read(file)));
    assert.equal(stored.key, resultKey(design, DEFAULT_RESOLUTION, meshOf(design)),
      `${resultFile} was made from another version of ${file} or of its target mesh: ${regenerate(id)}`);
  });
}

test('stored results inflate to the shape stored with them', async () => {
  const handlers = createHandlers(await loadApi());
  for (const file of designs) {
    const id = file.replace(/\.billow\.json$/, '');
    const stored = parseStoredResult(read(`${id}.result.json`));
    const pattern = JSON.parse(stored.patternText);
    assert.ok(patternForDisplay(stored.patternText, id).panels.length >= 2, `${id}: panels`);
    const shape = finish(handlers.inflatePattern({ patternText: stored.patternText }));
    assert.equal(shape.state, 'converged', `${id}: ${shape.message}`);
    assert.ok(shape.volume > 0, `${id}: volume ${shape.volume}`);
    // Every panel vertex ends where the file says: the stored shape is the balance of the stored panels.
    let worst = 0;
    pattern.inflated.forEach((panel, p) => panel.forEach((xyz, i) => {
      const v = shape.panelVertexMap[shape.panelVertexStart[p] + i];
      worst = Math.max(worst, Math.hypot(...xyz.map((c, k) => c - shape.positions[3 * v + k])));
    }));
    assert.ok(worst < 1e-3, `${id}: the inflated shape moved up to ${(worst * 1000).toFixed(2)} mm from the stored one`);
  }
});

test('the key changes with everything the optimization reads, and only with that', () => {
  const { design } = parseDesign(JSON.parse(read('sphere3.billow.json')));
  const mesh = meshOf(design);
  const key = resultKey(design, DEFAULT_RESOLUTION, mesh);
  const seams = (edit) => design.seams.map((s, i) => (i === 0 ? edit(s) : s));
  const changed = {
    weight: { ...design, seams: seams((s) => ({ ...s, weight: 2 })) },
    point: { ...design, seams: seams((s) => ({ ...s, points: [[0, 1, 0], ...s.points.slice(1)].map((p, k) => (k === 1 ? [p[0] + 1e-5, p[1], p[2]] : p)) })) },
    smooth: { ...design, seams: seams((s) => ({ ...s, smooth: true })) },
    connections: { ...design, connections: [{ seams: [0, 1] }] },
    height: { ...design, size: { height: 0.51 } },
    pressure: { ...design, pressure: 1001 },
    material: { ...design, material: { ...design.material, thickness: 3e-5 } },
    target: { ...design, target: { example: 'spot' } },
  };
  for (const [what, other] of Object.entries(changed)) assert.notEqual(resultKey(other, DEFAULT_RESOLUTION, mesh), key, what);
  assert.notEqual(resultKey(design, 3000, mesh), key, 'resolution');
  const otherMesh = Buffer.from(mesh);
  otherMesh[otherMesh.length - 3] ^= 1;
  assert.notEqual(resultKey(design, DEFAULT_RESOLUTION, otherMesh), key, 'mesh file');
  // The cut files' settings and the order fields were written in do not matter.
  const same = JSON.parse(JSON.stringify({ ...design, fabrication: { ...design.fabrication, allowance: 5 } }), (k, v) =>
    (v && typeof v === 'object' && !Array.isArray(v) ? Object.fromEntries(Object.entries(v).reverse()) : v));
  assert.equal(resultKey(same, DEFAULT_RESOLUTION, mesh), key);
});

test('canonical JSON and the hash', () => {
  assert.equal(canonicalJson({ b: 1, a: [{ d: null, c: 'x' }], e: undefined }), '{"a":[{"c":"x","d":null}],"b":1}');
  assert.match(hashBytes('billow'), /^[0-9a-f]{16}$/);
  assert.equal(hashBytes('billow'), hashBytes(new TextEncoder().encode('billow')));
  assert.notEqual(hashBytes('billow'), hashBytes('billoW'));
  assert.notEqual(hashBytes(''), hashBytes('\0'));
});

test('a damaged or foreign result file is not used', () => {
  const good = read('sphere3.result.json');
  assert.ok(parseStoredResult(good));
  assert.equal(parseStoredResult(good.slice(0, good.length / 2)), null, 'cut short');
  assert.equal(parseStoredResult('{"format":"billow-pattern","version":1}'), null, 'another format');
  assert.equal(parseStoredResult(JSON.stringify({ ...JSON.parse(good), version: RESULT_VERSION + 1 })), null, 'a newer version');
  assert.equal(parseStoredResult(JSON.stringify({ ...JSON.parse(good), version: RESULT_VERSION - 1 })), null, 'made by an older solver');
  assert.equal(parseStoredResult(JSON.stringify({ ...JSON.parse(good), pattern: { format: 'billow-pattern', panels: [] } })), null, 'no inflated shape');
  assert.equal(parseStoredResult(null), null, 'not fetched');
});
