//! Numbers as people read them: the shortest decimal that parses back to
//! the same `f64`, in one style everywhere (messages and text output; JSON
//! output is serde_json's, also shortest round-trip).

use core::fmt;

/// Displays an `f64` in its shortest round-trip form: plain decimals for
/// magnitudes in [1e-4, 1e6) (`0.5`, `8`, `0.003`), exponent form outside
/// (`1e-5`, `2.5e7`); `0` is `0`. Parsing the text gives the same `f64`.
/// Non-finite values print as `NaN`, `inf`, `-inf`.
///
/// ```
/// use ke_friction::Shortest;
/// assert_eq!(Shortest(0.5).to_string(), "0.5");
/// assert_eq!(Shortest(8.0).to_string(), "8");
/// assert_eq!(Shortest(1e-5).to_string(), "1e-5");
/// assert_eq!(Shortest(0.1 + 0.2).to_string(), "0.30000000000000004");
/// let x = 1.0 / 3.0e9;
/// assert_eq!(Shortest(x).to_string().parse::<f64>().unwrap(), x);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shortest(pub f64);

impl Shortest {
    /// `x` rounded to 4 significant digits, for messages (`-28.2`, not
    /// `-28.20201007867259`).
    ///
    /// ```
    /// assert_eq!(ke_friction::Shortest::rounded(-28.20201007867259).to_string(), "-28.2");
    /// ```
    pub fn rounded(x: f64) -> Shortest {
        Shortest(format!("{x:.3e}").parse().unwrap_or(x))
    }

    /// `x` rounded to 6 significant digits: the one format of numbers in
    /// text output and in warnings (`1.36222`, not `1.36222e0` nor
    /// `1.3622249834211117`); JSON keeps every digit.
    ///
    /// ```
    /// use ke_friction::Shortest;
    /// assert_eq!(Shortest::sig(1.3622249834211117).to_string(), "1.36222");
    /// assert_eq!(Shortest::sig(2.0000000000000004e-11).to_string(), "2e-11");
    /// ```
    pub fn sig(x: f64) -> Shortest {
        Shortest(format!("{x:.5e}").parse().unwrap_or(x))
    }
}

impl fmt::Display for Shortest {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Rust's `{}` and `{:e}` both print the shortest round-trip digits.
        let x = self.0;
        let a = x.abs();
        if !x.is_finite() || a == 0.0 || (1e-4..1e6).contains(&a) {
            write!(f, "{x}")
        } else {
            write!(f, "{x:e}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_form_round_trips() {
        let mut x = 1.234_567_890_123_456_7e-300_f64;
        while x < 1e300 {
            for v in [x, -x, x.next_up(), 1.0 / x] {
                let text = Shortest(v).to_string();
                assert_eq!(text.parse::<f64>().unwrap(), v, "{text}");
            }
            x *= 7.3;
        }
        assert_eq!(Shortest(1e-4).to_string(), "0.0001");
        assert_eq!(Shortest(999_999.0).to_string(), "999999");
        assert_eq!(Shortest(1e6).to_string(), "1e6");
        assert_eq!(Shortest(-2.5e-7).to_string(), "-2.5e-7");
        assert_eq!(Shortest(0.0).to_string(), "0");
    }
}
