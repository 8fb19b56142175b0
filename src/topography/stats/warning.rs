//! What to know about a result that is still returned.

use serde::ser::{Serialize, SerializeMap, Serializer};
use std::fmt;

/// Something to know about a result that is still returned.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Warning {
    /// α < 1.5: not an isotropic Gaussian surface (α ≥ 1.5 for one), so
    /// the relations of MODEL.md §10 are approximate.
    LowBandwidth {
        /// The bandwidth α.
        alpha: f64,
    },
    /// A ratio m20/m02 or m40/m04 outside 0.8–1.25: the surface is
    /// anisotropic, and the relations assume isotropy.
    Anisotropy {
        /// `"m20/m02"` or `"m40/m04"`.
        ratio: &'static str,
        /// Its value.
        value: f64,
    },
    /// [`combine`](super::combine()): the two surfaces were sampled at intervals differing by
    /// more than 1 %, so their m2, m4 belong to different bands.
    IntervalMismatch {
        /// `"dx"` or `"dy"`.
        name: &'static str,
        /// The interval of the first surface (metres).
        first: f64,
        /// The interval of the second surface (metres).
        second: f64,
    },
    /// The shortest scale the statistics see (λs, or 2·max(dx, dy)
    /// without an S-filter) is below the instrument's reliability cut-off:
    /// m2, m4 and so β and ψ come from scales the instrument distorts.
    Unreliable {
        /// The shortest scale the statistics see (metres).
        scale: f64,
        /// The reliability cut-off (metres).
        cutoff: f64,
    },
}

impl Warning {
    /// A short snake_case name of the warning: `"low_bandwidth"`,
    /// `"anisotropy"` or `"interval_mismatch"`.
    pub const fn kind(&self) -> &'static str {
        match self {
            Warning::LowBandwidth { .. } => "low_bandwidth",
            Warning::Anisotropy { .. } => "anisotropy",
            Warning::IntervalMismatch { .. } => "interval_mismatch",
            Warning::Unreliable { .. } => "unreliable_scale",
        }
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Warning::LowBandwidth { alpha } => write!(
                f,
                "the bandwidth alpha = {alpha} is below 1.5: this is not an isotropic Gaussian surface, \
                 so the summit density, radius and beta are approximate"
            ),
            Warning::Anisotropy { ratio, value } => write!(
                f,
                "{ratio} = {value} is outside 0.8-1.25: the surface is anisotropic, \
                 and the relations assume an isotropic surface"
            ),
            Warning::IntervalMismatch { name, first, second } => write!(
                f,
                "the two surfaces have {name} = {first} m and {second} m (differing by more than 1 %): \
                 their slope and curvature moments belong to different bands; the result keeps the first's"
            ),
            Warning::Unreliable { scale, cutoff } => write!(
                f,
                "the shortest scale analysed, {scale:e} m, is below the instrument's reliability cut-off \
                 {cutoff:e} m: beta, R, eta and psi come from distorted scales; filter with --lambda-s {cutoff:e} \
                 (or auto)"
            ),
        }
    }
}

/// A warning is recorded as `{"kind": "...", "message": "...", ...}` with
/// its values (`alpha`, `ratio` and `value`, or `name`, `first` and
/// `second`).
impl Serialize for Warning {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(None)?;
        map.serialize_entry("kind", self.kind())?;
        map.serialize_entry("message", &self.to_string())?;
        match self {
            Warning::LowBandwidth { alpha } => map.serialize_entry("alpha", alpha)?,
            Warning::Anisotropy { ratio, value } => {
                map.serialize_entry("ratio", ratio)?;
                map.serialize_entry("value", value)?;
            }
            Warning::Unreliable { scale, cutoff } => {
                map.serialize_entry("scale", scale)?;
                map.serialize_entry("cutoff", cutoff)?;
            }
            Warning::IntervalMismatch { name, first, second } => {
                map.serialize_entry("name", name)?;
                map.serialize_entry("first", first)?;
                map.serialize_entry("second", second)?;
            }
        }
        map.end()
    }
}
