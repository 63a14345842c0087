"""A class's exact fit in a process of its own (docs/class.md, "The projector's numbers"), so
that one a toss made stale is stopped at once, its core given back to the live estimate and the
next fit: the module cannot stop a fit half way in a thread (at 350 tosses the stale fit ran on
for minutes). The process is spawned, not forked (the server's threads may hold locks at the
moment of a fork), runs at nice 10 (below the tosses' path, as fit_threads.py's threads do),
and dies with the process that started it (a server or fit worker SIGKILLed leaves no fit
running)."""
import asyncio
import ctypes
import multiprocessing
import os
import signal

CONTEXT = multiprocessing.get_context("spawn")
PR_SET_PDEATHSIG = 1  # prctl(2): the signal this process gets when its parent dies


class Ended(Exception):
    """The fit's process ended without an answer (killed by the system: out of memory)."""


def _die_with_parent():
    try:
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGKILL)
    except (OSError, AttributeError):
        pass  # not Linux: a fit outliving a killed server ends when it is done


def _child(connection):
    """The spawned process: (function, args) received, function(*args) sent back, or what it
    raised."""
    _die_with_parent()
    if os.getppid() == 1:  # the parent died before prctl: nothing to fit for
        return
    try:
        os.nice(10)
    except OSError:
        pass
    try:
        function, args = connection.recv()
    except EOFError:  # the parent stopped it before sending
        return
    try:
        answer = ("returned", function(*args))
    except Exception as error:  # raised in the parent as it is (bookspin.Error pickles)
        answer = ("raised", error)
    connection.send(answer)
    connection.close()


def _receive(connection, process):
    try:
        return connection.recv()
    except EOFError:  # no answer: killed (stopped as stale, or by the system)
        process.join()
        return ("ended", process.exitcode)
    finally:
        connection.close()


async def run_apart(function, *args):
    """function(*args) in a process of its own (function and args picklable: a module's
    function, plain data): what it returns, or raises what it raised. Cancelled, the process is
    killed at once. Raises Ended where the process ended without an answer."""
    ours, its = CONTEXT.Pipe()
    process = CONTEXT.Process(target=_child, args=(its,), daemon=True,
                              name="bookspin-class-exact-fit")
    # Started from this thread, the event loop's (it lives as long as the process: the child's
    # PR_SET_PDEATHSIG is of the thread that started it), its work sent after (25 MB at 350).
    process.start()
    its.close()
    try:
        await asyncio.to_thread(ours.send, (function, args))
        kind, value = await asyncio.to_thread(_receive, ours, process)
    except asyncio.CancelledError:
        if process.pid is not None:
            process.kill()
            process.join(5)
        raise
    if kind == "raised":
        raise value
    if kind == "ended":
        how = f"killed by signal {-value}, by the system: out of memory?" if value < 0 else \
            f"exit status {value}: the server's log says why"
        raise Ended(f"the class's exact fit ended without an answer ({how})")
    await asyncio.to_thread(process.join)
    return value
