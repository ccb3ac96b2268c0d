// The app's state in one store: the design's undo history, the revision its panels are made for, the results
// computed for a revision, what the worker is busy with, what the panes show, and the view's own settings (the
// resolution, the status line). The App writes it; views and the classroom walk subscribe and read. A result
// carries the revision it was made for, so the result of a design since edited is never taken for the current
// one's.
import { History } from './history.js';
import { canonicalJson, optimizeArgs, DEFAULT_RESOLUTION } from './stored-result.js';

// What a design's panels are made from, besides the target mesh and the resolution, as comparable text: the target's
// thin handles cut or not (undo and redo cross the cut) is part of it.
const panelInputs = (design) =>
  canonicalJson({ height: design.size.height, up: design.target.up, cutThinHandles: Boolean(design.target.cutThinHandles), ...optimizeArgs(design, 0) });

// How many optimized results are kept for designs met again (undo, redo, a compared layout put back).
const KEPT_RESULTS = 8;

export class Store {
  constructor(design) {
    this.history = new History(design);
    this.revision = 0; // counts the changes of what the panels are made from
    this.results = new Map(); // kind -> { revision, value }
    // The newest optimized results by what they were made from (madeKey), oldest first: a design met again shows
    // its panels at once instead of optimizing them again, also on a target opened again (the classroom walk's
    // way back to the designer's own).
    this.kept = new Map();
    this.targetKey = ''; // the target mesh on screen, as a hash of its vertices and triangles
    this.work = new Map(); // kind -> how many of that kind run ('opening', 'panels', 'inflation')
    // What the panes show: the pattern (its JSON text and, parsed, in meters), its inflated shape and its cut
    // figures (the exporter's statistics). A pattern opened from a file is shown without being a result.
    this.shown = { patternText: null, pattern: null, inflated: null, cut: null };
    this.resolution = DEFAULT_RESOLUTION; // triangles of the simulation mesh: a view setting, not the design's
    this.status = '';
    this.listeners = new Set();
  }

  get design() {
    return this.history.present;
  }

  // fn(what) runs after every change: what is 'design', 'results', 'work', 'shown', 'status' or 'seams'.
  // Returns the function that unsubscribes.
  subscribe(fn) {
    this.listeners.add(fn);
    return () => this.listeners.delete(fn);
  }

  changed(what) {
    for (const fn of [...this.listeners]) fn(what);
  }

  // The design after an edit (mergeKey: quick edits with the same key are one undo step, all of a gesture's until
  // endStep: History.apply) or, with reset, a new history starting at it. True when what the panels are made from
  // changed: a new revision.
  commit(design, { reset = false, mergeKey = null, gesture = false } = {}) {
    const before = this.design;
    if (reset) this.history.reset(design);
    else this.history.apply(() => design, { mergeKey, gesture });
    return this.moved(before, reset);
  }

  // A fix-up that belongs to the edit just made: no new undo step.
  amend(design) {
    const before = this.design;
    this.history.amend(() => design);
    return this.moved(before);
  }

  undo() {
    const before = this.design;
    this.history.undo();
    return this.moved(before);
  }

  redo() {
    const before = this.design;
    this.history.redo();
    return this.moved(before);
  }

  // The next edit is a step of its own, even with the same merge key (a new drag).
  endStep() {
    this.history.endStep();
  }

  // Another undo history in place of this one (by default a fresh one at the present design: the classroom
  // walk's own; then the designer's back); returns the one it replaces.
  swapHistory(history = new History(this.design)) {
    const before = this.design;
    const previous = this.history;
    this.history = history;
    this.moved(before);
    return previous;
  }

  moved(before, always = false) {
    const bumped = always || panelInputs(before) !== panelInputs(this.design);
    if (bumped) this.revision += 1;
    this.changed('design');
    return bumped;
  }

  setResolution(triangles) {
    this.resolution = triangles;
    this.revision += 1; // panels made at another resolution are not this one's
    this.changed('design');
  }

  // A result of the design at `revision` (the one current when its work began).
  setResult(kind, value, revision = this.revision) {
    this.results.set(kind, { revision, value });
    this.changed('results');
  }

  // The result of this kind made for the current design, or null.
  result(kind) {
    const r = this.results.get(kind);
    return r && r.revision === this.revision ? r.value : null;
  }

  // What the current design's panels are made from, with the target mesh and the resolution: the key of a kept result.
  madeKey() {
    return `${this.targetKey}|${this.resolution}|${panelInputs(this.design)}`;
  }

  keepResult(key, value) {
    this.kept.delete(key);
    this.kept.set(key, value);
    if (this.kept.size > KEPT_RESULTS) this.kept.delete(this.kept.keys().next().value);
  }

  // The result kept for this key (now the newest), or null.
  keptResult(key) {
    const value = this.kept.get(key);
    if (value === undefined) return null;
    this.keepResult(key, value);
    return value;
  }

  dropResult(kind) {
    this.results.delete(kind);
    this.changed('results');
  }

  clearResults() {
    this.results.clear();
    this.changed('results');
  }

  // Work of a kind began (+1) or ended (-1).
  working(kind, delta) {
    this.work.set(kind, (this.work.get(kind) ?? 0) + delta);
    this.changed('work');
  }

  // True while work of this kind (or of any kind) runs.
  isWorking(kind = null) {
    if (kind) return (this.work.get(kind) ?? 0) > 0;
    return [...this.work.values()].some((n) => n > 0);
  }

  // The optimized panels of the current design, made, inflated and on screen, with nothing under way:
  // { optimized, inflated, pattern }, or null.
  optimizedShown() {
    const optimized = this.result('optimized');
    const { inflated, pattern, patternText } = this.shown;
    if (!optimized || this.isWorking('panels') || this.isWorking('inflation') || !inflated || patternText !== optimized.patternText) return null;
    return { optimized, inflated, pattern };
  }

  show(changes) {
    Object.assign(this.shown, changes);
    this.changed('shown');
  }

  setStatus(text) {
    this.status = text;
    this.changed('status');
  }
}
