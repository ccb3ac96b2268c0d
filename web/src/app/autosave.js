// Autosave in IndexedDB: the design document and, for a target loaded from a file, its welded mesh.
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
};
