//! `kef_law_from_props` under threads, as Abaqus calls FRIC_COEF: every
//! call looks its material's law up by the props, then evaluates a block
//! of nodes. Prints ns per lookup and per block call (lookup + 37 nodes)
//! at 1 and 4 threads, two materials alternating.
//!
//! `cargo run --release -p ke-friction-ffi --example props_threads [CALLS]`
//! (CALLS per thread, default 200000).

use kefriction::{kef_law_from_props, kef_law_mu_and_derivative_batch_nan};
use std::hint::black_box;
use std::time::Instant;

/// Nodes in a block (the FRIC_COEF driver's).
const BLOCK: usize = 37;

fn main() {
    let calls: usize = std::env::args()
        .nth(1)
        .map_or(200_000, |a| a.parse().expect("CALLS: a whole number"));
    let props = [vec![1.0, 1e-3, 1e9], vec![2.5, 3e-3, 2e9, 1e5, 1e8, 0.05, 0.33, 6e-3]];
    let p: Vec<f64> = (0..BLOCK).map(|k| 1e5 * 1.2f64.powi(k as i32)).collect();
    // Built once, outside the timing.
    for props in &props {
        // SAFETY: a valid list.
        assert!(!unsafe { kef_law_from_props(props.len(), props.as_ptr()) }.is_null());
    }
    for threads in [1, 2, 4] {
        for with_block in [false, true] {
            let start = Instant::now();
            std::thread::scope(|s| {
                for t in 0..threads {
                    let (props, p) = (&props, &p);
                    s.spawn(move || {
                        let (mut mu, mut d) = ([0.0; BLOCK], [0.0; BLOCK]);
                        let mut n_nan = 0usize;
                        for i in 0..calls {
                            let props = &props[(i + t) % 2];
                            // SAFETY: valid lists and buffers of BLOCK.
                            unsafe {
                                let law = kef_law_from_props(props.len(), black_box(props.as_ptr()));
                                if with_block {
                                    kef_law_mu_and_derivative_batch_nan(
                                        law,
                                        BLOCK,
                                        p.as_ptr(),
                                        mu.as_mut_ptr(),
                                        d.as_mut_ptr(),
                                        &mut n_nan,
                                    );
                                }
                                black_box(law);
                            }
                        }
                        black_box((mu, d));
                    });
                }
            });
            let ns = start.elapsed().as_secs_f64() * 1e9 / calls as f64;
            println!(
                "{threads} thread(s), {}: {ns:.0} ns of wall time per call per thread ({:.1} M calls/s in all)",
                if with_block {
                    "lookup + a block of 37 nodes"
                } else {
                    "lookup only"
                },
                threads as f64 * 1e3 / ns
            );
        }
    }
}
