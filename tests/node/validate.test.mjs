// The wasm module in Node: target validation through the same JS layer the worker uses, compared with
// the native CLI's report (`billow check --json`): native and wasm must agree.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { execFileSync, spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { loadApi } from './load-module.mjs';
import { readObjText } from './obj.mjs';

const MESHES = fileURLToPath(new URL('../../../shared/meshes', import.meta.url));
const CLI = fileURLToPath(new URL('../../build/native/billow', import.meta.url));
const api = await loadApi();

function nativeReport(path) {
  try {
    return JSON.parse(execFileSync(CLI, ['check', '--json', path], { encoding: 'utf8' }));
  } catch (error) {
    if (error.status === 1) return JSON.parse(error.stdout); // "not usable" exits 1 with the report
    throw error;
  }
}

// The CLI's report of a mesh given as arrays (written to an OBJ file for it).
function objText(positions, indices) {
  const lines = [];
  for (let v = 0; v < positions.length; v += 3) lines.push(`v ${positions[v]} ${positions[v + 1]} ${positions[v + 2]}`);
  for (let f = 0; f < indices.length; f += 3) lines.push(`f ${indices[f] + 1} ${indices[f + 1] + 1} ${indices[f + 2] + 1}`);
  return lines.join('\n');
}

function nativeReportOf(positions, indices) {
  const dir = mkdtempSync('/tmp/billow-node-');
  writeFileSync(`${dir}/mesh.obj`, objText(positions, indices));
  try {
    return nativeReport(`${dir}/mesh.obj`);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

// Numbers equal to 12 significant digits (summation order may differ between SIMD and scalar builds).
function assertSameReport(a, b, path = 'report') {
  if (typeof a === 'number' && typeof b === 'number') {
    assert.ok(Math.abs(a - b) <= 1e-12 * Math.max(1, Math.abs(a), Math.abs(b)), `${path}: ${a} vs ${b}`);
  } else if (Array.isArray(a)) {
    assert.equal(a.length, b.length, `${path}.length`);
    a.forEach((v, i) => assertSameReport(v, b[i], `${path}[${i}]`));
  } else if (a && typeof a === 'object') {
    assert.deepEqual(Object.keys(a).sort(), Object.keys(b).sort(), path);
    for (const k of Object.keys(a)) assertSameReport(a[k], b[k], `${path}.${k}`);
  } else {
    assert.equal(a, b, path);
  }
}

for (const name of ['sphere.obj', 'spot.obj', 'blub.obj', 'octopus.obj']) {
  test(`${name}: wasm and native reports are identical and the target is usable`, () => {
    const path = `${MESHES}/${name}`;
    const { positions, indices } = readObjText(readFileSync(path, 'utf8'));
    const { report } = api.validateTarget(positions, indices);
    assert.equal(report.ok, true);
    assert.equal(report.stats.genus, 0);
    assertSameReport(report, nativeReport(path));
  });
}

test('an open mesh is reported identically by wasm and native, with the hole located', () => {
  const { positions, indices } = readObjText(readFileSync(`${MESHES}/sphere.obj`, 'utf8'));
  const open = indices.slice(3); // drop the first triangle
  const { report } = api.validateTarget(positions, open);
  assert.equal(report.ok, false);
  const issue = report.issues.find((i) => i.code === 'mesh.open');
  assert.ok(issue, 'mesh.open reported');
  assert.equal(report.stats.boundary_edges, 3);
  assert.match(issue.message, /must be closed/);
  assert.equal(issue.location.length, 3);
  // The same mesh through the CLI.
  assertSameReport(report, nativeReportOf(positions, open));
  // Told in words, `billow check` names its own way to close the holes (the app's message has its button).
  const dir = mkdtempSync('/tmp/billow-node-');
  try {
    writeFileSync(`${dir}/open.obj`, objText(positions, open));
    const run = spawnSync(CLI, ['check', `${dir}/open.obj`], { encoding: 'utf8' });
    assert.equal(run.status, 1);
    assert.match(run.stderr, /must be closed to hold air/);
    assert.match(run.stderr, new RegExp(`billow suggest ${dir}/open\\.obj --close-holes`));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('a triangle written twice comes back once, with a notice, the other faces in their order', () => {
  const { positions, indices } = readObjText(readFileSync(`${MESHES}/spot.obj`, 'utf8'));
  const twice = Uint32Array.from([...indices.slice(0, 30), ...indices.slice(27, 30), ...indices.slice(30)]);
  const result = api.validateTarget(positions, twice);
  assert.equal(result.report.ok, true);
  assert.equal(result.report.modified, true);
  const notice = result.report.issues.find((i) => i.code === 'mesh.duplicate');
  assert.equal(notice?.severity, 'notice');
  assert.match(notice.message, /1 triangle appeared twice, the first .*: the copy was left out\./);
  assert.deepEqual(Array.from(result.indices), Array.from(indices));
});

test('an inside-out mesh comes back flipped with a notice', () => {
  const { positions, indices } = readObjText(readFileSync(`${MESHES}/blub.obj`, 'utf8'));
  const flipped = indices.slice();
  for (let f = 0; f < flipped.length; f += 3) [flipped[f + 1], flipped[f + 2]] = [flipped[f + 2], flipped[f + 1]];
  const result = api.validateTarget(positions, flipped);
  assert.equal(result.report.ok, true);
  assert.equal(result.report.modified, true);
  assert.ok(result.report.issues.some((i) => i.code === 'mesh.inside-out' && i.severity === 'notice'));
  assert.deepEqual(Array.from(result.indices), Array.from(indices));
});

test('a point where one piece touches itself gets a vertex for each part, as the CLI gives it, and the mesh is usable', () => {
  // The sphere with its vertex farthest from vertex 0 welded onto it (test_validate.cpp's pinched sphere).
  const { positions, indices } = readObjText(readFileSync(`${MESHES}/sphere.obj`, 'utf8'));
  const at = (v) => [0, 1, 2].map((k) => positions[3 * v + k]);
  const gap = (v) => Math.hypot(...at(v).map((x, k) => x - at(0)[k]));
  let far = 0;
  for (let v = 0; v < positions.length / 3; v++) if (gap(v) > gap(far)) far = v;
  const pinched = indices.map((v) => (v === far ? 0 : v));
  const result = api.validateTarget(positions, pinched);
  assert.equal(result.report.ok, true, JSON.stringify(result.report.issues));
  assert.ok(result.report.issues.some((i) => i.code === 'mesh.pinch-split' && i.severity === 'notice'));
  assert.equal(result.positions.length, positions.length + 3);
  assert.deepEqual(Array.from(result.positions.slice(-3)), Array.from(Float32Array.from(at(0))));
  const renamed = [...result.indices].filter((v, i) => v !== pinched[i]);
  assert.ok(renamed.length >= 3 && renamed.every((v) => v === positions.length / 3), JSON.stringify(renamed));
  // The CLI reads the mesh from a file, welded as the app reads one (the vertex left unused goes): the same report as
  // the app's for that file.
  const fromFile = api.readMeshFile('mesh.obj', new TextEncoder().encode(objText(positions, pinched)).buffer, 1e7);
  assertSameReport(api.validateTarget(fromFile.positions, fromFile.indices).report, nativeReportOf(positions, pinched));
});

test('no heap growth over repeated validations', () => {
  const { positions, indices } = readObjText(readFileSync(`${MESHES}/spot.obj`, 'utf8'));
  api.validateTarget(positions, indices);
  const before = api.module.HEAPU8.length;
  for (let i = 0; i < 30; i++) api.validateTarget(positions, indices);
  assert.equal(api.module.HEAPU8.length, before);
});
