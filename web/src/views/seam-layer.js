// Seams drawn over the target: each seam's curve as a screen-space-wide line (width shows its weight σ),
// its control points as dots, the curve being drawn as a dashed preview (red when it would make a problem),
// and the snap cursor.
import { Color, Group, Mesh, MeshBasicMaterial, SphereGeometry, Vector2 } from 'three';
import { Line2 } from 'three/addons/lines/Line2.js';
import { LineGeometry } from 'three/addons/lines/LineGeometry.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';

const SEAM_COLOR = new Color('#1d2330');
const SELECTED_COLOR = new Color('#2f6fdd');
const PREVIEW_COLOR = new Color('#2f6fdd');
const SNAP_COLOR = new Color('#d55e00');
const WARNING_COLOR = new Color('#c62828'); // a seam being drawn that would cross itself or cut a sliver

export function seamWidth(weight) {
  return 2 + 1.5 * Math.min(6, Math.sqrt(Math.max(0, weight)) * 2); // px
}

export class SeamLayer extends Group {
  constructor(radius) {
    super();
    this.resolution = new Vector2(1, 1);
    this.dot = new SphereGeometry(radius, 12, 8);
    this.cursor = new Mesh(new SphereGeometry(radius * 1.3, 16, 10), new MeshBasicMaterial({ color: PREVIEW_COLOR, depthTest: false }));
    this.cursor.renderOrder = 3;
    this.cursor.visible = false;
    this.add(this.cursor);
    this.items = new Group();
    this.add(this.items);
    this.materials = [];
  }

  setResolution(width, height) {
    this.resolution.set(width, height);
    for (const m of this.materials) m.resolution.copy(this.resolution);
  }

  line(positions, color, width, dashed = false) {
    const geometry = new LineGeometry();
    geometry.setPositions(positions);
    const material = new LineMaterial({ color, linewidth: width, dashed, dashSize: 0.02, gapSize: 0.015, worldUnits: false });
    material.resolution.copy(this.resolution);
    this.materials.push(material);
    const line = new Line2(geometry, material);
    line.computeLineDistances();
    line.renderOrder = 2;
    return line;
  }

  // seams: [{ curve: Float32Array (x,y,z...), controls: [[x,y,z]], weight, selected, selectedPoint }]
  // preview: Float32Array | null (the seam being drawn, to the cursor), or a list of them (the seams a click would
  // lay: a gusset band's two); warn: it would make a problem
  update(seams, preview = null, warn = false) {
    for (const child of [...this.items.children]) {
      this.items.remove(child);
      if (child.geometry !== this.dot) child.geometry.dispose?.();
      if (child.material !== this.dotMaterial) child.material.dispose?.();
    }
    this.materials = [];
    for (const seam of seams) {
      const color = seam.selected ? SELECTED_COLOR : SEAM_COLOR;
      if (seam.curve?.length >= 6) this.items.add(this.line(seam.curve, color, seamWidth(seam.weight)));
      seam.controls.forEach((c, k) => {
        const selected = seam.selected && seam.selectedPoint === k;
        const dot = new Mesh(this.dot, new MeshBasicMaterial({ color: selected ? SNAP_COLOR : color }));
        dot.position.set(c[0], c[1], c[2]);
        dot.renderOrder = 2;
        this.items.add(dot);
      });
    }
    for (const curve of Array.isArray(preview) ? preview : [preview])
      if (curve?.length >= 6) this.items.add(this.line(curve, warn ? WARNING_COLOR : PREVIEW_COLOR, warn ? 3.5 : 2.5, true));
  }

  // A cursor dot at position (local coordinates), orange when it snaps to a seam.
  showCursor(position, snapped) {
    this.cursor.visible = Boolean(position);
    if (!position) return;
    this.cursor.position.copy(position);
    this.cursor.material.color.copy(snapped ? SNAP_COLOR : PREVIEW_COLOR);
  }
}
