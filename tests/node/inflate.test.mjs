// Inflation through the wasm module in Node, by the same JS layer the worker uses: a Mylar balloon
// settles with sensible figures; cancel between steps frees everything (no heap growth over cycles);
// a bad pattern is refused with a message.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadApi } from './load-module.mjs';
import { Runner } from '../../web/src/worker/runner.js';
import { createHandlers } from '../../web/src/worker/handlers.js';

const api = await loadApi();

function run(handlers, op, args, { cancelAfter = Infinity } = {}) {
  return new Promise((resolve, reject) => {
    let progress = 0;
    const runner = new Runner(handlers, (message) => {
      if (message.kind === 'progress' && ++progress >= cancelAfter) runner.receive({ kind: 'cancel', id: 1 });
      if (message.kind === 'reply') (message.ok ? resolve : reject)(message.ok ? message.result : message.error);
      if (message.kind === 'crashed') reject(new Error(message.message));
    });
    runner.receive({ kind: 'request', id: 1, op, args });
  });
}

test('a Mylar pattern inflates to a lens of the expected volume, with per-triangle fields', async () => {
  const patternText = JSON.stringify(api.examplePattern('mylar', 800));
  const handlers = createHandlers(api);
  const result = await run(handlers, 'inflatePattern', { patternText });
  assert.equal(result.converged, true);
  // Paulsen: rim radius 0.7627 a and thickness 1.1981 r; its volume is about 0.0329 m3 for a = 0.3 m.
  assert.ok(result.volume > 0.029 && result.volume < 0.037, `volume ${result.volume}`);
  const F = result.triangles.length / 3;
  assert.equal(result.compression.length, 4 * F);
  assert.equal(result.outer.length, F);
  assert.ok(result.positions.every(Number.isFinite));
  assert.ok(result.maxCompression > 0, 'the rim wrinkles');
  assert.equal(result.panelVertexStart.length, 3);
});

test('inflation cancels between steps, and 30 cycles of start and cancel do not grow the heap', async () => {
  const patternText = JSON.stringify(api.examplePattern('mylar', 1500));
  const handlers = createHandlers(api);
  await assert.rejects(run(handlers, 'inflatePattern', { patternText }, { cancelAfter: 2 }), (e) => e.code === 'cancelled');
  const heap = api.module.HEAPU8.length;
  for (let i = 0; i < 30; i++)
    await assert.rejects(run(handlers, 'inflatePattern', { patternText }, { cancelAfter: 2 }), (e) => e.code === 'cancelled');
  assert.equal(api.module.HEAPU8.length, heap, 'the wasm heap did not grow');
});

test('a pattern that cannot be sewn is refused with a message', async () => {
  const pattern = api.examplePattern('pillow', 400);
  pattern.stitches[0][3] = 123456;
  const handlers = createHandlers(api);
  await assert.rejects(run(handlers, 'inflatePattern', { patternText: JSON.stringify(pattern) }), (e) => {
    assert.match(e.code, /^pattern\./);
    assert.ok(e.message.length > 20);
    return true;
  });
  await assert.rejects(run(handlers, 'inflatePattern', { patternText: '{"format":"billow-pattern","version":2}' }), (e) => e.code === 'pattern.version');
});
