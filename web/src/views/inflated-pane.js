// The inflated pane: the simulated shape, colored by the compression field (where wrinkles form),
// internal panels translucent. Shows each streamed iterate while the solver runs.
import { BufferAttribute, BufferGeometry, Color, DoubleSide, Group, Mesh, MeshStandardMaterial } from 'three';
import { Pane3D } from './pane3d.js';

const TAUT = new Color('#9ec3e6');
const WRINKLED = new Color('#f0c05a');
const STRONG = new Color('#d55e00');
const FULL_SCALE = 0.05; // compression (fraction of length taken up by wrinkles) shown at full color

export function compressionColor(c, out = new Color()) {
  const t = Math.min(1, Math.max(0, c / FULL_SCALE));
  return t < 0.5 ? out.lerpColors(TAUT, WRINKLED, t * 2) : out.lerpColors(WRINKLED, STRONG, (t - 0.5) * 2);
}

export class InflatedPane extends Pane3D {
  constructor(element, viewport) {
    super(element, viewport);
    this.group = new Group();
    this.scene.add(this.group);
    this.outerMaterial = new MeshStandardMaterial({ vertexColors: true, roughness: 0.35, metalness: 0.15, side: DoubleSide });
    this.innerMaterial = new MeshStandardMaterial({ color: 0xb0b6c4, transparent: true, opacity: 0.35, side: DoubleSide, depthWrite: false });
    this.legend = document.createElement('div');
    this.legend.className = 'legend';
    this.legend.hidden = true;
    const title = document.createElement('div');
    title.textContent = 'Wrinkles (compression)';
    const bar = document.createElement('div');
    bar.className = 'bar';
    const ends = document.createElement('div');
    ends.className = 'ends';
    ends.append(Object.assign(document.createElement('span'), { textContent: 'taut' }),
      Object.assign(document.createElement('span'), { textContent: `${FULL_SCALE * 100}% +` }));
    this.legend.append(title, bar, ends);
    element.parentElement.append(this.legend);
    this.shape = null; // { triangles, outer }
  }

  // result: { positions (#V*3), triangles (#F*3), outer (#F), compression (#F*4) | undefined }
  setResult(result, { frame = true } = {}) {
    this.clear();
    this.position = null;
    this.shape = { triangles: result.triangles, outer: result.outer };
    const outerFaces = [];
    const innerFaces = [];
    for (let f = 0; f < result.outer.length; f++) (result.outer[f] ? outerFaces : innerFaces).push(f);
    this.outerMesh = this.buildMesh(outerFaces, result, this.outerMaterial);
    if (innerFaces.length) this.innerMesh = this.buildMesh(innerFaces, result, this.innerMaterial);
    this.legend.hidden = !result.compression;
    this.element.parentElement.querySelector('.hint')?.setAttribute('hidden', '');
    if (frame) this.frame(this.group);
    this.viewport.requestRender();
  }

  // Moves the vertices of the current shape (a streamed iterate): same triangles, new positions.
  updatePositions(positions) {
    if (!this.shape) return;
    this.position.array.set(positions);
    this.position.needsUpdate = true;
    for (const mesh of [this.outerMesh, this.innerMesh]) {
      if (!mesh) continue;
      mesh.geometry.computeVertexNormals();
      mesh.geometry.computeBoundingSphere();
    }
    this.viewport.requestRender();
  }

  // Indexed meshes share one position attribute, so the shape is smooth-shaded; the compression field
  // (per triangle) is averaged to the vertices for display.
  buildMesh(faces, result, material) {
    if (!this.position || this.position.count * 3 !== result.positions.length)
      this.position = new BufferAttribute(new Float32Array(result.positions.length), 3);
    this.position.array.set(result.positions);
    const n = result.positions.length / 3;
    const sum = new Float32Array(n);
    const count = new Float32Array(n);
    const index = new Uint32Array(faces.length * 3);
    faces.forEach((f, k) => {
      for (let corner = 0; corner < 3; corner++) {
        const v = result.triangles[3 * f + corner];
        index[3 * k + corner] = v;
        sum[v] += result.compression ? result.compression[4 * f] : 0;
        count[v] += 1;
      }
    });
    const color = new Float32Array(n * 3);
    const c = new Color();
    for (let v = 0; v < n; v++) {
      compressionColor(count[v] ? sum[v] / count[v] : 0, c);
      color.set([c.r, c.g, c.b], 3 * v);
    }
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', this.position);
    geometry.setAttribute('color', new BufferAttribute(color, 3));
    geometry.setIndex(new BufferAttribute(index, 1));
    geometry.computeVertexNormals();
    const mesh = new Mesh(geometry, material);
    this.group.add(mesh);
    return mesh;
  }

  clear() {
    for (const child of [...this.group.children]) {
      this.group.remove(child);
      child.geometry.dispose();
    }
    this.outerMesh = this.innerMesh = null;
    this.shape = null;
    this.position = null;
  }
}
