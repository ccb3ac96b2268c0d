// Gusset bands (issue 23): two seams a chosen width apart on the cut pattern, with a strip panel between them
// for thickness, and a seam across the strip (a closed strip is a tube until a seam opens it). Along a section:
// the plane sections half the width to each side of a point. Along the outline: the level sets at plus and
// minus half the width of the signed surface distance to the outline, front and back. The design remembers a
// band on its seams (seam.band, parseBand) so it can be laid again at another width.
import { outlineLoop, sectionThrough, sectionSeamPoints, splitInTwo, zeroLoops, loopLength, distance } from './section.js';
import { segmentDistance } from './geometry.js';
import { positionOf } from './symmetry.js';

export const BAND_PARTS = ['side 1', 'side 2', 'across'];
const BAND_KINDS = ['section', 'outline'];
const MAX_BAND_MM = 10000;

// The seams' names: "Band 40 mm, side 1", ...; an outline band's sides are its front and back.
export function bandNames(kind, widthMm) {
  const width = `${+widthMm.toFixed(1)} mm`;
  return kind === 'outline'
    ? [`Band ${width}, front side`, `Band ${width}, back side`, `Band ${width}, across`]
    : [`Band ${width}, side 1`, `Band ${width}, side 2`, `Band ${width}, across`];
}

// The two sides of a band along a section: the loops of the planes half the width (target units) to each side
// of origin, each the one nearest the point there; null where a plane misses the target.
export function sectionBandLoops(mesh, { origin, normal }, width) {
  const loops = [-width / 2, width / 2].map((o) => sectionThrough(mesh, { position: origin.map((x, k) => x + o * normal[k]), face: -1 }, normal));
  return loops.every(Boolean) ? loops : null;
}

// The two sides of a band along the outline seen from `towards`: { loops: [front, back], outline, absorbed }
// (absorbed: front or back parts narrower than the band, laid into it, not counting specks), or { problem } in the
// designer's words.
// The sides are the zero sets of d -/+ width / 2, d the surface distance to the outline signed by the facing
// side, each made one loop as the outline is (splitInTwo).
export function outlineBandLoops(mesh, { towards }, width) {
  const outline = outlineLoop(mesh, towards);
  if (!outline) return { problem: 'The shape shows no outline from here: turn the view and try again.' };
  const d = distanceToZeroSet(mesh, outline.facing);
  for (let v = 0; v < d.length; v++) if (outline.facing[v] < 0) d[v] = -d[v];
  const loops = [];
  const levels = [];
  let absorbed = 0;
  for (const [k, side] of [[1, 'front'], [-1, 'back']]) {
    // Positive beyond the side's seam, away from the outline (the front or back panel), negative in the band.
    const level = Float64Array.from(d, (x) => k * x - width / 2);
    const split = splitInTwo(mesh, level);
    if (!split) return { problem: `The band is too wide for the shape seen from here: no part of the ${side} lies farther than half the band from the outline.` };
    // The panel keeps its largest part; the band takes the rest, so much of the panel lost means a band too wide.
    const [panel] = split.area;
    const lost = split.movedParts[0].reduce((sum, a) => sum + a, 0);
    if (lost > 0.5 * panel)
      return { problem: `The band is too wide for the shape seen from here: the ${side} panel would keep only ${Math.round(100 * (1 - lost / panel))} % of its part of the surface (narrow parts go into the band). Try a narrower band.` };
    // Parts smaller than a square half the band wide are specks where the side's level barely crosses zero, no tail
    // or ear a designer would miss: the note leaves them out (a letter K at 30 mm had 28, none of them wider than a
    // vertex).
    absorbed += split.movedParts[0].filter((a) => a >= (width / 2) ** 2).length;
    const found = zeroLoops(mesh, level);
    if (!found.length) return { problem: `The band is too wide for the shape seen from here: its ${side} side makes no seam.` };
    if (found.length > outline.loops) return { problem: `The band's ${side} side breaks up into ${found.length} loops here (the shape is narrower than the band in places). Try a narrower band or another view.` };
    loops.push(found.reduce((best, l) => (loopLength(l) > loopLength(best) ? l : best)));
    levels.push(level);
  }
  // A strip: each side within about the band's width of the other along most of its length. Where the front or
  // back is mostly narrower than the band, it went into the band, and the "strip" is a panel of its own shape.
  for (const [k, side] of [[0, 'front'], [1, 'back']]) {
    const other = distanceToZeroSet(mesh, levels[1 - k]);
    const share = shareWithin(mesh, loops[k], other, 1.5 * width);
    if (share < 0.5)
      return { problem: `The band is too wide for the shape seen from here: most of the ${side} is narrower than the band, so the strip would not be of even width (its sides are the band's width apart along only ${Math.round(100 * share)} % of the ${side} side). Try a narrower band or another view.` };
  }
  return { loops, outline, absorbed };
}

// The share of a zero-set loop's length (zeroLoops) where a field at the vertices, read on the loop's edges, is
// below `limit`.
function shareWithin({ positions, indices }, loop, field, limit) {
  const valueAt = (p) => {
    const corners = [0, 1, 2].map((c) => indices[3 * p.face + c]);
    return corners.reduce((sum, v, c) => sum + p.bary[c] * field[v], 0);
  };
  let within = 0;
  let total = 0;
  loop.forEach((p, i) => {
    const length = distance(p.position, loop[(i + 1) % loop.length].position);
    total += length;
    if (valueAt(p) <= limit) within += length;
  });
  return total > 0 ? within / total : 0;
}

// The loops of a band record (seam.band) at a width in mm: { loops } or { problem } (designer's words).
export function bandLoops(mesh, band, unitsPerMillimetre, widthMm = band.width_mm) {
  const width = widthMm * unitsPerMillimetre;
  if (band.kind === 'outline') return outlineBandLoops(mesh, band, width);
  const loops = sectionBandLoops(mesh, band, width);
  return loops ? { loops } : { problem: `A plane ${+(widthMm / 2).toFixed(1)} mm from the band's middle misses the shape: the band is too wide here.` };
}

// The seams of a band, as surface points: its two sides (sectionSeamPoints), and the two ends of the seam across
// the strip: the point of side 1 nearest `near` (a position) and the point of side 2 nearest that. With `width`
// (target units), only where side 2 comes within about the band's width: where a narrow part went into an outline
// band the sides lie far apart, and a seam across there would cut off a sliver of it.
export function bandSeamPoints(mesh, loops, near, { width = null } = {}) {
  const sides = loops.map((loop) => sectionSeamPoints(mesh, loop));
  const at = sides.map((points) => points.map((p) => positionOf(mesh, p)));
  const nearest = (k, to) => at[k].reduce((best, p, i) => (distance(p, to) < distance(at[k][best], to) ? i : best), 0);
  const across = at[0].map((p, i) => ({ i, j: nearest(1, p) })).map((c) => ({ ...c, gap: distance(at[0][c.i], at[1][c.j]) }));
  const narrowest = Math.min(...across.map((c) => c.gap));
  const strip = across.filter((c) => width === null || c.gap <= Math.max(1.2 * width, narrowest));
  const { i, j } = strip.reduce((best, c) => (distance(at[0][c.i], near) < distance(at[0][best.i], near) ? c : best));
  return { sides, across: [sides[0][i], sides[1][j]] };
}

// Where the seam across an outline band goes when nothing says: the outline's lowest point (`up`, the target's
// up direction in its own coordinates), under the balloon where the strip is least seen.
export function lowestPoint(loop, up) {
  const height = (p) => p.position[0] * up[0] + p.position[1] * up[1] + p.position[2] * up[2];
  return loop.reduce((best, p) => (height(p) < height(best) ? p : best)).position;
}

// Surface distance from the zero set of a field given at the vertices (linear over each triangle) to every
// vertex: the distance to the zero set's segment in each triangle it crosses, then Dijkstra over the edges with
// the triangles' plane-wave updates (as fast marching), so a distance along the surface comes out within a few
// percent, not an edge path's up to 15 % too long.
export function distanceToZeroSet({ positions, indices }, values) {
  const nv = positions.length / 3;
  const nf = indices.length / 3;
  const p = (v) => [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
  const d = new Float64Array(nv).fill(Infinity);
  const h = Float64Array.from(values, (x) => x + 1e-9); // as zeroLoops reads it
  for (let f = 0; f < nf; f++) {
    const tri = [indices[3 * f], indices[3 * f + 1], indices[3 * f + 2]];
    const cut = [];
    for (let k = 0; k < 3; k++) {
      const [a, b] = [tri[k], tri[(k + 1) % 3]];
      if (h[a] < 0 === h[b] < 0) continue;
      const s = h[a] / (h[a] - h[b]);
      cut.push(p(a).map((x, c) => x + s * (p(b)[c] - x)));
    }
    if (cut.length !== 2) continue;
    for (const v of tri) d[v] = Math.min(d[v], segmentDistance(p(v), cut[0], cut[1]));
  }
  const faces = Array.from({ length: nv }, () => []);
  for (let f = 0; f < nf; f++) for (let k = 0; k < 3; k++) faces[indices[3 * f + k]].push(f);
  const done = new Uint8Array(nv);
  const heap = new MinHeap();
  for (let v = 0; v < nv; v++) if (d[v] < Infinity) heap.push(d[v], v);
  const offer = (v, x) => {
    if (x < d[v]) (d[v] = x), heap.push(x, v);
  };
  while (heap.size) {
    const [dv, v] = heap.pop();
    if (done[v] || dv > d[v]) continue;
    done[v] = 1;
    for (const f of faces[v]) {
      const tri = [indices[3 * f], indices[3 * f + 1], indices[3 * f + 2]];
      const k = tri.indexOf(v);
      const [u, w] = [tri[(k + 1) % 3], tri[(k + 2) % 3]];
      for (const [known, open] of [[u, w], [w, u]]) {
        if (done[open]) continue;
        offer(open, d[v] + distance(p(v), p(open)));
        if (done[known]) offer(open, unfolded(p(v), d[v], p(known), d[known], p(open)));
      }
    }
  }
  return d;
}

// The distance at C where the front that reached A at dA and B at dB crosses the triangle as a plane wave (the
// distance linear over it, its gradient of length 1, pointing into the triangle from edge AB: Kimmel and Sethian
// 1998, "Computing geodesic paths on manifolds", the triangle update); Infinity when the wave comes from
// elsewhere (its line back from C misses AB: the edges' paths then hold). A plane wave, not a point source, since
// the front starts from a curve: a point source placed to fit dA and dB would fall short of a straight front.
function unfolded(A, dA, B, dB, C) {
  const e = B.map((x, k) => x - A[k]);
  const L = Math.hypot(...e);
  const c = C.map((x, k) => x - A[k]);
  const cx = (c[0] * e[0] + c[1] * e[1] + c[2] * e[2]) / L;
  const cy = Math.sqrt(Math.max(0, c[0] ** 2 + c[1] ** 2 + c[2] ** 2 - cx * cx));
  const gx = (dB - dA) / L;
  if (!(Math.abs(gx) < 1) || cy <= 0) return Infinity;
  const gy = Math.sqrt(1 - gx * gx);
  const foot = cx - (gx * cy) / gy; // where the line back from C along the gradient meets AB
  return foot >= 0 && foot <= L ? dA + gx * cx + gy * cy : Infinity;
}

class MinHeap {
  constructor() {
    this.keys = [];
    this.values = [];
  }
  get size() {
    return this.keys.length;
  }
  push(key, value) {
    const { keys, values } = this;
    let i = keys.length;
    keys.push(key), values.push(value);
    while (i > 0) {
      const parent = (i - 1) >> 1;
      if (keys[parent] <= key) break;
      keys[i] = keys[parent], values[i] = values[parent];
      i = parent;
    }
    keys[i] = key, values[i] = value;
  }
  pop() {
    const { keys, values } = this;
    const top = [keys[0], values[0]];
    const key = keys.pop();
    const value = values.pop();
    if (keys.length) {
      let i = 0;
      for (;;) {
        let child = 2 * i + 1;
        if (child >= keys.length) break;
        if (child + 1 < keys.length && keys[child + 1] < keys[child]) child++;
        if (keys[child] >= key) break;
        keys[i] = keys[child], values[i] = values[child];
        i = child;
      }
      keys[i] = key, values[i] = value;
    }
    return top;
  }
}

const isVector = (v) => Array.isArray(v) && v.length === 3 && v.every((x) => typeof x === 'number' && Number.isFinite(x));

// Whether the design has a gusset band (its seams keep their band records: design.js drops a bad one on reading).
export const hasGusset = (design) => design.seams.some((s) => s.band);

// Parse-and-default of seam.band: { id, part, kind, width_mm, origin, normal (section) | towards (outline) }, or
// null when it is not a band Billow can lay again.
export function parseBand(value) {
  if (value === null || typeof value !== 'object' || Array.isArray(value)) return null;
  const { id, part, kind, width_mm: width, origin } = value;
  if (!Number.isInteger(id) || id < 1 || !BAND_PARTS.includes(part) || !BAND_KINDS.includes(kind)) return null;
  if (!(typeof width === 'number' && width > 0 && width <= MAX_BAND_MM) || !isVector(origin)) return null;
  const direction = kind === 'section' ? value.normal : value.towards;
  if (!isVector(direction) || !(Math.hypot(...direction) > 1e-9)) return null;
  return { ...value };
}
