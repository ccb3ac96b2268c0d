// The pattern pane: flat panels seen from above with pan and zoom (no rotation).
import { OrthographicCamera, Scene, GridHelper, Box3, Vector3 } from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

export class PatternPane {
  constructor(element, viewport) {
    this.element = element;
    this.viewport = viewport;
    this.scene = new Scene();
    this.halfHeight = 0.5; // meters visible above the center
    this.camera = new OrthographicCamera(-1, 1, 1, -1, -10, 10);
    this.camera.position.set(0, 0, 5);
    this.grid = new GridHelper(4, 40, 0xb8c0cc, 0xd8dde5); // 10 cm squares over 4 m
    this.grid.rotation.x = Math.PI / 2;
    this.scene.add(this.grid);
    this.controls = new OrbitControls(this.camera, element);
    this.controls.enableRotate = false;
    this.controls.screenSpacePanning = true;
    this.controls.mouseButtons = { LEFT: 2, MIDDLE: 1, RIGHT: 2 }; // PAN, DOLLY, PAN
    this.controls.touches = { ONE: 1, TWO: 2 }; // PAN, DOLLY_PAN
    this.controls.addEventListener('change', () => viewport.requestRender());
    viewport.add(this);
  }

  frame(object) {
    const box = new Box3().setFromObject(object);
    if (box.isEmpty()) return;
    const center = box.getCenter(new Vector3());
    const size = box.getSize(new Vector3());
    this.halfHeight = 0.6 * Math.max(size.y, size.x / this.aspect());
    this.camera.zoom = 1;
    this.controls.target.set(center.x, center.y, 0);
    this.camera.position.set(center.x, center.y, 5);
    this.controls.update();
    this.viewport.requestRender();
  }

  aspect() {
    const r = this.element.getBoundingClientRect();
    return r.height > 0 ? r.width / r.height : 1;
  }

  render(renderer, aspect) {
    const h = this.halfHeight;
    if (this.camera.top !== h || this.camera.right !== h * aspect) {
      Object.assign(this.camera, { left: -h * aspect, right: h * aspect, top: h, bottom: -h });
      this.camera.updateProjectionMatrix();
    }
    renderer.render(this.scene, this.camera);
  }
}
