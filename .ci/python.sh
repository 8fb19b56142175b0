#!/usr/bin/env bash
# The Python package: install it with pip (maturin builds the extension),
# run its tests, the example (headless) and the benchmark's accuracy check.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${CARGO_TARGET_DIR:-target}
export KEFRIC=${KEFRIC:-$PWD/$target/release/kefric}
[ -x "$KEFRIC" ] || cargo build --release --quiet -p kefric
pip() { python3 -m pip --disable-pip-version-check --quiet "$@"; }
pip install maturin pytest numpy scipy matplotlib
t0=$SECONDS
pip install --force-reinstall --no-deps ./python
echo "python: pip install ./python took $((SECONDS - t0)) s"
out="$target/ci-python"
rm -rf "$out" && mkdir -p "$out"
# Run from outside the source tree so the installed package is what is tested.
(cd "$out" && python3 -m pytest -q -p no:cacheprovider "$OLDPWD/python/tests")
MPLBACKEND=Agg python3 python/examples/friction_map.py "$out/friction_map.png"
test -s "$out/friction_map.png"
python3 python/bench.py --quick
