// Suggested seam layouts in wasm, as the app runs them (web/src/app/suggest-run.js over worker threads running the
// worker's handlers, in Node): per mesh of ../shared/meshes, 0.6 m tall, mirror-symmetric where it has a mirror plane,
// the app's settings (1,000 triangles, at most 40 iterations, the eight most promising optimized), with one worker and with as
// many as the app starts here (one per core, at most 4): the time until the first layout shows (its first look), until
// the first optimized one, until the end, and the best layout's distance (the worse way, % of the diagonal).
//   node --no-experimental-fetch bench/suggest-bench-wasm.mjs [--panels 12] [--meshes koala,spot,blub] [--workers 1,2]
// A mesh named with a slash is a mesh file's path (OBJ, STL or PLY: a shape made for the purpose).
import { readFileSync } from 'node:fs';
import { availableParallelism } from 'node:os';
import { basename } from 'node:path';
import { SHARED_MESHES } from '../tests/node/obj.mjs';
import { threadedClient } from '../tests/node/solver-clients.mjs';
import { Op } from '../web/src/worker/protocol.js';
import { suggestLayouts } from '../web/src/app/suggest-run.js';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const panels = Number(arg('--panels', '12'));
const meshes = arg('--meshes', 'koala,spot,blub').split(',');
const workerCounts = arg('--workers', `1,${Math.min(4, availableParallelism())}`).split(',').map(Number);
const HEIGHT = 0.6;

console.log(`| mesh | panels asked | workers | first layout s | first optimized s | all s | layouts tried | best layout | panels | distance % |`);
console.log('|---|---|---|---|---|---|---|---|---|---|');
for (const given of meshes) {
  const name = given.includes('/') ? basename(given).replace(/\.[^.]*$/, '') : given;
  const path = given.includes('/') ? given : new URL(`${given}.obj`, SHARED_MESHES);
  const file = readFileSync(path);
  // Opened as the app opens a file (loadTarget: the command line's reader); the helpers take the mesh it gives, as the
  // app's take its own worker's.
  const reader = threadedClient();
  const mesh = await reader.request(Op.loadTarget, { fileName: basename(String(path)), bytes: file.buffer.slice(file.byteOffset, file.byteOffset + file.byteLength) });
  reader.terminate();
  let lo = Infinity;
  let hi = -Infinity;
  for (let v = 1; v < mesh.positions.length; v += 3) (lo = Math.min(lo, mesh.positions[v])), (hi = Math.max(hi, mesh.positions[v]));
  for (const workers of new Set(workerCounts)) {
    const clients = Array.from({ length: workers }, () => threadedClient());
    try {
      await Promise.all(clients.map((client) => client.request(Op.setTarget, { positions: mesh.positions, indices: mesh.indices })));
      const { axis } = await clients[0].request(Op.mirrorSymmetry, {});
      const t0 = performance.now();
      let firstLook = null;
      let firstOptimized = null;
      const args = { panels, symmetry: axis, scale: HEIGHT / (hi - lo), up: '+y', triangles: 1000, maxIterations: 40 };
      const result = await suggestLayouts(clients, args, {
        onProgress: (p) => {
          if (p.look && firstLook === null) firstLook = performance.now() - t0;
          if (p.layout && firstOptimized === null) firstOptimized = performance.now() - t0;
        },
      }).promise;
      const all = performance.now() - t0;
      const best = result.layouts[0];
      const s = (ms) => (ms === null ? '—' : (ms / 1000).toFixed(1));
      console.log(`| ${name}${axis ? ` (mirror ${axis})` : ''} | ${panels} | ${workers} | ${s(firstLook)} | ${s(firstOptimized)} | ${s(all)} | ${result.tried} | ${best?.name ?? 'none'} | ${best?.panels ?? '—'} | ${best ? (100 * best.distance).toFixed(2) : '—'} |`);
    } finally {
      for (const client of clients) client.terminate();
    }
  }
}
