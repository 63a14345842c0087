"""The threads the classes' fits run in (docs/class.md, "The projector's numbers"), below the
tosses' path: each at a lower scheduling priority, so that the fits yield the cores to the
event loop and the tosses' reading. pooled.py's fits and judgement.py's own fits use them."""
import concurrent.futures
import os
import threading


def lower_priority():
    """Lowers the calling thread's scheduling priority (Linux: a thread's own nice value, 10),
    so that the fits yield the cores to the event loop and the tosses' reading: a toss reaches
    the projector within its 2 s while the classes are refitted (docs/performance-class.md, "A
    lecture hall and a school")."""
    try:
        os.setpriority(os.PRIO_PROCESS, threading.get_native_id(), 10)
    except (AttributeError, OSError):
        pass  # not Linux: the fit at the server's own priority


# The threads the classes' fits run in (the gate, ClassServer.gate, lets one at a time).
FIT_THREADS = concurrent.futures.ThreadPoolExecutor(os.cpu_count() or 1,
                                                    thread_name_prefix="bookspin-class-fit",
                                                    initializer=lower_priority)
