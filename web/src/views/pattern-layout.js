// Pattern geometry for display: panels laid out side by side (no overlap), boundary edges, and which
// boundary edges are sewn to which panel, so both sides of a seam get the same color.

import { segmentDistance } from '../app/geometry.js';

// pattern: { panels: [{ name, vertices: [[x,y]], triangles: [[i,j,k]] }], stitches: [[pa, va, pb, vb]] }
// Returns per panel { offset: [dx, dy], boundary: [[a, b, partnerPanel | -1]], center: [x, y] (of its
// bounding box, in its frame), centroid: [x, y] (the same, laid out) }.
export function layoutPattern(pattern, gapRatio = 0.08) {
  const partners = stitchPartners(pattern);
  const boxes = pattern.panels.map((p) => bounds(p.vertices));
  const largest = Math.max(...boxes.map((b) => Math.max(b.w, b.h)), 1e-9);
  const gap = gapRatio * largest;
  const totalWidth = boxes.reduce((s, b) => s + b.w + gap, -gap);
  const rowWidth = Math.max(largest, Math.sqrt(totalWidth * largest) * 1.2); // a roughly square sheet
  let x = 0;
  let y = 0;
  let rowHeight = 0;
  return pattern.panels.map((panel, i) => {
    const b = boxes[i];
    if (x > 0 && x + b.w > rowWidth) {
      x = 0;
      y -= rowHeight + gap;
      rowHeight = 0;
    }
    const offset = [x - b.minX, y - b.maxY];
    x += b.w + gap;
    rowHeight = Math.max(rowHeight, b.h);
    const boundary = boundaryEdges(panel.triangles).map(([a, c]) => [a, c, sharedPartner(partners, i, a, c)]);
    const center = [(b.minX + b.maxX) / 2, (b.minY + b.maxY) / 2];
    return { offset, boundary, center, centroid: [offset[0] + center[0], offset[1] + center[1]] };
  });
}

function bounds(vertices) {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (const [x, y] of vertices) {
    minX = Math.min(minX, x); maxX = Math.max(maxX, x);
    minY = Math.min(minY, y); maxY = Math.max(maxY, y);
  }
  return { minX, minY, maxX, maxY, w: maxX - minX, h: maxY - minY };
}

// The share of the outer panels' outlines that lie within `within` mean triangle edges of another part of their own
// panel's outline (across a leg, a tail, a narrow strip, a sharp tip), where the mesh is only a triangle or so across:
// what a fresh meshing of the outline (the cut panels) may inflate differently. The other part is one farther along
// the outline than 2.5 times its distance, so a vertex's own neighbours and a blunt turn do not count.
export function narrowOutlineShare(pattern, within = 1.5) {
  const outer = pattern.panels.filter((p) => !p.internal);
  let edgeSum = 0;
  let edgeCount = 0;
  for (const { vertices: V, triangles } of outer)
    for (const t of triangles)
      for (let e = 0; e < 3; e++) {
        const [a, b] = [V[t[e]], V[t[(e + 1) % 3]]];
        edgeSum += Math.hypot(b[0] - a[0], b[1] - a[1]);
        edgeCount++;
      }
  if (!edgeCount) return 0;
  const reach = (within * edgeSum) / edgeCount;
  let narrow = 0;
  let total = 0;
  for (const { vertices: V, triangles } of outer) {
    const next = new Map(boundaryEdges(triangles));
    const loops = [];
    const seen = new Set();
    for (const start of next.keys()) {
      if (seen.has(start)) continue;
      const loop = [];
      for (let v = start; v !== undefined && !seen.has(v); v = next.get(v)) seen.add(v), loop.push(v);
      loops.push(loop);
    }
    const length = (a, b) => Math.hypot(V[b][0] - V[a][0], V[b][1] - V[a][1]);
    const arcs = loops.map((loop) => {
      const arc = [0];
      for (let i = 1; i <= loop.length; i++) arc.push(arc[i - 1] + length(loop[i - 1], loop[i % loop.length]));
      return arc;
    });
    loops.forEach((loop, l) => {
      const n = loop.length;
      const arc = arcs[l];
      const along = (i, x) => Math.min(Math.abs(x - arc[i]), arc[n] - Math.abs(x - arc[i]));
      // Another part of an outline within reach of vertex i: a segment of another loop, or of its own far enough along.
      const across = (i) => loops.some((other, m) => other.some((_, j) => {
        if (m === l && (j === i || (j + 1) % n === i)) return false;
        const d = segmentDistance(V[loop[i]], V[other[j]], V[other[(j + 1) % other.length]]);
        return d < reach && (m !== l || Math.min(along(i, arc[j]), along(i, arc[j + 1])) > 2.5 * d);
      }));
      for (let i = 0; i < n; i++) {
        const share = (length(loop[(i + n - 1) % n], loop[i]) + length(loop[i], loop[(i + 1) % n])) / 2;
        total += share;
        if (across(i)) narrow += share;
      }
    });
  }
  return total > 0 ? narrow / total : 0;
}

// Edges used by exactly one triangle, in the triangles' direction.
export function boundaryEdges(triangles) {
  const count = new Map();
  const key = (a, b) => (a < b ? `${a},${b}` : `${b},${a}`);
  for (const t of triangles) for (let e = 0; e < 3; e++) {
    const k = key(t[e], t[(e + 1) % 3]);
    count.set(k, (count.get(k) || 0) + 1);
  }
  const out = [];
  for (const t of triangles) for (let e = 0; e < 3; e++) {
    const a = t[e], b = t[(e + 1) % 3];
    if (count.get(key(a, b)) === 1) out.push([a, b]);
  }
  return out;
}

// "panel:vertex" -> set of partner panels it is stitched to (through chains of stitches).
function stitchPartners(pattern) {
  const parent = new Map();
  const find = (x) => {
    while (parent.has(x) && parent.get(x) !== x) x = parent.get(x);
    return x;
  };
  for (const [pa, va, pb, vb] of pattern.stitches ?? []) {
    const a = `${pa}:${va}`, b = `${pb}:${vb}`;
    if (!parent.has(a)) parent.set(a, a);
    if (!parent.has(b)) parent.set(b, b);
    parent.set(find(a), find(b));
  }
  const groups = new Map();
  for (const k of parent.keys()) {
    const root = find(k);
    if (!groups.has(root)) groups.set(root, []);
    groups.get(root).push(k);
  }
  const partners = new Map();
  for (const members of groups.values()) {
    const panels = new Set(members.map((m) => Number(m.split(':')[0])));
    for (const m of members) partners.set(m, panels);
  }
  return partners;
}

function sharedPartner(partners, panel, a, b) {
  const pa = partners.get(`${panel}:${a}`);
  const pb = partners.get(`${panel}:${b}`);
  if (!pa || !pb) return -1;
  for (const q of pa) if (q !== panel && pb.has(q)) return q;
  return -1;
}
