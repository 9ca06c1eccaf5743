"""Progress of many contacts (solve_many, Batch.solve), as the creepwork CLI
reports long work:

    creepwork: solve_many: 4000 of 10000 contacts done (40 %), 700 contacts/s, about 9 s to go

progress=True prints such a line on stderr after 2 s and then every 10 s
(work shorter than 2 s prints nothing); a number S of seconds prints one
every S seconds; a callable is called as progress(done, total) after each
part of the work. The contacts are then solved in about a hundred calls of
cw_batch_solve instead of one, with the same results bitwise."""

import sys
import time

PARTS = 100


def reporter(progress, total, caller):
    """None when progress is off (False or None), else a function of the
    number of contacts done. Raises ValueError naming progress."""
    if progress is None or progress is False:
        return None
    if callable(progress):
        return lambda done: progress(done, total)
    if progress is True:
        first, every = 2.0, 10.0
    else:
        try:
            every = float(progress)
        except (TypeError, ValueError):
            every = float("nan")
        if isinstance(progress, bool) or not 0.0 < every <= 86400.0:
            raise ValueError("%s(): progress = %r is invalid: must be True, False, a number of "
                             "seconds in (0, 86400] or a callable(done, total)"
                             % (caller, progress))
        first = every
    start = time.monotonic()
    due = [first]

    def report(done):
        seconds = time.monotonic() - start
        if seconds < due[0]:
            return
        rate = done / seconds if seconds > 0.0 else 0.0
        left = (total - done) / rate if rate > 0.0 else 0.0
        print("creepwork: %s: %d of %d contacts done (%.0f %%), %.0f contacts/s, about %.0f s "
              "to go" % (caller, done, total, 100.0 * done / total, rate, left),
              file=sys.stderr, flush=True)
        due[0] = seconds + every

    return report
