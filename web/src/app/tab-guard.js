// Two-tab protection for the autosave: of all the tabs of this browser that have Billow open, only one
// (the primary) autosaves, so two tabs never overwrite each other's design. The primary holds a Web Lock
// for as long as it is open; the others wait in the lock's queue, and the first of them becomes primary
// as soon as the primary tab closes or reloads. Without the Web Locks API every tab is primary.
const DEFAULT_NAME = 'billow-autosave';

// What a secondary tab tells the designer.
export function secondaryTabMessage() {
  return 'Billow is already open in another tab. This tab does not autosave over it, so the other tab\'s design is safe; what you do here survives reloading this tab, and Save design keeps it for good.';
}

export class TabGuard {
  // onChange(isPrimary) is called whenever isPrimary changes, never for the starting state: a tab counts
  // as primary until start() finds out otherwise.
  constructor({ name = DEFAULT_NAME, onChange = () => {} } = {}) {
    this.name = name;
    this.onChange = onChange;
    this.primary = true;
    this.stopped = false;
    this.release = null; // ends the callback that holds the lock
    this.abort = null; // withdraws a waiting request
  }

  get isPrimary() {
    return this.primary;
  }

  // Resolves with isPrimary once this tab knows whether it is primary.
  async start() {
    this.stopped = false;
    const locks = globalThis.navigator?.locks;
    if (!locks) {
      this.set(true);
      return this.primary;
    }
    const granted = await new Promise((resolve) => {
      locks
        .request(this.name, { ifAvailable: true }, (lock) => {
          resolve(Boolean(lock));
          return lock ? this.hold() : undefined;
        })
        .then(
          () => this.lost(locks),
          () => {
            resolve(true); // locks refused altogether (e.g. an opaque origin): as without locks
            this.lost(locks);
          },
        );
    });
    if (!granted) {
      this.set(false);
      this.wait(locks);
    }
    return this.primary;
  }

  // Gives up the lock or the place in its queue. The tab stops autosaving (isPrimary is false), without
  // onChange: a stopped guard guards nothing, and two primaries must never be.
  stop() {
    this.stopped = true;
    this.abort?.abort();
    this.abort = null;
    this.release?.();
    this.release = null;
    this.primary = false;
  }

  // The lock is held until the promise returned here settles: when stop() is called or the tab goes away.
  hold() {
    this.set(true);
    return new Promise((resolve) => (this.release = resolve));
  }

  // Queues a request that is granted when the tab holding the lock closes.
  wait(locks) {
    if (this.stopped) return;
    this.abort = new AbortController();
    locks
      .request(this.name, { signal: this.abort.signal }, () => this.hold())
      .then(() => this.lost(locks), () => this.lost(locks));
  }

  // A request ended: either stop() released it, or the lock was taken away (steal) while held.
  lost(locks) {
    if (this.stopped || !this.release) return;
    this.release = null;
    this.set(false);
    this.wait(locks);
  }

  set(primary) {
    if (primary === this.primary) return;
    this.primary = primary;
    this.onChange(primary);
  }
}
