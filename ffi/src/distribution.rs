//! The asperity heights' distribution of a kef_constants: the
//! `KEF_DIST_*` families, setting one (or measured heights), reading it.

use crate::constants::{kef_constants, named, update};
use crate::error::Failure;
use ke_friction::{Family, HeightDistribution};
use std::ffi::{c_char, c_int};

/// Height distribution family (kef_constants_set_distribution,
/// kef_constants_distribution): the paper's Gaussian, the default
/// (skewness 0, kurtosis 3).
pub const KEF_DIST_GAUSSIAN: c_int = 0;
/// Height distribution family: the Pearson system from skewness Sk and
/// kurtosis K (not excess: 3 for a Gaussian), admissible where
/// K > Sk² + 1, |Sk| <= 5 and K <= 100. Pearson(0, 3) is the Gaussian.
pub const KEF_DIST_PEARSON: c_int = 1;
/// Height distribution family: a standardised Weibull distribution of
/// skewness Sk in (-1.1395, 2]; its kurtosis follows from Sk.
pub const KEF_DIST_WEIBULL: c_int = 2;
/// Height distribution family: an empirical (kernel) density of measured
/// heights, set by kef_constants_set_heights (not by
/// kef_constants_set_distribution).
pub const KEF_DIST_EMPIRICAL: c_int = 3;

/// The families with a `KEF_DIST_*` constant (literals above, for
/// cbindgen and the Fortran module), by name. A family added to the core
/// without one is reached by name (kef_constants_set_distribution_named)
/// and by its core code.
const CONSTANTS: [(&str, c_int, Family); 4] = [
    ("KEF_DIST_GAUSSIAN", KEF_DIST_GAUSSIAN, Family::Gaussian),
    ("KEF_DIST_PEARSON", KEF_DIST_PEARSON, Family::Pearson),
    ("KEF_DIST_WEIBULL", KEF_DIST_WEIBULL, Family::Weibull),
    ("KEF_DIST_EMPIRICAL", KEF_DIST_EMPIRICAL, Family::Empirical),
];

/// The distribution of family `family` (a `KEF_DIST_*` code other than
/// [`KEF_DIST_EMPIRICAL`]) with `skewness` and `kurtosis` (the latter read
/// by [`KEF_DIST_PEARSON`] alone, neither by [`KEF_DIST_GAUSSIAN`]),
/// validated.
fn distribution(family: c_int, skewness: f64, kurtosis: f64) -> Result<HeightDistribution, Failure> {
    let known = u8::try_from(family).ok().and_then(Family::from_code);
    match known.map(|f| (f, HeightDistribution::of_family(f, skewness, kurtosis))) {
        Some((_, Some(d))) => Ok(d.validate().map(|()| d)?),
        Some((f, None)) => Err(Failure::argument(format!(
            "family {family} ({}) is set by kef_constants_set_heights",
            constant(f)
        ))),
        None => {
            // The families a code sets, from the core's list.
            let settable: Vec<String> = Family::ALL
                .into_iter()
                .filter(|f| HeightDistribution::of_family(*f, 0.0, 3.0).is_some())
                .map(|f| format!("{} ({})", constant(f), f.code()))
                .collect();
            let (last, rest) = settable.split_last().expect("a family set by its code");
            Err(Failure::argument(format!(
                "family {family} is unknown: must be {} or {last}",
                rest.join(", ")
            )))
        }
    }
}

/// A family as C code names it: its `KEF_DIST_*` constant, or (a family
/// without one) its name, for kef_constants_set_distribution_named.
fn constant(f: Family) -> String {
    match CONSTANTS.iter().find(|(_, _, family)| *family == f) {
        Some((name, _, _)) => (*name).to_string(),
        None => format!("\"{}\"", f.name()),
    }
}

/// The `KEF_DIST_*` code of a distribution: its family's core code.
fn family_code(d: &HeightDistribution) -> c_int {
    c_int::from(d.family_kind().code())
}

/// Writes the distribution's family, skewness and kurtosis.
fn describe(d: &HeightDistribution, family: &mut c_int, skewness: &mut f64, kurtosis: &mut f64) -> Result<(), Failure> {
    (*family, *skewness, *kurtosis) = (family_code(d), d.skewness(), d.kurtosis());
    Ok(())
}

/// Sets the asperity heights' distribution (MODEL.md §9) to `family`:
/// KEF_DIST_GAUSSIAN (the default; `skewness` and `kurtosis` ignored),
/// KEF_DIST_PEARSON (skewness Sk and kurtosis K, not excess: 3 for a
/// Gaussian; admissible where K > Sk² + 1, |Sk| <= 5, K <= 100) or
/// KEF_DIST_WEIBULL (skewness Sk in (-1.1395, 2]; `kurtosis` ignored: it
/// follows from Sk). Checked at once: KEF_ERR_DOMAIN for a value outside
/// its admissible region (the message names it and the bound, e.g.
/// "kurtosis = 1.2 is out of range: must be > skewness² + 1 ..."),
/// KEF_ERR_ARGUMENT for NaN or ±inf where it is read, an unknown family,
/// KEF_DIST_EMPIRICAL (see kef_constants_set_heights) or a NULL handle;
/// the handle is unchanged on failure.
///
/// # Safety
/// As kef_constants_set_beta.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_set_distribution(
    constants: *mut kef_constants,
    family: c_int,
    skewness: f64,
    kurtosis: f64,
) -> c_int {
    ffi!(constants => update(constants, |c| Ok(c.distribution(distribution(family, skewness, kurtosis)?))))
}

/// kef_constants_set_distribution with the family by its name, the
/// library's record name `distribution`: "gaussian", "pearson" or
/// "weibull" ("empirical" is set by kef_constants_set_heights).
/// KEF_ERR_ARGUMENT for NULL or an unknown name (the message lists the
/// names); otherwise as kef_constants_set_distribution.
///
/// # Safety
/// As kef_constants_set_beta; `family` NULL or a NUL-terminated string.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_set_distribution_named(
    constants: *mut kef_constants,
    family: *const c_char,
    skewness: f64,
    kurtosis: f64,
) -> c_int {
    ffi!(constants, family => update(constants, |c| {
        let code = family_code_of(named::<Family>(family)?);
        Ok(c.distribution(distribution(code, skewness, kurtosis)?))
    }))
}

/// The `KEF_DIST_*` code of a family: its core code.
fn family_code_of(family: Family) -> c_int {
    c_int::from(family.code())
}

/// Sets the asperity heights' distribution to the empirical (kernel)
/// density of `n` measured heights (any unit; NaN entries are skipped as
/// missing points): at least 100 finite values, not all equal, no ±inf.
/// The data are copied (the density is built at once; the array may be
/// freed after the call). KEF_ERR_DOMAIN for too few heights or constant
/// ones, KEF_ERR_ARGUMENT for an infinite height, a NULL handle, or
/// `heights` NULL with `n` > 0; the handle is unchanged on failure.
/// kef_constants_distribution then gives KEF_DIST_EMPIRICAL and the
/// heights' skewness and kurtosis.
///
/// # Safety
/// As kef_constants_set_beta; `heights` NULL or valid for `n` reads.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_set_heights(
    constants: *mut kef_constants,
    heights: *const f64,
    n: usize,
) -> c_int {
    ffi!(constants, heights[n] => update(constants, |c| Ok(c.distribution(HeightDistribution::empirical(heights)?))))
}

/// The asperity heights' distribution of `constants` (NULL: the default,
/// the Gaussian): its family into `*family` (a KEF_DIST_* code), its
/// skewness into `*skewness` and its kurtosis (not excess) into
/// `*kurtosis`: 0 and 3 for the Gaussian, the values set for Pearson, the
/// kurtosis its skewness implies for Weibull (2.717 at Sk = 0), the
/// heights' own for an empirical density. KEF_ERR_ARGUMENT for a NULL
/// output or outputs that alias each other (the three must be distinct;
/// no output written then).
///
/// # Safety
/// `constants` is NULL or a live kef_constants; the outputs NULL or
/// writable.
#[no_mangle]
pub unsafe extern "C" fn kef_constants_distribution(
    constants: *const kef_constants,
    family: *mut c_int,
    skewness: *mut f64,
    kurtosis: *mut f64,
) -> c_int {
    ffi!(constants, family, skewness, kurtosis => describe(&constants.distribution, family, skewness, kurtosis))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The C constants (literals, for cbindgen and the Fortran module) are
    /// the core's family codes.
    #[test]
    fn the_kef_dist_constants_are_the_core_family_codes() {
        for (name, c, family) in CONSTANTS {
            assert_eq!(c, c_int::from(family.code()), "{family}");
            assert_eq!(name, format!("KEF_DIST_{}", family.name().to_uppercase()));
            assert_eq!(constant(family), name);
        }
    }

    /// Every family of the core is named in C: by its constant or by its
    /// name (never a constant that does not exist).
    #[test]
    fn every_family_is_named_by_an_existing_constant_or_its_name() {
        for f in Family::ALL {
            let named = constant(f);
            let known = CONSTANTS.iter().any(|(name, _, _)| *name == named);
            assert!(known || named == format!("\"{}\"", f.name()), "{f}: {named}");
        }
    }
}
