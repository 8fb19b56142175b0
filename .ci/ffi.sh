#!/usr/bin/env bash
# The C ABI from C, C++ and Fortran: build the library, compile the examples
# against it (C: static library; Fortran: shared library), run them, and
# compare the C example's mu with direct integration (`kefric eval`); the
# kef_last_error guarantee under AddressSanitizer; ffi/install.sh into a
# scratch prefix, and the examples built against the installed tree
# (pkg-config, CMake's find_package, the Fortran module) and run from
# another directory.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${CARGO_TARGET_DIR:-target}
lib="$target/release"
out="$target/ci-ffi"
rm -rf "$out" && mkdir -p "$out"

source .ci/lib.sh
need gfortran gfortran "$out/apt.log"
need pkg-config pkg-config "$out/apt.log"
need cmake cmake "$out/apt.log"

cargo build --release --quiet -p ke-friction-ffi -p kefric

# C99, warnings as errors, against the static library.
gcc -std=c99 -D_POSIX_C_SOURCE=199309L -O2 -Wall -Wextra -Werror -I ffi/include \
  ffi/examples/contacts.c "$lib/libkefriction.a" -lpthread -ldl -lm -o "$out/contacts"
# The batches' NaN mode and the stable kef_last_error pointer, from C.
gcc -std=c99 -O2 -Wall -Wextra -Werror -I ffi/include \
  ffi/tests/batch_nan.c "$lib/libkefriction.a" -lpthread -ldl -lm -o "$out/batch_nan"
# The warnings' bits and messages, and F* > 1 refused, from C.
gcc -std=c99 -O2 -Wall -Wextra -Werror -I ffi/include \
  ffi/tests/warnings.c "$lib/libkefriction.a" -lpthread -ldl -lm -o "$out/warnings"
"$out/warnings"
"$out/batch_nan"
# The header from C++.
printf '#include <kefriction.h>\nint main() { double mu; return kef_table_mu(kef_table_default(), 1.0, 0.001, 0.01, &mu); }\n' > "$out/use.cpp"
g++ -std=c++11 -Wall -Wextra -Werror -I ffi/include "$out/use.cpp" -L "$lib" -lkefriction -Wl,-rpath,"$PWD/$lib" -o "$out/use_cpp"
"$out/use_cpp"
# Fortran, against the shared library.
for prog in contacts vfric_style; do
  gfortran -O2 -Wall -Werror -J "$out" ffi/fortran/ke_friction.f90 "ffi/examples/$prog.f90" \
    -L "$lib" -lkefriction -Wl,-rpath,"$PWD/$lib" -o "$out/${prog}_f"
done

"$out/contacts" | tee "$out/contacts.txt"
"$out/contacts_f"
"$out/vfric_style_f"

# Abaqus: ffi/abaqus/fric_coef.f (fixed form, the stand-in ABA_PARAM.INC)
# called as Abaqus/Standard calls it, blocks of nodes from 4 threads:
# values against the library (1e-12), dmu/dp against a central difference
# (1e-5), every other fCoefDeriv entry 0 and fCoef(:,2) untouched; props
# of a wrong length stop it through XIT (exit 3).
gfortran -O2 -fopenmp -Wall -Werror -Wno-unused-dummy-argument -I ffi/abaqus/driver \
  -c ffi/abaqus/fric_coef.f -o "$out/fric_coef.o"
gfortran -O2 -fopenmp -Wall -Werror -J "$out" ffi/fortran/ke_friction.f90 ffi/abaqus/driver/driver.f90 \
  "$out/fric_coef.o" -L "$lib" -lkefriction -Wl,-rpath,"$PWD/$lib" -o "$out/fric_coef_driver"
OMP_NUM_THREADS=4 "$out/fric_coef_driver"
set +e
"$out/fric_coef_driver" bad > "$out/fric_coef_bad.txt" 2>&1
status=$?
set -e
[ "$status" = 3 ] && grep -q 'kef_law_from_props: n_props = 4: must be 3' "$out/fric_coef_bad.txt" \
  || { cat "$out/fric_coef_bad.txt"; echo "ffi: FRIC_COEF did not stop (XIT) on bad props: status $status"; exit 1; }
echo "ffi: FRIC_COEF stops through XIT on bad props"

# The C example's mu (a curve from the default table) against direct integration,
# within the table's recorded tolerance.
tolerance=$("$lib/kefric" info --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["tolerance"])')
python3 - "$lib/kefric" "$tolerance" "$out/contacts.txt" <<'PY'
import json, subprocess, sys
kefric, tolerance, path = sys.argv[1], float(sys.argv[2]), sys.argv[3]
rows = [dict(kv.split("=") for kv in line.split()[1:]) for line in open(path) if line.startswith("mu ")]
assert len(rows) == 4, rows
worst = 0.0
for r in rows:
    out = subprocess.run([kefric, "eval", "--json", "--psi", r["psi"], "--theta", r["theta"], "--f-star", r["f_star"]],
                         check=True, capture_output=True, text=True).stdout
    exact = json.loads(out)["mu"]
    rel = abs(float(r["mu"]) / exact - 1)
    worst = max(worst, rel)
    assert rel <= tolerance, f"F* = {r['f_star']}: C {r['mu']}, kefric eval {exact}: {rel:.2e} > {tolerance}"
print(f"ffi: the C example's mu within {worst:.2e} of kefric eval (tolerance {tolerance:g}) at {len(rows)} loads")
PY

# The kef_last_error guarantee (the pointer stays valid; read in the same
# expression as the failing call, after it, after a handle is freed; a long
# message is cut) under AddressSanitizer, against the static library.
gcc -std=c99 -g -O1 -fsanitize=address -fno-omit-frame-pointer -Wall -Wextra -Werror -I ffi/include \
  ffi/tests/last_error_asan.c "$lib/libkefriction.a" -lpthread -ldl -lm -o "$out/last_error_asan"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=0 "$out/last_error_asan" > "$out/asan.txt" \
  || { cat "$out/asan.txt"; echo "ffi: last_error_asan failed"; exit 1; }
grep -qx '2 psi = NaN is out of range: must be in \[1e-3, 1e3\]' "$out/asan.txt" \
  || { cat "$out/asan.txt"; echo "ffi: kef_model_mu(NaN, ...)'s message is not the expected one"; exit 1; }
echo "ffi: kef_last_error under ASan: $(head -1 "$out/asan.txt")"

# ffi/install.sh into a scratch prefix; then the examples against the
# installed tree only, each run from another directory (the rpath, not the
# working directory, finds the library).
out=$(cd "$out" && pwd -P)
mkdir -p "$out/prefix"
prefix="$out/prefix"
elsewhere=$(mktemp -d)
trap 'rm -rf "$elsewhere"' EXIT
ffi/install.sh "$prefix"
cmp ffi/include/kefriction.h "$prefix/include/kefriction.h"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
version=$(pkg-config --modversion kefriction)
[ "$version" = "$(cargo pkgid -p ke-friction-ffi | sed 's/.*[#@]//')" ] || { echo "ffi: kefriction.pc says $version"; exit 1; }
# C by pkg-config (contacts.c's own -lm: it calls exp and log).
cc -O2 ffi/examples/contacts.c $(pkg-config --cflags --libs kefriction) -lm -Wl,-rpath,"$prefix/lib" \
  -o "$out/contacts_pc"
(cd "$elsewhere" && "$out/contacts_pc") > "$out/contacts_pc.txt"
# CMake: find_package(kefriction CONFIG) and kefriction::kefriction,
# configured as its header comment says (no build type: it defaults to
# Release, an optimised build).
cmake -S ffi/examples/cmake -B "$out/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" \
  > "$out/cmake.log" 2>&1 && cmake --build "$out/cmake-build" --verbose >> "$out/cmake.log" 2>&1 \
  || { cat "$out/cmake.log"; echo "ffi: the CMake example failed"; exit 1; }
grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$out/cmake-build/CMakeCache.txt" \
  && grep -q -- '-O[23]' "$out/cmake.log" \
  || { echo "ffi: the CMake example does not default to an optimised (Release) build"; exit 1; }
(cd "$elsewhere" && "$out/cmake-build/contacts") > "$out/contacts_cmake.txt"
# Fortran: the installed module (.mod and its library) by pkg-config.
gfortran -O2 -Wall -Werror ffi/examples/contacts.f90 $(pkg-config --cflags --libs kefriction-fortran) \
  -Wl,-rpath,"$prefix/lib" -o "$out/contacts_f_installed"
(cd "$elsewhere" && "$out/contacts_f_installed") > /dev/null
# The same mu as the in-tree static build.
for built in contacts_pc contacts_cmake; do
  cmp <(grep '^mu ' "$out/contacts.txt") <(grep '^mu ' "$out/$built.txt") \
    || { echo "ffi: $built's mu differs from the in-tree build's"; exit 1; }
done
echo "ffi: installed kefriction $version: pkg-config, CMake and Fortran builds run from $elsewhere"

# The README's C and Fortran lines, as written (its first sh block under
# "From C, C++ and Fortran"), with HOME a scratch directory (cargo and
# rustup keep theirs).
readme_home=$(mktemp -d)
awk '/^## From C, C\+\+ and Fortran/ { on = 1 } on && /^```sh$/ { inside = 1; next }
     inside && /^```$/ { exit } inside { print }' README.md > "$out/readme-ffi.sh"
grep -q 'ffi/examples/contacts.c' "$out/readme-ffi.sh" || { cat "$out/readme-ffi.sh"; echo "ffi: no README block"; exit 1; }
CARGO_HOME=${CARGO_HOME:-$HOME/.cargo} RUSTUP_HOME=${RUSTUP_HOME:-$HOME/.rustup} HOME=$readme_home \
  bash -euo pipefail "$out/readme-ffi.sh" > "$out/readme-ffi.txt" 2>&1 \
  || { cat "$out/readme-ffi.txt"; echo "ffi: the README's C/Fortran lines failed"; exit 1; }
grep -q '^mu ' "$out/readme-ffi.txt" || { cat "$out/readme-ffi.txt"; echo "ffi: the README's C example printed no mu"; exit 1; }
rm -rf "$readme_home"
echo "ffi: the README's C and Fortran lines build and run ($(grep -c '^mu ' "$out/readme-ffi.txt") mu lines)"
