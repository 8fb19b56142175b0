//! Structure-aware text: a grid of rows (a matrix, `x z` pairs or `x y z`
//! triples on a regular or jittered grid, in shuffled order) written with
//! fuzzed separators (`,` `;` tab space), line ends (LF, CRLF, lone CR),
//! numbers in several spellings, `nan` and `inf`, then spliced with fuzzed
//! tokens (comments, blank lines, a BOM, words, non-UTF-8 bytes). Read by
//! `read_bytes` as `Format::TEXT` and as `Format::MATRIX`; a surface read
//! keeps the invariant of surface_check.rs.
#![no_main]

#[path = "surface_check.rs"]
mod surface_check;

use arbitrary::Arbitrary;
use ke_friction::topography::Format;
use libfuzzer_sys::fuzz_target;
use surface_check::OptionsSpec;

/// A number as the fuzzer spells it.
#[derive(Debug, Clone, Copy, Arbitrary)]
enum Value {
    /// k/16, written plainly.
    Small(i16),
    /// Special spellings: nan, inf, huge exponents, signs, hex.
    Special(u8),
    /// Any bits, in `{:e}` (NaN and inf included).
    Raw(f64),
}

impl Value {
    fn text(self) -> String {
        match self {
            Value::Small(k) => format!("{}", k as f64 / 16.0),
            Value::Special(k) => {
                const S: [&str; 16] = [
                    "nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e999", "-1e999", "1e-999", "+1.5", ".5", "5.",
                    "0x1f", "1e", "--1", "1_0",
                ];
                S[k as usize % S.len()].to_string()
            }
            Value::Raw(v) => format!("{v:e}"),
        }
    }
}

#[derive(Debug, Clone, Copy, Arbitrary)]
enum Sep {
    Space,
    Spaces,
    Tab,
    Comma,
    Semicolon,
    CommaSpace,
}

impl Sep {
    fn text(self) -> &'static str {
        match self {
            Sep::Space => " ",
            Sep::Spaces => "   ",
            Sep::Tab => "\t",
            Sep::Comma => ",",
            Sep::Semicolon => ";",
            Sep::CommaSpace => ", ",
        }
    }
}

#[derive(Debug, Clone, Copy, Arbitrary)]
enum Eol {
    Lf,
    CrLf,
    Cr,
}

impl Eol {
    fn text(self) -> &'static str {
        match self {
            Eol::Lf => "\n",
            Eol::CrLf => "\r\n",
            Eol::Cr => "\r",
        }
    }
}

/// The layout of the rows.
#[derive(Debug, Clone, Copy, Arbitrary)]
enum Layout {
    /// `cols` heights per row.
    Matrix,
    /// `x z`: x = i·step (+ jitter).
    Pairs,
    /// `x y z` on a grid of `cols` x positions (+ jitter).
    Triples,
}

/// A token spliced into the text.
#[derive(Debug, Clone, Arbitrary)]
enum Token {
    Value(Value),
    Sep(Sep),
    Eol(Eol),
    Comment(String),
    Word(String),
    Bom,
    /// Bytes that are often not UTF-8.
    Bytes(Vec<u8>),
}

#[derive(Debug, Arbitrary)]
struct Input {
    options: OptionsSpec,
    bom: bool,
    header_comment: Option<String>,
    layout: Layout,
    /// 1 … 16 columns of a matrix, x positions of a grid.
    cols: u8,
    /// 1 … 64 rows (matrix), points (pairs) or y positions (triples).
    rows: u8,
    values: Vec<Value>,
    sep: Sep,
    eol: Eol,
    final_eol: bool,
    /// The grid step (2^(k/4)) and a jitter in 1/1000ths of it.
    step: i8,
    jitter: Vec<i8>,
    /// Swap rows i and j (of the rows written).
    swaps: Vec<(u8, u8)>,
    /// Tokens inserted at byte positions (mod the length).
    splice: Vec<(u16, Token)>,
}

fuzz_target!(|input: Input| {
    let cols = 1 + input.cols as usize % 16;
    let rows = 1 + input.rows as usize % 64;
    let step = 2f64.powf(input.step as f64 / 4.0);
    let mut vals = input.values.iter().copied().cycle();
    let mut jit = input.jitter.iter().copied().cycle();
    let mut jitter = || jit.next().map_or(0.0, |j| j as f64 / 1000.0 * step);
    let mut height = || vals.next().map_or("1".to_string(), Value::text);
    let mut lines: Vec<Vec<String>> = vec![];
    match input.layout {
        Layout::Matrix => {
            for _ in 0..rows {
                lines.push((0..cols).map(|_| height()).collect());
            }
        }
        Layout::Pairs => {
            for i in 0..rows {
                lines.push(vec![format!("{}", i as f64 * step + jitter()), height()]);
            }
        }
        Layout::Triples => {
            for j in 0..rows.min(16) {
                for i in 0..cols {
                    lines.push(vec![
                        format!("{}", i as f64 * step + jitter()),
                        format!("{}", j as f64 * step + jitter()),
                        height(),
                    ]);
                }
            }
        }
    }
    for &(a, b) in input.swaps.iter().take(16) {
        let n = lines.len();
        lines.swap(a as usize % n, b as usize % n);
    }

    let mut bytes: Vec<u8> = vec![];
    if input.bom {
        bytes.extend("\u{feff}".as_bytes());
    }
    if let Some(c) = &input.header_comment {
        bytes.extend(format!("# {c}{}", input.eol.text()).as_bytes());
    }
    for (k, line) in lines.iter().enumerate() {
        bytes.extend(line.join(input.sep.text()).as_bytes());
        if k + 1 < lines.len() || input.final_eol {
            bytes.extend(input.eol.text().as_bytes());
        }
    }
    for (at, token) in input.splice.iter().take(16) {
        let at = *at as usize % (bytes.len() + 1);
        let insert: Vec<u8> = match token {
            Token::Value(v) => v.text().into_bytes(),
            Token::Sep(s) => s.text().as_bytes().to_vec(),
            Token::Eol(e) => e.text().as_bytes().to_vec(),
            Token::Comment(c) => format!("\n# {c}\n").into_bytes(),
            Token::Word(w) => w.clone().into_bytes(),
            Token::Bom => "\u{feff}".as_bytes().to_vec(),
            Token::Bytes(b) => b.iter().take(8).copied().collect(),
        };
        bytes.splice(at..at, insert);
    }

    for format in [Format::TEXT, Format::MATRIX] {
        let options = input.options.options(Some(format));
        surface_check::read(&bytes, "surface.txt", &options);
    }
});
