// Mirror symmetry of seams for symmetric targets. The design's `symmetry` ({ axis: 'x' | 'y' | 'z' })
// names a plane of the target's own axes through the center of its bounding box. A seam drawn while it is
// on gets a mirrored twin (seam.mirror = the twin's index, both ways); editing either edits both. A seam
// that is its own mirror image (a loop around the belly of a symmetric animal) gets no twin.
// Mirroring a surface point: its position reflected across the plane, then the closest point of the target.

import { polylineDistance } from './geometry.js';

export const SYMMETRY_AXES = ['x', 'y', 'z'];
const SELF_SYMMETRIC_TOLERANCE = 0.01; // of the bounding-box diagonal

// The plane { axis: 0 | 1 | 2, offset } in target units, or null when the design has no symmetry.
export function symmetryPlane(design, target) {
  const axis = SYMMETRY_AXES.indexOf(design?.symmetry?.axis);
  if (axis < 0 || !target) return null;
  const { lo, hi } = bounds(target);
  return { axis, offset: (lo[axis] + hi[axis]) / 2 };
}

// Parse-and-default of the design field: { axis } or undefined (no symmetry).
export function parseSymmetry(value, warnings) {
  if (value === undefined || value === null) return undefined;
  if (typeof value === 'object' && SYMMETRY_AXES.includes(value.axis)) return { ...value };
  warnings.push('The design\'s mirror symmetry is not one of the x, y or z planes; it is turned off.');
  return undefined;
}

export function reflect(position, plane) {
  const out = [...position];
  out[plane.axis] = 2 * plane.offset - position[plane.axis];
  return out;
}

const boundsCache = new WeakMap();
// The target's bounding box { lo, hi } and its diagonal, in its own units (kept per target).
export function bounds(target) {
  let b = boundsCache.get(target);
  if (!b) {
    const lo = [Infinity, Infinity, Infinity];
    const hi = [-Infinity, -Infinity, -Infinity];
    const p = target.positions;
    for (let i = 0; i < p.length; i++) {
      lo[i % 3] = Math.min(lo[i % 3], p[i]);
      hi[i % 3] = Math.max(hi[i % 3], p[i]);
    }
    b = { lo, hi, diagonal: Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) };
    boundsCache.set(target, b);
  }
  return b;
}

export function positionOf(target, { face, bary }) {
  const { positions, indices } = target;
  const out = [0, 0, 0];
  for (let c = 0; c < 3; c++) for (let k = 0; k < 3; k++) out[k] += bary[c] * positions[3 * indices[3 * face + c] + k];
  return out;
}

// A seam's control point: a surface point or, as a design file may give it, a plain 3D point (docs/formats.md).
export const controlPosition = (target, point) => (Array.isArray(point) ? point : positionOf(target, point));

// Per triangle: a bounding sphere (center, radius), to skip far triangles in closest-point queries.
const spheresCache = new WeakMap();
function triangleSpheres(target) {
  let s = spheresCache.get(target);
  if (!s) {
    const { positions: p, indices: t } = target;
    const n = t.length / 3;
    s = new Float64Array(4 * n);
    for (let f = 0; f < n; f++) {
      let cx = 0, cy = 0, cz = 0;
      for (let c = 0; c < 3; c++) {
        const v = 3 * t[3 * f + c];
        cx += p[v] / 3;
        cy += p[v + 1] / 3;
        cz += p[v + 2] / 3;
      }
      let r = 0;
      for (let c = 0; c < 3; c++) {
        const v = 3 * t[3 * f + c];
        r = Math.max(r, Math.hypot(p[v] - cx, p[v + 1] - cy, p[v + 2] - cz));
      }
      s.set([cx, cy, cz, r], 4 * f);
    }
    spheresCache.set(target, s);
  }
  return s;
}

// The closest point of triangle (a, b, c) to p, as barycentric coordinates (Ericson, Real-Time Collision
// Detection, 5.1.5: the Voronoi regions of the vertices, then the edges, then the face).
export function closestOnTriangle(p, a, b, c) {
  const sub = (u, v) => [u[0] - v[0], u[1] - v[1], u[2] - v[2]];
  const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return [1, 0, 0];
  const bp = sub(p, b);
  const d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return [0, 1, 0];
  const vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const v = d1 / (d1 - d3);
    return [1 - v, v, 0];
  }
  const cp = sub(p, c);
  const d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return [0, 0, 1];
  const vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const w = d2 / (d2 - d6);
    return [1 - w, 0, w];
  }
  const va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const w = (d4 - d3) / (d4 - d3 + (d5 - d6));
    return [0, 1 - w, w];
  }
  const denom = 1 / (va + vb + vc);
  const v = vb * denom, w = vc * denom;
  return [1 - v - w, v, w];
}

// The surface point { face, bary } of the target closest to position.
export function closestSurfacePoint(target, position) {
  const { positions: p, indices: t } = target;
  const spheres = triangleSpheres(target);
  const vertex = (i) => [p[3 * i], p[3 * i + 1], p[3 * i + 2]];
  let best = null;
  let bestDistance = Infinity;
  for (let f = 0; f < t.length / 3; f++) {
    const centerDistance = Math.hypot(position[0] - spheres[4 * f], position[1] - spheres[4 * f + 1], position[2] - spheres[4 * f + 2]);
    if (centerDistance - spheres[4 * f + 3] >= bestDistance) continue;
    const a = vertex(t[3 * f]), b = vertex(t[3 * f + 1]), c = vertex(t[3 * f + 2]);
    const bary = closestOnTriangle(position, a, b, c);
    const q = [0, 1, 2].map((k) => bary[0] * a[k] + bary[1] * b[k] + bary[2] * c[k]);
    const d = Math.hypot(q[0] - position[0], q[1] - position[1], q[2] - position[2]);
    if (d < bestDistance) {
      bestDistance = d;
      best = { face: f, bary };
    }
  }
  return best;
}

// The mirror image of a seam control point. A point snapped onto seam k ("on": k) is snapped onto k's twin
// (or onto k itself when k is its own mirror image).
export function mirrorPoint(design, target, plane, point) {
  const image = closestSurfacePoint(target, reflect(controlPosition(target, point), plane));
  if (point.on === undefined) return image;
  const host = design.seams[point.on];
  return { ...image, on: host?.mirror ?? point.on };
}

// The share of the seam's control points whose mirror image lies on the seam's own line through its control points
// (not necessarily at another control point: a section loop across the plane has its points at equal arc lengths from
// wherever it starts, 2 % of the diagonal apart, which the mirror does not map onto each other).
function ownImageShare(seam, target, plane) {
  const tolerance = SELF_SYMMETRIC_TOLERANCE * bounds(target).diagonal;
  const controls = seam.points.map((p) => controlPosition(target, p));
  if (!controls.length) return 0;
  return controls.filter((c) => polylineDistance(reflect(c, plane), controls, seam.closed) < tolerance).length / controls.length;
}

// True when the seam's mirror image is the seam itself.
export function isSelfSymmetric(seam, target, plane) {
  return ownImageShare(seam, target, plane) === 1;
}

// True when half of the seam or more is its own mirror image: a twin would lie over it there and cut slivers off where
// the two part (an animal's outline seen from its side runs along the mirror plane over its back and belly, and round
// one side's legs), so it gets none.
export function needsNoTwin(seam, target, plane) {
  return ownImageShare(seam, target, plane) >= 0.5;
}

// The design with a mirrored twin of seam i appended (linked both ways), or the same design when the seam
// already has one or needs none (needsNoTwin).
export function addMirroredTwin(design, target, plane, i) {
  const seam = design.seams[i];
  if (!seam || !plane || seam.mirror !== undefined || needsNoTwin(seam, target, plane)) return design;
  // The band record stays with the seam the band was laid as: the twin follows it through the mirror link.
  const { band, ...own } = seam;
  const twin = {
    ...own,
    name: `${seam.name ?? `Seam ${i + 1}`} (mirror)`,
    points: seam.points.map((p) => mirrorPoint(design, target, plane, p)),
    mirror: i,
  };
  const seams = design.seams.map((s, k) => (k === i ? { ...s, mirror: design.seams.length } : s));
  return { ...design, seams: [...seams, twin] };
}

// Seams laid together as their own mirror images (a suggested layout, suggest.js), linked as twins: from seam `from`
// on, each seam that is not its own mirror image takes as twin the seam whose middle lies nearest its mirrored
// middle (within 2 % of the diagonal), which becomes its exact mirror image point for point, so that editing one side
// edits the other as for seams drawn with symmetry on.
export function linkMirrorTwins(design, target, plane, from = 0) {
  if (!plane) return design;
  const seams = design.seams.slice();
  const middle = (seam) => {
    const out = [0, 0, 0];
    for (const p of seam.points) controlPosition(target, p).forEach((x, k) => (out[k] += x / seam.points.length));
    return out;
  };
  const tolerance = 0.02 * bounds(target).diagonal;
  for (let i = from; i < seams.length; i++) {
    if (seams[i].mirror !== undefined || isSelfSymmetric(seams[i], target, plane)) continue;
    const image = reflect(middle(seams[i]), plane);
    let twin = -1;
    let nearest = tolerance;
    for (let j = from; j < seams.length; j++) {
      if (j === i || seams[j].mirror !== undefined || seams[j].closed !== seams[i].closed) continue;
      const m = middle(seams[j]);
      const d = Math.hypot(m[0] - image[0], m[1] - image[1], m[2] - image[2]);
      if (d < nearest) (nearest = d), (twin = j);
    }
    if (twin < 0) continue;
    seams[i] = { ...seams[i], mirror: twin };
    seams[twin] = { ...seams[twin], mirror: i, mirrored: true };
  }
  // Then each twin laid again as the other's image, its ends attached to the twins of the seams the other's are on.
  const linked = { ...design, seams };
  return {
    ...design,
    seams: seams.map(({ mirrored, ...seam }) =>
      mirrored ? { ...seam, points: seams[seam.mirror].points.map((p) => mirrorPoint(linked, target, plane, p)) } : seam,
    ),
  };
}
