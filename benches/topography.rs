//! Surface statistics (MODEL.md §10) of a synthetic 4096 × 4096 f64 map:
//! the target is ≤ 0.25 s on one core for the default options
//! (plane detrend, finite differences). Also a 1024² map, the masked path
//! (1 % of the points missing) and the spectral path at 1024².
//!
//! Reading a 4096 × 4096 X3P (`read_file`): the target is ≤ 2 s.
//! The files are written once per run with `write_x3p` (z types D, f64,
//! and F, f32; Deflate, as the writer does) into Cargo's bench temporary
//! directory (`target/tmp/x3p_4096x4096_D.x3p`, `..._F.x3p`), and kept
//! there for timing the program (`kefric surface FILE`).
//!
//! `cargo bench -p ke-friction-bench --bench topography`
//! (`-- read_x3p` for the reading only)
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use ke_friction::topography::{read_file, write_x3p, Derivative, Detrend, ReadOptions, StatsOptions, Topography};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A rough map: a few sinusoids, white noise, a tilt and an offset
/// (heights of a few micrometres on a 1 µm grid).
fn map(n: usize, missing: f64) -> Topography {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let heights = (0..n * n)
        .map(|k| {
            if rng.gen::<f64>() < missing {
                return f64::NAN;
            }
            let (x, y) = ((k % n) as f64, (k / n) as f64);
            1e-3 + 1e-9 * (x + 0.5 * y)
                + 1e-6 * ((x * 0.05).sin() + 0.5 * (y * 0.11 + x * 0.03).cos() + 0.2 * (x * 0.7).sin())
                + 2e-7 * (rng.gen::<f64>() - 0.5)
        })
        .collect();
    Topography::map(heights, n, n, 1e-6, 1.2e-6).expect("a valid map")
}

fn bench_stats(c: &mut Criterion) {
    let mut group = c.benchmark_group("topography");
    group.sample_size(10);
    let default = StatsOptions::default();
    for n in [4096, 1024] {
        let t = map(n, 0.0);
        group.bench_function(format!("stats_{n}x{n}"), |b| {
            b.iter(|| black_box(black_box(&t).stats(&default).expect("stats")))
        });
    }
    let masked = map(4096, 0.01);
    group.bench_function("stats_4096x4096_1pct_missing", |b| {
        b.iter(|| black_box(black_box(&masked).stats(&default).expect("stats")))
    });
    let t = map(1024, 0.0);
    let spectral = StatsOptions {
        detrend: Detrend::Mean,
        derivative: Derivative::Spectral,
        lambda_s: None,
        lambda_c: None,
    };
    group.bench_function("spectral_1024x1024", |b| {
        b.iter(|| black_box(black_box(&t).stats(&spectral).expect("stats")))
    });
    group.finish();
}

fn bench_read_x3p(c: &mut Criterion) {
    let mut group = c.benchmark_group("topography");
    group.sample_size(10);
    let t = map(4096, 0.0);
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"));
    let options = ReadOptions::default();
    for z_type in ['D', 'F'] {
        let path = dir.join(format!("x3p_4096x4096_{z_type}.x3p"));
        write_x3p(&t, &path, z_type).expect("write the X3P file");
        let back = read_file(&path, &options).expect("read the X3P file");
        assert_eq!((back.nx(), back.ny()), (4096, 4096));
        group.bench_function(format!("read_x3p_4096x4096_{z_type}"), |b| {
            b.iter(|| black_box(read_file(black_box(&path), &options).expect("read")))
        });
    }
    group.finish();
}

criterion_group!(benches, bench_stats, bench_read_x3p);
criterion_main!(benches);
