// One design document, one reader: the native CLI (`billow check DESIGN.json --json`) and the app's worker
// (TargetSession.buildPattern, the wasm module through the worker's JS layer) read the seams, internal
// connections, material and pressure of a design through the same C++ functions (wasm/src/io/design_json.hpp),
// so they accept and refuse the same designs, with the same error code and message.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { loadApi } from './load-module.mjs';
import { readObjText } from './obj.mjs';
import { TargetSession } from '../../web/src/worker/solver-api.js';

const CLI = fileURLToPath(new URL('../../build/native/billow', import.meta.url));
const SPHERE = fileURLToPath(new URL('../../web/public/examples/sphere.obj', import.meta.url));
const api = await loadApi();
const sphere = readObjText(readFileSync(SPHERE, 'utf8'));
const base = JSON.parse(readFileSync(new URL('../data/sphere-gores.billow.json', import.meta.url), 'utf8'));
base.target = { obj: SPHERE };
const dir = mkdtempSync(join(tmpdir(), 'billow-design-reader-'));

// Meters per target unit, as the app computes it: the height over the target's extent along +y.
const ys = sphere.positions.filter((_, i) => i % 3 === 1);
const scale = base.size.height / (Math.max(...ys) - Math.min(...ys));

// A copy of the base design with one change.
const edit = (change) => {
  const d = structuredClone(base);
  change(d);
  return d;
};

// Good designs: each must be read by both.
const GOOD = {
  'as saved': () => {},
  'a connection as {seams}': (d) => { d.connections = [{ seams: [0, 1] }]; },
  'a connection as a pair': (d) => { d.connections = [[0, 1]]; },
  'a seam joined to itself (the builder\'s problem)': (d) => { d.connections = [[2, 2]]; },
  'a preset material': (d) => { d.material = { name: 'pvc' }; },
  'a material of its own': (d) => { d.material = { name: 'mine', thickness: 1e-4, youngs_modulus: 5e7, density: 900 }; },
  'a pressure': (d) => { d.pressure = 2500; },
  'sliding seams': (d) => { for (const s of d.seams) s.weight = 0; },
  'barycentric coordinates within tolerance': (d) => {
    const p = d.seams[0].points[0];
    p.bary = [p.bary[0] + 5e-4, p.bary[1], p.bary[2]];
  },
  'a 3D point off the surface, within the target\'s size': (d) => { d.seams[1].points[1] = d.seams[1].points[1].map((x) => 1.8 * x); },
};

// Bad designs: each must be refused by both with design.bad-value and a message holding these words.
const BAD = {
  'barycentric coordinates summing to 1.5': [(d) => { d.seams[0].points[0].bary = [0.5, 0.5, 0.5]; }, /Point 1 of seam 1 "meridian 1" \(seams\[0\]\.points\[0\]\) lies outside its triangle/],
  'a negative barycentric coordinate': [(d) => { d.seams[0].points[0].bary = [1.1, -0.1, 0]; }, /outside its triangle/],
  'a face the target does not have': [(d) => { d.seams[0].points[0].face = 99999; }, /Seam 1 "meridian 1": point 1 lies on triangle 99999, but the target has only 1280 triangles/],
  'a negative face': [(d) => { d.seams[0].points[0].face = -1; }, /names no triangle of the target: -1/],
  'a face that is no whole number': [(d) => { d.seams[0].points[0].face = 2.5; }, /names no triangle/],
  'a point kilometres away': [(d) => { d.seams[1].points[1] = [0, 0, 5000]; }, /Seam 2 "meridian 2": point 2 \[0, 0, 5000\] lies [\d.]+ times the target's size away/],
  'a point beyond the target\'s size': [(d) => { d.seams[1].points[1] = d.seams[1].points[1].map((x) => 5 * x); }, /Seam 2 "meridian 2": point 2 .* times the target's size away/],
  'a connection to a seam the design does not have': [(d) => { d.connections = [[0, 7]]; }, /Internal connection 1 \(connections\[0\]\) joins seam 7 \(counted from 0\), but the design has only 3 seams/],
  'connections that are no list': [(d) => { d.connections = 'all'; }, /The internal connections \(connections\) must be a list/],
  'a connection of one seam': [(d) => { d.connections = [[0]]; }, /must join two of the design's seams/],
  'a connection {seams} of one seam': [(d) => { d.connections = [{ seams: [0] }]; }, /must join two of the design's seams/],
  'a connection in another form': [(d) => { d.connections = [{ pair: [0, 1] }]; }, /must join two of the design's seams/],
  'a connection to seam 1.5': [(d) => { d.connections = [[0, 1.5]]; }, /must join two of the design's seams/],
  'a negative weight': [(d) => { d.seams[2].weight = -1; }, /The weight of seam 3 "meridian 3" \(seams\[2\]\.weight\)/],
  'a weight in words': [(d) => { d.seams[2].weight = 'heavy'; }, /seams\[2\]\.weight/],
  'a weight past 10^6': [(d) => { d.seams[2].weight = 2e6; }, /seams\[2\]\.weight/],
  'closed in words': [(d) => { d.seams[0].closed = 'yes'; }, /seams\[0\]\.closed/],
  'a name that is no text': [(d) => { d.seams[0].name = 7; }, /seams\[0\]\.name/],
  'a seam of one point': [(d) => { d.seams[2].points = d.seams[2].points.slice(0, 1); }, /Seam 3 "meridian 3" \(seams\[2\]\) is open and needs at least 2 points/],
  'a point that is neither form': [(d) => { d.seams[2].points[0] = [1, 2]; }, /must be a surface point \{face, bary\} or a 3D point/],
  'seams that are no list': [(d) => { d.seams = { points: 1 }; }, /The seams \(seams\) must be a list/],
  'a negative thickness': [(d) => { d.material = { name: 'pvc', thickness: -1 }; }, /The sheet thickness \(material\.thickness\) must be between 0\.1 µm and 1 cm/],
  'a Young\'s modulus past 10 TPa': [(d) => { d.material = { youngs_modulus: 1e20 }; }, /material\.youngs_modulus/],
  'a material that is a word': [(d) => { d.material = 'foil'; }, /The material \(material\) must be an object/],
  'a material name that is no text': [(d) => { d.material = { name: 5 }; }, /material\.name/],
  'a negative density': [(d) => { d.material = { density: -1 }; }, /material\.density/],
  'no pressure': [(d) => { d.pressure = 0; }, /The pressure \(pressure\) must be between 1 Pa and 10 MPa, not 0/],
  'a pressure in words': [(d) => { d.pressure = 'high'; }, /pressure/],
};

// The CLI's reply: { status: 'ok', result } or { status: 'error', code, message }.
function cliReads(design, name) {
  const path = join(dir, `${name.replace(/[^a-z0-9]+/gi, '-')}.billow.json`);
  writeFileSync(path, JSON.stringify(design));
  try {
    return JSON.parse(execFileSync(CLI, ['check', path, '--json'], { encoding: 'utf8' }));
  } catch (error) {
    if (error.status === 1) return JSON.parse(error.stdout); // refused: exit 1 with the reply
    throw error;
  }
}

// The worker's reply to the design's seams and physics, sent as the document holds them.
function workerReads(design) {
  const t = new TargetSession(api);
  try {
    t.setTarget(sphere.positions, sphere.indices);
    const options = { scale, triangles: 300 };
    for (const key of ['connections', 'material', 'pressure']) if (key in design) options[key] = design[key];
    const built = t.buildPattern(design.seams, options);
    return { status: 'ok', built };
  } catch (error) {
    if (!error.code) throw error;
    return { status: 'error', code: error.code, message: error.message };
  } finally {
    t.delete();
  }
}

test('good designs are read by both the CLI and the worker', () => {
  for (const [name, change] of Object.entries(GOOD)) {
    const design = edit(change);
    const cli = cliReads(design, name);
    const worker = workerReads(design);
    assert.equal(cli.status, 'ok', `${name}: the CLI refused it: ${cli.message}`);
    assert.equal(worker.status, 'ok', `${name}: the worker refused it: ${worker.message}`);
    assert.equal(cli.result.seams, design.seams.length, name);
    assert.equal(worker.built.figures.internalPanels, name.startsWith('a connection') ? 1 : 0, name);
  }
  // A seam joined to itself is read, and the pattern builder says what is wrong with it.
  const self = workerReads(edit(GOOD['a seam joined to itself (the builder\'s problem)'])).built;
  assert.equal(self.ok, false);
  assert.match(self.problems.find((p) => p.code === 'pattern.connection')?.message ?? '', /joins a seam to itself/);
  // Both take the design's material and pressure.
  const own = workerReads(edit(GOOD['a material of its own'])).built.pattern.material;
  assert.deepEqual([own.name, own.thickness, own.youngs_modulus, own.density], ['mine', 1e-4, 5e7, 900]);
  assert.equal(cliReads(edit(GOOD['a preset material']), 'pvc').result.material, 'pvc');
});

test('bad designs are refused by both, with the same code and message', () => {
  for (const [name, [change, words]] of Object.entries(BAD)) {
    const design = edit(change);
    const cli = cliReads(design, name);
    const worker = workerReads(design);
    assert.equal(cli.status, 'error', `${name}: the CLI accepted it`);
    assert.equal(worker.status, 'error', `${name}: the worker accepted it`);
    assert.equal(cli.code, 'design.bad-value', `${name}: ${cli.message}`);
    assert.equal(worker.code, cli.code, `${name}: ${worker.message}`);
    assert.match(cli.message, words, name);
    assert.equal(worker.message, cli.message, name);
  }
});

test('a seam traced on its own is refused by the same rules, naming it by its name', () => {
  const t = new TargetSession(api);
  try {
    t.setTarget(sphere.positions, sphere.indices);
    const seam = base.seams[1];
    assert.ok(t.traceSeam(seam).length > 0);
    const refused = (s) => {
      try {
        t.traceSeam(s);
      } catch (error) {
        return error;
      }
      return null;
    };
    const far = refused({ ...seam, points: [seam.points[0], [0, 0, 5000]] });
    assert.equal(far?.code, 'design.bad-value');
    assert.match(far.message, /^The seam "meridian 2": point 2 \[0, 0, 5000\] lies [\d.]+ times the target's size away/);
    const bary = refused({ ...seam, points: [{ face: 3, bary: [0.5, 0.5, 0.5] }, seam.points[1]] });
    assert.equal(bary?.code, 'design.bad-value');
    assert.match(bary.message, /^Point 1 of the seam "meridian 2" \(seam\.points\[0\]\) lies outside its triangle/);
  } finally {
    t.delete();
  }
});
