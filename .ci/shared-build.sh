#!/usr/bin/env bash
# The README's quickstart shares one build: every package `cargo run
# --release -- build` compiles (kefric and its dependencies) is resolved
# with the same features in `cargo test --release` (the default members
# with their dev-dependencies), so the second compiles only the tests and
# what they alone use (issue 49). Fails naming each package whose features
# differ.
set -euo pipefail
cd "$(dirname "$0")/.."
features() { cargo tree "$@" -f '{p} {f}' --prefix none | sed 's/ (\*)$//' | grep -v '^$' | sort -u; }
run=$(features -p kefric -e normal,build)
test=$(features -e normal,build,dev)
differ=$(comm -23 <(echo "$run") <(echo "$test"))
if [ -n "$differ" ]; then
  echo "shared-build: cargo test --release would rebuild these with other features:"
  echo "$differ"
  exit 1
fi
echo "shared-build: the $(echo "$run" | wc -l) packages of kefric's build have the same features in cargo test's"
