//! The registry of every range the library checks: one [`Bound`] each,
//! declared beside the type it bounds, listed here once so that tests walk
//! them all and front ends quote them ([`Bound::range`],
//! [`bound::help`](crate::bound::help)) instead of spelling a range.

use crate::bound::Bound;
#[cfg(feature = "builder")]
pub use crate::build::{
    verify::SAMPLES, F_STAR_END, GHOSTS, GHOST_F_STAR, GHOST_PSI, GHOST_THETA, GRID_NODES, GRID_POINTS, H_NODES,
    H_STAR, NODES, TOLERANCE,
};
pub use crate::distribution::{HEIGHTS, PEARSON_KURTOSIS, PEARSON_SKEWNESS, SD, WEIBULL_SKEWNESS};
#[cfg(feature = "plot")]
pub use crate::figures::SCALE;
pub use crate::gw::ALPHA_ADMISSIBLE;
pub use crate::law_table::{LAW_ROWS, LAW_TOLERANCE};
pub use crate::load::{AREA, FORCE, F_STAR, LOAD_COUNT};
pub use crate::params::{
    BETA, BETA_ADMISSIBLE, DENSITY, ENERGY, EPS_STAR, METRES, NU, NU2, PASCALS, PSI, THETA_AT_MOST, THETA_NON_NEGATIVE,
};
#[cfg(feature = "topography")]
pub use crate::topography::{DIFFERENCES, PER_DECADE, POINTS_ALONG, PSD_POINTS, VALID_POINTS};

/// Every bound, by its name in lower case (`beta` for [`BETA`]).
pub static ALL: &[(&str, &Bound)] = &[
    ("psi", &PSI),
    ("theta_non_negative", &THETA_NON_NEGATIVE),
    ("theta_at_most", &THETA_AT_MOST),
    ("beta", &BETA),
    ("beta_admissible", &BETA_ADMISSIBLE),
    ("nu", &NU),
    ("nu2", &NU2),
    ("eps_star", &EPS_STAR),
    ("pascals", &PASCALS),
    ("metres", &METRES),
    ("density", &DENSITY),
    ("energy", &ENERGY),
    ("alpha_admissible", &ALPHA_ADMISSIBLE),
    ("force", &FORCE),
    ("area", &AREA),
    ("f_star", &F_STAR),
    ("pearson_skewness", &PEARSON_SKEWNESS),
    ("pearson_kurtosis", &PEARSON_KURTOSIS),
    ("weibull_skewness", &WEIBULL_SKEWNESS),
    ("heights", &HEIGHTS),
    ("sd", &SD),
    ("load_count", &LOAD_COUNT),
    ("law_rows", &LAW_ROWS),
    ("law_tolerance", &LAW_TOLERANCE),
    #[cfg(feature = "topography")]
    ("per_decade", &PER_DECADE),
    #[cfg(feature = "topography")]
    ("points_along", &POINTS_ALONG),
    #[cfg(feature = "topography")]
    ("valid_points", &VALID_POINTS),
    #[cfg(feature = "topography")]
    ("differences", &DIFFERENCES),
    #[cfg(feature = "topography")]
    ("psd_points", &PSD_POINTS),
    #[cfg(feature = "plot")]
    ("scale", &SCALE),
    #[cfg(feature = "builder")]
    ("f_star_end", &F_STAR_END),
    #[cfg(feature = "builder")]
    ("nodes", &NODES),
    #[cfg(feature = "builder")]
    ("ghosts", &GHOSTS),
    #[cfg(feature = "builder")]
    ("h_star", &H_STAR),
    #[cfg(feature = "builder")]
    ("h_nodes", &H_NODES),
    #[cfg(feature = "builder")]
    ("tolerance", &TOLERANCE),
    #[cfg(feature = "builder")]
    ("samples", &SAMPLES),
    #[cfg(feature = "builder")]
    ("ghost_psi", &GHOST_PSI),
    #[cfg(feature = "builder")]
    ("ghost_theta", &GHOST_THETA),
    #[cfg(feature = "builder")]
    ("ghost_f_star", &GHOST_F_STAR),
    #[cfg(feature = "builder")]
    ("grid_nodes", &GRID_NODES),
    #[cfg(feature = "builder")]
    ("grid_points", &GRID_POINTS),
];

#[cfg(test)]
mod tests {
    use super::ALL;
    use crate::bound::End;

    /// Each bound's words state its ends, and the check agrees with the
    /// words at the ends and just beyond them.
    #[test]
    fn every_bound_states_and_checks_its_ends() {
        for &(what, bound) in ALL {
            let range = bound.range();
            assert!(!range.is_empty(), "{what}");
            assert!(!bound.contains(f64::NAN), "{what}: NaN");
            let step = |x: f64, up: bool| {
                if bound.is_whole() {
                    x + if up { 1.0 } else { -1.0 }
                } else if up {
                    x.next_up()
                } else {
                    x.next_down()
                }
            };
            let words = |x: f64| {
                let text = if bound.is_whole() {
                    format!("{x}")
                } else {
                    format!("{x:e}")
                };
                let plain = format!("{x}");
                // 4 significant digits: the words hold the end or its rounding.
                let rounded: f64 = format!("{x:.3e}").parse().unwrap();
                range.contains(&text)
                    || range.contains(&plain)
                    || range.contains(&format!("{rounded}"))
                    || range.contains(&format!("{rounded:e}"))
            };
            // Each end: (the end, the step inward, the marks of an open
            // and of a closed end in the words).
            for (end, up, open, closed) in [
                (bound.lo(), true, ["(", ">"], ["[", ">="]),
                (bound.hi(), false, [")", "<"], ["]", "<="]),
            ] {
                let marked = |marks: [&str; 2]| marks.iter().any(|m| range.contains(m));
                match end {
                    End::Closed(x) => {
                        assert!(bound.contains(x) && !bound.contains(step(x, !up)), "{what}: {range}");
                        assert!(words(x) && (marked(closed) || bound.is_whole()), "{what}: {range}");
                    }
                    End::Open(x) => {
                        assert!(!bound.contains(x) && bound.contains(step(x, up)), "{what}: {range}");
                        assert!(words(x) && marked(open), "{what}: {range}");
                    }
                    End::Unbounded => assert!(bound.contains(if up { -1e300 } else { 1e300 }), "{what}: {range}"),
                }
            }
        }
    }

    /// No two entries are the same bound.
    #[test]
    fn the_registry_lists_each_bound_once() {
        for (i, (a, x)) in ALL.iter().enumerate() {
            for (b, y) in &ALL[..i] {
                assert!(!std::ptr::eq(*x, *y), "{a} and {b}");
            }
        }
    }
}
