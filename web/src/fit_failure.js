// A failed fit told to a student in one sentence that says what to do (docs/phone-lab.md, "When
// a fit fails"), the fit's own words one tap away: the lab's fit of a recording (lab.js) and the
// class's pooled fit as the phone shows it (class_join.js). The fit's line is the command line's
// (`bookspin fit`); its "no free flight found" line names each stretch of motion dropped and why,
// and the thresholds it was judged by: the sentence takes its numbers from that line, so the
// finder's thresholds have one home (src/fit/flights.hpp, FinderSettings).

/** A fit's line longer than this (characters) is shown as a sentence with the line folded. */
export const LONG_LINE = 200;

/** The longest sentence made from a line's first clause (characters), cut at a word. */
const SENTENCE_MAX = 160;

/** A number of the fit's line ("0.300000", "2.000") as a person writes it ("0.3", "2"). */
const plain = (text) => String(Number(text));

/** The sentence of the fit's "no free flight found" line `line` (its dropped stretches' reasons
 * give the thresholds), or '' where `line` is not that line. */
function noFlightSentence(line) {
  if (!/no free flight found/.test(line)) return '';
  const stretch = line.match(/no torque-free stretch of ([0-9.]+) s or longer/);
  if (stretch) {
    return `No flight in this recording: record again, throwing the phone spinning so that it flies free for at ` +
      `least ${plain(stretch[1])} s before you catch it.`;
  }
  const slow = line.match(/turning slower than ([0-9.]+) rad\/s/);
  if (slow) {
    return `No flight in this recording: record again, spinning the phone faster as you throw it (at least ` +
      `${plain(slow[1])} rad/s, a turn in ${plain((2 * Math.PI / Number(slow[1])).toFixed(1))} s).`;
  }
  return 'No flight in this recording: record again, throwing the phone spinning into the air and catching it.';
}

/** A line's first clause as a sentence: up to its first "; " or " (", at most SENTENCE_MAX
 * characters cut at a space ("…" where cut). */
function firstClause(line) {
  const first = String(line).split('\n')[0];
  let clause = first.split(/; | \(/)[0];
  if ([...clause].length > SENTENCE_MAX) {
    const cut = [...clause].slice(0, SENTENCE_MAX).join('');
    clause = `${cut.slice(0, Math.max(cut.lastIndexOf(' '), SENTENCE_MAX / 2))}…`;
  }
  return clause;
}

/** What a student is shown of the fit's line `line` (its message, without "error: "): {sentence
 * (what to do, one sentence), detail (the line whole, shown one tap away; '' where the sentence
 * is the line itself: a short line is shown as it is)}. */
export function fitFailure(line) {
  const text = String(line);
  const flight = noFlightSentence(text);
  if (flight) return { sentence: flight, detail: text };
  if ([...text].length <= LONG_LINE && !text.includes('\n')) return { sentence: text, detail: '' };
  return { sentence: `${firstClause(text)} (the fit's own words below)`, detail: text };
}

/** What a student is shown of the class's pooled fit that failed (`pooled`: the server's
 * pooled body, docs/class.md "The API": its `error_summary`, one sentence, where the server
 * gives one, and its `error`, the fit's line; a server that gives neither: fitted from
 * `recordings` recordings and no `ratios`, which only a failed fit leaves): {sentence, detail},
 * or null where it did not fail. */
export function classFitFailure(pooled) {
  if (!pooled || typeof pooled !== 'object') return null;
  const detail = typeof pooled.error === 'string' ? pooled.error : '';
  const summary = typeof pooled.error_summary === 'string' ? pooled.error_summary : '';
  if (summary) return { sentence: summary, detail };
  const leaveOut = 'your teacher sees the class\'s tosses on the projector and can leave out the one that breaks it.';
  if (detail) return { sentence: `The class's body could not be fitted (${firstClause(detail)}): ${leaveOut}`, detail };
  if (!pooled.ratios && typeof pooled.recordings === 'number' && pooled.recordings > 0) {
    return { sentence: `The class's body could not be fitted from its ${pooled.recordings} ` +
      `recording${pooled.recordings === 1 ? '' : 's'}: ${leaveOut}`, detail: '' };
  }
  return null;
}

/** The HTML of a failure `f` ({sentence, detail}) under `prefix` ("error: "): the sentence, and
 * the fit's whole line in a <details> one tap away where there is one. `html`: text as HTML. */
export function failureHtml(f, prefix, html) {
  const sentence = `<span class="failureSentence">${html(prefix + f.sentence)}</span>`;
  if (!f.detail) return sentence;
  return `${sentence}<details class="failureDetail"><summary>the fit's own words</summary>` +
    `<p>${html(f.detail)}</p></details>`;
}
