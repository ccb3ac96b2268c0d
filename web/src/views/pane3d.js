// A 3D pane: scene, perspective camera, lights and orbit controls bound to the pane's element. Two panes can
// be linked (linkViews): turning one turns the other, so the target and its inflated shape are seen from the
// same side.
import {
  AmbientLight, Box3, DirectionalLight, HemisphereLight, PerspectiveCamera, Scene, Sphere, Vector3,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { freeArea, watchOverlays } from './free-area.js';

const DEFAULT_VIEW = new Vector3(0.35, 0.3, 1).normalize(); // from the front, a little right and above

// The world box of what is shown of object: the geometry of its visible descendants. Box3.setFromObject also takes
// hidden ones, such as the seam cursor at the target's own origin, which for a file whose origin lies far from its
// shape framed the target small in a corner.
export function visibleBox(object) {
  const box = new Box3(), part = new Box3();
  object.updateWorldMatrix(true, true);
  object.traverseVisible((o) => {
    if (!o.geometry) return;
    if (!o.geometry.boundingBox) o.geometry.computeBoundingBox();
    box.union(part.copy(o.geometry.boundingBox).applyMatrix4(o.matrixWorld));
  });
  return box.isEmpty() ? new Box3().setFromObject(object) : box;
}

export class Pane3D {
  constructor(element, viewport) {
    this.element = element;
    this.viewport = viewport;
    this.scene = new Scene();
    this.camera = new PerspectiveCamera(35, 1, 0.001, 1000);
    this.camera.position.copy(DEFAULT_VIEW).multiplyScalar(1.8);
    this.scene.add(new HemisphereLight(0xffffff, 0x8890a0, 1.6));
    this.scene.add(new AmbientLight(0xffffff, 0.25));
    const key = new DirectionalLight(0xffffff, 1.6);
    key.position.set(1, 2, 1.5);
    this.camera.add(key); // the key light follows the viewer
    this.scene.add(this.camera);
    this.controls = new OrbitControls(this.camera, element);
    this.controls.enableDamping = false;
    this.controls.zoomToCursor = true; // a thin part under the cursor stays there as it grows, to click on
    this.controls.addEventListener('change', () => viewport.requestRender(this));
    this.square = null; // where the view is framed: { left, top, side } in client pixels (fitView)
    this.fitKey = '';
    this.front = null; // the way the shown object faces, in its own coordinates (defaultView)
    viewport.add(this);
    watchOverlays(element.parentElement, () => viewport.requestRender(this)); // a box opened, closed or shown
  }

  // The view is framed in the free part of the pane (free-area.js): the largest square that fits there, centred
  // in it, spans the field of view, and the rest of the pane shows what lies around it (setViewOffset), so a
  // framed shape is never under a box and keeps its size while the boxes' contents change. With nothing over the
  // pane the pane is the view, as three.js has it (the field of view spans its height; the classroom frames so).
  fitView() {
    const body = this.element.getBoundingClientRect();
    if (!(body.width > 0 && body.height > 0)) return;
    const free = freeArea(this.element);
    const whole = free.left <= body.left + 0.5 && free.top <= body.top + 0.5 && free.right >= body.right - 0.5 && free.bottom >= body.bottom - 0.5;
    const side = whole ? Math.min(body.width, body.height) : Math.min(free.right - free.left, free.bottom - free.top);
    const x = whole ? (body.width - side) / 2 : free.left - body.left + (free.right - free.left - side) / 2;
    const y = whole ? (body.height - side) / 2 : free.top - body.top + (free.bottom - free.top - side) / 2;
    this.square = { left: body.left + x, top: body.top + y, side };
    const key = whole ? `${body.width} ${body.height}` : `${body.width} ${body.height} ${x} ${y} ${side}`;
    if (key === this.fitKey) return;
    this.fitKey = key;
    if (whole) {
      this.camera.clearViewOffset();
      this.camera.aspect = body.width / body.height;
      this.camera.updateProjectionMatrix();
    } else {
      this.camera.aspect = 1;
      this.camera.setViewOffset(side, side, -x, -y, body.width, body.height);
    }
  }

  // The unit direction from the orbit centre to the camera.
  viewDirection() {
    const d = this.camera.position.clone().sub(this.controls.target);
    return d.lengthSq() > 0 ? d.normalize() : DEFAULT_VIEW.clone();
  }

  // The three-quarter front view of the object, its front +Z unless this.front (in the object's own coordinates, as
  // the model faces in its file) says otherwise: turned about the vertical to face it.
  defaultView(object) {
    const front = this.front?.clone().applyQuaternion(object.quaternion);
    if (!front || front.x * front.x + front.z * front.z < 1e-12) return DEFAULT_VIEW.clone();
    return DEFAULT_VIEW.clone().applyAxisAngle(new Vector3(0, 1, 0), Math.atan2(front.x, front.z));
  }

  // The unit direction from the object to the viewer of a named view: 'front', 'back', 'left', 'right' (the
  // viewer's, facing the front), 'top', 'bottom' or 'three-quarter' (defaultView), turned about the vertical as
  // defaultView is. Top and bottom lean a hair to the front, so the orbit keeps its up direction.
  namedView(name, object) {
    if (name === 'three-quarter') return this.defaultView(object);
    const front = this.front?.clone().applyQuaternion(object.quaternion);
    const yaw = front && front.x * front.x + front.z * front.z >= 1e-12 ? Math.atan2(front.x, front.z) : 0;
    const turns = { front: 0, right: Math.PI / 2, back: Math.PI, left: -Math.PI / 2 };
    const vertical = { top: 1, bottom: -1 }[name];
    const across = vertical ? 1e-3 : 1;
    const angle = yaw + (turns[name] ?? 0);
    return new Vector3(across * Math.sin(angle), vertical ?? 0, across * Math.cos(angle)).normalize();
  }

  // Turns the view about its centre to look along `direction` (from the centre to the viewer), keeping the zoom.
  turnTo(direction) {
    const distance = this.camera.position.distanceTo(this.controls.target);
    this.camera.position.copy(this.controls.target).addScaledVector(direction.clone().normalize(), distance);
    this.controls.update();
    this.controls.dispatchEvent({ type: 'change' });
  }

  // Frames the object: camera distance from its bounding sphere and the field of view, whole in the free part
  // of the pane (fitView), seen from where the camera already looks (a new shape does not undo the designer's
  // turning of the view), or with reset from the default three-quarter front view.
  frame(object, { reset = false } = {}) {
    const sphere = visibleBox(object).getBoundingSphere(new Sphere());
    if (!Number.isFinite(sphere.radius) || sphere.radius <= 0) return;
    const direction = reset ? this.defaultView(object) : this.viewDirection();
    this.fitView();
    const half = (this.camera.fov * Math.PI) / 360;
    // The framed square spans the field of view; a whole pane narrower than tall spans less of it across.
    const across = this.camera.view?.enabled ? half : Math.atan(Math.tan(half) * Math.min(1, this.camera.aspect));
    const distance = (sphere.radius / Math.sin(across)) * 1.05;
    this.camera.position.copy(sphere.center).addScaledVector(direction, distance);
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.controls.target.copy(sphere.center);
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.viewport.requestRender(this);
  }

  // Turns the view about its centre until `point` (a Vector3 in the scene) faces the viewer, keeping the zoom:
  // how a problem's place is shown.
  turnTowards(point) {
    const direction = point.clone().sub(this.controls.target);
    if (direction.lengthSq() > 0) this.turnTo(direction);
  }

  render(renderer) {
    this.fitView();
    renderer.render(this.scene, this.camera);
  }
}

// Turning either pane (orbit controls, or frame()) turns the other the same way: the same view direction
// (orbit controls keep y up in both); each keeps its own centre and distance (zoom).
export function linkViews(a, b) {
  let following = false;
  const follow = (from, to) => () => {
    if (following) return;
    following = true;
    const distance = to.camera.position.distanceTo(to.controls.target);
    to.camera.position.copy(to.controls.target).addScaledVector(from.viewDirection(), distance);
    to.controls.update();
    to.viewport.requestRender(to);
    following = false;
  };
  a.controls.addEventListener('change', follow(a, b));
  b.controls.addEventListener('change', follow(b, a));
}
