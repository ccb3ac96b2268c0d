// The module Web Worker: loads the wasm solver, then runs operations (handlers.js) through the Runner.
// onmessage is registered at once; messages that arrive while the module loads wait in the queue.
import createBillow from '@wasm/billow.mjs';
import wasmUrl from '@wasm/billow.wasm?url';
import { SolverApi } from './solver-api.js';
import { createHandlers } from './handlers.js';
import { Runner } from './runner.js';

const early = [];
let runner = null;
self.onmessage = (event) => (runner ? runner.receive(event.data) : early.push(event.data));

const post = (message, transfer = []) => self.postMessage(message, transfer);

createBillow({ locateFile: (path) => (path.endsWith('.wasm') ? wasmUrl : path) })
  .then((module) => {
    const api = new SolverApi(module);
    runner = new Runner(createHandlers(api), post);
    post({ kind: 'ready', version: api.version() });
    for (const message of early.splice(0)) runner.receive(message);
  })
  .catch((error) => post({ kind: 'crashed', message: `The solver could not start: ${error?.message || error}` }));
