#!/usr/bin/env python3
"""Cross-check the library's X3P writer and reader against SurfaceTopography.

Usage:
    python3 tools/x3p_check.py [DIR]

DIR holds the files of `cargo run --release --features topography --example
write_x3p -- DIR` (without DIR the script runs that example into a
temporary directory). For each X3P file of the index, SurfaceTopography's
reader (PyPI `SurfaceTopography`) must give:

  * the grid (nx, ny) and the physical sizes nx*dx, ny*dy (dx != dy in some
    files) to 1e-15 relative;
  * the heights this library reads back from the same file (NAME.read.npy)
    to REL = 1e-15 of the largest height, with missing points (the validity
    mask) in the same places;
  * the heights written (NAME.orig.npy): exactly for z type D, to f32's
    precision for F, to half the quantisation step (range / (2^n - 1)) for
    L and I.

And the other way: SurfaceTopography writes each map it read (its
`to_x3p`, the same z type) and this library's reader (the example's
`--read`) must give the same grid, intervals and heights to REL.

Profiles (FeatureType PRF) are skipped: SurfaceTopography's X3P reader reads
SUR files only.

Needs numpy and SurfaceTopography (`pip install SurfaceTopography`). Prints
"x3p_check: N passed, M failed, K skipped" and exits 1 if anything failed.
"""

import os
import subprocess
import sys
import tempfile

import numpy as np

REL = 1e-15


def run_example(out):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    subprocess.run(
        ["cargo", "run", "--quiet", "--release", "--features", "topography",
         "--example", "write_x3p", "--", out],
        cwd=root, check=True)


def read_ours(root, path, out):
    """This library's reading of `path`: (nx, ny, dx, dy), heights to `out`."""
    cmd = [os.path.join(root, "write_x3p"), "--read", path, out] if root else \
        ["cargo", "run", "--quiet", "--release", "--features", "topography",
         "--example", "write_x3p", "--", "--read", path, out]
    words = subprocess.run(cmd, check=True, capture_output=True, text=True,
                           cwd=os.path.dirname(os.path.dirname(os.path.abspath(__file__)))).stdout.split()
    return int(words[0]), int(words[1]), float(words[2]), float(words[3]) if len(words) > 3 else None


def check_dir(d, example=None):
    from SurfaceTopography.IO import X3PReader

    passed = failed = skipped = 0
    with open(os.path.join(d, "index.tsv")) as f:
        index = [line.rstrip("\n").split("\t") for line in f if line.strip()]
    for name, ztype, nx, ny, dx, dy in index:
        nx, ny, dx = int(nx), int(ny), float(dx)
        if not dy:
            print(f"skip {name}: a profile (PRF); SurfaceTopography reads SUR only")
            skipped += 1
            continue
        dy = float(dy)
        problems = []
        t = X3PReader(os.path.join(d, name + ".x3p")).topography()
        if tuple(t.nb_grid_pts) != (nx, ny):
            problems.append(f"grid {t.nb_grid_pts} != {(nx, ny)}")
        for got, want, what in zip(t.physical_sizes, (nx * dx, ny * dy), "xy"):
            if abs(got - want) > REL * want:
                problems.append(f"physical size {what} {got!r} != {want!r}")
        # SurfaceTopography's heights are (nx, ny); ours (ny, nx), rows = y.
        st = np.ma.filled(np.ma.asarray(t.heights(), dtype=float), np.nan).T
        ours = np.load(os.path.join(d, name + ".read.npy"))
        orig = np.load(os.path.join(d, name + ".orig.npy"))
        if st.shape != ours.shape:
            problems.append(f"shape {st.shape} != {ours.shape}")
        else:
            if not np.array_equal(np.isnan(st), np.isnan(ours)):
                problems.append("missing points differ")
            if not np.array_equal(np.isnan(st), np.isnan(orig)):
                problems.append("missing points differ from those written")
            ok = ~np.isnan(orig)
            scale = np.nanmax(np.abs(orig))
            diff = np.max(np.abs(st[ok] - ours[ok]), initial=0.0)
            if diff > REL * scale:
                problems.append(f"vs this library's reader: max |diff| {diff:.3e} > {REL * scale:.3e}")
            span = np.nanmax(orig) - np.nanmin(orig)
            tol = {
                "D": 0.0,
                "F": scale * np.finfo(np.float32).eps,
                "L": 0.51 * span / (2.0**32 - 1) + REL * scale,
                "I": 0.51 * span / (2.0**16 - 1) + REL * scale,
            }[ztype]
            diff_orig = np.max(np.abs(st[ok] - orig[ok]), initial=0.0)
            if diff_orig > tol:
                problems.append(f"vs the heights written: max |diff| {diff_orig:.3e} > {tol:.3e}")
        if not problems:
            # SurfaceTopography's writer, this library's reader.
            back = os.path.join(d, name + ".st.x3p")
            t.to_x3p(back, dtype=ztype)
            got_nx, got_ny, got_dx, got_dy = read_ours(example, back, back + ".npy")
            theirs = np.load(back + ".npy")
            if (got_nx, got_ny) != (nx, ny):
                problems.append(f"its file: grid {(got_nx, got_ny)} != {(nx, ny)}")
            elif abs(got_dx - dx) > REL * dx or got_dy is None or abs(got_dy - dy) > REL * dy:
                problems.append(f"its file: intervals {got_dx!r}, {got_dy!r} != {dx!r}, {dy!r}")
            elif not np.array_equal(np.isnan(theirs), np.isnan(st)):
                problems.append("its file: missing points differ")
            else:
                ok = ~np.isnan(st)
                scale = np.nanmax(np.abs(st))
                # Its integer types quantise again: half a step of its own.
                span = np.nanmax(st) - np.nanmin(st)
                tol = {"D": 0.0, "F": scale * np.finfo(np.float32).eps,
                       "L": 0.51 * span / (2.0**32 - 1), "I": 0.51 * span / (2.0**16 - 1)}[ztype] + REL * scale
                diff = np.max(np.abs(theirs[ok] - st[ok]), initial=0.0)
                if diff > tol:
                    problems.append(f"its file, read here: max |diff| {diff:.3e} > {tol:.3e}")
        if problems:
            failed += 1
            print(f"FAIL {name}: " + "; ".join(problems))
        else:
            passed += 1
            print(f"ok   {name}: {nx} x {ny}, type {ztype}, both ways")
    return passed, failed, skipped


def main():
    if len(sys.argv) > 2 or (len(sys.argv) == 2 and sys.argv[1].startswith("-")):
        print(__doc__)
        return 2
    if len(sys.argv) == 2:
        passed, failed, skipped = check_dir(sys.argv[1])
    else:
        with tempfile.TemporaryDirectory() as d:
            run_example(d)
            root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
            target = os.environ.get("CARGO_TARGET_DIR", os.path.join(root, "target"))
            passed, failed, skipped = check_dir(d, os.path.join(target, "release", "examples"))
    print(f"x3p_check: {passed} passed, {failed} failed, {skipped} skipped")
    return 1 if failed or not passed else 0


if __name__ == "__main__":
    sys.exit(main())
