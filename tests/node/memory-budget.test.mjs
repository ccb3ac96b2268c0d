// A computation that would not fit in memory is refused before it starts, through the worker's own
// handlers: an inflation (pattern import) and a pattern optimization (the app's panels) over a budget get
// the error "memory.budget" with a message saying how much they need and what to do; within the default
// budget (the wasm heap's room, up to 2 GB) the same requests run.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadApi } from './load-module.mjs';
import { readObjText } from './obj.mjs';
import { Runner } from '../../web/src/worker/runner.js';
import { createHandlers } from '../../web/src/worker/handlers.js';

const api = await loadApi();
const handlers = createHandlers(api);
let nextId = 1;

// One request through a Runner, as in solver.worker.js; cancelled after `cancelAfter` progress events.
function call(op, args, { cancelAfter = Infinity } = {}) {
  const id = nextId++;
  return new Promise((resolve, reject) => {
    let progress = 0;
    const runner = new Runner(handlers, (message) => {
      if (message.kind === 'progress' && ++progress === cancelAfter) runner.receive({ kind: 'cancel', id });
      if (message.kind === 'reply') (message.ok ? resolve : reject)(message.ok ? message.result : message.error);
      if (message.kind === 'crashed') reject(new Error(message.message));
    });
    runner.receive({ kind: 'request', id, op, args });
  });
}

const refusedForMemory = (what) => (error) => {
  assert.equal(error.code, 'memory.budget', `${what}: ${error.code} ${error.message}`);
  assert.match(error.message, /needs about \d+ MB of memory/);
  return true;
};

test('an inflation over the memory budget is refused before any work, with what to do', async () => {
  const patternText = JSON.stringify(api.examplePattern('mylar', 3000));
  const tight = { memoryBudget: 8 * 2 ** 20 }; // 8 MB: the 3k-triangle Mylar balloon needs about 30
  await assert.rejects(call('inflatePattern', { patternText, options: tight }), (error) => {
    refusedForMemory('inflation')(error);
    assert.match(error.message, /Inflating this pattern \(\d+ triangles\)/);
    assert.match(error.message, /fewer triangles/);
    return true;
  });
  // The default budget is the heap's room: the same pattern inflates (cancelled once it runs).
  await assert.rejects(call('inflatePattern', { patternText }, { cancelAfter: 3 }), (error) => error.code === 'cancelled');
});

test('a pattern optimization over the memory budget is refused; a coarser one runs', async () => {
  const read = (path) => readFileSync(new URL(path, import.meta.url), 'utf8');
  const sphere = readObjText(read('../../web/public/examples/sphere.obj'));
  const design = JSON.parse(read('../data/sphere-equator.billow.json'));
  const seams = design.seams.map(({ points, closed, weight }) => ({ points, closed, weight }));
  await call('setTarget', { positions: sphere.positions, indices: sphere.indices });
  const budget = 100 * 2 ** 20;
  await assert.rejects(call('optimizeDesign', { seams, scale: 0.25, triangles: 20000, memoryBudget: budget }), (error) => {
    refusedForMemory('optimization')(error);
    assert.match(error.message, /Optimizing panels of 20000 triangles/);
    assert.match(error.message, /coarser panel resolution/);
    return true;
  });
  // Within the same budget a coarse resolution starts (cancelled at its first optimizer step).
  await assert.rejects(
    call('optimizeDesign', { seams, scale: 0.25, triangles: 500, memoryBudget: budget }, { cancelAfter: 2 }),
    (error) => error.code === 'cancelled',
  );
});
