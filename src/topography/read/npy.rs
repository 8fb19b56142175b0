//! NumPy `.npy` (format versions 1–3): a 1-D array is a profile, a 2-D
//! array a map of `shape = (ny, nx)` (rows = y); `f4` or `f8`, little or
//! big endian, C or Fortran order. The file gives no intervals: they come
//! from the options.

use super::{clip, Ctx, Entry, ReadError, ReadOptions, Source, CHUNK};
use crate::topography::Topography;

/// The registry's entry.
pub(super) const ENTRY: Entry = Entry {
    name: "npy",
    description: "NumPy .npy (f4 or f8; 1-D profile, 2-D map)",
    extensions: &["npy"],
    sniff: Some(|head| head.starts_with(b"\x93NUMPY")),
    read,
};

/// The bound on the header (bytes).
const MAX_HEADER: usize = 1 << 16;

fn npy_err(cx: &Ctx, detail: impl Into<String>) -> ReadError {
    ReadError::Npy {
        path: cx.path(),
        detail: detail.into(),
    }
}

/// Reads a `.npy` file of `len` bytes from `source`: the header, then the
/// data decoded piece by piece into the heights (the data are never held
/// as bytes).
pub(super) fn read(
    cx: &Ctx,
    source: &mut dyn Source,
    len: u64,
    options: &ReadOptions,
) -> Result<Topography, ReadError> {
    let truncated = || npy_err(cx, "truncated in the preamble");
    let mut preamble = [0u8; 8];
    source.read_exact(&mut preamble).map_err(|e| cx.eof_or(e, truncated))?;
    if &preamble[..6] != b"\x93NUMPY" {
        return Err(npy_err(cx, "no \\x93NUMPY magic at the start"));
    }
    let (header, start) = match preamble[6] {
        1 => {
            let mut b = [0u8; 2];
            source.read_exact(&mut b).map_err(|e| cx.eof_or(e, truncated))?;
            (usize::from(u16::from_le_bytes(b)), 10u64)
        }
        2 | 3 => {
            let mut b = [0u8; 4];
            source.read_exact(&mut b).map_err(|e| cx.eof_or(e, truncated))?;
            (u32::from_le_bytes(b) as usize, 12u64)
        }
        major => return Err(cx.unsupported(format!(".npy format version {major}"))),
    };
    if header > MAX_HEADER || header as u64 > len.saturating_sub(start) {
        return Err(npy_err(cx, format!("a header of {header} bytes")));
    }
    let mut text = vec![0u8; header];
    source.read_exact(&mut text).map_err(|e| cx.eof_or(e, truncated))?;
    let data_len = len - start - header as u64;
    let header = std::str::from_utf8(&text).map_err(|_| npy_err(cx, "the header is not text"))?;
    let Header {
        descr,
        fortran_order,
        shape,
    } = parse_header(header).map_err(|e| npy_err(cx, e))?;

    let (big_endian, size) = match descr.as_bytes() {
        [order @ (b'<' | b'>' | b'='), b'f', size @ (b'4' | b'8')] => (
            *order == b'>' || (*order == b'=' && cfg!(target_endian = "big")),
            usize::from(size - b'0'),
        ),
        _ => {
            return Err(cx.unsupported(format!(
                "dtype '{}' (only float32 and float64, f4 and f8, are read)",
                clip(&descr, 40)
            )))
        }
    };
    let (nx, ny) = match shape[..] {
        [nx] => (nx, 1),
        [ny, nx] => (nx, ny),
        _ => {
            return Err(cx.unsupported(format!(
                "a {}-dimensional array (a profile is 1-D, a map 2-D)",
                shape.len()
            )))
        }
    };
    let n = nx
        .checked_mul(ny)
        .filter(|&n| n > 0)
        .ok_or_else(|| cx.size(format!("an array of shape {shape:?}")))?;
    let expected = (n as u64).saturating_mul(size as u64);
    if data_len != expected {
        return Err(cx.size(format!(
            "shape {shape:?} of {descr} makes {expected} bytes of data, the file holds {data_len}"
        )));
    }
    let mut heights = cx.heights(|| format!("the shape {shape:?}"), n as u64, options)?;
    let z = options.z_unit;
    let value = |b: &[u8]| -> f64 {
        match (size, big_endian, b) {
            (4, false, &[a, b, c, d]) => f64::from(f32::from_le_bytes([a, b, c, d])),
            (4, true, &[a, b, c, d]) => f64::from(f32::from_be_bytes([a, b, c, d])),
            (8, false, &[a, b, c, d, e, f, g, h]) => f64::from_le_bytes([a, b, c, d, e, f, g, h]),
            (8, true, &[a, b, c, d, e, f, g, h]) => f64::from_be_bytes([a, b, c, d, e, f, g, h]),
            _ => f64::NAN,
        }
    };
    // Column-major (a map in Fortran order): the k-th stored element is
    // (row k mod ny, column k / ny), scattered to its row-major place.
    let transpose = fortran_order && ny > 1 && nx > 1;
    if transpose {
        heights.resize(n, f64::NAN);
    }
    let mut buf = vec![0u8; CHUNK];
    let mut k = 0;
    let mut left = data_len;
    while left > 0 {
        let piece = left.min(CHUNK as u64) as usize;
        source
            .read_exact(&mut buf[..piece])
            .map_err(|e| cx.eof_or(e, || cx.size("the data end early (truncated)")))?;
        for item in buf[..piece].chunks_exact(size) {
            let h = z * value(item);
            if transpose {
                heights[(k % ny) * nx + k / ny] = h;
            } else {
                heights.push(h);
            }
            k += 1;
        }
        left -= piece as u64;
    }
    cx.make(heights, (nx, ny), (None, None), options, shape.len() == 1)
}

/// The fields of a `.npy` header that matter here.
#[derive(Debug)]
struct Header {
    descr: String,
    fortran_order: bool,
    shape: Vec<usize>,
}

/// Parses the header, a Python dict literal such as
/// `{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }`.
fn parse_header(text: &str) -> Result<Header, String> {
    let mut p = Parser {
        s: text.as_bytes(),
        i: 0,
    };
    let (mut descr, mut fortran_order, mut shape) = (None, None, None);
    p.expect(b'{')?;
    loop {
        p.skip_ws();
        if p.eat(b'}') {
            break;
        }
        let key = p.string()?;
        p.skip_ws();
        p.expect(b':')?;
        p.skip_ws();
        match key.as_str() {
            "descr" => {
                if p.peek() == Some(b'[') {
                    return Err("a structured dtype (only f4 and f8 arrays are read)".into());
                }
                descr = Some(p.string()?);
            }
            "fortran_order" => fortran_order = Some(p.boolean()?),
            "shape" => shape = Some(p.tuple()?),
            other => return Err(format!("unknown header key '{}'", clip(other, 40))),
        }
        p.skip_ws();
        if !p.eat(b',') {
            p.skip_ws();
            p.expect(b'}')?;
            break;
        }
    }
    match (descr, fortran_order, shape) {
        (Some(descr), Some(fortran_order), Some(shape)) => Ok(Header {
            descr,
            fortran_order,
            shape,
        }),
        _ => Err("the header lacks descr, fortran_order or shape".into()),
    }
}

/// A cursor over the header's bytes.
struct Parser<'a> {
    s: &'a [u8],
    i: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<u8> {
        self.s.get(self.i).copied()
    }

    fn skip_ws(&mut self) {
        while self.peek().is_some_and(|c| c.is_ascii_whitespace()) {
            self.i += 1;
        }
    }

    fn eat(&mut self, c: u8) -> bool {
        let found = self.peek() == Some(c);
        self.i += usize::from(found);
        found
    }

    fn expect(&mut self, c: u8) -> Result<(), String> {
        if self.eat(c) {
            Ok(())
        } else {
            Err(format!(
                "malformed header: expected '{}' at byte {}",
                char::from(c),
                self.i
            ))
        }
    }

    fn string(&mut self) -> Result<String, String> {
        let quote = match self.peek() {
            Some(q @ (b'\'' | b'"')) => q,
            _ => return Err(format!("malformed header: expected a string at byte {}", self.i)),
        };
        self.i += 1;
        let start = self.i;
        while let Some(c) = self.peek() {
            self.i += 1;
            if c == quote {
                return Ok(String::from_utf8_lossy(&self.s[start..self.i - 1]).into_owned());
            }
        }
        Err("malformed header: an unterminated string".into())
    }

    fn boolean(&mut self) -> Result<bool, String> {
        for (word, value) in [(&b"True"[..], true), (&b"False"[..], false)] {
            if self.s[self.i..].starts_with(word) {
                self.i += word.len();
                return Ok(value);
            }
        }
        Err(format!("malformed header: expected True or False at byte {}", self.i))
    }

    fn tuple(&mut self) -> Result<Vec<usize>, String> {
        self.expect(b'(')?;
        let mut items = Vec::new();
        loop {
            self.skip_ws();
            if self.eat(b')') {
                return Ok(items);
            }
            let start = self.i;
            while self.peek().is_some_and(|c| c.is_ascii_digit()) {
                self.i += 1;
            }
            let digits = std::str::from_utf8(&self.s[start..self.i]).unwrap_or("");
            let item = digits
                .parse::<usize>()
                .map_err(|_| format!("malformed header: a shape item at byte {start}"))?;
            items.push(item);
            self.eat(b'L'); // Python 2's long integers
            self.skip_ws();
            if !self.eat(b',') {
                self.skip_ws();
                self.expect(b')')?;
                return Ok(items);
            }
        }
    }
}
