"""The class's pooled body (docs/class.md, "The projector's numbers"): every toss not left out,
fitted as one body by bookspin.fit([files…]), the very fit `bookspin fit FILES…` makes of the
set the teacher downloads (the same CSV text in files of the same names), so the projector's
numbers are the command's to the digit. The exact fit runs in a process of its own
(fit_process.py), one at a time, stopped when a toss makes it stale; tosses that arrive during a
fit are fitted together by the next (a burst is one refit). During a burst the projector shows
the live estimate (docs/class.md, "The projector's numbers"): each toss prepared once as it arrives
(bookspin.prepare_recording, in the worker threads, in parallel), the set refitted warm from the
last estimate (bookspin.live_fit), marked "live"; once the class is quiet for QUIET_SECONDS the
exact fit follows."""
import asyncio
import datetime
import io
import math
import os
import pathlib
import re
import sys
import tempfile
import unicodedata
import zipfile

import bookspin

from bookspin_class import fit_process
from bookspin_class.fit_threads import FIT_THREADS
from bookspin_class.judgement import Judge, text_key


RETRY_SECONDS = 1.0  # a refit that could not read the store tries again after this
# No new toss for this long after a live estimate, and the exact fit follows (docs/class.md,
# "The projector's numbers").
QUIET_SECONDS = float(os.environ.get("BOOKSPIN_CLASS_QUIET_SECONDS", "3"))
# A live estimate waits for the tosses that keep coming to be prepared for at most this long.
PREPARE_SECONDS = 5.0

def file_stem(student_name, seq):
    """The file name (without .csv) a toss has in the class's set: the student's name in NFC
    with every letter, mark, digit, punctuation and symbol of any script kept (a Devanagari vowel
    sign, a Persian zero-width non-joiner, an emoji's joiner), what the project's name rule
    replaces and each run of spaces and '-' made one '-' (none first, nor a '.': an option, a
    hidden file), then '-' and the class's number of the toss ("प्रिया-शर्मा-4"). Unique in the
    class (seq is), at most MAX_FILE_NAME_BYTES bytes of UTF-8 (a longer name cut before a whole
    character), and already in the form `bookspin fit` names a recording by
    (common/file_name.hpp: file_name_of() leaves it as it is), so the fit's table names it the
    same (docs/class.md, "Names"). "toss-SEQ" for a name with nothing left."""
    name = _REPLACED.sub("-", unicodedata.normalize("NFC", student_name)).lstrip(".-").rstrip("-")
    suffix = f"-{seq}"
    budget = MAX_FILE_NAME_BYTES - len(suffix.encode("utf-8"))
    if len(name.encode("utf-8")) > budget:
        end = 0
        for at in range(1, len(name) + 1):
            if len(name[:at].encode("utf-8")) > budget:
                break
            if at == len(name) or not (_joins_previous(name[at]) or name[at - 1] == "\u200d"):
                end = at
        name = name[:end].rstrip("-")
    return f"{name or 'toss'}{suffix}"


# What a file's name cannot hold under the project's name rule (src/common/file_name.hpp,
# file_name_of: the characters of / \ : * ? " < > |, the controls, the line and paragraph
# separators, surrogates, the bidirectional overrides and isolates), and here also each space, so
# that a file of the set is one word on a command line.
_REPLACED = re.compile('[\x00-\x1f\x7f-\x9f/\\\\:*?"<>|\u2028\u2029\u202a-\u202e\u2066-\u2069'
                       '\ud800-\udfff\\s-]+')
MAX_FILE_NAME_BYTES = 160  # common/file_name.hpp, kMaxFileNameBytes: the fit cuts a longer name


def _joins_previous(ch):
    """Whether `ch` belongs to the character before it as one writes it (a mark: a vowel sign,
    a virama, an emoji's variation selector; a zero-width joiner or non-joiner)."""
    return unicodedata.category(ch)[0] == "M" or ch in "\u200c\u200d"


def write_set(folder, files):
    """Writes {stem: csv text} as FOLDER/stem.csv; returns the paths, sorted."""
    paths = []
    for stem, text in files.items():
        path = pathlib.Path(folder) / f"{stem}.csv"
        path.write_bytes(text.encode("utf-8"))
        paths.append(str(path))
    return sorted(paths)


def set_zip(files, folder_name, left_out=None):
    """The class's set as a zip: folder_name/stem.csv per toss fitted (the bytes the fit read),
    and each toss the teacher left out, `left_out` {stem: (csv text, reason)}, apart in
    folder_name/left-out/stem.csv with folder_name/left-out/README.txt (UTF-8) giving each one's
    reason, so that `bookspin fit folder_name/*.csv` is the pooled fit and nothing is lost."""
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as archive:
        for stem in sorted(files):
            archive.writestr(f"{folder_name}/{stem}.csv", files[stem].encode("utf-8"))
        if left_out:
            lines = ["The teacher left these tosses out of the class's fit; each with the "
                     "teacher's reason.", f"`bookspin fit {folder_name}/*.csv` fits the others "
                     "(the projector's numbers); add a file here to fit it with them.", ""]
            for stem in sorted(left_out):
                text, reason = left_out[stem]
                archive.writestr(f"{folder_name}/left-out/{stem}.csv", text.encode("utf-8"))
                lines.append(f"{stem}.csv: {' '.join(reason.split())}")
            archive.writestr(f"{folder_name}/left-out/README.txt",
                             ("\n".join(lines) + "\n").encode("utf-8"))
    return out.getvalue()


def fit_set(files):
    """bookspin.fit of the set {stem: csv text} written to a fresh folder: (body dict with
    ratios and σ, {stem: [flight rows]}) or raises bookspin.Error (its message naming the
    files by their names, not the folder's paths). Called in a worker thread."""
    with tempfile.TemporaryDirectory(prefix="bookspin-class-") as folder:
        paths = write_set(folder, files)
        try:
            fit = bookspin.fit(paths)
        except bookspin.Error as failure:
            raise bookspin.Error(str(failure).replace(str(pathlib.Path(folder)) + "/", "")) \
                from None
    body = fit.body
    rows = {stem: [] for stem in files}
    only = next(iter(files)) if len(files) == 1 else None
    for row in fit.tosses:
        rows.setdefault(only if only is not None else row.get("recording"), []).append(row)
    # Flights numbered within their recording (docs/class.md, "The projector"): 1..n per toss,
    # the set's own number kept as toss_in_set (the `toss` column of `bookspin fit`'s table).
    flights = {stem: [flight_of(row, number) for number, row in enumerate(stem_rows, 1)]
               for stem, stem_rows in rows.items()}
    pooled = {
        "tosses": len(fit.tosses),
        "recordings": len(files),
        "ratios": [body["I1_over_I3"], body["I2_over_I3"], body["I3_over_I3"]],
        "sigma": [body["I1_sigma"], body["I2_sigma"], 0.0],
        "summary": list(fit.summary),
        "live": False,
    }
    return pooled, flights


def prepare_toss(stem, text):
    """bookspin.prepare_recording of one toss's CSV text, written as stem.csv in a fresh
    folder (the name the exact fit gives it): what the live fit needs of it, done once; None
    for a recording the module cannot read (the exact fit says why). Called in a worker
    thread."""
    with tempfile.TemporaryDirectory(prefix="bookspin-class-") as folder:
        try:
            return bookspin.prepare_recording(write_set(folder, {stem: text})[0])
        except bookspin.Error:
            return None


def live_set(prepared, start=None):
    """bookspin.live_fit of the prepared tosses {stem: PreparedRecording} from `start` (the
    last live fit, or None): (pooled dict marked live, {stem: [flight rows]}, the live fit, the
    next one's start), as fit_set's; raises bookspin.Error. Called in a worker thread."""
    fit = bookspin.live_fit(list(prepared.values()), start)
    body = fit.body
    flights = {stem: [] for stem in prepared}
    for row in fit.tosses:
        flights.setdefault(row["recording"], []).append(flight_of(row, row["flight"]))
    pooled = {
        "tosses": len(fit.tosses),
        "recordings": len(prepared),
        "ratios": [body["I1_over_I3"], body["I2_over_I3"], body["I3_over_I3"]],
        "sigma": [body["I1_sigma"], body["I2_sigma"], 0.0],
        "summary": [],
        "live": True,
    }
    return pooled, flights, fit


def flight_of(row, number=None):
    """A fit table's row as the projector shows it: T/2 measured, predicted from the others ±
    2σ and whether the measured lies within (as the command's table says "within 2σ"); its
    number within its recording (`number`, 1..n) and in the set (toss_in_set); how its interval
    is calibrated, or why it has none (prediction_interval, not_predicted)."""
    measured = row.get("half_period_measured")
    predicted = row.get("half_period_predicted")
    sigma = row.get("half_period_predicted_sigma")
    within = None
    if measured is not None and predicted is not None and sigma is not None:
        within = abs(measured - predicted) <= 2.0 * sigma
    return {"flight": int(row["toss"]) if number is None else number,
            "toss_in_set": int(row["toss"]), "t_start": row.get("t_start"),
            "t_end": row.get("t_end"), "half_period_measured": measured,
            "half_period_predicted": predicted, "sigma": sigma, "within": within,
            "flag": row.get("flag"), "not_predicted": row.get("not_predicted"),
            "prediction_interval": row.get("prediction_interval") or None}


def named_recording(message, stems):
    """The recording a fit's error is about, where it begins with one file's name ("Ben-4.csv:
    the same samples as Anna-2.csv …"); None for an error about the set as a whole."""
    for stem in stems:
        if message.startswith(f"{stem}.csv:") or message.startswith(f"{stem}.csv "):
            return stem
    return None


def error_summary(message):
    """One sentence telling a student what to do about the fit's error `message` (its detail
    stays in `error`), with the finder's own requirements (bookspin.flight_requirements)."""
    need = bookspin.flight_requirements
    turn = 2 * math.pi / need["flight_omega"]
    again = (f"Record again: throw the phone spinning (at least {need['flight_omega']:g} rad/s, "
             f"a turn every {turn:.0f} s) so that it flies free for at least "
             f"{need['min_flight']:g} s, and let it lie still a moment before and after.")
    if "no free flight found" in message:
        return again
    if "did not converge" in message or "no rigid body" in message:
        return "The fit found no body in these flights: " + again[0].lower() + again[1:]
    if "the same samples as" in message or "the same file as" in message or \
            "given twice" in message:
        return "The same recording was sent twice: the teacher leaves one of them out."
    return "The class's fit failed on these recordings: the teacher sees the detail."


def fit_class(files, judge):
    """The class's pooled fit of {stem: csv text} with what one toss breaks set aside
    (docs/class.md, "The projector"): (pooled dict, {stem: flights}, {stem: why set aside}).
    A fit refused for one recording (its error begins with that file's name) is fitted again
    without it; a fit refused for the set, again without each recording whose own fit
    (judge.own_fits) is refused for other than having no flight. Raises bookspin.Error where
    neither names a recording. Called in a worker thread."""
    aside = {}
    while True:
        kept = {stem: text for stem, text in files.items() if stem not in aside}
        try:
            pooled, flights = fit_set(kept)
            return pooled, flights, aside
        except bookspin.Error as failure:
            message = str(failure)
            stem = named_recording(message, kept) if len(kept) > 1 else None
            if stem is not None:
                aside[stem] = message
                continue
            own = judge.own_fits(kept) if len(kept) > 1 else {}
            broken = {s: f.error for s, f in own.items()
                      if f.error is not None and "no free flight found" not in f.error}
            if not broken or len(broken) == len(kept):
                raise
            aside.update(broken)


def exact_fit(files):
    """fit_class(files) with a judge of its own: what the exact fit's process runs
    (fit_process.run_apart)."""
    return fit_class(files, Judge())


def add_alone(flights, own):
    """Each flight's T/2 as its recording alone measures it (OwnFit.flights, the phone's own
    fit): the flight of the same start within 0.15 s, as half_period_measured_alone."""
    for stem, stem_flights in flights.items():
        alone = own.get(stem)
        for flight in stem_flights:
            match = None
            if alone is not None and flight["t_start"] is not None:
                match = next((half for start, half in alone.flights
                              if start is not None and abs(start - flight["t_start"]) < 0.15),
                             None)
            flight["half_period_measured_alone"] = match


class PooledFit:
    """One class's pooled fit, kept up to date: request() after each change; the fit runs in a
    thread at a lower priority than the tosses' path, one at a time for the class and as many
    classes' at once as `gate` lets, and `on_done` is called (on the event loop) with each result: first the
    pooled body (result["judging"] true), then each toss's judgement against the others' body
    (judgements, docs/class.md)."""

    def __init__(self, files_of, on_done, gate, judge=None):
        self.files_of = files_of  # () -> {stem: csv text}, the tosses not left out
        self.on_done = on_done
        self.gate = gate
        self.judge = judge or Judge()
        self.dirty = False
        self.task = None
        self.fitting = False
        self.result = {"tosses": 0, "recordings": 0, "ratios": None, "sigma": None,
                       "updated": None, "error": None, "error_summary": None, "set_aside": [],
                       "judging": False, "live": False}
        self.flights = {}
        self.wake = asyncio.Event()  # set by request(): a toss came during the quiet wait
        self.prepared = {}  # stem -> (text_key, bookspin.PreparedRecording or None)
        self.live_start = None  # the last live fit: the next one's start
        self.judgements = {}  # stem -> {"outlier", "why", "residual_share", "own_residual_share"}
        self.fits = 0

    def request(self):
        self.note_change()
        if self.task is None or self.task.done():
            self.task = asyncio.get_running_loop().create_task(self._run())

    def note_change(self):
        """A change of the class's tosses, for the fit running (a fit worker's stage: it joins
        the live estimate's preparing, or makes the exact fit stale)."""
        self.dirty = True
        self.wake.set()

    async def live_once(self):
        """A fit worker's live stage (fit_jobs.py): the live estimate of the class's tosses
        published, as the laptop's burst makes it. Whether one was shown (none where no toss
        the module can read, or the live fit failed: the exact fit is due at once). Raises
        what files_of raises."""
        self.dirty = False
        async with self.gate:
            files = await asyncio.to_thread(self.files_of)
            if not files:
                return False
            shown, _ = await self._live(files)
        return shown

    async def exact_once(self):
        """A fit worker's exact stage (fit_jobs.py): the exact fit and the judgements
        published, as the laptop's quiet class gets them. False where a toss came during it
        (the exact fit stopped and not shown, stale; during the judgements, its live estimate
        shown beside them, the judgements not). Raises what files_of raises."""
        self.dirty = False
        async with self.gate:
            files = await asyncio.to_thread(self.files_of)
            if self._nothing_shown_or_held(files):
                return True
            self.fitting = True
            await self._exact(files)
        return not self.dirty

    def _nothing_shown_or_held(self, files):
        """No toss held (`files` empty) and none shown: no refit to tell the projector of."""
        return not files and self.result["recordings"] == 0 and self.result["error"] is None

    async def _run(self):
        exact_next = False  # the class quiet after a live estimate: the exact fit's turn
        while self.dirty or exact_next:
            self.dirty = False
            shown_live = False
            async with self.gate:
                try:
                    files = await asyncio.to_thread(self.files_of)  # the store, off the loop
                except Exception as error:  # the store lost (PostgreSQL restarting): again soon
                    line = str(error).strip().splitlines()[0] if str(error).strip() else \
                        type(error).__name__
                    print(f"bookspin-class: the class's refit waits for the store: {line}",
                          file=sys.stderr, flush=True)
                    self.dirty = True
                    await asyncio.sleep(RETRY_SECONDS)
                    continue
                if self._nothing_shown_or_held(files):
                    exact_next = False
                    continue
                self.fitting = True
                if files and not exact_next:
                    shown_live, files = await self._live(files)
                exact_next = False
                if not shown_live:
                    await self._exact(files)
            if shown_live and not self.dirty:
                # The exact fit once no toss has come for QUIET_SECONDS; a toss before then is
                # another live estimate first (one that came during this one: at once).
                self.wake.clear()
                try:
                    await asyncio.wait_for(self.wake.wait(), QUIET_SECONDS)
                except asyncio.TimeoutError:
                    exact_next = not self.dirty

    async def _live(self, files):
        """The live estimate of `files` published (result["live"] true): each toss new to the
        class prepared (in the worker threads, in parallel), then the set refitted from the
        last estimate. Returns (whether one was shown, the files it holds); none where no toss
        the module can read or the fit fails: the exact fit then follows at once. Tosses that come while the others are
        prepared are prepared too before the fit (for at most PREPARE_SECONDS): a burst is one
        fit of all, not one of each part of it."""
        loop = asyncio.get_running_loop()
        begun = loop.time()
        while True:
            await self._prepare(files)
            if not self.dirty or loop.time() - begun > PREPARE_SECONDS:
                break
            self.dirty = False
            try:
                files = await asyncio.to_thread(self.files_of)
            except Exception:  # the store lost: fit what is prepared; the loop reads it again
                self.dirty = True
                break
        usable = {stem: one for stem, (_, one) in sorted(self.prepared.items())
                  if one is not None and one.flights > 0}
        if not usable:
            return False, files
        try:
            pooled, flights, self.live_start = await loop.run_in_executor(
                FIT_THREADS, live_set, usable, self.live_start)
        except bookspin.Error:
            self.live_start = None
            return False, files
        pooled["updated"] = datetime.datetime.now(datetime.timezone.utc).isoformat(
            timespec="seconds")
        # Every toss held, as the exact fit counts them (one with no flight too).
        pooled.update(recordings=len(files), error=None, error_summary=None, judging=False,
                      set_aside=self.result.get("set_aside", []))
        self.result, self.flights = pooled, flights
        self.judgements = {stem: j for stem, j in self.judgements.items() if stem in files}
        self.on_done()
        return True, files

    async def _prepare(self, files):
        """Each toss of `files` new to the class (or whose text changed) prepared, in the
        worker threads, in parallel; those no longer held forgotten."""
        loop = asyncio.get_running_loop()
        keys = await asyncio.to_thread(  # 350 texts of 70 kB: off the loop
            lambda: {stem: text_key(text) for stem, text in files.items()})
        new = [stem for stem in files if self.prepared.get(stem, (None, None))[0] != keys[stem]]
        made = await asyncio.gather(*(loop.run_in_executor(FIT_THREADS, prepare_toss, stem,
                                                           files[stem]) for stem in new))
        self.prepared = {stem: self.prepared[stem] for stem in files if stem in self.prepared}
        self.prepared.update({stem: (keys[stem], one) for stem, one in zip(new, made)})

    async def _exact(self, files):
        """The exact fit of `files` (fit_class: `bookspin fit`'s numbers), published with
        result["live"] false, then each toss's judgement."""
        aside = {}
        try:
            if not files:
                pooled, flights = {"tosses": 0, "recordings": 0, "ratios": None,
                                   "sigma": None, "live": False}, {}
                error = None
            else:
                try:
                    done = await self._exact_unless_stale(files)
                    if done is None:  # a toss came while it ran: the loop fits them all again
                        self.dirty = True
                        return
                    pooled, flights, aside = done
                    error = None
                except (bookspin.Error, fit_process.Ended) as failure:
                    pooled, flights = {"tosses": 0, "recordings": len(files),
                                       "ratios": None, "sigma": None, "live": False}, {}
                    error = str(failure)
            self.fitting = False
        except BaseException:
            self.fitting = False
            raise
        self.fits += 1
        pooled["updated"] = datetime.datetime.now(datetime.timezone.utc).isoformat(
            timespec="seconds")
        pooled["error"] = error
        pooled["error_summary"] = error_summary(error) if error else None
        pooled["set_aside"] = [{"file": f"{stem}.csv", "why": why,
                                "why_summary": error_summary(why)}
                               for stem, why in sorted(aside.items())]
        kept = {stem: text for stem, text in files.items() if stem not in aside}
        pooled["judging"] = bool(kept) and not self.dirty
        self.result, self.flights = pooled, flights
        self.judgements = {stem: j for stem, j in self.judgements.items() if stem in kept}
        self.on_done()
        if not pooled["judging"]:
            return
        # The judgements: each recording against the body the others give.
        judging = asyncio.get_running_loop().run_in_executor(FIT_THREADS, self._judge, kept)
        if await self._live_while(judging):
            return  # stale: not shown (the own fits it made are kept for the next)
        own, judged = judging.result()
        add_alone(flights, own)
        self.judgements = judged
        self.result = dict(pooled, judging=False)
        self.on_done()

    async def _live_while(self, judging):
        """Waits for the judgements `judging` (longer the larger the class); a toss that comes
        meanwhile has its live estimate at once, beside them (docs/class.md, "The projector's
        numbers"). Whether one came: the judgements are then stale, self.dirty set (the loop
        fits them all again once the class is quiet)."""
        stale = False
        while not judging.done():
            if not self.dirty:
                await self._change_or(judging)
                continue
            self.dirty, stale, self.fitting = False, True, True
            try:
                newer = await asyncio.to_thread(self.files_of)
            except Exception:  # the store lost: the loop reads it again after the judgements
                continue
            if newer:
                await self._live(newer)
        judging.result()  # what the judgements raised, raised
        if stale:
            self.dirty = True
        return stale

    async def _change_or(self, running):
        """Until a change of the class's tosses (request, note_change) or the end of
        `running`, whichever is first."""
        self.wake.clear()
        woken = asyncio.ensure_future(self.wake.wait())
        await asyncio.wait({running, woken}, return_when=asyncio.FIRST_COMPLETED)
        woken.cancel()

    async def _exact_unless_stale(self, files):
        """fit_class(files) in a process of its own (fit_process.run_apart); a toss that comes
        while it runs (minutes at 350) makes it stale: its process is stopped at once and None
        returned (self.dirty set), the loop then shows the live estimate of them all, and the
        exact fit follows once the class is quiet again (docs/class.md, "The projector's
        numbers"). Raises bookspin.Error as fit_class does, fit_process.Ended."""
        exact = asyncio.ensure_future(fit_process.run_apart(exact_fit, files))
        while not exact.done():
            if self.dirty:
                exact.cancel()
                await asyncio.gather(exact, return_exceptions=True)
                return None
            await self._change_or(exact)
        return exact.result()

    def _judge(self, files):
        own = self.judge.own_fits(files)
        judged = self.judge.judge(files, own)
        for stem, fit in own.items():
            if judged.get(stem) is None and fit.error is not None:
                judged[stem] = {"outlier": False, "residual_share": None,
                                "own_residual_share": None, "why": error_summary(fit.error)}
        return own, judged
