#!/usr/bin/env bash
# CI stage web: the web page (web/) built with `bash web/build.sh` and
# driven in headless Chromium (Debian's chromium and chromium-driver,
# installed when missing; Selenium from PyPI into $PYTHON's venv) from a
# static server on 127.0.0.1: its #record equals `kefric surface --json`
# on the synthetic X3P (three option sets) and on every file of
# ../shared/topographies (or $KEF_TOPOGRAPHIES) that kefric reads, no
# console errors, a bad file shows the CLI's message; each
# contact.engineering container of ../shared/containers (or
# $KEF_CONTAINERS) gives kefric's record, scan and combined PSD; a 1024 x
# 1024 X3P is read, analysed and its mu(F) drawn within 1.5 s; the .wasm is
# <= 3 MiB.
# Screenshots go to $CARGO_TARGET_DIR/ci-web/out.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
py=${PYTHON:-python3}
target=${CARGO_TARGET_DIR:-target}
case $target in /*) ;; *) target=$root/$target ;; esac
out=$target/ci-web
rm -rf "$out" && mkdir -p "$out"

source .ci/lib.sh
need chromium chromium "$out/apt.log"
need chromedriver chromium-driver "$out/apt.log"
"$py" -m pip install --quiet --disable-pip-version-check selenium

# The analysis natively (its options and command line).
cargo test --release --quiet -p ke-friction-web --lib
t0=$SECONDS
bash web/build.sh "$out/site"
echo "web: build.sh took $((SECONDS - t0)) s"
cargo build --release --quiet -p kefric
"$target/release/examples/rough_surface" "$out/big.x3p" 1024 > /dev/null

topographies=${KEF_TOPOGRAPHIES:-$root/../shared/topographies}
extra=()
[ -d "$topographies" ] && extra+=(--topographies "$topographies")
containers=${KEF_CONTAINERS:-$root/../shared/containers}
[ -d "$containers" ] && extra+=(--containers "$containers")
"$py" web/tests/browser.py "$out/site" "$target/release/kefric" "$out/out" --big "$out/big.x3p" "${extra[@]}"
