// Sharing a design by URL: the design document as JSON, deflated and base64url-encoded into the hash
// (#design=...). A design whose target is the designer's own mesh file carries the mesh too
// (&mesh=..., see encodeMesh: positions quantized to 16 bits of the bounding box, delta-coded, deflated).
// Reading validates everything (parseDesign, decodeMesh) and reports a designer-facing error.
import { parseDesign } from './design.js';

export const HASH_KEY = 'design';
export const MESH_KEY = 'mesh';
export const MAX_LINK_CHARS = 60000; // links longer than this are unreliable in browsers and chat apps
const MESH_MAGIC = [0x42, 0x4d, 0x01]; // "BM", version 1
const QUANT = 65535; // 16-bit positions: 1.5e-5 of the bounding box, far below any seam or cut tolerance
const MAX_LINK_VERTICES = 1 << 20;

async function pipe(bytes, stream) {
  const out = new Response(new Blob([bytes]).stream().pipeThrough(stream));
  return new Uint8Array(await out.arrayBuffer());
}

function toBase64Url(bytes) {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

function fromBase64Url(text) {
  if (!/^[A-Za-z0-9_-]*$/.test(text)) throw new Error('bad characters');
  const binary = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
  return Uint8Array.from(binary, (c) => c.charCodeAt(0));
}

// Little-endian base-128 varints of zigzag-coded signed integers: small deltas take one byte.
class ByteWriter {
  constructor() {
    this.bytes = new Uint8Array(1024);
    this.length = 0;
  }
  ensure(n) {
    if (this.length + n <= this.bytes.length) return;
    const grown = new Uint8Array(Math.max(this.bytes.length * 2, this.length + n));
    grown.set(this.bytes.subarray(0, this.length));
    this.bytes = grown;
  }
  byte(b) {
    this.ensure(1);
    this.bytes[this.length++] = b;
  }
  varint(value) {
    let v = value >= 0 ? value * 2 : -value * 2 - 1; // zigzag
    while (v >= 0x80) {
      this.byte((v % 0x80) | 0x80);
      v = Math.floor(v / 0x80);
    }
    this.byte(v);
  }
  float32(x) {
    this.ensure(4);
    new DataView(this.bytes.buffer).setFloat32(this.length, x, true);
    this.length += 4;
  }
  result() {
    return this.bytes.subarray(0, this.length);
  }
}

class ByteReader {
  constructor(bytes) {
    this.bytes = bytes;
    this.at = 0;
  }
  byte() {
    if (this.at >= this.bytes.length) throw new Error('truncated');
    return this.bytes[this.at++];
  }
  varint() {
    let v = 0;
    let scale = 1;
    for (let k = 0; k < 8; k++) {
      const b = this.byte();
      v += (b & 0x7f) * scale;
      if (b < 0x80) return v % 2 === 0 ? v / 2 : -(v + 1) / 2;
      scale *= 0x80;
    }
    throw new Error('bad number');
  }
  float32() {
    if (this.at + 4 > this.bytes.length) throw new Error('truncated');
    const x = new DataView(this.bytes.buffer, this.bytes.byteOffset).getFloat32(this.at, true);
    this.at += 4;
    return x;
  }
}

// A target mesh ({ positions, indices }) as bytes for a link. Triangle order is kept exactly: seam points
// are (face, barycentric) pairs on it.
export function packMesh({ positions, indices }) {
  const nv = positions.length / 3;
  const out = new ByteWriter();
  for (const b of MESH_MAGIC) out.byte(b);
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
  return out.result();
}

// The inverse of packMesh; throws Error('...') on anything malformed (the caller words the message).
export function unpackMesh(bytes) {
  const input = new ByteReader(bytes);
  for (const b of MESH_MAGIC) if (input.byte() !== b) throw new Error('not a mesh');
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
  if (input.at !== bytes.length) throw new Error('trailing bytes');
  return { positions, indices };
}

function tooLarge(length, what) {
  return new Error(
    `This design is too large for a link (${Math.round(length / 1000)} k characters${what}; links hold about ${MAX_LINK_CHARS / 1000} k). Save it to a file and send the file instead.`,
  );
}

// The hash fragment for a design ("design=...", and "&mesh=..." when a target mesh goes with it); throws
// a designer-facing Error when the link would be too long.
export async function encodeDesign(design, mesh = null) {
  const json = new TextEncoder().encode(JSON.stringify(design));
  let fragment = `${HASH_KEY}=${toBase64Url(await pipe(json, new CompressionStream('deflate-raw')))}`;
  if (mesh) {
    const packed = toBase64Url(await pipe(packMesh(mesh), new CompressionStream('deflate-raw')));
    fragment += `&${MESH_KEY}=${packed}`;
    if (fragment.length > MAX_LINK_CHARS) throw tooLarge(fragment.length, ', most of it the target mesh');
  }
  if (fragment.length > MAX_LINK_CHARS) throw tooLarge(fragment.length, '');
  return fragment;
}

// Reads a hash ("#design=...[&mesh=...]"): null when there is no design in it; { design, warnings, mesh }
// when there is (mesh: { positions, indices } or null); throws Error with a designer-facing message when
// the link is damaged.
export async function decodeDesign(hash) {
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  const packed = params.get(HASH_KEY);
  if (packed === null) return null;
  const packedMesh = params.get(MESH_KEY);
  if (packed.length + (packedMesh?.length ?? 0) > MAX_LINK_CHARS * 2) throw new Error('This link is too long to be a Billow design.');
  let value;
  try {
    const bytes = await pipe(fromBase64Url(packed), new DecompressionStream('deflate-raw'));
    if (bytes.length > 4 * 1024 * 1024) throw new Error('too large');
    value = JSON.parse(new TextDecoder().decode(bytes));
  } catch {
    throw new Error('This link does not contain a readable Billow design: it may have been cut short when it was copied.');
  }
  let mesh = null;
  if (packedMesh !== null) {
    try {
      const bytes = await pipe(fromBase64Url(packedMesh), new DecompressionStream('deflate-raw'));
      if (bytes.length > 64 * 1024 * 1024) throw new Error('too large');
      mesh = unpackMesh(bytes);
    } catch {
      throw new Error('The target shape in this link is damaged: it may have been cut short when it was copied.');
    }
  }
  return { ...parseDesign(value), mesh };
}
