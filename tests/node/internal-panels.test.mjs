// Internal connections through the wasm binding (TargetSession.buildPattern / startOptimization): the option
// "connections" ([[i, j]] or [{ seams: [i, j] }]) adds an internal panel, sewn onto both seams; a bad
// connection is a problem in the designer's words, not a thrown error.
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

test('a bad connection is a problem; the outer panels are still built', () => {
  const t = session();
  try {
    const built = t.buildPattern(seams, { ...options, connections: [[2, 2], [0, 9]] });
    assert.equal(built.ok, false);
    assert.equal(built.pattern.panels.length, 3);
    const messages = built.problems.filter((p) => p.code === 'pattern.connection').map((p) => p.message);
    assert.equal(messages.length, 2);
    assert.match(messages[0], /The internal connection between seams "meridian 3" and "meridian 3" cannot be built: it joins a seam to itself/);
    assert.match(messages[1], /there is no seam 10/);
    assert.throws(() => t.buildPattern(seams, { ...options, connections: 'all' }), (e) => e.code === 'pattern.bad-options');
    assert.throws(() => t.buildPattern(seams, { ...options, connections: [[0]] }), (e) => e.code === 'pattern.bad-options');
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
