// A 3D pane: scene, perspective camera, lights and orbit controls bound to the pane's element.
import {
  AmbientLight, Box3, DirectionalLight, HemisphereLight, PerspectiveCamera, Scene, Sphere, Vector3,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

export class Pane3D {
  constructor(element, viewport) {
    this.element = element;
    this.viewport = viewport;
    this.scene = new Scene();
    this.camera = new PerspectiveCamera(35, 1, 0.001, 1000);
    this.camera.position.set(0.6, 0.5, 1.6);
    this.scene.add(new HemisphereLight(0xffffff, 0x8890a0, 1.6));
    this.scene.add(new AmbientLight(0xffffff, 0.25));
    const key = new DirectionalLight(0xffffff, 1.6);
    key.position.set(1, 2, 1.5);
    this.camera.add(key); // the key light follows the viewer
    this.scene.add(this.camera);
    this.controls = new OrbitControls(this.camera, element);
    this.controls.enableDamping = false;
    this.controls.addEventListener('change', () => viewport.requestRender());
    viewport.add(this);
  }

  // Frames the object: camera distance from its bounding sphere and the field of view.
  frame(object) {
    const sphere = new Box3().setFromObject(object).getBoundingSphere(new Sphere());
    if (!Number.isFinite(sphere.radius) || sphere.radius <= 0) return;
    const direction = new Vector3(0.35, 0.3, 1).normalize();
    const distance = (sphere.radius / Math.sin((this.camera.fov * Math.PI) / 360)) * 1.05;
    this.camera.position.copy(sphere.center).addScaledVector(direction, distance);
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.controls.target.copy(sphere.center);
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.viewport.requestRender();
  }

  render(renderer, aspect) {
    if (this.camera.aspect !== aspect) {
      this.camera.aspect = aspect;
      this.camera.updateProjectionMatrix();
    }
    renderer.render(this.scene, this.camera);
  }
}
