// Bytes for links: raw DEFLATE both ways, base64url, and a byte writer/reader with zigzag varints.
// Shared by the design part and the mesh part of a share link (share.js, mesh-link.js).

export async function pipe(bytes, stream) {
  const out = new Response(new Blob([bytes]).stream().pipeThrough(stream));
  return new Uint8Array(await out.arrayBuffer());
}

export const deflate = (bytes) => pipe(bytes, new CompressionStream('deflate-raw'));

// limit: the most bytes a well-formed part can inflate to; a "zip bomb" stops there with an error.
export async function inflate(bytes, limit) {
  const reader = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate-raw')).getReader();
  const chunks = [];
  let length = 0;
  try {
    for (;;) {
      const { done, value } = await reader.read();
      if (done) break;
      length += value.length;
      if (length > limit) throw new Error('too large');
      chunks.push(value);
    }
  } finally {
    reader.cancel().catch(() => {});
  }
  const out = new Uint8Array(length);
  let at = 0;
  for (const c of chunks) {
    out.set(c, at);
    at += c.length;
  }
  return out;
}

export function toBase64Url(bytes) {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

export function fromBase64Url(text) {
  if (!/^[A-Za-z0-9_-]*$/.test(text)) throw new Error('bad characters');
  const binary = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
  return Uint8Array.from(binary, (c) => c.charCodeAt(0));
}

// Little-endian base-128 varints of zigzag-coded signed integers: small numbers take one byte.
export class ByteWriter {
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
  append(bytes) {
    this.ensure(bytes.length);
    this.bytes.set(bytes, this.length);
    this.length += bytes.length;
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

export class ByteReader {
  constructor(bytes) {
    this.bytes = bytes;
    this.at = 0;
  }
  get done() {
    return this.at === this.bytes.length;
  }
  byte() {
    if (this.at >= this.bytes.length) throw new Error('truncated');
    return this.bytes[this.at++];
  }
  // The next n bytes as a reader of their own (a stream inside the part).
  sub(n) {
    if (!(n >= 0 && this.at + n <= this.bytes.length)) throw new Error('truncated');
    const part = new ByteReader(this.bytes.subarray(this.at, this.at + n));
    this.at += n;
    return part;
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
