//! Raw bytes as a table file: `Table::from_bytes` returns an error or a
//! table that keeps the invariant (see check.rs). Seeds: `fuzz/seeds/`.
#![no_main]

#[path = "check.rs"]
mod check;

use ke_friction::Table;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(t) = Table::from_bytes(data) {
        let q = check::queries(&t, &[[0.3, 0.5, 0.7], [0.01, 0.99, 0.5]]);
        // The loader bounds |ln μ| coefficients by 700.
        check::check(&t, &q, 700.0);
    }
});
