// Sharing a design by URL: the design document as JSON, deflated and base64url-encoded into the hash
// (#design=...). Reading validates everything (parseDesign) and reports a designer-facing error.
import { parseDesign } from './design.js';

export const HASH_KEY = 'design';
export const MAX_LINK_CHARS = 32000; // links longer than this are unreliable in browsers and chat apps

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

// The hash fragment for a design ("design=..."); throws when the link would be too long.
export async function encodeDesign(design) {
  const json = new TextEncoder().encode(JSON.stringify(design));
  const packed = toBase64Url(await pipe(json, new CompressionStream('deflate-raw')));
  const fragment = `${HASH_KEY}=${packed}`;
  if (fragment.length > MAX_LINK_CHARS)
    throw new Error(
      `This design is too large for a link (${Math.round(fragment.length / 1000)} k characters; links hold about ${MAX_LINK_CHARS / 1000} k). Save it to a file and send the file instead.`,
    );
  return fragment;
}

// Reads a hash ("#design=..."): null when there is no design in it; { design, warnings } when there is;
// throws Error with a designer-facing message when the link is damaged.
export async function decodeDesign(hash) {
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  const packed = params.get(HASH_KEY);
  if (packed === null) return null;
  if (packed.length > MAX_LINK_CHARS * 2) throw new Error('This link is too long to be a Billow design.');
  let value;
  try {
    const bytes = await pipe(fromBase64Url(packed), new DecompressionStream('deflate-raw'));
    if (bytes.length > 4 * 1024 * 1024) throw new Error('too large');
    value = JSON.parse(new TextDecoder().decode(bytes));
  } catch {
    throw new Error('This link does not contain a readable Billow design: it may have been cut short when it was copied.');
  }
  return parseDesign(value);
}
