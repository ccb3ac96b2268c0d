// Pattern geometry for display: panels laid out side by side (no overlap), boundary edges, and which
// boundary edges are sewn to which panel, so both sides of a seam get the same color.

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
