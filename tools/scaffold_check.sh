#!/usr/bin/env bash
# The registries are open (issue 47): a new contact law, height-distribution
# family and surface format each take one new file and one registry line,
# and nothing else. Copies the checkout (the files git knows, as they are
# in the work tree) to a temporary directory, adds there
#   - a toy law: src/model/laws/ceb.rs copied as toy.rs, renamed, and its
#     line in src/model/laws/registry.rs;
#   - a toy family: src/distribution/weibull.rs copied as toy.rs, renamed,
#     and its line in families! (src/distribution/mod.rs);
#   - a toy format: src/topography/read/sur.rs copied as toy.rs (name
#     "toy", extension .toy) and its line in readers!
#     (src/topography/read/mod.rs);
# then runs the default members' tests (`cargo test --release`) and the
# Python package's tests against the package built from the copy. Every
# one must pass with no other edit.
#
# Compiled dependencies are reused: CARGO_TARGET_DIR is target/scaffold in
# the checkout (kept between runs; the first run compiles the dependencies).
# Python: PYTHON (default python3) with numpy, pytest and maturin (CI's
# venv), else a venv made once in target/scaffold/venv; the package built
# from the copy is installed into target/scaffold/site, ahead on
# PYTHONPATH. The copy is target/scaffold/tree (kept until the next run).
# Runs from anywhere in a checkout; exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
export CARGO_TARGET_DIR=$root/target/scaffold CARGO_TERM_COLOR=never
mkdir -p "$CARGO_TARGET_DIR"
# A fresh clone (CI) has no compiled dependencies here: seed them from the
# checkout's own release build (a copy: the registry's crates build the
# same in both trees; the copy's own crates are newer than their
# fingerprints, so they are compiled again).
if [ ! -d "$CARGO_TARGET_DIR/release" ] && [ -d "$root/target/release" ]; then
  t_seed=$SECONDS
  cp -a "$root/target/release" "$CARGO_TARGET_DIR/release"
  echo "scaffold: seeded the compiled dependencies from target/release in $((SECONDS - t_seed)) s"
fi
# The copy stays at one path (its files keep their times), so that a
# second run recompiles only what changed.
copy=$CARGO_TARGET_DIR/tree
rm -rf "$copy" && mkdir -p "$copy"
t0=$SECONDS

# The tree: tracked and new (not ignored) files, as in the work tree.
git ls-files -z --cached --others --exclude-standard |
  while IFS= read -r -d '' f; do [ -e "$f" ] && printf '%s\0' "$f"; done |
  tar --null -T - -cf - | tar -xf - -C "$copy"
cd "$copy"

# Adds `line` right after the line matching `anchor` in `file` (exactly
# one; a second call puts its line before the first's).
add_line() {
  local file=$1 anchor=$2 line=$3
  [ "$(grep -c -- "$anchor" "$file")" = 1 ] || { echo "scaffold: '$anchor' is not one line of $file"; exit 1; }
  sed -i "/$anchor/a\\$line" "$file"
}

# A toy contact law: the CEB-type law under another name.
sed 's/CebType/ToyLaw/g; s/CebCapacity/ToyCapacity/g' src/model/laws/ceb.rs > src/model/laws/toy.rs
add_line src/model/laws/registry.rs 'CebType = ("ceb", 1,' '    ToyLaw = ("toy", 2, "Toy law") => toy::ToyLaw,'
add_line src/model/laws/registry.rs 'CebType = ("ceb", 1,' '    /// A toy law: the CEB-type law copied (tools/scaffold_check.sh).'

# A toy height distribution family: Weibull under another name.
sed 's/Weibull/Toy/g; s/WEIBULL/TOY/g; s/weibull/toy/g' src/distribution/weibull.rs > src/distribution/toy.rs
add_line src/distribution/mod.rs 'Weibull = 2, "weibull" => weibull::Weibull,' '    Toy = 5, "toy" => toy::Toy,'
add_line src/distribution/mod.rs 'Weibull = 2, "weibull" => weibull::Weibull,' '    /// A toy family: Weibull copied (tools/scaffold_check.sh).'

# A toy surface format: .sur under another name and extension.
sed 's/name: "sur"/name: "toy"/; s/extensions: &\["sur"\]/extensions: \&["toy"]/; s/description: "Digital Surf .sur (MountainsMap)"/description: "a toy copy of Digital Surf .sur"/' \
  src/topography/read/sur.rs > src/topography/read/toy.rs
grep -q 'name: "toy"' src/topography/read/toy.rs && grep -q '&\["toy"\]' src/topography/read/toy.rs
add_line src/topography/read/mod.rs '^    nid => \[ENTRY\],' '    toy => [ENTRY],'
echo "scaffold: copied and extended in $((SECONDS - t0)) s"

t1=$SECONDS
log=$CARGO_TARGET_DIR/scaffold-test.log
nice cargo test --release --no-fail-fast > "$log" 2>&1 || {
  grep -E '^(error|failures:|---- |test .* FAILED|thread .* panicked)' -A6 "$log" | tail -150
  echo "scaffold: cargo test --release failed (the whole log: $log)"
  exit 1
}
echo "scaffold: cargo test --release passed in $((SECONDS - t1)) s"

t2=$SECONDS
py=${PYTHON:-python3}
if ! "$py" -c 'import numpy, pytest, maturin' 2> /dev/null; then
  # No tools in PYTHON: a venv of our own, made once.
  venv=$CARGO_TARGET_DIR/venv
  [ -x "$venv/bin/python" ] || "$py" -m venv "$venv"
  py=$venv/bin/python
  "$py" -m pip install --quiet --disable-pip-version-check maturin pytest numpy scipy
fi
# maturin (the package's build backend) from PYTHON's environment.
export PATH=$(dirname "$py"):$PATH
# The package built from the copy, beside (not over) PYTHON's own.
site=$CARGO_TARGET_DIR/site
rm -rf "$site"
"$py" -m pip install --quiet --disable-pip-version-check --no-build-isolation --no-deps --target "$site" ./python
export KEFRIC=$CARGO_TARGET_DIR/release/kefric MPLBACKEND=Agg PYTHONPATH=$site
# What .ci/python.sh gives the tests: the crafted tables, the reader's dump
# and the instruments' files (../shared/topographies beside the checkout).
cargo build --release --quiet -p ke-friction --features builder,plot,topography --example crafted_tables --example read_dump
export KEF_CRAFTED_DIR=$CARGO_TARGET_DIR/crafted KEF_READ_DUMP=$CARGO_TARGET_DIR/release/examples/read_dump
"$CARGO_TARGET_DIR/release/examples/crafted_tables" "$KEF_CRAFTED_DIR" > /dev/null
export KEF_TOPOGRAPHIES=${KEF_TOPOGRAPHIES:-$root/../shared/topographies}
mkdir -p "$CARGO_TARGET_DIR/pytest-run"
(cd "$CARGO_TARGET_DIR/pytest-run" && "$py" -m pytest -q -p no:cacheprovider "$copy/python/tests")
echo "scaffold: python tests passed in $((SECONDS - t2)) s"
echo "scaffold: a toy law, family and format added with one file and one line each: all tests pass ($((SECONDS - t0)) s)"
