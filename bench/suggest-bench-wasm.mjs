// Suggested seam layouts in wasm, as the app's worker runs them (its handlers over the module, in Node): per mesh of
// ../shared/meshes, 0.6 m tall, mirror-symmetric where it has a mirror plane, the app's settings (1,000 triangles,
// at most 40 iterations, the six closest optimized): the time until the first layout shows (its first look), until
// the first optimized one, until the end, and the best layout's distance (the worse way, % of the diagonal).
//   node --no-experimental-fetch bench/suggest-bench-wasm.mjs [--panels 12] [--meshes koala,spot,blub]
import { loadApi } from '../tests/node/load-module.mjs';
import { loadSharedMesh } from '../tests/node/obj.mjs';
import { createHandlers } from '../web/src/worker/handlers.js';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const panels = Number(arg('--panels', '12'));
const meshes = arg('--meshes', 'koala,spot,blub').split(',');
const HEIGHT = 0.6;

const api = await loadApi();
const drive = (generator, onProgress) => {
  for (let step = generator.next(); ; step = generator.next()) {
    if (step.done) return step.value;
    onProgress(step.value);
  }
};

console.log(`| mesh | panels asked | first layout s | first optimized s | all s | layouts tried | best layout | panels | distance % |`);
console.log('|---|---|---|---|---|---|---|---|---|');
for (const name of meshes) {
  const mesh = loadSharedMesh(`${name}.obj`);
  const handlers = createHandlers(api);
  drive(handlers.setTarget({ positions: mesh.positions, indices: mesh.indices }), () => {});
  let lo = Infinity;
  let hi = -Infinity;
  for (let v = 1; v < mesh.positions.length; v += 3) (lo = Math.min(lo, mesh.positions[v])), (hi = Math.max(hi, mesh.positions[v]));
  const { axis } = drive(handlers.mirrorSymmetry(), () => {});
  const t0 = performance.now();
  let firstLook = null;
  let firstOptimized = null;
  const result = drive(
    handlers.suggestSeams({ panels, symmetry: axis, scale: HEIGHT / (hi - lo), up: '+y', triangles: 1000, maxIterations: 40, optimize: 6 }),
    (p) => {
      if (p.look && firstLook === null) firstLook = performance.now() - t0;
      if (p.layout && firstOptimized === null) firstOptimized = performance.now() - t0;
    },
  );
  const all = performance.now() - t0;
  const best = result.layouts[0];
  const s = (ms) => (ms === null ? '—' : (ms / 1000).toFixed(1));
  console.log(`| ${name}${axis ? ` (mirror ${axis})` : ''} | ${panels} | ${s(firstLook)} | ${s(firstOptimized)} | ${s(all)} | ${result.tried} | ${best?.name ?? 'none'} | ${best?.panels ?? '—'} | ${best ? (100 * best.distance).toFixed(2) : '—'} |`);
}
