// The grid a link's mesh positions are quantized on (mesh-link.js): whole steps from the low corner of the
// box, the step a fraction of the mean edge length.
//
// The grid step is 1/64 of the mean edge: a vertex moves by at most sqrt(3)/2 step, 1.4 % of a mean edge.
// That is below what a design resolves: a 0.6 m balloon of a 16k-triangle mesh has 7 mm edges, so its
// vertices move by at most 0.1 mm where seams are drawn and cut to about a millimetre; and the solver's
// distance to the target (0.3 % of the diagonal at best) is 4 steps on the coarse sphere and 20 or more on
// the 12k-16k meshes, while the grid's error is 0.29 step RMS (uniform), lost in that figure's decimals.
// The grid follows the edges, not the box: a long thin shape is quantized as finely as a round one of the
// same detail. A mesh whose thin triangles would turn by more than 45 degrees gets a finer grid (MAX_TURN).
export const QUANT_BITS = 6;
const MAX_QUANT_BITS = 16;
const MAX_TURN = Math.cos(Math.PI / 4); // cosine of the largest turn of a triangle's normal

// The grid: its origin (the box's low corner) and step, both as float32 so the decoder sees the same.
export function gridOf(positions, indices, bits = QUANT_BITS) {
  const lo = [Infinity, Infinity, Infinity];
  for (const v of indices) for (let a = 0; a < 3; a++) lo[a] = Math.min(lo[a], positions[3 * v + a]);
  let sum = 0;
  for (let f = 0; f < indices.length; f += 3)
    for (let c = 0; c < 3; c++) {
      const u = 3 * indices[f + c];
      const v = 3 * indices[f + ((c + 1) % 3)];
      sum += Math.hypot(positions[u] - positions[v], positions[u + 1] - positions[v + 1], positions[u + 2] - positions[v + 2]);
    }
  const step = Math.fround(sum / indices.length / 2 ** bits);
  if (!(step > 0 && Number.isFinite(step) && lo.every(Number.isFinite))) throw new Error('no size');
  return { lo: lo.map(Math.fround), step };
}

export const quantize = (positions, { lo, step }) => Float64Array.from(positions, (x, i) => Math.round((x - lo[i % 3]) / step));

// Face f's normal, as long as twice its area: (b - a) x (c - a), each edge scaled by `scale` (grid steps to length).
export function faceNormal(p, indices, f, scale = 1) {
  const [a, b, c] = [0, 1, 2].map((k) => 3 * indices[3 * f + k]);
  const u = [0, 1, 2].map((i) => (p[b + i] - p[a + i]) * scale);
  const v = [0, 1, 2].map((i) => (p[c + i] - p[a + i]) * scale);
  return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
}

// True when every triangle on the grid (quantized positions q) faces about the way it did.
function keepsTriangles(positions, indices, q, step) {
  for (let f = 0; f < indices.length / 3; f++) {
    const n = faceNormal(positions, indices, f);
    const m = faceNormal(q, indices, f, step);
    const dot = n[0] * m[0] + n[1] * m[1] + n[2] * m[2];
    const size = Math.hypot(...n);
    if (size > 0 && !(dot > MAX_TURN * size * Math.hypot(...m))) return false; // one without area has no way
  }
  return true;
}

// The quantized positions on the coarsest grid that keeps every triangle (at least 1/2^QUANT_BITS).
export function gridFor(positions, indices) {
  for (let bits = QUANT_BITS; ; bits++) {
    const grid = gridOf(positions, indices, bits);
    const q = quantize(positions, grid);
    if (bits >= MAX_QUANT_BITS || keepsTriangles(positions, indices, q, grid.step)) return { grid, q };
  }
}
