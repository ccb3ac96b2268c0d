// Plane sections of the target: the closed loops where a plane cuts it, as the section seam tool lays them and
// as scripts/plane-sections.mjs cuts the bench and gallery designs. Each loop point lies on a mesh edge; a seam
// made of a loop keeps, for every control point, the triangle and barycentric weights it lies in, so it is an
// ordinary seam of surface points.
import { bounds } from './symmetry.js';

// The loops where the plane {p · normal = offset} cuts the mesh ({ positions, indices }, flat arrays). Each
// loop is an array of { position: [x, y, z], face, bary: [3] }, in walking order (a point on an edge, with
// the face the walk crossed to reach it).
export function planeSection({ positions, indices }, normal, offset) {
  const nv = positions.length / 3;
  // Signed heights above the plane; no vertex exactly on it, so every crossing is inside an edge.
  const h = new Float64Array(nv);
  for (let v = 0; v < nv; v++)
    h[v] = positions[3 * v] * normal[0] + positions[3 * v + 1] * normal[1] + positions[3 * v + 2] * normal[2] - offset + 1e-9;
  const key = (a, b) => (a < b ? `${a},${b}` : `${b},${a}`);
  const next = new Map(); // edge key -> [{ edge, face }]: the cut faces on each crossed edge
  const edges = new Map(); // edge key -> [a, b]
  for (let f = 0; f < indices.length / 3; f++) {
    const tri = [indices[3 * f], indices[3 * f + 1], indices[3 * f + 2]];
    const crossed = [[tri[0], tri[1]], [tri[1], tri[2]], [tri[2], tri[0]]].filter(([p, q]) => h[p] < 0 !== h[q] < 0);
    if (crossed.length !== 2) continue;
    const [e0, e1] = crossed.map(([p, q]) => key(p, q));
    crossed.forEach(([p, q]) => edges.set(key(p, q), [p, q]));
    if (!next.has(e0)) next.set(e0, []);
    if (!next.has(e1)) next.set(e1, []);
    next.get(e0).push({ edge: e1, face: f });
    next.get(e1).push({ edge: e0, face: f });
  }
  const point = (edge, face) => {
    const [a, b] = edges.get(edge);
    const s = h[a] / (h[a] - h[b]);
    const position = [0, 1, 2].map((k) => positions[3 * a + k] + s * (positions[3 * b + k] - positions[3 * a + k]));
    const bary = [0, 1, 2].map((k) => (indices[3 * face + k] === a ? 1 - s : indices[3 * face + k] === b ? s : 0));
    return { position, face, bary };
  };
  const seen = new Set();
  const loops = [];
  for (const start of next.keys()) {
    if (seen.has(start)) continue;
    const loop = [];
    let current = start;
    // The start's face is the one the walk closes the loop across (the other face on its edge).
    let face = (next.get(start)[1] ?? next.get(start)[0]).face;
    while (current && !seen.has(current)) {
      seen.add(current);
      loop.push(point(current, face));
      const step = next.get(current).find((n) => !seen.has(n.edge));
      current = step?.edge;
      face = step?.face;
    }
    if (loop.length >= 3) loops.push(loop);
  }
  return loops;
}

// A section seam's control points lie about this share of the target's size apart (a finger's width holds a
// few), within these counts; the surface paths between them follow the section.
const SECTION_SPACING = 0.02;
const SECTION_POINTS = [12, 160];

const distance = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

export const loopLength = (loop) => loop.reduce((s, p, i) => s + distance(p.position, loop[(i + 1) % loop.length].position), 0);

// n points at equal arc length along a closed loop of planeSection, each in the face between its neighbours on
// the loop: a point between two crossings lies in the face the walk crossed from one to the other.
export function resampleLoop({ indices }, loop, n) {
  const total = loopLength(loop);
  const out = [];
  let i = 0;
  let walked = 0;
  const span = (k) => distance(loop[k].position, loop[(k + 1) % loop.length].position);
  for (let k = 0; k < n; k++) {
    const want = (k * total) / n;
    while (i < loop.length - 1 && walked + span(i) < want) walked += span(i++);
    const a = loop[i];
    const b = loop[(i + 1) % loop.length];
    const s = Math.min(1, Math.max(0, (want - walked) / Math.max(span(i), 1e-300)));
    // b was reached across b.face, which also holds a's edge: both points' weights in that face.
    const face = b.face;
    const weightsIn = (p) => {
      if (p.face === face) return p.bary;
      const corner = [0, 1, 2].map((c) => indices[3 * p.face + c]);
      return [0, 1, 2].map((c) => {
        const at = corner.indexOf(indices[3 * face + c]);
        return at < 0 ? 0 : p.bary[at];
      });
    };
    const wa = weightsIn(a);
    const wb = b.bary;
    const bary = [0, 1, 2].map((c) => (1 - s) * wa[c] + s * wb[c]);
    out.push({ position: a.position.map((x, c) => x + s * (b.position[c] - x)), face, bary });
  }
  return out;
}

// The section loop through a point of the surface ({ position, face }) across `normal`: the loop that passes
// through the point's own triangle, or the nearest one. null where the plane misses.
export function sectionThrough(mesh, at, normal) {
  const offset = at.position[0] * normal[0] + at.position[1] * normal[1] + at.position[2] * normal[2];
  const loops = planeSection(mesh, normal, offset);
  if (!loops.length) return null;
  const own = loops.find((loop) => loop.some((p) => p.face === at.face));
  if (own) return own;
  const gap = (loop) => Math.min(...loop.map((p) => distance(p.position, at.position)));
  return loops.reduce((best, loop) => (gap(loop) < gap(best) ? loop : best));
}

// The control points ({ face, bary }) of the seam a section loop makes: the loop at equal arc length, spaced
// by SECTION_SPACING.
export function sectionSeamPoints(mesh, loop) {
  const { diagonal } = bounds(mesh);
  const n = Math.round(Math.min(SECTION_POINTS[1], Math.max(SECTION_POINTS[0], loopLength(loop) / (SECTION_SPACING * diagonal))));
  return resampleLoop(mesh, loop, n).map(({ face, bary }) => ({ face, bary }));
}
