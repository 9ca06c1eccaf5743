#!/usr/bin/env python3
"""Cost of the Python package against the C library it calls, side by side
in one run on the same contacts:

  batch     creepwork.solve_many (and a kept creepwork.Batch) over COUNT
            FASTSIM contacts on Kalker's 20 x 20 grid, against one
            cw_batch_solve call of the C program bench_batch.c on the same
            contacts (bitwise equal inputs; the results are compared bitwise)
  per call  one contact at a time: Solver.solve and solve() against C's
            cw_solver_solve, and an empty ctypes call, in CPU time of the
            calling thread (a busy machine disturbs it far less)

Each timing is the best of its repetitions, and the table gives the best
of the rounds (and the median of the rounds' best); rounds alternate C and
Python so that a machine busy with other work slows both alike. Not a test: prints a
table with its stamp. CTest runs it once with few contacts, for the bitwise
comparison only.

usage: bench_python.py --c-program build/bin/creepwork_bench_python_batch
                       [--count 10000] [--rounds 9] [--reps 5] [--threads 1,0]
"""

import argparse
import datetime
import os
import platform
import subprocess
import sys
import tempfile
import time
import timeit

import numpy as np

import creepwork
from creepwork._library import lib


def contacts(n):
    """Contact k of bench_batch.c's contact(), as arrays, same operations in the same order."""
    k = np.arange(n)
    return dict(a=7e-3, b=5e-3, N=100e3,
                xi_x=-3e-3 + 6e-3 * (k % 101).astype(float) / 100.0,
                xi_y=-2e-3 + 4e-3 * (k % 37).astype(float) / 36.0,
                phi=-1.5 + 3.0 * (k % 13).astype(float) / 12.0)


def best(fn, reps, timer=timeit.default_timer):
    return min(timeit.repeat(fn, number=1, repeat=reps, timer=timer))


def run_c(program, n, threads, reps, path):
    out = subprocess.run([program, str(n), str(threads), str(reps), path], check=True,
                         capture_output=True, text=True).stdout
    values = dict(line.split() for line in out.splitlines())
    return float(values["c_batch_seconds"]), float(values["c_single_seconds"])


def cpu_name():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def commit():
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        return subprocess.run(["git", "-C", here, "rev-parse", "--short", "HEAD"], check=True,
                              capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--c-program", required=True)
    ap.add_argument("--count", type=int, default=10000)
    ap.add_argument("--rounds", type=int, default=9)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--threads", default="1,0",
                    help="comma-separated thread counts of the batch (0: every core)")
    ap.add_argument("--compiler", default="")
    args = ap.parse_args()
    args.threads = [int(t) for t in args.threads.split(",")]
    n = args.count
    kw = contacts(n)

    # Same contacts, same results, bitwise.
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "c.bin")
        run_c(args.c_program, n, args.threads[-1], 1, path)
        c_totals = np.fromfile(path, np.float64).reshape(n, 4)
    out = creepwork.solve_many(**kw, threads=args.threads[0])
    mine = np.stack([out.Fx, out.Fy, out.Mz, out.W_macro], axis=1)
    if not out.ok.all() or mine.tobytes() != c_totals.tobytes():
        sys.exit("bench_python.py: solve_many's totals differ from the C batch's")
    print("solve_many's totals equal the C batch's bitwise on %d contacts" % n)
    if args.rounds == 0:
        return

    rows, singles = [], []
    for threads in args.threads:
        c_batch, c_single, py_many, py_batch = [], [], [], []
        with creepwork.Batch(threads=threads) as batch, tempfile.TemporaryDirectory() as tmp:
            for _ in range(args.rounds):
                cb, cs = run_c(args.c_program, n, threads, args.reps, os.path.join(tmp, "c.bin"))
                c_batch.append(cb)
                c_single.append(cs)
                py_many.append(best(lambda: creepwork.solve_many(**kw, threads=threads),
                                    args.reps))
                py_batch.append(best(lambda: batch.solve(**kw), args.reps))
        rows.append((threads, min(c_batch), min(py_many), min(py_batch), np.median(c_batch),
                     np.median(py_many), np.median(py_batch)))
        singles += c_single
    c_one = min(singles) / n

    # The same call split in two: the time inside cw_batch_solve (measured
    # around the C call by a wrapper) and solve_many's total, per call. This
    # ratio does not depend on how busy the machine was between two runs.
    inner = []
    real = lib.cw_batch_solve

    def timed(*a):
        t0 = timeit.default_timer()
        status = real(*a)
        inner.append(timeit.default_timer() - t0)
        return status

    split = []
    lib.cw_batch_solve = timed
    try:
        for threads in args.threads:
            totals = []
            del inner[:]
            for _ in range(args.rounds * args.reps):
                t0 = timeit.default_timer()
                creepwork.solve_many(**kw, threads=threads)
                totals.append(timeit.default_timer() - t0)
            ratios = np.array(totals) / np.array(inner)
            split.append((threads, np.median(totals), np.median(inner), np.median(ratios),
                          np.median(np.array(totals) - np.array(inner))))
    finally:
        lib.cw_batch_solve = real

    # One contact at a time.
    one = {k: float(np.asarray(v).flat[0]) if np.ndim(v) else v for k, v in kw.items()}
    rec = creepwork.params(**one)
    calls = 2000
    cpu = time.thread_time  # CPU time of this thread, as the C program's one-by-one loop
    with creepwork.Solver() as s:
        per = {
            "empty ctypes call (cw_version_number)":
                best(lambda: [lib.cw_version_number() for _ in range(calls)], args.reps, cpu),
            "Solver.solve(record, fields=False, warn=False)":
                best(lambda: [s.solve(rec, fields=False, warn=False) for _ in range(calls)],
                     args.reps, cpu),
            "Solver.solve(record, fields=False)":
                best(lambda: [s.solve(rec, fields=False) for _ in range(calls)], args.reps, cpu),
            "Solver.solve(**6 keywords, fields=False)":
                best(lambda: [s.solve(**one, fields=False) for _ in range(calls)], args.reps, cpu),
            "Solver.solve(**6 keywords), fields and profile":
                best(lambda: [s.solve(**one) for _ in range(calls)], args.reps, cpu),
            "creepwork.solve(**6 keywords, fields=False) (makes a Solver)":
                best(lambda: [creepwork.solve(**one, fields=False) for _ in range(calls)],
                     args.reps, cpu),
        }

    print()
    print("%d FASTSIM contacts, Kalker strip grid 20 x 20, CW_SOLVE_FORCES; best of %d rounds "
          "x %d repetitions (median of the rounds' best in brackets); threads 0 = every core "
          "(%d here)" % (n, args.rounds, args.reps, os.cpu_count()))
    print()
    print("| threads | C: one cw_batch_solve [ms] | Python: solve_many [ms] | ratio | "
          "Python: Batch.solve, batch kept [ms] | ratio |")
    print("|---:|---:|---:|---:|---:|---:|")
    for threads, cb, pm, pb, cbm, pmm, pbm in rows:
        print("| %d | %.2f (%.2f) | %.2f (%.2f) | %.3f (%.3f) | %.2f (%.2f) | %.3f (%.3f) |"
              % (threads, 1e3 * cb, 1e3 * cbm, 1e3 * pm, 1e3 * pmm, pm / cb, pmm / cbm,
                 1e3 * pb, 1e3 * pbm, pb / cb, pbm / cbm))
    print()
    print("The same solve_many calls, split: time inside cw_batch_solve and total (medians "
          "of %d calls)" % (args.rounds * args.reps))
    print()
    print("| threads | solve_many [ms] | of which cw_batch_solve [ms] | ratio | Python's own [ms] |")
    print("|---:|---:|---:|---:|---:|")
    for threads, total, c_call, ratio, own in split:
        print("| %d | %.2f | %.2f | %.3f | %.3f |" % (threads, 1e3 * total, 1e3 * c_call, ratio,
                                                     1e3 * own))
    print()
    print("| one contact at a time (CPU time of the thread) | per call [us] | "
          "overhead over C's cw_solver_solve [us] |")
    print("|---|---:|---:|")
    print("| C: cw_solver_solve | %.2f | 0 |" % (1e6 * c_one))
    for name, t in per.items():
        us = 1e6 * t / calls
        extra = "" if "empty" in name else "%.2f" % (us - 1e6 * c_one)
        print("| Python: %s | %.2f | %s |" % (name, us, extra))
    print()
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print("stamp: %s, %d cores; Python %s, numpy %s; %s; commit %s; %s; load average %.1f "
          "while measuring" % (cpu_name(), os.cpu_count(), platform.python_version(),
                               np.__version__, args.compiler or "C compiler unknown", commit(),
                               datetime.date.today().isoformat(), load))


if __name__ == "__main__":
    main()
