// The design benchmark in wasm (Node), as the app's worker runs it (bench/README.md "Pattern optimization"):
// per design of bench/designs/manifest.json, through the worker's handlers (web/src/worker/handlers.js),
// so every iterate's shape and its distance to the target are computed as the app streams them.
//   node bench/design-bench-wasm.mjs [--json] [--designs sphere3,teddy] [--max-seconds S] [--triangles N] [--trace]
//                                    [--json-out FILE] [--perturb SEED]
// --triangles overrides every design's element count (quick runs), as in the native bench; --json-out FILE writes the
// rows --json prints besides the table (bench/table1.mjs reads them).
// Needs build/wasm/billow.{mjs,wasm}; BILLOW_WASM_DIR overrides.
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadApi } from '../tests/node/load-module.mjs';
import { createHandlers } from '../web/src/worker/handlers.js';
import { warmUp } from '../web/src/worker/warm-up.js';

const HERE = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? args[args.indexOf(name) + 1] : fallback);
const asJson = args.includes('--json');
const trace = args.includes('--trace');  // each iterate's status on stderr
const only = option('--designs', '').split(',').filter(Boolean);
const maxSeconds = Number(option('--max-seconds', 600));
const triangles = Number(option('--triangles', 0));
// > 0: every seam control point inside its face moves by 1e-9 of its barycentric coordinates (a seeded draw), so the
// run takes another path of the same design, as the native bench's --perturb does (one wasm run is one path).
const perturb = Number(option('--perturb', 0));
const manifestPath = resolve(option('--manifest', join(HERE, 'designs/manifest.json')));
const manifest = JSON.parse(readFileSync(manifestPath, 'utf8'));

// The largest move of a vertex between two shapes of one mesh (flat x, y, z arrays).
function largestMove(a, b) {
  let worst = 0;
  for (let i = 0; i < b.length; i += 3) worst = Math.max(worst, Math.hypot(a[i] - b[i], a[i + 1] - b[i + 1], a[i + 2] - b[i + 2]));
  return worst;
}

// The squared distance from p to triangle (a, b, c) (points as [x, y, z]): the closest point by the region
// of the triangle p projects to (vertex, edge or face).
function triangleDistance2(p, a, b, c) {
  const sub = (u, v) => [u[0] - v[0], u[1] - v[1], u[2] - v[2]];
  const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const at = (o, u, s, v, t) => [o[0] + s * u[0] + t * v[0], o[1] + s * u[1] + t * v[1], o[2] + s * u[2] + t * v[2]];
  const ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const d1 = dot(ab, ap), d2 = dot(ac, ap);
  let q;
  if (d1 <= 0 && d2 <= 0) q = a;
  else {
    const bp = sub(p, b), d3 = dot(ab, bp), d4 = dot(ac, bp);
    const cp = sub(p, c), d5 = dot(ab, cp), d6 = dot(ac, cp);
    const vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (d3 >= 0 && d4 <= d3) q = b;
    else if (d6 >= 0 && d5 <= d6) q = c;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0) q = at(a, ab, d1 / (d1 - d3), ac, 0);
    else if (vb <= 0 && d2 >= 0 && d6 <= 0) q = at(a, ab, 0, ac, d2 / (d2 - d6));
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) q = at(b, sub(c, b), (d4 - d3) / (d4 - d3 + (d5 - d6)), ab, 0);
    else {
      const denominator = va + vb + vc;
      q = at(a, ab, vb / denominator, ac, vc / denominator);
    }
  }
  const d = sub(p, q);
  return dot(d, d);
}

// The triangles tb of the shape b binned by their bounding boxes into cells of size tol, so the 27 cells around a
// point hold every triangle within tol of it.
function surfaceCells(b, tb, tol) {
  const cells = new Map(), cell = (x) => Math.floor(x / tol);
  for (let f = 0; f < tb.length; f += 3) {
    const lo = [0, 1, 2].map((d) => cell(Math.min(b[3 * tb[f] + d], b[3 * tb[f + 1] + d], b[3 * tb[f + 2] + d])));
    const hi = [0, 1, 2].map((d) => cell(Math.max(b[3 * tb[f] + d], b[3 * tb[f + 1] + d], b[3 * tb[f + 2] + d])));
    for (let i = lo[0]; i <= hi[0]; i++)
      for (let j = lo[1]; j <= hi[1]; j++)
        for (let k = lo[2]; k <= hi[2]; k++) {
          const list = cells.get(`${i},${j},${k}`);
          if (list) list.push(f);
          else cells.set(`${i},${j},${k}`, [f]);
        }
  }
  return { b, tb, tol, cell, cells };
}

// Whether some vertex of the shape a lies farther than tol from the surface binned in `surface` (surfaceCells).
function fartherThan(a, { b, tb, tol, cell, cells }) {
  const corner = (t) => [b[3 * t], b[3 * t + 1], b[3 * t + 2]];
  for (let v = 0; v < a.length; v += 3) {
    const p = [a[v], a[v + 1], a[v + 2]], [ci, cj, ck] = p.map(cell);
    let near = false;
    for (let i = ci - 1; i <= ci + 1 && !near; i++)
      for (let j = cj - 1; j <= cj + 1 && !near; j++)
        for (let k = ck - 1; k <= ck + 1 && !near; k++)
          for (const f of cells.get(`${i},${j},${k}`) ?? [])
            if (triangleDistance2(p, corner(tb[f]), corner(tb[f + 1]), corner(tb[f + 2])) <= tol * tol) {
              near = true;
              break;
            }
    if (!near) return true;
  }
  return false;
}

const api = await loadApi();
// The module warmed as the app's worker warms it while the designer opens a shape and draws its seams, so the first
// design runs in optimized code as a designer's first optimization does (web/src/worker/warm-up.js).
for (const _ of warmUp(api)); // eslint-disable-line no-unused-vars

// A seeded uniform draw in [-1, 1) (mulberry32).
let seed = perturb >>> 0;
function draw() {
  seed = (seed + 0x6d2b79f5) >>> 0;
  let t = seed;
  t = Math.imul(t ^ (t >>> 15), t | 1);
  t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
  return (((t ^ (t >>> 14)) >>> 0) / 4294967296) * 2 - 1;
}

// A seam point's barycentric coordinates nudged within its face (a point on an edge or a vertex stays there).
function nudged(point) {
  if (!point.bary || point.bary.some((b) => b < 1e-5)) return point;
  const bary = point.bary.map((b) => b * (1 + 1e-9 * draw()));
  const sum = bary[0] + bary[1] + bary[2];
  return { ...point, bary: bary.map((b) => b / sum) };
}

// The design's target mesh, read as the app and the command line read it (the module's reader).
function targetOf(design, designPath) {
  const t = design.target;
  const file = t.example ? join(HERE, '../web/public/examples', `${t.example}.obj`) : resolve(dirname(designPath), t.obj);
  return api.readMeshFile(file, readFileSync(file), 10_000_000);
}

function run(entry) {
  const designPath = resolve(dirname(manifestPath), entry.file);
  const design = JSON.parse(readFileSync(designPath, 'utf8'));
  const target = targetOf(design, designPath);
  let lo = Infinity, hi = -Infinity;
  for (let i = 1; i < target.positions.length; i += 3) (lo = Math.min(lo, target.positions[i])), (hi = Math.max(hi, target.positions[i]));
  const scale = design.size.height / (hi - lo);
  const handlers = createHandlers(api);
  const t0 = performance.now();
  // The design's repairs of its target, as the app makes them when it opens the design.
  const repairs = { cutThinHandles: Boolean(design.target.cutThinHandles), closeHoles: Boolean(design.target.closeHoles) };
  for (const _ of handlers.setTarget({ ...target, ...repairs })); // eslint-disable-line no-unused-vars
  const seams = design.seams.map(({ points, closed, weight, name }) => ({ points: perturb > 0 ? points.map(nudged) : points, closed, weight: weight ?? 1, name }));
  const job = handlers.optimizeDesign({
    seams, scale, triangles: triangles > 0 ? triangles : entry.triangles, maxIterations: 300, pressure: design.pressure, material: design.material,
    connections: design.connections ?? [],
  });
  const shapes = [];
  let tStart = 0, last = null, first = null, patternSeconds = 0, meshTriangles = null;
  for (let step = job.next(); !step.done; step = job.next()) {
    const v = step.value;
    if (v.stage !== 'optimizing') continue;
    if (v.iteration === 0 && !first) (first = v), (patternSeconds = (performance.now() - t0) / 1000), (tStart = performance.now());
    last = v;
    if (v.triangles) meshTriangles = v.triangles; // from this iterate on (a coarse first phase streams its own mesh)
    // Preview time counts from the start of the job (the target, the panels and the first inflation), as
    // the designer waits for it. The first iterate is the built panels before any inflation (the target's own
    // surface): no preview; the second is the first inflation (iteration 0 again).
    if (v !== first) shapes.push({ iteration: v.iteration ?? 0, seconds: (performance.now() - t0) / 1000, positions: v.positions, triangles: meshTriangles, remeshings: v.remeshings ?? 0 });
    if (trace) {
      const scalars = Object.entries(v).filter(([, x]) => typeof x === 'number' || typeof x === 'string' || typeof x === 'boolean');
      console.error(`${entry.name} ${((performance.now() - t0) / 1000).toFixed(2)} s ${scalars.filter(([k]) => k !== 'stage').map(([k, x]) => `${k} ${typeof x === 'number' ? +x.toPrecision(4) : x}`).join(' ')}`);
    }
    if ((performance.now() - tStart) / 1000 > maxSeconds) break;
  }
  const seconds = (performance.now() - tStart) / 1000;
  // Preview quality: the first iterate within 5 % of the model size (the target's diagonal) of the final one: the
  // largest vertex move on the same mesh, else (before a remeshing) every vertex of either within that of the other's
  // surface, as shapeDistance in design_bench.cpp.
  const final = last.positions, diagonal = first.distance.diagonal, tol = 0.05 * diagonal;
  const finalRemeshings = last.remeshings ?? 0;
  const finalSurface = surfaceCells(final, meshTriangles, tol);
  let preview = null;
  for (const s of shapes) {
    const close = s.remeshings === finalRemeshings ? largestMove(s.positions, final) < tol
      : !fartherThan(s.positions, finalSurface) && !fartherThan(final, surfaceCells(s.positions, s.triangles, tol));
    if (close) { preview = s; break; }
  }
  const pattern = JSON.parse(first.flattenedText);
  return {
    design: entry.name, class: entry.class, elements: meshTriangles.length / 3, panels: pattern.panels.length,
    internalPanels: pattern.panels.filter((p) => p.internal).length, remeshingSteps: last.remeshings ?? 0,
    iterations: last.iteration ?? 0, patternSeconds, previewIteration: preview?.iteration ?? -1, previewSeconds: preview?.seconds ?? 0,
    seconds, state: last.state ?? 'time limit', message: last.message ?? '',
    flattenedDistanceRms: last.flattenedDistanceRms ?? null, distanceRms: last.distance.rms, distanceMax: last.distance.max,
    targetDistanceRms: last.distance.targetRms, targetDistanceMax: last.distance.targetMax,
    seamMismatch: last.seamMismatch, heapMb: api.memoryStats().heapBytes / 2 ** 20,
  };
}

const rows = [];
if (!asJson)
  console.log(['design', 'class', 'elems', 'panels', 'iters', 'pattern s', 'preview s', 'full s', 'rms %', 'max %', 'tgt %', 'seam', 'heap MB', 'state'].map((h, i) => (i < 2 ? h.padEnd(9) : h.padStart(9))).join(' '));
for (const entry of manifest.designs) {
  if (only.length && !only.includes(entry.name)) continue;
  let row;
  try {
    row = run(entry);
  } catch (error) {
    row = { design: entry.name, error: error.message };
  }
  rows.push(row);
  if (asJson) continue;
  if (row.error) {
    console.log(`${entry.name.padEnd(9)} ${row.error}`);
    continue;
  }
  console.log([
    row.design.padEnd(9), row.class.padEnd(9), String(row.elements).padStart(9), `${row.panels} (${row.internalPanels})`.padStart(9),
    String(row.iterations).padStart(9), row.patternSeconds.toFixed(2).padStart(9), row.previewSeconds.toFixed(2).padStart(9),
    row.seconds.toFixed(2).padStart(9), (100 * row.distanceRms).toFixed(3).padStart(9), (100 * row.distanceMax).toFixed(3).padStart(9),
    (100 * row.targetDistanceRms).toFixed(3).padStart(9), (row.seamMismatch ?? 0).toExponential(1).padStart(9), row.heapMb.toFixed(0).padStart(9), row.state,
  ].join(' '));
}
const result = { runtime: 'wasm (node)', rows };
if (asJson) console.log(JSON.stringify(result, null, 2));
const jsonOut = option('--json-out', null);
if (jsonOut) writeFileSync(jsonOut, `${JSON.stringify(result, null, 2)}\n`);
