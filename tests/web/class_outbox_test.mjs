// The phone's outbox of tosses for its class (web/src/class_outbox.js, docs/phone-lab.md "In a
// class") under node: a stand-in for the phone's storage (a Map behind promises, as IndexedDB's
// rows are, and reopened for a reload), a class server written here as the API says it answers
// (docs/class.md: a toss id stored once per student, 201 then 200 for the same bytes, 409 for
// other bytes), a network that can be down or lose an answer after the server committed, and a
// clock the test moves by hand. Checked: every toss kept is held once, in the order kept,
// whatever fails on the way; a refusal (4xx) is shown with the server's reason and not sent
// again; no answer or a 5xx is tried again after a wait that doubles, at most 60 s, the first
// wait again once a toss is held, a toss kept during a wait not sent past it (one timer); a
// reload finds every toss not yet held and sends it, and none held again; a toss forgotten (its
// recording removed) is not sent, even when its send was in flight.
// Usage: node tests/web/class_outbox_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/class_outbox_test.mjs SOURCE_DIR');
const { ClassOutbox, verdict, serverFault, retryDelay, tossId, stateWords, RETRY_FIRST_MS, RETRY_MAX_MS } =
  await import(pathToFileURL(join(source, 'web/src/class_outbox.js')).href);

/** The phone's storage: rows kept across "reloads" (each page a new ClassOutbox over it), copied
 * in and out as IndexedDB's structured clone does. */
function phoneStorage() {
  const rows = new Map();
  return {
    rows,
    all: async () => [...rows.values()].map((r) => structuredClone(r)),
    put: async (row) => { rows.set(row.toss, structuredClone(row)); },
    remove: async (toss) => { rows.delete(toss); },
  };
}

/** The class's server as docs/class.md says it answers, behind a network the test breaks:
 * `down` (no answer at all), `loseAnswer` (the server commits, the answer never arrives),
 * `status` (every request answered so, a 5xx or a 4xx with `error`). `stored`: each toss in
 * the order it was stored. */
function classServer() {
  const server = { stored: [], byId: new Map(), down: false, loseAnswer: 0, status: 0, error: '', asked: [] };
  server.post = async (item) => {
    server.asked.push(item.toss);
    if (server.down) throw new TypeError('Failed to fetch');
    if (server.status) return { status: server.status, body: { error: server.error } };
    let answer;
    if (typeof item.toss !== 'string' || !/^[0-9a-f-]{36}$/.test(item.toss)) answer = { status: 400, body: { error: 'toss: not a UUID' } };
    else if (server.byId.has(item.toss)) {
      answer = server.byId.get(item.toss).csv === item.csv
        ? { status: 200, body: { toss: item.toss, held: true } }
        : { status: 409, body: { error: `toss ${item.toss} is held with other bytes` } };
    } else {
      server.byId.set(item.toss, item);
      server.stored.push(item);
      answer = { status: 201, body: { toss: item.toss, held: true } };
    }
    if (server.loseAnswer > 0) { server.loseAnswer -= 1; throw new TypeError('network changed: the answer was lost'); }
    return answer;
  };
  return server;
}

/** A clock the test moves: timers kept, run by tick(). */
function handClock() {
  const clock = { timers: [], waits: [] };
  clock.later = (fn, ms) => { const t = { fn, ms }; clock.timers.push(t); clock.waits.push(ms); return t; };
  clock.cancel = (t) => { clock.timers = clock.timers.filter((x) => x !== t); };
  /** Every timer due runs (as setTimeout would after its wait). */
  clock.tick = () => { const due = clock.timers; clock.timers = []; for (const t of due) t.fn(); };
  return clock;
}

/** An outbox over `storage`, `server` and `clock`, as the page makes it (a page's life). */
function page(storage, server, clock) {
  const changes = [];
  const outbox = new ClassOutbox({ store: Promise.resolve(storage), post: server.post, later: clock.later,
    cancel: clock.cancel, random: () => 0.5, onChange: (item) => changes.push([item.toss, item.state]) });
  return { outbox, changes };
}

/** A toss as the lab keeps it: its id made on the phone, its CSV. */
let made = 0;
function toss(code = 'ABC123') {
  made += 1;
  return { toss: tossId(), code, recording: made, name: `toss-2026-11-29-10-00-0${made}-gyroscope-60Hz.csv`,
    recorded_at: new Date(Date.UTC(2026, 10, 29, 9, 0, made)).toISOString(), csv: `t,wx,wy,wz\n0,${made},0,0\n` };
}

/** Until every pending promise of the outbox has run (the storage's and the server's). */
const settle = async (outbox) => { for (let k = 0; k < 20; ++k) { await outbox.draining; await new Promise((r) => setImmediate(r)); } };

test('a toss id is a fresh UUID v4, with or without crypto.randomUUID', () => {
  const v4 = /^[0-9a-f]{8}-[0-9a-f]{4}-4[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}$/;
  const ids = new Set(Array.from({ length: 200 }, () => tossId()));
  assert.equal(ids.size, 200);
  for (const id of ids) assert.match(id, v4);
  // A page over plain http: no randomUUID; getRandomValues alone.
  const own = crypto.randomUUID;
  try {
    Object.defineProperty(crypto, 'randomUUID', { value: undefined, configurable: true });
    const plain = new Set(Array.from({ length: 200 }, () => tossId()));
    assert.equal(plain.size, 200);
    for (const id of plain) assert.match(id, v4);
  } finally {
    Object.defineProperty(crypto, 'randomUUID', { value: own, configurable: true, writable: true });
  }
});

test('an answer means held (201, 200 held), refused (4xx) or try again (no 2xx held, 408, 429, 5xx)', () => {
  assert.equal(verdict(201, { held: true }), 'held');
  assert.equal(verdict(200, { held: true }), 'held');
  assert.equal(verdict(200, {}), 'retry');
  for (const s of [400, 401, 403, 404, 409, 413, 422]) assert.equal(verdict(s, { error: 'x' }), 'refused', String(s));
  for (const s of [408, 425, 429, 500, 502, 503, 504]) assert.equal(verdict(s, { error: 'x' }), 'retry', String(s));
});

test('the wait before a try again doubles from 1 s to 60 s, spread ±20 %', () => {
  assert.deepEqual([1, 2, 3, 4, 5, 6, 7, 8, 20].map((n) => retryDelay(n, () => 0.5)),
    [1000, 2000, 4000, 8000, 16000, 32000, 60000, 60000, 60000]);
  assert.equal(retryDelay(1, () => 0), 0.8 * RETRY_FIRST_MS);
  assert.ok(retryDelay(30, () => 0.999999) <= 1.2 * RETRY_MAX_MS);
});

test('tosses kept with no network wait in storage, in order, and are each held once when it comes back', async () => {
  const storage = phoneStorage(), server = classServer(), clock = handClock();
  const { outbox } = page(storage, server, clock);
  server.down = true;
  const kept = [toss(), toss(), toss()];
  for (const k of kept) await outbox.add(k);
  await settle(outbox);
  assert.equal(server.stored.length, 0);
  // Each kept in the phone's storage with its bytes, waiting; the first tried, the rest behind it.
  assert.deepEqual([...storage.rows.values()].map((r) => [r.toss, r.state, r.csv]), kept.map((k) => [k.toss, 'waiting', k.csv]));
  assert.ok(server.asked.every((id) => id === kept[0].toss), `tried out of order: ${server.asked}`);
  assert.match(stateWords(outbox.state(kept[2].toss)), /waiting to be sent to class ABC123/);
  assert.match(outbox.state(kept[0].toss).reason, /no network or no server; next try in \d+ s/);
  // Each failed try waits twice as long as the one before.
  const tries = server.asked.length;
  clock.tick(); await settle(outbox);
  clock.tick(); await settle(outbox);
  assert.equal(server.asked.length, tries + 2);
  assert.deepEqual(clock.waits.slice(-3), [clock.waits.at(-3), 2 * clock.waits.at(-3), 4 * clock.waits.at(-3)]);
  // Back: the next try sends all three, in the order kept, each stored once.
  server.down = false;
  clock.tick(); await settle(outbox);
  assert.deepEqual(server.stored.map((s) => s.toss), kept.map((k) => k.toss));
  assert.deepEqual(server.stored.map((s) => s.csv), kept.map((k) => k.csv));
  for (const k of kept) assert.equal(outbox.state(k.toss).state, 'held');
  // Held: the phone's copy of the bytes dropped, the state kept.
  assert.deepEqual([...storage.rows.values()].map((r) => [r.state, 'csv' in r]), kept.map(() => ['held', false]));
  assert.equal(clock.timers.length, 0);
});

test('back online sends at once, not after the wait', async () => {
  const storage = phoneStorage(), server = classServer(), clock = handClock();
  const { outbox } = page(storage, server, clock);
  server.down = true;
  const k = toss();
  await outbox.add(k);
  await settle(outbox);
  for (let n = 0; n < 5; ++n) { clock.tick(); await settle(outbox); }
  assert.equal(clock.timers.length, 1);
  assert.equal(clock.waits.at(-1), 32000);
  // Online, but the server still unreachable (the Wi-Fi back, the laptop not yet): the waits
  // start again from the first.
  await outbox.drain(true);
  await settle(outbox);
  assert.equal(clock.timers.length, 1);
  assert.equal(clock.waits.at(-1), RETRY_FIRST_MS);
  server.down = false;
  await outbox.drain(true);  // the browser's online event
  await settle(outbox);
  assert.equal(clock.timers.length, 0, 'the pending try was not cancelled');
  assert.deepEqual(server.stored.map((s) => s.toss), [k.toss]);
  assert.equal(outbox.failures, 0);
});

test('an answer lost after the server stored the toss: sent again under its id, stored once', async () => {
  const storage = phoneStorage(), server = classServer(), clock = handClock();
  const { outbox } = page(storage, server, clock);
  server.loseAnswer = 2;
  const k = toss();
  await outbox.add(k);
  await settle(outbox);
  assert.equal(outbox.state(k.toss).state, 'waiting');
  clock.tick(); await settle(outbox);
  clock.tick(); await settle(outbox);
  assert.equal(outbox.state(k.toss).state, 'held');
  assert.equal(server.asked.length, 3);
  assert.deepEqual(new Set(server.asked), new Set([k.toss]));
  assert.equal(server.stored.length, 1);
});

test('a reload finds the tosses not yet held and sends them; those held are not sent again', async () => {
  const storage = phoneStorage(), server = classServer(), clock = handClock();
  const first = page(storage, server, clock);
  const held = toss();
  await first.outbox.add(held);
  await settle(first.outbox);
  // A toss whose answer a reload cut: stored as waiting though the server holds it.
  server.loseAnswer = 1;
  const cut = toss();
  await first.outbox.add(cut);
  await settle(first.outbox);
  server.down = true;
  const waiting = [toss(), toss()];
  for (const k of waiting) await first.outbox.add(k);
  await settle(first.outbox);
  server.down = false;
  assert.equal(server.stored.length, 2);
  // The page reloaded (the old one's timers gone with it): a new outbox over the same storage.
  const asked = server.asked.length;
  const second = page(storage, server, handClock());
  await second.outbox.loaded;
  assert.deepEqual(second.outbox.list().map((i) => [i.toss, i.state]),
    [[held.toss, 'held'], [cut.toss, 'waiting'], ...waiting.map((k) => [k.toss, 'waiting'])]);
  await second.outbox.drain(true);  // the page loaded
  await settle(second.outbox);
  assert.deepEqual(server.asked.slice(asked), [cut, ...waiting].map((k) => k.toss), 'the held one sent again, or out of order');
  assert.deepEqual(server.stored.map((s) => s.toss), [held, cut, ...waiting].map((k) => k.toss));
  for (const k of [held, ...waiting, cut]) assert.equal(second.outbox.state(k.toss).state, 'held');
  // Added again (two tabs, a double hook): still once.
  await second.outbox.add(held);
  await settle(second.outbox);
  assert.equal(server.stored.length, 4);
});

test('a refusal (4xx) is shown with the server\'s reason and not sent again; the tosses behind it go on', async () => {
  const storage = phoneStorage(), server = classServer(), clock = handClock();
  const { outbox } = page(storage, server, clock);
  const bad = toss();
  server.status = 413;
  server.error = 'the request is 5 MiB: at most 4 MiB';
  await outbox.add(bad);
  await settle(outbox);
  assert.equal(outbox.state(bad.toss).state, 'refused');
  assert.equal(stateWords(outbox.state(bad.toss)), '✗ refused by class ABC123: the request is 5 MiB: at most 4 MiB');
  assert.equal(clock.timers.length, 0, 'a refused toss is tried again');
  assert.equal(storage.rows.get(bad.toss).state, 'refused');
  server.status = 0;
  const good = toss();
  await outbox.add(good);
  await settle(outbox);
  for (let n = 0; n < 3; ++n) { clock.tick(); await outbox.drain(true); await settle(outbox); }
  assert.deepEqual(server.asked, [bad.toss, good.toss]);
  assert.equal(outbox.state(good.toss).state, 'held');
  // A reload does not send it again either.
  const again = page(storage, server, handClock());
  await again.outbox.drain(true);
  await settle(again.outbox);
  assert.deepEqual(server.asked, [bad.toss, good.toss]);
  assert.equal(again.outbox.state(bad.toss).state, 'refused');
});

test('a server error (5xx) or a busy server (429) is tried again, the reason shown meanwhile', async () => {
  const storage = phoneStorage(), server = classServer(), clock = handClock();
  const { outbox } = page(storage, server, clock);
  server.status = 503;
  server.error = 'the database is busy';
  const k = toss();
  await outbox.add(k);
  await settle(outbox);
  assert.equal(outbox.state(k.toss).state, 'waiting');
  assert.match(outbox.state(k.toss).reason, /^the server answered 503: the database is busy; next try in 1 s$/);
  server.status = 429;
  clock.tick(); await settle(outbox);
  assert.equal(outbox.state(k.toss).state, 'waiting');
  server.status = 0;
  clock.tick(); await settle(outbox);
  assert.equal(outbox.state(k.toss).state, 'held');
  assert.equal(server.stored.length, 1);
});

test('the server failing on one toss (500) holds back none behind it; a proxy\'s 502–504 holds back all', async () => {
  for (const s of [500, 501, 505, 599]) assert.equal(serverFault(s), true, String(s));
  for (const s of [502, 503, 504, 429, 408, 201, 404]) assert.equal(serverFault(s), false, String(s));
  const storage = phoneStorage(), server = classServer(), clock = handClock();
  const post = server.post;
  let bad = null;
  // The server fails on one toss (a bug its bytes meet), and on that one alone.
  server.post = async (item) => (item.toss === bad
    ? (server.asked.push(item.toss), { status: 500, body: { error: 'internal error' } }) : post(item));
  const { outbox } = page(storage, server, clock);
  const first = toss(), second = toss(), third = toss();
  bad = first.toss;
  await outbox.add(first);
  await outbox.add(second);
  await outbox.add(third);
  await settle(outbox);
  assert.equal(outbox.state(first.toss).state, 'waiting');
  assert.match(outbox.state(first.toss).reason, /^the server answered 500: internal error; next try in 1 s$/);
  assert.deepEqual(server.stored.map((i) => i.toss), [second.toss, third.toss]);
  assert.equal(clock.timers.length, 1, 'one timer for the toss that waits');
  // Its wait ran out while the others were being sent: it is tried when that drain ends.
  bad = null;
  clock.tick(); await settle(outbox);
  assert.equal(outbox.state(first.toss).state, 'held');
  assert.deepEqual(server.stored.map((i) => i.toss), [second.toss, third.toss, first.toss]);
  // A proxy's 503 (the server behind it away): the first waits, and those behind it too.
  server.status = 503;
  const fourth = toss(), fifth = toss();
  const asked = server.asked.length;
  await outbox.add(fourth);
  await outbox.add(fifth);
  await settle(outbox);
  assert.deepEqual(server.asked.slice(asked), [fourth.toss], 'the tosses behind a 503 wait');
  assert.equal(outbox.state(fifth.toss).state, 'waiting');
  server.status = 0;
  clock.tick(); await settle(outbox);
  assert.deepEqual(server.stored.slice(-2).map((i) => i.toss), [fourth.toss, fifth.toss]);
});

test('a wait that runs out during a drain is not lost: the toss is tried once the drain ends', async () => {
  const storage = phoneStorage(), server = classServer(), clock = handClock();
  const post = server.post;
  let bad = null, release = null;
  server.post = async (item) => {
    if (item.toss === bad) { server.asked.push(item.toss); return { status: 500, body: { error: 'internal error' } }; }
    if (release === null) return post(item);
    await new Promise((r) => { release = r; });  // a slow send: the wait runs out meanwhile
    return post(item);
  };
  const { outbox } = page(storage, server, clock);
  const first = toss(), second = toss();
  bad = first.toss;
  release = () => {};
  await outbox.add(first);
  await outbox.add(second);
  for (let k = 0; k < 20; ++k) await new Promise((r) => setImmediate(r));
  assert.equal(clock.timers.length, 1);
  bad = null;
  clock.tick();  // the first's wait runs out while the second's send is in flight
  release();
  release = null;
  await settle(outbox);
  assert.equal(outbox.state(second.toss).state, 'held');
  assert.equal(outbox.state(first.toss).state, 'held', 'the wait that ran out during the drain was lost');
});

test('once a toss is held, the next failure waits the first wait again, not the long one', async () => {
  const storage = phoneStorage(), server = classServer(), clock = handClock();
  const { outbox } = page(storage, server, clock);
  server.down = true;
  const first = toss();
  await outbox.add(first);
  await settle(outbox);
  for (let n = 0; n < 4; ++n) { clock.tick(); await settle(outbox); }
  assert.equal(clock.waits.at(-1), 16 * RETRY_FIRST_MS);
  // Back by the timer alone (no online event, which forgets the failures itself): held.
  server.down = false;
  clock.tick(); await settle(outbox);
  assert.equal(outbox.state(first.toss).state, 'held');
  // Down again: the next toss's first wait is the first one, as for a fresh outage.
  server.down = true;
  const second = toss();
  await outbox.add(second);
  await settle(outbox);
  assert.equal(outbox.state(second.toss).state, 'waiting');
  assert.equal(clock.waits.at(-1), RETRY_FIRST_MS, `waits ${clock.waits}`);
});

test('a toss kept during a wait waits with the others: no try before the wait ends, one timer', async () => {
  const storage = phoneStorage(), server = classServer(), clock = handClock();
  const { outbox } = page(storage, server, clock);
  server.status = 503;
  server.error = 'the database is busy';
  const first = toss();
  await outbox.add(first);
  await settle(outbox);
  clock.tick(); await settle(outbox);
  clock.tick(); await settle(outbox);
  const asked = server.asked.length;
  assert.equal(clock.timers.length, 1);
  // Three more kept while the server keeps failing: none asked until the wait ends.
  const more = [toss(), toss(), toss()];
  for (const k of more) { await outbox.add(k); await settle(outbox); }
  assert.equal(server.asked.length, asked, 'a toss kept during a wait was sent at once, past the backoff');
  assert.equal(clock.timers.length, 1, 'a second timer: the backoff is run twice');
  for (const k of more) assert.equal(outbox.state(k.toss).state, 'waiting');
  // The wait ends: one try (the first toss, still failing), the wait doubled.
  clock.tick(); await settle(outbox);
  assert.equal(server.asked.length, asked + 1);
  assert.equal(clock.waits.at(-1), 8 * RETRY_FIRST_MS);
  // The server well again: all four held, in order.
  server.status = 0;
  clock.tick(); await settle(outbox);
  assert.deepEqual(server.stored.map((s) => s.toss), [first, ...more].map((k) => k.toss));
});

test('a toss forgotten (its recording removed) is not sent, nor again, and leaves the storage', async () => {
  const storage = phoneStorage(), server = classServer(), clock = handClock();
  const { outbox } = page(storage, server, clock);
  server.down = true;
  const [kept, removed] = [toss(), toss()];
  await outbox.add(kept);
  await outbox.add(removed);
  await settle(outbox);
  await outbox.forget(removed.toss);
  assert.equal(outbox.state(removed.toss), undefined);
  assert.ok(!storage.rows.has(removed.toss));
  server.down = false;
  clock.tick(); await settle(outbox);
  assert.deepEqual(server.stored.map((s) => s.toss), [kept.toss]);
  // One forgotten while in flight: its answer changes nothing, it is not stored again.
  let release;
  const slow = toss();
  const post = server.post;
  server.post = (item) => new Promise((resolve) => { release = () => resolve(post(item)); });
  const again = page(storage, server, clock);
  await again.outbox.add(slow);
  await new Promise((r) => setImmediate(r));
  assert.equal(again.outbox.state(slow.toss).state, 'sending');
  await again.outbox.forget(slow.toss);
  release();
  await settle(again.outbox);
  assert.equal(again.outbox.state(slow.toss), undefined);
  assert.ok(!storage.rows.has(slow.toss));
});
