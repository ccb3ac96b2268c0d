// A closed triangle mesh of the surface f = 0 (f < 0 inside), by marching tetrahedra on an n^3 grid over the cube
// [lo, hi]^3 (each cell in six tetrahedra around its diagonal): shapes for tests that no mesh of ../shared/meshes has
// (a mug's handle). Vertices are shared along grid edges, so the surface is closed and manifold where f is smooth.
export function implicitMesh(f, lo, hi, n) {
  const h = (hi - lo) / n, N = n + 1;
  const id = (i, j, k) => (i * N + j) * N + k;
  const corner = (g) => {
    const k = g % N, j = Math.floor(g / N) % N, i = Math.floor(g / (N * N));
    return [lo + i * h, lo + j * h, lo + k * h];
  };
  const value = new Float64Array(N * N * N);
  for (let g = 0; g < value.length; g++) {
    const v = f(...corner(g));
    value[g] = v === 0 ? 1e-12 : v; // every sign change is an edge's
  }
  const positions = [], indices = [], onEdge = new Map();
  const cut = (a, b) => {
    const key = Math.min(a, b) * value.length + Math.max(a, b);
    if (!onEdge.has(key)) {
      // Kept off the corners, where a cut point next to one makes a triangle of no area.
      const t = Math.min(0.95, Math.max(0.05, value[a] / (value[a] - value[b]))), pa = corner(a), pb = corner(b);
      onEdge.set(key, positions.length / 3);
      positions.push(...pa.map((x, c) => x + t * (pb[c] - x)));
    }
    return onEdge.get(key);
  };
  // A triangle turned so that its normal points away from `inside`.
  const triangle = (p, q, r, inside) => {
    const [P, Q, R] = [p, q, r].map((v) => positions.slice(3 * v, 3 * v + 3));
    const e = Q.map((x, c) => x - P[c]), g = R.map((x, c) => x - P[c]);
    const n = [e[1] * g[2] - e[2] * g[1], e[2] * g[0] - e[0] * g[2], e[0] * g[1] - e[1] * g[0]];
    const out = n[0] * (P[0] - inside[0]) + n[1] * (P[1] - inside[1]) + n[2] * (P[2] - inside[2]);
    indices.push(...(out >= 0 ? [p, q, r] : [p, r, q]));
  };
  const mean = (gs) => [0, 1, 2].map((c) => gs.reduce((s, g) => s + corner(g)[c], 0) / gs.length);
  const TETRAHEDRA = [[0, 1, 3, 7], [0, 3, 2, 7], [0, 2, 6, 7], [0, 6, 4, 7], [0, 4, 5, 7], [0, 5, 1, 7]];
  for (let i = 0; i < n; i++)
    for (let j = 0; j < n; j++)
      for (let k = 0; k < n; k++) {
        const cell = [0, 1, 2, 3, 4, 5, 6, 7].map((b) => id(i + (b >> 2), j + ((b >> 1) & 1), k + (b & 1)));
        for (const tet of TETRAHEDRA) {
          const g = tet.map((t) => cell[t]);
          const inside = g.filter((x) => value[x] < 0), outside = g.filter((x) => value[x] >= 0);
          if (inside.length === 1) triangle(...outside.map((o) => cut(inside[0], o)), corner(inside[0]));
          else if (inside.length === 3) triangle(...inside.map((x) => cut(outside[0], x)), mean(inside));
          else if (inside.length === 2) {
            const [a, b] = inside, [p, q] = outside, centre = mean(inside);
            triangle(cut(a, p), cut(a, q), cut(b, q), centre);
            triangle(cut(a, p), cut(b, q), cut(b, p), centre);
          }
        }
      }
  return { positions: Float64Array.from(positions), indices: Uint32Array.from(indices) };
}
