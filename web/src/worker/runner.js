// Runs operations for the worker: each handler is a generator that yields progress between steps of work.
// A step should take at most a few tens of milliseconds (long solvers step with a time budget); between
// steps the runner yields to the event loop so a { kind: 'cancel' } message can arrive, and a cancelled
// operation stops at its next step.
import { ErrorCode, IMMEDIATE_OPS, SolverError, transferables } from './protocol.js';

const tick = () =>
  new Promise((resolve) => {
    const channel = new MessageChannel();
    channel.port1.onmessage = () => {
      channel.port1.close(); // an open port would keep a Node process alive
      resolve();
    };
    channel.port2.postMessage(0);
  });

export class Runner {
  // handlers: { [op]: function* (args, context) -> result }, post: (message, transfer) => void
  constructor(handlers, post) {
    this.handlers = handlers;
    this.post = post;
    this.cancelled = new Set();
    this.unfinished = new Set(); // ids queued or running: a cancel for any other id has nothing to stop
    this.queue = Promise.resolve();
    this.idleSteps = null; // a generator stepped only while no request is queued or running (idle())
    this.stepping = false;
  }

  // Runs `steps` (a generator of short steps, whose results nobody waits for) while the worker has nothing else to
  // do: a request waits at most for the step under way, and the rest go on once the worker is idle again.
  // idle(null) drops the steps left.
  idle(steps) {
    this.idleSteps?.return(); // its finally blocks free what it made
    this.idleSteps = steps;
    if (steps) this.stepWhileIdle();
  }

  async stepWhileIdle() {
    if (this.stepping) return;
    this.stepping = true;
    try {
      while (this.idleSteps) {
        await tick();
        if (this.unfinished.size > 0) return; // run()'s finally resumes it
        if (this.idleSteps.next().done) this.idleSteps = null;
      }
    } catch {
      // Nothing waits for it, so a failure only ends it; were the module dead, the next request says so.
      this.idleSteps = null;
    } finally {
      this.stepping = false;
    }
  }

  receive(message) {
    if (message.kind === 'cancel') {
      if (this.unfinished.has(message.id)) this.cancelled.add(message.id);
      return;
    }
    if (message.kind !== 'request') return;
    this.unfinished.add(message.id);
    if (IMMEDIATE_OPS.has(message.op)) {
      // Quick, read-only operations (a seam preview while a long inflation runs) do not wait in line:
      // they run now, between two steps of whatever is running.
      this.run(message, { immediate: true });
      return;
    }
    // One operation at a time, in order: the worker's state changes only between operations.
    this.queue = this.queue.then(() => this.run(message));
  }

  async run({ id, op, args }, { immediate = false } = {}) {
    const handler = this.handlers[op];
    if (!handler) {
      this.unfinished.delete(id);
      this.post({ kind: 'reply', id, ok: false, error: { code: ErrorCode.unknownOp, message: `Unknown operation ${op}` } });
      return;
    }
    let steps = null;
    try {
      steps = handler(args, { id });
      for (;;) {
        // Yield to the event loop before each step, so that a cancel sent meanwhile is seen.
        if (!immediate) await tick();
        if (this.cancelled.has(id)) throw new SolverError(ErrorCode.cancelled, 'Cancelled.');
        const { value, done } = steps.next();
        if (done) {
          this.post({ kind: 'reply', id, ok: true, result: value }, transferables(value));
          break;
        }
        if (value) this.post({ kind: 'progress', id, ...value }, transferables(value));
      }
    } catch (error) {
      if (error instanceof SolverError) {
        const { code, message, details } = error;
        this.post({ kind: 'reply', id, ok: false, error: { code, message, details } });
      } else {
        // A trap in wasm (abort, out of bounds, unreachable) leaves the module unusable: ask for a new worker.
        this.post({ kind: 'crashed', message: String(error?.message || error) });
      }
    } finally {
      this.cancelled.delete(id);
      this.unfinished.delete(id);
      if (this.unfinished.size === 0 && this.idleSteps) this.stepWhileIdle();
      try {
        steps?.return(); // runs the handler's finally blocks (frees wasm objects) on cancel and error
      } catch {
        // the module may be dead after a trap
      }
    }
  }
}
