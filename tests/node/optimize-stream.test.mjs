// The optimization streams every iterate through the worker's handlers: the sewn mesh once, then each
// iterate's inflated shape with its signed distances to the target, whose outer-surface RMS is the
// optimizer's own figure; now and then the panels. And distanceToTarget is 0 on the target, positive outside.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadApi } from './load-module.mjs';
import { readObjText, splitInFour } from './obj.mjs';
import { capsuleMesh } from './capsule-mesh.mjs';
import { createHandlers } from '../../web/src/worker/handlers.js';
import { cutPanelsNote } from '../../web/src/app/panels.js';
import { narrowOutlineShare } from '../../web/src/views/pattern-layout.js';

const api = await loadApi();
const read = (path) => readFileSync(new URL(path, import.meta.url), 'utf8');
// The worker's handlers with the sphere example as the target.
const sphereSession = () => {
  const handlers = createHandlers(api);
  const sphere = readObjText(read('../../web/public/examples/sphere.obj'));
  for (const _ of handlers.setTarget({ positions: sphere.positions, indices: sphere.indices }));
  return { handlers, sphere };
};

test('each optimizer iterate streams its shape and its distance to the target, the optimizer\'s own figure', () => {
  const { handlers, sphere } = sphereSession();
  const design = JSON.parse(read('../../web/public/gallery/sphere3.billow.json'));
  const seams = design.seams.map(({ points, closed }) => ({ points, closed, weight: 1 }));
  const iterates = [];
  // 800 triangles: a target no finer than twice the balloon's outer surface, which every record measures whole.
  const run = handlers.optimizeDesign({ seams, scale: 0.25, triangles: 800, maxIterations: 8 });
  for (let step = run.next(); !step.done; step = run.next()) if (step.value.stage === 'optimizing') iterates.push(step.value);
  assert.ok(iterates.length >= 5, `${iterates.length} iterates`);
  const [first, ...rest] = iterates;
  assert.ok(first.triangles.length > 0 && first.outer.length === first.triangles.length / 3, 'the sewn mesh comes first');
  const n = first.positions.length / 3;
  // Then the flattened panels inflated, before any optimizer step: the first look at the balloon.
  assert.equal(rest[0].iteration, 0, 'the first equilibrium comes as iteration 0');
  assert.ok(Math.abs(rest[0].distanceRms - rest[0].flattenedDistanceRms) < 1e-12, 'it is the flattened panels\' shape');
  assert.ok(rest[0].positions.some((x, i) => Math.abs(x - first.positions[i]) > 1e-4), 'inflated, not the target it starts from');
  for (const it of rest) {
    assert.equal(it.positions.length, 3 * n);
    assert.equal(it.distances.length, n);
    assert.ok(Math.abs(it.distance.rms - it.distanceRms) < 1e-6 * Math.max(1, it.distanceRms), `iteration ${it.iteration}: ${it.distance.rms} vs ${it.distanceRms}`);
    assert.ok(it.distance.max >= it.distance.rms);
    // The other way, the target's vertices to the shape: the optimizer's figure and the colors' alike.
    // The parts left out come as target triangles: indices of the target's vertices, three each.
    assert.equal(it.uncoveredTriangles.length % 3, 0);
    assert.ok(it.uncoveredTriangles.every((v) => v < sphere.positions.length / 3));
    assert.equal(it.uncoveredTriangles.length > 0, it.distance.uncovered.length > 0, 'drawn when warned of');
    assert.ok(Math.abs(it.distance.targetRms - it.targetDistanceRms) < 1e-6 * Math.max(1, it.targetDistanceRms), `iteration ${it.iteration}: ${it.distance.targetRms} vs ${it.targetDistanceRms}`);
    assert.ok(it.distance.targetMax >= it.distance.targetRms && it.distance.targetRms > 0);
    assert.ok(Array.isArray(it.distance.uncovered) && it.distance.uncoveredDistance > 0);
  }
  assert.ok(rest.at(-1).distance.rms < rest[0].distance.rms, 'the iterates come closer to the target');
  assert.ok(rest.every((it) => it.slidingSeams === false), 'seams of weight 1 are held');
  for (const it of rest) if (it.patternText) assert.equal(JSON.parse(it.patternText).panels.length, 3, 'streamed panels'); // every 0.5 s
  // Points on the target are at distance 0; pushed out along the sphere's radius they are outside.
  const scale = 0.25;
  const onTarget = Float64Array.from(sphere.positions, (x) => x * scale);
  const out = handlers.distanceToTarget({ positions: onTarget.map((x) => x * 1.02), scale }).next().value;
  const on = handlers.distanceToTarget({ positions: onTarget, scale }).next().value;
  assert.ok(on.max < 1e-9, `on the target: ${on.max}`);
  assert.ok(out.distances.every((d) => d > 0), 'outside: positive');
  assert.ok(Math.abs(out.rms * out.diagonal - 0.02 * scale) < 0.002 * scale, `2 % out: ${out.rms * out.diagonal} m`);
  // A balloon too flat for the round target (the sphere squashed to half along z, on its own triangles): a gusset
  // helps, and where the design has one already, a wider one.
  const flat = onTarget.map((x, i) => (i % 3 === 2 ? 0.5 * x : x));
  const outer = new Uint8Array(sphere.indices.length / 3).fill(1);
  const tooFlat = (gusseted) =>
    handlers.distanceToTarget({ positions: flat, scale, triangles: sphere.indices, outer: outer, gusseted }).next().value.uncovered[0];
  assert.match(tooFlat(false).message, /too flat .* A gusset \(a strip sewn in along the seam\)/);
  assert.equal(tooFlat(false).helps, 'a gusset or more panels');
  assert.match(tooFlat(true).message, /too flat .* A wider gusset/);
  assert.equal(tooFlat(true).helps, 'a wider gusset or more panels');
});

test('seams of weight 0 slide, and every iterate says so; the panels are meshed anew on the way', () => {
  const { handlers } = sphereSession();
  const design = JSON.parse(read('../../web/public/gallery/sphere-sliding.billow.json'));
  assert.ok(design.seams.every((s) => s.weight === 0), 'the gallery\'s sliding sphere has seams of weight 0');
  const seams = design.seams.map(({ points, closed, weight }) => ({ points, closed, weight }));
  const iterates = [];
  const run = handlers.optimizeDesign({ seams, scale: 0.25, triangles: 600, maxIterations: 25 });
  for (let step = run.next(); !step.done; step = run.next()) if (step.value.stage === 'optimizing' && step.value.state) iterates.push(step.value);
  assert.ok(iterates.length >= 20, `${iterates.length} iterates`);
  assert.ok(iterates.every((it) => it.slidingSeams === true), 'every iterate says the seams slide');
  assert.ok(iterates.at(-1).remeshings >= 1, `remeshed ${iterates.at(-1).remeshings} times by iteration ${iterates.at(-1).iteration}`);
  // A remeshed iterate brings its new sewn mesh, and its distances fit that mesh.
  const remeshed = iterates.find((it, i) => i > 0 && it.remeshings !== iterates[i - 1].remeshings);
  assert.ok(remeshed?.triangles?.length > 0, 'the remeshed iterate carries its triangles');
  assert.equal(remeshed.distances.length, remeshed.positions.length / 3);
  assert.ok(Math.max(...remeshed.triangles) < remeshed.positions.length / 3, 'its triangles index its own vertices');
});

test('a design of 1,500 triangles and more starts on a coarse mesh, and its switch to the design\'s mesh streams that mesh', () => {
  const { handlers } = sphereSession();
  const design = JSON.parse(read('../../web/public/gallery/sphere3.billow.json'));
  const seams = design.seams.map(({ points, closed }) => ({ points, closed, weight: 1 }));
  const iterates = [];
  const run = handlers.optimizeDesign({ seams, scale: 0.25, triangles: 1600, maxIterations: 40 });
  let step = run.next();
  for (; !step.done; step = run.next()) if (step.value.stage === 'optimizing') iterates.push(step.value);
  const first = iterates[0];
  assert.ok(first.triangles.length / 3 < 0.4 * 1600, `the first mesh is coarse: ${first.triangles.length / 3} triangles`);
  const switched = iterates.findIndex((it, i) => i > 0 && it.state && it.remeshings !== (iterates[i - 1].remeshings ?? 0));
  assert.ok(switched > 0, 'the run switched to the design\'s mesh');
  const fine = iterates[switched];
  assert.ok(Math.abs(fine.triangles.length / 3 - 1600) < 0.15 * 1600, `the design's mesh: ${fine.triangles.length / 3} triangles`);
  // The run ends on its cut panels, meshed anew at the design's triangle count: that mesh streams too.
  let vertices = 0;
  for (const it of iterates.slice(switched)) {
    if (it.triangles) {
      assert.ok(Math.abs(it.triangles.length / 3 - 1600) < 0.15 * 1600, `iteration ${it.iteration}: ${it.triangles.length / 3} triangles`);
      vertices = Math.max(...it.triangles) + 1;
    }
    assert.equal(it.positions.length / 3, vertices, `iteration ${it.iteration}: positions of the design's mesh`);
    assert.equal(it.distances.length, vertices);
  }
  assert.equal(iterates.at(-1).remeshings, 2, 'the switch to the design\'s mesh and the cut panels');
  // The run's own mesh's last figures come with the end, for the designer to be told where the cut panels differ.
  const { ownMesh } = step.value.status;
  assert.ok(ownMesh && ownMesh.distanceRms > 0 && ownMesh.targetDistanceRms > 0, JSON.stringify(step.value.status));
  for (const it of iterates.slice(1, switched)) assert.equal(it.positions.length, first.positions.length, 'the coarse phase on its own mesh');
  assert.ok(iterates.at(-1).distanceRms < iterates[1].distanceRms, 'closer than the flattened panels');
  const optimized = JSON.parse(step.value.patternText);
  const triangles = optimized.panels.reduce((n, panel) => n + panel.triangles.length, 0);
  assert.ok(Math.abs(triangles - 1600) < 0.15 * 1600, `the optimized pattern has the design's triangles: ${triangles}`);
});

test('panels that cannot be made are refused with each problem and its place on the target, in its own units', () => {
  const { handlers, sphere } = sphereSession();
  // No seam: the sphere stays one closed piece, which no panel can be.
  const seams = [];
  const run = handlers.optimizeDesign({ seams, scale: 0.25, triangles: 600, maxIterations: 5, up: '+y' });
  assert.throws(() => { for (let step = run.next(); !step.done; step = run.next()); }, (error) => {
    assert.equal(error.code, 'pattern.not-built');
    const problems = error.details?.problems ?? [];
    assert.ok(problems.length >= 1, JSON.stringify(error.details));
    for (const p of problems) {
      assert.equal(p.severity, 'error');
      assert.ok(error.message.includes(p.message), 'every problem is in the message too');
      assert.equal(p.location.length, 3);
      // On the unit sphere (target units), not the 0.25 m one the panels are made at.
      assert.ok(Math.abs(Math.hypot(...p.location) - 1) < 0.05, `${p.location}`);
    }
    return true;
  });
});

test('what the panels were made despite comes with the first look and the result, placed on the target in its units', () => {
  // A sausage eight times as long as it is round with one seam near its left end: the long part folds when laid
  // flat (tests/native: PatternBuild.ASegmentThatFoldsWhenLaidFlatIsAWarningPlacedWhereItFolds).
  const handlers = createHandlers(api);
  const r = 0.05, length = 8 * 2 * Math.PI * r;
  const target = capsuleMesh(12, r, length);
  for (const _ of handlers.setTarget(target));
  const x0 = -length / 2 + 0.02;
  const seams = [{ points: [0.3, 2.4, 4.5].map((a) => [x0, r * Math.cos(a), r * Math.sin(a)]), closed: true, weight: 1 }];
  const run = handlers.optimizeDesign({ seams, scale: 1, triangles: 600, maxIterations: 1, up: '+y' });
  const iterates = [];
  let step = run.next();
  for (; !step.done; step = run.next()) if (step.value.stage === 'optimizing') iterates.push(step.value);
  const firstLook = iterates.find((it) => it.warnings);
  assert.ok(firstLook && firstLook === iterates[0], 'the warnings come with the first look');
  assert.equal(iterates.filter((it) => it.warnings).length, 1, 'once');
  for (const warnings of [firstLook.warnings, step.value.warnings]) {
    const folded = warnings.filter((w) => w.code === 'pattern.flipped');
    assert.equal(folded.length, 1, JSON.stringify(warnings));
    const [w] = folded;
    assert.match(w.message, /^Segment \d cannot be laid flat without folding over itself near the .*A seam across it there lets it lie flat as two panels\.$/);
    assert.equal(w.severity, 'warning');
    // On the tube, past the seam, on its surface, in the target's own units.
    assert.ok(w.location[0] > x0 + 0.25 * length, `${w.location}`);
    assert.ok(Math.abs(Math.hypot(w.location[1], w.location[2]) - r) < 0.05 * r, `${w.location}`);
  }
  assert.ok(JSON.parse(step.value.patternText).panels.length === 2, 'the panels were made');
});

// The current iterate's distance as the stream gives it (optimizedDistance) and its shape measured again whole.
function streamedAndWhole(session, scale) {
  const streamed = session.optimizedDistance(scale, '+y');
  const mesh = session.optimizedMesh();
  const surface = [];
  for (let f = 0; f < mesh.outer.length; f++) if (mesh.outer[f]) surface.push(...mesh.triangles.slice(3 * f, 3 * f + 3));
  return { streamed, whole: session.distanceToTarget(session.optimizedPositions(), scale, surface, '+y') };
}

test('the streamed distance is the shape\'s own: the target\'s side as the optimizer measured it equals measuring again', () => {
  const sphere = readObjText(read('../../web/public/examples/sphere.obj'));
  const session = api.targetSession();
  session.setTarget(sphere.positions, sphere.indices);
  const design = JSON.parse(read('../../web/public/gallery/sphere3.billow.json'));
  const seams = design.seams.map(({ points, closed }) => ({ points, closed, weight: 1 }));
  const scale = 0.25;
  assert.ok(session.startOptimization(seams, { scale, triangles: 800 }).ok);
  for (let k = 0; k < 4; k++) {
    const status = session.optimizeStep(1, 0);
    assert.ok(status.state === 'running' || status.state === 'converged', status.message);
    const { streamed, whole: fresh } = streamedAndWhole(session, scale);
    for (const key of ['rms', 'max', 'targetRms', 'targetMax']) {
      assert.ok(Math.abs(streamed[key] - fresh[key]) <= 1e-12 * Math.max(1, fresh[key]), `${key}: ${streamed[key]} vs ${fresh[key]}`);
    }
    assert.ok(Math.abs(streamed.targetRms - status.targetDistanceRms) <= 1e-12, 'the record\'s figure');
    assert.deepEqual(streamed.distances, fresh.distances);
    assert.deepEqual(streamed.uncoveredTriangles, fresh.uncoveredTriangles);
    assert.deepEqual(streamed.uncovered.map((r) => r.message), fresh.uncovered.map((r) => r.message));
  }
  // At 600 triangles the target has more than twice the outer surface's vertices: during the run a record measures
  // it at a sample, close to the whole measure (the run's last figures are whole: the native
  // PatternOptimizer.AFineTargetIsSampledDuringARunAndMeasuredWholeWhereItsFiguresAreKept).
  assert.ok(session.startOptimization(seams, { scale, triangles: 600 }).ok);
  for (let k = 0; k < 4; k++) {
    const status = session.optimizeStep(1, 0);
    assert.equal(status.state, 'running', status.message);
    const { whole } = streamedAndWhole(session, scale);
    assert.ok(Math.abs(whole.targetRms - status.targetDistanceRms) <= 0.15 * whole.targetRms, `sampled: ${status.targetDistanceRms} vs ${whole.targetRms}`);
    assert.ok(Math.abs(whole.targetRms - status.targetDistanceRms) > 0, 'measured at a sample, not whole');
  }
  session.delete();
});


test('on a fine target the stream measures the target\'s side whole now and then, its own side at every iterate', (t) => {
  // 81,920 triangles: a whole measurement costs more than a step of a 300-triangle design, so most iterates show the
  // last whole one's target side (TargetSession::optimizedDistance). Whichever they show, it is a whole measurement
  // of this shape or of one streamed before; the shape's own side is always its own.
  const design = JSON.parse(read('../../web/public/gallery/sphere3.billow.json'));
  let target = readObjText(read('../../web/public/examples/sphere.obj'));
  for (let k = 0; k < 3; k++) target = splitInFour(target);
  const seams = design.seams.map(({ points, closed }) => ({ points, closed, weight: 1 }));
  const session = api.targetSession();
  session.setTarget(target.positions, target.indices);
  const scale = 0.25;
  assert.ok(session.startOptimization(seams, { scale, triangles: 300 }).ok);
  const wholeOf = [];
  let stale = 0;
  for (let k = 0; k < 8; k++) {
    const status = session.optimizeStep(1, 0);
    assert.ok(status.state === 'running' || status.state === 'converged', status.message);
    const { streamed, whole: fresh } = streamedAndWhole(session, scale);
    wholeOf.push(fresh);
    assert.ok(Math.abs(streamed.rms - fresh.rms) <= 1e-12 * Math.max(1, fresh.rms), `own side: ${streamed.rms} vs ${fresh.rms}`);
    assert.deepEqual(streamed.distances, fresh.distances);
    const same = (d) => d.targetRms === streamed.targetRms && d.targetMax === streamed.targetMax
      && d.uncoveredTriangles.length === streamed.uncoveredTriangles.length;
    assert.ok(wholeOf.some(same), `iteration ${status.iteration}: the target's side ${streamed.targetRms} is no shape's so far`);
    if (!same(fresh)) stale += 1;
    if (status.state === 'converged') break;
  }
  t.diagnostic(`${stale} of ${wholeOf.length} iterates showed an earlier whole measurement`);
  session.delete();
});

test('the designer is told when the cut panels inflate clearly farther than the optimizer\'s own mesh showed', () => {
  const own = { distanceRms: 0.0073, targetDistanceRms: 0.015 };
  const note = cutPanelsNote({ ownMesh: own, distanceRms: 0.027, targetDistanceRms: 0.022 });
  assert.match(note, /1\.50 % → 2\.70 %/); // the worse way of each
  assert.match(note, /another shape once cut/);
  assert.equal(cutPanelsNote({ ownMesh: own, distanceRms: 0.0078, targetDistanceRms: 0.017 }), null, 'within 20 %: no note');
  assert.equal(cutPanelsNote({ distanceRms: 0.027, targetDistanceRms: 0.022 }), null, 'a run that did not end on cut panels');
  // Twice as far, but both close: a ring balloon's 0.11 % and 0.26 % differ by what no one sees.
  const close = { distanceRms: 0.0011, targetDistanceRms: 0.0010 };
  assert.equal(cutPanelsNote({ ownMesh: close, distanceRms: 0.0026, targetDistanceRms: 0.0025 }), null, 'both close: no note');
  assert.match(cutPanelsNote({ ownMesh: close, distanceRms: 0.0040, targetDistanceRms: 0.0030 }), /0\.11 % → 0\.40 %/);
  // Outlines along parts a triangle or so across: the finer Panels setting is named, where there is one.
  const narrow = cutPanelsNote({ ownMesh: own, distanceRms: 0.027, targetDistanceRms: 0.022 }, { narrowShare: 0.25, finer: 'medium' });
  assert.ok(narrow.startsWith(note), narrow);
  assert.match(narrow, /A 25 % share of the outlines borders parts only a triangle or so across at this resolution/);
  assert.match(narrow, /the "medium" Panels setting follows them better\.$/);
  assert.equal(cutPanelsNote({ ownMesh: own, distanceRms: 0.027, targetDistanceRms: 0.022 }, { narrowShare: 0.25, finer: null }), note, 'at the finest setting');
  assert.equal(cutPanelsNote({ ownMesh: own, distanceRms: 0.027, targetDistanceRms: 0.022 }, { narrowShare: 0.05, finer: 'fine' }), note, 'outlines mostly wide');
  assert.equal(cutPanelsNote({ ownMesh: own, distanceRms: 0.0078, targetDistanceRms: 0.017 }, { narrowShare: 0.5, finer: 'fine' }), null, 'no gap, no note');
});

// A panel of n x m squares (two triangles each), `size` m to a square.
function gridPanel(n, m, size = 0.01) {
  const vertices = [];
  const triangles = [];
  for (let j = 0; j <= m; j++) for (let i = 0; i <= n; i++) vertices.push([i * size, j * size]);
  const at = (i, j) => j * (n + 1) + i;
  for (let j = 0; j < m; j++)
    for (let i = 0; i < n; i++) triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)], [at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
  return { name: 'panel', vertices, triangles };
}

test('the share of narrow outlines counts the sides of a strip a triangle across, not those of a wide panel', () => {
  // Mean edge: (2 sides + a diagonal) / 3 of a square, 1.14 squares.
  const strip = narrowOutlineShare({ panels: [gridPanel(40, 1)] });
  assert.ok(strip > 0.9, `a strip one square wide: ${strip}`);
  assert.equal(narrowOutlineShare({ panels: [gridPanel(20, 20)] }), 0, 'a square 20 across');
  // A wide square with a strip one square wide and 20 long sticking out of it (an L of the two): about the strip's
  // two sides of the outline.
  const wide = gridPanel(20, 20);
  const leg = gridPanel(1, 20);
  const offset = wide.vertices.length;
  const L = {
    name: 'L',
    vertices: [...wide.vertices, ...leg.vertices.map(([x, y]) => [x, y + 0.2])],
    triangles: [...wide.triangles, ...leg.triangles.map((t) => t.map((v) => v + offset))],
  };
  // The leg's bottom row shares the square's top edge: weld its two vertices there.
  const weld = new Map([[offset, 20 * 21], [offset + 1, 20 * 21 + 1]]);
  L.triangles = L.triangles.map((t) => t.map((v) => weld.get(v) ?? v));
  const share = narrowOutlineShare({ panels: [L] });
  // Outline: the square's 80 squares less the one the leg stands on, and the leg's 41: about 41 of 120 narrow.
  assert.ok(share > 0.25 && share < 0.45, `an L: ${share}`);
  // Internal panels do not count.
  assert.equal(narrowOutlineShare({ panels: [gridPanel(20, 20), { ...gridPanel(40, 1), internal: true }] }), 0);
});
