// The worker's side of the protocol over a loaded module (solver.worker.js; the Node tests' stand-ins): the
// Runner over the handlers, and the module's warm-up whenever the worker has nothing else to do.
import { createHandlers } from './handlers.js';
import { Op } from './protocol.js';
import { Runner } from './runner.js';
import { warmUp } from './warm-up.js';

// Requests that run the optimizer's loops themselves: after one, the module needs no warm-up.
const WARMING_OPS = new Set([Op.optimizeDesign, Op.suggestLook, Op.suggestOptimize]);

// api: a SolverApi; post(message, transfer). Posts 'ready' and returns { receive(message), runner }.
export function serveSolver(api, post) {
  const runner = new Runner(createHandlers(api), post);
  post({ kind: 'ready', version: api.version() });
  runner.idle(warmUp(api)); // while the designer opens a shape and draws seams (warm-up.js)
  const receive = (message) => {
    if (WARMING_OPS.has(message.op)) runner.idle(null);
    runner.receive(message);
  };
  return { receive, runner };
}
