// SolverClient: the main thread's side of the worker protocol (protocol.js). Promises per request,
// progress callbacks, cooperative cancel, and recovery: a crashed worker is thrown away, a fresh one
// started, and the replayable state sent again. A request that was running when the worker crashed is
// rejected (not re-sent), so a crash cannot loop.
import { ErrorCode, REPLAYED_OPS, SolverError } from './protocol.js';

const MAX_RECENT_CRASHES = 3;

export class SolverClient {
  // createWorker: () => Worker (a module worker running solver.worker.js)
  constructor(createWorker, { onCrash = () => {}, onReady = () => {} } = {}) {
    this.createWorker = createWorker;
    this.onCrash = onCrash;
    this.onReady = onReady;
    this.nextId = 1;
    this.pending = new Map(); // id -> { resolve, reject, onProgress, op, args }
    this.replay = new Map(); // op -> args of the last successful replayable request
    this.latestOf = new Map(); // kind -> the call latest() made last, while it runs
    this.crashes = 0;
    this.recentCrashes = 0; // crashes since the last successful reply: a loop guard
    this.broken = false;
    this.start();
  }

  start() {
    this.worker = this.createWorker();
    this.ready = new Promise((resolve) => (this.resolveReady = resolve));
    this.worker.onmessage = (event) => this.receive(event.data);
    this.worker.onerror = (event) => {
      event.preventDefault?.();
      this.crashed(event.message || 'the solver stopped unexpectedly');
    };
    this.worker.onmessageerror = () => this.crashed('a message from the solver could not be read');
  }

  // Sends op(args); resolves with the result, rejects with a SolverError. Returns { promise, cancel }. A
  // cancelled call rejects at once with ErrorCode.cancelled and reports no more progress; the worker stops it
  // at its next step (or skips it, still queued).
  call(op, args = {}, { onProgress, transfer = [], replaying = false } = {}) {
    const id = this.nextId++;
    if (this.broken) {
      const promise = Promise.reject(new SolverError(ErrorCode.crashed, 'The solver is stopped. Reload the page to try again.'));
      return { promise, cancel: () => {}, id };
    }
    let cancel;
    const promise = new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject, onProgress, op, args, replaying });
      this.worker.postMessage({ kind: 'request', id, op, args }, transfer);
      cancel = () => {
        if (!this.pending.has(id)) return;
        this.pending.delete(id);
        this.worker.postMessage({ kind: 'cancel', id });
        reject(new SolverError(ErrorCode.cancelled, 'Cancelled.'));
      };
    });
    return { promise, cancel, id };
  }

  // The one way to ask for "the latest of its kind" (the segmentation of the seams on screen, the cut lines of
  // the pattern shown, ...): the call of this kind still running is cancelled, so only the newest answer
  // arrives; the older call's promise rejects with ErrorCode.cancelled. Returns { promise, cancel }.
  latest(kind, op, args, options) {
    this.supersede(kind);
    const call = this.call(op, args, options);
    this.latestOf.set(kind, call);
    const done = () => this.latestOf.get(kind) === call && this.latestOf.delete(kind);
    call.promise.then(done, done);
    return call;
  }

  // Cancels the running call of this kind (latest), if there is one.
  supersede(kind) {
    const call = this.latestOf.get(kind);
    this.latestOf.delete(kind);
    call?.cancel();
  }

  // True while a call of this kind (latest) runs.
  running(kind) {
    return this.latestOf.has(kind);
  }

  request(op, args, options) {
    return this.call(op, args, options).promise;
  }

  receive(message) {
    if (message.kind === 'ready') {
      this.resolveReady(message);
      this.onReady(message);
      return;
    }
    if (message.kind === 'crashed') {
      this.crashed(message.message);
      return;
    }
    const entry = this.pending.get(message.id);
    if (!entry) return; // a reply to a request that was cancelled or lost in a crash
    if (message.kind === 'progress') {
      entry.onProgress?.(message);
    } else if (message.kind === 'reply') {
      this.pending.delete(message.id);
      if (message.ok) {
        if (!entry.replaying) this.recentCrashes = 0; // only the designer's own requests prove the worker sane
        if (REPLAYED_OPS.has(entry.op)) this.replay.set(entry.op, entry.args);
        entry.resolve(message.result);
      } else {
        if (!entry.replaying) this.recentCrashes = 0;
        entry.reject(new SolverError(message.error.code, message.error.message, message.error.details));
      }
    }
  }

  // Remembers replayable state without a round trip (e.g. a target the worker installed itself).
  remember(op, args) {
    if (REPLAYED_OPS.has(op)) this.replay.set(op, args);
  }

  crashed(reason) {
    this.crashes += 1;
    this.recentCrashes += 1;
    this.worker.terminate();
    const lost = [...this.pending.values()];
    this.pending.clear();
    // Replaying a state that crashes again would loop: after MAX_RECENT_CRASHES, stop restarting.
    this.broken = this.recentCrashes > MAX_RECENT_CRASHES;
    const message = this.broken
      ? 'The solver keeps stopping in this browser, so Billow stopped restarting it. Your design is safe: reload the page to try again.'
      : 'The solver stopped unexpectedly and was restarted. Your design is safe; try the last step again.';
    for (const entry of lost) entry.reject(new SolverError(ErrorCode.crashed, message));
    if (this.broken) {
      this.worker = { postMessage: () => {}, terminate: () => {} };
      this.onCrash({ reason, crashes: this.crashes, broken: true, replayed: Promise.resolve() });
      return;
    }
    this.start();
    const replayed = [];
    for (const [op, args] of this.replay)
      replayed.push(this.request(op, args, { replaying: true }).catch(() => this.replay.delete(op)));
    this.onCrash({ reason, crashes: this.crashes, replayed: Promise.all(replayed) });
  }

  terminate() {
    this.worker.terminate();
  }
}
