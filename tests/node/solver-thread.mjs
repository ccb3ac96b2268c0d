// The worker (web/src/worker/solver.worker.js) as a Node thread: the wasm module served as the worker serves it.
import { parentPort } from 'node:worker_threads';
import { loadApi } from './load-module.mjs';
import { serveSolver } from '../../web/src/worker/serve.js';

const early = [];
let receive = null;
parentPort.on('message', (message) => (receive ? receive(message) : early.push(message)));
({ receive } = serveSolver(await loadApi(), (message, transfer) => parentPort.postMessage(message, transfer)));
for (const message of early.splice(0)) receive(message);
