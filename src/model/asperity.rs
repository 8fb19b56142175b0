//! Single-asperity laws (Table 1 of the paper, corrected per MODEL.md §6),
//! and the CEB-type tangential capacity of MODEL.md §8.
//!
//! `x = ω/ω_c` is an asperity's interference over the critical interference.
//!
//! The regime bounds and the adhesion rows (shared by both laws) are here;
//! each law's own rows live with its implementation of the contact-law
//! seam (`src/model/laws/`), re-exported here.

pub use super::laws::ceb::CebCapacity;
pub use super::laws::ke::{load, mu_ep, FRICTION_ELASTIC, X0};

/// The Hertz load of the fully elastic regime, `P̄/P̄_c = x^1.5` as
/// `(a, b)` of `a·x^b`: the same in every law (MODEL.md §3).
pub const HERTZ: (f64, f64) = (1.0, 1.5);

/// Upper end of the fully elastic regime.
pub const X_ELASTIC: f64 = 1.0;
/// Upper end of the 1st elastic-plastic regime.
pub const X_EP1: f64 = 6.0;
/// Start of the fully plastic regime.
pub const X_PLASTIC: f64 = 110.0;

/// Adhesion of a contacting asperity, `F̄_s/F̄_s0 = a·x^b·r^c` (MODEL.md §3).
pub mod adhesion {
    /// Fully elastic: `0.98·x^0.298·r^−0.29`.
    pub const ELASTIC: (f64, f64, f64) = (0.98, 0.298, -0.29);
    /// 1st elastic-plastic: `0.79·x^0.356·r^−0.321`.
    pub const EP1: (f64, f64, f64) = (0.79, 0.356, -0.321);
    /// 2nd elastic-plastic: `1.19·x^0.093·r^−0.332`.
    pub const EP2: (f64, f64, f64) = (1.19, 0.093, -0.332);
    /// The rows in order (a law's regime names its row by index).
    pub const ROWS: [(f64, f64, f64); 3] = [ELASTIC, EP1, EP2];
}

/// Adhesion of a non-contacting asperity, `F̄_s/F̄_s0 = (4/3)(u^−2 − ¼u^−8)`
/// with `u` the gap over ε plus one (MODEL.md §3).
#[inline]
pub fn adhesion_noncontact(u: f64) -> f64 {
    let u2 = 1.0 / (u * u);
    let u8 = (u2 * u2) * (u2 * u2);
    (4.0 / 3.0) * (u2 - 0.25 * u8)
}

/// d/du of [`adhesion_noncontact`]: `(4/3)(−2u^−3 + 2u^−9)`.
#[inline]
pub fn adhesion_noncontact_slope(u: f64) -> f64 {
    let u3 = 1.0 / (u * u * u);
    (8.0 / 3.0) * (u3 * u3 * u3 - u3)
}
