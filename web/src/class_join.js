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
import { askFirst } from './modal.js';
import { classFitFailure, failureHtml } from './fit_failure.js';

const $ = (id) => document.getElementById(id);

/** The longest name a class takes (characters); the server holds the same limit. */
export const NAME_MAX = 80;

/** ms a request may take before it counts as no answer (a 4 MiB recording on a slow network). */
export const ASK_MS = 30000;

/** ms between two readings of the class's results while the lab is open. */
export const RESULTS_EVERY_MS = 15000;

/** localStorage's key of this phone's place in class `code`: {student, token, name}. */
export const joinedKey = (code) => `bookspin-class-${code}`;

/** A class code as typed (`text`) in the form the server gives it: its letters in upper case,
 * without spaces or dashes ("k7pq 2m", "K7P-Q2M" → "K7PQ2M"), full-width letters as ASCII
 * (Unicode's compatibility form, NFKC: a phone's Japanese or Chinese keyboard). */
export function classCode(text) {
  return String(text).normalize('NFKC').replace(/[\s\p{Pd}]/gu, '').toUpperCase();
}

/** Whether the page was served by a class's server (docs/class.md, "The API"): over https
 * (a class's server serves nothing else), its CA's certificate at /ca.pem. A promise of true or
 * false (a page from a file, over http, or from another server: false; not asked over http,
 * where a missing /ca.pem would be a 404 in the console of every page served so). */
function servedByAClass() {
  if (location.protocol !== 'https:') return Promise.resolve(false);
  return fetch('/ca.pem', { method: 'HEAD', cache: 'no-store' })
    .then((r) => r.ok && /x509|pem/.test(r.headers.get('Content-Type') || ''), () => false);
}

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
    this.code = classCode(new URLSearchParams(location.search).get('class') || '');
    this.place = this.code ? placeIn(this.code) : null;
    this.outbox = new ClassOutbox({
      store: classStore().catch(() => null),
      post: (item) => this.send(item),
      onChange: (item) => this.changed(item),
    });
    recorder.onKept = (k) => this.kept(k);
    recorder.onRow = (row, k) => this.row(row, k);
    recorder.beforeRemove = (k) => this.beforeRemove(k);
    // Back on the network: every waiting toss at once. The page loaded: those earlier pages left.
    window.addEventListener('online', () => this.outbox.drain(true));
    this.outbox.loaded.then(() => { this.recorder.list(); this.outbox.drain(true); });
    $('classJoin').addEventListener('submit', (e) => { e.preventDefault(); this.join(); });
    $('classAgain').addEventListener('click', () => this.showJoined(false));
    $('classRefresh').addEventListener('click', () => this.results());
    setInterval(() => { if (this.place && !$('lab').hidden && !document.hidden) this.results(); }, RESULTS_EVERY_MS);
    if (this.code) this.offer();
    // The address without its class (explorer.html#lab, or the bare https://ADDRESS:PORT/,
    // typed by hand) on a class's server: the lab and its join form all the same, the code to
    // type.
    else {
      servedByAClass().then((yes) => {
        if (!yes || this.code) return;
        this.offer();
        if (!location.hash) $('lab').hidden = false;
      });
    }
  }

  /** The class's box shown: the join form (the code from the address, where it names one), or
   * the class joined. */
  offer() {
    $('classBox').hidden = false;
    $('classTitle').textContent = this.code ? 'In a class' : 'Join a class';
    $('labLeaves').textContent = 'In a class, each toss you keep goes to the class (above); nothing else leaves this page.';
    $('classCode').value = this.code;
    if (this.place) $('className').value = this.place.name;
    this.showJoined(Boolean(this.place));
  }

  /** The join form, or (`joined`) the line saying which class and name, and the results. */
  showJoined(joined) {
    $('classJoin').hidden = joined;
    $('classAgain').hidden = !joined;
    $('classMe').hidden = !joined;
    $('classTitle').textContent = joined || this.code ? 'In a class' : 'Join a class';
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
    const typed = $('classCode').value;
    const name = $('className').value.trim();
    // A lone surrogate named before NFKC (which would turn it into U+FFFD) and before the code
    // goes into the address (encodeURIComponent throws).
    const loneCode = loneSurrogateProblem(typed, 'class code');
    if (loneCode) { this.say(`error: ${loneCode}`, true); return; }
    const code = classCode(typed);
    $('classCode').value = code;
    if (!code) { this.say('error: give the class code (on the projector)', true); return; }
    if (!name) { this.say('error: give your name', true); return; }
    // A lone surrogate named before the module's rule is asked (its UTF-8 encoder ate the
    // character after one) and before the code goes into the address (encodeURIComponent throws).
    const lone = loneSurrogateProblem(name, 'your name');
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
          $('classTitle').textContent = 'In a class';
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
      if ((status === 404 || status === 410) && code === this.code && this.place) { this.ended(); return; }
      if (status !== 200) throw new Error(body.error || `the server answered ${status}`);
      this.showResults(body);
    }).catch((e) => {
      $('classResultsState').textContent = `the class's results could not be read (${(e && e.message) || e}); ` +
        'they come again with the next toss held, or tap Refresh';
    });
  }

  /** The class is no more on its server (a 404 to this student's results: the teacher ended it,
   * its data deleted, or started another class in its place): said once; this phone's place in
   * it forgotten and the class taken out of the address (a reload does not claim it again);
   * nothing more asked of it (a toss still waiting is answered so once and shown refused); the
   * join form, for another class. */
  ended() {
    const code = this.code;
    localStorage.removeItem(joinedKey(code));
    this.place = null;
    this.code = '';
    const params = new URLSearchParams(location.search);
    params.delete('class');
    const query = params.toString();
    history.replaceState(history.state, '', `${location.pathname}${query ? `?${query}` : ''}${location.hash}`);
    $('classMe').hidden = true;
    $('classAgain').hidden = true;
    $('classJoin').hidden = false;
    $('classTitle').textContent = 'Join a class';
    $('classCode').value = '';
    this.say(`Class ${code} is over: its server no longer has it (the teacher ended it, deleting its data, or ` +
      'started another class). Your recordings stay on this phone, below; each row\'s Download saves it. To join ' +
      'another class, type its code.', true);
    this.outbox.drain(true);
  }

  /** Before a recording `k` is removed from the phone (the list's Remove): where its class holds
   * it or may, the student is asked first and told what becomes of the class's copy; once
   * removed, its toss leaves the outbox (not sent, or not again). A promise of whether to
   * remove it. */
  beforeRemove(k) {
    const item = k.toss ? this.outbox.state(k.toss) : null;
    if (!item) return Promise.resolve(true);
    const words = {
      held: `Class ${item.code} keeps its copy: it stays in the class's fit and on the projector. To have it left ` +
        'out, ask your teacher.',
      sending: `It is being sent to class ${item.code} now: if it arrives, the class keeps its copy. To have it left ` +
        'out, ask your teacher.',
      waiting: `It has not reached class ${item.code} yet: it will not be sent.`,
    }[item.state];
    const asked = words
      ? askFirst({ question: `Remove ${k.name} from this phone?`, detail: words, yes: 'Remove from this phone', no: 'Keep it' })
      : Promise.resolve(true);
    return asked.then((yes) => {
      if (yes) this.outbox.forget(k.toss);
      return yes;
    });
  }

  showResults(me) {
    const p = me.pooled;
    // The class's fit failed: one sentence saying what to do, its line one tap away.
    const failed = classFitFailure(p);
    $('classPooledError').hidden = !failed;
    $('classPooledError').innerHTML = failed ? failureHtml(failed, '', html) : '';
    const ratios = p && Array.isArray(p.ratios) && p.ratios.length === 3 ? p.ratios : null;
    const sigma = p && Array.isArray(p.sigma) ? p.sigma : [];
    $('classPooled').textContent = ratios
      ? `The class's body, pooled from ${p.tosses} toss${p.tosses === 1 ? '' : 'es'}` +
        (typeof p.recordings === 'number' ? ` in ${p.recordings} recording${p.recordings === 1 ? '' : 's'}` : '') + ': I1 : I2 : I3 = ' +
        `${plusMinus(ratios[0], sigma[0])} : ${plusMinus(ratios[1], sigma[1])} : 1`
      : failed ? 'The class\'s body: not fitted' : 'The class\'s body: not fitted yet (too few tosses held)';
    const mine = Array.isArray(me.tosses) ? me.tosses : [];
    const rows = mine.map((t) => {
      const predicted = typeof t.half_period_predicted === 'number'
        ? (typeof t.sigma === 'number' ? plusMinus(t.half_period_predicted, 2 * t.sigma) : seconds(t.half_period_predicted))
        : 'not predicted';
      // No verdict: the class's reason (no prediction, or no ± yet while the class holds too
      // few other tosses); the class's T/2 and this phone's own fit's, where they differ, side
      // by side (docs/class.md, "The class's T/2 and the phone's own").
      const why = typeof t.not_predicted === 'string' && t.half_period_predicted === null ? t.not_predicted
        : typeof t.prediction_interval === 'string' && typeof t.sigma !== 'number' ? t.prediction_interval : '';
      const within = t.excluded ? `left out: ${t.excluded}` : t.within === true ? 'yes' : t.within === false ? 'no'
        : why ? `– (${why})` : '–';
      const alone = typeof t.half_period_measured_alone === 'number' && typeof t.half_period_measured === 'number' &&
        seconds(t.half_period_measured_alone) !== seconds(t.half_period_measured)
        ? ` (this phone's own fit: ${seconds(t.half_period_measured_alone)}, about its own body's axis)` : '';
      return `<tr><td class="words" data-label="recording">${html(t.name)}</td><td data-label="T/2 measured (s)">${html(seconds(t.half_period_measured) + alone)}</td>` +
        `<td data-label="T/2 predicted ± 2σ (s)">${html(predicted)}</td><td class="words" data-label="within 2σ">${html(within)}</td></tr>`;
    });
    $('classMine').innerHTML = `<caption>Your tosses the class holds (${mine.length}): T/2 measured against predicted from the others</caption>` +
      '<tr><th>recording</th><th>T/2 measured (s)</th><th>T/2 predicted ± 2σ (s)</th><th>within 2σ</th></tr>' + rows.join('');
    const at = p && p.updated ? new Date(p.updated) : null;
    $('classResultsState').textContent = at && !Number.isNaN(at.getTime()) ? `as the class's server fitted them at ${at.toLocaleTimeString()}` : '';
  }
}
