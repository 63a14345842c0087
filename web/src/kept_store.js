// The lab's recordings kept across a reload: the browser's IndexedDB, one concept (docs/phone-lab.md,
// "The lab in a class").

/** The store's version, this page's: a store a newer page left at a later one is named so,
 * never blamed on the browser. */
export const STORE_VERSION = 1;

/** The id of the row that holds the recording in progress, written again while it records and
 * when the page is hidden or left (pagehide): what a reload finds there was cut short by it. */
export const LIVE_ID = 0;

/** One IndexedDB object store `store` of the open database `db` as a function (mode, act):
 * `act(objectStore)` run in a transaction of `mode`, a promise of its request's result, settled
 * when the transaction is committed (a row said stored is on the disk's way). The lab's store and
 * the class's outbox (class_store.js) both. */
export function inTransaction(db, store) {
  return (mode, act) => new Promise((done, failed) => {
    const tx = db.transaction(store, mode);
    const r = act(tx.objectStore(store));
    tx.oncomplete = () => done(r.result);
    tx.onerror = () => failed(tx.error);
    tx.onabort = () => failed(tx.error || new Error('IndexedDB aborted'));
  });
}

/** The browser's own storage of the lab's recordings (IndexedDB): a promise of the store's
 * four doors {all() → rows, put(row), settle(row): row put and the row in progress (LIVE_ID)
 * removed in one transaction (a reload finds one or the other, never both or neither),
 * remove(id)}, each a promise; rejected where the browser
 * gives the page no storage (a private window, storage blocked, no IndexedDB), or with an
 * Error named 'StoreVersionError' whose message says so where the store is at a later version
 * than STORE_VERSION (a newer page's). A row: {id, name, when (ISO time), samples, rate, api,
 * text, ticked, and cut: why it was cut short, where the page has not said so yet}; the
 * recording in progress is the row LIVE_ID. */
export function keptStore(name = 'bookspin-lab') {
  return new Promise((resolve, reject) => {
    let request;
    try {
      request = indexedDB.open(name, STORE_VERSION);
    } catch (e) {
      reject(e);
      return;
    }
    request.onupgradeneeded = () => request.result.createObjectStore('recordings', { keyPath: 'id' });
    request.onerror = () => {
      const error = request.error || new Error('IndexedDB refused');
      if (error.name !== 'VersionError') { reject(error); return; }
      // The store is there at a later version: which, read by opening it as it is.
      const asIs = indexedDB.open(name);
      const said = (version) => {
        const e = new Error(`this browser holds the lab's recordings in a store at version ${version ?? 'later than ' + STORE_VERSION}, ` +
          `made by a newer copy of this page (this one reads version ${STORE_VERSION})`);
        e.name = 'StoreVersionError';
        reject(e);
      };
      asIs.onsuccess = () => { const v = asIs.result.version; asIs.result.close(); said(v); };
      asIs.onerror = () => said(null);
    };
    request.onblocked = () => reject(new Error('IndexedDB blocked'));
    request.onsuccess = () => {
      const db = request.result;
      // A newer page opened beside this one asks for the store: this page lets go of it.
      db.onversionchange = () => db.close();
      const go = inTransaction(db, 'recordings');
      resolve({
        all: () => go('readonly', (s) => s.getAll()),
        put: (row) => go('readwrite', (s) => s.put(row)),
        settle: (row) => go('readwrite', (s) => { s.delete(LIVE_ID); return s.put(row); }),
        remove: (id) => go('readwrite', (s) => s.delete(id)),
      });
    };
  });
}

/** Why `row` (as the store gave it) is no recording this page can list, or '' where it is one:
 * an older page's row, a write cut by a crash, another page's row under the same name. */
export function rowProblem(row) {
  if (row === null || typeof row !== 'object') return 'not a recording';
  if (!Number.isInteger(row.id) || row.id < 0) return 'its id is not a whole number';
  if (typeof row.name !== 'string' || !row.name) return 'no name';
  if (typeof row.text !== 'string' || !row.text) return 'no text (the recording\'s CSV)';
  if (!Number.isInteger(row.samples) || row.samples < 0) return 'its samples are not a count';
  if (typeof row.rate !== 'number' || !Number.isFinite(row.rate) || row.rate < 0) return 'its rate is not a number';
  if (typeof row.when !== 'string' || Number.isNaN(new Date(row.when).getTime())) return 'its time is not a time';
  if (typeof row.ticked !== 'boolean') return 'its tick is not true or false';
  if ('cut' in row && typeof row.cut !== 'string') return 'why it was cut short is not text';
  if (row.toss !== undefined && typeof row.toss !== 'string') return 'its id for a class is not text';
  return '';
}

/** The rows `rows` split: {good: the rows rowProblem() takes, skipped: "id 5 (no text …)" for
 * each other, named by its id (or its place where it has none)}. */
export function keptRows(rows) {
  const good = [], skipped = [];
  rows.forEach((row, i) => {
    const why = rowProblem(row);
    if (!why) { good.push(row); return; }
    const id = row !== null && typeof row === 'object' && 'id' in row ? `id ${JSON.stringify(row.id)}` : `row ${i + 1}`;
    skipped.push(`${id} (${why})`);
  });
  return { good, skipped };
}
