//! Structure-aware `.npy`: an `arbitrary` header (format version, descr,
//! fortran_order, shape including huge and many-dimensional ones, key
//! order, quotes, padding, a declared header length right or off) and data
//! (values of the dtype, or bytes, of a length right or off), read by
//! `read_bytes` as `surface.npy`; a surface read keeps the invariant of
//! surface_check.rs. Raw bytes rarely make a header that parses: this
//! target reaches the dtype, shape, size and order handling every run.
#![no_main]

#[path = "surface_check.rs"]
mod surface_check;

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use surface_check::OptionsSpec;

/// The most data bytes generated for an exact length.
const MAX_DATA: usize = 1 << 16;

#[derive(Debug, Clone, Copy, Arbitrary)]
enum Version {
    V1,
    V2,
    V3,
    Other(u8, u8),
}

#[derive(Debug, Clone, Arbitrary)]
enum Descr {
    /// `<f4`, `<f8`, `>f4`, `>f8`, `=f4`, `=f8`, `|f8`, `<f2`, `<i4`, `f8`.
    Usual(u8),
    /// `[('a', '<f8')]`: a structured dtype, unquoted.
    Structured,
    Other(String),
}

impl Descr {
    fn text(&self, quote: char) -> String {
        const USUAL: [&str; 10] = ["<f4", "<f8", ">f4", ">f8", "=f4", "=f8", "|f8", "<f2", "<i4", "f8"];
        match self {
            Descr::Usual(k) => format!("{quote}{}{quote}", USUAL[*k as usize % USUAL.len()]),
            Descr::Structured => "[('a', '<f8')]".to_string(),
            Descr::Other(s) => format!("{quote}{s}{quote}"),
        }
    }

    /// (big endian, value size) of a float dtype.
    fn float(&self) -> Option<(bool, usize)> {
        match self {
            Descr::Usual(k) => match k % 10 {
                0 | 4 => Some((false, 4)),
                1 | 5 => Some((false, 8)),
                2 => Some((true, 4)),
                3 => Some((true, 8)),
                _ => None,
            },
            _ => None,
        }
    }
}

/// One shape item.
#[derive(Debug, Clone, Arbitrary)]
enum Dim {
    /// 0 … 63.
    Small(u8),
    Huge(u8),
    Text(String),
}

impl Dim {
    fn text(&self) -> String {
        const HUGE: [&str; 8] = [
            "4294967296",
            "18446744073709551615",
            "18446744073709551616",
            "9223372036854775807",
            "1048577",
            "3L",
            "-1",
            "",
        ];
        match self {
            Dim::Small(k) => (k % 64).to_string(),
            Dim::Huge(k) => HUGE[*k as usize % HUGE.len()].to_string(),
            Dim::Text(s) => s.chars().take(24).collect(),
        }
    }
}

#[derive(Debug, Clone, Copy, Arbitrary)]
enum Fortran {
    True,
    False,
    Missing,
    Garbage,
}

/// What follows the dict: spaces and a newline to a multiple of 64 bytes
/// (as NumPy writes), nothing, or a few bytes.
#[derive(Debug, Clone, Copy, Arbitrary)]
enum Padding {
    Aligned,
    None,
    Spaces(u8),
    Tabs(u8),
}

/// A value of the data.
#[derive(Debug, Clone, Copy, Arbitrary)]
enum Value {
    /// k/1024.
    Small(i16),
    Special(u8),
    Raw(f64),
}

impl Value {
    fn get(self) -> f64 {
        match self {
            Value::Small(k) => k as f64 / 1024.0,
            Value::Special(k) => {
                const S: [f64; 9] = [
                    f64::NAN,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::MAX,
                    f64::MIN_POSITIVE,
                    4e38,
                    -0.0,
                    5e-324,
                    1e300,
                ];
                S[k as usize % S.len()]
            }
            Value::Raw(v) => v,
        }
    }
}

/// The data's length: what the shape makes, that ± a few, or the values
/// as they are.
#[derive(Debug, Clone, Copy, Arbitrary)]
enum Len {
    Exact,
    Delta(i8),
    Raw,
}

#[derive(Debug, Arbitrary)]
struct Input {
    options: OptionsSpec,
    bad_magic: bool,
    version: Version,
    descr: Descr,
    double_quotes: bool,
    fortran: Fortran,
    shape: Vec<Dim>,
    trailing_comma: bool,
    /// An extra key (unknown to the reader).
    extra: Option<String>,
    /// Which of the 6 orders of the three keys.
    order: u8,
    padding: Padding,
    /// Added to the header length written in the preamble.
    header_delta: Option<i16>,
    values: Vec<Value>,
    len: Len,
}

fuzz_target!(|input: Input| {
    let options = input.options.options(None);
    let q = if input.double_quotes { '"' } else { '\'' };
    let shape: Vec<String> = input.shape.iter().take(6).map(Dim::text).collect();
    let shape_text = match (shape.len(), input.trailing_comma) {
        (1, _) | (_, true) => format!("({},)", shape.join(", ")),
        _ => format!("({})", shape.join(", ")),
    };
    let fortran = match input.fortran {
        Fortran::True => Some("True"),
        Fortran::False => Some("False"),
        Fortran::Missing => None,
        Fortran::Garbage => Some("1"),
    };
    let mut items = vec![format!("{q}descr{q}: {}", input.descr.text(q))];
    if let Some(f) = fortran {
        items.push(format!("{q}fortran_order{q}: {f}"));
    }
    items.push(format!("{q}shape{q}: {shape_text}"));
    let k = input.order as usize % 6;
    let m = items.len();
    items.rotate_left(k % m);
    if k >= 3 {
        items.reverse();
    }
    if let Some(extra) = &input.extra {
        items.push(format!("{q}{extra}{q}: 0"));
    }
    let mut header = format!("{{{}, }}", items.join(", "));

    let (major, minor, len_bytes) = match input.version {
        Version::V1 => (1, 0, 2),
        Version::V2 => (2, 0, 4),
        Version::V3 => (3, 0, 4),
        Version::Other(a, b) => (a, b, 2),
    };
    let preamble = 6 + 2 + len_bytes;
    match input.padding {
        Padding::Aligned => {
            let total = (preamble + header.len() + 1).div_ceil(64) * 64;
            header.extend(std::iter::repeat_n(' ', total - preamble - header.len() - 1));
            header.push('\n');
        }
        Padding::None => {}
        Padding::Spaces(n) => header.extend(std::iter::repeat_n(' ', n as usize % 80)),
        Padding::Tabs(n) => header.extend(std::iter::repeat_n('\t', n as usize % 8)),
    }
    let declared = (header.len() as i64 + input.header_delta.unwrap_or(0) as i64).max(0) as u64;

    let mut bytes = if input.bad_magic {
        b"\x93NUMPz".to_vec()
    } else {
        b"\x93NUMPY".to_vec()
    };
    bytes.extend([major, minor]);
    if len_bytes == 2 {
        bytes.extend((declared as u16).to_le_bytes());
    } else {
        bytes.extend((declared as u32).to_le_bytes());
    }
    bytes.extend(header.as_bytes());

    // The data: values in the dtype (f8 little endian when not a float one).
    let (big, size) = input.descr.float().unwrap_or((false, 8));
    let dims: Option<Vec<usize>> = shape.iter().map(|d| d.parse::<usize>().ok()).collect();
    let want = dims
        .and_then(|d| d.iter().try_fold(1usize, |n, &d| n.checked_mul(d)))
        .filter(|&n| n.saturating_mul(size) <= MAX_DATA);
    let values: Vec<f64> = input.values.iter().map(|v| v.get()).collect();
    let count = match (input.len, want) {
        (Len::Exact, Some(n)) => n,
        (Len::Delta(d), Some(n)) => n.saturating_add_signed(d as isize),
        _ => values.len(),
    };
    let source: Box<dyn Iterator<Item = f64>> = if values.is_empty() {
        Box::new(std::iter::repeat(0.25))
    } else {
        Box::new(values.iter().copied().cycle())
    };
    for v in source.take(count) {
        match (size, big) {
            (4, false) => bytes.extend((v as f32).to_le_bytes()),
            (4, true) => bytes.extend((v as f32).to_be_bytes()),
            (_, false) => bytes.extend(v.to_le_bytes()),
            (_, true) => bytes.extend(v.to_be_bytes()),
        }
    }
    if let Len::Delta(d) = input.len {
        // An odd number of bytes off, sometimes.
        if d % 3 == 0 && !bytes.is_empty() {
            bytes.pop();
        }
    }
    surface_check::read(&bytes, "surface.npy", &options);
});
