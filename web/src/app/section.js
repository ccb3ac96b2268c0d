// Plane sections of the target: the closed loops where a plane cuts it, as the section seam tool lays them and
// as scripts/plane-sections.mjs cuts the bench and gallery designs. Each loop point lies on a mesh edge; a seam
// made of a loop keeps, for every control point, the triangle and barycentric weights it lies in, so it is an
// ordinary seam of surface points.
import { bounds } from './symmetry.js';
import { faceNormal } from './mesh-grid.js';

// The loops where the plane {p · normal = offset} cuts the mesh ({ positions, indices }, flat arrays). Each
// loop is an array of { position: [x, y, z], face, bary: [3] }, in walking order (a point on an edge, with
// the face the walk crossed to reach it).
export function planeSection(mesh, normal, offset) {
  const { positions } = mesh;
  const h = new Float64Array(positions.length / 3);
  for (let v = 0; v < h.length; v++)
    h[v] = positions[3 * v] * normal[0] + positions[3 * v + 1] * normal[1] + positions[3 * v + 2] * normal[2] - offset;
  return zeroLoops(mesh, h);
}

// The loops where a field given at the vertices (linear over each triangle) is zero, as planeSection's.
export function zeroLoops({ positions, indices }, values) {
  // No vertex exactly on the zero set, so every crossing is inside an edge.
  const h = Float64Array.from(values, (x) => x + 1e-9);
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
const CORNER_STRAY = 0.1;
const CORNER_POINTS_MAX = 400;

export const distance = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

export const loopLength = (loop) => loop.reduce((s, p, i) => s + distance(p.position, loop[(i + 1) % loop.length].position), 0);

// Points at the given arc lengths (ascending, from the loop's first point) along a closed loop of planeSection,
// each in the face between its neighbours on the loop: a point between two crossings lies in the face the walk
// crossed from one to the other.
export function resampleLoop({ indices }, loop, arcs) {
  const out = [];
  let i = 0;
  let walked = 0;
  const span = (k) => distance(loop[k].position, loop[(k + 1) % loop.length].position);
  for (const want of arcs) {
    while (i < loop.length - 1 && walked + span(i) < want) walked += span(i++);
    const a = loop[i];
    const b = loop[(i + 1) % loop.length];
    const s = Math.min(1, Math.max(0, (want - walked) / Math.max(span(i), 1e-300)));
    // b was reached across b.face, which also holds a's edge: both points' weights in that face. Where the two share
    // no face (a loop with points left out), the nearer of them: weights of a point off the face would not sum to 1.
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
    if (Math.abs(wa[0] + wa[1] + wa[2] - 1) > 1e-9) {
      const near = s < 0.5 ? a : b;
      out.push({ position: near.position, face: near.face, bary: near.bary });
      continue;
    }
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
// by SECTION_SPACING; with `corners`, where the loop strays from the chord between two of them by more than
// CORNER_STRAY of that spacing, its farthest point too, until none does. The seam runs along shortest paths between
// its points, and one that skips a sharp turn of an outline (a star's tip, a letter's corner) would cut it off and
// give it to the other side. A band's sides go without: they are offsets of the outline, and followed into every
// turn they would pinch the strip.
export function sectionSeamPoints(mesh, loop, { corners = false } = {}) {
  const { diagonal } = bounds(mesh);
  const total = loopLength(loop);
  const n = Math.round(Math.min(SECTION_POINTS[1], Math.max(SECTION_POINTS[0], total / (SECTION_SPACING * diagonal))));
  const arcs = Array.from({ length: n }, (_, k) => (k * total) / n);
  if (corners) keepTurns(loop, arcs, CORNER_STRAY * (total / n));
  return resampleLoop(mesh, loop, arcs).map(({ face, bary }) => ({ face, bary }));
}

// Inserts into `arcs` (ascending arc lengths from the loop's first point, the first 0) the arc of the loop point
// farthest from the chord between two neighbouring arcs, while one strays from it by more than `stray`.
function keepTurns(loop, arcs, stray) {
  const arcOf = [0];
  for (let i = 1; i <= loop.length; i++) arcOf.push(arcOf[i - 1] + distance(loop[i - 1].position, loop[i % loop.length].position));
  const total = arcOf[loop.length];
  const after = (arc) => {
    // The last loop point at or before an arc length in [0, total].
    let lo = 0;
    let hi = loop.length;
    while (hi - lo > 1) (arcOf[(lo + hi) >> 1] <= arc ? (lo = (lo + hi) >> 1) : (hi = (lo + hi) >> 1));
    return lo;
  };
  const at = (arc) => {
    const k = after(arc);
    const a = loop[k].position;
    const b = loop[(k + 1) % loop.length].position;
    const s = Math.min(1, Math.max(0, (arc - arcOf[k]) / Math.max(arcOf[k + 1] - arcOf[k], 1e-300)));
    return a.map((x, c) => x + s * (b[c] - x));
  };
  for (let k = 0; k < arcs.length && arcs.length < CORNER_POINTS_MAX; k++) {
    const a = arcs[k];
    const b = k + 1 < arcs.length ? arcs[k + 1] : total;
    const p = at(a);
    const d = at(b).map((x, c) => x - p[c]);
    const dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    let corner = -1;
    let gap = stray;
    for (let i = after(a) + 1; i < loop.length && arcOf[i] < b; i++) {
      const x = loop[i].position;
      const t = dd > 0 ? Math.min(1, Math.max(0, ((x[0] - p[0]) * d[0] + (x[1] - p[1]) * d[1] + (x[2] - p[2]) * d[2]) / dd)) : 0;
      const off = distance(x, p.map((y, c) => y + t * d[c]));
      if (off > gap) (gap = off), (corner = arcOf[i]);
    }
    if (corner > a) arcs.splice(k + 1, 0, corner), k--;
  }
}

// The outline of the target as seen from `towards` (the unit direction from the target to the viewer, in its
// own coordinates): the zero set of n · towards over the vertex normals, the contour where the surface turns
// away, cleaned into one loop (splitInTwo). Front-facing parts that are not the largest front (a fold, an arm's
// far side) go with the back, then back-facing parts that are not the largest back go with the front, so front
// and back are each one piece. Returns { loop, holes, movedParts, largestMoved, loops, facing } (movedParts: each
// part that changed sides, a share of the surface; largestMoved: the largest of them, else 0; loops: how many the
// contour still makes, more than one on a shape with a handle; loop is the longest, holes the others; facing: the
// cleaned field, > 0 in front), or null when the shape has no front or back.
export function outlineLoop(mesh, towards) {
  const neighbours = vertexNeighbours(mesh.indices, mesh.positions.length / 3);
  const facing = facingField(mesh, towards, neighbours);
  const split = splitInTwo(mesh, facing, neighbours);
  if (!split) return null;
  const loops = fairInDepth(mesh, facing, towards, neighbours);
  if (!loops.length) return null;
  const loop = loops.reduce((best, l) => (loopLength(l) > loopLength(best) ? l : best));
  const surface = split.area[0] + split.area[1];
  const movedParts = [...split.movedParts[0], ...split.movedParts[1]].map((a) => a / surface);
  return { loop, holes: loops.filter((l) => l !== loop), movedParts, largestMoved: movedShare(split), loops: loops.length, facing };
}

// outlineLoop's largestMoved alone, without tracing the contour: the largest part the outline seen from `towards` would
// turn to the other side, a share of the surface, or null when the shape has no front or back from there.
function largestTurnedAway(mesh, towards) {
  const neighbours = vertexNeighbours(mesh.indices, mesh.positions.length / 3);
  const split = splitInTwo(mesh, facingField(mesh, towards, neighbours), neighbours);
  return split && movedShare(split);
}

// Of the straight views [{ name, key, towards }], the one to name where the outline from here turns a part of `largest`
// (a share of the surface) away: of those that turn less than half as much away, the one that shows most of the
// shape, its surface's area projected along the view (a foil balloon is cut along its largest silhouette: a horse
// from its side, not from above, where both leave its legs out alike), with its share; null when none does.
export function straighterView(mesh, views, largest) {
  let best = null;
  for (const view of views) {
    const share = largestTurnedAway(mesh, view.towards);
    if (share === null || share >= largest / 2) continue;
    const shown = projectedArea(mesh, view.towards);
    if (!best || shown > best.shown) best = { ...view, share, shown };
  }
  return best && { name: best.name, key: best.key, share: best.share };
}

// The area of the surface seen along `towards` (unit), front and back alike: half the sum of |n . towards| over its
// triangles, the silhouette's area where the shape is convex.
export function projectedArea({ positions, indices }, towards) {
  let sum = 0;
  for (let f = 0; f < indices.length / 3; f++) {
    const n = faceNormal(positions, indices, f);
    sum += Math.abs(n[0] * towards[0] + n[1] * towards[1] + n[2] * towards[2]);
  }
  return sum / 4;
}

// splitInTwo's largest moved part as a share of the surface, 0 when none moved.
function movedShare(split) {
  return Math.max(0, ...split.movedParts[0], ...split.movedParts[1]) / (split.area[0] + split.area[1]);
}

// A shape with a handle seen through it (a ring face on, a letter O) has an outline of several loops: the rim
// and a hole per handle; the front and the back are then rings, not panels. Per hole, two sections along the view,
// each straight across the hole's line, cut them open into halves: one where the ring is narrowest, one opposite it
// across the hole. One cut alone would leave each ring a C sewn to itself across the cut, which the panels flatten
// badly. A hole gets none where no such cut runs around its ring (across the rim and its hole once or twice each, no
// other hole, along no flat wall: on a statue's legs and base a plane grazes a hole or wanders along an edge-on rim);
// the worker's cuts that open a tube open those (openIntoPanels). Each loop as zeroLoops'. The same rule as
// seams/outline.cpp's acrossHandles.
export function acrossHandles(mesh, rim, holes, towards) {
  const every = (loop, most) => loop.filter((_, i) => i % Math.max(1, Math.ceil(loop.length / most)) === 0);
  const nearestOn = (loop, x) => loop.reduce((best, q, i) => (distance(x, q.position) < distance(x, loop[best].position) ? i : best), 0);
  const hair = 1e-9 * bounds(mesh).diagonal;
  const rimPoints = every(rim, 400);
  const out = [];
  holes.forEach((hole, h) => {
    const some = every(hole, 200);
    const n = some.length;
    if (n < 3) return;
    // The section through the hole's point i straight across its line there (the plane along the view, across the
    // line's tangent), where it runs around the ring: across the rim and this hole once each (a ring seen through) or
    // twice (a torus seen from its side, whose inner contour is no hole one sees through), no other hole, and nowhere
    // along a piece of their lines. A section that grazes its hole, crosses a wavering rim more often, runs along a
    // flat wall seen edge-on or crosses another hole cuts slivers off (a statue's legs, its base seen edge-on).
    // Not at a corner (a letter's hole's), where the line has no one tangent: turning by more than 30 degrees between
    // the points a 24th of the loop to either side (nearer, a coarse mesh's contour zig-zags across a wall seen
    // edge-on; a circle turns 15 degrees there).
    const w = Math.max(2, Math.round(n / 24));
    const cut = (i) => {
      const seen = (a, b) => {
        const d = b.position.map((x, c) => x - a.position[c]);
        const along = dot(d, towards);
        return d.map((x, c) => x - along * towards[c]);
      };
      const before = seen(some[(i + n - (w % n)) % n], some[i]);
      const after = seen(some[i], some[(i + w) % n]);
      if (!(dot(before, after) > (Math.sqrt(3) / 2) * Math.hypot(...before) * Math.hypot(...after))) return null;
      const tangent = before.map((x, c) => x + after[c]);
      const unit = tangent.map((x) => x / Math.hypot(...tangent));
      const section = sectionThrough(mesh, some[i], unit);
      if (!section) return null;
      const offset = dot(some[i].position, unit);
      const faces = new Set(section.map((p) => p.face));
      const inPlane = (x) => Math.abs(dot(x.position, unit) - offset) <= hair;
      if ([hole, rim].some((loop) => loop.some((x, k) => inPlane(x) && inPlane(loop[(k + 1) % loop.length])))) return null;
      const around = (loop) => [1, 2].includes(crossings(loop, faces, unit, offset, hair));
      const runsAround = around(rim) && holes.every((other, k) => (k === h ? around(other) : crossings(other, faces, unit, offset, hair) === 0));
      return runsAround ? section : null;
    };
    const gap = some.map((p) => distance(p.position, rimPoints[nearestOn(rimPoints, p.position)].position));
    const nearest = gap.indexOf(Math.min(...gap));
    // The cut where the ring is narrowest: through the middle of a stretch as narrow (a letter's straight stroke,
    // where a cut at its end would leave a sliver at the corner), else through the narrowest point.
    const within = gap[nearest] * 1.01 + hair;
    let ahead = 0;
    let behind = 0;
    while (ahead + 1 < n && gap[(nearest + ahead + 1) % n] <= within) ahead++;
    while (behind + ahead + 1 < n && gap[(nearest + n - behind - 1) % n] <= within) behind++;
    let k = -1;
    let near = null;
    for (const i of [(nearest + n + (ahead >> 1) - (behind >> 1)) % n, nearest]) {
      near = cut(i);
      if (near) {
        k = i;
        break;
      }
    }
    if (!near) return;
    // The other cut opposite it across the hole's middle, else farthest from it, else where the ring is narrowest a
    // quarter of the hole or more away (a letter B's hole has its other stroke opposite, not the rim).
    const at = some[k].position;
    const middle = [0, 1, 2].map((c) => some.reduce((sum, p) => sum + p.position[c], 0) / n);
    const places = [
      nearestOn(some, middle.map((x, c) => 2 * x - at[c])),
      some.reduce((best, p, j) => (distance(p.position, at) > distance(some[best].position, at) ? j : best), k),
      ...[...gap.keys()].sort((a, b) => gap[a] - gap[b]).filter((j) => Math.min((j + n - k) % n, (k + n - j) % n) >= n / 4).slice(0, 4),
    ];
    for (const j of places) {
      const far = cut(j);
      if (far) {
        out.push(near, far);
        return;
      }
    }
  });
  return out;
}

// How many times `loop` crosses a loop of the plane {p . normal = offset} that passes through `faces` (a Set): where
// two consecutive points of the loop lie on either side of the plane, in one of those faces (a zeroLoops point names the
// face of the step that reaches it; the plane's other loops pass through other faces). A point within `hair` of the
// plane is on its positive side, as a vertex there is to planeSection (a loop point at a vertex is rounded off it).
function crossings(loop, faces, normal, offset, hair) {
  const below = (p) => dot(p.position, normal) - offset < -hair;
  let n = 0;
  loop.forEach((a, i) => {
    const b = loop[(i + 1) % loop.length];
    if (below(a) !== below(b) && faces.has(b.face)) n++;
  });
  return n;
}

// Per vertex, n · towards over the vertex normal (area-weighted), kept away from zero; where seen edge-on, from
// around (fillEdgeOn; neighbours: vertexNeighbours).
function facingField({ positions, indices }, towards, neighbours) {
  const nv = positions.length / 3;
  const normal = new Float64Array(3 * nv);
  for (let f = 0; f < indices.length / 3; f++) {
    const n = faceNormal(positions, indices, f);
    for (let i = 0; i < 3; i++) for (let k = 0; k < 3; k++) normal[3 * indices[3 * f + i] + k] += n[k];
  }
  const facing = new Float64Array(nv);
  for (let v = 0; v < nv; v++) {
    const n = [normal[3 * v], normal[3 * v + 1], normal[3 * v + 2]];
    facing[v] = (n[0] * towards[0] + n[1] * towards[1] + n[2] * towards[2]) / (Math.hypot(...n) || 1);
    // Away from zero, so the sides read the same here as where the contour is drawn (zeroLoops).
    if (Math.abs(facing[v]) < AWAY_FROM_ZERO) facing[v] = facing[v] > 0 ? AWAY_FROM_ZERO : -AWAY_FROM_ZERO;
  }
  fillEdgeOn(neighbours, facing);
  return facing;
}

const AWAY_FROM_ZERO = 1e-6;

// Where the surface is seen nearly edge-on the contour's depth is ill-set: across a flat base seen from the side, or
// along a coarse mesh's long triangles, it bends around a single vertex whose value is near zero (one a pinch moved,
// one that kept its zero beside a part that changed sides), and back: a spike in depth that the seam, and a foil
// piece cut along it, would follow. The vertex a spike's tip lies nearest takes the largest value of its neighbours on
// its side, which moves the crossings off it as far as they allow, and the contour is traced again; a move is kept
// where the contour got shorter (a vertex moved can also send it round another way), the largest spikes first, for a
// few rounds. A spike is a point whose neighbours on the loop are closer to each other than half its distance from
// them (a turn of more than 90 degrees) and that stands off their chord, across the view, by less than a quarter of
// that: a sharp turn seen from the front (a star's tip, a letter's corner) is the outline itself. Signs do not change,
// so the sides stay as splitInTwo left them. The same rule as seams/outline.cpp's fairInDepth.
const FAIR_ROUNDS = 4;
const FAIR_TRIES = 16;
function fairInDepth(mesh, values, towards, around) {
  const { indices } = mesh;
  const across = (d) => { const t = d[0] * towards[0] + d[1] * towards[1] + d[2] * towards[2]; return d.map((x, c) => x - t * towards[c]); };
  const norm = (d) => Math.hypot(d[0], d[1], d[2]);
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  let loops = zeroLoops(mesh, values);
  let length = totalLength(loops);
  let tries = 0;
  for (let round = 0; round < FAIR_ROUNDS; round++) {
    const tips = new Map(); // vertex -> how far its spike stands off
    for (const loop of loops) {
      // The loop without repeats (a crossing at a vertex is listed once per edge it ends, one near a vertex nearly so).
      const apart = 1e-3 * loopLength(loop) / loop.length;
      const points = loop.filter((p, i) => norm(sub(p.position, loop[(i + 1) % loop.length].position)) > apart);
      const n = points.length;
      if (n < 4) continue;
      for (let i = 0; i < n; i++) {
        const a = points[(i + n - 1) % n].position, tip = points[i].position, b = points[(i + 1) % n].position;
        const chord = sub(b, a);
        const off = sub(tip, a);
        const t = Math.min(1, Math.max(0, (off[0] * chord[0] + off[1] * chord[1] + off[2] * chord[2]) / Math.max(norm(chord) ** 2, 1e-300)));
        const stand = norm(sub(off, chord.map((x) => t * x)));
        if (!(stand > 0.5 * norm(chord) + 1e-12)) continue;
        // Across the view: the tip's distance from the chord's line as seen from `towards`.
        const c = across(chord), o = across(off), cc = norm(c);
        const seen = cc > 1e-12 ? norm(sub(o, c.map((x) => ((o[0] * c[0] + o[1] * c[1] + o[2] * c[2]) / (cc * cc)) * x))) : norm(o);
        if (seen >= 0.25 * stand) continue;
        const { face, bary } = points[i];
        const v = indices[3 * face + bary.indexOf(Math.max(...bary))];
        tips.set(v, Math.max(tips.get(v) ?? 0, stand));
      }
    }
    // The largest spikes first, each kept where it shortens the contour.
    let changed = false;
    for (const [v] of [...tips].sort((p, q) => q[1] - p[1] || p[0] - q[0])) {
      if (tries >= FAIR_TRIES) break;
      const side = around[v].filter((w) => values[w] > 0 === values[v] > 0);
      const largest = side.reduce((best, w) => (Math.abs(values[w]) > Math.abs(best) ? values[w] : best), 0);
      if (!(Math.abs(largest) > Math.abs(values[v]))) continue;
      tries++;
      const kept = values[v];
      values[v] = largest;
      const traced = zeroLoops(mesh, values);
      const tracedLength = totalLength(traced);
      if (tracedLength < length) (loops = traced), (length = tracedLength), (changed = true);
      else values[v] = kept;
    }
    if (!changed) break;
  }
  return loops;
}

const totalLength = (loops) => loops.reduce((sum, loop) => sum + loopLength(loop), 0);

// A vertex whose normal is within this of square to the view (n · towards, about 3 degrees) lies on a part seen
// edge-on: a letter's or a box's side wall, a flat sole seen from the side.
const EDGE_ON = 0.05;

// Where the surface is seen edge-on its facing is zero up to round-off, and the contour would run wherever that
// round-off put it: along a letter's front edge rather than round the middle of its side wall, back and forth across
// a flat sole. There the field is interpolated from around (harmonic, uniform weights; conjugate gradients), so the
// contour runs midway between the parts that face the viewer and those that face away, as a foil letter's seal
// does. An edge-on vertex between a part that faces the viewer and one that faces away (a pillow's rim, a star's
// tip) keeps its value: the contour passes through it. The same rule as seams/outline.cpp's fillEdgeOn.
function fillEdgeOn(around, facing) {
  const edgeOn = (v) => Math.abs(facing[v]) < EDGE_ON;
  const unknown = [];
  const slot = new Int32Array(facing.length).fill(-1);
  for (let v = 0; v < facing.length; v++) {
    if (!edgeOn(v)) continue;
    const sides = around[v].filter((w) => !edgeOn(w)).map((w) => facing[w] > 0);
    if (!(sides.includes(true) && sides.includes(false))) (slot[v] = unknown.length), unknown.push(v);
  }
  const n = unknown.length;
  if (n === 0) return;
  // L x = b over the unknowns: each row its ring's count (plus a hair, for a part edge-on all over) against its
  // unknown neighbours, the known ones' values on the right.
  const rings = unknown.map((v) => [...new Set(around[v])]);
  const diagonal = Float64Array.from(rings, (ring) => ring.length + 1e-9);
  const b = new Float64Array(n);
  rings.forEach((ring, i) => { for (const w of ring) if (slot[w] < 0) b[i] += facing[w]; });
  const apply = (x, out) => {
    for (let i = 0; i < n; i++) {
      let sum = diagonal[i] * x[i];
      for (const w of rings[i]) if (slot[w] >= 0) sum -= x[slot[w]];
      out[i] = sum;
    }
  };
  // Jacobi-preconditioned conjugate gradients from zero, to a residual of 1e-10 of the right side.
  const x = new Float64Array(n), r = Float64Array.from(b), z = new Float64Array(n), p = new Float64Array(n), q = new Float64Array(n);
  for (let i = 0; i < n; i++) (z[i] = r[i] / diagonal[i]), (p[i] = z[i]);
  let rz = r.reduce((s, ri, i) => s + ri * z[i], 0);
  const stop = 1e-20 * b.reduce((s, bi) => s + bi * bi, 0);
  for (let k = 0; k < 10 * n && r.reduce((s, ri) => s + ri * ri, 0) > stop; k++) {
    apply(p, q);
    const alpha = rz / p.reduce((s, pi, i) => s + pi * q[i], 0);
    for (let i = 0; i < n; i++) (x[i] += alpha * p[i]), (r[i] -= alpha * q[i]), (z[i] = r[i] / diagonal[i]);
    const next = r.reduce((s, ri, i) => s + ri * z[i], 0);
    for (let i = 0; i < n; i++) p[i] = z[i] + (next / rz) * p[i];
    rz = next;
  }
  if (!x.every(Number.isFinite)) return;
  unknown.forEach((v, i) => { facing[v] = Math.abs(x[i]) < AWAY_FROM_ZERO ? Math.sign(x[i] || 1) * AWAY_FROM_ZERO : x[i]; });
}

// Changes the sign of a field given at the vertices (values, changed in place) where needed so that its positive
// and its negative side are each one edge-connected piece and no vertex pinches a side: its zero set is then one
// loop on a shape without handles. Parts of a side that are not its largest change sides, the positive side's
// first. Returns { movedParts: [the areas of the parts that went to negative, to positive], area: [positive,
// negative] as they were }, or null when a side is empty.
// neighbours: vertexNeighbours, where the caller has them already.
export function splitInTwo(mesh, values, neighbours = vertexNeighbours(mesh.indices, mesh.positions.length / 3)) {
  const { positions, indices } = mesh;
  const nv = positions.length / 3;
  const area = vertexAreas(mesh);
  const sideArea = (positive) => area.reduce((s, a, v) => (values[v] > 0 === positive ? s + a : s), 0);
  const before = [sideArea(true), sideArea(false)];
  const movedParts = [[], []];
  // Keeps only the largest edge-connected part of a side: the others change sides. False when the side is empty.
  const keepLargest = (front) => {
    const part = new Int32Array(nv).fill(-1);
    const sizes = [];
    for (let s = 0; s < nv; s++) {
      if (part[s] >= 0 || values[s] > 0 !== front) continue;
      const id = sizes.length;
      let size = 0;
      const stack = [s];
      part[s] = id;
      while (stack.length) {
        const v = stack.pop();
        size += area[v];
        for (const w of neighbours[v])
          if (part[w] < 0 && values[w] > 0 === front) (part[w] = id), stack.push(w);
      }
      sizes.push(size);
    }
    if (!sizes.length) return false;
    const largest = sizes.indexOf(Math.max(...sizes));
    for (const [id, size] of sizes.entries()) if (id !== largest) movedParts[front ? 0 : 1].push(size);
    for (let v = 0; v < nv; v++)
      if (part[v] >= 0 && part[v] !== largest) values[v] = front ? -Math.max(values[v], 1e-6) : Math.max(-values[v], 1e-6);
    return true;
  };
  // A vertex whose ring of neighbours changes side more than twice pinches its side there: the zero set would
  // pass it twice, as two loops touching. It goes to the other side, which joins across it; the parts of its
  // own side it held together are sorted again by keepLargest.
  const pinches = () => {
    const changes = new Int32Array(nv);
    for (let f = 0; f < indices.length / 3; f++)
      for (let k = 0; k < 3; k++) {
        const a = indices[3 * f + ((k + 1) % 3)];
        const b = indices[3 * f + ((k + 2) % 3)];
        if (values[a] > 0 !== values[b] > 0) changes[indices[3 * f + k]]++;
      }
    let flipped = 0;
    for (let v = 0; v < nv; v++) if (changes[v] > 2) (values[v] = values[v] > 0 ? -1e-6 : 1e-6), flipped++;
    return flipped;
  };
  for (let round = 0; round < 20; round++) {
    if (!keepLargest(true) || !keepLargest(false)) return null;
    if (!pinches()) break;
  }
  return { movedParts, area: before };
}

// A third of the area of the triangles around each vertex.
export function vertexAreas({ positions, indices }) {
  const area = new Float64Array(positions.length / 3);
  for (let f = 0; f < indices.length / 3; f++) {
    const twice = Math.hypot(...faceNormal(positions, indices, f));
    for (let i = 0; i < 3; i++) area[indices[3 * f + i]] += twice / 6;
  }
  return area;
}

// Per vertex, the vertices it shares an edge with (twice over for interior edges: each face lists them).
export function vertexNeighbours(indices, nv) {
  const neighbours = Array.from({ length: nv }, () => []);
  for (let f = 0; f < indices.length / 3; f++)
    for (let k = 0; k < 3; k++) {
      const a = indices[3 * f + k];
      const b = indices[3 * f + ((k + 1) % 3)];
      neighbours[a].push(b);
      neighbours[b].push(a);
    }
  return neighbours;
}
