//! The C ABI's friction law from Rust (the calls a C program makes): a
//! valid lookup, a failing one (an open contact, p <= 0), a failing one
//! whose message is then read (what every failure cost while messages were
//! formatted at once), a loop with 17 % open nodes, and the Rust law.
//! `cargo bench -p ke-friction-bench --bench c_abi`.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use ke_friction::{FrictionLaw, OutOfRange, Params};
use kefriction::*;
use rand::{Rng, SeedableRng};
use std::ptr::null;

/// Pressures a batch.
const N: usize = 4096;

fn bench_law(c: &mut Criterion) {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(38);
    // Log-uniform in the law's range [1e4, 1e8] Pa.
    let p: Vec<f64> = (0..N).map(|_| 1e4 * 1e4f64.powf(rng.gen::<f64>())).collect();
    let open: Vec<f64> = p.iter().map(|x| -x).collect();
    // 17 % of the nodes open, at random places.
    let mixed: Vec<f64> = p
        .iter()
        .map(|&x| if rng.gen::<f64>() < 0.17 { -x } else { x })
        .collect();
    // SAFETY: NULL constants are the defaults; the law lives to the end.
    let law = unsafe { kef_law_new(null(), 1.0, 0.001, 1e9, 1e4, 1e8, KEF_LAW_ERROR) };
    assert!(!law.is_null());
    let rust = FrictionLaw::new(Params::new(1.0, 0.001), 1e9, Some((1e4, 1e8)), OutOfRange::Error).unwrap();
    let run = |loads: &[f64], read_message: bool| {
        let mut s = 0.0;
        for &x in loads {
            let mut mu = 0.0;
            // SAFETY: a live law and a local double.
            let code = unsafe { kef_law_mu(law, black_box(x), &mut mu) };
            if code == KEF_OK {
                s += mu;
            } else if read_message {
                s += black_box(kef_last_error()) as usize as f64 * 0.0;
            }
        }
        black_box(s)
    };
    let mut g = c.benchmark_group("c_law");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("kef_law_mu", |b| b.iter(|| run(&p, false)));
    g.bench_function("kef_law_mu_open", |b| b.iter(|| run(&open, false)));
    g.bench_function("kef_law_mu_open_then_message", |b| b.iter(|| run(&open, true)));
    g.bench_function("kef_law_mu_17pct_open", |b| b.iter(|| run(&mixed, false)));
    g.bench_function("rust_law_mu", |b| {
        b.iter(|| {
            let mut s = 0.0;
            for &x in &p {
                s += rust.mu(black_box(x)).unwrap();
            }
            black_box(s)
        })
    });
    g.finish();
    // SAFETY: no longer in use.
    unsafe { kef_law_free(law) };
}

criterion_group!(benches, bench_law);
criterion_main!(benches);
