// SolverClients (web/src/worker/client.js) in Node, over the worker's own Runner and handlers: in this thread (the
// protocol as the app speaks it, one step at a time) or each in a thread of its own (worker_threads, so several
// work side by side as the app's helper workers do; the bench's figures).
import { Worker as ThreadWorker } from 'node:worker_threads';
import { SolverClient } from '../../web/src/worker/client.js';
import { Runner } from '../../web/src/worker/runner.js';
import { createHandlers } from '../../web/src/worker/handlers.js';

// A Worker as SolverClient sees one: postMessage, onmessage, onerror, terminate.
class InThreadWorker {
  constructor(api) {
    this.runner = new Runner(createHandlers(api), (message) => setImmediate(() => this.onmessage?.({ data: structuredClone(message) })));
    setImmediate(() => this.onmessage?.({ data: { kind: 'ready', version: api.version() } }));
  }
  postMessage(message) {
    const copy = structuredClone(message);
    setImmediate(() => this.runner.receive(copy));
  }
  terminate() {}
}

class ThreadedWorker {
  constructor() {
    this.thread = new ThreadWorker(new URL('./solver-thread.mjs', import.meta.url));
    this.thread.on('message', (data) => this.onmessage?.({ data }));
    this.thread.on('error', (error) => this.onerror?.({ message: String(error?.message || error) }));
  }
  postMessage(message) {
    this.thread.postMessage(message);
  }
  terminate() {
    this.thread.terminate();
  }
}

export const inThreadClient = (api) => new SolverClient(() => new InThreadWorker(api));
export const threadedClient = () => new SolverClient(() => new ThreadedWorker());
