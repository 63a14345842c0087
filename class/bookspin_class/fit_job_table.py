"""The fit jobs' tables on PostgreSQL (docs/class.md, "A school's server"): what the store
keeps of them (their schema, made with the store's, and the statement that makes a class's job
pending in a change's own transaction, Store.notice). The workers that take the jobs are
fit_jobs.py's; this module imports nothing of the class server, so that the store and the
workers each use it without one importing the other."""

SCHEMA = [
    """CREATE TABLE IF NOT EXISTS fit_jobs (
         class_code TEXT PRIMARY KEY REFERENCES classes(code) ON DELETE CASCADE,
         version BIGINT NOT NULL,
         state TEXT NOT NULL CHECK (state IN ('pending', 'running', 'done')),
         worker TEXT,
         leased_until TIMESTAMPTZ,
         attempts INTEGER NOT NULL DEFAULT 0,
         queued TIMESTAMPTZ NOT NULL DEFAULT now())""",
    # The job's stage (docs/class.md, "A school's server"): 'live', the class's live estimate,
    # taken before any class's 'exact' fit, which is due once the class has been quiet
    # (not_before). Added to a database of before the stages.
    "ALTER TABLE fit_jobs ADD COLUMN IF NOT EXISTS stage TEXT NOT NULL DEFAULT 'live'",
    "ALTER TABLE fit_jobs ADD COLUMN IF NOT EXISTS not_before TIMESTAMPTZ",
    """CREATE TABLE IF NOT EXISTS class_fits (
         class_code TEXT NOT NULL REFERENCES classes(code) ON DELETE CASCADE,
         version BIGINT NOT NULL,
         result TEXT NOT NULL,
         worker TEXT NOT NULL,
         attempt INTEGER NOT NULL,
         stage INTEGER NOT NULL DEFAULT 1,
         stored TIMESTAMPTZ NOT NULL DEFAULT now(),
         PRIMARY KEY (class_code, version))""",
]


def create_tables(connection):
    """The job tables, beside the store's (store.open_postgres)."""
    with connection.transaction():
        for statement in SCHEMA:
            connection.execute(statement)
        # A database of before the jobs: every class holding tosses gets one, to fit them.
        connection.execute("INSERT INTO fit_jobs (class_code, version, state) SELECT code, 1, "
                           "'pending' FROM classes c WHERE EXISTS (SELECT 1 FROM tosses t "
                           "WHERE t.class_code = c.code) ON CONFLICT (class_code) DO NOTHING")


def enqueue(code):
    """The statement that makes the class's job pending for its next version, coalesced (one
    job a class; a job being fitted stays the running worker's, which fits again at its end,
    or under its expired lease the next worker's): run in the transaction of the change
    (Store.notice). Its stage is the live estimate again, due at once (a change restarts the
    quiet the exact fit waits for); its attempts count again from 0 unless it is running."""
    return [("INSERT INTO fit_jobs (class_code, version, state) VALUES (%s, 1, 'pending') "
             "ON CONFLICT (class_code) DO UPDATE SET version = fit_jobs.version + 1, "
             "state = CASE WHEN fit_jobs.state = 'running' THEN 'running' ELSE 'pending' END, "
             "attempts = CASE WHEN fit_jobs.state = 'running' AND fit_jobs.leased_until > now() "
             "THEN fit_jobs.attempts ELSE 0 END, queued = CASE WHEN fit_jobs.state = 'done' "
             "OR fit_jobs.stage = 'exact' THEN now() ELSE fit_jobs.queued END, stage = 'live', "
             "not_before = NULL", (code,))]
