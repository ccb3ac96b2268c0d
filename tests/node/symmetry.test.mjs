// Mirror symmetry of seams (web/src/app/symmetry.js): closest points on the target, mirrored twins,
// self-symmetric seams, and the design commands and reader keeping twin links consistent.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { readObjText } from './obj.mjs';
import {
  closestOnTriangle, closestSurfacePoint, symmetryPlane, mirrorPoint, isSelfSymmetric, needsNoTwin, addMirroredTwin, positionOf, reflect, bounds,
} from '../../web/src/app/symmetry.js';
import { planeSection, resampleLoop, loopLength } from '../../web/src/app/section.js';
import { newDesign, parseDesign } from '../../web/src/app/design.js';
import * as cmd from '../../web/src/app/commands.js';

const readObj = (name) => readObjText(readFileSync(new URL(`../../../shared/meshes/${name}`, import.meta.url), 'utf8'));
const sphere = readObj('sphere.obj');
const spot = readObj('spot.obj');
const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

test('closest point on a triangle: vertex, edge and face regions', () => {
  const a = [0, 0, 0], b = [1, 0, 0], c = [0, 1, 0];
  assert.deepEqual(closestOnTriangle([-1, -1, 0], a, b, c), [1, 0, 0]);
  assert.deepEqual(closestOnTriangle([2, -0.5, 0], a, b, c), [0, 1, 0]);
  const edge = closestOnTriangle([0.5, -1, 3], a, b, c);
  assert.ok(Math.abs(edge[0] - 0.5) < 1e-12 && Math.abs(edge[1] - 0.5) < 1e-12 && edge[2] === 0);
  const hyp = closestOnTriangle([1, 1, 0], a, b, c);
  assert.ok(Math.abs(hyp[1] - 0.5) < 1e-12 && Math.abs(hyp[2] - 0.5) < 1e-12);
  const face = closestOnTriangle([0.2, 0.3, -5], a, b, c);
  assert.ok(Math.abs(face[0] - 0.5) < 1e-12 && Math.abs(face[1] - 0.2) < 1e-12 && Math.abs(face[2] - 0.3) < 1e-12);
});

test('closest surface point agrees with a brute-force search over vertices and lands on the surface', () => {
  for (const dir of [[1, 0.2, 0.1], [-0.3, 1, 0.5], [0.1, -0.2, -1]]) {
    const n = Math.hypot(...dir);
    const p = dir.map((x) => (1.3 * x) / n);
    const hit = closestSurfacePoint(sphere, p);
    const q = positionOf(sphere, hit);
    assert.ok(Math.abs(Math.hypot(...q) - 1) < 0.02, 'on the unit icosphere');
    assert.ok(dist(q, p) <= 0.31, 'about 0.3 away');
    let nearestVertex = Infinity;
    for (let v = 0; v < sphere.positions.length; v += 3) nearestVertex = Math.min(nearestVertex, dist(p, [sphere.positions[v], sphere.positions[v + 1], sphere.positions[v + 2]]));
    assert.ok(dist(q, p) <= nearestVertex + 1e-12, 'never farther than the nearest vertex');
  }
});

test('a mirrored twin lies at the reflected positions; a seam across the plane is its own mirror image', () => {
  const design = { ...newDesign('spot'), symmetry: { axis: 'x' } };
  const plane = symmetryPlane(design, spot);
  assert.equal(plane.axis, 0);
  // A seam on one flank of Spot (x > 0): points from the closest surface points of a few positions.
  const side = [[0.4, 0.2, 0.1], [0.4, 0.3, 0.4], [0.35, 0.0, 0.5]].map((p) => closestSurfacePoint(spot, p));
  let d = cmd.addSeam(design, { points: side, closed: true });
  d = addMirroredTwin(d, spot, plane, 0);
  assert.equal(d.seams.length, 2);
  assert.equal(d.seams[0].mirror, 1);
  assert.equal(d.seams[1].mirror, 0);
  assert.match(d.seams[1].name, /mirror/);
  d.seams[1].points.forEach((p, k) => {
    const expected = reflect(positionOf(spot, side[k]), plane);
    assert.ok(dist(positionOf(spot, p), expected) < 0.02, `mirrored point ${k} on the other flank`);
  });
  assert.equal(addMirroredTwin(d, spot, plane, 0), d, 'a seam with a twin gets no second one');
  // Across the back: symmetric control points -> no twin.
  const across = [[0.3, 0.5, 0.2], [0, 0.6, 0.2], [-0.3, 0.5, 0.2]].map((p) => closestSurfacePoint(spot, p));
  assert.equal(isSelfSymmetric({ points: across }, spot, plane), true);
  assert.equal(isSelfSymmetric({ points: across.slice(0, 2) }, spot, plane), false, 'half of it is not');
  const d2 = addMirroredTwin(cmd.addSeam(design, { points: across, closed: false }), spot, plane, 0);
  assert.equal(d2.seams.length, 1);
});

// A section loop across the mirror plane (a band around Spot's body) has its control points at equal arc lengths from
// wherever the loop starts, which the mirror does not map onto each other; each image lies on the loop's own line.
test('a section loop across the mirror plane is its own mirror image, wherever its control points fall', () => {
  const plane = symmetryPlane({ ...newDesign('spot'), symmetry: { axis: 'x' } }, spot);
  const { lo, hi } = bounds(spot);
  for (const share of [0.35, 0.5, 0.65]) {
    const loops = planeSection(spot, [0, 0, 1], lo[2] + share * (hi[2] - lo[2]));
    const loop = loops.reduce((best, l) => (l.length > best.length ? l : best));
    // 30 points at equal arc lengths from a third of a spacing past the loop's first point: spaced wider than the
    // tolerance, so an image falls between two of them.
    const total = loopLength(loop);
    const points = resampleLoop(spot, loop, Array.from({ length: 30 }, (_, k) => ((k + 1 / 3) * total) / 30)).map(({ face, bary }) => ({ face, bary }));
    assert.equal(isSelfSymmetric({ points, closed: true }, spot, plane), true, `across z at ${share}`);
    // Half of it is not.
    assert.equal(isSelfSymmetric({ points: points.slice(0, points.length >> 1), closed: false }, spot, plane), false, `half of it at ${share}`);
  }
});

// Spot's outline seen from its side runs along the mirror plane over her back and belly and round one side's legs; a
// twin would lie over it there and cut slivers off where the two part.
test('a seam that is mostly its own mirror image gets no twin; one mostly off the plane does', () => {
  const design = { ...newDesign('spot'), symmetry: { axis: 'x' } };
  const plane = symmetryPlane(design, spot);
  const { lo, hi } = bounds(spot);
  const loops = planeSection(spot, [0, 0, 1], lo[2] + 0.5 * (hi[2] - lo[2]));
  const loop = loops.reduce((best, l) => (l.length > best.length ? l : best));
  const total = loopLength(loop);
  const points = resampleLoop(spot, loop, Array.from({ length: 30 }, (_, k) => ((k + 0.5) * total) / 30)).map(({ face, bary }) => ({ face, bary }));
  // The loop's half on the far side (x < 0) moved off the plane's image: each of its points taken further along -x.
  const offPlane = (keep) => points.map((p, k) => {
    const position = positionOf(spot, p);
    return position[0] < plane.offset && !keep(k) ? closestSurfacePoint(spot, [position[0] - 0.15, position[1], position[2]]) : p;
  });
  const count = (seam) => seam.points.filter((p) => positionOf(spot, p)[0] < plane.offset).length;
  const mostlyOwn = { points: offPlane((k) => k % 3 !== 0), closed: true };
  assert.ok(count(mostlyOwn) > 5, 'some of its points on the far side');
  assert.equal(isSelfSymmetric(mostlyOwn, spot, plane), false, 'not all of it is its own image');
  assert.equal(needsNoTwin(mostlyOwn, spot, plane), true, 'most of it is');
  const d = cmd.addSeam(design, { points: mostlyOwn.points, closed: true });
  assert.equal(addMirroredTwin(d, spot, plane, 0), d, 'no twin over it');
  const side = [[0.4, 0.2, 0.1], [0.4, 0.3, 0.4], [0.35, 0.0, 0.5]].map((p) => closestSurfacePoint(spot, p));
  assert.equal(needsNoTwin({ points: side, closed: true }, spot, plane), false, 'a seam on one flank needs its twin');
});

// A design file may give control points as plain 3D points (docs/formats.md): the gallery's three gores do.
test('a seam of plain 3D points gets its twin at the reflected points', () => {
  const design = { ...newDesign('sphere'), symmetry: { axis: 'x' } };
  const plane = symmetryPlane(design, sphere);
  const meridian = [[0, 1, 0], [0.70711, 0.70711, 0], [1, 0, 0], [0.70711, -0.70711, 0], [0, -1, 0]];
  const seam = { points: meridian, closed: false };
  assert.equal(needsNoTwin(seam, sphere, plane), false, 'only its ends are their own images');
  const d = addMirroredTwin(cmd.addSeam(design, seam), sphere, plane, 0);
  assert.equal(d.seams.length, 2);
  d.seams[1].points.forEach((p, k) => assert.ok(dist(positionOf(sphere, p), reflect(meridian[k], plane)) < 0.05, `point ${k} reflected`));
});

test('points snapped to a seam are snapped to its twin when mirrored', () => {
  const design = { ...newDesign('sphere'), symmetry: { axis: 'x' } };
  const plane = symmetryPlane(design, sphere);
  const host = [[0.6, 0.6, 0.5], [0.6, -0.6, 0.5]].map((p) => closestSurfacePoint(sphere, p));
  let d = addMirroredTwin(cmd.addSeam(design, { points: host, closed: false }), sphere, plane, 0);
  const snapped = { ...closestSurfacePoint(sphere, [0.7, 0, 0.7]), on: 0 };
  assert.equal(mirrorPoint(d, sphere, plane, snapped).on, 1);
  d = cmd.addSeam(d, { points: [snapped, closestSurfacePoint(sphere, [0.9, 0, -0.3])], closed: false });
  d = addMirroredTwin(d, sphere, plane, 2);
  assert.equal(d.seams[3].points[0].on, 1);
});

test('deleting a seam keeps twin links consistent; the reader drops broken links and bad planes', () => {
  const base = { ...newDesign('sphere'), symmetry: { axis: 'z' } };
  const seam = (name, mirror) => ({ name, closed: false, weight: 1, points: [{ face: 0, bary: [1, 0, 0] }, { face: 1, bary: [1, 0, 0] }], ...(mirror === undefined ? {} : { mirror }) });
  const d = { ...base, seams: [seam('a'), seam('b', 3), seam('c'), seam('b (mirror)', 1)] };
  const afterA = cmd.deleteSeam(d, 0);
  assert.equal(afterA.seams[0].mirror, 2);
  assert.equal(afterA.seams[2].mirror, 0);
  const afterTwin = cmd.deleteSeam(d, 3);
  assert.equal(afterTwin.seams[1].mirror, undefined, 'the survivor loses its link');
  const parsed = parseDesign({ ...d, seams: [seam('a', 1), seam('b', 2), seam('c', 1)] });
  assert.equal(parsed.design.seams[0].mirror, undefined, 'a one-way link is dropped');
  assert.equal(parsed.design.seams[1].mirror, 2);
  assert.equal(parsed.design.seams[2].mirror, 1);
  assert.deepEqual(parsed.design.symmetry, { axis: 'z' });
  const bad = parseDesign({ ...d, symmetry: { axis: 'w' } });
  assert.equal(bad.design.symmetry, undefined);
  assert.match(bad.warnings.join(' '), /mirror symmetry/);
  assert.equal(cmd.setSymmetry(d, null).symmetry, undefined);
  assert.deepEqual(cmd.setSymmetry(d, 'y').symmetry, { axis: 'y' });
});
