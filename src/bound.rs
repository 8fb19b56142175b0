//! A range of accepted values that states itself: one constant gives both
//! the check and the words of the message (`in [1e-3, 1e3]`, `> 0 Pa`),
//! so the two cannot drift apart.
//!
//! A leaf module: it uses nothing else of the crate.

use std::fmt::Write as _;
use std::sync::OnceLock;

/// One end of a [`Bound`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum End {
    /// The value must be beyond this one (`(`, `>`).
    Open(f64),
    /// The value may equal this one (`[`, `>=`).
    Closed(f64),
    /// No limit at this end.
    Unbounded,
}

/// A range of accepted values, and its description, made once on first
/// use (declare bounds as `static`s: the description is kept in them).
/// Every range the library checks is one, declared beside the type it
/// bounds and listed in [`crate::bounds::ALL`]; the front ends' help texts
/// and docstrings quote [`Bound::range`].
#[derive(Debug)]
pub struct Bound {
    lo: End,
    hi: End,
    unit: &'static str,
    /// A count: described with whole numbers (`a whole number from 2 to 100000`).
    whole: bool,
    text: OnceLock<String>,
}

impl Bound {
    /// The values between `lo` and `hi`.
    pub const fn new(lo: End, hi: End) -> Bound {
        Bound {
            lo,
            hi,
            unit: "",
            whole: false,
            text: OnceLock::new(),
        }
    }

    /// The whole numbers from `lo` to `hi` (a count; `hi` may be
    /// `usize::MAX` for no upper limit).
    pub const fn whole(lo: usize, hi: usize) -> Bound {
        Bound {
            lo: End::Closed(lo as f64),
            hi: if hi == usize::MAX {
                End::Unbounded
            } else {
                End::Closed(hi as f64)
            },
            unit: "",
            whole: true,
            text: OnceLock::new(),
        }
    }

    /// The values above `lo` (`> lo`).
    pub const fn above(lo: f64) -> Bound {
        Bound::new(End::Open(lo), End::Unbounded)
    }

    /// The values from `lo` up (`>= lo`).
    pub const fn at_least(lo: f64) -> Bound {
        Bound::new(End::Closed(lo), End::Unbounded)
    }

    /// The values up to `hi` (`<= hi`).
    pub const fn at_most(hi: f64) -> Bound {
        Bound::new(End::Unbounded, End::Closed(hi))
    }

    /// The same range, its description ending in `unit` (`> 0 Pa`) or
    /// other words (`<= 100 (ghost nodes included)`).
    pub const fn unit(self, unit: &'static str) -> Bound {
        let (lo, hi, whole) = (self.lo, self.hi, self.whole);
        // `self`'s description is empty (not yet made): nothing to free,
        // and a const fn may not drop it.
        std::mem::forget(self);
        Bound {
            lo,
            hi,
            unit,
            whole,
            text: OnceLock::new(),
        }
    }

    /// The lower end.
    pub fn lo(&self) -> End {
        self.lo
    }

    /// The upper end.
    pub fn hi(&self) -> End {
        self.hi
    }

    /// Whether the range is of whole numbers (a count).
    pub fn is_whole(&self) -> bool {
        self.whole
    }

    /// Whether `value` is in the range (NaN never is; a count's value must
    /// be whole).
    pub fn contains(&self, value: f64) -> bool {
        if self.whole && value.fract() != 0.0 {
            return false;
        }
        let lo = match self.lo {
            End::Open(lo) => value > lo,
            End::Closed(lo) => value >= lo,
            End::Unbounded => !value.is_nan(),
        };
        let hi = match self.hi {
            End::Open(hi) => value < hi,
            End::Closed(hi) => value <= hi,
            End::Unbounded => !value.is_nan(),
        };
        lo && hi
    }

    /// The range in words, as messages state it after "must be ":
    /// `in (0.8968, 100]`, `in [0, 0.5)`, `>= 0`, `<= 1e3`, `> 0 Pa`.
    pub fn range(&'static self) -> &'static str {
        self.text.get_or_init(|| self.describe())
    }

    fn describe(&self) -> String {
        let number = |x: f64| if self.whole { format!("{x}") } else { number(x) };
        let mut text = match (self.lo, self.hi) {
            (End::Unbounded, End::Unbounded) => String::from("finite"),
            (End::Closed(lo), End::Closed(hi)) if self.whole => format!("a whole number from {lo} to {hi}"),
            (End::Closed(lo), End::Unbounded) if self.whole => format!("at least {lo}"),
            (lo, End::Unbounded) => match lo {
                End::Open(lo) => format!("> {}", number(lo)),
                _ => format!(">= {}", number(end_value(lo))),
            },
            (End::Unbounded, hi) => match hi {
                End::Open(hi) => format!("< {}", number(hi)),
                _ => format!("<= {}", number(end_value(hi))),
            },
            (lo, hi) => format!(
                "in {}{}, {}{}",
                if matches!(lo, End::Open(_)) { '(' } else { '[' },
                number(end_value(lo)),
                number(end_value(hi)),
                if matches!(hi, End::Open(_)) { ')' } else { ']' },
            ),
        };
        if !self.unit.is_empty() {
            let _ = write!(text, " {}", self.unit);
        }
        text
    }
}

/// The model's validity domain (docs/MODEL.md, "Validity domain"): the
/// ranges the paper studied, outside which a result is returned with a
/// warning ([`crate::Warning::of_params`]), not refused.
pub(crate) mod domain {
    use super::{Bound, End};

    /// ψ the paper covers: "a wide range of plasticity index values from
    /// ψ = 0.5 to ψ = 8 was covered"; at ψ = 8 the friction is
    /// "unreasonably small" and the model "may be invalid at large
    /// plasticity index values".
    pub(crate) static PSI: Bound = Bound::new(End::Closed(0.5), End::Closed(8.0));
    /// θ the paper covers: "the range of the adhesion parameter, θ, is
    /// 1e-4 ≤ θ ≤ 0.01 where the upper limit corresponds to very high
    /// adhesion energy". Only the upper end warns: below 1e-4 adhesion is
    /// negligible, which the model handles (θ = 0 is the paper's limit).
    pub(crate) static THETA: Bound = Bound::at_most(0.01);
    /// β: the paper takes β = 0.04 "according to the finding of Greenwood
    /// and Williamson" and varies nothing else. The range is this
    /// project's choice (docs/MODEL.md, "Validity domain"): within a factor
    /// 4 of the paper's β (0.01–0.16), and above the model's own floor
    /// β > β_min (`gw::BETA_MIN`: σ_s real, MODEL.md §2), so from 0.02.
    pub(crate) static BETA: Bound = Bound::new(End::Closed(0.02), End::Closed(0.16));
}

fn end_value(end: End) -> f64 {
    match end {
        End::Open(x) | End::Closed(x) => x,
        End::Unbounded => f64::NAN,
    }
}

/// A help text or docstring: `what`, then the range in brackets and
/// `tail` (`Poisson's ratio ν, in [0, 0.5) [default: 0.3]`).
pub fn help(what: &str, bound: &'static Bound, tail: &str) -> String {
    let range = bound.range();
    let mut text = if range.starts_with("in ") {
        format!("{what}, {range}")
    } else {
        format!("{what} ({range})")
    };
    if !tail.is_empty() {
        let _ = write!(text, " {tail}");
    }
    text
}

/// `x` exactly if it has at most 6 significant digits (`-1.1395`), else
/// rounded to 4, in the shorter of plain and exponent form, plain on a
/// tie: `0.8968`, `0.5`, `100`, `1e-3`, `1e3`.
fn number(x: f64) -> String {
    let rounded = |digits: usize| format!("{x:.digits$e}").parse::<f64>().unwrap_or(x);
    let r = (0..6).map(rounded).find(|&r| r == x).unwrap_or_else(|| rounded(3));
    let (plain, exponent) = (format!("{r}"), format!("{r:e}"));
    if exponent.len() < plain.len() {
        exponent
    } else {
        plain
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_state_themselves() {
        static ROUNDED: Bound = Bound::new(End::Open(0.896_805_76), End::Closed(100.0));
        static NU: Bound = Bound::new(End::Closed(0.0), End::Open(0.5));
        static PSI: Bound = Bound::new(End::Closed(1e-3), End::Closed(1e3));
        static EPS: Bound = Bound::new(End::Closed(1e-9), End::Closed(100.0));
        static NU2: Bound = Bound::new(End::Closed(-1.0), End::Closed(0.5));
        static E: Bound = Bound::above(0.0).unit("Pa");
        static GAMMA: Bound = Bound::at_least(0.0).unit("J/m²");
        static THETA: Bound = Bound::at_most(1e3);
        static ALPHA: Bound = Bound::above(0.896_805_76);
        static WEIBULL: Bound = Bound::new(End::Open(-1.1395), End::Closed(2.0));
        for (bound, text) in [
            (&ROUNDED, "in (0.8968, 100]"),
            (&NU, "in [0, 0.5)"),
            (&PSI, "in [1e-3, 1e3]"),
            (&EPS, "in [1e-9, 100]"),
            (&NU2, "in [-1, 0.5]"),
            (&E, "> 0 Pa"),
            (&GAMMA, ">= 0 J/m²"),
            (&THETA, "<= 1e3"),
            (&ALPHA, "> 0.8968"),
            (&WEIBULL, "in (-1.1395, 2]"),
        ] {
            assert_eq!(bound.range(), text);
            assert_eq!(bound.range(), text, "kept");
        }
    }

    #[test]
    fn the_validity_domain_states_itself() {
        assert_eq!(domain::PSI.range(), "in [0.5, 8]");
        assert_eq!(domain::THETA.range(), "<= 0.01");
        assert_eq!(domain::BETA.range(), "in [0.02, 0.16]");
        assert!(domain::PSI.contains(8.0) && !domain::PSI.contains(8.0f64.next_up()));
        assert!(domain::BETA.contains(0.04) && !domain::BETA.contains(0.548));
    }

    #[test]
    fn bounds_check_their_ends() {
        static NU: Bound = Bound::new(End::Closed(0.0), End::Open(0.5));
        assert!(NU.contains(0.0) && NU.contains(0.4999) && !NU.contains(0.5) && !NU.contains(-1e-300));
        assert!(!NU.contains(f64::NAN));
        static POSITIVE: Bound = Bound::above(0.0);
        assert!(POSITIVE.contains(f64::MIN_POSITIVE) && !POSITIVE.contains(0.0) && !POSITIVE.contains(-0.0));
        assert!(POSITIVE.contains(f64::INFINITY) && !POSITIVE.contains(f64::NAN));
        static MOST: Bound = Bound::at_most(1e3);
        assert!(MOST.contains(1e3) && !MOST.contains(1e3f64.next_up()) && MOST.contains(f64::NEG_INFINITY));
    }
}
