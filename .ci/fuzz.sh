#!/usr/bin/env bash
# CI stage fuzz (fuzz/), under AddressSanitizer, each target from its
# committed seed corpus (fuzz/seeds/TARGET/) plus the inputs of crashes
# found before (fuzz/regressions/TARGET/, replayed first):
# - table_bytes, table_spec (table files): FUZZ_SECONDS each (default 12);
# - surface_x3p, surface_npy, surface_text (the measured-surface readers,
#   read_bytes), surface_instruments_a (.sur, .plu, .opd, .al3d) and
#   surface_instrument_b (MetroPro, Nanoscope, .nid), surface_container
#   (contact.engineering containers): READER_SECONDS each
#   (default 12).
# About 1.6 minutes of fuzzing plus the build (longer runs: set the
# variables). A crash, a panic, a broken invariant or an
# out-of-bounds access fails the stage; libFuzzer writes the input to
# fuzz/artifacts/TARGET/.
# Needs the nightly toolchain; installs cargo-fuzz when missing.
set -euo pipefail
cd "$(dirname "$0")/../fuzz"
table_secs=${FUZZ_SECONDS:-12}
reader_secs=${READER_SECONDS:-12}
if ! command -v cargo-fuzz > /dev/null; then
  echo "installing cargo-fuzz"
  # Unoptimised: a third of the compile time; it only drives cargo.
  CARGO_PROFILE_RELEASE_OPT_LEVEL=0 CARGO_PROFILE_RELEASE_DEBUG=false \
    cargo install --quiet --locked cargo-fuzz
fi
cargo +nightly fuzz build -O 2>&1 | tail -3
for target in table_bytes table_spec surface_x3p surface_npy surface_text surface_instruments_a surface_instrument_b surface_container; do
  case $target in
    table_*) secs=$table_secs ;;
    *) secs=$reader_secs ;;
  esac
  corpus=target/ci-corpus/$target
  rm -rf "$corpus" && mkdir -p "$corpus"
  cp seeds/$target/* "$corpus/"
  if [ -d regressions/$target ]; then
    cp regressions/$target/* "$corpus/"
  fi
  # libFuzzer's own summary lines (runs, coverage) are kept in a log.
  log=target/ci-$target.log
  if ! cargo +nightly fuzz run -O "$target" "$corpus" -- -max_total_time="$secs" -print_final_stats=1 > "$log" 2>&1; then
    tail -40 "$log"
    echo "fuzz: $target failed (input in fuzz/artifacts/$target/)"
    exit 1
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  echo "fuzz: $target: $runs runs in $secs s, no crash"
done
