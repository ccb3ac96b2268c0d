// Wasm benchmark of the inflation simulator in Node (same table as billow_bench, see bench/README.md).
//   node bench/bench-wasm.mjs [--json] [--sizes 700,3000,15000] [--examples mylar,sphere3,pillow:20] [--max-seconds S]
// An example named NAME:R is the example NAME with aspect R (pillow:20 is a 20:1 tube).
// Loads the app's module, build/wasm/billow.mjs, as the Node tests do (BILLOW_WASM_DIR overrides the folder).
// V8 has no on-stack replacement for wasm, so a warm-up inflation runs first and the solve is driven by
// many short step() calls, as the worker does.
import { loadModule } from '../tests/node/load-module.mjs';

const Module = await loadModule();

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
};
const asJson = args.includes('--json');
const sizes = option('--sizes', '700,3000,15000').split(',').map(Number);
const examples = option('--examples', 'mylar,sphere3').split(',');
const radius = Number(option('--radius', '0.3'));
const maxSeconds = Number(option('--max-seconds', '120'));
const PAULSEN = { rimOverDisc: 1 / 1.31103, thicknessOverRim: 1.19814 };

function unwrap(text) {
  const r = JSON.parse(text);
  if (r.status !== 'ok') throw new Error(`${r.code}: ${r.message}`);
  return r.result;
}

function run(example, triangles) {
  const [name, aspect = '1'] = example.split(':');
  const options = { triangles, size: radius, aspect: Number(aspect) };
  const pattern = JSON.stringify(unwrap(Module.examplePattern(name, JSON.stringify(options))));
  const session = new Module.InflationSession();
  try {
    const t0 = performance.now();
    // load() includes the start: a coarse-to-fine start inflates coarser patterns first (coarse_start.hpp).
    const info = unwrap(session.load(pattern, '{}'));
    let state;
    do {
      state = unwrap(session.step(1, 0));
    } while (state.state === 'running' && performance.now() - t0 < maxSeconds * 1000);
    const seconds = (performance.now() - t0) / 1000;
    let factorMs = Infinity;
    for (let k = 0; k < 3; ++k) factorMs = Math.min(factorMs, unwrap(session.timeFactorization()).ms);
    const result = unwrap(session.result());
    const row = {
      example, triangles: session.numTriangles(), vertices: session.numVertices(),
      iterations: result.iterations, factorizations: result.timings.factorizations, seconds, factorMs,
      coarseLevels: info.coarseStart.levels, coarseIterations: info.coarseStart.iterations,
      startSeconds: info.coarseStart.ms / 1000, smoothingSeconds: info.coarseStart.gaussSeidelMs / 1000,
      setupMs: result.timings.setupMs, heapMb: Module.HEAPU8.length / 2 ** 20, residual: result.residual,
      converged: result.converged,
    };
    if (name === 'mylar') {
      const m = unwrap(session.measureMylar());
      row.rimOverDisc = m.rimRadius / radius;
      row.thicknessOverRim = m.thickness / m.rimRadius;
      row.rimError = row.rimOverDisc / PAULSEN.rimOverDisc - 1;
      row.thicknessError = row.thicknessOverRim / PAULSEN.thicknessOverRim - 1;
    }
    return row;
  } finally {
    session.delete();
  }
}

run('mylar', 300);  // warm-up: tier up the hot functions before measuring
run('sphere3', 300);
run('mylar', 2400);  // and those of the coarse-to-fine start (coarsening, smoothing), from 600 triangles up
const rows = [];
if (!asJson) {
  console.log(['example', 'tris', 'verts', 'iters', 'facts', 'start s', 'solve s', 'factor ms', 'setup ms', 'heap MB', 'rim/a',
    'thick/rim', 'conv'].map((s, i) => (i === 0 ? s.padEnd(16) : s.padStart(9))).join(' '));
}
for (const name of examples) {
  for (const n of sizes) {
    const r = run(name, n);
    rows.push(r);
    if (!asJson) {
      const f = (v, d) => (v === undefined ? '-' : v.toFixed(d)).padStart(9);
      console.log([r.example.padEnd(16), String(r.triangles).padStart(9), String(r.vertices).padStart(9),
        String(r.iterations).padStart(9), String(r.factorizations).padStart(9), f(r.startSeconds, 3), f(r.seconds, 3),
        f(r.factorMs, 2),
        f(r.setupMs, 1), f(r.heapMb, 1), f(r.rimOverDisc, 5), f(r.thicknessOverRim, 5),
        (r.converged ? 'yes' : 'NO').padStart(9)].join(' '));
    }
  }
}
if (asJson) console.log(JSON.stringify({ runtime: 'wasm-node', reference: PAULSEN, rows }, null, 2));
else console.log(`Paulsen: rim/a = ${PAULSEN.rimOverDisc.toFixed(5)}, thickness/rim = ${PAULSEN.thicknessOverRim}`);
