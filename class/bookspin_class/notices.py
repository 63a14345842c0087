"""The class's changes across server processes on one PostgreSQL (docs/class.md, "A school's
server"): each server LISTENs on store.CHANNEL, and a change another server committed (a
student joined, a toss held, left out or put back, the class ended) reaches this server's
projectors as if made here. PostgreSQL's LISTEN/NOTIFY through psycopg 3: no queue of our own.
SQLite has one server, and no notices."""
import asyncio

from bookspin_class import store


async def listen(url, instance, on_notice, on_connected, retry_seconds=1.0):
    """Calls on_notice(kind, code) on the event loop for every notice of another server
    (`instance` is this one's, Store.instance), and on_connected() each time the listening
    connection is made (at first and after PostgreSQL came back: what was missed while it was
    away is refreshed by the caller). Runs until cancelled; a lost connection is made again
    every `retry_seconds`."""
    import psycopg
    while True:
        try:
            async with await psycopg.AsyncConnection.connect(url, autocommit=True) as connection:
                await connection.execute(f"LISTEN {store.CHANNEL}")
                on_connected()
                async for notice in connection.notifies():
                    parts = notice.payload.split(" ")
                    if len(parts) == 3 and parts[2] != instance:
                        on_notice(parts[0], parts[1])
        except psycopg.Error:
            await asyncio.sleep(retry_seconds)
