// The module's warm-up: a small foil balloon optimized while the worker has nothing to do, so the designer's first
// optimization runs in optimized code. A fresh module runs in baseline code until each function has run often
// enough to be compiled again (V8's tiering), which doubled the time to the first look at the inflated panels
// (bench/README.md "The module's warm-up").
import { STEP_MILLIS } from './handlers.js';
import { TargetSession } from './solver-api.js';

// Optimizer iterations on 300 triangles, at most (the optimizer may stop first): enough for the solver's and the
// optimizer's loops to be compiled again (a 3,000-element design's iterations then take as long as in a process that
// has optimized another before).
const WARM_UP_ITERATIONS = 20;
const SCALE = 0.3; // meters per target unit: a balloon 0.48 m tall

// An ellipsoid (semi-axes 1, 0.8 and 0.45, poles on z) meshed by latitude rings, with the ring at z = 0 among
// them: { positions, indices, equator } (equator: the ring's vertex indices, in order around it).
export function warmUpTarget(segments = 24, rings = 12) {
  const positions = [0, 0, 0.45];
  for (let r = 1; r < rings; r++) {
    const theta = (Math.PI * r) / rings;
    for (let s = 0; s < segments; s++) {
      const phi = (2 * Math.PI * s) / segments;
      positions.push(Math.sin(theta) * Math.cos(phi), 0.8 * Math.sin(theta) * Math.sin(phi), 0.45 * Math.cos(theta));
    }
  }
  positions.push(0, 0, -0.45);
  const south = positions.length / 3 - 1;
  const at = (r, s) => 1 + (r - 1) * segments + (s % segments);
  const indices = [];
  for (let s = 0; s < segments; s++) {
    indices.push(0, at(1, s), at(1, s + 1));
    indices.push(south, at(rings - 1, s + 1), at(rings - 1, s));
    for (let r = 1; r < rings - 1; r++) indices.push(at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s), at(r + 1, s + 1), at(r, s + 1));
  }
  const equator = Array.from({ length: segments }, (_, s) => at(rings / 2, s));
  return { positions, indices, equator };
}

// The seam along the equator: control points on every third of its vertices, each given as its corner of a
// triangle (as the seam tool's points are: a face and barycentric coordinates).
function equatorSeam({ indices, equator }) {
  const points = [];
  for (let i = 0; i < equator.length; i += 3) {
    const k = indices.indexOf(equator[i]);
    points.push({ face: Math.floor(k / 3), bary: [0, 1, 2].map((c) => (c === k % 3 ? 1 : 0)) });
  }
  return { points, closed: true, weight: 1 };
}

// A generator of short steps (the worker's runner takes one at a time while it has nothing else to do): the
// balloon's two panels built and optimized for a few iterations, on a session of its own, so the worker's target
// and design are untouched. Returns the iterations made.
export function* warmUp(api) {
  const target = warmUpTarget();
  const session = new TargetSession(api);
  try {
    session.setTarget(target.positions, target.indices);
    yield;
    const start = session.startOptimization([equatorSeam(target)], { scale: SCALE, triangles: 300, pressure: 1000, material: { name: 'foil' } });
    if (!start.ok) return 0;
    let done = 0;
    for (let step = 0; done < WARM_UP_ITERATIONS; step = 1) {
      yield;
      const status = session.optimizeStep(step, STEP_MILLIS); // the flattened panels' first equilibrium, then iterations
      done = status.iteration;
      if (status.state !== 'running') break;
      session.optimizedDistance(SCALE); // as the worker measures each iterate it streams
    }
    return done;
  } finally {
    session.delete();
  }
}
