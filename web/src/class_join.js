// The phone in a class (docs/phone-lab.md, "In a class"; the server and its API: docs/class.md):
// the page opened at the class's address (explorer.html?class=CODE#lab, its QR code) offers to
// join the class under a name in any alphabet; every toss the lab then keeps goes to the class
// through the outbox (class_outbox.js), and its row in the lab's list says whether the class
// holds it; the class's pooled body and the student's own tosses, predicted against measured,
// are shown as the server gives them. Nothing is fitted here: the class's server fits.
import { ClassOutbox, stateWords } from './class_outbox.js';
import { classStore } from './class_store.js';
import { loneSurrogateProblem } from './well_formed.js';
import { announce } from './gyro_recorder.js';
import { plusMinus } from './precision.js';

const $ = (id) => document.getElementById(id);

/** The longest name a class takes (characters); the server holds the same limit. */
export const NAME_MAX = 80;

/** ms a request may take before it counts as no answer (a 4 MiB recording on a slow network). */
export const ASK_MS = 30000;

/** ms between two readings of the class's results while the lab is open. */
export const RESULTS_EVERY_MS = 15000;

/** localStorage's key of this phone's place in class `code`: {student, token, name}. */
export const joinedKey = (code) => `bookspin-class-${code}`;

/** The address of the class's `what` (join, tosses, me) on the server that served the page. */
const api = (code, what) => `/api/class/${encodeURIComponent(code)}/${what}`;

/** This phone's place in class `code` as kept by an earlier join ({student, token, name}), or
 * null. */
export function placeIn(code) {
  try {
    const m = JSON.parse(localStorage.getItem(joinedKey(code)) || 'null');
    return m && typeof m.token === 'string' ? m : null;
  } catch (e) {
    return null;
  }
}

/** A request to the class's server: a promise of {status, body (its JSON, or {error: its text}
 * where it is not JSON)}, rejected where no answer came within ASK_MS (no network, no server). */
function ask(url, options = {}) {
  const abort = new AbortController();
  const timer = setTimeout(() => abort.abort(), ASK_MS);
  return fetch(url, { ...options, signal: abort.signal, cache: 'no-store' })
    .then((r) => r.text().then((text) => {
      let body;
      try {
        body = JSON.parse(text);
      } catch (e) {
        body = { error: text.trim().slice(0, 200) || `HTTP ${r.status}` };
      }
      return { status: r.status, body: body && typeof body === 'object' ? body : {} };
    }))
    .finally(() => clearTimeout(timer));
}

const html = (text) => String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
const seconds = (v) => (typeof v === 'number' && Number.isFinite(v) ? v.toFixed(3) : '–');

/** The class's part of the lab over the lab's recorder (gyro_recorder.js: its onKept and onRow
 * hooks); `nameProblem(text)`: why `text` cannot be a name under the project's rule ('' where it
 * can; the module's, common/file_name.hpp). */
export class ClassLink {
  constructor(recorder, nameProblem) {
    this.recorder = recorder;
    this.nameProblem = nameProblem;
    this.code = (new URLSearchParams(location.search).get('class') || '').trim();
    this.place = this.code ? placeIn(this.code) : null;
    this.outbox = new ClassOutbox({
      store: classStore().catch(() => null),
      post: (item) => this.send(item),
      onChange: (item) => this.changed(item),
    });
    recorder.onKept = (k) => this.kept(k);
    recorder.onRow = (row, k) => this.row(row, k);
    // Back on the network: every waiting toss at once. The page loaded: those earlier pages left.
    window.addEventListener('online', () => this.outbox.drain(true));
    this.outbox.loaded.then(() => { this.recorder.list(); this.outbox.drain(true); });
    if (!this.code) return;
    $('classBox').hidden = false;
    $('labLeaves').textContent = 'In a class, each toss you keep goes to the class (above); nothing else leaves this page.';
    $('classCode').value = this.code;
    if (this.place) $('className').value = this.place.name;
    $('classJoin').addEventListener('submit', (e) => { e.preventDefault(); this.join(); });
    $('classAgain').addEventListener('click', () => this.showJoined(false));
    $('classRefresh').addEventListener('click', () => this.results());
    this.showJoined(Boolean(this.place));
    setInterval(() => { if (this.place && !$('lab').hidden && !document.hidden) this.results(); }, RESULTS_EVERY_MS);
  }

  /** The join form, or (`joined`) the line saying which class and name, and the results. */
  showJoined(joined) {
    $('classJoin').hidden = joined;
    $('classAgain').hidden = !joined;
    $('classMe').hidden = !joined;
    if (joined) {
      $('classState').textContent = `In class ${this.code} as ${this.place.name}: each toss you keep is sent to the ` +
        'class; the list of recordings says whether the class holds it.';
      $('classState').classList.remove('error');
      this.results();
    } else {
      $('classState').textContent = this.place ? `In class ${this.code} as ${this.place.name}; join again under another ` +
        'name or code:' : '';
    }
  }

  say(text, error = false) {
    $('classState').textContent = text;
    $('classState').classList.toggle('error', error);
    announce(text);
  }

  /** Join: the code and the name checked here as the server checks them, then asked. */
  join() {
    const code = $('classCode').value.trim();
    const name = $('className').value.trim();
    if (!code) { this.say('error: give the class code (on the projector)', true); return; }
    if (!name) { this.say('error: give your name', true); return; }
    // A lone surrogate named before the module's rule is asked (its UTF-8 encoder ate the
    // character after one) and before the code goes into the address (encodeURIComponent throws).
    const lone = loneSurrogateProblem(code, 'class code') || loneSurrogateProblem(name, 'your name');
    if (lone) { this.say(`error: ${lone}`, true); return; }
    const problem = this.nameProblem(name);
    if (problem) { this.say(`error: your name: ${problem}`, true); return; }
    if ([...name].length > NAME_MAX) { this.say(`error: your name: at most ${NAME_MAX} characters`, true); return; }
    $('classJoinButton').disabled = true;
    this.say(`joining class ${code}…`);
    ask(api(code, 'join'), { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify({ name }) })
      .then(({ status, body }) => {
        if (status !== 201 && status !== 200 || typeof body.token !== 'string') {
          this.say(`error: class ${code} refused: ${body.error || `the server answered ${status}`}`, true);
          return;
        }
        this.place = { student: body.student, token: body.token, name: body.name || name };
        localStorage.setItem(joinedKey(code), JSON.stringify(this.place));
        if (code !== this.code) {
          // The address carries the class joined (a reload comes back to it).
          this.code = code;
          const params = new URLSearchParams(location.search);
          params.set('class', code);
          history.replaceState(history.state, '', `?${params}${location.hash}`);
        }
        this.showJoined(true);
        announce($('classState').textContent);
        this.recorder.list();
      }, (e) => {
        this.say(`error: no answer from class ${code}'s server (${(e && e.message) || e}): check this phone's network ` +
          '(the classroom\'s Wi-Fi) and join again', true);
      })
      .finally(() => { $('classJoinButton').disabled = false; });
  }

  /** A recording just kept by the lab (before it is stored): in the outbox where this phone is
   * in a class. */
  kept(k) {
    if (this.place && k.toss) this.give(k);
  }

  give(k) {
    return this.outbox.add({ toss: k.toss, code: this.code, recording: k.id, name: k.name,
      recorded_at: k.when.toISOString(), csv: k.text });
  }

  /** One toss to its class's server (the outbox's post). */
  send(item) {
    const place = placeIn(item.code);
    if (!place) return Promise.resolve({ status: 401, body: { error: `this phone has not joined class ${item.code}` } });
    return ask(api(item.code, 'tosses'), {
      method: 'POST',
      headers: { 'Content-Type': 'application/json', Authorization: `Bearer ${place.token}` },
      body: JSON.stringify({ toss: item.toss, name: item.name, recorded_at: item.recorded_at, csv: item.csv }),
    });
  }

  /** A row of the lab's list (`k` its recording): the class's state of its toss, in words. */
  row(li, k) {
    if (!k.toss) return;
    li.dataset.toss = k.toss;
    const item = this.outbox.state(k.toss);
    if (item) {
      const state = document.createElement('span');
      state.className = `classState ${item.state}`;
      state.textContent = stateWords(item);
      li.append(state);
    } else if (this.place) {
      // Kept before this phone joined: sent when the student asks.
      const send = document.createElement('button');
      send.className = 'classSend';
      send.textContent = `Send to class ${this.code}`;
      send.addEventListener('click', () => { send.disabled = true; this.give(k).then(() => this.recorder.list()); });
      li.append(send);
    }
  }

  /** A toss's state changed: its row's words, said where it is held, refused or first waits. */
  changed(item) {
    const li = [...document.querySelectorAll('#labRecordList li')].find((r) => r.dataset.toss === item.toss);
    if (li) {
      let state = li.querySelector('.classState');
      if (!state) {
        li.querySelector('.classSend')?.remove();
        state = document.createElement('span');
        li.append(state);
      }
      state.className = `classState ${item.state}`;
      state.textContent = stateWords(item);
    }
    const was = this.said && this.said.get(item.toss);
    (this.said = this.said || new Map()).set(item.toss, item.state);
    // Said: held, refused, and the first wait of a toss the server did not take (not each try,
    // nor a toss just put in the outbox, which is sent at once).
    if (item.state === 'sending' || (item.state === 'waiting' && (was === 'waiting' || !item.reason))) return;
    if (item.state === 'waiting' && was === 'sending' && this.outbox.failures > 1) return;
    announce(`${item.name}: ${stateWords(item)}`);
    if (item.state === 'held') {
      clearTimeout(this.soon);
      this.soon = setTimeout(() => this.results(), 300);
    }
  }

  /** The class's results as its server gives them (GET me): the pooled body and this
   * student's tosses, each T/2 measured against predicted from the others ± 2σ. */
  results() {
    if (!this.place) return Promise.resolve();
    const code = this.code;
    return ask(api(code, 'me'), { headers: { Authorization: `Bearer ${this.place.token}` } }).then(({ status, body }) => {
      if (status !== 200) throw new Error(body.error || `the server answered ${status}`);
      this.showResults(body);
    }).catch((e) => {
      $('classResultsState').textContent = `the class's results could not be read (${(e && e.message) || e}); ` +
        'they come again with the next toss held, or tap Refresh';
    });
  }

  showResults(me) {
    const p = me.pooled;
    const ratios = p && Array.isArray(p.ratios) && p.ratios.length === 3 ? p.ratios : null;
    const sigma = p && Array.isArray(p.sigma) ? p.sigma : [];
    $('classPooled').textContent = ratios
      ? `The class's body, pooled from ${p.tosses} toss${p.tosses === 1 ? '' : 'es'}` +
        (typeof p.recordings === 'number' ? ` in ${p.recordings} recording${p.recordings === 1 ? '' : 's'}` : '') + ': I1 : I2 : I3 = ' +
        `${plusMinus(ratios[0], sigma[0])} : ${plusMinus(ratios[1], sigma[1])} : 1`
      : 'The class\'s body: not fitted yet (too few tosses held)';
    const mine = Array.isArray(me.tosses) ? me.tosses : [];
    const rows = mine.map((t) => {
      const predicted = typeof t.half_period_predicted === 'number'
        ? (typeof t.sigma === 'number' ? plusMinus(t.half_period_predicted, 2 * t.sigma) : seconds(t.half_period_predicted))
        : 'not predicted';
      const within = t.excluded ? `left out: ${t.excluded}` : t.within === true ? 'yes' : t.within === false ? 'no' : '–';
      return `<tr><td class="words" data-label="recording">${html(t.name)}</td><td data-label="T/2 measured (s)">${html(seconds(t.half_period_measured))}</td>` +
        `<td data-label="T/2 predicted ± 2σ (s)">${html(predicted)}</td><td class="words" data-label="within 2σ">${html(within)}</td></tr>`;
    });
    $('classMine').innerHTML = `<caption>Your tosses the class holds (${mine.length}): T/2 measured against predicted from the others</caption>` +
      '<tr><th>recording</th><th>T/2 measured (s)</th><th>T/2 predicted ± 2σ (s)</th><th>within 2σ</th></tr>' + rows.join('');
    const at = p && p.updated ? new Date(p.updated) : null;
    $('classResultsState').textContent = at && !Number.isNaN(at.getTime()) ? `as the class's server fitted them at ${at.toLocaleTimeString()}` : '';
  }
}
