// A designer's mesh repaired through the worker's handlers in Node, as the app installs a target. Thin handles: a wire
// hoop's report names its thin handle (the loop round its tube), a swim ring's does not, and installed with
// cutThinHandles the hoop comes back cut: a handle fewer, every face kept, the ends closed. Holes: a sphere open at its
// top is refused as closable, and installed with closeHoles comes back closed, every face kept.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Op } from '../../web/src/worker/protocol.js';
import { handlers, run } from './worker-handlers.mjs';
import { designForFile, newDesign, parseDesign } from '../../web/src/app/design.js';
import { loadSharedMesh } from './obj.mjs';

// A ring around y: radius R to the tube's middle, tube radius r, as flat arrays.
function ring(R, r, nu, nv) {
  const positions = [], indices = [];
  for (let i = 0; i < nu; i++)
    for (let j = 0; j < nv; j++) {
      const u = (2 * Math.PI * i) / nu, v = (2 * Math.PI * j) / nv, rho = R + r * Math.cos(v);
      positions.push(rho * Math.cos(u), r * Math.sin(v), rho * Math.sin(u));
    }
  const at = (i, j) => (i % nu) * nv + (j % nv);
  for (let i = 0; i < nu; i++)
    for (let j = 0; j < nv; j++) indices.push(at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i + 1, j));
  return { positions: Float32Array.from(positions), indices: Uint32Array.from(indices) };
}

test('a hoop names its thin handle and is cut through it on request; a swim ring has none', () => {
  const hoop = ring(1, 0.03, 120, 16);
  const shown = run(handlers[Op.setTarget](hoop));
  assert.equal(shown.report.stats.genus, 1);
  assert.equal(shown.report.thinHandles.length, 1);
  // Round the tube: the 16-gon's perimeter (float32 positions).
  assert.ok(Math.abs(shown.report.thinHandles[0] - 32 * 0.03 * Math.sin(Math.PI / 16)) < 1e-6, `${shown.report.thinHandles[0]}`);
  assert.equal(shown.indices.length, hoop.indices.length, 'nothing is cut unasked');

  const cut = run(handlers[Op.setTarget]({ ...hoop, cutThinHandles: true }));
  assert.equal(cut.report.stats.genus, 0);
  assert.equal(cut.report.stats.components, 1);
  assert.equal(cut.report.thinHandlesCut, 1);
  assert.deepEqual(cut.report.thinHandles, []);
  assert.ok(cut.report.ok);
  assert.equal(cut.indices.length, hoop.indices.length + 32 * 3, 'two ends of 16 triangles');
  assert.equal(cut.positions.length, hoop.positions.length + (16 + 2) * 3);
  // Every face of the hoop keeps its corners or their copies, within 0.3 of an edge of where they were.
  const far = [];
  for (let c = 0; c < hoop.indices.length; c++) {
    const a = hoop.indices[c] * 3, b = cut.indices[c] * 3;
    const d = Math.hypot(...[0, 1, 2].map((k) => hoop.positions[a + k] - cut.positions[b + k]));
    if (d > 0.3 * 0.055) far.push(c);
  }
  assert.deepEqual(far, []);
  // Installed again as the autosave gives it back, with the design's flag: nothing more to cut.
  const again = run(handlers[Op.setTarget]({ positions: cut.positions, indices: cut.indices, cutThinHandles: true }));
  assert.equal(again.indices.length, cut.indices.length);
  assert.equal(again.report.stats.genus, 0);

  const swimRing = run(handlers[Op.setTarget](ring(1, 0.4, 48, 24)));
  assert.equal(swimRing.report.stats.genus, 1);
  assert.deepEqual(swimRing.report.thinHandles, []);
});

test('a design keeps target.cutThinHandles when it is true or false, and drops another value with a warning', () => {
  const read = (value) => parseDesign({ format: 'billow-design', version: 1, target: { file: 'boot.obj', cutThinHandles: value }, seams: [] });
  assert.equal(read(true).design.target.cutThinHandles, true);
  assert.deepEqual(read(true).warnings, []);
  assert.equal(read(false).design.target.cutThinHandles, false);
  const bad = read('yes');
  assert.equal('cutThinHandles' in bad.design.target, false);
  assert.match(bad.warnings.join('\n'), /target\.cutThinHandles\) must be true or false, not "yes"/);
  const holes = parseDesign({ format: 'billow-design', version: 1, target: { file: 'lion.obj', closeHoles: 1 }, seams: [] });
  assert.equal('closeHoles' in holes.design.target, false);
  assert.match(holes.warnings.join('\n'), /target\.closeHoles\) must be true or false, not 1/);
});

test('a sphere open at its top is refused as one whose holes can be closed, and closed on request', () => {
  const sphere = loadSharedMesh('sphere.obj');
  const y = (f) => [0, 1, 2].reduce((sum, k) => sum + sphere.positions[3 * sphere.indices[3 * f + k] + 1], 0) / 3;
  const faces = sphere.indices.length / 3, kept = [];
  for (let f = 0; f < faces; f++) if (y(f) < 0.8) kept.push(...sphere.indices.slice(3 * f, 3 * f + 3));
  const open = { positions: Float32Array.from(sphere.positions), indices: Uint32Array.from(kept) };
  assert.throws(() => run(handlers[Op.setTarget](open)), (error) => {
    assert.equal(error.code, 'target.invalid');
    assert.equal(error.details.closable, true);
    assert.equal(error.details.report.stats.holes, 1);
    return true;
  });
  const closed = run(handlers[Op.setTarget]({ ...open, closeHoles: true }));
  assert.ok(closed.report.ok);
  assert.equal(closed.report.holesClosed, 1);
  assert.equal(closed.report.stats.genus, 0);
  assert.deepEqual(Array.from(closed.indices.slice(0, kept.length)), kept, 'every face kept');
  assert.equal(closed.report.facesRead, kept.length / 3, 'the faces added are known as such');
  // Saved beside the mesh file, a seam point on the cap is written as the 3D point it is (a later Billow may cap
  // otherwise), one on the file's own faces as { face, bary }.
  const target = { positions: closed.positions, indices: closed.indices, report: closed.report };
  const capFace = kept.length / 3 + 2, corners = [0, 1, 2].map((k) => closed.indices[3 * capFace + k]);
  const design = { ...newDesign(), target: { file: 'open.obj', closeHoles: true }, seams: [{ name: 'around', closed: false, points: [{ face: 5, bary: [0.2, 0.3, 0.5] }, { face: capFace, bary: [0.5, 0.5, 0] }] }] };
  const written = designForFile(design, target);
  assert.deepEqual(written.seams[0].points[0], { face: 5, bary: [0.2, 0.3, 0.5] });
  const expected = [0, 1, 2].map((axis) => 0.5 * closed.positions[3 * corners[0] + axis] + 0.5 * closed.positions[3 * corners[1] + axis]);
  written.seams[0].points[1].forEach((x, axis) => assert.ok(Math.abs(x - expected[axis]) < 1e-6, `${x} against ${expected[axis]}`));
  assert.deepEqual(design.seams[0].points[1], { face: capFace, bary: [0.5, 0.5, 0] }, 'the design itself is left as it is');
  // A target opened as it was (nothing added) has no report.facesRead: its design is written as it is.
  const whole = run(handlers[Op.setTarget]({ positions: Float32Array.from(sphere.positions), indices: Uint32Array.from(sphere.indices) }));
  assert.equal(whole.report.facesRead, undefined);
  assert.equal(designForFile(design, { ...whole }), design);
  // A mesh with another fault as well is not offered the closing: it would still be refused.
  // Three triangles on one edge: open, and non-manifold there.
  const fin = { positions: Float32Array.from([0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1]), indices: Uint32Array.from([0, 1, 2, 1, 0, 3, 0, 1, 4]) };
  assert.throws(() => run(handlers[Op.setTarget](fin)), (error) => {
    assert.ok(error.details.report.issues.some((i) => i.code === 'mesh.non-manifold-edge'));
    assert.equal(error.details.closable, false);
    return true;
  });
});
