// A gallery design's stored result (web/public/gallery/<id>.result.json, made by `node scripts/make-gallery.mjs
// results` with the app's own pipeline: the worker's handlers on the wasm module): its optimized panels with
// their inflated shape, so the design opens with its result shown while the same pipeline refines it live.
// Its key says exactly what it was computed from; a stored result whose key is not the one of the design
// being opened (the design changed, the file is stale) is not used. The format: docs/formats.md.

export const RESULT_FORMAT = 'billow-gallery-result';
// 2: made with the seams' stiffness (wasm/src/simulate/seam_rods.hpp); results of version 1 are not used.
export const RESULT_VERSION = 2;

// The app's resolution when it opens (the store's resolution, the Panels menu's "coarse"): stored results are made at it.
export const DEFAULT_RESOLUTION = 1000;

// What Panels.make asks the worker to optimize (Op.optimizeDesign) for a design at a resolution
// (triangles of the simulation mesh), but the scale, which follows from the target mesh and the height.
export function optimizeArgs(design, triangles) {
  return {
    seams: design.seams.map(({ name, points, closed, weight, smooth }) => ({ name, points, closed, weight, smooth: Boolean(smooth) })),
    triangles,
    pressure: design.pressure,
    material: design.material,
    connections: design.connections.map((c) => c.seams), // internal panels (paper Sec. 3.2)
  };
}

// JSON with every object's keys sorted, so equal values give equal text whatever order fields were written in.
export function canonicalJson(value) {
  if (Array.isArray(value)) return `[${value.map(canonicalJson).join(',')}]`;
  if (value && typeof value === 'object')
    return `{${Object.keys(value).filter((k) => value[k] !== undefined).sort().map((k) => `${JSON.stringify(k)}:${canonicalJson(value[k])}`).join(',')}}`;
  return JSON.stringify(value);
}

// 64 bits as 16 hex digits from two 32-bit multiplicative hashes (FNV-1a and a Murmur-style mix) of the
// bytes. Not cryptographic: it tells a changed design or mesh from the one a result was made for, and
// needs no secure context (crypto.subtle is missing on plain-http hosts).
export function hashBytes(bytes) {
  const data = typeof bytes === 'string' ? new TextEncoder().encode(bytes) : new Uint8Array(bytes.buffer ?? bytes, bytes.byteOffset ?? 0, bytes.byteLength);
  let a = 0x811c9dc5;
  let b = 0x9747b28c ^ data.length;
  for (let i = 0; i < data.length; i++) {
    a = Math.imul(a ^ data[i], 0x01000193);
    b = Math.imul(b ^ data[i], 0x5bd1e995);
    b ^= b >>> 15;
  }
  const hex = (h) => (h >>> 0).toString(16).padStart(8, '0');
  return hex(a) + hex(b);
}

// The key of a design's result: its optimization inputs, its height and the target mesh file's bytes.
export function resultKey(design, triangles, meshBytes) {
  const inputs = { target: design.target, height: design.size.height, mesh: hashBytes(meshBytes), ...optimizeArgs(design, triangles) };
  return hashBytes(canonicalJson(inputs));
}

// The stored result in a result file's text: { key, triangles, patternText, optimizer }, or null when the
// text is no stored result this app can show (the caller then computes the result live).
export function parseStoredResult(text) {
  let value;
  try {
    value = JSON.parse(text);
  } catch {
    return null;
  }
  if (value?.format !== RESULT_FORMAT || value.version !== RESULT_VERSION || typeof value.key !== 'string') return null;
  const pattern = value.pattern;
  if (pattern?.format !== 'billow-pattern' || !Array.isArray(pattern.panels) || !Array.isArray(pattern.inflated)) return null;
  return { key: value.key, triangles: value.triangles, patternText: JSON.stringify(pattern), optimizer: value.optimizer ?? null };
}
