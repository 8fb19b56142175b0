//! The words of the CLI's flags that are not a surface request's (the
//! SI inputs of `eval`, `params`, `law`): a record field's flag, and the
//! inputs that go together. A surface request's messages are the core's
//! ([`ke_friction::topography::RequestError`]), its inputs spelled by
//! [`crate::surface_args::spell`].

/// The flag of a record field: `--` and the name with `-` for `_`
/// (`delta_gamma` → `--delta-gamma`).
pub fn flag(field: &str) -> String {
    format!("--{}", field.replace('_', "-"))
}

/// The input to blame for a [`ParamError`](ke_friction::ParamError) of
/// [`Params::from_physical`](ke_friction::Params::from_physical) named
/// `name`: β's bound is the summit density's (`--density`), a derived
/// parameter out of range is the roughness' as a whole (`roughness`), any
/// other the flag of its field.
pub fn param_flag(name: &str, roughness: &str) -> String {
    match name {
        n if n.starts_with("beta") => "--density".to_string(),
        "psi" | "theta" | "nu" | "eps_star" => roughness.to_string(),
        n => flag(n),
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_words_name_the_flags() {
        assert_eq!(flag("delta_gamma"), "--delta-gamma");
        assert_eq!(param_flag("beta (eta*R*sigma)", "x"), "--density");
        assert_eq!(param_flag("psi", "the surface"), "the surface");
        assert_eq!(param_flag("e1", "x"), "--e1");
        assert_eq!(param_flag("sigma", "x"), "--sigma");
        assert_eq!(
            together(&[("--e1", Some(1.0)), ("--nu1", None)]),
            Err("--nu1: missing: the SI inputs go together (--e1, --nu1)".to_string())
        );
        assert_eq!(
            together(&[("--e1", Some(1.0)), ("--nu1", Some(0.3))]),
            Ok(vec![1.0, 0.3])
        );
    }
}
