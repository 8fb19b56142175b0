#!/usr/bin/env python3
"""Does the default height model reproduce the empirical density's mu(F)
trend? (issue 48, item 5; docs/MODEL.md, "The default height model").

For every instrument file in $KEF_TOPOGRAPHIES (else ../shared/topographies
beside the repository) and the README's synthetic map
(target/release/examples/rough_surface), runs

    kefric surface FILE <steel on steel> --area 1e-5 --force 0.01:100:3 --json

with --distribution pearson, gaussian, empirical and the default, and
prints a Markdown table: K, Sk, mu at 0.01, 1 and 100 N for each model
(or why it is refused), the trend of each ("falls", "rises", "mixed"), the
default's family, and whether the default inverts the empirical trend and,
if so, whether it warns `tail`. Exit status 1 if a default inverts the
empirical trend without a `tail` warning.

Usage: tools/height_model_trend.py [target/release/kefric]
"""

import json
import os
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]
KEFRIC = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "target" / "release" / "kefric")
FOLDER = pathlib.Path(os.environ.get("KEF_TOPOGRAPHIES", str(ROOT.parent / "shared" / "topographies")))
STEEL = ["--e1", "200e9", "--nu1", "0.3", "--e2", "200e9", "--nu2", "0.3", "--hardness", "2e9",
         "--delta-gamma", "0.3", "--epsilon", "0.4e-9"]
LOADS = ["--area", "1e-5", "--force", "0.01:100:3"]
FAMILIES = ["pearson", "gaussian", "empirical"]


def run(path, family):
    """(record, None) or (None, the error line)."""
    args = [KEFRIC, "surface", str(path), *STEEL, *LOADS, "--json"]
    if family:
        args += ["--distribution", family]
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != 0:
        return None, p.stderr.strip().splitlines()[-1] if p.stderr.strip() else f"exit {p.returncode}"
    return json.loads(p.stdout), None


def trend(mus):
    if all(b < a for a, b in zip(mus, mus[1:])):
        return "falls"
    if all(b > a for a, b in zip(mus, mus[1:])):
        return "rises"
    return "mixed"


def main():
    files = sorted(f for f in FOLDER.glob("*.*") if f.suffix != ".md") if FOLDER.is_dir() else []
    if not files:
        print(f"note: no instrument files in {FOLDER} (set KEF_TOPOGRAPHIES)", file=sys.stderr)
    tmp = tempfile.mkdtemp()
    example = ROOT / "target" / "release" / "examples" / "rough_surface"
    if example.exists():
        readme = pathlib.Path(tmp) / "readme-rough.x3p"
        subprocess.run([str(example), str(readme)], check=True, capture_output=True)
        files.append(readme)
    else:
        print(f"note: {example} is not built (cargo build --release --features topography --example "
              "rough_surface): the README's map is left out", file=sys.stderr)
    print("| file | K | Sk | model | mu(0.01 N) | mu(1 N) | mu(100 N) | trend | tail warned at |")
    print("|---|---|---|---|---|---|---|---|---|")
    bad = []
    for f in files:
        results = {fam: run(f, fam) for fam in FAMILIES + [None]}
        any_record = next((r for r, _ in results.values() if r), None)
        k = sk = float("nan")
        if any_record:
            k, sk = any_record["surface"]["kurtosis"], any_record["surface"]["skewness"]
        trends = {}
        for fam in FAMILIES + [None]:
            record, error = results[fam]
            if record is None:
                label = fam or "default"
                print(f"| {f.name} | {k:.3g} | {sk:.3g} | {label} | refused: {error[:60]} | | | | |")
                continue
            mus = [r["mu"] for r in record["friction"]]
            loads = [r["force"] for r in record["friction"]]
            tails = [w for w in record["warnings"] if w["kind"] == "tail"]
            tail_at = ""
            if tails:
                # Which loads warned: the tail warning is one a result; rerun is
                # not needed, the summary's worst gives h*; say how many.
                tail_at = f"{tails[0]['count']} of {tails[0]['of']} loads"
            trends[fam] = (trend(mus), bool(tails))
            label = fam or f"default ({record['model']['distribution']})"
            cells = " | ".join(f"{m:.4g}" for m in mus)
            print(f"| {f.name} | {k:.3g} | {sk:.3g} | {label} | {cells} | {trends[fam][0]} | {tail_at} |")
            assert loads == [0.01, 1.0, 100.0], loads
        if None in trends and "empirical" in trends:
            (d, d_tail), (e, _) = trends[None], trends["empirical"]
            if d != e and not d_tail:
                bad.append(f"{f.name}: the default {d}, the empirical density {e}, no tail warning")
    for b in bad:
        print(f"inverted without a tail warning: {b}", file=sys.stderr)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
