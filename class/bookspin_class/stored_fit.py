"""A server's view of a class's fit on PostgreSQL (docs/class.md, "A school's server"): the fit
is not made in the server but by the fit workers (fit_jobs.py), and read from the database as
they stored it, on their notice."""
import asyncio

from bookspin_class import fit_jobs, pooled


class StoredFit(pooled.PooledFit):
    """A PooledFit (its attributes, as the routes read them, and its coalesced request()) whose
    fit is read, not made: `read(the (version, stage) shown)` (fit_jobs.stored) in `run` (a
    store thread), and on_done called where the result or `fitting` changed; `fitting` while
    the job holds a version newer than the one shown, or fits it still."""

    def __init__(self, read, run, on_done):
        super().__init__(None, on_done, None)
        self.read, self.run, self.version = read, run, None

    async def _run(self):
        while self.dirty:
            self.dirty = False
            try:
                found, version, job_version, state = await self.run(self.read, self.version)
            except Exception as error:  # the store lost (PostgreSQL restarting): again soon
                fit_jobs.say(f"the class's fit waits for the store: {fit_jobs.one_line(error)}")
                self.dirty = True
                await asyncio.sleep(fit_jobs.POLL_SECONDS)
                continue
            was = (self.version, self.fitting)
            if found is not None:
                self.result, self.flights = found["result"], found["flights"]
                self.judgements, self.version = found["judgements"], version
                self.fits += 1
            self.fitting = state in ("pending", "running") or (
                job_version is not None and job_version != (version or (None,))[0])
            if (self.version, self.fitting) != was:  # else the projector has it already
                self.on_done()
