#!/usr/bin/env bash
# CI stage fuzz: both fuzz targets on table files (fuzz/), each for
# FUZZ_SECONDS (default 60) from the committed seed corpus, under
# AddressSanitizer. A crash, a panic or an out-of-bounds access fails the
# stage; libFuzzer writes the input to fuzz/artifacts/TARGET/.
# Needs the nightly toolchain; installs cargo-fuzz when missing.
set -euo pipefail
cd "$(dirname "$0")/../fuzz"
secs=${FUZZ_SECONDS:-60}
if ! command -v cargo-fuzz > /dev/null; then
  echo "installing cargo-fuzz"
  cargo install --quiet --locked cargo-fuzz
fi
cargo +nightly fuzz build -O 2>&1 | tail -3
for target in table_bytes table_spec; do
  corpus=target/ci-corpus/$target
  rm -rf "$corpus" && mkdir -p "$corpus"
  cp seeds/$target/* "$corpus/"
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
