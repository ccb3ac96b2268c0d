// The module's warm-up (web/src/worker/warm-up.js) and the Runner's idle steps that carry it (runner.js): it
// optimizes a balloon of its own, frees what it made, and never keeps a request waiting for more than one step.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadApi } from './load-module.mjs';
import { Runner } from '../../web/src/worker/runner.js';
import { serveSolver } from '../../web/src/worker/serve.js';
import { Op } from '../../web/src/worker/protocol.js';
import { warmUp, warmUpTarget } from '../../web/src/worker/warm-up.js';

const api = await loadApi();

test('the warm-up target is a closed ellipsoid with its equator among its vertices', () => {
  const { positions, indices, equator } = warmUpTarget();
  const { report, indices: checked } = api.validateTarget(positions, indices);
  assert.equal(report.ok, true, JSON.stringify(report.problems));
  assert.equal(report.modified, false, 'every triangle faces out');
  assert.equal(checked.length, indices.length);
  assert.equal(equator.length, 24);
  for (const v of equator) assert.ok(Math.abs(positions[3 * v + 2]) < 1e-12, `vertex ${v} is off the equator`);
});

test('the warm-up optimizes its balloon for up to 20 iterations and leaves nothing on the heap', () => {
  const run = () => {
    const steps = warmUp(api);
    let step = steps.next();
    let count = 0;
    while (!step.done) (step = steps.next()), (count += 1);
    // 20, or where the optimizer stops first (16 since its steps follow the equal seam lengths).
    assert.ok(step.value >= 10 && step.value <= 20, `${step.value} iterations made`);
    assert.ok(count >= step.value, `${count} steps`);
  };
  run(); // the module's first optimization also makes what it keeps for the next ones
  const before = api.memoryStats().inUse;
  run();
  assert.equal(api.memoryStats().inUse, before);
});

test('a warm-up dropped halfway frees its session', () => {
  const before = api.memoryStats().inUse;
  const steps = warmUp(api);
  for (let i = 0; i < 4; i++) steps.next();
  assert.ok(api.memoryStats().inUse > before, 'the session holds its design');
  steps.return();
  assert.equal(api.memoryStats().inUse, before);
});

// A Runner over handlers that record when their steps run, with idle steps that do the same.
function recordingRunner(log) {
  const handlers = {
    *work({ name }) {
      for (let i = 0; i < 3; i++) {
        log.push(`${name}${i}`);
        yield { stage: name };
      }
      return name;
    },
  };
  const replies = new Map();
  const runner = new Runner(handlers, (message) => message.kind === 'reply' && replies.get(message.id)?.(message.result));
  const request = (id, name) => new Promise((resolve) => {
    replies.set(id, resolve);
    runner.receive({ kind: 'request', id, op: 'work', args: { name } });
  });
  return { runner, request };
}

function* idleSteps(log, count, ended) {
  try {
    for (let i = 0; i < count; i++) {
      log.push(`idle${i}`);
      yield;
    }
  } finally {
    ended.push(true);
  }
}

const settle = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
// Waits until `holds` or two seconds have passed: a loaded machine runs the idle steps' timers late.
async function until(holds) {
  for (let t = 0; t < 2000 && !holds(); t += 5) await settle(5);
}

test('idle steps stop while a request is under way and go on once it is answered', async () => {
  const log = [], ended = [];
  const { runner, request } = recordingRunner(log);
  runner.idle(idleSteps(log, 1000, ended));
  await until(() => log.length > 0);
  const before = log.length;
  assert.ok(before > 0, 'idle steps ran');
  await request(1, 'a');
  // The request's steps ran one after another: no idle step between them.
  const a0 = log.indexOf('a0');
  assert.deepEqual(log.slice(a0, a0 + 3), ['a0', 'a1', 'a2']);
  assert.ok(a0 <= before + 1, 'the request waited for at most the idle step under way');
  const after = log.length;
  await until(() => log.length > after);
  assert.ok(log.length > after, 'idle steps went on after the reply');
  runner.idle(null);
  assert.deepEqual(ended, [true], 'dropped, the steps ran their finally block');
  const dropped = log.length;
  await settle(5);
  assert.equal(log.length, dropped);
});

test('idle steps run to their end and are not run again', async () => {
  const log = [], ended = [];
  const { runner, request } = recordingRunner(log);
  runner.idle(idleSteps(log, 3, ended));
  await settle(20);
  assert.deepEqual(log, ['idle0', 'idle1', 'idle2']);
  assert.deepEqual(ended, [true]);
  assert.equal(await request(1, 'b'), 'b');
  await settle(5);
  assert.deepEqual(log.slice(3), ['b0', 'b1', 'b2']);
});

test('the worker warms up while idle, answers at once, and an optimization ends the warm-up', async () => {
  const messages = [];
  const replies = new Map();
  const { receive } = serveSolver(api, (message) => {
    messages.push(message);
    if (message.kind === 'reply') replies.get(message.id)?.(message);
  });
  assert.equal(messages[0].kind, 'ready');
  const request = (id, op, args) => new Promise((resolve) => {
    replies.set(id, resolve);
    receive({ kind: 'request', id, op, args });
  });
  await settle(50); // the warm-up's balloon is being optimized
  const { positions, indices } = warmUpTarget(32, 16);
  const t0 = performance.now();
  const loaded = await request(1, Op.setTarget, { positions, indices });
  assert.equal(loaded.ok, true);
  assert.ok(performance.now() - t0 < 3000, 'the request waited for one warm-up step at most');
  // The worker's own target is the one it was given, not the warm-up's.
  const segmented = await request(2, Op.segment, { seams: [] });
  assert.equal(segmented.ok, true);
  assert.equal(segmented.result.positions.length, positions.length);
  // A request that optimizes ends the warm-up at once: its session goes.
  const inUse = api.memoryStats().inUse;
  const optimized = request(3, Op.optimizeDesign, { seams: [], scale: 0.3 });
  assert.ok(api.memoryStats().inUse < inUse, 'the warm-up\'s session was freed');
  assert.equal((await optimized).ok, false, 'no seams, no panels');
});
