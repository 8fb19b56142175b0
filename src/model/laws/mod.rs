//! The contact-law seam: what the surface integrals need from a
//! single-asperity law ([`ContactLaw`]), one implementation per file
//! (`ke.rs`, `ceb.rs`), and one registry line per law ([`LAWS`](registry::LAWS): its name,
//! its table code, its label).
//!
//! A law is everything that differs between surface models at one
//! asperity: its regimes of interference `x = ω/ω_c` (their bounds), the
//! load law `P̄/P̄_c` on each, which adhesion row applies there, the
//! friction row `Q̄/P̄_c`, and (read off the regimes) the jumps of the laws
//! at the regime boundaries. The integrals themselves (panels, Gauss rules,
//! the height density, the non-contact adhesion) stay in `surface/`, the
//! same for every law.
//!
//! Dispatch is static: [`Law`] wraps the planned laws (one line each in
//! `laws!`), and `Integrals::evaluate` matches on it once per evaluation
//! ([`Law::visit`]) and calls the generic integrals with the concrete law
//! (no `dyn`, no allocation).
//! docs/ARCHITECTURE.md lists the places a new law touches.

pub mod registry;

use crate::model::integrator::{Integrator, Phi, Sums, Window};
use crate::params::Constants;
use registry::ModelKind;

/// A regime's load law `P̄/P̄_c` before its coefficient ([`Regime::coef`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LoadLaw {
    /// `x^b` (evaluated as `exp(b·ln x)`), slope `b·x^b/x`.
    Power(f64),
    /// `x`, slope 1.
    Linear,
    /// `a·(b·x + c)`, slope `a·b`.
    Affine(f64, f64, f64),
}

impl LoadLaw {
    /// The law at `x` (at a regime boundary, for its jump).
    pub fn value(self, x: f64) -> f64 {
        match self {
            LoadLaw::Power(b) => x.powf(b),
            LoadLaw::Linear => x,
            LoadLaw::Affine(a, b, c) => a * (b * x + c),
        }
    }
}

/// A friction row `Q̄/P̄_c = coef·(P̄/P̄_c ÷ coef of the load)·μ(x)` on a
/// regime, `μ` being [`ContactLaw::mu`], up to `to`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionRow {
    /// The row's coefficient (in place of the load's).
    pub coef: f64,
    /// Where the row ends (x₀ for a row clipped at the root of μ).
    pub to: f64,
}

/// One regime `[xa, xc]` above the elastic one: `P̄/P̄_c = coef·load(x)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Regime {
    /// Lower bound of x.
    pub xa: f64,
    /// Upper bound of x (∞ for the last).
    pub xc: f64,
    /// The load's coefficient, applied to the regime's integral.
    pub coef: f64,
    /// The load law.
    pub load: LoadLaw,
    /// The contact adhesion row (`asperity::adhesion::ROWS`), if any.
    pub adhesion: Option<usize>,
    /// The friction row, if any.
    pub friction: Option<FrictionRow>,
    /// A point inside where the integral is split (the end of a clipped
    /// friction row): the pieces are summed before `coef` applies.
    pub split: Option<f64>,
}

impl Regime {
    /// A regime `[xa, xc]` of load `coef·load(x)` and contact adhesion row
    /// `adhesion`, without a friction row (so with nothing to split at).
    pub const fn plain(xa: f64, xc: f64, coef: f64, load: LoadLaw, adhesion: Option<usize>) -> Regime {
        Regime {
            xa,
            xc,
            coef,
            load,
            adhesion,
            friction: None,
            split: None,
        }
    }
}

/// A regime boundary `x` where the laws jump: the load below and above,
/// and the contact adhesion row and its `x^b` below and above (row 0 with
/// 0 for none). Planned once per law ([`jumps_of`]): general densities add
/// the jumps to ∂P*/∂d*, ∂Fs*/∂d* (the boundaries move with d*).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jump {
    /// Where.
    pub x: f64,
    /// `coef·load(x)` below and above.
    pub load: [f64; 2],
    /// `(row, x^b)` below and above.
    pub adhesion: [(usize, f64); 2],
}

/// The jumps at the lower bound of each regime of `regimes` (the first
/// one's at x = 1, from the elastic regime: Hertz, adhesion row 0). The
/// last regime must reach x = ∞.
pub fn jumps_of<const N: usize>(regimes: &[Regime; N]) -> [Jump; N] {
    use crate::model::asperity::{adhesion, HERTZ};
    debug_assert!(regimes.last().is_none_or(|r| r.xc == f64::INFINITY));
    let adh = |row: Option<usize>, x: f64| row.map_or((0, 0.0), |row| (row, x.powf(adhesion::ROWS[row].1)));
    let (mut coef, mut law, mut row) = (HERTZ.0, LoadLaw::Power(HERTZ.1), Some(0));
    regimes.map(|r| {
        let x = r.xa;
        let jump = Jump {
            x,
            load: [coef * law.value(x), r.coef * r.load.value(x)],
            adhesion: [adh(row, x), adh(r.adhesion, x)],
        };
        (coef, law, row) = (r.coef, r.load, r.adhesion);
        jump
    })
}

/// What the surface integrals need from a single-asperity contact law.
///
/// The elastic regime `0 ≤ x < 1` (Hertz load `x^1.5`, adhesion row 0) is
/// integrated by [`ContactLaw::elastic`], whose friction row is the law's
/// own (a power of x, or a capacity with endpoint behaviour of its own);
/// the regimes above it by the shared `Integrals::smooth`, from
/// [`ContactLaw::regimes`]. Jumps of the laws at the regime boundaries
/// (general densities) follow from the regimes.
pub trait ContactLaw {
    /// The regimes above the elastic one, contiguous from x = 1.
    fn regimes(&self) -> &[Regime];

    /// The jumps of the laws at the regime boundaries ([`jumps_of`] the
    /// regimes).
    fn jumps(&self) -> &[Jump];

    /// `μ(x)` of the friction rows above the elastic regime.
    #[inline(always)]
    fn mu(&self, _x: f64) -> f64 {
        0.0
    }

    /// The elastic regime `[0, 1)`: P̄, F̄_s (row 0, when `adh`), their
    /// d*-derivatives and, if `want_q`, the friction row with its
    /// coefficient applied.
    fn elastic<H: Phi>(&self, s: &Integrator, h: &H, d: f64, win: Window, adh: bool, want_q: bool) -> Sums {
        let _ = want_q;
        s.elastic_hertz(h, d, win, adh)
    }
}

/// Something done with a law, whichever it is: [`Law::visit`] calls
/// [`visit`](Self::visit) with the concrete law (static dispatch).
pub(crate) trait LawVisitor {
    /// What it gives.
    type Out;
    /// Does it with `law`.
    fn visit<L: ContactLaw>(self, law: &L) -> Self::Out;
}

/// Writes the wrapper [`Law`] from one line a law (the variant of
/// [`ModelKind`] => its type): the enum, `Law::new` and `Law::visit`.
macro_rules! laws {
    ($($variant:ident => $law:ty),+ $(,)?) => {
        /// The planned laws: the wrapper the surface dispatches on (one
        /// `match` per evaluation).
        // One per Integrals, read on every evaluation: inline, not boxed.
        #[allow(clippy::large_enum_variant)]
        #[derive(Debug, Clone)]
        pub(crate) enum Law {
            $($variant($law)),+
        }

        impl Law {
            /// Plans the law `c.kind` for the constants `c`.
            pub fn new(c: &Constants) -> Law {
                match c.kind {
                    $(ModelKind::$variant => Law::$variant(<$law>::new(c))),+
                }
            }

            /// `v` with the concrete law: one `match`, then static calls.
            #[inline(always)]
            pub fn visit<V: LawVisitor>(&self, v: V) -> V::Out {
                match self {
                    $(Law::$variant(law) => v.visit(law)),+
                }
            }
        }
    };
}

// The laws of the registry's lines: their modules (`pub mod ke;` …) and
// `Law`.
registry::registered_laws!();

/// A test-only law: Hertz `x^1.5` at every interference (no plastic
/// regime), no friction; registered only in the tests.
#[cfg(test)]
pub(crate) mod hertz {
    use super::registry::LawInfo;
    use super::*;

    pub const INFO: LawInfo = LawInfo {
        kind: ModelKind::KogutEtsion,
        name: "hertz",
        code: 255,
        label: "Hertz (elastic only)",
    };

    #[derive(Debug, Clone)]
    pub struct Hertz {
        jumps: [Jump; 1],
    }

    impl Hertz {
        #[allow(clippy::new_without_default)]
        pub fn new() -> Hertz {
            Hertz {
                jumps: jumps_of(&REGIMES),
            }
        }
    }

    const REGIMES: [Regime; 1] = [Regime::plain(1.0, f64::INFINITY, 1.0, LoadLaw::Power(1.5), Some(0))];

    impl ContactLaw for Hertz {
        fn regimes(&self) -> &[Regime] {
            &REGIMES
        }

        fn jumps(&self) -> &[Jump] {
            &self.jumps
        }
    }
}

#[cfg(test)]
mod tests {
    use super::registry::LAWS;
    use super::*;

    #[test]
    fn registry_names_codes_and_labels_are_unique() {
        let all = LAWS.iter().chain([&hertz::INFO]).collect::<Vec<_>>();
        for (i, a) in all.iter().enumerate() {
            for b in &all[i + 1..] {
                assert!(
                    a.name != b.name && a.code != b.code && a.label != b.label,
                    "{a:?} vs {b:?}"
                );
            }
        }
        for (i, l) in LAWS.iter().enumerate() {
            assert_eq!(l.kind as usize, i);
            assert_eq!(l.kind.name(), l.name);
            assert_eq!(ModelKind::ALL[i], l.kind);
        }
    }
}
