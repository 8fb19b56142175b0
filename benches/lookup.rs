//! Table lookups against direct integration, on the same random in-domain
//! queries; and for one surface pair, a `Curve` against the table.
use criterion::{black_box, criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use ke_friction::{Curve, Model, Params, Table};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const N: usize = 4096;

fn queries(n: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let d = Table::embedded().domain();
    let mut rng = ChaCha8Rng::seed_from_u64(42);
    let log = |(lo, hi): (f64, f64), u: f64| (lo.ln() + (hi.ln() - lo.ln()) * u).exp();
    let mut p = vec![];
    let mut t = vec![];
    let mut f = vec![];
    for _ in 0..n {
        p.push(log(d.psi, rng.gen()));
        t.push(d.theta.0 + (d.theta.1 - d.theta.0) * rng.gen::<f64>());
        f.push(log(d.f_star, rng.gen()));
    }
    (p, t, f)
}

fn bench_lookup(c: &mut Criterion) {
    let table = Table::embedded();
    let (p, t, f) = queries(N);
    let mut g = c.benchmark_group("lookup");
    // Single calls, as a simulator's inner loop makes them: one call per
    // query over all N queries, so the time per call is the reported time / N.
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("mu", |b| {
        b.iter(|| {
            let mut s = 0.0;
            for i in 0..N {
                s += table.mu(black_box(p[i]), black_box(t[i]), black_box(f[i])).unwrap();
            }
            black_box(s)
        })
    });
    g.bench_function("mu_with_slope", |b| {
        b.iter(|| {
            let mut s = 0.0;
            for i in 0..N {
                let (m, d) = table
                    .mu_with_slope(black_box(p[i]), black_box(t[i]), black_box(f[i]))
                    .unwrap();
                s += m + d;
            }
            black_box(s)
        })
    });
    // The exact f64 kernel, which f64 tables and CPUs without AVX2 run.
    g.bench_function("mu_portable", |b| {
        b.iter(|| {
            let mut s = 0.0;
            for i in 0..N {
                s += table
                    .mu_portable(black_box(p[i]), black_box(t[i]), black_box(f[i]))
                    .unwrap();
            }
            black_box(s)
        })
    });
    let mut out = vec![0.0; N];
    g.bench_function("mu_batch", |b| {
        b.iter(|| {
            table
                .mu_batch(black_box(&p), black_box(&t), black_box(&f), &mut out)
                .unwrap();
            black_box(&out);
        })
    });
    let mut pairs = vec![(0.0, 0.0); N];
    g.bench_function("mu_with_slope_batch", |b| {
        b.iter(|| {
            table
                .mu_with_slope_batch(black_box(&p), black_box(&t), black_box(&f), &mut pairs)
                .unwrap();
            black_box(&pairs);
        })
    });
    g.finish();

    // The peer: interpn's regular-grid multicubic interpolation on the very
    // same grid (the table's nodes inside its domain, in the same
    // coordinates ln ψ, √θ, ln F*, holding ln μ) and the same queries,
    // including the coordinate maps and the final exp, as our lookup does.
    let axes = table.axes();
    let nodes = ke_friction::export::table_nodes(table);
    let mut vals = Vec::new();
    for &u in &nodes[0] {
        for &t in &nodes[1] {
            for &v in &nodes[2] {
                vals.push(table.mu(u, t, v).unwrap().ln());
            }
        }
    }
    let dims = nodes.each_ref().map(|n| n.len());
    let starts = [0, 1, 2].map(|k| axes[k].scale.forward(nodes[k][0]));
    let steps = [axes[0].step, axes[1].step, axes[2].step];
    let (mut cu, mut ct, mut cv) = (vec![0.0; N], vec![0.0; N], vec![0.0; N]);
    let mut g = c.benchmark_group("peer");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("interpn_multicubic_batch", |b| {
        b.iter(|| {
            for i in 0..N {
                cu[i] = p[i].ln();
                ct[i] = t[i].sqrt();
                cv[i] = f[i].ln();
            }
            let obs = [&cu[..], &ct[..], &cv[..]];
            interpn::multicubic::regular::interpn(&dims, &starts, &steps, &vals, false, &obs, &mut out).unwrap();
            for o in out.iter_mut() {
                *o = o.exp();
            }
            black_box(&out);
        })
    });
    g.finish();
    // (Its own name: benches/model.rs has `direct/at_f_star` without
    // `Model::new`, and criterion compares runs of the same name.)
    let mut g = c.benchmark_group("direct");
    g.sample_size(20);
    let mut i = 0;
    g.bench_function("new_and_at_f_star", |b| {
        b.iter(|| {
            i = (i + 1) & (N - 1);
            let m = Model::new(Params::new(p[i], t[i])).unwrap();
            black_box(m.at_f_star(black_box(f[i])).unwrap().mu)
        })
    });
    g.finish();
}

/// A large batch (10⁵ random queries, one call), on warm caches and after
/// other work has swept them: a 64 MB buffer written and freed before
/// every call (not timed), as a caller's own work between batches would.
/// The cold call is where the kernel's sequential pass over the
/// coefficients (for batches of about 12,900 queries or more) pays.
fn bench_large_batch(c: &mut Criterion) {
    const LARGE: usize = 100_000;
    let table = Table::embedded();
    let (p, t, f) = queries(LARGE);
    let mut out = vec![0.0; LARGE];
    let mut g = c.benchmark_group("large_batch");
    g.throughput(Throughput::Elements(LARGE as u64));
    g.sample_size(30);
    let mut run = || {
        table
            .mu_batch(black_box(&p), black_box(&t), black_box(&f), &mut out)
            .unwrap();
        black_box(&out);
    };
    g.bench_function("mu_batch_warm", |b| b.iter(&mut run));
    g.bench_function("mu_batch_cold", |b| {
        b.iter_batched(
            || black_box(vec![1u8; 64 << 20]).len(),
            |_| run(),
            BatchSize::PerIteration,
        )
    });
    g.finish();
}

criterion_group!(benches, bench_lookup, bench_curve, bench_large_batch);
criterion_main!(benches);

/// One surface pair (ψ, θ fixed), random loads: the curve against the
/// table at the same (ψ, θ) and the same F*, in one group so that the runs
/// are made together; and against direct integration on a built model.
fn bench_curve(c: &mut Criterion) {
    const PSI: f64 = 2.0;
    const THETA: f64 = 0.003;
    let table = Table::embedded();
    let curve = table.curve(PSI, THETA).unwrap();
    let (_, _, f) = queries(N);
    let hi = curve.range().1;
    let (p, t) = (vec![PSI; N], vec![THETA; N]);
    let mut g = c.benchmark_group("surface");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("table_mu", |b| {
        b.iter(|| {
            let mut s = 0.0;
            for &x in &f {
                s += table.mu(black_box(PSI), black_box(THETA), black_box(x)).unwrap();
            }
            black_box(s)
        })
    });
    g.bench_function("curve_mu", |b| {
        b.iter(|| {
            let mut s = 0.0;
            for &x in &f {
                s += curve.mu(black_box(x)).unwrap();
            }
            black_box(s)
        })
    });
    // Each load depends on the previous μ (as in an implicit update): the
    // latency of one lookup, not the throughput of many.
    g.bench_function("table_mu_chain", |b| {
        b.iter(|| {
            let mut m = 0.0;
            for &x in &f {
                m = table.mu(PSI, THETA, (x + 1e-12 * m).min(hi)).unwrap();
            }
            black_box(m)
        })
    });
    g.bench_function("curve_mu_chain", |b| {
        b.iter(|| {
            let mut m = 0.0;
            for &x in &f {
                m = curve.mu((x + 1e-12 * m).min(hi)).unwrap();
            }
            black_box(m)
        })
    });
    let mut out = vec![0.0; N];
    g.bench_function("table_mu_batch", |b| {
        b.iter(|| {
            table
                .mu_batch(black_box(&p), black_box(&t), black_box(&f), &mut out)
                .unwrap();
            black_box(&out);
        })
    });
    g.bench_function("curve_mu_batch", |b| {
        b.iter(|| {
            curve.mu_batch(black_box(&f), &mut out).unwrap();
            black_box(&out);
        })
    });
    g.finish();

    // Direct integration on an already-built model, on the first 64 loads.
    let model = Model::new(Params::new(PSI, THETA)).unwrap();
    let mut g = c.benchmark_group("surface_direct");
    g.throughput(Throughput::Elements(64));
    g.bench_function("model_at_f_star", |b| {
        b.iter(|| {
            let mut s = 0.0;
            for &x in &f[..64] {
                s += model.at_f_star(black_box(x)).unwrap().mu.unwrap();
            }
            black_box(s)
        })
    });
    // Building a curve from the model, and from the table.
    g.throughput(Throughput::Elements(1));
    g.bench_function("curve_from_model", |b| {
        b.iter(|| Curve::from_model(black_box(&model), 1e-5, 0.1).unwrap())
    });
    g.bench_function("curve_from_table", |b| {
        b.iter(|| table.curve(black_box(PSI), black_box(THETA)).unwrap())
    });
    g.finish();
}
