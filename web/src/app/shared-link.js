// A design from a link that left its target mesh out (too large for a link, share.js): the designer is
// told which file to open, and when they open it the design goes onto it, if it is the very mesh the
// design was drawn on (triangle and vertex counts, and a hash of its triangles and positions: seam points
// name triangles by number, so a similar mesh would put them elsewhere).
import { meshFingerprint } from './mesh-link.js';

const count = (n) => n.toLocaleString('en-US');

// For every design opened from a link (decoded: decodeDesign's result): an AwaitedTarget when the design
// waits for a mesh file, after telling the designer which; else null.
export function awaitTarget(decoded, messages) {
  const { design, mesh, awaiting } = decoded;
  if (mesh || !design.target.file) return null;
  if (!awaiting) {
    messages.show('warning', `The link refers to the file "${design.target.file}", which is not in the link. Open that file to continue.`);
    return null;
  }
  const awaited = new AwaitedTarget(design, awaiting, messages);
  awaited.tell(
    `This design was drawn on your mesh "${awaiting.file}" (${count(awaiting.triangles)} triangles), which is too large to travel in a link. Open that file (Open…, or drop it on the page) and the design goes onto it.`,
  );
  return awaited;
}

export class AwaitedTarget {
  constructor(design, expected, messages) {
    this.design = design;
    this.expected = expected;
    this.messages = messages;
    this.attached = false;
    this.shown = null; // the message about the waiting design: one at a time, gone once it is on its mesh
  }

  tell(text) {
    this.shown?.remove();
    this.shown = text === null ? null : this.messages.show('warning', text);
  }

  // The design for a target the designer just opened (design: the new one the app would give it; mesh:
  // { positions, indices } as loaded): the waiting design when the file is its mesh, else `design` with a
  // message saying why the waiting design stays out of it.
  attach(fileName, mesh, design) {
    if (this.attached || !design.target.file) return design;
    const found = meshFingerprint(mesh);
    const { file, triangles, vertices, hash } = this.expected;
    if (found.triangles === triangles && found.vertices === vertices && found.hash === hash) {
      this.attached = true;
      this.tell(null);
      return { ...this.design, target: { ...this.design.target, file: fileName } };
    }
    const why =
      found.triangles !== triangles || found.vertices !== vertices
        ? `this file has ${count(found.triangles)} triangles and ${count(found.vertices)} vertices, "${file}" had ${count(triangles)} and ${count(vertices)}`
        : `its triangles or vertices are not where they were in "${file}"`;
    this.tell(`"${fileName}" is not the mesh the shared design was drawn on (${why}), so it opens on its own. The shared design still waits: open "${file}" to put it on its mesh.`);
    return design;
  }
}
