//! The words of the CLI's flags, which the web page (`web/`) gives word
//! for word: a record field's flag, and the messages about inputs that go
//! together. One place for both front ends (the CLI's tests check the
//! words, the page's browser test checks it says the CLI's).

#[cfg(feature = "topography")]
use crate::topography::EvaluateError;
use crate::{Family, Materials};
use std::fmt::Display;

/// The flag of a record field: `--` and the name with `-` for `_`
/// (`delta_gamma` → `--delta-gamma`).
pub fn flag(field: &str) -> String {
    format!("--{}", field.replace('_', "-"))
}

/// The input to blame for a [`ParamError`](crate::ParamError) of
/// [`Params::from_physical`](crate::Params::from_physical) named `name`:
/// β's bound is the summit density's (`--density`), a derived parameter
/// out of range is the roughness' as a whole (`roughness`: what gave σ,
/// R and η, e.g. [`WITH_MATERIALS`]), any other the flag of its field.
pub fn param_flag(name: &str, roughness: &str) -> String {
    match name {
        n if n.starts_with("beta") => "--density".to_string(),
        "psi" | "theta" | "nu" | "eps_star" => roughness.to_string(),
        n => flag(n),
    }
}

/// What a measured surface with materials is called in messages.
pub const WITH_MATERIALS: &str = "the surface with these materials";

/// `flag` (a load or a distribution) given without the materials.
pub fn materials_needed(flag: &str) -> String {
    let all: Vec<String> = Materials::FIELDS.iter().map(|f| self::flag(f)).collect();
    format!("{flag}: needs the materials ({})", all.join(", "))
}

/// `missing` left out of the SI inputs `all` (flags) that go together.
fn missing_together(missing: &str, all: &[&str]) -> String {
    format!("{missing}: missing: the SI inputs go together ({})", all.join(", "))
}

/// The values of inputs that go together (`(flag, value)` pairs), in
/// order, or the message naming the first one left out (`--nu1:
/// missing: the SI inputs go together (…)`).
pub fn together(given: &[(&str, Option<f64>)]) -> Result<Vec<f64>, String> {
    if let Some((missing, _)) = given.iter().find(|(_, v)| v.is_none()) {
        let all: Vec<&str> = given.iter().map(|(f, _)| *f).collect();
        return Err(missing_together(missing, &all));
    }
    Ok(given.iter().map(|(_, v)| v.unwrap_or_default()).collect())
}

/// A surface whose heights the distribution `family` asks for (`None`:
/// the default) cannot take, `e` saying why; with a hint to the
/// empirical density unless that was asked for.
pub fn distribution_failure(e: impl Display, family: Option<Family>) -> String {
    let hint = if family == Some(Family::Empirical) {
        ""
    } else {
        " (try --distribution empirical)"
    };
    format!("--distribution: the surface's {e}{hint}")
}

/// Why a surface has no model inputs or friction
/// ([`Surface::evaluate`](crate::topography::Surface::evaluate)), in the
/// CLI's words: the step's flag (`load_flag`: `--force` or `--pressure`
/// for a load's failure) and the error; `family` is the distribution asked
/// for.
#[cfg(feature = "topography")]
pub fn evaluate_failure(e: &EvaluateError, family: Option<Family>, load_flag: &str) -> String {
    match e {
        EvaluateError::Distribution(e) => distribution_failure(e, family),
        EvaluateError::Params(e) => format!("{}: {e}", param_flag(e.name, WITH_MATERIALS)),
        EvaluateError::Model(e) => format!("{WITH_MATERIALS}: {e}"),
        EvaluateError::Load(e) => format!("{load_flag}: {e}"),
    }
}

/// `--lambda-s auto` or a reliability check without what gives the
/// cut-off.
pub const RELIABILITY_NEEDED: &str = "give --tip-radius or --resolution for the reliability cut-off";

/// `--lambda-s auto` where `--tip-radius` (m) distorts no scale of
/// `file`'s data, so the cut-off, and λs, is none: said as a warning, not
/// refused (issue 49). The data need no S-filter for that tip, and the
/// unfiltered result is the right one; an error would also fail a batch
/// of files of which some have a cut-off. The front ends print it beside
/// the result (the CLI on stderr, the page in its warnings, Python as a
/// `UserWarning`).
/// `names`: how the front end names λs and the tip radius (the CLI's
/// `("--lambda-s", "--tip-radius")`).
pub fn auto_without_cutoff(file: impl Display, names: (&str, &str), tip_radius: f64) -> String {
    let (lambda_s, tip) = names;
    format!(
        "{file}: {lambda_s} auto: {tip} {} m distorts no scale of these data (reliability cut-off: none): no S-filter applied (lambda_s = none)",
        crate::Shortest(tip_radius)
    )
}

/// The CLI's names of λs and the tip radius, for [`auto_without_cutoff`].
pub const LAMBDA_S_TIP_FLAGS: (&str, &str) = ("--lambda-s", "--tip-radius");

/// A file (`file`, as the front end names it) that gives no sampling
/// interval `name` (`dx` or `dy`).
pub fn no_interval(file: impl Display, name: &str) -> String {
    format!(
        "{file}: the file gives no sampling interval {name}: give --dx (and --dy for a map, if it differs), in --xy-unit"
    )
}

/// The instrument's reliability cut-off (m) on `t`: `resolution`
/// (`--resolution`) as given, or that of a scanning probe of tip radius
/// `tip_radius` (m, `--tip-radius`) with the safety factor
/// [`TIP_SAFETY_FACTOR`](crate::topography::TIP_SAFETY_FACTOR), `None`
/// when the data show no tip artefact; [`RELIABILITY_NEEDED`] without
/// either.
#[cfg(feature = "topography")]
pub fn reliability_cutoff(
    t: &crate::topography::Topography,
    resolution: Option<f64>,
    tip_radius: Option<f64>,
) -> Result<Option<f64>, String> {
    use crate::topography::{tip_reliability_cutoff, TIP_SAFETY_FACTOR};
    match (resolution, tip_radius) {
        (Some(r), _) => Ok(Some(r)),
        (None, Some(radius)) if !(radius.is_finite() && radius > 0.0) => Err(format!(
            "--tip-radius {} is out of range: must be > 0 (metres)",
            crate::Shortest(radius)
        )),
        (None, Some(radius)) => tip_reliability_cutoff(t, radius, TIP_SAFETY_FACTOR).map_err(|e| e.to_string()),
        (None, None) => Err(RELIABILITY_NEEDED.into()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_words_name_the_flags() {
        assert_eq!(flag("delta_gamma"), "--delta-gamma");
        assert_eq!(param_flag("beta (eta*R*sigma)", "x"), "--density");
        assert_eq!(param_flag("psi", WITH_MATERIALS), WITH_MATERIALS);
        assert_eq!(param_flag("e1", "x"), "--e1");
        assert_eq!(
            materials_needed("--force"),
            "--force: needs the materials (--e1, --nu1, --e2, --nu2, --hardness, --delta-gamma, --epsilon)"
        );
        assert_eq!(
            missing_together("--nu1", &["--e1", "--nu1"]),
            "--nu1: missing: the SI inputs go together (--e1, --nu1)"
        );
        assert_eq!(
            together(&[("--e1", Some(1.0)), ("--nu1", None)]),
            Err("--nu1: missing: the SI inputs go together (--e1, --nu1)".to_string())
        );
        assert_eq!(
            together(&[("--e1", Some(1.0)), ("--nu1", Some(0.3))]),
            Ok(vec![1.0, 0.3])
        );
        assert_eq!(
            distribution_failure("e", Some(Family::Empirical)),
            "--distribution: the surface's e"
        );
        assert!(distribution_failure("e", None).ends_with(" (try --distribution empirical)"));
    }
}
