// The pattern pane: flat panels seen from above with pan and zoom (no rotation).
import {
  OrthographicCamera, Scene, GridHelper, Box3, Vector3, Group, BufferGeometry, Float32BufferAttribute, Mesh,
  MeshBasicMaterial, LineSegments, LineBasicMaterial, DoubleSide,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { layoutPattern } from './pattern-layout.js';
import { panelTint, seamColor } from './palette.js';

export class PatternPane {
  constructor(element, viewport) {
    this.element = element;
    this.viewport = viewport;
    this.scene = new Scene();
    this.halfHeight = 0.5; // meters visible above the center
    this.camera = new OrthographicCamera(-1, 1, 1, -1, -10, 10);
    this.camera.position.set(0, 0, 5);
    this.setGridColors(0xb8c0cc, 0xd8dde5);
    this.controls = new OrbitControls(this.camera, element);
    this.controls.enableRotate = false;
    this.controls.screenSpacePanning = true;
    this.controls.mouseButtons = { LEFT: 2, MIDDLE: 1, RIGHT: 2 }; // PAN, DOLLY, PAN
    this.controls.touches = { ONE: 1, TWO: 2 }; // PAN, DOLLY_PAN
    this.controls.addEventListener('change', () => viewport.requestRender());
    this.content = new Group();
    this.scene.add(this.content);
    this.labels = document.createElement('div');
    this.labels.className = 'pane-labels';
    element.parentElement.append(this.labels);
    this.labelAnchors = [];
    viewport.add(this);
  }

  // pattern: panels in meters (see docs/formats.md). Panels are laid out side by side; each seam has one
  // color on both panels it joins; labels name the panels.
  // The 10 cm grid over 4 m in the theme's colors (the axes, the lines).
  setGridColors(axes, lines) {
    if (this.grid) {
      this.scene.remove(this.grid);
      this.grid.geometry.dispose();
      this.grid.material.dispose();
    }
    this.grid = new GridHelper(4, 40, axes, lines);
    this.grid.rotation.x = Math.PI / 2;
    this.scene.add(this.grid);
    this.viewport.requestRender();
  }

  // frame: fit the view to the panels (not for a streamed iterate: the designer's pan and zoom stay).
  setPattern(pattern, { frame = true } = {}) {
    this.clear();
    const layout = layoutPattern(pattern);
    this.pattern = pattern;
    this.layout = layout;
    const seamIds = new Map();
    const seamIndex = (a, b) => {
      const k = a < b ? `${a}-${b}` : `${b}-${a}`;
      if (!seamIds.has(k)) seamIds.set(k, seamIds.size);
      return seamIds.get(k);
    };
    pattern.panels.forEach((panel, i) => {
      const { offset, boundary, centroid } = layout[i];
      const xy = (v) => [panel.vertices[v][0] + offset[0], panel.vertices[v][1] + offset[1], 0];
      const fill = new BufferGeometry();
      fill.setAttribute('position', new Float32BufferAttribute(panel.triangles.flat().flatMap(xy), 3));
      const material = new MeshBasicMaterial({ color: panelTint(i), side: DoubleSide, transparent: panel.internal, opacity: 0.6 });
      this.content.add(new Mesh(fill, material));
      const points = [];
      const colors = [];
      for (const [a, b, partner] of boundary) {
        const color = partner < 0 ? seamColor(7) : seamColor(seamIndex(i, partner));
        points.push(...xy(a), ...xy(b));
        colors.push(color.r, color.g, color.b, color.r, color.g, color.b);
      }
      const outline = new BufferGeometry();
      outline.setAttribute('position', new Float32BufferAttribute(points, 3));
      outline.setAttribute('color', new Float32BufferAttribute(colors, 3));
      const line = new LineSegments(outline, new LineBasicMaterial({ vertexColors: true }));
      line.position.z = 0.001;
      this.content.add(line);
      const label = document.createElement('div');
      label.className = 'panel-label';
      label.textContent = `${i + 1} ${panel.name ?? ''}`.trim();
      this.labels.append(label);
      this.labelAnchors.push({ label, at: new Vector3(centroid[0], centroid[1], 0) });
    });
    this.element.parentElement.querySelector('.hint')?.setAttribute('hidden', '');
    if (frame) this.frame(this.content);
    else this.viewport.requestRender();
  }

  // The cut lines (sewing line plus seam allowance) of `pattern`'s panels, each a flat [x0, y0, x1, ...]
  // in the panel's frame [m]; ignored when another pattern is shown by now.
  setCutLines(pattern, cutLines) {
    if (pattern !== this.pattern || !this.layout) return false;
    if (this.cutLines) {
      this.content.remove(this.cutLines);
      this.cutLines.geometry.dispose();
      this.cutLines.material.dispose();
    }
    const points = [];
    cutLines.forEach((line, i) => {
      const [dx, dy] = this.layout[i].offset;
      const n = line.length / 2;
      for (let k = 0; k < n; k++) {
        const j = (k + 1) % n;
        points.push(line[2 * k] + dx, line[2 * k + 1] + dy, 0, line[2 * j] + dx, line[2 * j + 1] + dy, 0);
      }
    });
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new Float32BufferAttribute(points, 3));
    this.cutLines = new LineSegments(geometry, new LineBasicMaterial({ color: 0x1d2330 }));
    this.cutLines.position.z = 0.002;
    this.content.add(this.cutLines);
    this.viewport.requestRender();
    return true;
  }

  clear() {
    this.cutLines = null;
    for (const child of [...this.content.children]) {
      this.content.remove(child);
      child.geometry.dispose();
      child.material.dispose();
    }
    this.labels.replaceChildren();
    this.labelAnchors = [];
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
    this.placeLabels();
  }

  placeLabels() {
    const r = this.element.getBoundingClientRect();
    const top = this.element.offsetTop;
    const p = new Vector3();
    for (const { label, at } of this.labelAnchors) {
      p.copy(at).project(this.camera);
      label.style.left = `${((p.x + 1) / 2) * r.width}px`;
      label.style.top = `${top + ((1 - p.y) / 2) * r.height}px`;
    }
  }
}
