// Undo/redo as a history of document snapshots (documents are immutable values; commands are pure
// doc -> doc functions). Quick successive edits with the same merge key (a slider drag, a point drag)
// become one step.
export class History {
  constructor(initial, { limit = 200, mergeMillis = 800 } = {}) {
    this.past = [];
    this.present = initial;
    this.future = [];
    this.limit = limit;
    this.mergeMillis = mergeMillis;
    this.lastKey = null;
    this.lastTime = 0;
  }

  // Applies command(doc) -> doc. mergeKey: edits with the same key within mergeMillis merge into one step; with
  // gesture, however far apart (a point drag, whose end calls endStep: a pause mid-drag on a slow machine is still
  // the one drag).
  apply(command, { mergeKey = null, gesture = false, now = Date.now() } = {}) {
    const next = command(this.present);
    if (next === this.present) return this.present;
    const merge = mergeKey !== null && mergeKey === this.lastKey && (gesture || now - this.lastTime < this.mergeMillis);
    if (!merge) {
      this.past.push(this.present);
      if (this.past.length > this.limit) this.past.shift();
    }
    this.present = next;
    this.future = [];
    this.lastKey = mergeKey;
    this.lastTime = now;
    return next;
  }

  // Changes the present without a new step: derived fix-ups that belong to the edit just made
  // (e.g. seam ends that follow the seam they are attached to).
  amend(command) {
    this.present = command(this.present);
    return this.present;
  }

  // Replaces the whole history (a new target or an opened design).
  reset(doc) {
    this.past = [];
    this.future = [];
    this.present = doc;
    this.lastKey = null;
  }

  // The next edit is a step of its own, even with the same merge key (a gesture ended).
  endStep() {
    this.lastKey = null;
  }

  get canUndo() {
    return this.past.length > 0;
  }

  get canRedo() {
    return this.future.length > 0;
  }

  undo() {
    if (!this.canUndo) return this.present;
    this.future.push(this.present);
    this.present = this.past.pop();
    this.lastKey = null;
    return this.present;
  }

  redo() {
    if (!this.canRedo) return this.present;
    this.past.push(this.present);
    this.present = this.future.pop();
    this.lastKey = null;
    return this.present;
  }
}
