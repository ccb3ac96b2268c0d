// A capsule along x (a tube of radius r, `length` long, closed by hemispheres), `around` vertices to a ring, the rings
// staggered, triangles facing out: a sausage balloon, and a long closed-ended tube no single panel lies flat on.
export function capsuleMesh(around, r, length) {
  const rings = Math.floor(length / (2 * Math.PI * r / around)), cap = around / 4, profile = [];
  for (let i = 1; i < cap; i++) profile.push([-length / 2 - r * Math.cos(Math.PI / 2 * i / cap), r * Math.sin(Math.PI / 2 * i / cap)]);
  for (let i = 0; i <= rings; i++) profile.push([-length / 2 + length * i / rings, r]);
  for (let i = 1; i < cap; i++) profile.push([length / 2 + r * Math.sin(Math.PI / 2 * i / cap), r * Math.cos(Math.PI / 2 * i / cap)]);
  const positions = [], indices = [], n = profile.length, id = (k, j) => k * around + (j % around);
  profile.forEach(([x, radius], k) => {
    for (let j = 0; j < around; j++) {
      const a = 2 * Math.PI * (j + 0.5 * (k % 2)) / around;
      positions.push(x, radius * Math.cos(a), radius * Math.sin(a));
    }
  });
  positions.push(-length / 2 - r, 0, 0, length / 2 + r, 0, 0);
  for (let k = 0; k + 1 < n; k++) {
    for (let j = 0; j < around; j++) {
      if (k % 2 === 0) indices.push(id(k, j), id(k, j + 1), id(k + 1, j), id(k, j + 1), id(k + 1, j + 1), id(k + 1, j));
      else indices.push(id(k, j), id(k, j + 1), id(k + 1, j + 1), id(k, j), id(k + 1, j + 1), id(k + 1, j));
    }
  }
  for (let j = 0; j < around; j++) indices.push(n * around, id(0, j + 1), id(0, j), n * around + 1, id(n - 1, j), id(n - 1, j + 1));
  return { positions: Float64Array.from(positions), indices: Uint32Array.from(indices) };
}
