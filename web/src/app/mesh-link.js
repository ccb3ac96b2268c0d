// The target mesh in a share link (&mesh=..., before deflate and base64url; see docs/formats.md).
//
// Version 2: the triangles in the order a region-growing traversal meets them (mesh-frontier.js), so the
// connectivity costs an operation byte per triangle, mostly "new vertex" or "next to the gate", which
// deflate packs to under two bits; each new vertex is predicted by completing the parallelogram of the
// triangle across the gate, and only the difference is sent, quantized on a grid of 1/64 of the mean
// edge length (mesh-grid.js). The triangles and their corners come out renumbered: packMesh says how, and
// the link carries a design whose seam points are renumbered to match (renumberDesign).
// Version 1 (mesh-link-v1.js) is still read, and written for a mesh that is not a closed surface.
import { ByteWriter, ByteReader } from './link-bytes.js';
import { Frontier } from './mesh-frontier.js';
import { writeIndexed, readIndexed } from './mesh-link-v1.js';
import { gridOf, gridFor, quantize } from './mesh-grid.js';

const MAGIC = [0x42, 0x4d]; // "BM"
const VERSION_INDEXED = 1;
const VERSION_TRAVERSED = 2;
const MAX_LINK_VERTICES = 1 << 20;
const WALK_BUDGET = 1e8; // steps along the frontier; real meshes take far fewer, a hostile link is stopped
const Op = { grow: 0, next: 1, previous: 2, split: 3, merge: 4 };

// The seam points of a design moved to the renumbered triangles: face f becomes face[f], and its corners
// turn by turn[f] (new corner t is old corner t + turn), so the barycentric coordinates turn with them.
export function renumberDesign(design, { face, turn }) {
  const move = (p) => {
    if (p === null || typeof p !== 'object' || !Number.isInteger(p.face) || p.face < 0 || p.face >= face.length) return p;
    const t = turn[p.face];
    const bary = Array.isArray(p.bary) && p.bary.length === 3 ? [0, 1, 2].map((i) => p.bary[(i + t) % 3]) : p.bary;
    return { ...p, face: face[p.face], bary };
  };
  const seams = Array.isArray(design.seams)
    ? design.seams.map((s) => (s && Array.isArray(s.points) ? { ...s, points: s.points.map(move) } : s))
    : design.seams;
  return { ...design, seams };
}

// Throws when the mesh is not a closed, oriented, edge-manifold surface (the caller falls back to v1).
function traverse(indices, nv, q) {
  const nt = indices.length / 3;
  const halfEdge = new Map(); // directed edge -> 3 * face + corner it leaves from
  const key = (a, b) => a * nv + b;
  for (let h = 0; h < indices.length; h++) {
    const a = indices[h];
    const b = indices[h - (h % 3) + ((h + 1) % 3)];
    if (a === b || halfEdge.has(key(a, b))) throw new Error('not manifold');
    halfEdge.set(key(a, b), h);
  }
  for (const k of halfEdge.keys()) if (!halfEdge.has(key(k % nv, Math.floor(k / nv)))) throw new Error('open');
  const visited = new Uint8Array(nt);
  const number = new Int32Array(nv).fill(-1);
  let vertices = 0;
  let faces = 0;
  const renumbering = { face: new Int32Array(nt), turn: new Uint8Array(nt) };
  const ops = new ByteWriter();
  const joins = new ByteWriter();
  const residuals = new ByteWriter();
  const frontier = new Frontier(3 * nt + 3);
  const nodeOf = new Map(); // directed edge -> frontier node
  const remember = (count) => {
    for (let n = frontier.count - count; n < frontier.count; n++) nodeOf.set(key(frontier.from[n], frontier.to[n]), n);
  };
  const visit = (f, turn) => {
    visited[f] = 1;
    renumbering.face[f] = faces++;
    renumbering.turn[f] = turn;
  };
  const put = (v, predicted) => {
    for (let a = 0; a < 3; a++) residuals.varint(q[3 * v + a] - predicted[a]);
  };
  const coords = (v) => [q[3 * v], q[3 * v + 1], q[3 * v + 2]];
  // The frontier node ending at c next to the new triangle t: turn around c from t's edge (c -> b) across
  // unvisited triangles until a visited one; the edge into c there is on the frontier.
  const nodeInto = (c, b) => {
    for (let x = b, steps = 0; steps <= nt; steps++) {
      const h = halfEdge.get(key(x, c));
      if (visited[Math.floor(h / 3)]) return nodeOf.get(key(x, c));
      x = indices[h - (h % 3) + ((h + 2) % 3)];
    }
    throw new Error('vertex not on the frontier');
  };
  for (let seed = 0; seed < nt; seed++) {
    if (visited[seed]) continue;
    const corners = [0, 1, 2].map((c) => indices[3 * seed + c]);
    if (corners.some((v) => number[v] >= 0)) throw new Error('components share a vertex');
    visit(seed, 0);
    corners.forEach((v, i) => {
      number[v] = vertices++;
      put(v, i === 0 ? [0, 0, 0] : coords(corners[i - 1]));
    });
    frontier.seed(...corners);
    remember(3);
    while (frontier.loop) {
      const g = frontier.loop.gate;
      const a = frontier.from[g];
      const b = frontier.to[g];
      const h = halfEdge.get(key(b, a));
      const t = Math.floor(h / 3);
      const c = indices[h - (h % 3) + ((h + 2) % 3)];
      visit(t, h % 3); // its corners b, a, c are the triangle's own from corner h % 3 on
      if (number[c] < 0) {
        ops.byte(Op.grow);
        number[c] = vertices++;
        const d = frontier.opposite[g];
        put(c, [0, 1, 2].map((i) => q[3 * a + i] + q[3 * b + i] - q[3 * d + i]));
        frontier.grow(c);
      } else {
        joinAt(frontier, nodeInto(c, b), ops, joins);
      }
      remember(2);
      if (frontier.walked > WALK_BUDGET) throw new Error('too complex');
    }
  }
  const order = new Int32Array(vertices);
  number.forEach((n, v) => n >= 0 && (order[n] = v));
  return { ops: ops.result(), joins: joins.result(), residuals: residuals.result(), order, renumbering };
}

// Writes how the frontier node m, where the gate's triangle has its tip, is found, and joins there.
function joinAt(frontier, m, ops, joins) {
  const { gate, length } = frontier.loop;
  if (frontier.next[gate] === m) {
    ops.byte(Op.next);
    return frontier.join(m, 1, -1);
  }
  if (frontier.prev[frontier.prev[gate]] === m) {
    ops.byte(Op.previous);
    return frontier.join(m, length - 2, -1);
  }
  for (let i = 2, ahead = frontier.next[gate], back = frontier.prev[gate]; 2 * i <= length + 1; i++) {
    ahead = frontier.next[ahead];
    back = frontier.prev[back];
    frontier.walked += 2;
    const k = ahead === m ? i : back === m ? length - i : 0;
    if (!k) continue;
    ops.byte(Op.split);
    joins.varint(Frontier.shorter(k, length));
    return frontier.join(m, k, -1);
  }
  for (let depth = 0; depth < frontier.waiting.length; depth++) {
    const loop = frontier.waiting[frontier.waiting.length - 1 - depth];
    for (let k = 0, n = loop.gate; k < loop.length; k++, n = frontier.next[n]) {
      frontier.walked += 1;
      if (n !== m) continue;
      ops.byte(Op.merge);
      joins.varint(depth);
      joins.varint(Frontier.shorter(k, loop.length));
      return frontier.join(m, 0, depth);
    }
  }
  throw new Error('node not on the frontier');
}

function packTraversed({ positions, indices }) {
  const nv = positions.length / 3;
  const { grid, q } = gridFor(positions, indices);
  const { ops, joins, residuals, order, renumbering } = traverse(indices, nv, q);
  const out = new ByteWriter();
  for (const b of MAGIC) out.byte(b);
  out.byte(VERSION_TRAVERSED);
  out.varint(order.length);
  out.varint(indices.length / 3);
  for (const x of grid.lo) out.float32(x);
  out.float32(grid.step);
  for (const stream of [ops, joins, residuals]) {
    out.varint(stream.length);
    out.append(stream);
  }
  return { bytes: out.result(), renumbering, order, step: grid.step };
}

function unpackTraversed(input) {
  const nv = input.varint();
  const nt = input.varint();
  if (!(nv >= 3 && nv <= MAX_LINK_VERTICES && nt >= 1 && nt <= 2 * MAX_LINK_VERTICES)) throw new Error('bad counts');
  const lo = [input.float32(), input.float32(), input.float32()];
  const step = input.float32();
  if (!(lo.every(Number.isFinite) && step > 0 && Number.isFinite(step))) throw new Error('bad grid');
  const ops = input.sub(input.varint());
  const joins = input.sub(input.varint());
  const residuals = input.sub(input.varint());
  if (!input.done) throw new Error('trailing bytes');
  if (ops.bytes.length >= nt || 3 * (nt - ops.bytes.length) > nv) throw new Error('bad counts');
  const q = new Float64Array(3 * nv);
  const indices = new Uint32Array(3 * nt);
  const frontier = new Frontier(3 * nt + 3);
  let vertices = 0;
  const vertex = (predicted) => {
    if (vertices >= nv) throw new Error('too many vertices');
    for (let a = 0; a < 3; a++) q[3 * vertices + a] = predicted[a] + residuals.varint();
    return vertices++;
  };
  const coords = (v) => [q[3 * v], q[3 * v + 1], q[3 * v + 2]];
  for (let f = 0; f < nt; f++) {
    let corners;
    if (!frontier.loop) {
      const a = vertex([0, 0, 0]);
      const b = vertex(coords(a));
      corners = [a, b, vertex(coords(b))];
      frontier.seed(...corners);
    } else {
      corners = nextTriangle(frontier, ops.byte(), joins, (a, b, d) =>
        vertex([0, 1, 2].map((i) => q[3 * a + i] + q[3 * b + i] - q[3 * d + i])),
      );
    }
    indices.set(corners, 3 * f);
    if (frontier.walked > WALK_BUDGET) throw new Error('too complex');
  }
  if (frontier.loop || vertices !== nv || !ops.done || !joins.done || !residuals.done) throw new Error('bad mesh');
  const positions = new Float32Array(3 * nv);
  for (let i = 0; i < positions.length; i++) positions[i] = lo[i % 3] + q[i] * step;
  if (!positions.every(Number.isFinite)) throw new Error('bad position');
  return { positions, indices };
}

// The triangle across the gate for one operation: [b, a, c] (the gate is a -> b, c its tip).
function nextTriangle(frontier, op, joins, newVertex) {
  const { gate, length } = frontier.loop;
  const a = frontier.from[gate];
  const b = frontier.to[gate];
  if (op === Op.grow) {
    const c = newVertex(a, b, frontier.opposite[gate]);
    frontier.grow(c);
    return [b, a, c];
  }
  let m;
  if (op === Op.merge) {
    const depth = joins.varint();
    const loop = frontier.waiting[frontier.waiting.length - 1 - depth];
    const k = joins.varint();
    if (!loop || !(Math.abs(k) < loop.length)) throw new Error('bad join');
    m = frontier.walk(loop.gate, k);
    frontier.join(m, 0, depth);
  } else {
    let s;
    if (op === Op.next) s = 1;
    else if (op === Op.previous) s = -2;
    else if (op === Op.split) s = joins.varint();
    else throw new Error('bad operation');
    const k = s > 0 ? s : s + length;
    if (!(k >= 1 && k <= length - 2)) throw new Error('bad join');
    m = frontier.walk(gate, s); // the shorter way round
    frontier.join(m, k, -1);
  }
  const c = frontier.to[m];
  if (c === a || c === b) throw new Error('bad join');
  return [b, a, c];
}

// A target mesh ({ positions, indices }) as bytes for a link: { bytes, renumbering } where renumbering
// ({ face, turn }, see renumberDesign) says where each triangle went, or is null when the order is kept
// (version 1, for a mesh that is not a closed surface). Also the vertex order (new -> old) and grid step.
export function packMesh(mesh) {
  try {
    return packTraversed(mesh);
  } catch {
    const out = new ByteWriter();
    for (const b of MAGIC) out.byte(b);
    out.byte(VERSION_INDEXED);
    writeIndexed(out, mesh);
    return { bytes: out.result(), renumbering: null, order: null, step: null };
  }
}

// The inverse of packMesh, either version; throws Error('...') on anything malformed (the caller words
// the message).
export function unpackMesh(bytes) {
  const input = new ByteReader(bytes);
  for (const b of MAGIC) if (input.byte() !== b) throw new Error('not a mesh');
  const version = input.byte();
  if (version === VERSION_INDEXED) return readIndexed(input);
  if (version === VERSION_TRAVERSED) return unpackTraversed(input);
  throw new Error('not a mesh');
}

// What identifies the designer's mesh when it stays out of a link: counts and a hash of its triangles and
// of its positions on the link's grid (a file read the same way gives the same numbers).
export function meshFingerprint({ positions, indices }) {
  let grid = { lo: [0, 0, 0], step: 1 };
  try {
    grid = gridOf(positions, indices);
  } catch {
    // a mesh without size: its positions as they are
  }
  const q = quantize(positions, grid);
  let hash = 0x811c9dc5; // FNV-1a, 32 bits
  const mix = (x) => {
    for (let k = 0; k < 4; k++) {
      hash ^= (x >>> (8 * k)) & 0xff;
      hash = Math.imul(hash, 0x01000193);
    }
  };
  for (const x of q) mix(x | 0);
  for (const i of indices) mix(i);
  return { triangles: indices.length / 3, vertices: positions.length / 3, hash: (hash >>> 0).toString(16).padStart(8, '0') };
}
