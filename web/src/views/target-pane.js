// The target pane: the target mesh at its real size (meters), with statistics.
import { BufferAttribute, BufferGeometry, Mesh, MeshStandardMaterial, Group } from 'three';
import { Pane3D } from './pane3d.js';

export class TargetPane extends Pane3D {
  constructor(element, viewport) {
    super(element, viewport);
    this.group = new Group();
    this.scene.add(this.group);
    this.material = new MeshStandardMaterial({ color: 0x8fb3e0, roughness: 0.55, metalness: 0.05, flatShading: false });
    this.mesh = null;
  }

  // positions in file units, scale to meters; centered on the bounding box's bottom center.
  setTarget({ positions, indices }, scale) {
    if (this.mesh) {
      this.group.remove(this.mesh);
      this.mesh.geometry.dispose();
    }
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array(positions), 3));
    geometry.setIndex(new BufferAttribute(new Uint32Array(indices), 1));
    geometry.computeVertexNormals();
    geometry.computeBoundingBox();
    this.mesh = new Mesh(geometry, this.material);
    this.mesh.scale.setScalar(0); // forces setScale to place and frame it
    this.group.add(this.mesh);
    this.setScale(scale);
  }

  setScale(scale) {
    if (!this.mesh || this.mesh.scale.x === scale) return;
    const box = this.mesh.geometry.boundingBox;
    this.mesh.scale.setScalar(scale);
    this.mesh.position.set(
      -scale * 0.5 * (box.min.x + box.max.x),
      -scale * box.min.y,
      -scale * 0.5 * (box.min.z + box.max.z),
    );
    this.frame(this.group);
  }
}
