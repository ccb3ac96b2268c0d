// A small picture of a balloon for a card (the suggested layouts, app/suggest.js): its outer surface on a 2D canvas,
// triangles back to front (the painter's algorithm), each lit from the viewer's side times its distance color as the
// inflated pane has it, and its seams (edges between two panels) as dark lines. No WebGL: a dozen cards would each
// need a context of their own, and browsers keep only a few.
import { Color, Matrix4, Vector3 } from 'three';
import { distanceColor, distanceScaleOf } from './inflated-pane.js';

export const THUMBNAIL = { width: 160, height: 120 }; // CSS pixels
const MARGIN = 6;
const LIGHT = new Vector3(1, 2, 1.5).normalize(); // the panes' key light, which follows the viewer (pane3d.js)
const AMBIENT = 0.45; // the rest of the light, so the side turned away still shows its color
const SEAM = 'rgba(25, 30, 40, 0.9)';
const OUTLINE = 'rgba(25, 30, 40, 0.35)';
// The panes' first view (pane3d.js DEFAULT_VIEW), for a picture drawn with no pane to look from.
const DEFAULT_VIEW = new Matrix4().lookAt(new Vector3(0.35, 0.3, 1), new Vector3(), new Vector3(0, 1, 0)).transpose();

// The rotation from a pane's shape's own axes (its group, turned to stand on the design's up axis) to its camera's
// (x right, y up, z towards the viewer).
export function viewOf(pane) {
  if (!pane?.camera || !pane?.group) return DEFAULT_VIEW.clone();
  pane.camera.updateMatrixWorld();
  pane.group.updateMatrixWorld();
  return new Matrix4().extractRotation(new Matrix4().multiplyMatrices(pane.camera.matrixWorldInverse, pane.group.matrixWorld));
}

// Draws balloon ({ positions #V*3, triangles #F*3 (outward), distance #V (signed, over the target's diagonal),
// panel #F }) on canvas, seen through view (viewOf), whole and centred, at the device's pixel ratio.
export function drawBalloon(canvas, balloon, view = DEFAULT_VIEW) {
  const { width, height } = THUMBNAIL;
  const ratio = Math.min(window.devicePixelRatio || 1, 3);
  canvas.width = Math.round(width * ratio);
  canvas.height = Math.round(height * ratio);
  const context = canvas.getContext('2d');
  context.setTransform(ratio, 0, 0, ratio, 0, 0);
  context.clearRect(0, 0, width, height);
  const { positions, triangles, distance, panel } = balloon;
  const n = positions.length / 3;
  if (!n) return;
  // The vertices in the viewer's axes (orthographic: a thumbnail needs no perspective).
  const e = view.elements; // column-major
  const p = new Float64Array(3 * n);
  for (let v = 0; v < n; v++) {
    const [x, y, z] = [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
    for (let k = 0; k < 3; k++) p[3 * v + k] = e[k] * x + e[4 + k] * y + e[8 + k] * z;
  }
  // Each triangle's normal (area-weighted) and each vertex's, whose light the triangles share, so the surface reads
  // smooth as the inflated pane draws it rather than as facets.
  const faceCount = triangles.length / 3;
  const normals = new Float64Array(3 * faceCount);
  const u = new Vector3();
  const w = new Vector3();
  for (let f = 0; f < faceCount; f++) {
    const [a, b, c] = [triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2]];
    u.set(p[3 * b] - p[3 * a], p[3 * b + 1] - p[3 * a + 1], p[3 * b + 2] - p[3 * a + 2]);
    w.set(p[3 * c] - p[3 * a], p[3 * c + 1] - p[3 * a + 1], p[3 * c + 2] - p[3 * a + 2]);
    u.cross(w).toArray(normals, 3 * f);
  }
  turnToBroadSide(p, normals);
  const vertexNormals = new Float64Array(3 * n);
  for (let f = 0; f < faceCount; f++)
    for (let k = 0; k < 3; k++) for (let c = 0; c < 3; c++) vertexNormals[3 * triangles[3 * f + k] + c] += normals[3 * f + c];
  const low = [Infinity, Infinity];
  const high = [-Infinity, -Infinity];
  for (let v = 0; v < n; v++)
    for (let k = 0; k < 2; k++) {
      low[k] = Math.min(low[k], p[3 * v + k]);
      high[k] = Math.max(high[k], p[3 * v + k]);
    }
  const scale = Math.min((width - 2 * MARGIN) / (high[0] - low[0] || 1), (height - 2 * MARGIN) / (high[1] - low[1] || 1));
  const sx = (v) => width / 2 + (p[3 * v] - (low[0] + high[0]) / 2) * scale;
  const sy = (v) => height / 2 - (p[3 * v + 1] - (low[1] + high[1]) / 2) * scale;
  const light = new Float64Array(n);
  const normal = new Vector3();
  for (let v = 0; v < n; v++) light[v] = AMBIENT + (1 - AMBIENT) * Math.max(0, normal.fromArray(vertexNormals, 3 * v).normalize().dot(LIGHT));
  // The triangles facing the viewer (the surface is closed), farthest first, each with its light and color.
  const faces = [];
  const facing = new Uint8Array(faceCount);
  const fullColor = distanceScaleOf(1);
  for (let f = 0; f < faceCount; f++) {
    if (!(normals[3 * f + 2] > 0)) continue;
    const [a, b, c] = [triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2]];
    facing[f] = 1;
    const lit = (light[a] + light[b] + light[c]) / 3;
    const color = distanceColor((distance[a] + distance[b] + distance[c]) / 3 / fullColor, new Color()).multiplyScalar(lit);
    faces.push({ f, depth: p[3 * a + 2] + p[3 * b + 2] + p[3 * c + 2], color: `#${color.getHexString()}`, lines: [] });
  }
  faces.sort((x, y) => x.depth - y.depth);
  const order = new Int32Array(faceCount).fill(-1);
  faces.forEach((face, k) => (order[face.f] = k));
  // Each seam edge, and each edge of the outline (one side turned away), is drawn after the later of its faces in
  // view, so that the face beside it does not cover half of its line and the nearer ones do cover it.
  const across = new Map();
  for (let f = 0; f < faceCount; f++)
    for (let k = 0; k < 3; k++) {
      const a = triangles[3 * f + k];
      const b = triangles[3 * f + ((k + 1) % 3)];
      const key = Math.min(a, b) * n + Math.max(a, b);
      const g = across.get(key);
      if (g === undefined) {
        across.set(key, f);
        continue;
      }
      across.delete(key);
      const seam = panel[f] !== panel[g];
      if (!seam && facing[f] === facing[g]) continue;
      const later = Math.max(order[f], order[g]);
      if (later >= 0) faces[later].lines.push([a, b, seam]);
    }
  context.lineJoin = 'round';
  context.lineCap = 'round';
  for (const face of faces) {
    const [a, b, c] = [triangles[3 * face.f], triangles[3 * face.f + 1], triangles[3 * face.f + 2]];
    context.beginPath();
    context.moveTo(sx(a), sy(a));
    context.lineTo(sx(b), sy(b));
    context.lineTo(sx(c), sy(c));
    context.closePath();
    context.fillStyle = context.strokeStyle = face.color;
    context.lineWidth = 0.6; // over the hairline gaps antialiasing leaves between neighbours
    context.fill();
    context.stroke();
    for (const [s, t, seam] of face.lines) {
      context.beginPath();
      context.moveTo(sx(s), sy(s));
      context.lineTo(sx(t), sy(t));
      context.strokeStyle = seam ? SEAM : OUTLINE;
      context.lineWidth = seam ? 1.3 : 1;
      context.stroke();
    }
  }
}

// A flat balloon (two pieces sealed along an outline) seen edge on is a sliver: where the view shows less than
// BROAD_SIDE of the most it could, the picture turns about the viewer's vertical to the turn that shows the most
// (its up stays up). Turns positions and normals (x right, y up, z towards the viewer) in place.
const BROAD_SIDE = 0.6;
const TURNS = 12;
export function turnToBroadSide(p, normals) {
  // The area seen turned by theta: the normals' z after the turn, where positive.
  const seen = (theta) => {
    const [c, s] = [Math.cos(theta), Math.sin(theta)];
    let area = 0;
    for (let f = 0; f < normals.length; f += 3) area += Math.max(0, c * normals[f + 2] - s * normals[f]);
    return area;
  };
  let best = 0;
  let most = seen(0);
  const asSeen = most;
  for (let k = 1; k < TURNS; k++) {
    const area = seen((Math.PI * k) / TURNS);
    if (area > most) (most = area), (best = (Math.PI * k) / TURNS);
  }
  if (asSeen >= BROAD_SIDE * most) return;
  const [c, s] = [Math.cos(best), Math.sin(best)];
  for (const a of [p, normals])
    for (let i = 0; i < a.length; i += 3) [a[i], a[i + 2]] = [c * a[i] + s * a[i + 2], -s * a[i] + c * a[i + 2]];
}
