"""Which toss does not fit the others' body (docs/class.md, "A toss that does not fit the
others' body"): each recording fitted alone once (its own body and residual share, kept while
its text is), then judged against the body the other recordings give, by fitting it alone again
with that body's moments held (bookspin.fit(path, moments=…)): its residual share there against
its own. N + N single-recording fits, each run once per recording's text and per body, in
parallel across the cores (the module releases the GIL), not N pooled fits of N − 1."""
import concurrent.futures
import dataclasses
import hashlib
import math
import os
import pathlib
import tempfile

import bookspin
import numpy  # noqa: F401  (bookspin.fit's charts are numpy arrays: imported here, once, not by
#                          the first fits at once in several threads, which deadlocked)

# docs/class.md, "A toss that does not fit the others' body": a recording is singled out where
# its residual share under the others' body is at least SHARE_FACTOR times its own and at least
# SHARE_EXCESS of |ω| above it. Decided on 12-10-56, 12-13-01 (the bare phone) and 12-22-44,
# 12-38-00 (the plate) with thinnings of the phone's: under their own kind's body at most 1.02
# times their own share (+0.1 % of |ω|), under the other kind's at least 2.65 times (+18 %);
# held out: 12-13-51, 12-29-59, 12-44-51 (class/tests/test_class_fit.py).
SHARE_FACTOR = 2.0
SHARE_EXCESS = 0.10


@dataclasses.dataclass
class OwnFit:
    """A recording fitted alone: its body's I1/I3, I2/I3 and σ (None where not determined), its
    residual share (dimensionless, residual_share) and each flight's (t_start s, T/2 measured s
    or None); or the fit's error (one line) and nothing else."""
    ratios: tuple = None
    sigma: tuple = None
    share: float = None
    flights: list = dataclasses.field(default_factory=list)
    error: str = None


def residual_share(charts):
    """The residual's share of the motion over a recording's flights (`charts`: bookspin.Fit
    charts of one recording): √(Σ|ω_fitted − ω_measured|² / Σ|ω_measured|²) over every sample
    of every flight, dimensionless (0.02: 2 % of |ω|); None for no flight."""
    residual = motion = 0.0
    for chart in charts:
        difference = chart["fitted"] - chart["measured"]
        residual += float((difference * difference).sum())
        motion += float((chart["measured"] * chart["measured"]).sum())
    return math.sqrt(residual / motion) if motion > 0 else None


def text_key(text):
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def fit_alone(stem, text, moments=None):
    """bookspin.fit of one recording {stem}.csv written to a fresh folder, its moments held at
    `moments` (3,) where given: an OwnFit (error set where the fit refuses it)."""
    with tempfile.TemporaryDirectory(prefix="bookspin-class-") as folder:
        path = pathlib.Path(folder) / f"{stem}.csv"
        path.write_bytes(text.encode("utf-8"))
        try:
            fit = bookspin.fit(str(path), moments=moments)
        except bookspin.Error as failure:
            return OwnFit(error=str(failure).replace(str(path), f"{stem}.csv"))
    body = fit.body
    determined = body.get("I1_sigma") is not None and body.get("I2_sigma") is not None
    return OwnFit(ratios=(body["I1_over_I3"], body["I2_over_I3"]),
                  sigma=(body["I1_sigma"], body["I2_sigma"]) if determined else None,
                  share=residual_share(fit.charts),
                  flights=[(row["t_start"], row["half_period_measured"]) for row in fit.tosses])


def others_body(own, stem, left_out=(), robust=False):
    """The body the recordings of `own` ({stem: OwnFit}) other than `stem` and `left_out` give,
    from their own bodies' I1/I3 and I2/I3: their mean weighted by the inverse of their variance
    (the pooled least squares' estimate to first order), or with `robust` their medoid, the own
    body of the one whose summed distance to the others' is least (one recording one vote: a
    minority of another body cannot move it; docs/class.md); and how many there were. (None, 0)
    where none has a determined body."""
    others = [fit for other, fit in own.items()
              if other != stem and other not in left_out and fit.sigma is not None
              and all(s > 0 for s in fit.sigma)]
    if not others:
        return None, 0
    if robust:
        medoid = min(others, key=lambda candidate: sum(
            math.dist(candidate.ratios, fit.ratios) for fit in others))
        return tuple(medoid.ratios), len(others)
    body = []
    for i in range(2):
        total = sum(1.0 / fit.sigma[i] ** 2 for fit in others)
        body.append(sum(fit.ratios[i] / fit.sigma[i] ** 2 for fit in others) / total)
    return (body[0], body[1]), len(others)


def percent(share):
    return f"{100 * share:.0f} %" if share >= 0.1 else f"{100 * share:.1f} %"


def others_text(others):
    """"the body the other recording gives", "the body the other 9 recordings give"."""
    return ("the body the other recording gives" if others == 1
            else f"the body the other {others} recordings give")


def ratio_text(ratios):
    return f"{ratios[0]:.2f} : {ratios[1]:.2f} : 1"


def verdict(stem, own, under, body, others):
    """The judgement of one recording (docs/class.md): its own fit `own`, its fit `under` the
    body `body` of `others` other recordings."""
    if own.error is not None or own.share is None:
        return None
    if body is None:
        return {"outlier": False, "residual_share": None, "own_residual_share": own.share,
                "why": "no other recording with a body to judge it against yet"}
    if under.error is not None or under.share is None:
        return {"outlier": True, "residual_share": None, "own_residual_share": own.share,
                "why": f"does not fit {others_text(others)} "
                       f"({ratio_text(body)}): {under.error}"}
    outlier = under.share >= SHARE_FACTOR * own.share and under.share - own.share >= SHARE_EXCESS
    if outlier:
        why = (f"does not fit the others' body: its residual is {percent(under.share)} of |ω| "
               f"under {others_text(others)} ({ratio_text(body)}), "
               f"{percent(own.share)} under its own ({ratio_text(own.ratios)}): another body, "
               "or not a free flight: leave it out")
    else:
        why = (f"fits the others' body: residual {percent(under.share)} of |ω| under "
               f"{others_text(others)}, {percent(own.share)} under its own")
    return {"outlier": outlier, "residual_share": under.share,
            "own_residual_share": own.share, "why": why}


class Judge:
    """Keeps each recording's own fit and its fits under held bodies across refits (keyed by
    the recording's text), so that a class's refit fits only what changed."""

    def __init__(self, workers=None):
        self.workers = workers or os.cpu_count() or 1
        self.own = {}    # (stem, text key) -> OwnFit
        self.under = {}  # (stem, text key, rounded body) -> OwnFit

    def own_fits(self, files):
        """{stem: OwnFit} of {stem: csv text}, each fitted alone (once per text)."""
        keys = {stem: (stem, text_key(text)) for stem, text in files.items()}
        missing = [stem for stem, key in keys.items() if key not in self.own]
        self._run(missing, lambda stem: fit_alone(stem, files[stem]),
                  lambda stem, fit: self.own.__setitem__(keys[stem], fit))
        self.own = {key: self.own[key] for key in keys.values()}
        return {stem: self.own[key] for stem, key in keys.items()}

    def judge(self, files, own):
        """{stem: judgement} of the recordings `files` ({stem: csv text}) with their own fits
        `own`: each against the class's medoid body (its majority's), then, those singled out
        there left out where they are fewer than half, against the body the others give
        (leave-one-out: two odd tosses must not hide each other)."""
        used = set()
        judged = self._round(files, own, (), True, used)
        odd = {stem for stem, j in judged.items() if j and j["outlier"]}
        if 2 * len(odd) < len(judged):  # the others that fit are the most
            judged = self._round(files, own, odd, False, used)
        self.under = {key: fit for key, fit in self.under.items() if key in used}
        return judged

    def _round(self, files, own, left_out, robust, used):
        bodies = {}
        for stem in files:
            if own[stem].error is None and own[stem].share is not None:
                # The first round's body is the whole class's medoid (its majority's), the
                # second's the others' that fit, without the recording judged.
                body, count = others_body(own, None if robust else stem, left_out, robust)
                if robust:  # the class's body counted without the recording judged
                    count -= own[stem].sigma is not None and stem not in left_out
                bodies[stem] = (body, count)
        keys = {}
        for stem, (body, _) in bodies.items():
            if body is not None:
                keys[stem] = (stem, text_key(files[stem]), round(body[0], 3), round(body[1], 3))
        used.update(keys.values())
        missing = [stem for stem, key in keys.items() if key not in self.under]
        self._run(missing,
                  lambda stem: fit_alone(stem, files[stem],
                                         moments=[keys[stem][2], keys[stem][3], 1.0]),
                  lambda stem, fit: self.under.__setitem__(keys[stem], fit))
        return {stem: verdict(stem, own[stem], self.under.get(keys.get(stem)),
                              bodies[stem][0] and (keys[stem][2], keys[stem][3]),
                              bodies[stem][1]) for stem in bodies}

    def _run(self, stems, work, keep):
        if not stems:
            return
        from bookspin_class.fit_threads import lower_priority  # the fits yield to the tosses
        with concurrent.futures.ThreadPoolExecutor(max_workers=self.workers,
                                                   initializer=lower_priority) as pool:
            for stem, fit in zip(stems, pool.map(work, stems)):
                keep(stem, fit)
