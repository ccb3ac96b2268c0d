// Sharing a design by URL: the design document as JSON, deflated and base64url-encoded into the hash
// (#design=...). A design whose target is the designer's own mesh file carries the mesh too (&mesh=...,
// mesh-link.js: a traversal of the triangles and parallelogram-predicted positions on a grid of 1/64 of the
// mean edge), with its seam points renumbered to the order the mesh comes out in. When the mesh would make
// the link too long, the link carries what identifies the file instead (&target=triangles.vertices.hash)
// and whoever opens it is asked for that file (shared-link.js). Reading validates everything (parseDesign,
// unpackMesh) and reports a designer-facing error.
import { parseDesign } from './design.js';
import { deflate, inflate, toBase64Url, fromBase64Url } from './link-bytes.js';
import { packMesh, unpackMesh, renumberDesign, meshFingerprint } from './mesh-link.js';

export const HASH_KEY = 'design';
export const MESH_KEY = 'mesh';
export const TARGET_KEY = 'target';
export const MAX_LINK_CHARS = 60000; // links longer than this are unreliable in browsers and chat apps
const MAX_DESIGN_BYTES = 4 * 1024 * 1024;
const MAX_MESH_BYTES = 16 * 1024 * 1024; // a link's mesh inflates to a few hundred kB at most
// Real meshes take 1.2 to 2.5 characters per triangle in a link, a perfectly regular torus 0.49: past this
// none fits, and packing one would hold the page for seconds (4 s for 250,000 triangles).
const MAX_LINKED_TRIANGLES = 125000;

function tooLarge(length) {
  return new Error(
    `This design is too large for a link (${Math.round(length / 1000)} k characters; links hold about ${MAX_LINK_CHARS / 1000} k). Save it to a file and send the file instead.`,
  );
}

async function designPart(design) {
  return `${HASH_KEY}=${toBase64Url(await deflate(new TextEncoder().encode(JSON.stringify(design))))}`;
}

// The hash fragment for a design ("design=...", and "&mesh=..." when a target mesh goes with it, or
// "&target=..." when that mesh is too large for a link); throws a designer-facing Error when even the
// design alone is too long.
export async function encodeDesign(design, mesh = null) {
  if (mesh && mesh.indices.length / 3 <= MAX_LINKED_TRIANGLES) {
    const { bytes, renumbering } = packMesh(mesh);
    const carried = renumbering ? renumberDesign(design, renumbering) : design;
    const fragment = `${await designPart(carried)}&${MESH_KEY}=${toBase64Url(await deflate(bytes))}`;
    if (fragment.length <= MAX_LINK_CHARS) return fragment;
  }
  let fragment = await designPart(design);
  if (mesh) {
    const { triangles, vertices, hash } = meshFingerprint(mesh);
    fragment += `&${TARGET_KEY}=${triangles}.${vertices}.${hash}`;
  }
  if (fragment.length > MAX_LINK_CHARS) throw tooLarge(fragment.length);
  return fragment;
}

// What to tell the designer once a link is copied: a link without its mesh needs the file sent along.
export function linkNotice(fragment, design) {
  const copied = 'A link to this design was copied to the clipboard.';
  const target = new URLSearchParams(fragment).get(TARGET_KEY);
  if (target === null) return copied;
  const triangles = Number(target.split('.')[0]).toLocaleString('en-US');
  return `${copied} Its target "${design.target.file}" (${triangles} triangles) is too large to go in a link: send the file along, and whoever opens the link is asked to open it.`;
}

// { triangles, vertices, hash } from "&target=...", or null when it is missing or unreadable.
function readTarget(text) {
  const match = /^(\d{1,7})\.(\d{1,7})\.([0-9a-f]{8})$/.exec(text ?? '');
  return match ? { triangles: Number(match[1]), vertices: Number(match[2]), hash: match[3] } : null;
}

// Reads a hash ("#design=...[&mesh=...|&target=...]"): null when there is no design in it;
// { design, warnings, mesh, awaiting } when there is (mesh: { positions, indices } or null; awaiting: the
// mesh file the design needs, { file, triangles, vertices, hash }, when the link left it out); throws Error
// with a designer-facing message when the link is damaged.
export async function decodeDesign(hash) {
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  const packed = params.get(HASH_KEY);
  if (packed === null) return null;
  const packedMesh = params.get(MESH_KEY);
  if (packed.length + (packedMesh?.length ?? 0) > MAX_LINK_CHARS * 2) throw new Error('This link is too long to be a Billow design.');
  let value;
  try {
    value = JSON.parse(new TextDecoder().decode(await inflate(fromBase64Url(packed), MAX_DESIGN_BYTES)));
  } catch {
    throw new Error('This link does not contain a readable Billow design: it may have been cut short when it was copied.');
  }
  let mesh = null;
  if (packedMesh !== null) {
    try {
      mesh = unpackMesh(await inflate(fromBase64Url(packedMesh), MAX_MESH_BYTES));
    } catch {
      throw new Error('The target shape in this link is damaged: it may have been cut short when it was copied.');
    }
  }
  const parsed = parseDesign(value);
  const target = mesh || !parsed.design.target.file ? null : readTarget(params.get(TARGET_KEY));
  return { ...parsed, mesh, awaiting: target && { file: parsed.design.target.file, ...target } };
}
