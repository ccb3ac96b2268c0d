// The target and its inflated shape stand on the design's up axis (app/up-axis.js): each pane turns its group,
// not the positions, so picking (mesh.worldToLocal), seams, labels and marks stay in the target's own
// coordinates and the seams' {face, bary} mean the same triangles whatever the up axis.
import { Matrix4 } from 'three';
import { DEFAULT_UP, UP_FRAMES } from '../app/up-axis.js';

function turn(group, up) {
  const [x, y, z] = UP_FRAMES[up];
  group.quaternion.setFromRotationMatrix(new Matrix4().set(...x, 0, ...y, 0, ...z, 0, 0, 0, 0, 1));
  group.userData.up = up;
  group.updateMatrixWorld(true);
}

// Turns the target and inflated panes ({ target, inflated }) to stand on `up`. When it changes, the target is
// framed again from the front (it stands differently) and the inflated shape, if any, framed with it.
export function standUp(panes, up) {
  const frame = UP_FRAMES[up] ? up : DEFAULT_UP;
  const { target, inflated } = panes;
  if ((target.group.userData.up ?? DEFAULT_UP) === frame && (inflated.group.userData.up ?? DEFAULT_UP) === frame) return false;
  turn(target.group, frame);
  turn(inflated.group, frame);
  if (target.mesh) target.frame(target.group, { reset: true });
  if (inflated.shape) inflated.frame(inflated.group);
  target.viewport.requestRender(); // both panes turned
  return true;
}
