//! The Greenwood–Williamson quantities α, η, R, β, σ_s, y_s from the
//! spectral moments m0, m2, m4 (MODEL.md §10).

use super::{finite, positive, StatsError};
use std::f64::consts::PI;

/// 16/π − 3√3 + 1 = 0.89680576…: α must exceed it (σ_s real, MODEL.md §10).
const ALPHA_MIN: f64 = 16.0 / PI - 3.0 * 1.732_050_807_568_877_2 + 1.0;

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
        let beta = alpha.max(0.0).sqrt() / (16.0 * (3.0 * PI).sqrt());
        if !(alpha > ALPHA_MIN && alpha.is_finite()) {
            return Err(StatsError::Bandwidth { alpha, beta });
        }
        let derived = Derived {
            alpha,
            eta: m4 / (6.0 * PI * 3f64.sqrt() * m2),
            radius: 0.375 * (PI / m4).sqrt(),
            beta,
            sigma_s: m0.sqrt() * (1.0 - ALPHA_MIN / alpha).sqrt(),
            y_s: 4.0 * (m0 / (PI * alpha)).sqrt(),
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
    fn alpha_min_is_the_constant() {
        assert!((ALPHA_MIN - 0.896_805_76).abs() < 1e-8);
        assert!((ALPHA_MIN - (16.0 / PI - 3.0 * 3f64.sqrt() + 1.0)).abs() < 1e-15);
    }
}
