//! A measured surface end to end (MODEL.md §10 → §1–2 → §4, §9):
//! `topography::Surface` → `Surface::params` → `Load::friction`, against
//! the independent reference `tools/surface_friction_reference.py`
//! (tests/data/surface_friction_reference.json): NumPy statistics of the
//! synthetic maps of `tools/surface_reference.py`, ψ, θ, β, ε* from fixed
//! materials in mpmath, and μ at F* = F/(A_n·H) from the 30-digit Gaussian
//! (`tools/reference.py`) and Pearson (`tools/nongaussian_reference.py`)
//! models.
use crate::common::{assert_rel, REFERENCE_REL};
use crate::topography_stats::synthetic;
use ke_friction::topography::{Derivative, Detrend, StatsOptions, Surface, Topography};
use ke_friction::{Family, Load, Materials, Model, Named};
use serde_json::Value;

/// Statistics against NumPy, and ψ, θ, β, ε* against mpmath from them.
const STATS_REL: f64 = 1e-12;

fn reference() -> Value {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/surface_friction_reference.json"
    );
    let text = std::fs::read_to_string(path).expect("tests/data/surface_friction_reference.json");
    serde_json::from_str(&text).expect("valid JSON")
}

fn num(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("{key} missing in {v}"))
}

fn options(case: &Value) -> StatsOptions {
    StatsOptions {
        detrend: match case["detrend"].as_str() {
            Some("plane") => Detrend::Plane,
            Some("line") => Detrend::Line,
            Some("mean") => Detrend::Mean,
            other => panic!("detrend {other:?}"),
        },
        derivative: match case["derivative"].as_str() {
            Some("fd") => Derivative::FiniteDifference,
            Some("spectral") => Derivative::Spectral,
            other => panic!("derivative {other:?}"),
        },
        ..StatsOptions::default()
    }
}

fn materials(m: &Value) -> Materials {
    Materials {
        e1: num(m, "e1"),
        nu1: num(m, "nu1"),
        e2: num(m, "e2"),
        nu2: num(m, "nu2"),
        hardness: num(m, "hardness"),
        delta_gamma: num(m, "delta_gamma"),
        epsilon: num(m, "epsilon"),
    }
}

/// The surface of a case, rebuilt from the generator.
fn surface(case: &Value) -> Surface {
    let (nx, ny) = (num(case, "nx") as usize, num(case, "ny") as usize);
    let z = synthetic(nx, ny, num(case, "seed") as u64, num(case, "missing"));
    let t = Topography::map(z, nx, ny, num(case, "dx"), num(case, "dy")).unwrap();
    Surface::new(t, options(case)).unwrap()
}

#[test]
fn a_synthetic_map_end_to_end_matches_the_reference() {
    let doc = reference();
    let m = materials(&doc["materials"]);
    let cases = doc["cases"].as_array().expect("cases");
    assert!(cases.len() >= 2);
    let mut worst = [0.0f64; 3]; // statistics and parameters, μ, h*
    let mut checked = 0;
    for case in cases {
        let name = case["name"].as_str().unwrap();
        let s = surface(case);
        // §10: the statistics, against NumPy.
        let (st, want) = (s.stats(), &case["stats"]);
        for (key, got) in [
            ("sigma", st.sigma),
            ("skewness", st.skewness),
            ("kurtosis", st.kurtosis),
            ("radius", st.radius),
            ("eta", st.eta),
            ("alpha", st.alpha),
            ("beta", st.beta),
            ("m2", st.m2),
            ("m4", st.m4),
        ] {
            let r = crate::common::rel(got, num(want, key));
            worst[0] = worst[0].max(r);
            assert_rel(&format!("{name} {key}"), got, num(want, key), STATS_REL);
        }
        // §1–2: the model's inputs, against mpmath.
        let pw = &case["params"];
        for distribution in ["gaussian", "pearson"] {
            let p = s
                .params(&m, s.distribution(Some(Family::parse(distribution).unwrap())).unwrap())
                .unwrap();
            for (key, got) in [
                ("psi", p.psi),
                ("theta", p.theta),
                ("beta", p.constants.beta),
                ("nu", p.constants.nu),
                ("eps_star", p.constants.eps_star),
            ] {
                let r = crate::common::rel(got, num(pw, key));
                worst[0] = worst[0].max(r);
                assert_rel(&format!("{name} {key}"), got, num(pw, key), STATS_REL);
            }
        }
        // β from the summits (ηRσ) and from the bandwidth (α) agree.
        assert_rel(
            &format!("{name} beta(alpha)"),
            num(pw, "beta_from_alpha"),
            num(pw, "beta"),
            1e-14,
        );
        // §4, §9: μ at F* = F/(A_n·H), and the SI results.
        let physical = s.physical(&m);
        for load in case["loads"].as_array().unwrap() {
            let (force, area) = (num(load, "force"), num(load, "area"));
            let l = Load::Force { force, area };
            assert_rel(
                &format!("{name} F*"),
                l.f_star(m.hardness).unwrap(),
                num(load, "f_star"),
                1e-15,
            );
            for distribution in ["gaussian", "pearson"] {
                let want = &load[distribution];
                let tag = format!("{name} {distribution} F = {force} N");
                let params = s
                    .params(&m, s.distribution(Some(Family::parse(distribution).unwrap())).unwrap())
                    .unwrap();
                let model = Model::new(params).unwrap();
                let fr = l.friction(&model, &physical).unwrap();
                let c = fr.contact;
                worst[1] = worst[1].max(crate::common::rel(fr.mu, num(want, "mu")));
                worst[2] = worst[2].max((c.h_star - num(want, "h_star")).abs());
                assert_rel(&format!("{tag} mu"), fr.mu, num(want, "mu"), REFERENCE_REL);
                assert_eq!(c.mu, Some(fr.mu), "{tag}");
                assert!((c.h_star - num(want, "h_star")).abs() < 1e-11, "{tag}: h* {}", c.h_star);
                assert_rel(&format!("{tag} F*"), c.f_star, num(load, "f_star"), 1e-11);
                assert_rel(&format!("{tag} P*"), c.p_star, num(want, "p_star"), REFERENCE_REL);
                assert_rel(&format!("{tag} Q*"), c.q_star, num(want, "q_star"), REFERENCE_REL);
                assert_rel(&format!("{tag} Fs*"), c.fs_star, num(want, "fs_star"), REFERENCE_REL);
                assert_rel(&format!("{tag} h"), fr.separation, num(want, "separation"), 1e-11);
                assert_rel(
                    &format!("{tag} Q"),
                    fr.friction_force.unwrap(),
                    num(want, "friction_force"),
                    REFERENCE_REL,
                );
                assert_eq!(fr.force, Some(force));
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 8, "two maps, two loads, two distributions");
    eprintln!(
        "surface friction: max relative error statistics/parameters {:.1e}, mu {:.1e}; max |dh*| {:.1e}",
        worst[0], worst[1], worst[2]
    );
}

#[test]
fn the_reference_maps_are_in_the_papers_range() {
    // The materials were chosen so that the maps land where the paper has
    // results: ψ in 0.5–8, θ in 1e-4–1e-2, F* ≤ 0.1.
    let doc = reference();
    for case in doc["cases"].as_array().unwrap() {
        let p = &case["params"];
        assert!((0.5..=8.0).contains(&num(p, "psi")), "{p}");
        assert!((1e-4..=1e-2).contains(&num(p, "theta")), "{p}");
        for load in case["loads"].as_array().unwrap() {
            assert!(num(load, "f_star") <= 0.1);
        }
    }
}
