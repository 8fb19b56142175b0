#!/usr/bin/env bash
# CI stage crafted-tables: the crafted table files of tests/forge.rs (valid
# checksums, hostile contents) through `kefric` and through the C ABI, both
# under valgrind: each is refused naming its field (exit 2) or answers its
# query correctly, and valgrind reports no invalid read or write.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${CARGO_TARGET_DIR:-target}
out="$target/ci-crafted"
rm -rf "$out" && mkdir -p "$out"

source .ci/lib.sh
need valgrind valgrind "$out/apt.log"

cargo build --release --quiet -p kefric -p ke-friction-ffi
cargo build --release --quiet -p ke-friction --example crafted_tables
"$target/release/examples/crafted_tables" "$out/files" > /dev/null
# 99: valgrind found an error (kefric itself exits 0, 1 or 2).
vg=(valgrind -q --error-exitcode=99 --exit-on-first-error=yes)
kefric="$target/release/kefric"
n=0
while IFS=$'\t' read -r file field query expected name; do
  read -r psi theta f_star <<< "$query"
  t="$out/files/$file"
  set +e
  "${vg[@]}" "$kefric" lookup --table "$t" --psi "$psi" --theta "$theta" --f-star "$f_star" --json > "$out/stdout" 2> "$out/stderr"
  rc=$?
  set -e
  if [ "$field" = ok ]; then
    [ $rc -eq 0 ] || { echo "$name ($file): kefric lookup exit $rc"; cat "$out/stderr"; exit 1; }
    python3 - "$out/stdout" "$expected" "$name" <<'PY'
import json, math, sys
mu = json.load(open(sys.argv[1]))["mu"]
expected = float(sys.argv[2])
assert mu > 0 and abs(mu / expected - 1) <= 2e-6 * (1 + abs(math.log(expected))), (sys.argv[3], mu, expected)
PY
  else
    [ $rc -eq 2 ] || { echo "$name ($file): kefric lookup exit $rc (must be 2)"; cat "$out/stderr"; exit 1; }
    grep -q -- "--table.*$field" "$out/stderr" || { echo "$name ($file): error does not name $field"; cat "$out/stderr"; exit 1; }
  fi
  # info measures the slope at 4000 points by direct integration: too
  # slow under valgrind; it must exit as lookup did, without a panic.
  set +e
  "$kefric" info --table "$t" > /dev/null 2> "$out/stderr"
  rc_info=$?
  set -e
  [ $rc_info -eq $rc ] || { echo "$name ($file): kefric info exit $rc_info, lookup $rc"; cat "$out/stderr"; exit 1; }
  n=$((n + 1))
done < "$out/files/index.tsv"
echo "crafted tables through kefric under valgrind: $n files, no invalid access"

gcc -std=c99 -O2 -Wall -Wextra -Werror -I ffi/include ffi/tests/crafted.c "$target/release/libkefriction.a" \
  -lpthread -ldl -lm -o "$out/crafted"
"${vg[@]}" "$out/crafted" "$out/files"
