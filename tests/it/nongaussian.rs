//! Non-Gaussian asperity heights (MODEL.md §9): the model against the
//! independent mpmath reference (`tools/nongaussian_reference.py`), the
//! Gaussian reduction, curves and tables for a Pearson distribution, and
//! bad input.
use crate::common::rel;
use ke_friction::build::{build, BuildOptions, Precision};
use ke_friction::{Constants, Curve, Family, HeightDistribution, Model, Params, Table, CURVE_ACCURACY};
use serde_json::Value;

fn model(psi: f64, theta: f64, d: HeightDistribution) -> Model {
    Model::new(Constants::default().distribution(d).at(psi, theta).unwrap()).unwrap()
}

fn mu(m: &Model, f_star: f64) -> f64 {
    m.at_f_star(f_star).unwrap().mu.unwrap()
}

/// 39 points across the (Sk, K) box, every Pearson type (J-shaped type I,
/// both sides of the gamma line and of the type-V line), Weibull and the
/// Gaussian, to ≤ 1e-9 relative (measured: ~1e-14).
#[test]
fn mu_matches_the_independent_reference_across_the_box() {
    let doc: Value = serde_json::from_str(include_str!("../data/nongaussian_reference.json")).unwrap();
    let points = doc.as_array().unwrap();
    assert!(points.len() >= 39);
    let mut worst = (0.0f64, String::new());
    for p in points {
        let f = |k: &str| p[k].as_f64().unwrap();
        let dist = match p["distribution"].as_str().unwrap() {
            "gaussian" => HeightDistribution::GAUSSIAN,
            "pearson" => HeightDistribution::pearson(f("skewness"), f("kurtosis")).unwrap(),
            "weibull" => HeightDistribution::weibull(f("skewness")).unwrap(),
            other => panic!("unknown distribution {other}"),
        };
        if let Some(t) = p["pearson_type"].as_str() {
            assert_eq!(dist.density().unwrap().pearson_type().unwrap().name(), t, "{p}");
        }
        let c = model(f("psi"), f("theta"), dist).at_f_star(f("f_star")).unwrap();
        let e = rel(c.mu.unwrap(), f("mu")).max(rel(c.h_star, f("h_star")));
        if e > worst.0 {
            worst = (e, p.to_string());
        }
    }
    eprintln!("worst {:e} at {}", worst.0, worst.1);
    assert!(worst.0 <= 1e-9, "worst {:e} at {}", worst.0, worst.1);
}

/// The numbers: ψ = 1, θ = 0.001, F* = 1e-4.
#[test]
fn peaked_and_skewed_heights_change_mu_by_factors() {
    let at = |d| mu(&model(1.0, 1e-3, d), 1e-4);
    let gauss = at(HeightDistribution::GAUSSIAN);
    assert!(rel(gauss, 0.7567111956) < 1e-9);
    assert!(rel(at(HeightDistribution::pearson(0.0, 8.0).unwrap()), 0.2529016383) < 1e-9);
    assert!(rel(at(HeightDistribution::pearson(-0.5, 3.375).unwrap()), 1.004869931) < 1e-9);
    // Pearson(0, 3) is the Gaussian, bit for bit.
    assert_eq!(at(HeightDistribution::pearson(0.0, 3.0).unwrap()), gauss);
}

/// The general integrator (every node through the Pearson closed forms)
/// next to the Gaussian one: a Pearson distribution 1e-9 away from the
/// normal point moves μ by ~1e-9, no more.
#[test]
fn the_general_integrator_reduces_to_the_gaussian_one() {
    for (psi, theta, f_star) in [
        (0.5, 0.0, 1e-3),
        (1.0, 1e-3, 1e-4),
        (2.0, 3e-3, 0.03),
        (4.0, 1e-4, 1e-5),
    ] {
        let gauss = mu(&model(psi, theta, HeightDistribution::GAUSSIAN), f_star);
        for (sk, k) in [(1e-9, 3.0), (0.0, 3.0 + 1e-9), (0.0, 3.0 - 1e-9), (-1e-9, 3.0 + 1e-9)] {
            let near = mu(&model(psi, theta, HeightDistribution::pearson(sk, k).unwrap()), f_star);
            assert!(rel(near, gauss) < 2e-8, "({sk}, {k}) at psi {psi}: {near} vs {gauss}");
        }
    }
}

/// Curves from a non-Gaussian model keep the curve's accuracy contract.
/// (A density bounded below is not smooth where the contact plane passes
/// its lower end — F* ≈ 0.055 for the J-shaped (0.8, 2.5) at ψ = 1 — and a
/// curve across that point is refused with an accuracy error.)
#[test]
fn curves_from_pearson_and_weibull_models_meet_the_contract() {
    for (d, hi) in [
        (HeightDistribution::pearson(0.0, 8.0).unwrap(), 0.1),
        (HeightDistribution::pearson(0.8, 2.5).unwrap(), 0.04),
        (HeightDistribution::weibull(-0.5).unwrap(), 0.1),
    ] {
        let m = model(1.0, 1e-3, d.clone());
        let curve = Curve::from_model(&m, 1e-5, hi).unwrap();
        for i in 0..60 {
            let f = 1e-5 * (hi / 1e-5f64).powf((i as f64 + 0.37) / 60.0);
            let want = mu(&m, f);
            let got = curve.mu(f).unwrap();
            assert!(rel(got, want) <= CURVE_ACCURACY, "{d:?} at F* = {f}: {got} vs {want}");
        }
    }
}

/// A J-shaped density whose μ(F*) is not smooth at a load inside the range
/// (its infinite end meets a regime boundary of the laws there, near
/// F* = 0.03 here): the curve splits the few cells around that load and
/// meets the contract there too, against direct integration at loads
/// crowded around it (measured: 8.5e-7 at build time, ≤ 9.0e-7 at the
/// 600 loads below); batches give what single lookups give.
#[test]
fn a_curve_across_a_j_shaped_end_splits_its_cells_there() {
    let m = model(0.5, 1e-3, HeightDistribution::pearson(0.8, 2.5).unwrap());
    let curve = Curve::from_model(&m, 1e-3, 0.1).unwrap();
    assert!(curve.max_error() <= CURVE_ACCURACY, "{curve:?}");
    let loads: Vec<f64> = (0..600)
        .map(|i| {
            let u = (i as f64 + 0.5) / 200.0;
            match i / 200 {
                0 => 1e-3 * 100f64.powf(u),
                1 => 0.0299 + 2e-4 * u,
                _ => 0.03 * (1.0 + 1e-6 * (u - 0.5)),
            }
        })
        .collect();
    let mut worst = (0.0f64, 0.0);
    for &f in &loads {
        let e = rel(curve.mu(f).unwrap(), mu(&m, f));
        if e > worst.0 {
            worst = (e, f);
        }
    }
    eprintln!("worst {:e} at {}", worst.0, worst.1);
    assert!(worst.0 <= 2.0 * CURVE_ACCURACY, "{worst:?}");
    let mut batch = vec![0.0; loads.len()];
    curve.mu_batch(&loads, &mut batch).unwrap();
    for (f, b) in loads.iter().zip(&batch) {
        assert_eq!(b.to_bits(), curve.mu(*f).unwrap().to_bits(), "F* = {f}");
    }
}

/// A kernel density of Gaussian samples gives about the Gaussian μ, and
/// its moments are exactly standardised.
#[test]
fn an_empirical_density_of_gaussian_heights_is_close_to_the_gaussian() {
    // Deterministic normal samples by the inverse CDF on a stratified grid.
    let n = 20_000;
    let heights: Vec<f64> = (0..n)
        .map(|i| {
            let u = (i as f64 + 0.5) / n as f64;
            inverse_normal(u) * 3e-7 + 1e-6
        })
        .collect();
    let d = HeightDistribution::empirical(&heights).unwrap();
    let [m0, mean, var, _, _] = d.density().unwrap().moments();
    assert!((m0 - 1.0).abs() < 1e-10 && mean.abs() < 1e-10 && (var - 1.0).abs() < 1e-9);
    let m = model(1.0, 1e-3, d);
    let gauss = model(1.0, 1e-3, HeightDistribution::GAUSSIAN);
    for f in [1e-3, 1e-2] {
        assert!(rel(mu(&m, f), mu(&gauss, f)) < 0.03, "F* = {f}");
    }
}

/// Acklam's rational approximation of the normal quantile (1e-9 relative).
#[allow(clippy::excessive_precision)]
fn inverse_normal(p: f64) -> f64 {
    let a = [
        -3.969683028665376e1,
        2.209460984245205e2,
        -2.759285104469687e2,
        1.383577518672690e2,
        -3.066479806614716e1,
        2.506628277459239,
    ];
    let b = [
        -5.447609879822406e1,
        1.615858368580409e2,
        -1.556989798598866e2,
        6.680131188771972e1,
        -1.328068155288572e1,
    ];
    let c = [
        -7.784894002430293e-3,
        -3.223964580411365e-1,
        -2.400758277161838,
        -2.549732539343734,
        4.374664141464968,
        2.938163982698783,
    ];
    let d = [
        7.784695709041462e-3,
        3.224671290700398e-1,
        2.445134137142996,
        3.754408661907416,
    ];
    let tail = |q: f64| {
        (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5])
            / ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0)
    };
    if p < 0.02425 {
        tail((-2.0 * p.ln()).sqrt())
    } else if p > 1.0 - 0.02425 {
        -tail((-2.0 * (1.0 - p).ln()).sqrt())
    } else {
        let q = p - 0.5;
        let r = q * q;
        (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q
            / (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0)
    }
}

/// A table for a Pearson distribution records it (format version 2),
/// answers like its model, and is told apart from a Gaussian one; a
/// Gaussian table is still version 1.
#[test]
fn a_pearson_table_records_its_distribution() {
    let d = HeightDistribution::pearson(-0.5, 3.375).unwrap();
    let options = BuildOptions {
        nodes: [9, 9, 13],
        psi: (0.8, 2.0),
        theta: (0.0, 0.002),
        f_star: (1e-4, 0.05),
        samples: 100,
        tolerance: 0.05,
        precision: Precision::F64,
        constants: Constants::default().distribution(d.clone()),
        ..BuildOptions::default()
    };
    let bytes = build(&options, &()).unwrap().bytes;
    assert_eq!(bytes[8..12], 2u32.to_le_bytes());
    let table = Table::from_bytes(&bytes).unwrap();
    assert_eq!(table.domain().constants.distribution, d);
    let exact = mu(&model(1.3, 1e-3, d), 3e-3);
    assert!(rel(table.mu(1.3, 1e-3, 3e-3).unwrap(), exact) < 0.05);
    let json = serde_json::to_value(table.info()).unwrap();
    assert_eq!(json["distribution"], "pearson");
    assert_eq!(json["kurtosis"], 3.375);
    assert_eq!(
        Table::embedded().domain().constants.distribution,
        HeightDistribution::GAUSSIAN
    );
    assert_eq!(include_bytes!("../../tables/default.kft")[8..12], 1u32.to_le_bytes());
}

/// Inadmissible distributions are errors naming the bound, never panics.
#[test]
fn bad_distributions_are_refused_naming_the_bound() {
    for (sk, k, name) in [
        (0.5, 1.25, "kurtosis"),
        (0.0, 1.0, "kurtosis"),
        (f64::NAN, 3.0, "skewness"),
        (0.0, f64::NAN, "kurtosis"),
        (0.0, f64::INFINITY, "kurtosis"),
        (9.0, 100.0, "skewness"),
    ] {
        let e = HeightDistribution::pearson(sk, k).unwrap_err();
        assert_eq!(e.name, name, "({sk}, {k})");
        let p = Params::new(1.0, 1e-3).distribution(HeightDistribution::Pearson(ke_friction::Pearson {
            skewness: sk,
            kurtosis: k,
        }));
        assert!(Model::new(p).is_err());
    }
    assert!(HeightDistribution::pearson(0.5, 1.2500001).is_ok());
    for sk in [-1.14, 2.01, f64::NAN] {
        assert_eq!(HeightDistribution::weibull(sk).unwrap_err().name, "skewness");
    }
    assert!(HeightDistribution::empirical(&[1.0; 500])
        .unwrap_err()
        .to_string()
        .contains("constant"));
    assert!(HeightDistribution::empirical(&(0..99).map(f64::from).collect::<Vec<_>>()).is_err());
    let mut h: Vec<f64> = (0..200).map(f64::from).collect();
    h[3] = f64::INFINITY;
    assert!(HeightDistribution::empirical(&h).is_err());
    h[3] = f64::NAN; // a missing point is skipped
    assert_eq!(HeightDistribution::empirical(&h).unwrap().family(), "empirical");
    let options = BuildOptions {
        constants: Constants::default().distribution(HeightDistribution::empirical(&h[..150]).unwrap()),
        ..BuildOptions::default()
    };
    assert!(options.validate().unwrap_err().to_string().contains("empirical"));
}

/// MODEL.md §9's literature statements, at single points (the full scans
/// are `kefric validate`'s second section): Tayebi & Polycarpou's "high
/// kurtosis and positive skewness lower μ" holds at ψ = 1, θ = 1e-3,
/// F* = 1e-4; negative skewness raises μ at light load, and at ψ = 2 the
/// ratio reverses below 1 at F* = 0.1 (it crosses near F* ≈ 0.067).
#[test]
fn literature_statements_hold_at_light_load_and_one_reverses_near_0_07() {
    use ke_friction::paper::nongaussian::tayebi_ratio;
    let r = tayebi_ratio(1.0, 1e-3, 1e-4).unwrap();
    assert!(r < 1.0, "mu(0.5, 5)/mu_G = {r}");
    let neg = model(2.0, 1e-3, HeightDistribution::pearson(-0.5, 3.375).unwrap());
    let gauss = model(2.0, 1e-3, HeightDistribution::GAUSSIAN);
    let ratio = |f: f64| mu(&neg, f) / mu(&gauss, f);
    assert!(
        ratio(1e-4) > ratio(0.05) && ratio(0.05) > 1.0,
        "{} {}",
        ratio(1e-4),
        ratio(0.05)
    );
    assert!(ratio(0.1) < 1.0, "{}", ratio(0.1));
    let statements = ke_friction::paper::nongaussian::nongaussian_statements().unwrap();
    assert_eq!(statements.len(), 18);
    // Chilamakuri & Bhushan: K < 3 (and negative Sk) raise μ at light
    // loads by 1.3× to 14×, more so at larger ψ; the gain reverses near
    // F* = 0.01–0.05 except for (−0.5, 2.5) at ψ = 1.
    for s in &statements[10..] {
        assert!(s.value > 1.25, "{}: {}", s.paper, s.computed);
        assert!(s.computed.contains("larger at the lighter load"), "{}", s.computed);
    }
    assert!(statements[17].value > statements[14].value);
}

/// A U-shaped bounded density (Sk = 1, K = 2.5): every solved load is the
/// load asked for (a derivative that is off at the ends' kinks must not
/// end the search early).
#[test]
fn solved_loads_are_the_loads_asked_for_with_a_u_shaped_density() {
    let m = model(1.0, 1e-3, HeightDistribution::pearson(1.0, 2.5).unwrap());
    for f in [1e-4, 1e-3, 0.01, 0.03, 0.04] {
        let c = m.at_f_star(f).unwrap();
        assert!(rel(c.f_star, f) < 1e-9, "asked {f}, got {}", c.f_star);
    }
    // Near F* = 0.1 the plane passes the upper end, where the density is
    // infinite and F*(h*) has an infinite slope: h* to the last bit still
    // leaves F* ~1e-6 off.
    let c = m.at_f_star(0.1).unwrap();
    assert!(rel(c.f_star, 0.1) < 1e-5, "got {}", c.f_star);
}

/// The front ends' rules for a distribution's arguments, in one place.
#[test]
fn the_arguments_of_a_distribution_follow_one_set_of_rules() {
    use HeightDistribution as D;
    let heights: Vec<f64> = (0..200).map(|i| f64::from(i % 17)).collect();
    assert_eq!(D::from_arguments(None, None, None, None).unwrap(), D::GAUSSIAN);
    assert_eq!(
        D::from_arguments(None, Some(-0.5), None, None).unwrap(),
        D::pearson(-0.5, 3.0).unwrap()
    );
    assert_eq!(
        D::from_arguments(None, None, None, Some(&heights)).unwrap().family(),
        "empirical"
    );
    let weibull = D::weibull(0.3).unwrap();
    let implied = weibull.kurtosis();
    assert_eq!(
        D::from_arguments(Some(Family::Weibull), Some(0.3), Some(implied), None).unwrap(),
        weibull
    );
    for (family, sk, k, h, name) in [
        (Some(Family::Gaussian), Some(0.3), None, None, "skewness"),
        (Some(Family::Weibull), None, Some(3.0), None, "kurtosis"),
        (Some(Family::Pearson), None, None, Some(&heights[..]), "heights"),
        (Some(Family::Empirical), None, None, None, "heights"),
        (None, Some(0.1), None, Some(&heights[..]), "skewness"),
        (None, Some(0.5), Some(1.2), None, "kurtosis"),
        (None, None, None, Some(&heights[..50]), "heights"),
    ] {
        let e = D::from_arguments(family, sk, k, h).unwrap_err();
        assert_eq!(e.name(), name, "{e}");
        assert!(e.to_string().starts_with(name), "{e}");
    }
}

/// Equality is as distributions: Pearson(0, 3) is the Gaussian.
#[test]
fn pearson_0_3_equals_the_gaussian() {
    assert_eq!(
        HeightDistribution::pearson(0.0, 3.0).unwrap(),
        HeightDistribution::GAUSSIAN
    );
    assert_ne!(
        HeightDistribution::pearson(0.0, 3.5).unwrap(),
        HeightDistribution::GAUSSIAN
    );
    assert_ne!(
        HeightDistribution::pearson(0.0, 3.0).unwrap(),
        HeightDistribution::weibull(0.0).unwrap()
    );
}

/// dF*/dh* from `Model::force` against a five-point difference of F* for
/// densities with ends (J- and U-shaped type I, gamma, Weibull), a power
/// tail and measured heights, on both sides of where the contact plane
/// passes a support end.
#[test]
fn the_force_slope_matches_a_difference_of_the_force() {
    let heights: Vec<f64> = (0..5000)
        .map(|i| inverse_normal((i as f64 + 0.5) / 5000.0).powi(3))
        .collect();
    for d in [
        HeightDistribution::pearson(0.8, 2.5).unwrap(),
        HeightDistribution::pearson(1.0, 2.5).unwrap(),
        HeightDistribution::pearson(-0.5, 3.375).unwrap(),
        HeightDistribution::pearson(0.0, 8.0).unwrap(),
        HeightDistribution::weibull(0.5).unwrap(),
        HeightDistribution::empirical(&heights).unwrap(),
    ] {
        let m = model(1.0, 1e-3, d.clone());
        for h in [-1.5, -0.5, 0.2, 0.9, 1.6, 2.5, 3.5] {
            let (f, df) = m.force(h);
            if f.is_nan() || f.abs() <= 1e-12 {
                continue;
            }
            let step = 1e-3;
            let at = |k: f64| m.force(h + k * step).0;
            let want = (at(-2.0) - 8.0 * at(-1.0) + 8.0 * at(1.0) - at(2.0)) / (12.0 * step);
            assert!(
                (df - want).abs() <= 1e-6 * want.abs() + 1e-12,
                "{d} at h* = {h}: {df:e} vs {want:e}"
            );
        }
    }
}

/// Heavy tails at a heavy load (ψ = 0.5, F* = 0.1, the plane below the
/// mean): the laws' kinks at ω = ω_c·{1, 6, 110} then lie far out in the
/// tail, where panels must stay narrow enough. The references are
/// tools/nongaussian_reference.py's, at 20 digits:
/// `python3 -c "import nongaussian_reference as ng; print(ng.solve_mu(0.5, 0.001, 'pearson', 0.0, K, 0.1, dps=20))"`
/// (in tools/). Panels twice as wide in the tail put μ 7e-8 and 2e-7 off here.
#[test]
fn heavy_tails_at_a_heavy_load_match_the_reference() {
    for (kurtosis, mu, h_star) in [
        (8.0, 0.6117539137061359, -1.2551816152691997),
        (20.0, 0.6119485844777182, -1.2561972702900288),
    ] {
        let c = model(0.5, 0.001, HeightDistribution::pearson(0.0, kurtosis).unwrap())
            .at_f_star(0.1)
            .unwrap();
        assert!(
            rel(c.mu.unwrap(), mu) < 1e-10,
            "K = {kurtosis}: mu {} against {mu}",
            c.mu.unwrap()
        );
        assert!(
            rel(c.h_star, h_star) < 1e-10,
            "K = {kurtosis}: h* {} against {h_star}",
            c.h_star
        );
    }
}

/// Ends where the density vanishes like `t^power` with power above 2
/// (types I, II, III, VI) take their Gauss–Jacobi rules: F* and Q* with
/// the contact plane 0.3 above and 0.3 below the lower end of the support
/// (ψ = 1, θ = 0.001; d* − z*_end = ±0.3 roughly), against
/// `tools/nongaussian_reference.py`'s `Model.evaluate` at 30 digits
/// (measured: ≤ 1.4e-15).
#[test]
fn bounded_supports_past_their_lower_end_match_the_reference() {
    for (sk, k, h, f_star, q_star) in [
        (0.3, 2.7, -1.183783049366876, 0.18202617904846044, 0.03206122489594811),
        (0.3, 2.7, -1.783783049366876, 0.2488853219491786, 0.027087542767599775),
        (0.0, 2.5, -1.7136757947063124, 0.2408194856546825, 0.02712796328994972),
        (0.0, 2.5, -2.3136757947063122, 0.3134749463373211, 0.018323883372292134),
        (-0.4, 2.9, -4.687168005011163, 0.6465046261776232, 0.0002609259998659567),
        (
            -0.4,
            2.9,
            -5.2871680050111625,
            0.7344399686864634,
            3.799253070549427e-05,
        ),
        (
            0.5,
            3.375,
            -2.5513981345379335,
            0.3436942972236967,
            0.015200956095298033,
        ),
        (0.5, 3.375, -3.151398134537933, 0.4241626297042263, 0.006037142322942856),
        (0.8, 4.1, -1.5414051247550478, 0.22084730867912608, 0.030946444495688986),
        (0.8, 4.1, -2.141405124755048, 0.2916646365559511, 0.023008379308975552),
    ] {
        let c = model(1.0, 1e-3, HeightDistribution::pearson(sk, k).unwrap())
            .at_h_star(h)
            .unwrap();
        assert!(
            rel(c.f_star, f_star) < 1e-12,
            "({sk}, {k}) h* = {h}: F* {} against {f_star}",
            c.f_star
        );
        assert!(
            rel(c.q_star, q_star) < 1e-12,
            "({sk}, {k}) h* = {h}: Q* {} against {q_star}",
            c.q_star
        );
    }
}

/// Types IV and VII integrate all of a power tail in one panel of a
/// Gauss–Jacobi rule in `1/(z* − c)`: the plastic regime's upper tail
/// (in P*) and the non-contact adhesion's lower tail (in Fs*). P*, Fs*
/// and Q* at fixed h* against `tools/nongaussian_reference.py`'s
/// `Model.evaluate` at 30 digits, from ψ = 0.5 (the plastic regime far
/// out) to ψ = 8 (close to the contact plane), light and heavy loads
/// (measured: ≤ 7.6e-15).
#[test]
fn power_tails_in_one_panel_match_the_reference() {
    let mut worst = 0.0f64;
    for (sk, k, psi, theta, h, p, fs, q) in [
        (
            0.4,
            8.0,
            4.0,
            0.003,
            1.0,
            0.05936337020887216,
            0.0014180434290308624,
            0.00021960364555638145,
        ),
        (
            0.4,
            8.0,
            4.0,
            0.003,
            4.0,
            0.0007796869920161771,
            1.3300554799970413e-05,
            2.410870333906799e-06,
        ),
        (
            -0.8,
            5.0,
            0.5,
            0.001,
            -1.0,
            0.08712813138623565,
            0.0014738938365587053,
            0.05486504769254842,
        ),
        (
            0.0,
            8.0,
            2.0,
            0.002,
            6.0,
            5.7718287805743713e-05,
            8.052260590516022e-07,
            1.3742876600336935e-06,
        ),
        (
            0.8,
            4.0,
            1.0,
            0.003,
            2.5,
            0.002277056320214882,
            0.0002127899230275696,
            0.0010582099917574256,
        ),
        (
            -0.4,
            4.0,
            8.0,
            0.0005,
            0.5,
            0.17154772545389968,
            0.00020369759388862228,
            8.092809559470699e-06,
        ),
    ] {
        let c = model(psi, theta, HeightDistribution::pearson(sk, k).unwrap())
            .at_h_star(h)
            .unwrap();
        for (what, got, want) in [("P*", c.p_star, p), ("Fs*", c.fs_star, fs), ("Q*", c.q_star, q)] {
            let e = rel(got, want);
            worst = worst.max(e);
            assert!(
                e < 1e-12,
                "Sk = {sk}, K = {k}, psi = {psi}, h* = {h}: {what} {got:e} against {want:e} ({e:e})"
            );
        }
    }
    eprintln!("worst {worst:e}");
}

/// A law over the cusp of Sk = 5, K = 26.01 (F* = 1.46e-3) fails
/// saying why: the density is infinite at an end of its support.
#[test]
fn a_law_over_the_cusp_says_why_it_fails() {
    let c =
        ke_friction::Constants::default().distribution(ke_friction::HeightDistribution::pearson(5.0, 26.01).unwrap());
    let e = ke_friction::FrictionLaw::new(c.at(1.0, 0.001).unwrap(), 1e9, Some((1e5, 1e7)), Default::default())
        .expect_err("misses its accuracy")
        .to_string();
    assert!(
        e.contains("misses its accuracy") && e.contains("infinite at an end of its support"),
        "{e}"
    );
}
