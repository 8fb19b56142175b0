#!/usr/bin/env python3
"""Interleaved A/B of two criterion bench executables (same benchmarks):
A, B, A, B, ... for ROUNDS rounds; prints a Markdown table of each
benchmark's median point estimate (µs) under A and B and the median of
the per-round ratios B/A (with their range). Judge speed on this shared
machine by these same-run ratios, not by absolute times.

    cargo bench -p ke-friction-bench --bench model --no-run   # both trees
    python3 tools/criterion_ab.py OLD_EXECUTABLE NEW_EXECUTABLE [ROUNDS]

Each run: --warm-up-time 1 --measurement-time 4, no plots, in a scratch
directory of its own (criterion's saved baselines do not mix).
"""
import re
import statistics as st
import subprocess
import sys
import tempfile

UNITS = {"ns": 1e-3, "µs": 1.0, "us": 1.0, "ms": 1e3, "s": 1e6}


def run(exe, cwd):
    out = subprocess.run(
        [exe, "--bench", "--noplot", "--warm-up-time", "1", "--measurement-time", "4"],
        cwd=cwd, capture_output=True, text=True, check=True,
    ).stdout
    times, name = {}, None
    for line in out.splitlines():
        m = re.match(r"^(\S+/\S+)", line)
        if m:
            name = m.group(1)
        t = re.search(r"time:\s+\[\S+ \S+ (\S+) (\S+)", line)
        if t and name:
            times[name] = float(t.group(1)) * UNITS[t.group(2)]
            name = None
    if not times:
        sys.exit(f"{exe}: no criterion times in its output")
    return times


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    a_exe, b_exe = sys.argv[1], sys.argv[2]
    rounds = int(sys.argv[3]) if len(sys.argv) == 4 else 10
    if rounds < 1:
        sys.exit("ROUNDS must be a whole number >= 1")
    a_runs, b_runs = [], []
    with tempfile.TemporaryDirectory() as a_dir, tempfile.TemporaryDirectory() as b_dir:
        for r in range(rounds):
            a_runs.append(run(a_exe, a_dir))
            b_runs.append(run(b_exe, b_dir))
            print(f"round {r + 1} of {rounds}", file=sys.stderr)
    print(f"| benchmark | A (µs) | B (µs) | B/A, median of {rounds} rounds (range) |")
    print("|---|---|---|---|")
    for k in a_runs[0]:
        a = [x[k] for x in a_runs if k in x]
        b = [x[k] for x in b_runs if k in x]
        ratios = [y / x for x, y in zip(a, b)]
        print(f"| {k} | {st.median(a):.3f} | {st.median(b):.3f} | "
              f"{st.median(ratios):.3f} ({min(ratios):.3f}–{max(ratios):.3f}) |")


if __name__ == "__main__":
    main()
