// The target's up axis (web/src/app/up-axis.js): the app's design reader against the same good and bad values
// as the C++ reader (tests/data/up-axis-cases.json, tests/native/test_design_json.cpp), the height measured
// along the up axis as the CLI's designScale measures it, the edit and its undo, and the guess the validation report
// brings when a mesh is opened (wasm/src/mesh/up_axis.hpp, tested natively on every shared mesh).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, existsSync, mkdtempSync, writeFileSync } from 'node:fs';
import { execFileSync, spawnSync } from 'node:child_process';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { newDesign, parseDesign } from '../../web/src/app/design.js';
import { setUp } from '../../web/src/app/commands.js';
import { History } from '../../web/src/app/history.js';
import { UP_AXES, UP_FRAMES, upOf, upFrameSize, heightScale, withGuessedUp } from '../../web/src/app/up-axis.js';
import { readObjText } from './obj.mjs';
import { loadApi } from './load-module.mjs';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
const MESHES = join(ROOT, '../shared/meshes');
const CASES = JSON.parse(readFileSync(join(ROOT, 'tests/data/up-axis-cases.json'), 'utf8'));
const CLI = process.env.BILLOW_CLI ?? join(ROOT, 'build/native/billow');

const mesh = (name) => readObjText(readFileSync(join(MESHES, name), 'utf8'));

// The validator's bounding box of a mesh (report.stats), which the app's scale and statistics read.
function statsOf({ positions }) {
  const bbox_min = [Infinity, Infinity, Infinity];
  const bbox_max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3)
    for (let k = 0; k < 3; k++) {
      bbox_min[k] = Math.min(bbox_min[k], positions[i + k]);
      bbox_max[k] = Math.max(bbox_max[k], positions[i + k]);
    }
  return { bbox_min, bbox_max };
}

// A Y-up mesh as a Z-up tool writes it: (x, y, z) -> (x, -z, y), a quarter turn about x.
function turnedZUp({ positions, indices }) {
  const out = new Float64Array(positions.length);
  for (let i = 0; i < positions.length; i += 3) out.set([positions[i], -positions[i + 2], positions[i + 1]], i);
  return { positions: out, indices };
}

const fileDesign = (up) => ({ ...newDesign(), target: { file: 'koala.obj', ...(up === undefined ? {} : { up }) } });

test('the reader keeps the six up axes and drops anything else with a warning, as the C++ reader', () => {
  for (const up of CASES.good) {
    const { design, warnings } = parseDesign(fileDesign(up));
    assert.deepEqual(warnings, [], up);
    assert.equal(upOf(design), up);
  }
  for (const up of CASES.bad) {
    const { design, warnings } = parseDesign(fileDesign(up));
    assert.equal(warnings.length, 1, JSON.stringify(up));
    assert.match(warnings[0], /up axis .* is not one of \+y, -y, \+z, -z, \+x, -x; the target stands Y up instead/);
    assert.equal(design.target.up, undefined);
    assert.equal(design.target.file, 'koala.obj', 'the target itself is kept');
  }
  assert.equal(upOf(parseDesign(fileDesign()).design), '+y', 'no up axis is Y up');
  assert.equal(upOf(parseDesign({ ...fileDesign('+q'), target: { example: 'nope', up: '+z' } }).design), '+y');
});

test('the up frames are the C++ reader\'s rotations, and the toolbar offers each of them', () => {
  assert.deepEqual(UP_FRAMES, CASES.frames);
  const det = ([a, b, c]) => a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  for (const [up, frame] of Object.entries(UP_FRAMES)) assert.equal(det(frame), 1, `${up} turns without mirroring`);
  const html = readFileSync(join(ROOT, 'web/index.html'), 'utf8');
  const select = html.slice(html.indexOf('<select id="up-select">'), html.indexOf('</select>', html.indexOf('<select id="up-select">')));
  const options = [...select.matchAll(/<option value="([^"]+)"[^>]*>([^<]+)<\/option>/g)].map((m) => ({ value: m[1], label: m[2] }));
  assert.deepEqual(options, UP_AXES);
  assert.deepEqual(UP_AXES.map((a) => a.value).sort(), [...CASES.good].sort());
});

test('the height is measured along the up axis: the same sizes and scale as the CLI\'s designScale', () => {
  for (const c of CASES.sizes) {
    const stats = statsOf(mesh(c.mesh));
    const size = upFrameSize(stats, c.up);
    c.size.forEach((s, i) => assert.ok(Math.abs(size[i] - s) < 1e-9, `${c.up}: axis ${i} is ${size[i]}, not ${s}`));
    const design = { ...fileDesign(c.up), size: { height: 0.6 } };
    const scale = heightScale(design, stats);
    assert.ok(Math.abs(scale - 0.6 / c.size[1]) < 1e-9 * scale, `${c.up}: scale ${scale}`);
  }
  // koala.obj read Z up: its 9.21 units of length are the height, not its 5.34 units standing Y up.
  const stats = statsOf(mesh('koala.obj'));
  assert.ok(heightScale({ ...fileDesign('+z'), size: { height: 0.6 } }, stats) < 0.6 * heightScale({ ...fileDesign(), size: { height: 0.6 } }, stats));
});

test('the app\'s scale is the CLI\'s scale for the same mesh and up axis', { skip: !existsSync(CLI) && 'no native CLI built' }, () => {
  const dir = mkdtempSync(join(tmpdir(), 'billow-up-'));
  const stats = statsOf(mesh('koala.obj'));
  for (const up of CASES.good) {
    const design = { format: 'billow-design', version: 1, target: { obj: join(MESHES, 'koala.obj'), up }, size: { height: 0.75 }, seams: [] };
    const path = join(dir, `koala${up}.billow.json`);
    writeFileSync(path, JSON.stringify(design));
    const out = join(dir, `koala${up}.segments.json`);
    try {
      execFileSync(CLI, ['segment', path, '--out', out], { stdio: 'ignore' });
    } catch (error) {
      if (error.status !== 1) throw error; // 1: no seams make no panels, and the file is still written
    }
    const cli = JSON.parse(readFileSync(out, 'utf8')).scale;
    const app = heightScale({ ...fileDesign(up), size: { height: 0.75 } }, stats);
    assert.ok(Math.abs(cli - app) <= 1e-12 * app, `${up}: the CLI scales by ${cli}, the app by ${app}`);
  }
});

test('the up axis is an edit: set, undone and redone; Y up leaves the field out', () => {
  const start = fileDesign();
  const history = new History(start);
  history.apply((d) => setUp(d, '+z'));
  assert.equal(upOf(history.present), '+z');
  assert.equal(start.target.up, undefined, 'the command does not change its input');
  assert.equal(history.apply((d) => setUp(d, '+z')), history.present, 'the same axis is no new step');
  history.apply((d) => setUp(d, '-x'));
  assert.equal(upOf(history.undo()), '+z');
  assert.equal(upOf(history.undo()), '+y');
  assert.equal(history.canUndo, false);
  assert.equal(upOf(history.redo()), '+z');
  const back = setUp(history.present, '+y');
  assert.equal('up' in back.target, false, 'designs made before the up axis existed stay as they were');
  assert.equal(parseDesign(JSON.parse(JSON.stringify(history.present))).design.target.up, '+z', 'saved and read back');
});

test('a guessed Z up goes into the new design with a notice that says how to change it', async () => {
  const api = await loadApi();
  const reportOf = ({ positions, indices }) => api.validateTarget(positions, indices).report;
  const koala = mesh('koala.obj');
  const kept = withGuessedUp(fileDesign(), reportOf(koala), 'koala.obj');
  assert.equal(kept.notice, null);
  assert.equal(upOf(kept.design), '+y');
  const guessed = withGuessedUp(fileDesign(), reportOf(turnedZUp(koala)), 'koala-z.obj');
  assert.equal(upOf(guessed.design), '+z');
  assert.match(guessed.notice, /"koala-z\.obj".*Z up.*Height.*choose another axis in Up/);
  // Shown Z up, the turned koala is the koala as it was: the up frame undoes the turn exactly.
  const turned = turnedZUp(koala).positions;
  const [, y, z] = UP_FRAMES['+z'];
  for (let i = 0; i < turned.length; i += 3) {
    const p = [turned[i], turned[i + 1], turned[i + 2]];
    assert.equal(y[0] * p[0] + y[1] * p[1] + y[2] * p[2], koala.positions[i + 1]);
    assert.equal(z[0] * p[0] + z[1] * p[1] + z[2] * p[2] + 0, koala.positions[i + 2] + 0);
  }
});

// `billow suggest MESH` takes the guess from the same validation report: a shop's Z-up catalogue is patterned at the
// height it asks for, measured along Z, and --up overrides the guess.
test('the command line takes a Z-up mesh Z up, as the app does, unless --up says otherwise', { skip: !existsSync(CLI) && 'no native CLI built' }, () => {
  const dir = mkdtempSync(join(tmpdir(), 'billow-up-guess-'));
  const { positions, indices } = turnedZUp(mesh('koala.obj'));
  const lines = [];
  for (let i = 0; i < positions.length; i += 3) lines.push(`v ${positions[i]} ${positions[i + 1]} ${positions[i + 2]}`);
  for (let i = 0; i < indices.length; i += 3) lines.push(`f ${indices[i] + 1} ${indices[i + 1] + 1} ${indices[i + 2] + 1}`);
  const obj = join(dir, 'koala-z.obj');
  writeFileSync(obj, lines.join('\n'));
  const suggest = (out, extra) => {
    const run = spawnSync(CLI, ['suggest', obj, '--panels', '2', '--out-dir', join(dir, out), '--resolution', '300', '--max-iterations', '1', '--optimize', '1', ...extra], { encoding: 'utf8' });
    assert.equal(run.status, 0, run.stderr);
    return { said: run.stderr, design: JSON.parse(readFileSync(join(dir, out, 'layout-1.billow.json'), 'utf8')) };
  };
  const guessed = suggest('guessed', []);
  assert.match(guessed.said, /koala-z\.obj looks made Z up.*--up \+y keeps Y up/);
  assert.equal(guessed.design.target.up, '+z');
  const kept = suggest('kept', ['--up', '+y']);
  assert.doesNotMatch(kept.said, /looks made Z up/);
  assert.equal(kept.design.target.up ?? '+y', '+y');
});
