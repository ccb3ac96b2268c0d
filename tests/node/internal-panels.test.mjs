// Internal connections through the wasm binding (TargetSession.buildPattern / startOptimization): the option
// "connections" ([[i, j]] or [{ seams: [i, j] }]) adds an internal panel, sewn onto both seams; a connection that
// cannot be built is a problem in the designer's words, one the design cannot have is refused as the CLI refuses it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadApi } from './load-module.mjs';
import { readObjText } from './obj.mjs';
import { TargetSession } from '../../web/src/worker/solver-api.js';

const api = await loadApi();
const sphere = readObjText(readFileSync(new URL('../../web/public/examples/sphere.obj', import.meta.url), 'utf8'));
const design = JSON.parse(readFileSync(new URL('../data/sphere-gores.billow.json', import.meta.url), 'utf8'));
const seams = design.seams.map(({ name, points, closed, weight }) => ({ name, points, closed, weight }));
const options = { scale: 0.25, triangles: 800 };

function session() {
  const t = new TargetSession(api);
  t.setTarget(sphere.positions, sphere.indices);
  return t;
}

test('a connection between two meridians adds an internal panel sewn onto both seams', () => {
  const t = session();
  try {
    const plain = t.buildPattern(seams, options);
    assert.equal(plain.ok, true);
    assert.equal(plain.pattern.panels.length, 3);
    for (const connections of [[[0, 1]], [{ seams: [0, 1] }]]) {
      const built = t.buildPattern(seams, { ...options, connections });
      assert.equal(built.ok, true, JSON.stringify(built.problems));
      assert.equal(built.figures.panels, 4);
      assert.equal(built.figures.internalPanels, 1);
      const panels = built.pattern.panels;
      assert.equal(panels.length, 4);
      assert.deepEqual(panels.map((p) => p.internal), [false, false, false, true]);
      assert.equal(panels[3].name, 'internal 1 (seams meridian 1|meridian 2)');
      assert.ok(panels[3].triangles.length > 20);
      // Stitched to the outer panels: stitches join the internal panel (3) to gores along both meridians.
      const sewnTo = new Set();
      for (const [pa, , pb] of built.pattern.stitches) {
        if (pa === 3) sewnTo.add(pb);
        if (pb === 3) sewnTo.add(pa);
      }
      assert.ok(sewnTo.size >= 2, `the internal panel is sewn to panels ${[...sewnTo]}`);
      // The outer panels are the same as without the connection.
      for (let p = 0; p < 3; p++) assert.deepEqual(panels[p].vertices, plain.pattern.panels[p].vertices);
    }
  } finally {
    t.delete();
  }
});

test('a connection that cannot be built is a problem; the outer panels are still built', () => {
  const t = session();
  try {
    const built = t.buildPattern(seams, { ...options, connections: [[2, 2]] });
    assert.equal(built.ok, false);
    assert.equal(built.pattern.panels.length, 3);
    const messages = built.problems.filter((p) => p.code === 'pattern.connection').map((p) => p.message);
    assert.equal(messages.length, 1);
    assert.match(messages[0], /The internal connection between seams "meridian 3" and "meridian 3" cannot be built: it joins a seam to itself/);
  } finally {
    t.delete();
  }
});

// Connections are read by the design document's rules (io/design_json.hpp), as the CLI reads them: one naming a
// seam the design does not have, or in another form, is refused before any work, naming the connection.
test('a connection to a seam the design does not have, or in another form, is refused', () => {
  const t = session();
  try {
    assert.throws(() => t.buildPattern(seams, { ...options, connections: [[2, 2], [0, 9]] }),
      (e) => e.code === 'design.bad-value' && /Internal connection 2 \(connections\[1\]\) joins seam 9 \(counted from 0\), but the design has only 3 seams/.test(e.message));
    assert.throws(() => t.buildPattern(seams, { ...options, connections: 'all' }), (e) => e.code === 'design.bad-value' && /must be a list/.test(e.message));
    assert.throws(() => t.buildPattern(seams, { ...options, connections: [[0]] }), (e) => e.code === 'design.bad-value' && /must join two of the design's seams/.test(e.message));
  } finally {
    t.delete();
  }
});

test('the optimizer runs on a pattern with an internal panel', () => {
  const t = session();
  try {
    const start = t.startOptimization(seams, { ...options, triangles: 400, connections: [[0, 1]] });
    assert.equal(start.ok, true);
    const step = t.optimizeStep(2, 0);
    assert.notEqual(step.state, 'failed', step.message);
    assert.ok(Number.isFinite(step.distanceRms));
    const optimized = t.optimizedPattern();
    assert.equal(optimized.panels.length, 4);
    assert.equal(optimized.panels[3].internal, true);
  } finally {
    t.delete();
  }
});

// Whether an internal panel carries load (web/src/app/pattern-session.js internalPanelRow, a row of the
// inflated pane's figures). A cushion (the sphere squashed to 40 % of its height, cut at the equator and by an
// arc over each pole) wants to become round: a diaphragm joining the two arcs is pulled taut. The flattened
// fish's middle-plane panel between its back and belly seams hangs slack (the inflating sides pull that
// outline inward), so it does not shape the balloon.
test('the figures say whether an internal panel is in tension or hangs slack', async () => {
  const { Inflation } = await import('../../web/src/worker/solver-api.js');
  const { internalPanelRow, internalPanelTension } = await import('../../web/src/app/pattern-session.js');
  const inflate = (pattern) => {
    const inflation = new Inflation(api);
    try {
      inflation.load(JSON.stringify(pattern));
      let s = inflation.step(400, 0);
      while (s.state === 'running') s = inflation.step(400, 0);
      assert.equal(s.state, 'converged', s.message);
      return inflation.snapshot();
    } finally {
      inflation.delete();
    }
  };
  const build = (mesh, seamList, opts) => {
    const t = new TargetSession(api);
    try {
      t.setTarget(mesh.positions, mesh.indices);
      const b = t.buildPattern(seamList, opts);
      assert.equal(b.ok, true, JSON.stringify(b.problems));
      return b.pattern;
    } finally {
      t.delete();
    }
  };
  const squashed = { positions: sphere.positions.map((v, i) => (i % 3 === 1 ? 0.4 * v : v)), indices: sphere.indices };
  const equator = Array.from({ length: 6 }, (_, k) => [Math.cos((k * Math.PI) / 3), 0, Math.sin((k * Math.PI) / 3)]);
  const cushionSeams = [
    { name: 'equator', closed: true, weight: 1, points: equator },
    { name: 'top', closed: false, weight: 1, points: [[1, 0, 0], [0, 0.4, 0], [-1, 0, 0]] },
    { name: 'bottom', closed: false, weight: 1, points: [[1, 0, 0], [0, -0.4, 0], [-1, 0, 0]] },
  ];
  const cushion = build(squashed, cushionSeams, { scale: 0.25, triangles: 800, connections: [[1, 2]] });
  const cushionResult = inflate(cushion);
  const [diaphragm] = internalPanelTension(cushion, cushionResult);
  assert.ok(diaphragm.tense > 0.8, `diaphragm: ${diaphragm.tense} of it in tension`);
  assert.match(internalPanelRow(cushion, cushionResult).join(': '), /^Internal panel: in tension \(\d+ %\)$/);

  const fishDesign = JSON.parse(readFileSync(new URL('../data/fish-midplane.billow.json', import.meta.url), 'utf8'));
  const blub = readObjText(readFileSync(new URL('../../web/public/examples/blub.obj', import.meta.url), 'utf8'));
  let low = Infinity, high = -Infinity;
  for (let i = 1; i < blub.positions.length; i += 3) low = Math.min(low, blub.positions[i]), high = Math.max(high, blub.positions[i]);
  const fishSeams = fishDesign.seams.map(({ name, points, closed, weight }) => ({ name, points, closed, weight }));
  const fish = build(blub, fishSeams, { scale: fishDesign.size.height / (high - low), triangles: 600, connections: [[0, 1]] });
  const fishResult = inflate(fish);
  const [middle] = internalPanelTension(fish, fishResult);
  assert.ok(middle.tense < 0.2, `middle plane: ${middle.tense} of it in tension`);
  assert.match(internalPanelRow(fish, fishResult).join(': '), /^Internal panel: mostly slack \(\d+ %\): not shaping$/);
  // Not the simulation's triangles (another pattern): no row rather than a wrong one.
  assert.equal(internalPanelRow(cushion, fishResult), null);
});
