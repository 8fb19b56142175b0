//! The Greenwood–Williamson relations (MODEL.md §2, §10): the summit
//! quantities of an isotropic Gaussian surface from its spectral moments
//! m0, m2, m4 (bandwidth α = m0·m4/m2²), the roughness parameter β = ηRσ,
//! the ratio σ_s/σ of the summit heights' spread to the surface heights'
//! (McCool), and the bounds below which σ_s is imaginary.
//!
//! A leaf module: it uses nothing else of the crate. Each relation is the
//! one expression every caller evaluates (the same f64 operations in the
//! same order: the default table depends on them bit for bit).
// The α-based relations serve the measured-surface statistics (feature
// `topography`); the light runtime uses the β-based ones only.
#![cfg_attr(not(feature = "topography"), allow(dead_code))]

use crate::bound::Bound;
use std::f64::consts::PI;

/// 16/π − 3√3 + 1 = 0.89680576…: the bandwidth α must exceed it for σ_s
/// to be real (MODEL.md §10).
pub(crate) const ALPHA_MIN: f64 = 16.0 / PI - 3.0 * 1.732_050_807_568_877_2 + 1.0;

/// The bandwidths α at which σ_s is real: > 16/π − 3√3 + 1 (MODEL.md §10),
/// the check and its message.
pub static ALPHA_ADMISSIBLE: Bound = Bound::above(ALPHA_MIN);

/// McCool's constant in σ_s/σ = (1 − 3.717e-4/β²)^½: [`ALPHA_MIN`]/(768π)
/// (as β² = α/(768π)), rounded as MODEL.md §2 prints it.
const MCCOOL: f64 = 3.717e-4;

/// β must exceed this for σ_s/σ = (1 − 3.717e-4/β²)^½ to be real: the
/// largest f64 at which it is not, (3.717e-4)^½ = 0.0192795228… (so that
/// `beta > BETA_MIN` is exactly the f64 test 1 − 3.717e-4/β² > 0 for β > 0).
pub const BETA_MIN: f64 = 0.019_279_522_815_671_55;

/// β = α^½/(16√(3π)) (a negative α counts as 0).
pub(crate) fn beta_of_alpha(alpha: f64) -> f64 {
    alpha.max(0.0).sqrt() / (16.0 * (3.0 * PI).sqrt())
}

/// σ_s/σ = (1 − (16/π − 3√3 + 1)/α)^½ from the bandwidth α (MODEL.md §10).
pub(crate) fn sigma_s_ratio_of_alpha(alpha: f64) -> f64 {
    (1.0 - ALPHA_MIN / alpha).sqrt()
}

/// `1 − 3.717e-4/β²`, the square of σ_s/σ (McCool; MODEL.md §2).
fn sigma_s_ratio_squared(beta: f64) -> f64 {
    1.0 - MCCOOL / (beta * beta)
}

/// `σ_s/σ = (1 − 3.717e-4/β²)^½` from β (McCool; MODEL.md §2).
pub(crate) fn sigma_s_ratio(beta: f64) -> f64 {
    sigma_s_ratio_squared(beta).sqrt()
}

/// η = m4/(6π√3·m2), the summit density (MODEL.md §10).
pub(crate) fn summit_density(m2: f64, m4: f64) -> f64 {
    m4 / (6.0 * PI * 3f64.sqrt() * m2)
}

/// R = 0.375·(π/m4)^½, the mean summit radius (MODEL.md §10).
pub(crate) fn summit_radius(m4: f64) -> f64 {
    0.375 * (PI / m4).sqrt()
}

/// y_s = 4·(m0/(πα))^½, the mean summit height above the mean plane
/// (MODEL.md §10).
pub(crate) fn summit_mean_height(m0: f64, alpha: f64) -> f64 {
    4.0 * (m0 / (PI * alpha)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alpha_min_is_the_constant() {
        assert!((ALPHA_MIN - 0.896_805_76).abs() < 1e-8);
        assert!((ALPHA_MIN - (16.0 / PI - 3.0 * 3f64.sqrt() + 1.0)).abs() < 1e-15);
        // McCool's constant is the α bound carried over to β (4 digits).
        assert!((ALPHA_MIN / (768.0 * PI) / MCCOOL - 1.0).abs() < 2e-4);
    }

    #[test]
    fn beta_min_is_where_sigma_s_turns_real() {
        assert!(sigma_s_ratio_squared(BETA_MIN) <= 0.0);
        assert!(sigma_s_ratio_squared(BETA_MIN.next_up()) > 0.0);
        assert!((BETA_MIN - MCCOOL.sqrt()).abs() <= 1e-17);
        // Monotone: nothing below is admissible, everything above is.
        let mut b = BETA_MIN;
        for _ in 0..10_000 {
            assert!(sigma_s_ratio_squared(b) <= 0.0, "{b}");
            b = b.next_down();
        }
        let mut b = BETA_MIN.next_up();
        for _ in 0..10_000 {
            assert!(sigma_s_ratio_squared(b) > 0.0, "{b}");
            b = b.next_up();
        }
    }

    #[test]
    fn the_two_forms_of_sigma_s_agree() {
        // β and α of one surface give the same σ_s/σ (to McCool's rounding).
        for alpha in [1.0, 1.5, 2.0, 5.0, 30.0] {
            let beta = beta_of_alpha(alpha);
            let (a, b) = (sigma_s_ratio_of_alpha(alpha), sigma_s_ratio(beta));
            assert!((a - b).abs() < 2e-4 / (alpha - ALPHA_MIN), "{alpha}: {a} vs {b}");
        }
        assert!((sigma_s_ratio(0.04) - 0.87618).abs() < 5e-6);
    }
}
