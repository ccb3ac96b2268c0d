// Small geometry shared by the panes and the app's rules.

// The distance from p to the segment from a to b, points of any dimension (2D on the pattern, 3D on the target).
export function segmentDistance(p, a, b) {
  let l2 = 0;
  let dot = 0;
  for (let i = 0; i < a.length; i++) {
    const d = b[i] - a[i];
    l2 += d * d;
    dot += d * (p[i] - a[i]);
  }
  const t = l2 > 0 ? Math.max(0, Math.min(1, dot / l2)) : 0;
  let r2 = 0;
  for (let i = 0; i < a.length; i++) r2 += (a[i] + t * (b[i] - a[i]) - p[i]) ** 2;
  return Math.sqrt(r2);
}

// The distance from p to the polyline through `points` (closed: back to the first), points of any dimension.
export function polylineDistance(p, points, closed) {
  const n = points.length;
  let best = segmentDistance(p, points[0], points[0]);
  for (let k = 0; k + 1 < n + (closed ? 1 : 0); k++) best = Math.min(best, segmentDistance(p, points[k], points[(k + 1) % n]));
  return best;
}
