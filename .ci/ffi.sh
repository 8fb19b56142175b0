#!/usr/bin/env bash
# The C ABI from C, C++ and Fortran: build the library, compile the examples
# against it (C: static library; Fortran: shared library), run them, and
# compare the C example's mu with direct integration (`kefric eval`).
set -euo pipefail
cd "$(dirname "$0")/.."
target=${CARGO_TARGET_DIR:-target}
lib="$target/release"
out="$target/ci-ffi"
rm -rf "$out" && mkdir -p "$out"

source .ci/lib.sh
need gfortran gfortran "$out/apt.log"

cargo build --release --quiet -p ke-friction-ffi -p kefric

# C99, warnings as errors, against the static library.
gcc -std=c99 -D_POSIX_C_SOURCE=199309L -O2 -Wall -Wextra -Werror -I ffi/include \
  ffi/examples/contacts.c "$lib/libkefriction.a" -lpthread -ldl -lm -o "$out/contacts"
# The batches' NaN mode and the stable kef_last_error pointer, from C.
gcc -std=c99 -O2 -Wall -Wextra -Werror -I ffi/include \
  ffi/tests/batch_nan.c "$lib/libkefriction.a" -lpthread -ldl -lm -o "$out/batch_nan"
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
