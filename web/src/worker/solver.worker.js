// The module Web Worker: loads the wasm solver, then runs operations (handlers.js) through the Runner (serve.js).
// onmessage is registered at once; messages that arrive while the module loads wait in the queue.
import createBillow from '@wasm/billow.mjs';
import wasmUrl from '@wasm/billow.wasm?url';
import { SolverApi } from './solver-api.js';
import { serveSolver } from './serve.js';

const early = [];
let receive = null;
self.onmessage = (event) => (receive ? receive(event.data) : early.push(event.data));

const post = (message, transfer = []) => self.postMessage(message, transfer);

createBillow({ locateFile: (path) => (path.endsWith('.wasm') ? wasmUrl : path) })
  .then((module) => {
    ({ receive } = serveSolver(new SolverApi(module), post));
    for (const message of early.splice(0)) receive(message);
  })
  .catch((error) => post({ kind: 'crashed', message: `The solver could not start: ${error?.message || error}` }));
