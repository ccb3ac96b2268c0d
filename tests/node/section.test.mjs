// Section and outline seams (web/src/app/section.js, the section tool and the Outline button): the loop where a
// plane through a point cuts the target, or where its surface turns away from the viewer, as an ordinary seam
// of surface points. On every mesh of ../shared/meshes, sections across x, y and z through the middle and the
// outlines seen along x, y and z make seams that never cross themselves and leave no tiny or thin segment.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync } from 'node:fs';
import { SHARED_MESHES, loadSharedMesh } from './obj.mjs';
import { handlers, run } from './worker-handlers.mjs';
import { outlineLoop, planeSection, sectionSeamPoints, sectionThrough, acrossHandles, splitInTwo, vertexAreas, projectedArea, straighterView } from '../../web/src/app/section.js';
import { positionOf } from '../../web/src/app/symmetry.js';
import { implicitMesh } from './implicit-mesh.mjs';

const MESHES = SHARED_MESHES;
const load = loadSharedMesh;
const middle = ({ positions }) => {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i++) lo[i % 3] = Math.min(lo[i % 3], positions[i]), hi[i % 3] = Math.max(hi[i % 3], positions[i]);
  return { center: lo.map((l, k) => (l + hi[k]) / 2), diagonal: Math.hypot(...hi.map((h, k) => h - lo[k])) };
};

test('a section of the unit sphere is its circle, through the clicked triangle, with valid surface points', () => {
  const sphere = load('sphere.obj');
  const loops = planeSection(sphere, [0, 1, 0], 0.5);
  assert.equal(loops.length, 1);
  for (const p of loops[0]) {
    assert.ok(Math.abs(p.position[1] - 0.5) < 1e-6, 'on the plane');
    assert.ok(Math.abs(Math.hypot(...p.position) - 1) < 0.02, 'on the sphere');
    const back = positionOf(sphere, p);
    assert.ok(Math.hypot(...back.map((x, k) => x - p.position[k])) < 1e-9, 'its face and weights give its position');
  }
  const at = loops[0][5];
  const through = sectionThrough(sphere, { position: at.position, face: at.face }, [0, 1, 0]);
  assert.ok(through.some((p) => p.face === at.face), 'the loop through the clicked triangle');
  const points = sectionSeamPoints(sphere, through);
  // A circle of radius 0.87 over a diagonal of 3.46: 2 pi 0.87 / (0.02 * 3.46) = 79 points.
  assert.ok(points.length > 60 && points.length < 100, `${points.length} points`);
  for (const p of points) {
    const position = positionOf(sphere, p);
    assert.ok(Math.abs(position[1] - 0.5) < 1e-6, `each control point on the plane: ${position}`);
    assert.ok(Math.abs(p.bary.reduce((a, b) => a + b) - 1) < 1e-9 && p.bary.every((b) => b >= -1e-12), JSON.stringify(p.bary));
  }
});

test('a loop with points left out keeps every control point on the surface: the nearer point where two share no face', () => {
  const sphere = load('sphere.obj');
  const [loop] = planeSection(sphere, [0.3, 1, 0.2].map((x) => x / Math.hypot(0.3, 1, 0.2)), 0.2);
  // Its second quarter left out: the points either side of the gap share no face.
  const gapped = loop.filter((_, i) => i < loop.length / 4 || i >= loop.length / 2);
  const points = sectionSeamPoints(sphere, gapped);
  assert.ok(points.length > 30, `${points.length} points`);
  for (const p of points) {
    assert.ok(Math.abs(p.bary.reduce((a, b) => a + b) - 1) < 1e-9 && p.bary.every((b) => b >= -1e-12), JSON.stringify(p.bary));
    assert.ok(Math.abs(Math.hypot(...positionOf(sphere, p)) - 1) < 0.02, 'on the sphere');
  }
});

test('where a plane cuts a shape in several loops, the one through the click is laid', () => {
  const hand = load('hand.obj');
  const { center, diagonal } = middle(hand);
  const height = center[1] + 0.35 * diagonal / Math.sqrt(3); // across the fingers
  const loops = planeSection(hand, [0, 1, 0], height);
  assert.ok(loops.length >= 3, `the fingers: ${loops.length} loops`);
  for (const loop of loops) {
    const through = sectionThrough(hand, { position: loop[0].position, face: loop[0].face }, [0, 1, 0]);
    const faces = (l) => l.map((p) => p.face).sort((a, b) => a - b);
    assert.deepEqual(faces(through), faces(loop));
  }
});

// The loop as the tools lay it: no crossing, no tiny or thin segment, and the target cut in two.
function expectClean(mesh, loop, label) {
  const seam = { closed: true, smooth: false, weight: 1, points: sectionSeamPoints(mesh, loop, { corners: true }) };
  const result = run(handlers.checkSeams({ seams: [seam] }));
  const bad = result.problems.filter((p) => ['seam.self-crossing', 'segment.sliver', 'segment.thin'].includes(p.code));
  assert.deepEqual(bad.map((p) => p.message), [], label);
  assert.equal(result.segments.length, 2, `${label}: the loop cuts it in two`);
}

test('the outline of the sphere seen along z is its equator, with nothing turned away', () => {
  const sphere = load('sphere.obj');
  const outline = outlineLoop(sphere, [0, 0, 1]);
  assert.deepEqual([outline.movedParts, outline.loops], [[], 1]);
  for (const p of outline.loop) assert.ok(Math.abs(p.position[2]) < 0.05, `on the equator: ${p.position}`);
});

// A letter L extruded along z (n x n cells across, t deep), as the boundary of its cells: side walls t rows deep,
// every wall vertex inside a row seen exactly edge-on from the front.
function extrudedL(n, t) {
  return extruded(n, t, (x, y) => (x < 0.35 && y < 0.95) || (x < 0.8 && y < 0.3));
}

// The shape `inside(x, y)` (x, y in [0, 1)) extruded along z as extrudedL's, on n x n cells t deep.
function extruded(n, t, inside) {
  const filled = (i, j, k) => i >= 0 && j >= 0 && k >= 0 && i < n && j < n && k < t && inside((i + 0.5) / n, (j + 0.5) / n);
  const index = new Map();
  const positions = [];
  const indices = [];
  const vertex = (c) => {
    const key = c.join(' ');
    if (!index.has(key)) index.set(key, positions.length / 3), positions.push(...c.map((x) => x / n));
    return index.get(key);
  };
  for (let i = 0; i < n; i++) for (let j = 0; j < n; j++) for (let k = 0; k < t; k++) {
    if (!filled(i, j, k)) continue;
    for (let a = 0; a < 3; a++) for (const s of [-1, 1]) {
      const step = [0, 0, 0];
      step[a] = s;
      if (filled(i + step[0], j + step[1], k + step[2])) continue;
      const b = (a + 1) % 3, d = (a + 2) % 3;
      const q = [0, 1, 2, 3].map((m) => {
        const c = [i, j, k];
        if (s > 0) c[a] += 1;
        c[b] += m === 1 || m === 2 ? 1 : 0;
        c[d] += m >= 2 ? 1 : 0;
        return c;
      });
      if (s < 0) [q[1], q[3]] = [q[3], q[1]];
      const v = q.map(vertex);
      indices.push(v[0], v[1], v[2], v[0], v[2], v[3]);
    }
  }
  return { positions: Float64Array.from(positions), indices: Uint32Array.from(indices) };
}

test('an extruded letter seen from the front is outlined round the middle of its side walls', () => {
  const letter = extrudedL(24, 4);
  const outline = outlineLoop(letter, [0, 0, 1]);
  assert.equal(outline.loops, 1);
  // The walls are 4 rows deep (z 0 to 1/6): the seal runs round their middle, not along the front edge's next row
  // (z = 1/8, where the rows' exact zeros put it), so the front and the back are mirror images.
  const z = outline.loop.map((p) => p.position[2]);
  for (const depth of z) assert.ok(depth > 0.25 / 6 && depth < 0.75 / 6, `round the middle: z ${depth}`);
  const mean = z.reduce((a, b) => a + b, 0) / z.length;
  assert.ok(Math.abs(mean - 0.5 / 6) < 0.01, `mean z ${mean}`);
  run(handlers.setTarget({ positions: letter.positions, indices: letter.indices }));
  expectClean(letter, outline.loop, 'the extruded L');
});

// A slab with two square holes through it (a letter B's strokes, each as wide as a hole): its walls edge-on from the
// front, each ring as narrow along three walls of its hole.
const twoHoledSlab = () => extruded(30, 6, (x, y) => !(y > 1 / 3 && y < 2 / 3 && ((x > 0.2 && x < 0.4) || (x > 0.6 && x < 0.8))));

test('a slab with two holes seen through them: the sections across its rings cross its bars, not along a hole\'s wall', () => {
  const mesh = twoHoledSlab();
  run(handlers.setTarget({ positions: mesh.positions, indices: mesh.indices }));
  const outline = outlineLoop(mesh, [0, 0, 1]);
  assert.equal(outline.holes.length, 2);
  const across = acrossHandles(mesh, outline.loop, outline.holes, [0, 0, 1]);
  assert.equal(across.length, 4, 'two per hole');
  for (const loop of across) {
    // In a plane across x or y (as near as the rim's points, on walls seen edge-on, allow), and half a cell or more from
    // every wall (walls at 0, 6, 12, 18, 24 and 30 cells across, 0, 10, 20 and 30 up).
    const spread = [0, 1].map((k) => Math.max(...loop.map((p) => p.position[k])) - Math.min(...loop.map((p) => p.position[k])));
    const along = spread[0] < spread[1] ? 0 : 1;
    assert.ok(spread[along] < 0.3 / 30, `a plane across x or y: ${spread}`);
    const walls = along === 0 ? [0, 6, 12, 18, 24, 30] : [0, 10, 20, 30];
    const at = (loop.reduce((sum, p) => sum + p.position[along], 0) / loop.length) * 30;
    assert.ok(Math.min(...walls.map((w) => Math.abs(at - w))) >= 0.5, `across a bar, not along a wall: ${at} / 30`);
  }
  const seams = [outline.loop, ...outline.holes, ...across].map((loop, k) => ({ closed: true, smooth: false, weight: 1, points: sectionSeamPoints(mesh, loop, { corners: k <= 2 }) }));
  const result = run(handlers.checkSeams({ seams }));
  assert.deepEqual(result.problems.map((p) => p.message), []);
  assert.ok(result.segments.every((s) => s.isDisk), 'every part a panel');
});

test('a slab with two holes seen askew: a section that would run along it across both holes is not laid, and the cuts that open a tube make the panels', () => {
  const mesh = twoHoledSlab();
  run(handlers.setTarget({ positions: mesh.positions, indices: mesh.indices }));
  const towards = [0.2, 0.3, 1].map((x) => x / Math.hypot(0.2, 0.3, 1));
  const outline = outlineLoop(mesh, towards);
  assert.equal(outline.holes.length, 2);
  const across = acrossHandles(mesh, outline.loop, outline.holes, towards);
  assert.ok(across.length < 4, `${across.length} sections`);
  const seams = [outline.loop, ...outline.holes, ...across].map((loop, k) => ({ closed: true, smooth: false, weight: 1, points: sectionSeamPoints(mesh, loop, { corners: k <= 2 }) }));
  // As the Outline button commits them: the rim and the holes' rims, which part the front from the back, stay.
  const opened = run(handlers.openIntoPanels({ seams, connections: [], fixed: 3, scale: 0.3, triangles: 1000 }));
  assert.ok(opened.ok, opened.problem);
  for (const k of [0, 1, 2]) assert.deepEqual(opened.seams[k].points.map((p) => p.face), seams[k].points.map((p) => p.face), `rim ${k} stays`);
  assert.match(opened.description, /cuts? that opens? (a )?tubes?/);
  assert.doesNotMatch(opened.description, /grazed/);
  const result = run(handlers.checkSeams({ seams: opened.seams }));
  assert.deepEqual(result.problems.filter((p) => p.severity === 'error' || /sliver|thin/.test(p.code)).map((p) => p.message), []);
  assert.ok(result.segments.every((s) => s.isDisk), 'every part a panel');
});

// A head-like blob on a coarse grid (n cells across), cut flat at y = cut: seen from the front its base is edge-on.
function flatBasedBlob(n, cut) {
  const f = (x, y, z) => Math.max(Math.hypot(x / 0.8, y, z / 0.9) - 1 + 0.1 * Math.sin(3 * x + 2 * z), cut - y);
  return implicitMesh(f, -1.2, 1.2, n);
}

// The points of a loop where it turns back in depth: a turn of more than 90 degrees, both legs over `share` of the
// loop's length, whose tip stands off its neighbours' chord across the view by less than a quarter as much as in 3D.
function depthSpikes(loop, towards, share = 0.01) {
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const sub = (a, b) => a.map((x, k) => x - b[k]);
  const norm = (a) => Math.sqrt(dot(a, a));
  const length = loop.reduce((s, p, i) => s + norm(sub(p.position, loop[(i + 1) % loop.length].position)), 0);
  const P = loop.map((p) => p.position).filter((p, i, all) => norm(sub(p, all[(i + 1) % all.length])) > (1e-3 * length) / loop.length);
  const across = (d) => sub(d, towards.map((t) => t * dot(d, towards)));
  const spikes = [];
  for (let i = 0; i < P.length; i++) {
    const a = P[(i + P.length - 1) % P.length], tip = P[i], b = P[(i + 1) % P.length];
    const u = sub(a, tip), w = sub(b, tip);
    if (norm(u) < share * length || norm(w) < share * length || dot(u, w) <= 0) continue;
    const chord = sub(b, a), off = sub(tip, a);
    const t = Math.min(1, Math.max(0, dot(off, chord) / dot(chord, chord)));
    const stand = norm(sub(off, chord.map((x) => t * x)));
    const c = across(chord), o = across(off);
    if (norm(sub(o, c.map((x) => (dot(o, c) / Math.max(dot(c, c), 1e-300)) * x))) < 0.25 * stand) spikes.push(tip);
  }
  return spikes;
}

test('an outline across a flat base seen edge-on runs without spikes in depth', () => {
  // Each of these bent round one vertex of the base, or of a side seen nearly edge-on, and back, 1-6 % of the size
  // deep (a spike the foil pieces were cut with); the contour is now one fair line across.
  for (const [n, towards] of [[10, [1, 0, 0]], [14, [0, 0, 1]], [16, [0, 0, 1]]])
    for (const cut of [-0.5, -0.55, -0.6, -0.65]) {
      const blob = flatBasedBlob(n, cut);
      const outline = outlineLoop(blob, towards);
      assert.equal(outline.loops, 1);
      assert.deepEqual(depthSpikes(outline.loop, towards), [], `n ${n}, cut at ${cut}, seen from ${towards}`);
    }
  const blob = flatBasedBlob(14, -0.6);
  run(handlers.setTarget({ positions: blob.positions, indices: blob.indices }));
  expectClean(blob, outlineLoop(blob, [0, 0, 1]).loop, 'the flat-based blob');
});

test('the largest part an outline moves to the other side is the area of that part, and zero when it moves none', () => {
  const sphere = load('sphere.obj');
  const area = vertexAreas(sphere);
  const total = area.reduce((a, b) => a + b, 0);
  // Front above the equator, but for a cap around the north pole and a smaller one off it: two islands of the back.
  const z = (v) => sphere.positions[3 * v + 2];
  const x = (v) => sphere.positions[3 * v];
  const field = Float64Array.from({ length: area.length }, (_, v) => (z(v) > 0.8 || (z(v) > 0.3 && z(v) < 0.5 && x(v) > 0.7) ? -1 : z(v) > 0 ? 1 : -1));
  const cap = area.reduce((s, a, v) => (z(v) > 0.8 ? s + a : s), 0);
  const islands = area.reduce((s, a, v) => (z(v) > 0.8 || (z(v) > 0.3 && z(v) < 0.5 && x(v) > 0.7) ? s + a : s), 0);
  const split = splitInTwo(sphere, field);
  assert.equal(split.movedParts[1].length, 2, 'both islands join the front');
  const largest = Math.max(...split.movedParts.flat());
  const joined = split.movedParts[1].reduce((sum, a) => sum + a, 0);
  assert.ok(Math.abs(largest - cap) < 1e-12 * total, `the cap: ${largest} against ${cap}`);
  assert.ok(Math.abs(joined - islands) < 1e-12 * total, `both: ${joined} against ${islands}`);
  // As outlineLoop reports it: a share of the surface, zero where nothing moved.
  for (const file of ['sphere.obj', 'spot.obj', 'hand.obj'])
    for (const towards of [[0, 0, 1], [1, 0, 0], [0.33, 0.28, -0.9]].map((d) => d.map((c) => c / Math.hypot(...d)))) {
      const outline = outlineLoop(load(file), towards);
      if (outline.movedParts.length === 0) assert.equal(outline.largestMoved, 0, `${file} ${towards}`);
      else {
        assert.ok(outline.largestMoved > 0 && outline.largestMoved < 0.5, `${file} ${towards}: ${outline.largestMoved}`);
        assert.ok(Math.abs(outline.largestMoved - Math.max(...outline.movedParts)) < 1e-12, `${file} ${towards}: the largest of the parts`);
      }
    }
});

// The straight view the Outline note names: of those that turn less than half the largest part away, the one that
// shows most of the shape, as a foil balloon is cut along its largest silhouette.
test('the straight view the Outline note names is the one that shows most of the shape', () => {
  const views = [['front', '1', [0, 0, 1]], ['right', '3', [1, 0, 0]], ['top', '7', [0, 1, 0]]].map(([name, key, towards]) => ({ name, key, towards }));
  // An ellipsoid 3 x 1 x 2 (the unit sphere scaled): nothing turns away from any side, and its silhouettes are
  // pi a b: 6 pi from the top, 3 pi from the right, 2 pi from the front.
  const sphere = load('sphere.obj');
  const scale = [3, 1, 2];
  const ellipsoid = { ...sphere, positions: Float64Array.from(sphere.positions, (x, i) => x * scale[i % 3]) };
  for (const [towards, expected] of [[[0, 1, 0], 6 * Math.PI], [[1, 0, 0], 2 * Math.PI], [[0, 0, 1], 3 * Math.PI]]) {
    const area = projectedArea(ellipsoid, towards);
    assert.ok(Math.abs(area - expected) < 0.02 * expected, `along ${towards}: ${area} against ${expected}`);
  }
  assert.deepEqual(straighterView(ellipsoid, views, 0.5), { name: 'top', key: '7', share: 0 });
  // None that turns less than half as much away: none named.
  assert.equal(straighterView(ellipsoid, views, 0), null);
  // The cow is cut from its side (x), the hand from its front (z), whichever view the outline was laid from.
  for (const [file, name] of [['spot.obj', 'right'], ['hand.obj', 'front']]) {
    const chosen = straighterView(load(file), views, 1);
    assert.equal(chosen?.name, name, `${file}: ${JSON.stringify(chosen)}`);
    assert.ok(chosen.share < 0.5, `${file}: ${chosen.share}`);
  }
});

// A ring (a torus about z, tube radius r, ring radius R) as a mesh of n x m quads split in two.
function ring(R = 1, r = 0.35, n = 64, m = 24) {
  const positions = [], indices = [];
  for (let i = 0; i < n; i++)
    for (let j = 0; j < m; j++) {
      const [u, v] = [(2 * Math.PI * i) / n, (2 * Math.PI * j) / m];
      positions.push((R + r * Math.cos(v)) * Math.cos(u), (R + r * Math.cos(v)) * Math.sin(u), r * Math.sin(v));
    }
  const at = (i, j) => (i % n) * m + (j % m);
  for (let i = 0; i < n; i++)
    for (let j = 0; j < m; j++) indices.push(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1));
  return { positions: Float64Array.from(positions), indices: Uint32Array.from(indices) };
}

test('a ring seen face on: its rim, its hole and two sections across it cut it into four panels, as the Outline button lays them', () => {
  const mesh = ring();
  for (const _ of handlers.setTarget({ positions: mesh.positions, indices: mesh.indices }));
  const outline = outlineLoop(mesh, [0, 0, 1]);
  assert.equal(outline.loops, 2);
  assert.equal(outline.holes.length, 1);
  const radius = (loop) => loop.reduce((s, p) => s + Math.hypot(p.position[0], p.position[1]), 0) / loop.length;
  assert.ok(Math.abs(radius(outline.loop) - 1.35) < 0.02, `the rim: radius ${radius(outline.loop)}`);
  assert.ok(Math.abs(radius(outline.holes[0]) - 0.65) < 0.02, `the hole: radius ${radius(outline.holes[0])}`);
  const across = acrossHandles(mesh, outline.loop, outline.holes, [0, 0, 1]);
  assert.equal(across.length, 2);
  // Each a loop around the tube (about its circumference), the two on opposite sides of the ring.
  for (const loop of across) {
    const length = loop.reduce((s, p, i) => s + Math.hypot(...p.position.map((x, k) => x - loop[(i + 1) % loop.length].position[k])), 0);
    assert.ok(Math.abs(length - 2 * Math.PI * 0.35) < 0.1, `around the tube: ${length}`);
  }
  const side = (loop) => Math.atan2(loop[0].position[1], loop[0].position[0]);
  const turn = side(across[0]) - side(across[1]);
  const apart = Math.abs(Math.atan2(Math.sin(turn), Math.cos(turn)));
  assert.ok(apart > 2.5, `opposite: ${apart} rad apart`);
  const seams = [outline.loop, ...outline.holes, ...across].map((loop) => ({ closed: true, smooth: false, weight: 1, points: sectionSeamPoints(mesh, loop, { corners: true }) }));
  const result = run(handlers.checkSeams({ seams }));
  const bad = result.problems.filter((p) => ['seam.self-crossing', 'segment.sliver', 'segment.thin', 'segment.not-disk'].includes(p.code) || p.severity === 'error');
  assert.deepEqual(bad.map((p) => p.message), []);
  assert.equal(result.segments.length, 4);
  assert.ok(result.segments.every((s) => s.isDisk), 'four panels, each a disk');
});

for (const file of readdirSync(MESHES).filter((f) => f.endsWith('.obj')).sort()) {
  test(`sections of ${file} across x, y and z and its outlines make seams that neither cross themselves nor leave slivers`, () => {
    const mesh = load(file);
    for (const _ of handlers.setTarget({ positions: mesh.positions, indices: mesh.indices }));
    const { center } = middle(mesh);
    for (const axis of [0, 1, 2]) {
      const normal = [0, 0, 0];
      normal[axis] = 1;
      const loops = planeSection(mesh, normal, center[axis]);
      assert.ok(loops.length > 0, `${file}: the middle plane across ${'xyz'[axis]} cuts it`);
      const largest = loops.reduce((a, b) => (b.length > a.length ? b : a));
      expectClean(mesh, largest, `${file} across ${'xyz'[axis]}`);
      const outline = outlineLoop(mesh, normal);
      assert.ok(outline, `${file} seen along ${'xyz'[axis]} has an outline`);
      assert.equal(outline.loops, 1, `${file} seen along ${'xyz'[axis]}: one loop (genus 0)`);
      expectClean(mesh, outline.loop, `${file} outline along ${'xyz'[axis]}`);
    }
  });
}

// A five-pointed star pillow (a foil star balloon's target), front and back mirror images about z = 0, its rim on
// the vertices: rings of `around` vertices from each pole out to the rim.
function starPillow(around = 100, rings = 12) {
  const radius = (t) => 0.45 + 0.55 * Math.abs(((t * 5) / (2 * Math.PI)) % 1 - 0.5) * 2;
  const positions = [0, 0, 0.35, 0, 0, -0.35];
  const ring = (side, i) => (i === rings ? 2 + 2 * (rings - 1) * around : 2 + (side * (rings - 1) + i - 1) * around);
  for (const side of [0, 1])
    for (let i = 1; i < rings; i++)
      for (let j = 0; j < around; j++) {
        const t = (2 * Math.PI * j) / around, s = i / rings, r = radius(t);
        positions.push(s * r * Math.cos(t), s * r * Math.sin(t), (side ? -0.35 : 0.35) * Math.sqrt(1 - s * s));
      }
  for (let j = 0; j < around; j++) {
    const t = (2 * Math.PI * j) / around;
    positions.push(radius(t) * Math.cos(t), radius(t) * Math.sin(t), 0);
  }
  const indices = [];
  for (const side of [0, 1]) {
    const tri = (a, b, c) => indices.push(...(side ? [a, c, b] : [a, b, c]));
    for (let j = 0; j < around; j++) tri(side, ring(side, 1) + j, ring(side, 1) + ((j + 1) % around));
    for (let i = 1; i < rings; i++)
      for (let j = 0; j < around; j++) {
        const a = ring(side, i) + j, b = ring(side, i) + ((j + 1) % around);
        const c = ring(side, i + 1) + ((j + 1) % around), d = ring(side, i + 1) + j;
        tri(a, d, c), tri(a, c, b);
      }
  }
  return { positions: Float64Array.from(positions), indices: Int32Array.from(indices) };
}

test("an outline keeps a control point at every sharp turn: a star's tips go to neither side", () => {
  // Points at equal arc length skip most tips; the seam's shortest path from one side of a tip to the other then
  // cuts across it, and the tip (its curvature, a corner of the panel) goes to one panel only.
  const star = starPillow();
  const outline = outlineLoop(star, [0, 0, 1]);
  const points = sectionSeamPoints(star, outline.loop, { corners: true }).map((p) => positionOf(star, p));
  const { diagonal } = middle(star);
  for (let k = 0; k < 5; k++) {
    const tip = [Math.cos((2 * Math.PI * k) / 5), Math.sin((2 * Math.PI * k) / 5), 0];
    const near = Math.min(...points.map((p) => Math.hypot(p[0] - tip[0], p[1] - tip[1], p[2] - tip[2])));
    assert.ok(near < 1e-4 * diagonal, `tip ${k}: the nearest control point is ${(near / diagonal).toExponential(1)} of the size away`);
  }
  run(handlers.setTarget(star));
  const seam = { closed: true, smooth: false, weight: 1, points: sectionSeamPoints(star, outline.loop, { corners: true }) };
  const result = run(handlers.checkSeams({ seams: [seam] }));
  assert.deepEqual(result.problems.map((p) => p.message), []);
  const [front, back] = result.segments.map((s) => s.area);
  assert.ok(Math.abs(front - back) < 1e-3 * front, `front ${front} and back ${back}: mirror images`);
});

// The Outline tool (section.js, in the page) and the suggested layouts (seams/outline.hpp, in the solver) lay the
// outline by one rule written twice (the tool and the band around the outline run in the page); they must lay the
// same seam. On shapes with folds, limbs in front of the body and sharp turns, seen along each axis: the same
// control points, to rounding.
test('the Outline tool and the suggested front-and-back layouts lay the same outline seam', () => {
  let compared = 0;
  // The flat-based blob: the contour faired in depth across its base (fairInDepth) in both.
  const meshes = [...['spot.obj', 'bunny.obj', 'hand.obj', 'octopus.obj'].map((name) => [name, load(name)]), ['the flat-based blob', flatBasedBlob(16, -0.6)]];
  for (const [name, mesh] of meshes) {
    const { diagonal } = middle(mesh);
    run(handlers.setTarget({ positions: mesh.positions, indices: mesh.indices }));
    const looks = [];
    const progress = handlers.suggestLook({ panels: 2, scale: 1, triangles: 300, maxIterations: 1 });
    for (let step = progress.next(); !step.done; step = progress.next()) if (step.value?.look) looks.push(step.value.look);
    for (const [k, view] of ['side', 'above', 'front'].entries()) {
      const laid = looks.find((l) => l.name === `front and back, sealed along the outline seen ${view === 'above' ? 'from above' : `from the ${view}`}`);
      const towards = [0, 0, 0];
      towards[k] = 1;
      const outline = outlineLoop(mesh, towards);
      if (!laid) continue; // a look that made no panels (the octopus from its side): the seam is checked where laid
      assert.ok(outline, `${name} from ${view}`);
      const tool = sectionSeamPoints(mesh, outline.loop, { corners: true }).map((p) => positionOf(mesh, p));
      const solver = laid.seams[0].points.map((p) => positionOf(mesh, p));
      assert.equal(solver.length, tool.length, `${name} from ${view}: control points`);
      // The same points, whatever the loop's first.
      let worst = 0;
      for (const p of tool) worst = Math.max(worst, Math.min(...solver.map((q) => Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]))));
      // Exactly alike but where the two builds round a vertex normal differently on a fold (the octopus: 6e-5).
      assert.ok(worst < 1e-4 * diagonal, `${name} from ${view}: a control point ${worst / diagonal} of the diagonal off`);
      compared++;
    }
  }
  assert.ok(compared >= 10, `${compared} outlines compared`);
});

// A mug: a rounded body with a handle at its side (a ring in the x-y plane), one closed surface of genus 1.
function mug(n = 36) {
  const body = (x, y, z) => Math.hypot(x / 0.6, y, z / 0.6) - 1;
  const handle = (x, y, z) => Math.hypot(Math.hypot(x - 0.75, y) - 0.45, z) - 0.14;
  const blend = (a, b, k = 0.08) => Math.min(a, b) - (Math.max(k - Math.abs(a - b), 0) / k) ** 2 * (k / 4);
  return implicitMesh((x, y, z) => blend(body(x, y, z), handle(x, y, z)), -1.35, 1.35, n);
}

test('a mug seen with its handle towards the viewer: the seams that make every part a panel join the outline, which stays as it was', () => {
  const mesh = mug();
  const { report } = run(handlers.setTarget({ positions: mesh.positions, indices: mesh.indices }));
  assert.equal(report.stats.genus, 1);
  const towards = [1, 0, 0];
  const outline = outlineLoop(mesh, towards);
  assert.equal(outline.holes.length, 0, 'the view does not look through the handle');
  const seams = [{ closed: true, smooth: false, weight: 1, points: sectionSeamPoints(mesh, outline.loop, { corners: true }) }];
  const alone = run(handlers.checkSeams({ seams }));
  assert.ok(alone.segments.some((s) => !s.isDisk), 'the outline alone leaves the handle in a part that is not a panel');
  const opened = run(handlers.openIntoPanels({ seams, connections: [], scale: 0.3, triangles: 1000 }));
  assert.ok(opened.ok, opened.problem);
  assert.ok(opened.seams.length > 1, 'seams were added');
  // The outline seam as it was laid (to the last digits a round trip through the design reader keeps).
  assert.equal(opened.seams[0].points.length, seams[0].points.length);
  for (const [k, p] of seams[0].points.entries()) {
    assert.equal(opened.seams[0].points[k].face, p.face);
    assert.ok(p.bary.every((b, c) => Math.abs(b - opened.seams[0].points[k].bary[c]) < 1e-12));
  }
  assert.match(opened.description, /tube|handle/);
  const result = run(handlers.checkSeams({ seams: opened.seams }));
  assert.ok(result.segments.length >= 2 && result.segments.every((s) => s.isDisk), 'every part a panel');
  assert.deepEqual(result.problems.filter((p) => p.severity === 'error').map((p) => p.message), []);
  // Each added cut names the seams its ends lie on ("on"), which the app keeps them on as those are edited: a cut that
  // opens a tube joins two of them.
  const cuts = opened.seams.map((seam, i) => ({ seam, i })).filter(({ seam }) => !seam.closed);
  assert.ok(cuts.length > 0, 'a cut was added');
  for (const { seam, i } of cuts) {
    const hosts = [seam.points[0].on, seam.points.at(-1).on];
    assert.ok(hosts.every((h) => Number.isInteger(h) && h >= 0 && h < opened.seams.length && h !== i), `${seam.name}: ${hosts}`);
    if (/tube/.test(seam.name)) assert.notEqual(hosts[0], hosts[1], `${seam.name} joins two seams`);
    assert.ok(seam.points.slice(1, -1).every((p) => p.on === undefined), 'only the ends');
  }
});

test('a loop laid with the outline that crosses itself is left out, and the rest makes panels; the outline stays', () => {
  const mesh = mug();
  run(handlers.setTarget({ positions: mesh.positions, indices: mesh.indices }));
  const outline = outlineLoop(mesh, [1, 0, 0]);
  const rim = { closed: true, smooth: false, weight: 1, points: sectionSeamPoints(mesh, outline.loop, { corners: true }) };
  // A figure eight on the body's back, its turns all wide (a lemniscate): no hairpin to take out, it crosses itself.
  const eight = Array.from({ length: 24 }, (_, k) => {
    const t = (2 * Math.PI * k) / 24, d = 1 + Math.sin(t) ** 2;
    const y = (0.7 * Math.cos(t)) / d, z = (0.7 * Math.sin(t) * Math.cos(t)) / d;
    return [-0.6 * Math.sqrt(Math.max(0, 1 - y * y - (z / 0.6) ** 2)), y, z];
  });
  const seams = [rim, { closed: true, smooth: false, weight: 1, points: eight }];
  const laid = run(handlers.checkSeams({ seams }));
  assert.ok(laid.problems.some((p) => p.code === 'seam.self-crossing' && p.seam === 1), 'the figure eight crosses itself as laid');
  const opened = run(handlers.openIntoPanels({ seams, connections: [], fixed: 1, scale: 0.3, triangles: 1000 }));
  assert.ok(opened.ok, opened.problem);
  assert.match(opened.description, /1 loop left out that crossed itself/);
  assert.equal(opened.seams[0].points.length, rim.points.length, 'the outline stays');
  const result = run(handlers.checkSeams({ seams: opened.seams }));
  assert.ok(result.segments.length >= 2 && result.segments.every((s) => s.isDisk), 'every part a panel');
  assert.deepEqual(result.problems.filter((p) => p.severity === 'error').map((p) => p.message), []);
});
