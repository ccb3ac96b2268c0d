// Soak: the worker's operations, run many times over one wasm module and one Runner as in the worker,
// started and cancelled at different steps, leave no memory behind: neither in the wasm heap (its size,
// and where a fresh 1 MB block lands: the top of the allocator's used memory) nor in the JS heap.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import v8 from 'node:v8';
import vm from 'node:vm';
import { loadApi } from './load-module.mjs';
import { readObjText } from './obj.mjs';
import { Runner } from '../../web/src/worker/runner.js';
import { createHandlers } from '../../web/src/worker/handlers.js';

// The test runner gives no --expose-gc; the flag still exposes gc to contexts made after it is set.
v8.setFlagsFromString('--expose-gc');
const gc = globalThis.gc ?? vm.runInNewContext('gc');

const api = await loadApi();
const MB = 1 << 20;
const PROBE_SLACK = 256 * 1024; // allocator noise; a leaked inflation costs about 2 MB per cycle
// The session keeps the last (cancelled) optimizer until the next one starts, and how far it got before the
// cancel (its L-BFGS pairs, history, factorizations) depends on timing: up to a few hundred KB here. A leaked
// optimization would add that much at every one of the 25 measured cycles.
const OPTIMIZE_PROBE_SLACK = 1024 * 1024;
const JS_HEAP_SLACK = 3 * MB;

// The wasm heap: memory size, the address a fresh 1 MB block gets (malloc has no mmap in wasm, so a
// block that fits nowhere else comes from the top: it rises when anything leaks), and live embind handles.
function wasmMemory() {
  const probe = api.module._malloc(MB);
  api.module._free(probe);
  return { size: api.module.HEAPU8.length, probe, handles: api.module.count_emval_handles() };
}

function jsHeap() {
  gc();
  return process.memoryUsage().heapUsed;
}

const mb = (bytes) => `${(bytes / MB).toFixed(2)} MB`;

// One Runner for all requests, as in solver.worker.js; call() cancels after cancelAfter progress events.
function solver(handlers) {
  const pending = new Map();
  let nextId = 1;
  let lastProgress = 0; // progress events of the last request answered
  const runner = new Runner(handlers, (message) => {
    if (message.kind === 'crashed') {
      for (const entry of pending.values()) entry.reject(new Error(`the solver crashed: ${message.message}`));
      pending.clear();
      return;
    }
    const entry = pending.get(message.id);
    if (!entry) return;
    if (message.kind === 'progress' && ++entry.progress === entry.cancelAfter) runner.receive({ kind: 'cancel', id: message.id });
    if (message.kind === 'reply') {
      pending.delete(message.id);
      lastProgress = entry.progress;
      if (message.ok) entry.resolve(message.result);
      else entry.reject(message.error);
    }
  });
  return {
    lastProgress: () => lastProgress,
    call(op, args, { cancelAfter = Infinity } = {}) {
      const id = nextId++;
      return new Promise((resolve, reject) => {
        pending.set(id, { resolve, reject, cancelAfter, progress: 0 });
        runner.receive({ kind: 'request', id, op, args });
      });
    },
  };
}

const cancelled = (error) => error.code === 'cancelled';

test('100 inflations started and cancelled (every 10th run to the end) leave no memory behind', async (t) => {
  // The solve must span several of the worker's 30 ms steps, so that every cancel point below (the third at most)
  // comes before it converges: the smallest balloon that takes eight on this machine, a margin for the later
  // solves' warmer code (1,500 triangles took two steps on a fast machine).
  const { call, lastProgress } = solver(createHandlers(api));
  let patternText = '';
  for (const triangles of [1500, 3000, 6000, 12000, 24000]) {
    patternText = JSON.stringify(api.examplePattern('mylar', triangles));
    await call('inflatePattern', { patternText });
    if (lastProgress() >= 8) break;
  }
  assert.ok(lastProgress() >= 8, `an uncancelled solve reports ${lastProgress()} progress events`);
  const started = performance.now();
  let baseline = null;
  let jsBaseline = 0;
  let highestProbe = 0;
  for (let cycle = 1; cycle <= 100; cycle++) {
    if (cycle % 10 === 0) {
      const result = await call('inflatePattern', { patternText });
      assert.equal(result.converged, true, `cycle ${cycle} converged`);
    } else {
      // Cancelled before the pattern is read, after it is read, or after the first Newton step.
      await assert.rejects(call('inflatePattern', { patternText }, { cancelAfter: 1 + (cycle % 3) }), cancelled);
    }
    if (cycle === 10) {
      baseline = wasmMemory();
      jsBaseline = jsHeap();
    } else if (baseline) {
      const now = wasmMemory();
      assert.equal(now.size, baseline.size, `the wasm memory did not grow (cycle ${cycle})`);
      highestProbe = Math.max(highestProbe, now.probe);
    }
  }
  const last = wasmMemory();
  const jsLast = jsHeap();
  t.diagnostic(`${((performance.now() - started) / 1000).toFixed(1)} s; wasm memory ${mb(baseline.size)} after cycle 10 and ${mb(last.size)} after 100`);
  t.diagnostic(`top of the wasm heap ${mb(baseline.probe)} after cycle 10, at most ${mb(highestProbe)} after`);
  t.diagnostic(`JS heap ${mb(jsBaseline)} after cycle 10, ${mb(jsLast)} after 100`);
  assert.ok(highestProbe <= baseline.probe + PROBE_SLACK, `the wasm heap's top stayed at ${mb(baseline.probe)} (at most ${mb(highestProbe)})`);
  assert.equal(last.handles, baseline.handles, 'no embind handles left behind');
  assert.ok(jsLast - jsBaseline < JS_HEAP_SLACK, `the JS heap stayed flat: ${mb(jsBaseline)} -> ${mb(jsLast)}`);
});

test('30 pattern optimizations started and cancelled do not grow the wasm memory', async (t) => {
  const read = (path) => readFileSync(new URL(path, import.meta.url), 'utf8');
  const sphere = readObjText(read('../../web/public/examples/sphere.obj'));
  const design = JSON.parse(read('../data/sphere-equator.billow.json'));
  const seams = design.seams.map(({ points, closed, weight }) => ({ points, closed, weight }));
  const { call } = solver(createHandlers(api));
  await call('setTarget', { positions: sphere.positions, indices: sphere.indices });
  let baseline = null;
  let highestProbe = 0;
  for (let cycle = 1; cycle <= 30; cycle++) {
    // The second progress event comes once the optimization has started (the panels are flattened):
    // cancelled there, or after one or two optimizer steps.
    await assert.rejects(call('optimizeDesign', { seams, scale: 0.25, triangles: 300 }, { cancelAfter: 2 + (cycle % 3) }), cancelled);
    if (cycle === 5) baseline = wasmMemory();
    else if (baseline) {
      const now = wasmMemory();
      assert.equal(now.size, baseline.size, `the wasm memory did not grow (cycle ${cycle})`);
      highestProbe = Math.max(highestProbe, now.probe);
    }
  }
  t.diagnostic(`wasm memory ${mb(baseline.size)}; top of the wasm heap ${mb(baseline.probe)} after cycle 5, at most ${mb(highestProbe)} after`);
  assert.ok(highestProbe <= baseline.probe + OPTIMIZE_PROBE_SLACK, `the wasm heap's top stayed at ${mb(baseline.probe)} (at most ${mb(highestProbe)})`);
  assert.equal(wasmMemory().handles, baseline.handles, 'no embind handles left behind');
});
