// The suggested layouts' card pictures (web/src/views/balloon-thumbnail.js): a flat balloon (two pieces sealed along
// an outline) seen edge on is a sliver, so the picture turns about the viewer's vertical to its broad side; a round
// one, or one seen broadly enough, stays as the target pane shows it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { turnToBroadSide } from '../../web/src/views/balloon-thumbnail.js';

// An ellipsoid with semi-axes (a, b, c) in the viewer's axes: positions and its triangles' normals (area-weighted,
// outward), as drawBalloon hands them.
function ellipsoid(a, b, c, rings = 24, segments = 48) {
  const points = [];
  for (let i = 0; i <= rings; i++)
    for (let j = 0; j < segments; j++) {
      const [theta, phi] = [(Math.PI * i) / rings, (2 * Math.PI * j) / segments];
      points.push([a * Math.sin(theta) * Math.cos(phi), b * Math.cos(theta), c * Math.sin(theta) * Math.sin(phi)]);
    }
  const at = (i, j) => i * segments + (j % segments);
  const normals = [];
  for (let i = 0; i < rings; i++)
    for (let j = 0; j < segments; j++)
      for (const [p, q, r] of [[at(i, j), at(i + 1, j), at(i + 1, j + 1)], [at(i, j), at(i + 1, j + 1), at(i, j + 1)]]) {
        const u = points[q].map((x, k) => x - points[p][k]);
        const w = points[r].map((x, k) => x - points[p][k]);
        const n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
        const centre = [0, 1, 2].map((k) => (points[p][k] + points[q][k] + points[r][k]) / 3);
        const sign = Math.sign(n[0] * centre[0] + n[1] * centre[1] + n[2] * centre[2]) || 1;
        normals.push(...n.map((x) => sign * x));
      }
  return { p: Float64Array.from(points.flat()), normals: Float64Array.from(normals) };
}
const extent = (p, k) => {
  let [lo, hi] = [Infinity, -Infinity];
  for (let i = k; i < p.length; i += 3) (lo = Math.min(lo, p[i])), (hi = Math.max(hi, p[i]));
  return hi - lo;
};

test('a flat balloon seen edge on turns to its broad side, about the vertical', () => {
  const { p, normals } = ellipsoid(0.05, 0.5, 0.5); // thin across x: seen along z, a sliver 0.1 wide
  assert.ok(extent(p, 0) < 0.11);
  turnToBroadSide(p, normals);
  assert.ok(extent(p, 0) > 0.9, `${extent(p, 0)} wide after the turn`);
  assert.ok(Math.abs(extent(p, 1) - 1) < 1e-9, 'up stays up');
});

test('a balloon seen broadly enough stays as the pane shows it', () => {
  for (const [a, c] of [[0.5, 0.5], [0.3, 0.5], [0.5, 0.05]]) {
    const { p, normals } = ellipsoid(a, 0.5, c);
    const before = Float64Array.from(p);
    turnToBroadSide(p, normals);
    assert.deepEqual(p, before, `${a} x ${c}`);
  }
});
