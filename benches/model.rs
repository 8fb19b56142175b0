//! Direct integration: one `at_h_star` and one `at_f_star`, on random
//! in-domain parameters (ψ ∈ [0.5, 8], θ ∈ [0, 0.01], h* ∈ [0, 3],
//! F* ∈ [1e-5, 0.1] log-uniform), fixed seed.
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use ke_friction::{Constants, HeightDistribution, Model, Params};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn models(n: usize) -> Vec<Model> {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    (0..n)
        .map(|_| {
            let psi = 0.5 * 16f64.powf(rng.gen::<f64>());
            let theta = 0.01 * rng.gen::<f64>();
            Model::new(Params::new(psi, theta)).unwrap()
        })
        .collect()
}

fn bench_model(c: &mut Criterion) {
    let ms = models(64);
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    let hs: Vec<f64> = (0..64).map(|_| 3.0 * rng.gen::<f64>()).collect();
    let fs: Vec<f64> = (0..64).map(|_| 1e-5 * 1e4f64.powf(rng.gen::<f64>())).collect();
    let mut group = c.benchmark_group("direct");
    let mut i = 0;
    group.bench_function("at_h_star", |b| {
        b.iter(|| {
            i = (i + 1) % 64;
            black_box(ms[i].at_h_star(black_box(hs[i])).unwrap())
        })
    });
    group.bench_function("at_f_star", |b| {
        b.iter(|| {
            i = (i + 1) % 64;
            black_box(ms[i].at_f_star(black_box(fs[i])).unwrap())
        })
    });
    group.bench_function("model_new", |b| {
        b.iter(|| black_box(Model::new(black_box(Params::new(1.0, 0.003))).unwrap()))
    });
    group.finish();
}

/// `at_f_star` for the same (ψ, θ, F*) points with each height
/// distribution (MODEL.md §9): the same-run ratio to the Gaussian is the
/// figure that matters (the issue asks ≤ 3× for Pearson).
fn bench_distributions(c: &mut Criterion) {
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    let points: Vec<(f64, f64, f64)> = (0..32)
        .map(|_| {
            let psi = 0.5 * 8f64.powf(rng.gen::<f64>());
            let theta = 3e-3 * rng.gen::<f64>();
            (psi, theta, 1e-4 * 500f64.powf(rng.gen::<f64>()))
        })
        .collect();
    let mut group = c.benchmark_group("distribution");
    for (name, d) in [
        ("gaussian", HeightDistribution::GAUSSIAN),
        ("pearson_0_8", HeightDistribution::pearson(0.0, 8.0).unwrap()),
        ("pearson_-0.5_3.375", HeightDistribution::pearson(-0.5, 3.375).unwrap()),
        ("pearson_0.3_3.2", HeightDistribution::pearson(0.3, 3.2).unwrap()),
        ("pearson_0.4_8", HeightDistribution::pearson(0.4, 8.0).unwrap()),
        ("pearson_0.3_2.7", HeightDistribution::pearson(0.3, 2.7).unwrap()),
        ("weibull_0", HeightDistribution::weibull(0.0).unwrap()),
    ] {
        let ms: Vec<(Model, f64)> = points
            .iter()
            .map(|&(psi, theta, f)| {
                let p = Constants::default().distribution(d.clone()).at(psi, theta).unwrap();
                (Model::new(p).unwrap(), f)
            })
            .collect();
        let mut i = 0;
        group.bench_function(name, |b| {
            b.iter(|| {
                i = (i + 1) % ms.len();
                black_box(ms[i].0.at_f_star(black_box(ms[i].1)).unwrap())
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_model, bench_distributions);
criterion_main!(benches);
