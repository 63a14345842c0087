// The page's address (docs/explorer.md, "The address"): the state written into the URL, so
// that a reload or a copied link opens the same motion at the same time. While playing it is
// rewritten every 60 ms to 1 s (as often as browsers let a page rewrite its address, about 200
// times in 10 s), t written ahead of the time shown by half the time until the next rewrite, so
// that between two rewrites the address is never more than half that time off (0.45 at speed 15).
// A change of scene and a panel opened or closed are new history entries (Back and Forward go
// through them: main.js reads the address again on popstate); the rest rewrites the entry.
const URL_MIN_MS = 60, URL_MAX_MS = 1000;

export class Address {
  /** `space`: the StateSpace (format); `state()`: the current state; `base()`: its scene's. */
  constructor(space, state, base) {
    this.space = space; this.state = state; this.base = base;
    this.writtenAt = 0;
  }

  /** The address of the state; `lead` (time units) ahead of its t; the open panel as the
   * hash, as the gallery links them (#lab, #judge). */
  href(lead = 0) {
    const s = this.state();
    let q = this.space.format(lead ? { ...s, t: s.t + lead } : s, this.base());
    // The class the page was opened for (class_join.js) stays in the address: a reload joins it.
    const own = new URLSearchParams(location.search).get('class');
    if (own) q = `class=${encodeURIComponent(own)}${q ? `&${q}` : ''}`;
    const panel = !document.getElementById('lab').hidden ? '#lab' : !document.getElementById('judge').hidden ? '#judge' : '';
    return (q ? `?${q}` : location.pathname) + panel;
  }

  /** Writes the state in place; `lead` (time units) ahead of its t. After push(), the next
   * write is a new history entry instead (Back returns to the one before it). */
  write(lead = 0) {
    const href = this.href(lead);
    if (this.pushing) {
      this.pushing = false;
      // The address now in href's own form (`?query#panel`, or the path without a query): an
      // entry the same as the one before is not pushed again ("Play beside the measurement"
      // pushed the toss's scene twice, once for the scene and once for the lab closing, so
      // Back went to the toss again, rewound, not to the lab).
      if (href !== this.here()) { history.pushState(null, '', href); return; }
    }
    // The same address is not written again: each write has the browser draw its own bar anew
    // (a frame of its own, which a tap's answer waited behind on a software GPU).
    if (href !== this.here()) history.replaceState(null, '', href);
  }

  /** The address as it is, in href()'s own form (`?query#panel`, or the path without a query). */
  here() { return (location.search || location.pathname) + location.hash; }

  /** The next write a new history entry (a scene changed, a panel opened or closed). */
  push() { this.pushing = Boolean(this.live); }

  /** A push asked for and not yet written is not (Back or Forward came first). */
  forgetPush() { this.pushing = false; }

  /** While playing, at frame time `now` (ms): written every half time unit, within the limits. */
  whilePlaying(now) {
    const speed = this.state().speed;
    const every = Math.min(URL_MAX_MS, Math.max(URL_MIN_MS, 500 / Math.max(speed, 1e-9)));
    if (now - this.writtenAt < every) return;
    this.write(0.5 * (every / 1000) * speed);
    this.writtenAt = now;
  }
}
