// The target pane: the target mesh at its real size (meters), its seams and segments, and picking of
// surface points (triangle + barycentric coordinates) for the seam tool.
import {
  BufferAttribute, BufferGeometry, DoubleSide, Group, Mesh, MeshBasicMaterial, MeshStandardMaterial, PlaneGeometry, Raycaster, SphereGeometry, Triangle,
  Vector2, Vector3,
} from 'three';
import { Pane3D } from './pane3d.js';
import { SeamLayer } from './seam-layer.js';
import { unclutterLabels } from './label-rule.js';
import { segmentColor, PROBLEM_COLOR } from './palette.js';

const CONNECTION_MATERIAL = new MeshStandardMaterial({
  // Internal panels lie inside the target: drawn through it, translucent.
  color: 0xcc79a7, transparent: true, opacity: 0.3, side: DoubleSide, depthWrite: false, depthTest: false,
});

// n+1 points at equal arc-length steps along a polyline (flat x,y,z array).
function resample(curve, n) {
  const count = curve.length / 3;
  const cumulative = [0];
  for (let i = 1; i < count; i++)
    cumulative.push(cumulative[i - 1] + Math.hypot(curve[3 * i] - curve[3 * i - 3], curve[3 * i + 1] - curve[3 * i - 2], curve[3 * i + 2] - curve[3 * i - 1]));
  const total = cumulative[count - 1] || 1;
  const out = [];
  let j = 1;
  for (let k = 0; k <= n; k++) {
    const s = (k / n) * total;
    while (j < count - 1 && cumulative[j] < s) j++;
    const t = (s - cumulative[j - 1]) / (cumulative[j] - cumulative[j - 1] || 1);
    out.push([0, 1, 2].map((c) => curve[3 * (j - 1) + c] * (1 - t) + curve[3 * j + c] * t));
  }
  return out;
}

function ruledSurface(a, b, n) {
  const pa = resample(a, n);
  const pb = resample(b, n);
  // Pair the curves in the direction that gives the shorter rulings.
  const direct = pa.reduce((s, p, k) => s + Math.hypot(...p.map((x, c) => x - pb[k][c])), 0);
  const reversed = pa.reduce((s, p, k) => s + Math.hypot(...p.map((x, c) => x - pb[n - k][c])), 0);
  if (reversed < direct) pb.reverse();
  const position = new Float32Array((n + 1) * 6);
  pa.forEach((p, k) => position.set([...p, ...pb[k]], 6 * k));
  const index = [];
  for (let k = 0; k < n; k++) index.push(2 * k, 2 * k + 1, 2 * k + 2, 2 * k + 1, 2 * k + 3, 2 * k + 2);
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(position, 3));
  geometry.setIndex(index);
  geometry.computeVertexNormals();
  return geometry;
}

const SYMMETRY_MATERIAL = new MeshBasicMaterial({
  // The mirror plane: a faint sheet through the target, drawn through it.
  color: 0x0072b2, transparent: true, opacity: 0.12, side: DoubleSide, depthWrite: false,
});

const PLACE_MATERIAL = new MeshBasicMaterial({
  // A problem's place: a ring of color seen through the target.
  color: 0xd55e00, transparent: true, opacity: 0.35, depthTest: false, depthWrite: false,
});

const PUSH_BACK = { polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 };

export class TargetPane extends Pane3D {
  constructor(element, viewport) {
    super(element, viewport);
    this.group = new Group();
    this.scene.add(this.group);
    // Surfaces are pushed back a little in depth so seams drawn on them are never half hidden.
    this.material = new MeshStandardMaterial({ color: 0x8fb3e0, roughness: 0.55, metalness: 0.05, ...PUSH_BACK });
    this.mesh = null;
    this.seams = null;
    this.raycaster = new Raycaster();
    // Segment numbers on the model ("3"), the same as their panels' ("Panel 3") and their problems'.
    this.labels = document.createElement('div');
    this.labels.className = 'pane-labels';
    element.parentElement.append(this.labels);
    this.segmentLabels = []; // { label, at (target units), problem }
    // The note beside a seam being drawn that would make a problem ("Crosses itself here").
    this.draftNote = document.createElement('div');
    this.draftNote.className = 'draft-warning';
    this.draftNote.setAttribute('role', 'status');
    this.draftNote.hidden = true;
    this.labels.append(this.draftNote);
    this.draftAt = null;
  }

  // warning: { text, location (target units) } or null.
  setDraftWarning(warning) {
    this.draftAt = warning ? new Vector3(...warning.location) : null;
    this.draftNote.textContent = warning?.text ?? '';
    this.draftNote.dataset.code = warning?.code ?? '';
    this.draftNote.hidden = !warning;
    this.requestRender();
  }

  requestRender() {
    this.viewport.requestRender(this);
  }

  // positions in file units, scale to meters; centered on the bounding box's bottom center. front: the way the model
  // faces in its own coordinates ([x, y, z]), if known and not +Z.
  setTarget({ positions, indices }, scale, front = null) {
    if (this.mesh) {
      this.group.remove(this.mesh);
      this.mesh.geometry.dispose();
    }
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array(positions), 3));
    geometry.setIndex(new BufferAttribute(new Uint32Array(indices), 1));
    geometry.computeVertexNormals();
    geometry.computeBoundingBox();
    geometry.computeBoundingSphere();
    this.material.visible = true;
    this.clearSegments();
    this.mesh = new Mesh(geometry, this.material);
    this.connections = null;
    this.symmetry = null;
    this.placeMark = null;
    this.setSegmentLabels();
    this.seams = new SeamLayer(geometry.boundingSphere.radius * 0.012);
    this.mesh.add(this.seams);
    this.mesh.scale.setScalar(0); // forces setScale to place and frame it
    this.group.add(this.mesh);
    this.front = front ? new Vector3(...front) : null;
    this.newTarget = true; // a new target is seen from the default view
    this.setScale(scale);
  }

  // Turns the view to a named one (Pane3D.namedView), the target's front as it stands.
  showView(name) {
    if (this.mesh) this.turnTo(this.namedView(name, this.group));
  }

  setScale(scale) {
    if (!this.mesh || this.mesh.scale.x === scale) return;
    const box = this.mesh.geometry.boundingBox;
    this.mesh.scale.setScalar(scale);
    this.mesh.position.set(-scale * 0.5 * (box.min.x + box.max.x), -scale * box.min.y, -scale * 0.5 * (box.min.z + box.max.z));
    this.mesh.updateMatrixWorld(true);
    this.frame(this.group, { reset: this.newTarget });
    this.newTarget = false;
  }

  // The target cut into segments, each in its own color (segments that are not disks in red). The
  // original target stays for picking, undrawn; the segments mesh shares its transform.
  setSegments({ positions, indices, faceSegment, segments, problems }) {
    this.clearSegments();
    this.setSegmentLabels(segments, problems);
    if (!this.mesh || !segments || segments.length < 2) {
      this.material.visible = true;
      this.requestRender();
      return;
    }
    const indexed = new BufferGeometry();
    indexed.setAttribute('position', new BufferAttribute(positions, 3));
    indexed.setIndex(new BufferAttribute(indices, 1));
    indexed.computeVertexNormals();
    const geometry = indexed.toNonIndexed();
    const color = new Float32Array(faceSegment.length * 9);
    faceSegment.forEach((s, f) => {
      const c = segments[s]?.isDisk === false ? PROBLEM_COLOR : segmentColor(s);
      for (let k = 0; k < 3; k++) color.set([c.r, c.g, c.b], 9 * f + 3 * k);
    });
    geometry.setAttribute('color', new BufferAttribute(color, 3));
    this.segmentsMesh = new Mesh(geometry, new MeshStandardMaterial({ vertexColors: true, roughness: 0.6, metalness: 0.0, ...PUSH_BACK }));
    this.segmentsMesh.raycast = () => {}; // picking uses the original target's triangles
    this.mesh.add(this.segmentsMesh);
    this.material.visible = false;
    this.requestRender();
  }

  // segments: the segmentation's ({ label: [x, y, z] in target units, isDisk }); problems mark their labels.
  setSegmentLabels(segments = [], problems = []) {
    this.labels.replaceChildren(this.draftNote);
    this.segmentLabels = [];
    if (segments.length < 2) return this.requestRender();
    const troubled = new Set(problems.filter((p) => p.segment >= 0).map((p) => p.segment));
    segments.forEach((segment, i) => {
      if (!segment.label) return;
      const label = document.createElement('div');
      label.className = `segment-label${troubled.has(i) || segment.isDisk === false ? ' problem' : ''}`;
      label.textContent = String(i + 1);
      label.title = `Segment ${i + 1}: it becomes panel ${i + 1}`;
      label.dataset.segment = String(i + 1);
      this.labels.append(label);
      this.segmentLabels.push({ label, at: new Vector3(...segment.label) });
    });
    this.requestRender();
  }

  // Each segment label over its point, hidden where the model is in front of it; the note on a seam being
  // drawn beside its place (kept inside the pane: the place may be on the far side).
  placeLabels() {
    if (!this.mesh) return;
    const r = this.element.getBoundingClientRect();
    const top = this.element.offsetTop;
    const p = new Vector3();
    if (this.draftAt && !this.draftNote.hidden) {
      p.copy(this.draftAt);
      this.mesh.localToWorld(p).project(this.camera);
      const clamp = (v) => Math.min(0.9, Math.max(-0.9, v));
      this.draftNote.style.left = `${((clamp(p.x) + 1) / 2) * r.width}px`;
      this.draftNote.style.top = `${top + ((1 - clamp(p.y)) / 2) * r.height}px`;
    }
    if (!this.segmentLabels.length) return;
    for (const { label, at } of this.segmentLabels) {
      p.copy(at);
      this.mesh.localToWorld(p).project(this.camera);
      label.hidden = Math.abs(p.x) > 1 || Math.abs(p.y) > 1 || !this.isVisible(at);
      label.style.left = `${((p.x + 1) / 2) * r.width}px`;
      label.style.top = `${top + ((1 - p.y) / 2) * r.height}px`;
    }
    // Numbers that would overlap: a segment with a problem keeps its number first, another one waits for a
    // closer view (label-rule.js).
    const shown = this.segmentLabels.filter(({ label }) => !label.hidden);
    unclutterLabels(shown.sort((a, b) => b.label.classList.contains('problem') - a.label.classList.contains('problem')));
  }

  clearSegments() {
    if (!this.segmentsMesh) return;
    this.segmentsMesh.parent?.remove(this.segmentsMesh);
    this.segmentsMesh.geometry.dispose();
    this.segmentsMesh.material.dispose();
    this.segmentsMesh = null;
  }

  // Internal connections: a translucent ruled surface between the two seam curves (points matched by
  // arc length), showing where the internal panel will be. curves: [[curveA, curveB] | nulls].
  setConnections(pairs) {
    if (!this.mesh) return;
    if (!this.connections) {
      this.connections = new Group();
      this.mesh.add(this.connections);
    }
    for (const child of [...this.connections.children]) {
      this.connections.remove(child);
      child.geometry.dispose();
    }
    for (const [a, b] of pairs) {
      if (!a || !b) continue;
      const geometry = ruledSurface(a, b, 32);
      const panel = new Mesh(geometry, CONNECTION_MATERIAL);
      panel.renderOrder = 1;
      panel.raycast = () => {}; // seams are picked on the target, through the translucent panel
      this.connections.add(panel);
    }
    this.requestRender();
  }

  // The mirror plane ({ axis: 0 | 1 | 2, offset } in target units) as a faint sheet a little larger than
  // the target's box; null hides it.
  setSymmetryPlane(plane) {
    if (!this.mesh) return;
    if (this.symmetry) {
      this.mesh.remove(this.symmetry);
      this.symmetry.geometry.dispose();
      this.symmetry = null;
    }
    if (plane) {
      const box = this.mesh.geometry.boundingBox;
      const size = box.getSize(new Vector3()).multiplyScalar(1.15);
      const center = box.getCenter(new Vector3());
      // PlaneGeometry spans local x (width) and y (height); rotated so its normal is the plane's axis.
      const [width, height] = [[size.z, size.y], [size.x, size.z], [size.x, size.y]][plane.axis];
      this.symmetry = new Mesh(new PlaneGeometry(width, height), SYMMETRY_MATERIAL);
      if (plane.axis === 0) this.symmetry.rotation.y = Math.PI / 2; // the sheet's normal along x
      if (plane.axis === 1) this.symmetry.rotation.x = -Math.PI / 2; // along y
      center.setComponent(plane.axis, plane.offset);
      this.symmetry.position.copy(center);
      this.symmetry.renderOrder = 2;
      this.symmetry.raycast = () => {};
      this.mesh.add(this.symmetry);
    }
    this.requestRender();
  }

  ndc(event) {
    const r = this.element.getBoundingClientRect();
    return new Vector2(((event.clientX - r.left) / r.width) * 2 - 1, -((event.clientY - r.top) / r.height) * 2 + 1);
  }

  // The surface point under a pointer event: { point: { face, bary }, position: [x, y, z] (file units) }.
  pick(event) {
    if (!this.mesh) return null;
    this.raycaster.setFromCamera(this.ndc(event), this.camera);
    const hit = this.raycaster.intersectObject(this.mesh, false)[0];
    if (!hit) return null;
    const local = this.mesh.worldToLocal(hit.point.clone());
    const pos = this.mesh.geometry.getAttribute('position');
    const index = this.mesh.geometry.index.array;
    const corner = (c) => new Vector3().fromBufferAttribute(pos, index[3 * hit.faceIndex + c]);
    const bary = Triangle.getBarycoord(local, corner(0), corner(1), corner(2), new Vector3());
    return { point: { face: hit.faceIndex, bary: [bary.x, bary.y, bary.z] }, position: [local.x, local.y, local.z] };
  }

  // Turns the view towards a place on the target (its own units) and rings it: where a problem is. radius in
  // the target's units (0: a size that reads at the target's scale). null clears the mark.
  showPlace(position, radius = 0) {
    if (this.placeMark) {
      this.placeMark.parent?.remove(this.placeMark);
      this.placeMark.geometry.dispose();
      this.placeMark = null;
    }
    if (!this.mesh || !position) return this.requestRender();
    const local = new Vector3(...position);
    const size = this.mesh.geometry.boundingSphere.radius;
    const r = radius > 0 ? Math.min(radius, 0.3 * size) : 0.08 * size;
    this.placeMark = new Mesh(new SphereGeometry(r, 24, 16), PLACE_MATERIAL);
    this.placeMark.position.copy(local);
    this.placeMark.renderOrder = 3;
    this.placeMark.raycast = () => {};
    this.placeMark.name = 'place';
    this.mesh.add(this.placeMark);
    this.mesh.updateMatrixWorld(true);
    // Seen straight on, along the surface's normal there; from the centre's side where that hides it (a place
    // inside a fold). From the centre alone, a place on the side of a long shape (a sausage, a letter) was seen
    // end-on, behind the shape's own end.
    const world = this.mesh.localToWorld(local.clone());
    const normal = this.surfaceNormalNear(local);
    if (normal) this.turnTo(normal.transformDirection(this.mesh.matrixWorld));
    if (!normal || !this.isVisible(local)) this.turnTowards(world);
    this.requestRender();
  }

  // The target's outward normal at a point of its own (target units): the area-weighted normals of the triangles
  // around it, within three times the nearest triangle's distance or a hundredth of the model's size (a patch, not
  // a whole thin limb, whose normals around it would cancel); null without a mesh.
  surfaceNormalNear(point) {
    const position = this.mesh?.geometry.attributes.position, index = this.mesh?.geometry.index;
    if (!position || !index) return null;
    const a = new Vector3(), b = new Vector3(), c = new Vector3(), n = new Vector3(), sum = new Vector3();
    const distances = new Float64Array(index.count / 3); // of each triangle's centroid
    for (let t = 0; t < index.count; t += 3) {
      a.fromBufferAttribute(position, index.getX(t));
      b.fromBufferAttribute(position, index.getX(t + 1));
      c.fromBufferAttribute(position, index.getX(t + 2));
      distances[t / 3] = a.add(b).add(c).divideScalar(3).distanceTo(point);
    }
    let nearest = Infinity;
    for (const d of distances) nearest = Math.min(nearest, d);
    const reach = Math.max(3 * nearest, 0.01 * this.mesh.geometry.boundingSphere.radius);
    for (let t = 0; t < index.count; t += 3) {
      if (distances[t / 3] > reach) continue;
      a.fromBufferAttribute(position, index.getX(t));
      b.fromBufferAttribute(position, index.getX(t + 1));
      c.fromBufferAttribute(position, index.getX(t + 2));
      sum.add(n.subVectors(b, a).cross(c.sub(a))); // twice the area, outward for the target's triangles
    }
    return sum.lengthSq() > 0 ? sum.normalize() : null;
  }

  // Whether a point on the target's surface (its own units, a Vector3 or [x, y, z]) is seen from the camera:
  // nothing of the target lies between (a point behind the model is not one to click, snap to or label).
  isVisible(position) {
    if (!this.mesh) return false;
    const world = this.mesh.localToWorld(Array.isArray(position) ? new Vector3(...position) : position.clone());
    const eye = this.camera.position;
    const distance = eye.distanceTo(world);
    this.raycaster.set(eye, world.clone().sub(eye).normalize());
    const hit = this.raycaster.intersectObject(this.mesh, false)[0];
    // A point on the surface is hit at its own distance, give or take a sliver of the model's size.
    const tolerance = 0.002 * this.mesh.geometry.boundingSphere.radius * this.mesh.scale.x;
    return !hit || hit.distance >= distance - tolerance;
  }

  // Screen distance in pixels between a pointer event and a point in the target's own coordinates.
  screenDistance(event, position) {
    const r = this.element.getBoundingClientRect();
    const p = this.mesh.localToWorld(new Vector3(position[0], position[1], position[2])).project(this.camera);
    const x = ((p.x + 1) / 2) * r.width + r.left;
    const y = ((1 - p.y) / 2) * r.height + r.top;
    return Math.hypot(x - event.clientX, y - event.clientY);
  }

  render(renderer, aspect) {
    const r = this.element.getBoundingClientRect();
    this.seams?.setResolution(r.width, r.height);
    super.render(renderer, aspect);
    this.placeLabels();
  }
}
