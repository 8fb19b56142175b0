//! Numbers as people read them: the shortest decimal that parses back to
//! the same `f64`, in one style everywhere (messages, text output, JSON),
//! and the small JSON writer that prints them (the CLI's `--json` output,
//! the NumPy export's metadata).

use core::fmt;

/// Displays an `f64` in its shortest round-trip form: plain decimals for
/// magnitudes in [1e-4, 1e6) (`0.5`, `8`, `0.003`), exponent form outside
/// (`1e-5`, `2.5e7`); `0` is `0`. Parsing the text gives the same `f64`.
/// Non-finite values print as `NaN`, `inf`, `-inf`.
///
/// ```
/// use ke_friction::num::Shortest;
/// assert_eq!(Shortest(0.5).to_string(), "0.5");
/// assert_eq!(Shortest(8.0).to_string(), "8");
/// assert_eq!(Shortest(1e-5).to_string(), "1e-5");
/// assert_eq!(Shortest(0.1 + 0.2).to_string(), "0.30000000000000004");
/// let x = 1.0 / 3.0e9;
/// assert_eq!(Shortest(x).to_string().parse::<f64>().unwrap(), x);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shortest(pub f64);

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

/// A JSON number: [`Shortest`] form for finite values (valid JSON, exact
/// on parsing), `null` for NaN and infinities.
///
/// ```
/// use ke_friction::num::json;
/// assert_eq!(json(1e-5), "1e-5");
/// assert_eq!(json(f64::NAN), "null");
/// ```
pub fn json(x: f64) -> String {
    if x.is_finite() {
        Shortest(x).to_string()
    } else {
        "null".to_string()
    }
}

/// A JSON value of [`json_object`].
pub enum Json<'a> {
    /// A number ([`json`]: shortest round-trip, `null` if not finite).
    Num(f64),
    /// A whole number.
    Int(u64),
    /// A string (escaped).
    Str(&'a str),
    /// `null`.
    Null,
    /// Raw JSON text (a nested object or array).
    Raw(String),
}

/// One JSON object on one line, keys in the given order.
pub fn json_object(fields: &[(&str, Json)]) -> String {
    let body: Vec<String> = fields
        .iter()
        .map(|(k, v)| {
            let v = match v {
                Json::Num(x) => json(*x),
                Json::Int(n) => n.to_string(),
                Json::Str(t) => json_string(t),
                Json::Null => "null".to_string(),
                Json::Raw(r) => r.clone(),
            };
            format!("{}:{v}", json_string(k))
        })
        .collect();
    format!("{{{}}}", body.join(","))
}

/// A JSON array of numbers.
pub fn json_numbers(xs: &[f64]) -> String {
    let v: Vec<String> = xs.iter().map(|&x| json(x)).collect();
    format!("[{}]", v.join(","))
}

/// A JSON string literal, escaped.
pub fn json_string(t: &str) -> String {
    let mut out = String::with_capacity(t.len() + 2);
    out.push('"');
    for c in t.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
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
                assert_eq!(json(v), text);
            }
            x *= 7.3;
        }
        assert_eq!(Shortest(1e-4).to_string(), "0.0001");
        assert_eq!(Shortest(999_999.0).to_string(), "999999");
        assert_eq!(Shortest(1e6).to_string(), "1e6");
        assert_eq!(Shortest(-2.5e-7).to_string(), "-2.5e-7");
        assert_eq!(Shortest(0.0).to_string(), "0");
        assert_eq!(json(f64::INFINITY), "null");
    }

    #[test]
    fn json_objects_escape_strings_and_keep_order() {
        let text = json_object(&[
            ("b", Json::Num(0.5)),
            ("a", Json::Str("say \"hi\"\n\\")),
            ("n", Json::Int(3)),
            ("x", Json::Raw(json_numbers(&[1e-5, f64::NAN]))),
            ("z", Json::Null),
        ]);
        assert_eq!(
            text,
            r#"{"b":0.5,"a":"say \"hi\"\u000a\\","n":3,"x":[1e-5,null],"z":null}"#
        );
    }
}
