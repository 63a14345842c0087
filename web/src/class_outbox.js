// The phone's outbox of tosses for its class (docs/phone-lab.md, "In a class"; the class's API
// in docs/class.md): every toss the lab keeps while the phone is in a class, held in the phone's
// storage until the class's server says it holds it, sent one at a time in the order kept, each
// under the id the phone made for it as it was kept, so that a resend (a lost answer, a reload,
// a second tab) is stored once. No DOM, no fetch of its own: the page gives it its storage and
// its send (class_join.js), node's tests give it theirs (tests/web/class_outbox_test.mjs).

/** The first wait before a toss is tried again after a failed send (ms); each further failure
 * in a row doubles it, up to RETRY_MAX_MS. */
export const RETRY_FIRST_MS = 1000;
export const RETRY_MAX_MS = 60000;

/** A toss's id, made on the phone as it is kept: a UUID version 4 (RFC 9562, §5.4), from
 * crypto.randomUUID where the page is a secure context, else from crypto.getRandomValues (a
 * page over plain http has no randomUUID). */
export function tossId() {
  if (globalThis.crypto && typeof crypto.randomUUID === 'function') return crypto.randomUUID();
  const b = crypto.getRandomValues(new Uint8Array(16));
  b[6] = (b[6] & 0x0f) | 0x40;
  b[8] = (b[8] & 0x3f) | 0x80;
  const hex = [...b].map((x) => x.toString(16).padStart(2, '0')).join('');
  return `${hex.slice(0, 8)}-${hex.slice(8, 12)}-${hex.slice(12, 16)}-${hex.slice(16, 20)}-${hex.slice(20)}`;
}

/** What the server's answer `status` (an HTTP status) with its JSON `body` means for the toss
 * sent: 'held' (201 stored, or 200: that id already held for this student), 'refused' (any other
 * 4xx: the toss itself or the phone's place in the class is refused; sending it again would be
 * refused again), 'retry' (408, 425, 429 and 5xx: the server is busy or down for now; anything
 * else, not held). */
export function verdict(status, body) {
  if ((status === 200 || status === 201) && body && body.held === true) return 'held';
  if (status === 408 || status === 425 || status === 429 || status >= 500) return 'retry';
  if (status >= 400 && status < 500) return 'refused';
  return 'retry';
}

/** Whether the answer `status` is the server's own failure on the toss it was sent (500, 501,
 * 505 and up: the server reached, and it failed on this request), which the tosses behind it
 * need not wait for; not 502, 503 or 504 (a proxy's: the server behind it down, busy or too
 * slow), which every toss would meet. */
export function serverFault(status) {
  return status >= 500 && status !== 502 && status !== 503 && status !== 504;
}

/** The wait (ms) before the next try after `failures` failed sends in a row (1, 2, …): doubling
 * from RETRY_FIRST_MS to RETRY_MAX_MS, spread by ±20 % (`random()` in [0, 1)) so that a class's
 * phones coming back on the network at once do not all ask at the same instant. */
export function retryDelay(failures, random = Math.random) {
  const base = Math.min(RETRY_MAX_MS, RETRY_FIRST_MS * 2 ** Math.max(0, failures - 1));
  return Math.round(base * (0.8 + 0.4 * random()));
}

/** The words a toss's state is shown and said in (the list's line for it). */
export function stateWords(item) {
  if (!item) return '';
  if (item.state === 'held') return `✓ held by class ${item.code}`;
  if (item.state === 'refused') return `✗ refused by class ${item.code}: ${item.reason}`;
  if (item.state === 'sending') return `… sending to class ${item.code}`;
  return `… waiting to be sent to class ${item.code}${item.reason ? ` (${item.reason})` : ''}`;
}

/** The outbox. `store`: a promise of the phone's storage {all() → rows, put(row), remove(key)}
 * (each a promise; rows keyed by `toss`), or of null where the browser gives the page none (the
 * outbox then lasts as long as the page). `post(item)`: sends one toss ({toss, code, name,
 * recorded_at, csv}), a promise of {status, body} (the server's answer, its JSON or
 * {error: its text}), rejected where no answer came (no network, the server down, a timeout).
 * `onChange(item)`: told each change of a toss's state. `later(fn, ms)` and `cancel(timer)`:
 * the clock (setTimeout's, unless a test's). `random`: retryDelay's.
 *
 * A toss's row: {toss (its id), seq (the order kept), code (its class), recording (the lab's
 * id of its recording), name, recorded_at (ISO 8601), csv (dropped once held), state
 * ('waiting', 'held', 'refused'; 'sending' while in flight, never stored), reason (why waiting
 * or refused: a failure's or the server's words)}. */
export class ClassOutbox {
  constructor({ store, post, onChange = () => {}, later = (fn, ms) => setTimeout(fn, ms),
    cancel = (t) => clearTimeout(t), random = Math.random }) {
    this.post = post;
    this.onChange = onChange;
    this.later = later;
    this.cancelTimer = cancel;
    this.random = random;
    /** toss id → row, every toss this phone gave its classes. */
    this.items = new Map();
    this.failures = 0;
    this.timer = null;
    this.draining = null;
    this.again = false; // drain at once once this drain ends
    this.due = false; // the wait ran out during a drain: a try once it ends
    this.seq = 0;
    /** Where the rows are kept: the storage, or null (the outbox lasts as long as the page). */
    this.store = Promise.resolve(store).catch(() => null);
    /** Settles once the rows stored by earlier pages are read in. */
    this.loaded = this.store.then((s) => (s ? s.all() : [])).then((rows) => {
      for (const row of rows) {
        if (!row || typeof row.toss !== 'string' || this.items.has(row.toss)) continue;
        // One cut off while in flight by a reload: its answer never came; it waits.
        const item = { ...row, state: row.state === 'sending' ? 'waiting' : row.state };
        this.items.set(item.toss, item);
        this.seq = Math.max(this.seq, (item.seq || 0) + 1);
      }
    }).catch(() => {});
  }

  /** The row of toss `toss`, or undefined where this phone gave no class that toss. */
  state(toss) { return this.items.get(toss); }

  /** Every row in the order kept. */
  list() { return [...this.items.values()].sort((a, b) => a.seq - b.seq); }

  /** The toss `{toss, code, recording, name, recorded_at, csv}` put in the outbox: stored
   * first, then sent (after those kept before it). A toss already in it is left as it is. A
   * promise that settles once it is stored (or could not be). */
  add(toss) {
    return this.loaded.then(() => {
      if (this.items.has(toss.toss)) return this.items.get(toss.toss);
      const item = { ...toss, seq: this.seq++, state: 'waiting', reason: '' };
      this.items.set(item.toss, item);
      this.onChange(item);
      return this.save(item).then(() => { this.drain(); return item; });
    });
  }

  /** Toss `toss` taken out of the outbox (its recording removed from the phone): not sent,
   * or not sent again; a send in flight ends as it ends, its answer dropped. A promise that
   * settles once the storage has dropped it. */
  forget(toss) {
    this.items.delete(toss);
    return this.store.then((s) => s && s.remove(toss)).catch(() => {});
  }

  save(item) {
    const { state, ...row } = item;
    const stored = { ...row, state: state === 'sending' ? 'waiting' : state };
    return this.store.then((s) => s && s.put(stored)).catch(() => {});
  }

  /** Every waiting toss sent, in the order kept, one at a time, until all are held or refused
   * or one fails to reach the server (sendNext): then the rest wait for the next try (retryDelay after
   * the failures in a row; `now`: at once, the failures forgotten: the browser back online,
   * the page loaded). A promise that settles when this drain ends. */
  drain(now = false) {
    if (now) {
      this.failures = 0;
      if (this.timer !== null) { this.cancelTimer(this.timer); this.timer = null; }
    }
    if (this.draining) {
      if (now) this.again = true;
      return this.draining;
    }
    if (this.timer !== null && !now) return Promise.resolve();
    this.draining = this.loaded.then(() => this.sendNext()).finally(() => {
      this.draining = null;
      // Asked to drain at once while draining (back online as a send failed): once more now.
      if (this.again) { this.again = false; this.drain(true); }
      // The wait ran out while the others were sent: its try now.
      else if (this.due) { this.due = false; this.drain(); }
    });
    return this.draining;
  }

  /** The first waiting toss sent, then the next, until none waits or one is not held and
   * not refused: it and the rest wait for the next try, but for the server's own error about
   * that toss (serverFault: the server reached, and it failed on this toss), after which the
   * rest go on in this drain and it alone waits. */
  async sendNext() {
    const passed = new Set(); // tosses the server failed on in this drain: tried again later
    for (;;) {
      const next = this.list().find((i) => i.state === 'waiting' && !passed.has(i.toss));
      if (!next) return;
      next.state = 'sending';
      this.onChange(next);
      const { toss, code, name, recorded_at, csv } = next;
      let answer;
      try {
        answer = await this.post({ toss, code, name, recorded_at, csv });
      } catch (e) {
        answer = null;
      }
      // Forgotten while in flight (its recording removed): its answer changes nothing.
      if (this.items.get(toss) !== next) continue;
      const what = answer ? verdict(answer.status, answer.body) : 'retry';
      const said = answer && answer.body && answer.body.error;
      if (what === 'held') {
        this.failures = 0;
        Object.assign(next, { state: 'held', reason: '' });
        delete next.csv;
      } else if (what === 'refused') {
        Object.assign(next, { state: 'refused', reason: said || `the server answered ${answer.status}` });
      } else {
        // Not held and not refused: it waits for the next try, and the rest behind it unless
        // the server failed on this toss alone.
        this.failures += 1;
        const wait = retryDelay(this.failures, this.random);
        const why = answer ? `the server answered ${answer.status}${said ? `: ${said}` : ''}` : 'no network or no server';
        Object.assign(next, { state: 'waiting', reason: `${why}; next try in ${Math.round(wait / 1000)} s` });
        if (this.timer === null) {
          this.timer = this.later(() => {
            this.timer = null;
            if (this.draining) this.due = true; else this.drain();
          }, wait);
        }
        if (answer && serverFault(answer.status)) passed.add(next.toss);
      }
      this.onChange(next);
      await this.save(next);
      if (what === 'retry' && !passed.has(next.toss)) return;
    }
  }
}
