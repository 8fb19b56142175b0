#!/usr/bin/env python3
"""Cross-check of tools/surface_reference.py (itself checked against the
Rust crate by tests/it/topography_stats.rs to ~1e-14) with
SurfaceTopography (PyPI): Rq, Rdq, Rddq of the same data; and, with
--timing, SurfaceTopography's Sq + rms gradient + rms Laplacian on a
1024 x 1024 map timed side by side with the Rust statistics of the same
array (the program, `kefric surface FILE.npy --dx 1e-6 --json`).

Setup and use (from the repository root):

    python3 -m venv /tmp/stvenv2 && /tmp/stvenv2/bin/pip install SurfaceTopography numpy
    /tmp/stvenv2/bin/python tools/surface_topography_check.py
    cargo build --release -p kefric
    /tmp/stvenv2/bin/python tools/surface_topography_check.py --timing [--rounds 15]

Compared (non-periodic, no missing points, mean removed):
* Rq (rms_height_from_area / _from_profile) with sigma;
* Rdq**2 (rms_slope_from_profile: along x) with m20;
* Rddq**2 (rms_curvature_from_profile: along x) with m40;
* for a map, rms_gradient**2 with m20 + m02.

For a profile these are the same sums and agree to rounding (~1e-13). For
a map SurfaceTopography (1.27.1) averages over fewer points than we do, so
its Rdq**2, Rddq**2 and rms_gradient**2 differ from our m20, m40, m20 + m02
by 1e-4 to 1e-2 on these small random maps (and agree for a map of identical
rows, where every row contributes the same). The reason, in
SurfaceTopography/Uniform/Derivative.py: a map's derivatives use 2-D
stencils (first_2d_x = [[-1, 0], [1, 0]] with lower bounds (0, 0), 2 x 2;
second_2d_x, 3 x 3 with lower bounds (-1, -1)), evaluated as if periodic,
and trim_nonperiodic then cuts away every point where the stencil's *box*
sticks out of the data, along both axes, although the x stencils have
nonzero weights along x only. So
* Rdq (forward differences along x) drops the last row in y: the mean of
  d**2 over (nx - 1) x (ny - 1) points (we: (nx - 1) x ny);
* Rddq (central second differences along x) drops the first and the last
  row in y: (nx - 2) x (ny - 2) points (we: (nx - 2) x ny);
* rms_gradient: both components on the same (nx - 1) x (ny - 1) points,
  d/dx without the last row, d/dy without the last column (we: m20 over
  all rows, m02 over all columns).
The operators themselves (first differences / dx, second differences /
dx**2, x = SurfaceTopography's first axis = our columns, each axis with its
own pixel size, no detrending) are ours; rms_laplacian is the mean of
(d2x + d2y)**2 on the (nx - 2) x (ny - 2) interior, which has a cross term
and is not m40 + m04, so it is timed but not compared. The check therefore
also compares SurfaceTopography with our statistics of the trimmed maps it
actually averages over (m20 of z[:-1, :], m40 of z[1:-1, :], and m20 of
z[:-1, :] + m02 of z[:, :-1]): these agree to rounding, and the "largest"
line covers them. Both definitions converge as 1/ny; ours uses every
difference the data has.

--timing: one CPU (the process pins itself and its children to one core of
its affinity mask; --cpu picks it), rounds interleaved (SurfaceTopography,
then the program on the 1024 x 1024 .npy, on the same array with every
height NaN -- read, then refused before the statistics: process start and
the 8 MB read --, and on a 32 x 32 file -- process start only), medians of
the wall times, CPU time of each (getrusage) to show one thread each.
The Rust statistics alone, in process, are the criterion benchmark
`cargo bench -p ke-friction-bench --bench topography -- stats`
(topography/stats_1024x1024, stats_4096x4096).
"""

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np
from SurfaceTopography import Topography, UniformLineScan

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import surface_reference as ref  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def rel(a, b):
    return abs(a - b) / max(abs(a), abs(b))


def check(name, z, dx, dy):
    ours = ref.stats(z if dy is not None else z[0], dx, dy, detrend="mean")
    ny, nx = z.shape
    if dy is None:
        t = UniformLineScan(z[0], nx * dx, periodic=False)
        rq = t.rms_height_from_profile()
    else:
        t = Topography(z.T, (nx * dx, ny * dy), periodic=False)  # ST: first axis = x
        rq = t.rms_height_from_area()
    rdq2 = t.rms_slope_from_profile() ** 2
    rddq2 = t.rms_curvature_from_profile() ** 2
    rows = [
        ("Rq / sigma", rq, ours["sigma"], True),
        ("Rdq^2 / m20", rdq2, ours["m20"], dy is None),
        ("Rddq^2 / m40", rddq2, ours["m40"], dy is None),
    ]
    if dy is not None:
        grad2 = t.rms_gradient() ** 2
        rows.append(("rms_gradient^2 / m20+m02", grad2, ours["m20"] + ours["m02"], False))
        # Like with like: our statistics of the points SurfaceTopography
        # averages over (its 2-D stencils trimmed along both axes).
        no_last_row = ref.stats(z[:-1, :], dx, dy, detrend="mean")
        inner_rows = ref.stats(z[1:-1, :], dx, dy, detrend="mean")
        no_last_col = ref.stats(z[:, :-1], dx, dy, detrend="mean")
        rows += [
            ("Rdq^2 / m20 trimmed", rdq2, no_last_row["m20"], True),
            ("Rddq^2 / m40 trimmed", rddq2, inner_rows["m40"], True),
            ("rms_grad^2 / trimmed", grad2, no_last_row["m20"] + no_last_col["m02"], True),
        ]
    worst = 0.0
    for what, theirs, mine, counted in rows:
        r = rel(theirs, mine)
        if counted:
            worst = max(worst, r)
        print(f"{name:20s} {what:26s} ST {theirs:.15e}  ours {mine:.15e}  rel {r:.1e}")
    return worst


def checks():
    worst = 0.0
    for case in ref.CASES:
        name, nx, ny, dx, dy, seed, missing, detrend, derivative = case
        if missing > 0:
            continue
        worst = max(worst, check(name, ref.case_surface(case), dx, dy))
    print(f"largest relative difference (profiles; maps: Rq and the trimmed comparisons): {worst:.1e}")
    return worst


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_program(kefric, path):
    """Wall and CPU time (s) of one `kefric surface PATH`, and its output."""
    cpu = children_cpu()
    start = time.perf_counter()
    p = subprocess.run([kefric, "surface", path, "--dx", "1e-6", "--json"], capture_output=True, text=True)
    wall = time.perf_counter() - start
    return wall, children_cpu() - cpu, p


def timing(args):
    allowed = sorted(os.sched_getaffinity(0))
    cpu = allowed[0] if args.cpu is None else args.cpu
    os.sched_setaffinity(0, {cpu})  # inherited by the children
    kefric = args.kefric
    if not os.access(kefric, os.X_OK):
        sys.exit(f"{kefric} not found: cargo build --release -p kefric")
    n = 1024
    z = np.random.default_rng(3).standard_normal((n, n)) * 1e-7
    t = Topography(z.T, (n * 1e-6, n * 1e-6), periodic=False)  # ST: first axis = x
    with tempfile.TemporaryDirectory() as tmp:
        full = os.path.join(tmp, f"z{n}.npy")
        nan = os.path.join(tmp, f"nan{n}.npy")
        tiny = os.path.join(tmp, "z32.npy")
        np.save(full, z)
        np.save(nan, np.full_like(z, np.nan))
        np.save(tiny, z[:32, :32])
        # Warm-up (page cache, the binary, SurfaceTopography's imports) and
        # a check that the program does what is timed.
        _, _, p = run_program(kefric, full)
        if p.returncode != 0:
            sys.exit(f"kefric surface failed: {p.stderr}")
        _, _, q = run_program(kefric, nan)
        if q.returncode == 0 or "valid points" not in q.stderr:
            sys.exit(f"the all-NaN file was expected to be refused: {q.stderr}")
        run_program(kefric, tiny)
        t.rms_height_from_area(), t.rms_gradient(), t.rms_laplacian()
        s = json.loads(p.stdout)["surface"]
        print(f"kefric (plane detrend) on {n}x{n}: sigma {s['sigma']:.6e} (ST Sq {t.rms_height_from_area():.6e}), "
              f"m20 + m02 {s['m20'] + s['m02']:.6e} (ST rms_gradient^2, trimmed: {t.rms_gradient() ** 2:.6e})")

        rows = {k: [] for k in ("st", "st_cpu", "full", "full_cpu", "nan", "nan_cpu", "tiny", "tiny_cpu")}
        for r in range(args.rounds):
            # Rotate the order so that no kind always follows another.
            order = ["st", "full", "nan", "tiny"]
            k = r % 4
            for kind in order[k:] + order[:k]:
                if kind == "st":
                    c0, w0 = time.process_time(), time.perf_counter()
                    t.rms_height_from_area()
                    t.rms_gradient()
                    t.rms_laplacian()
                    wall, cpu_s = time.perf_counter() - w0, time.process_time() - c0
                else:
                    wall, cpu_s, _ = run_program(kefric, {"full": full, "nan": nan, "tiny": tiny}[kind])
                rows[kind].append(wall)
                rows[kind + "_cpu"].append(cpu_s)
    a = {k: np.array(v) for k, v in rows.items()}
    med = {k: float(np.median(v)) for k, v in a.items()}
    stats_only = a["full"] - a["nan"]  # per round
    with_read = a["full"] - a["tiny"]
    ms = lambda x: f"{x * 1e3:8.2f} ms"  # noqa: E731
    print(f"CPU {cpu} (of {allowed}), {args.rounds} interleaved rounds, medians (min-max):")
    for kind, label in [
        ("st", "SurfaceTopography Sq + rms_gradient + rms_laplacian"),
        ("full", f"kefric surface {n}x{n}.npy --json"),
        ("nan", f"kefric surface on all-NaN {n}x{n} (start + read)"),
        ("tiny", "kefric surface on 32x32 (process start)"),
    ]:
        v = a[kind]
        print(f"  {label:52s} wall {ms(med[kind])} ({v.min() * 1e3:.2f}-{v.max() * 1e3:.2f}), "
              f"CPU {ms(med[kind + '_cpu'])}")
    st = a["st"]
    for label, rust in [("statistics only (full - all-NaN)", stats_only),
                        ("statistics + .npy read (full - 32x32)", with_read),
                        ("whole program (full)", a["full"])]:
        print(f"  Rust {label:38s} {ms(np.median(rust))}; ratio ST / Rust: "
              f"of medians {np.median(st) / np.median(rust):6.1f}, median of per-round {np.median(st / rust):6.1f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--timing", action="store_true", help="time SurfaceTopography against kefric (1024 x 1024)")
    parser.add_argument("--rounds", type=int, default=15)
    parser.add_argument("--cpu", type=int, default=None, help="the CPU to pin to (default: the first allowed)")
    parser.add_argument("--kefric", default=os.path.join(ROOT, "target", "release", "kefric"))
    args = parser.parse_args()
    if args.timing:
        timing(args)
    else:
        checks()


if __name__ == "__main__":
    main()
