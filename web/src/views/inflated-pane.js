// The inflated pane: the simulated shape, colored by the compression field (where wrinkles form), the
// membrane stress or the distance to the target; internal panels translucent. Shows each streamed
// iterate while the solver runs.
import { BufferAttribute, BufferGeometry, Color, DoubleSide, Group, Mesh, MeshStandardMaterial } from 'three';
import { Pane3D } from './pane3d.js';
import { peakStress } from '../app/fabrication.js';
import { formatDistance } from '../app/units.js';

const TAUT = new Color('#9ec3e6');
const WRINKLED = new Color('#f0c05a');
const STRONG = new Color('#d55e00');
const FULL_SCALE = 0.05; // compression (fraction of length taken up by wrinkles) shown at full color
// Stress: pale at rest, yellow at half the material's strength, vermillion where it would burst.
const UNSTRESSED = new Color('#e4e8ef');
// Distance to target: a diverging blue / orange ramp (Okabe-Ito: tellable apart with any color vision).
const INSIDE = new Color('#0072b2');
const ON_TARGET = new Color('#eeeeee');
const OUTSIDE = new Color('#e69f00');
const DISTANCE_SCALE = 0.03; // signed distance shown at full color, as a fraction of the target's diagonal

export function compressionColor(c, out = new Color()) {
  const t = Math.min(1, Math.max(0, c / FULL_SCALE));
  return t < 0.5 ? out.lerpColors(TAUT, WRINKLED, t * 2) : out.lerpColors(WRINKLED, STRONG, (t - 0.5) * 2);
}

// share: stress over strength (1 = bursts).
export function stressColor(share, out = new Color()) {
  const t = Math.min(1, Math.max(0, share));
  return t < 0.5 ? out.lerpColors(UNSTRESSED, WRINKLED, t * 2) : out.lerpColors(WRINKLED, STRONG, (t - 0.5) * 2);
}

// The signed distance shown at full color for a target of this diagonal, in the distances' units (1: distances
// over the diagonal, as a suggested layout's picture has them).
export function distanceScaleOf(diagonal = 1) {
  return DISTANCE_SCALE * diagonal;
}

// t: signed distance over its full-color value, -1 (inside) .. 1 (outside).
export function distanceColor(t, out = new Color()) {
  const u = Math.min(1, Math.max(-1, t));
  return u < 0 ? out.lerpColors(ON_TARGET, INSIDE, -u) : out.lerpColors(ON_TARGET, OUTSIDE, u);
}

const GRADIENTS = {
  wrinkles: 'linear-gradient(to right, #9ec3e6, #f0c05a, #d55e00)',
  stress: 'linear-gradient(to right, #e4e8ef, #f0c05a, #d55e00)',
  distance: 'linear-gradient(to right, #0072b2, #eeeeee, #e69f00)',
};

// What the shape is colored by: 'wrinkles' (the compression field), 'stress' (max principal stress over
// the material's strength) or 'distance' (signed distance to the target, when the shape belongs to it).
export const COLOR_MODES = ['wrinkles', 'stress', 'distance'];

export class InflatedPane extends Pane3D {
  constructor(element, viewport) {
    super(element, viewport);
    this.group = new Group();
    this.scene.add(this.group);
    this.outerMaterial = new MeshStandardMaterial({ vertexColors: true, roughness: 0.35, metalness: 0.15, side: DoubleSide });
    this.innerMaterial = new MeshStandardMaterial({ color: 0xb0b6c4, transparent: true, opacity: 0.35, side: DoubleSide, depthWrite: false });
    // The parts of the target the shape leaves out, drawn with the distance colors as a translucent ghost.
    this.uncoveredMaterial = new MeshStandardMaterial({ color: INSIDE, transparent: true, opacity: 0.4, side: DoubleSide, depthWrite: false });
    this.target = null; // { positions (meters), indices }: the target, for its uncovered parts
    this.legend = document.createElement('div');
    this.legend.className = 'legend';
    this.legend.hidden = true;
    this.legendTitle = document.createElement('div');
    this.legendBar = document.createElement('div');
    this.legendBar.className = 'bar';
    this.legendEnds = document.createElement('div');
    this.legendEnds.className = 'ends';
    this.legendNote = document.createElement('div');
    this.legendNote.className = 'note';
    this.legend.append(this.legendTitle, this.legendBar, this.legendEnds, this.legendNote);
    element.parentElement.append(this.legend);
    this.shape = null; // { triangles, outer }
    this.colorMode = 'wrinkles';
    this.fields = null; // { compression #F*4, stress #F*2, distances #V | null, distance summary, strength }
    this.strength = null; // the material's strength [Pa], when known
    this.onFieldsChanged = null; // called when what the legend can show changes (e.g. distances arrive)
  }

  // result: { positions (#V*3), triangles (#F*3), outer (#F), compression (#F*4) | undefined, stress (#F*2) }
  setResult(result, { frame = true } = {}) {
    this.clear();
    this.position = null;
    this.shape = { triangles: result.triangles, outer: result.outer };
    // A streamed iterate has no fields yet: neutral colors, unless its distances arrive.
    this.fields = {
      compression: result.compression ?? null,
      stress: result.stress ?? null,
      peakStress: result.stress ? peakStress(result) : 0,
      distances: null,
      distance: null,
    };
    const outerFaces = [];
    const innerFaces = [];
    for (let f = 0; f < result.outer.length; f++) (result.outer[f] ? outerFaces : innerFaces).push(f);
    this.outerFaces = outerFaces;
    this.outerMesh = this.buildMesh(outerFaces, result, this.outerMaterial);
    if (innerFaces.length) this.innerMesh = this.buildMesh(innerFaces, result, this.innerMaterial);
    this.recolor();
    this.element.parentElement.querySelector('.hint')?.setAttribute('hidden', '');
    if (frame) this.frame(this.group);
    this.viewport.requestRender(this);
    this.onFieldsChanged?.();
  }

  // The material's strength [Pa] for the stress colors (null: scale by the largest stress instead).
  setStrength(pascals) {
    this.strength = pascals > 0 ? pascals : null;
    if (this.colorMode === 'stress') this.recolor();
  }

  // The target ({ positions, indices } in its own units, scale: meters per unit), for the parts of it a shape
  // leaves out.
  setTarget(target, scale) {
    this.targetOf = target;
    this.targetScale = scale;
    this.target = target && { positions: Float32Array.from(target.positions, (x) => x * scale), indices: target.indices };
  }

  // Signed distances (#V, meters) of the shown shape to the target and their summary (SolverApi.distanceToTarget:
  // both ways); uncoveredTriangles (3 target vertex indices each) the parts of the target it leaves out, when known.
  setDistances(distances, summary, uncoveredTriangles = null) {
    if (!this.fields || !this.position || distances.length * 3 !== this.position.count * 3) return;
    this.fields.distances = distances;
    this.fields.distance = summary;
    this.showUncovered(uncoveredTriangles);
    if (this.colorMode === 'distance') this.recolor();
    this.onFieldsChanged?.();
  }

  // The target's parts the shape leaves out (UncoveredRegion::triangles), drawn translucent over it.
  showUncovered(triangles) {
    if (this.uncoveredMesh) {
      this.group.remove(this.uncoveredMesh);
      this.uncoveredMesh.geometry.dispose();
      this.uncoveredMesh = null;
    }
    const t = this.target;
    if (!t || !triangles?.length || triangles.reduce((a, b) => Math.max(a, b), 0) * 3 >= t.positions.length) return; // none, or another target's
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(t.positions, 3));
    geometry.setIndex(new BufferAttribute(triangles, 1));
    geometry.computeVertexNormals();
    this.uncoveredMesh = new Mesh(geometry, this.uncoveredMaterial);
    this.uncoveredMesh.name = 'uncovered target';
    this.uncoveredMesh.visible = this.colorMode === 'distance';
    this.group.add(this.uncoveredMesh);
  }

  // Frames the shape with the parts of the target it leaves out, when they are shown: a shape far smaller than
  // its target (a fingertip's panels against a whole hand) would leave them outside the pane.
  frameWithUncovered() {
    if (this.uncoveredMesh?.visible) this.frame(this.group);
  }

  get hasDistances() {
    return Boolean(this.fields?.distances);
  }

  setColorMode(mode) {
    if (!COLOR_MODES.includes(mode)) return;
    this.colorMode = mode;
    this.recolor();
  }

  // The per-vertex colors of the outer surface for the current mode, and the legend that explains them.
  recolor() {
    const fields = this.fields;
    if (!fields || !this.outerMesh) return void (this.legend.hidden = true);
    const n = this.position.count;
    let mode = this.colorMode;
    if (mode === 'distance' && !fields.distances) mode = 'wrinkles';
    if (this.uncoveredMesh) this.uncoveredMesh.visible = mode === 'distance';
    if (mode === 'stress' && !fields.stress) mode = 'wrinkles';
    this.legend.hidden = mode === 'wrinkles' && !fields.compression; // a streamed iterate: nothing to explain
    const source = mode === 'stress' ? fields.stress : fields.compression;
    let value; // per vertex
    if (mode === 'distance') value = fields.distances;
    else {
      // Per-triangle fields, averaged to the vertices (the shape is smooth-shaded).
      const stride = mode === 'stress' ? 2 : 4;
      const sum = new Float32Array(n);
      const count = new Float32Array(n);
      for (const f of this.outerFaces) {
        const x = source ? source[stride * f] : 0;
        for (let k = 0; k < 3; k++) {
          const v = this.shape.triangles[3 * f + k];
          sum[v] += x;
          count[v] += 1;
        }
      }
      value = sum.map((x, v) => (count[v] ? x / count[v] : 0));
    }
    const maxStress = mode === 'stress' ? fields.peakStress : 0;
    const stressScale = this.strength ?? (maxStress || 1);
    const distanceScale = distanceScaleOf(fields.distance?.diagonal ?? 1);
    const color = this.outerMesh.geometry.getAttribute('color');
    const c = new Color();
    for (let v = 0; v < n; v++) {
      if (mode === 'distance') distanceColor(value[v] / distanceScale, c);
      else if (mode === 'stress') stressColor(value[v] / stressScale, c);
      else compressionColor(value[v], c);
      color.setXYZ(v, c.r, c.g, c.b);
    }
    color.needsUpdate = true;
    this.describe(mode, { maxStress, distanceScale });
    this.viewport.requestRender(this);
  }

  describe(mode, { maxStress, distanceScale }) {
    this.legendBar.style.background = GRADIENTS[mode];
    const ends = (...texts) => this.legendEnds.replaceChildren(...texts.map((textContent) => Object.assign(document.createElement('span'), { textContent })));
    let note = '';
    if (mode === 'wrinkles') {
      this.legendTitle.textContent = 'Wrinkles (compression)';
      ends('taut', `${FULL_SCALE * 100}% +`);
    } else if (mode === 'stress') {
      const mpa = (pa) => `${(pa / 1e6).toFixed(pa < 1e7 ? 1 : 0)} MPa`;
      if (this.strength) {
        this.legendTitle.textContent = "Stress (share of the material's strength)";
        ends('0', `${mpa(this.strength / 2)}`, `${mpa(this.strength)}: bursts`);
        note = `Peak ${mpa(maxStress)}, safety factor ${(this.strength / Math.max(maxStress, 1e-9)).toFixed(1)}`;
      } else {
        this.legendTitle.textContent = 'Stress';
        ends('0', mpa(maxStress));
      }
    } else {
      const d = this.fields.distance;
      const mm = `${Math.round(distanceScale * 1000)} mm`;
      this.legendTitle.textContent = 'Distance to target';
      ends(`${mm} inside`, 'on target', `${mm} outside`);
      const largest = Math.max(d.max, d.targetMax ?? 0);
      note = `Average ${formatDistance(d)}; largest ${(100 * largest).toFixed(2)} % of the size`;
      if (this.uncoveredMesh) note += '. Translucent blue: parts of the target the inflated shape leaves out';
      // The largest part's remedy, judged by the solver from the shape (uncoveredRemedy).
      const worst = d.uncovered?.[0];
      if (worst?.helps) note += `. What helps ${worst.where}: ${worst.helps}`;
    }
    this.legendNote.textContent = note;
    this.legendNote.hidden = !note;
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
    this.viewport.requestRender(this);
  }

  // Indexed meshes share one position attribute, so the shape is smooth-shaded; recolor() fills the
  // outer surface's per-vertex colors from the fields.
  buildMesh(faces, result, material) {
    if (!this.position || this.position.count * 3 !== result.positions.length)
      this.position = new BufferAttribute(new Float32Array(result.positions.length), 3);
    this.position.array.set(result.positions);
    const n = result.positions.length / 3;
    const index = new Uint32Array(faces.length * 3);
    faces.forEach((f, k) => {
      for (let corner = 0; corner < 3; corner++) index[3 * k + corner] = result.triangles[3 * f + corner];
    });
    const color = new Float32Array(n * 3).fill(1);
    const c = compressionColor(0);
    for (let v = 0; v < n; v++) color.set([c.r, c.g, c.b], 3 * v);
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
    this.outerMesh = this.innerMesh = this.uncoveredMesh = null;
    this.shape = null;
    this.position = null;
    this.fields = null;
    this.serial = (this.serial ?? 0) + 1; // which shown shape late results (distances) belong to
    this.viewport.requestRender(this);
  }
}
