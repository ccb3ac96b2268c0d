// Seams along plane sections of a mesh, as a pattern maker would chalk them (a middle seam, rings around
// limbs, bands across the body), and the koala's plush-toy cuts made of them: used by
// scripts/make-bench-designs.mjs (bench/designs/teddy and elephant) and scripts/make-gallery.mjs (the
// gallery's koala). Each seam is a loop of one plane section, picked by a point it must pass near, sampled
// at equal arc length.

import { planeSection } from '../web/src/app/section.js';

export const AXES = { x: 0, y: 1, z: 2 };

// The closed loops where the plane {p[axis] = value} cuts the mesh: arrays of 3D points (planeSection, the
// section seam tool's own rule).
export function sectionLoops({ v, t }, axis, value) {
  const normal = [0, 0, 0];
  normal[axis] = 1;
  return planeSection({ positions: v.flat(), indices: t.flat() }, normal, value).map((loop) => loop.map((p) => p.position));
}

const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
export const length = (loop) => loop.reduce((s, p, i) => s + dist(p, loop[(i + 1) % loop.length]), 0);

// n points at equal arc length along a closed loop.
function resample(loop, n) {
  const total = length(loop), out = [];
  let i = 0, walked = 0;
  for (let k = 0; k < n; k++) {
    const want = (k * total) / n;
    while (walked + dist(loop[i], loop[(i + 1) % loop.length]) < want) walked += dist(loop[i], loop[(i + 1) % loop.length]), i++;
    const a = loop[i], b = loop[(i + 1) % loop.length], s = (want - walked) / Math.max(dist(a, b), 1e-300);
    out.push(a.map((x, c) => Math.round((x + s * (b[c] - x)) * 1e5) / 1e5));
  }
  return out;
}

// The loop of the section {axis = value} passing nearest to `near`, as a seam of n points.
export function sectionSeam(mesh, name, axis, value, near, n) {
  const loops = sectionLoops(mesh, AXES[axis], value);
  if (!loops.length) throw new Error(`${name}: the plane ${axis} = ${value} misses the mesh`);
  const gap = (loop) => Math.min(...loop.map((p) => dist(p, near)));
  const loop = loops.reduce((best, l) => (gap(l) < gap(best) ? l : best));
  return { name, closed: true, weight: 1, points: resample(loop, n) };
}

export function bbox({ v }) {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (const p of v) for (let k = 0; k < 3; k++) (lo[k] = Math.min(lo[k], p[k])), (hi[k] = Math.max(hi[k], p[k]));
  return { lo, hi };
}

// The koala (koala.obj: standing on all fours, head towards +z, symmetric in x, in its own units) cut like
// a plush toy: a middle seam and a seam down each side through the legs (x = +-0.85, sidePoints points
// each: four strips from nose to tail), bands [name, z] across the body, and a ring around each ear.
export function koalaSeams(mesh, { sidePoints, bands }) {
  const seams = [sectionSeam(mesh, 'middle', 'x', 0, [0, 3.5, 0], 80)];
  for (const [name, x] of [['left side', 0.85], ['right side', -0.85]]) seams.push(sectionSeam(mesh, name, 'x', x, [x, -1, -2.8], sidePoints));
  for (const [name, z] of bands) seams.push(sectionSeam(mesh, name, 'z', z, [0, 3, z], 40));
  for (const [name, x] of [['left ear', 1.4], ['right ear', -1.4]]) seams.push(sectionSeam(mesh, name, 'x', x, [x, 3.0, 3.1], 20));
  return seams;
}

// The teddy cut (paper Table 1 "Teddy": about 17 panels): bands across the back (z = -1) and across the
// head through the ears (z = 3.1): 18 panels.
export const teddySeams = (mesh) => koalaSeams(mesh, { sidePoints: 96, bands: [['back band', -1.0], ['head band', 3.1]] });
