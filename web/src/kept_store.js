// The lab's recordings kept across a reload: the browser's IndexedDB, one concept (docs/phone-lab.md,
// "The lab in a class").

/** The browser's own storage of the lab's recordings (IndexedDB): a promise of the store's
 * three doors {all() → rows, put(row), remove(id)}, each a promise; rejected where the browser
 * gives the page no storage (a private window, storage blocked, no IndexedDB). A row:
 * {id, name, when (ISO time), samples, rate, api, text, ticked}. */
export function keptStore(name = 'bookspin-lab') {
  return new Promise((resolve, reject) => {
    let request;
    try {
      request = indexedDB.open(name, 1);
    } catch (e) {
      reject(e);
      return;
    }
    request.onupgradeneeded = () => request.result.createObjectStore('recordings', { keyPath: 'id' });
    request.onerror = () => reject(request.error || new Error('IndexedDB refused'));
    request.onblocked = () => reject(new Error('IndexedDB blocked'));
    request.onsuccess = () => {
      const db = request.result;
      const go = (mode, act) => new Promise((done, failed) => {
        const tx = db.transaction('recordings', mode);
        const r = act(tx.objectStore('recordings'));
        tx.oncomplete = () => done(r.result);
        tx.onerror = () => failed(tx.error);
        tx.onabort = () => failed(tx.error || new Error('IndexedDB aborted'));
      });
      resolve({
        all: () => go('readonly', (s) => s.getAll()),
        put: (row) => go('readwrite', (s) => s.put(row)),
        remove: (id) => go('readwrite', (s) => s.delete(id)),
      });
    };
  });
}
