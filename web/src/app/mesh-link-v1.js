// The target mesh in a share link, version 1 (docs/formats.md): every position quantized to 16 bits of the
// bounding box and every vertex index, as zigzag varints of their differences to the previous ones, in the
// mesh's own order. Links made before version 2 carry it; mesh-link.js still writes it for a mesh that is
// not a closed surface, which the version-2 traversal cannot walk.
const QUANT = 65535;
const MAX_LINK_VERTICES = 1 << 20;

// Writes the mesh after the header's version byte.
export function writeIndexed(out, { positions, indices }) {
  const nv = positions.length / 3;
  out.varint(nv);
  out.varint(indices.length / 3);
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i++) {
    lo[i % 3] = Math.min(lo[i % 3], positions[i]);
    hi[i % 3] = Math.max(hi[i % 3], positions[i]);
  }
  const box = [...lo.map(Math.fround), ...hi.map(Math.fround)];
  for (const x of box) out.float32(x);
  const previous = [0, 0, 0];
  for (let i = 0; i < positions.length; i++) {
    const a = i % 3;
    const span = box[a + 3] - box[a];
    const q = span > 0 ? Math.min(QUANT, Math.max(0, Math.round(((positions[i] - box[a]) / span) * QUANT))) : 0;
    out.varint(q - previous[a]);
    previous[a] = q;
  }
  let last = 0;
  for (let i = 0; i < indices.length; i++) {
    out.varint(indices[i] - last);
    last = indices[i];
  }
}

// Reads the mesh after the header's version byte; throws Error('...') on anything malformed.
export function readIndexed(input) {
  const nv = input.varint();
  const nt = input.varint();
  if (!(nv >= 3 && nv <= MAX_LINK_VERTICES && nt >= 1 && nt <= 2 * MAX_LINK_VERTICES)) throw new Error('bad counts');
  const box = Array.from({ length: 6 }, () => input.float32());
  if (!box.every(Number.isFinite)) throw new Error('bad box');
  const positions = new Float32Array(nv * 3);
  const q = [0, 0, 0];
  for (let i = 0; i < positions.length; i++) {
    const a = i % 3;
    q[a] += input.varint();
    if (q[a] < 0 || q[a] > QUANT) throw new Error('bad position');
    positions[i] = box[a] + ((box[a + 3] - box[a]) * q[a]) / QUANT;
  }
  const indices = new Uint32Array(nt * 3);
  let last = 0;
  for (let i = 0; i < indices.length; i++) {
    last += input.varint();
    if (last < 0 || last >= nv) throw new Error('bad index');
    indices[i] = last;
  }
  if (!input.done) throw new Error('trailing bytes');
  return { positions, indices };
}
