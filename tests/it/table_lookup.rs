//! The default table: accuracy against direct integration, smoothness,
//! batch and threads, domain errors, and that it is exactly what the
//! builder makes.
use ke_friction::build::{build, BuildOptions};
use ke_friction::Precision;
use ke_friction::{LookupError, Model, Params, Table};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn table() -> &'static Table {
    Table::embedded()
}

/// A coarse (9³) table over the default domain, stored in f64: it runs
/// the portable kernel everywhere.
fn small_f64_table() -> Table {
    let options = BuildOptions {
        nodes: [9, 9, 9],
        samples: 200,
        tolerance: 0.5,
        precision: ke_friction::build::Precision::F64,
        ..BuildOptions::default()
    };
    Table::from_bytes(&build(&options, &()).unwrap().bytes).unwrap()
}

/// A random in-domain query, uniform in (ln ψ, θ, ln F*).
fn query(rng: &mut ChaCha8Rng) -> (f64, f64, f64) {
    let d = table().domain();
    let lerp_log = |(lo, hi): (f64, f64), u: f64| (lo.ln() + (hi.ln() - lo.ln()) * u).exp();
    (
        lerp_log(d.psi, rng.gen()),
        d.theta.0 + (d.theta.1 - d.theta.0) * rng.gen::<f64>(),
        lerp_log(d.f_star, rng.gen()),
    )
}

#[test]
fn the_committed_default_table_is_exactly_what_the_builder_writes() {
    let built = build(&BuildOptions::default(), &()).expect("default build");
    let committed = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/default.kft")).unwrap();
    assert!(
        built.bytes == committed,
        "tables/default.kft is stale: run `cargo run --release -- build` and commit it"
    );
    assert_eq!(Table::embedded_bytes(), &committed[..]);
}

#[test]
fn the_default_table_meets_its_tolerance_against_direct_integration() {
    let t = table();
    let tol = t.info().tolerance;
    assert!(tol <= 1e-4, "default tolerance {tol}");
    assert!(t.info().accuracy.max_rel <= tol);
    // Fresh points (not the builder's): random, plus the centres of cells.
    let mut rng = ChaCha8Rng::seed_from_u64(99);
    let mut points: Vec<(f64, f64, f64)> = (0..600).map(|_| query(&mut rng)).collect();
    let axes = t.axes();
    let d = t.domain();
    for _ in 0..600 {
        let centre = |k: usize, lo: f64, hi: f64, rng: &mut ChaCha8Rng| {
            let a = axes[k];
            let c_lo = a.scale.forward(lo);
            let cells = ((a.scale.forward(hi) - c_lo) / a.step).round() as usize;
            let i = rng.gen_range(0..cells);
            a.scale.inverse(c_lo + (i as f64 + 0.5) * a.step)
        };
        points.push((
            centre(0, d.psi.0, d.psi.1, &mut rng),
            centre(1, d.theta.0, d.theta.1, &mut rng),
            centre(2, d.f_star.0, d.f_star.1, &mut rng),
        ));
    }
    let mut worst = 0.0f64;
    for (p, th, f) in points {
        let exact = Model::new(Params::new(p, th))
            .unwrap()
            .at_f_star(f)
            .unwrap()
            .mu
            .unwrap();
        let got = t.mu(p, th, f).unwrap();
        worst = worst.max(((got - exact) / exact).abs());
    }
    assert!(worst <= tol, "worst relative error {worst:e} > tolerance {tol:e}");
}

#[test]
fn the_slope_matches_a_finite_difference_of_direct_integration() {
    let t = table();
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    for _ in 0..100 {
        let (p, th, f) = query(&mut rng);
        let f = f.clamp(2e-5, 0.05);
        let m = Model::new(Params::new(p, th)).unwrap();
        let h = 1e-4 * f;
        let fd = (m.at_f_star(f + h).unwrap().mu.unwrap() - m.at_f_star(f - h).unwrap().mu.unwrap()) / (2.0 * h);
        let (mu, slope) = t.mu_with_slope(p, th, f).unwrap();
        // ln μ is good to ~1e-4; its derivative in ln F* loses one order: compare
        // on the scale μ/F*, the natural size of ∂μ/∂F*.
        assert!(
            (slope - fd).abs() <= 2e-3 * mu / f,
            "ψ={p} θ={th} F*={f}: slope {slope:e} vs {fd:e}"
        );
    }
}

/// A probe across a node: axis, F*, the lookup below and above.
type Probe = (usize, f64, (f64, f64), (f64, f64));

/// Evaluates `lookup` a fraction `eps` of a node spacing below and above
/// random interior nodes on each axis.
fn across_nodes(eps: f64, lookup: impl Fn(f64, f64, f64) -> (f64, f64)) -> Vec<Probe> {
    let t = table();
    let axes = t.axes();
    let d = t.domain();
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let mut out = vec![];
    for _ in 0..300 {
        let (p, th, f) = query(&mut rng);
        for k in 0..3 {
            let a = axes[k];
            let (lo, hi) = d.ranges()[k];
            let c_lo = a.scale.forward(lo);
            let cells = ((a.scale.forward(hi) - c_lo) / a.step).round() as usize;
            let node = c_lo + rng.gen_range(1..cells) as f64 * a.step;
            let at = |c: f64| {
                let v = a.scale.inverse(c);
                let q = [(v, th, f), (p, v, f), (p, th, v)][k];
                (q.2, lookup(q.0, q.1, q.2))
            };
            let ((f_star, below), (_, above)) = (at(node - eps * a.step), at(node + eps * a.step));
            out.push((k, f_star, below, above));
        }
    }
    out
}

#[test]
fn the_interpolant_and_its_slope_are_continuous_across_cell_boundaries() {
    // The exact (f64) interpolant, a billionth of a spacing either side.
    for (k, f, (m0, s0), (m1, s1)) in across_nodes(1e-9, |p, t, f| table().mu_with_slope_portable(p, t, f).unwrap()) {
        assert!(
            ((m1 - m0) / m0).abs() < 1e-8,
            "μ jumps across axis {k} node: {m0} vs {m1}"
        );
        let scale = s0.abs().max(m0 / f);
        assert!(
            (s1 - s0).abs() < 1e-6 * scale,
            "slope jumps across axis {k} node: {s0} vs {s1}"
        );
    }
}

#[test]
fn lookups_are_continuous_across_cell_boundaries_to_within_f32_rounding() {
    // What `mu_with_slope` returns (the f32 kernel on AVX2 machines), 1e-4
    // of a spacing either side: μ and its slope change as the exact
    // interpolant's do, to within the kernel's rounding (a jump of the
    // size of the table's error, 4e-5, would fail).
    // Differences from the exact interpolant, relative to μ and to μ/F*.
    let deviation = |p, t, f| {
        let (m, s) = table().mu_with_slope(p, t, f).unwrap();
        let (me, se) = table().mu_with_slope_portable(p, t, f).unwrap();
        ((m - me) / me, (s - se) * f / me)
    };
    for (k, _, (d0, ds0), (d1, ds1)) in across_nodes(1e-4, deviation) {
        assert!((d1 - d0).abs() <= 1e-5, "μ jumps by {:e} across axis {k} node", d1 - d0);
        assert!(
            (ds1 - ds0).abs() <= 1e-4,
            "slope jumps by {:e} across axis {k} node",
            ds1 - ds0
        );
    }
}

#[test]
fn the_fast_kernel_stays_within_3e_6_of_the_exact_interpolant() {
    let t = table();
    let mut rng = ChaCha8Rng::seed_from_u64(23);
    let (mut worst, mut worst_slope) = (0.0f64, 0.0f64);
    for _ in 0..100_000 {
        let (p, th, f) = query(&mut rng);
        let (m, s) = t.mu_with_slope(p, th, f).unwrap();
        let (me, se) = t.mu_with_slope_portable(p, th, f).unwrap();
        assert_eq!(t.mu(p, th, f).unwrap(), m);
        assert_eq!(t.mu_portable(p, th, f).unwrap(), me);
        worst = worst.max((m / me - 1.0).abs());
        worst_slope = worst_slope.max((s - se).abs() / se.abs().max(me / f));
    }
    // The domain's corners, edge midpoints and centre, where rounding
    // could put a query a hair outside its cell.
    let d = t.domain();
    let three = |(lo, hi): (f64, f64)| [lo, 0.5 * (lo + hi), hi];
    for p in three(d.psi) {
        for th in three(d.theta) {
            for f in three(d.f_star) {
                let (m, me) = (t.mu(p, th, f).unwrap(), t.mu_portable(p, th, f).unwrap());
                worst = worst.max((m / me - 1.0).abs());
            }
        }
    }
    if !t.fast_kernel() {
        assert_eq!(
            (worst, worst_slope),
            (0.0, 0.0),
            "without the fast kernel, mu is mu_portable"
        );
    }
    assert!(worst <= 3e-6, "μ differs from the exact interpolant by {worst:e}");
    assert!(
        worst_slope <= 1e-4,
        "∂μ/∂F* differs from the exact interpolant's by {worst_slope:e}"
    );
}

/// A batch form checked against its scalar form (`key` gives a result's
/// bits): equal bit for bit on random queries and on lengths that are not
/// a multiple of the fast kernel's eight, and on a batch large enough
/// (20,000) for the fast kernel to read the coefficients through first; a
/// length mismatch is an error; a bad element in the first block, a later
/// one or the tail is reported by index, with the elements before it
/// written as if it were not there.
fn check_batch<T: Copy + Default>(
    batch: impl Fn(&[f64], &[f64], &[f64], &mut [T]) -> Result<(), LookupError>,
    single: impl Fn(f64, f64, f64) -> T,
    key: impl Fn(T) -> (u64, u64),
) {
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let q: Vec<(f64, f64, f64)> = (0..20_000).map(|_| query(&mut rng)).collect();
    let psi: Vec<f64> = q.iter().map(|x| x.0).collect();
    let theta: Vec<f64> = q.iter().map(|x| x.1).collect();
    let f: Vec<f64> = q.iter().map(|x| x.2).collect();
    let same = |out: &[T], upto: usize| {
        for j in 0..upto {
            assert_eq!(key(out[j]), key(single(psi[j], theta[j], f[j])), "element {j}");
        }
    };
    for len in [0, 1, 7, 9, 17, 1001, 1003, 20_000] {
        let mut out = vec![T::default(); len];
        batch(&psi[..len], &theta[..len], &f[..len], &mut out).unwrap();
        same(&out, len);
    }
    let mut out = vec![T::default(); q.len()];
    let err = batch(&psi, &theta, &f[..10], &mut out).unwrap_err();
    assert!(matches!(err, LookupError::LengthMismatch { f_star: 10, .. }));
    for (len, at) in [(1000, 7), (1000, 500), (1003, 1001), (13, 12), (20_000, 15_001)] {
        let mut bad = f[..len].to_vec();
        bad[at] = f64::NAN;
        let mut out = vec![T::default(); len];
        let err = batch(&psi[..len], &theta[..len], &bad, &mut out).unwrap_err();
        assert!(
            matches!(err, LookupError::BatchElement { index, name: "f_star", .. } if index == at),
            "{err}"
        );
        same(&out, at);
    }
}

/// Both batch forms on both kernels: the default (f32) table, which runs
/// the fast kernel on AVX2 machines, and an f64 table, which runs the
/// portable one.
#[test]
fn batch_lookups_equal_scalar_lookups() {
    let f64_table = small_f64_table();
    for t in [table(), &f64_table] {
        check_batch(
            |p, th, f, out| t.mu_batch(p, th, f, out),
            |p, th, f| t.mu(p, th, f).unwrap(),
            |m: f64| (m.to_bits(), 0),
        );
        check_batch(
            |p, th, f, out| t.mu_with_slope_batch(p, th, f, out),
            |p, th, f| t.mu_with_slope(p, th, f).unwrap(),
            |(m, s): (f64, f64)| (m.to_bits(), s.to_bits()),
        );
    }
}

#[test]
fn threads_sharing_one_table_get_the_single_threaded_results() {
    fn assert_send_sync<T: Send + Sync>() {}
    assert_send_sync::<Table>();
    let t = table();
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    let q: Vec<(f64, f64, f64)> = (0..2000).map(|_| query(&mut rng)).collect();
    let expected: Vec<u64> = q.iter().map(|&(p, th, f)| t.mu(p, th, f).unwrap().to_bits()).collect();
    std::thread::scope(|s| {
        for _ in 0..8 {
            s.spawn(|| {
                for (i, &(p, th, f)) in q.iter().enumerate() {
                    assert_eq!(t.mu(p, th, f).unwrap().to_bits(), expected[i]);
                }
            });
        }
    });
}

#[test]
fn out_of_domain_and_nan_queries_are_errors_naming_the_argument() {
    let t = table();
    let cases = [
        (0.49, 0.001, 0.01, "psi"),
        (8.01, 0.001, 0.01, "psi"),
        (f64::NAN, 0.001, 0.01, "psi"),
        (1.0, -1e-9, 0.01, "theta"),
        (1.0, 0.0101, 0.01, "theta"),
        (1.0, f64::INFINITY, 0.01, "theta"),
        (1.0, 0.001, 9e-6, "f_star"),
        (1.0, 0.001, 0.11, "f_star"),
        (1.0, 0.001, f64::NAN, "f_star"),
        (1.0, 0.001, -1.0, "f_star"),
    ];
    for (p, th, f, name) in cases {
        for err in [
            t.mu(p, th, f).unwrap_err(),
            t.mu_with_slope(p, th, f).unwrap_err(),
            t.h_star(p, th, f).unwrap_err(),
        ] {
            match err {
                LookupError::OutOfDomain { name: n, .. } => assert_eq!(n, name),
                other => panic!("{other:?}"),
            }
            assert!(err.to_string().starts_with(name), "{err}");
        }
    }
    // The corners themselves are in the domain.
    let d = t.domain();
    for p in [d.psi.0, d.psi.1] {
        for th in [d.theta.0, d.theta.1] {
            for f in [d.f_star.0, d.f_star.1] {
                assert!(t.mu(p, th, f).unwrap() > 0.0);
            }
        }
    }
}

#[test]
fn h_star_lookup_matches_direct_integration() {
    let t = table();
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    for _ in 0..200 {
        let (p, th, f) = query(&mut rng);
        let exact = Model::new(Params::new(p, th)).unwrap().at_f_star(f).unwrap().h_star;
        let got = t.h_star(p, th, f).unwrap();
        assert!((got - exact).abs() < 1e-4, "ψ={p} θ={th} F*={f}: h* {got} vs {exact}");
    }
}

#[test]
fn the_clamping_variant_takes_the_edge_value_and_still_rejects_nan() {
    let t = table();
    let d = t.domain();
    // Outside on every axis: the value at the nearest corner.
    let edge = t.mu(d.psi.1, d.theta.0, d.f_star.0).unwrap();
    assert_eq!(t.mu_clamped(100.0, -1.0, 1e-9).unwrap(), edge);
    // Inside: identical to `mu`.
    assert_eq!(t.mu_clamped(1.0, 0.001, 0.01).unwrap(), t.mu(1.0, 0.001, 0.01).unwrap());
    assert!(matches!(
        t.mu_clamped(1.0, f64::NAN, 0.01),
        Err(LookupError::OutOfDomain { name: "theta", .. })
    ));
}

#[test]
fn f32_tables_run_the_fast_kernel_where_the_cpu_has_avx2_and_f64_tables_the_exact_one() {
    // `--cfg ke_friction_portable` forces the portable kernel on x86-64.
    #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
    let avx2 = std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma");
    #[cfg(not(all(target_arch = "x86_64", not(ke_friction_portable))))]
    let avx2 = false;
    assert_eq!(table().fast_kernel(), avx2);
    let t = small_f64_table();
    assert!(t.info().precision == Precision::F64 && !t.fast_kernel());
    let mut rng = ChaCha8Rng::seed_from_u64(41);
    for _ in 0..100 {
        let (p, th, f) = query(&mut rng);
        assert_eq!(
            t.mu(p, th, f).unwrap().to_bits(),
            t.mu_portable(p, th, f).unwrap().to_bits()
        );
        assert_eq!(
            t.mu_with_slope(p, th, f).unwrap(),
            t.mu_with_slope_portable(p, th, f).unwrap()
        );
    }
}
