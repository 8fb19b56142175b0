#!/usr/bin/env bash
# Builds the web page into OUT_DIR: `bash web/build.sh OUT_DIR`, then serve
# OUT_DIR with any static server (`python3 -m http.server -d OUT_DIR`).
#
# Installs what it needs when missing: the wasm32-unknown-unknown target
# (rustup) and wasm-bindgen-cli at exactly the version of the wasm-bindgen
# crate in Cargo.lock, into $CARGO_TARGET_DIR/tools/ (never globally).
# Writes OUT_DIR/index.html, app.js, worker.js, style.css, vendor/ (uPlot),
# pkg/ (the WebAssembly and its JS glue) and example.x3p (the built-in
# synthetic surface, examples/rough_surface.rs).
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: bash web/build.sh OUT_DIR" >&2; exit 2; }
out=$1
cd "$(dirname "$0")/.."
root=$PWD
mkdir -p "$out"
out=$(cd "$out" && pwd)
target=${CARGO_TARGET_DIR:-target}
case $target in /*) ;; *) target=$root/$target ;; esac

if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
  rustup target add wasm32-unknown-unknown
fi

# The CLI must match the crate's version exactly (wasm-bindgen's schema).
version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/[^0-9.]/, ""); print; exit }' Cargo.lock)
[ -n "$version" ] || { echo "web: no wasm-bindgen in Cargo.lock" >&2; exit 1; }
tools=$target/tools/wasm-bindgen-$version
bindgen=$tools/bin/wasm-bindgen
if [ ! -x "$bindgen" ]; then
  echo "web: installing wasm-bindgen-cli $version into $tools (a few minutes, once)"
  # Not --locked: its published lock file pins a webpki-roots that the
  # index no longer resolves.
  # Unoptimised (opt-level 0, no debug info): it compiles in 117 CPU s
  # instead of 378 (2026-11-28) and writes the same files, byte for byte,
  # as a release build of it, in 2 s instead of 0.6 s.
  CARGO_PROFILE_RELEASE_OPT_LEVEL=0 CARGO_PROFILE_RELEASE_DEBUG=false \
    cargo install --quiet wasm-bindgen-cli --version "=$version" --root "$tools"
fi
"$bindgen" --version | grep -qF " $version" || { echo "web: $bindgen is not version $version" >&2; exit 1; }

cargo build --quiet --profile web -p ke-friction-web --target wasm32-unknown-unknown
rm -rf "$out/pkg"
"$bindgen" --target web --no-typescript --out-dir "$out/pkg" \
  "$target/wasm32-unknown-unknown/web/ke_friction_web.wasm"
cp -r web/static/. "$out/"
cargo run --release --quiet --features topography --example rough_surface -- "$out/example.x3p" > /dev/null
echo "web: built $out ($(stat -c %s "$out/pkg/ke_friction_web_bg.wasm") bytes of WebAssembly)"
