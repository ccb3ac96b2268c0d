// Autosave in IndexedDB: the design document and, for a target loaded from a file, its welded mesh.
// Two kinds of record: 'current', written by the one tab that autosaves (tab-guard.js) and opened by a new
// tab, and one per tab ('tab:<id>', the id kept in the tab's sessionStorage), written by every tab, so a
// reloaded tab finds its own design, even a tab that is not the one that autosaves.
const DB_NAME = 'billow';
const STORE = 'autosave';

function open() {
  return new Promise((resolve, reject) => {
    const request = indexedDB.open(DB_NAME, 1);
    request.onupgradeneeded = () => request.result.createObjectStore(STORE);
    request.onsuccess = () => resolve(request.result);
    request.onerror = () => reject(request.error);
  });
}

async function transact(mode, fn) {
  const db = await open();
  try {
    return await new Promise((resolve, reject) => {
      const tx = db.transaction(STORE, mode);
      const result = fn(tx.objectStore(STORE));
      tx.oncomplete = () => resolve(result.result);
      tx.onerror = () => reject(tx.error);
      tx.onabort = () => reject(tx.error);
    });
  } finally {
    db.close();
  }
}

export const autosave = {
  // record: { design, mesh?: { positions, indices } }
  save: (key, record) => transact('readwrite', (store) => store.put({ ...record, savedAt: Date.now() }, key)),
  load: (key) => transact('readonly', (store) => store.get(key)),
  clear: (key) => transact('readwrite', (store) => store.delete(key)),
  // Deletes the per-tab records ('tab:...') not saved for maxAgeMs, except keep's.
  pruneTabs: (keep, maxAgeMs, now = Date.now()) =>
    transact('readwrite', (store) => {
      const request = store.openCursor();
      request.onsuccess = () => {
        const cursor = request.result;
        if (!cursor) return;
        const key = String(cursor.key);
        if (key.startsWith('tab:') && key !== keep && !(now - (cursor.value?.savedAt ?? 0) < maxAgeMs)) cursor.delete();
        cursor.continue();
      };
      return request;
    }),
};

// This tab's own record key, stable across reloads of the tab (sessionStorage), new for a new tab.
export function tabRecordKey() {
  const name = 'billow-tab-id';
  try {
    let id = sessionStorage.getItem(name);
    if (!id) {
      id = crypto.randomUUID?.() ?? `${Date.now()}-${Math.random().toString(36).slice(2)}`;
      sessionStorage.setItem(name, id);
    }
    return `tab:${id}`;
  } catch {
    return null; // storage refused: only the shared record
  }
}
