// Which of the target's own axes points up (the design's target.up, docs/formats.md): mesh files carry no
// reliable up, and a Z-up file (CAD, 3D printing) shown Y up lies on its side with Height along its length.
// The target keeps its own coordinates (seams are {face, bary} on its triangles, the solver works in them);
// the views turn it to stand on its up axis (views/up-frame.js), and every figure shown is read in that frame.

export const DEFAULT_UP = '+y';

// The choices of the toolbar's Up select, in the designer's words.
export const UP_AXES = [
  { value: '+y', label: 'Y up' },
  { value: '+z', label: 'Z up' },
  { value: '+x', label: 'X up' },
  { value: '-y', label: '−Y up' },
  { value: '-z', label: '−Z up' },
  { value: '-x', label: '−X up' },
];

export const isUpAxis = (value) => UP_AXES.some((a) => a.value === value);

export const upLabel = (up) => UP_AXES.find((a) => a.value === up)?.label ?? up;
const axisName = (up) => up.slice(1).toUpperCase();

// The design's up axis ('+y' when it names none).
export const upOf = (design) => design?.target?.up ?? DEFAULT_UP;

// Parse-and-default of target.up (design.js): a valid axis is kept, anything else is dropped with a warning.
export function parseUp(target, warnings) {
  if (target.up === undefined || isUpAxis(target.up)) return target;
  warnings.push(`The design's up axis ${JSON.stringify(target.up)} is not one of +y, -y, +z, -z, +x, -x; the target stands Y up instead.`);
  const { up, ...rest } = target;
  return rest;
}

// The rotation from the target's own coordinates to the up frame (x right, y up, z towards the viewer), as
// its rows: up-frame coordinate i is UP_FRAMES[up][i] · p. Proper rotations, so the target is not mirrored;
// '+z' undoes the usual Y-up to Z-up conversion (x, y, z) -> (x, -z, y) exactly.
export const UP_FRAMES = {
  '+y': [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
  '-y': [[1, 0, 0], [0, -1, 0], [0, 0, -1]],
  '+z': [[1, 0, 0], [0, 0, 1], [0, -1, 0]],
  '-z': [[1, 0, 0], [0, 0, -1], [0, 1, 0]],
  '+x': [[0, -1, 0], [1, 0, 0], [0, 0, 1]],
  '-x': [[0, 1, 0], [-1, 0, 0], [0, 0, 1]],
};

// The target's own axis (0 x, 1 y, 2 z) that is up-frame axis `i` (0 width, 1 height, 2 depth).
const ownAxis = (up, i) => UP_FRAMES[up][i].findIndex((c) => c !== 0);

// The target's size in its own units as width × height × depth in the up frame, from the validation stats'
// bounding box.
export function upFrameSize(stats, up = DEFAULT_UP) {
  const frame = UP_FRAMES[up] ? up : DEFAULT_UP;
  return [0, 1, 2].map((i) => {
    const k = ownAxis(frame, i);
    return stats.bbox_max[k] - stats.bbox_min[k];
  });
}

// Meters per target unit: the design's height over the target's extent along its up axis. The C++ reader's
// designScale (wasm/src/io/design_json.cpp) has the same rule.
export function heightScale(design, stats) {
  if (!stats) return 1;
  const height = upFrameSize(stats, upOf(design))[1];
  return height > 0 ? design.size.height / height : 1;
}

// --- The guess when a mesh is opened --------------------------------------------------------------------
// Files are Y up (graphics tools, Billow's examples) or Z up (CAD, 3D printing); nothing in OBJ, STL or PLY
// says which. A standing shape stands on its bottom: the centroid of its surface (an inflatable's mass is its
// skin) lies inside the footprint of what touches the floor. The guess is Z up only when the shape cannot
// stand on its Y bottom and can on its Z bottom; otherwise (both, neither) the file's Y stays up.

const FLOOR_BAND = 0.02; // a vertex touches the floor when this close to it, as a share of the shape's extent
const STANDS = 0.005; // the centroid must lie this far inside the footprint, as a share of the box diagonal

// The convex hull of 2D points ([u, v] pairs), counter-clockwise (Andrew's monotone chain).
function convexHull(points) {
  const p = points.slice().sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  if (p.length < 3) return p;
  const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const chain = (list) => {
    const out = [];
    for (const q of list) {
      while (out.length >= 2 && cross(out[out.length - 2], out[out.length - 1], q) <= 0) out.pop();
      out.push(q);
    }
    out.pop();
    return out;
  };
  return [...chain(p), ...chain(p.reverse())];
}

// Signed distance from c to the boundary of a counter-clockwise convex polygon: positive inside.
function depthInside(hull, c) {
  if (hull.length < 3) return -Infinity;
  let depth = Infinity;
  for (let i = 0; i < hull.length; i++) {
    const a = hull[i];
    const b = hull[(i + 1) % hull.length];
    const ex = b[0] - a[0];
    const ey = b[1] - a[1];
    depth = Math.min(depth, (ex * (c[1] - a[1]) - ey * (c[0] - a[0])) / Math.hypot(ex, ey));
  }
  return depth;
}

// How firmly the shape stands with its own axis `axis` (1 y, 2 z) pointing up: how deep its surface centroid
// lies inside its footprint, over the box diagonal (negative: it tips over).
function standing(positions, lo, hi, centroid, axis) {
  const [u, v] = [0, 1, 2].filter((k) => k !== axis);
  const floor = lo[axis] + FLOOR_BAND * (hi[axis] - lo[axis]);
  const touching = [];
  for (let i = 0; i < positions.length; i += 3) if (positions[i + axis] <= floor) touching.push([positions[i + u], positions[i + v]]);
  const diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  return depthInside(convexHull(touching), [centroid[u], centroid[v]]) / diagonal;
}

// mesh: { positions (#V*3), indices (#F*3) } in the file's own units. Returns { up: '+y' | '+z', standsY,
// standsZ } (how firmly it stands each way, as in `standing`).
export function guessUp({ positions, indices }) {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3)
    for (let k = 0; k < 3; k++) {
      lo[k] = Math.min(lo[k], positions[i + k]);
      hi[k] = Math.max(hi[k], positions[i + k]);
    }
  const centroid = [0, 0, 0];
  let area = 0;
  const p = positions;
  for (let f = 0; f < indices.length; f += 3) {
    const a = 3 * indices[f];
    const b = 3 * indices[f + 1];
    const c = 3 * indices[f + 2];
    const ex = p[b] - p[a], ey = p[b + 1] - p[a + 1], ez = p[b + 2] - p[a + 2];
    const gx = p[c] - p[a], gy = p[c + 1] - p[a + 1], gz = p[c + 2] - p[a + 2];
    const w = 0.5 * Math.hypot(ey * gz - ez * gy, ez * gx - ex * gz, ex * gy - ey * gx);
    area += w;
    for (let k = 0; k < 3; k++) centroid[k] += (w * (p[a + k] + p[b + k] + p[c + k])) / 3;
  }
  if (!(area > 0)) return { up: DEFAULT_UP, standsY: 0, standsZ: 0 };
  for (let k = 0; k < 3; k++) centroid[k] /= area;
  const standsY = standing(positions, lo, hi, centroid, 1);
  const standsZ = standing(positions, lo, hi, centroid, 2);
  return { up: standsY <= STANDS && standsZ > STANDS ? '+z' : DEFAULT_UP, standsY, standsZ };
}

// A newly opened mesh file's design with the guessed up axis, and the notice that says so (null when the
// file's Y stays up). design: the new design for the file; mesh: { positions, indices } as loaded.
export function withGuessedUp(design, mesh, fileName) {
  const { up } = guessUp(mesh);
  if (up === upOf(design)) return { design, notice: null };
  return {
    design: { ...design, target: { ...design.target, up } },
    notice: `"${fileName}" looks made ${upLabel(up)}, as files from CAD and 3D printing often are: it stands on its ${axisName(up)} bottom and would tip over on its Y bottom. Billow shows it ${upLabel(up)} and measures Height along ${axisName(up)}. If it stands wrong, choose another axis in Up, next to Height.`,
  };
}
