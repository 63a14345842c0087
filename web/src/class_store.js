// The outbox of a phone's tosses for its class kept across a reload (class_outbox.js): the
// browser's IndexedDB, a database of its own beside the lab's recordings (kept_store.js).

import { inTransaction } from './kept_store.js';

/** The browser's storage of the outbox's rows (IndexedDB database `name`, its store `outbox`
 * keyed by the toss's id): a promise of {all() → rows, put(row), remove(toss)}, each a promise;
 * rejected where the browser gives the page no storage (a private window, storage blocked, no
 * IndexedDB). */
export function classStore(name = 'bookspin-class') {
  return new Promise((resolve, reject) => {
    let request;
    try {
      request = indexedDB.open(name, 1);
    } catch (e) {
      reject(e);
      return;
    }
    request.onupgradeneeded = () => request.result.createObjectStore('outbox', { keyPath: 'toss' });
    request.onerror = () => reject(request.error || new Error('IndexedDB refused'));
    request.onblocked = () => reject(new Error('IndexedDB blocked'));
    request.onsuccess = () => {
      const db = request.result;
      const go = inTransaction(db, 'outbox');
      resolve({
        all: () => go('readonly', (s) => s.getAll()),
        put: (row) => go('readwrite', (s) => s.put(row)),
        remove: (toss) => go('readwrite', (s) => s.delete(toss)),
      });
    };
  });
}
