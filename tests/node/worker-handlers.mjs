// The worker's request handlers over the solver module, run in Node as the worker runs them: each handler is
// a generator of progress steps; `run` drives one to its result. HeadlessApp is the app as the seam editor and
// the seam tool see it, over these handlers.
import { loadApi } from './load-module.mjs';
import { createHandlers } from '../../web/src/worker/handlers.js';
import { Store } from '../../web/src/app/store.js';

export const api = await loadApi();
export const handlers = createHandlers(api);
export const run = (generator) => {
  for (let step = generator.next(); ; step = generator.next()) if (step.done) return step.value;
};

// The app as the seam editor sees it: its store (the history of designs), the worker's handlers in the same
// thread, no views.
// scaleFor(design): target units per metre of the design (the app's heightScale).
export class HeadlessApp {
  constructor(target, design, scaleFor) {
    this.target = target;
    this.store = new Store(design);
    this.notes = [];
    this.messages = { resolve: () => {}, show: (severity, text) => this.notes.push({ severity, text }) };
    const request = async (op, args) => run(handlers[op](args));
    this.client = { request, latest: (kind, op, args) => ({ promise: request(op, args), cancel: () => {} }), supersede: () => {}, running: () => false };
    this.panes = { target: { seams: null, setSegments: () => {} } };
    this.scaleFor = scaleFor;
  }
  get design() {
    return this.store.design;
  }
  get history() {
    return this.store.history;
  }
  commitDesign(design, { mergeKey = null } = {}) {
    this.store.commit(design, { mergeKey });
  }
  amendDesign(design) {
    this.store.amend(design);
  }
  panels = { make: () => {}, remake: () => {}, markOutdated: () => {} };
}
