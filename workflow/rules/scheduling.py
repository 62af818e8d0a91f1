"""Snakemake's scheduler timers: cancel the ones still pending when the workflow ends.

After every scheduling round Snakemake arms a ``threading.Timer`` of the rate limiter's timespan
(``--max-jobs-per-timespan``, the profile's ``max-jobs-per-timespan``) that starts one more round; each
round arms another, so the rounds per second grow with the number of jobs finished (with the default
``100/1s``, about 900 rounds for the 55 jobs of ``config/test.yaml``, each resetting the parameters
and resources of every waiting job).  A longer timespan makes them rare, but the timers are not daemon
threads: the process waits for each pending one to fire before it exits.  The Snakefile's
``onsuccess`` and ``onerror`` handlers call ``cancel_pending_timers`` instead.  A job still starts as
soon as another finishes (the scheduler is woken by the job's end, not by a timer).
"""

from __future__ import annotations

import threading

__all__ = ["cancel_pending_timers"]


def cancel_pending_timers() -> int:
    """Cancel every ``threading.Timer`` of this process that has not fired; return how many were running."""
    timers = [thread for thread in threading.enumerate() if isinstance(thread, threading.Timer)]
    for timer in timers:
        timer.cancel()
    return len(timers)
