// The worker (web/src/worker/solver.worker.js) as a Node thread: the wasm module, the Runner over the handlers.
import { parentPort } from 'node:worker_threads';
import { loadApi } from './load-module.mjs';
import { createHandlers } from '../../web/src/worker/handlers.js';
import { Runner } from '../../web/src/worker/runner.js';

const early = [];
let runner = null;
parentPort.on('message', (message) => (runner ? runner.receive(message) : early.push(message)));
const api = await loadApi();
runner = new Runner(createHandlers(api), (message, transfer) => parentPort.postMessage(message, transfer));
parentPort.postMessage({ kind: 'ready', version: api.version() });
for (const message of early.splice(0)) runner.receive(message);
