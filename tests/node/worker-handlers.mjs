// The worker's request handlers over the solver module, run in Node as the worker runs them: each handler is
// a generator of progress steps; `run` drives one to its result.
import { loadApi } from './load-module.mjs';
import { createHandlers } from '../../web/src/worker/handlers.js';

export const api = await loadApi();
export const handlers = createHandlers(api);
export const run = (generator) => {
  for (let step = generator.next(); ; step = generator.next()) if (step.done) return step.value;
};
