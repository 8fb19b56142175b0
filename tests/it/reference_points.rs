//! Agreement with an independent 30-digit mpmath implementation
//! (`tools/reference.py generate`) at random points nobody picked by hand:
//! default and non-default constants, both fits, both models, h* and F*.
use crate::common::{assert_rel, REFERENCE_REL};
use ke_friction::{Fit, Model, ModelKind, Params};
use serde_json::Value;

fn points() -> Vec<Value> {
    let text = include_str!("../data/reference_points.json");
    let doc: Value = serde_json::from_str(text).expect("reference_points.json parses");
    doc["points"].as_array().expect("points array").clone()
}

fn num(p: &Value, key: &str) -> f64 {
    p[key].as_f64().unwrap_or_else(|| panic!("{key} missing in {p}"))
}

/// Absolute floor for quantities that are zero or nearly so relative to
/// the others of the same point (e.g. Fs* when θ is tiny): a relative
/// error of 1e-9 of F* is what matters for μ.
fn check(tag: &str, got: f64, want: f64, scale: f64) {
    if (got - want).abs() <= 1e-12 * scale {
        return;
    }
    assert_rel(tag, got, want, REFERENCE_REL);
}

#[test]
fn model_agrees_with_mpmath_at_random_points() {
    let mut checked = 0;
    for p in points().iter().filter(|p| p.get("model").is_some()) {
        let kind = if p["model"] == "ceb" {
            ModelKind::CebType
        } else {
            ModelKind::KogutEtsion
        };
        let fit = if p["fit"] == "as-printed" {
            Fit::AsPrinted
        } else {
            Fit::Consistent
        };
        let params = Params::new(num(p, "psi"), num(p, "theta"))
            .beta(num(p, "beta"))
            .nu(num(p, "nu"))
            .eps_star(num(p, "eps_star"))
            .fit(fit)
            .kind(kind);
        let model = Model::new(params).unwrap();
        let c = if p["mode"] == "f" {
            let c = model.at_f_star(num(p, "f_star")).unwrap();
            assert!((c.h_star - num(p, "h_star")).abs() < 1e-11, "h* {} vs {p}", c.h_star);
            c
        } else {
            model.at_h_star(num(p, "h_star")).unwrap()
        };
        let tag = format!("{p}");
        let scale = num(p, "p_star").abs().max(num(p, "fs_star").abs());
        check(&format!("P* at {tag}"), c.p_star, num(p, "p_star"), scale);
        check(&format!("Fs* at {tag}"), c.fs_star, num(p, "fs_star"), scale);
        check(&format!("Q* at {tag}"), c.q_star, num(p, "q_star"), scale);
        check(&format!("F* at {tag}"), c.f_star, num(p, "f_star"), scale);
        match (c.mu, p["mu"].as_f64()) {
            (Some(got), Some(want)) => assert_rel(&format!("μ at {tag}"), got, want, REFERENCE_REL),
            (None, None) => {}
            (got, _) => panic!("μ = {got:?} at {tag}"),
        }
        checked += 1;
    }
    assert!(checked >= 50, "only {checked} reference points");
}
