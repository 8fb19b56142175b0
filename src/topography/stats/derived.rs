//! The Greenwood–Williamson quantities α, η, R, β, σ_s, y_s from the
//! spectral moments m0, m2, m4 (MODEL.md §10).

use super::{finite, positive, StatsError};
use crate::gw::{self, ALPHA_ADMISSIBLE};

/// α, η, R, β, σ_s, y_s from m0, m2, m4 (MODEL.md §10).
pub(super) struct Derived {
    pub(super) alpha: f64,
    pub(super) eta: f64,
    pub(super) radius: f64,
    pub(super) beta: f64,
    pub(super) sigma_s: f64,
    pub(super) y_s: f64,
}

impl Derived {
    pub(super) fn new(m0: f64, m2: f64, m4: f64) -> Result<Derived, StatsError> {
        positive("m0", m0)?;
        positive("m2", m2)?;
        finite("m4", m4)?;
        let alpha = m0 * m4 / (m2 * m2);
        let beta = gw::beta_of_alpha(alpha);
        if !(ALPHA_ADMISSIBLE.contains(alpha) && alpha.is_finite()) {
            return Err(StatsError::Bandwidth { alpha, beta });
        }
        let derived = Derived {
            alpha,
            eta: gw::summit_density(m2, m4),
            radius: gw::summit_radius(m4),
            beta,
            sigma_s: m0.sqrt() * gw::sigma_s_ratio_of_alpha(alpha),
            y_s: gw::summit_mean_height(m0, alpha),
        };
        positive("eta", derived.eta)?;
        positive("radius", derived.radius)?;
        positive("sigma_s", derived.sigma_s)?;
        positive("y_s", derived.y_s)?;
        Ok(derived)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bandwidth_refusal_states_both_bounds() {
        let e = StatsError::Bandwidth { alpha: 0.5, beta: 0.01 };
        assert_eq!(
            e.to_string(),
            format!(
                "alpha = 0.5 is out of range: must be > 0.8968 (beta = 0.01 must be {}), else sigma_s is imaginary",
                crate::bounds::BETA_ADMISSIBLE.range()
            )
        );
        assert!(!ALPHA_ADMISSIBLE.contains(gw::ALPHA_MIN) && ALPHA_ADMISSIBLE.contains(gw::ALPHA_MIN.next_up()));
        assert!(Derived::new(1.0, 1.0, gw::ALPHA_MIN).is_err());
        assert!(Derived::new(1.0, 1.0, 1.0).is_ok());
    }
}
