//! What the readers of instruments' binary files share: fixed-layout
//! little-endian header fields ([`Fields`]), blocks read at an offset
//! checked against the file's length before anything is allocated
//! ([`Binary::block`]), and the height data decoded piece by piece
//! ([`Binary::stream`]). Hand-written rather than a parsing crate: the
//! layouts are a few dozen fixed fields, and every offset and size must be
//! checked against the file's length with the file's own words in the
//! error, which a generic decoder would not say.

use std::io::SeekFrom;

use super::{Ctx, ReadError, Source, CHUNK};
use crate::LengthUnit;

/// A binary file being read: its context, content and length, and the
/// format's description for the errors ([`ReadError::Format`]).
pub(super) struct Binary<'c, 'p, 's> {
    pub cx: &'c Ctx<'p>,
    pub source: &'s mut dyn Source,
    pub len: u64,
    pub format: &'static str,
}

impl<'c, 'p, 's> Binary<'c, 'p, 's> {
    /// The file `source` of `len` bytes, of the format `format` (its
    /// description, in errors).
    pub fn new(cx: &'c Ctx<'p>, source: &'s mut dyn Source, len: u64, format: &'static str) -> Self {
        Binary {
            cx,
            source,
            len,
            format,
        }
    }
}

impl Binary<'_, '_, '_> {
    /// A malformed file.
    pub fn err(&self, detail: impl Into<String>) -> ReadError {
        self.cx.format(self.format, detail)
    }

    /// `count` items of `size` bytes from byte `offset` (`what`, for the
    /// error) lie within the file: their end, or an error saying the file
    /// is truncated.
    pub fn check_within(&self, what: &str, offset: u64, count: u64, size: u64) -> Result<u64, ReadError> {
        let end = count
            .checked_mul(size)
            .and_then(|bytes| bytes.checked_add(offset))
            .filter(|&end| end <= self.len);
        end.ok_or_else(|| {
            self.err(format!(
                "{what} ({count} x {size} bytes from byte {offset}) runs past the end of the file \
                 ({} bytes): the file is truncated or its header is wrong",
                self.len
            ))
        })
    }

    /// The `n` bytes at `offset` (`what`, for the error), checked against
    /// the file's length first.
    pub fn block(&mut self, what: &str, offset: u64, n: usize) -> Result<Vec<u8>, ReadError> {
        self.check_within(what, offset, n as u64, 1)?;
        let mut bytes = self.cx.vec(n as u64)?;
        bytes.resize(n, 0);
        self.source.seek(SeekFrom::Start(offset)).map_err(|e| self.cx.io(e))?;
        let cx = self.cx;
        let format = self.format;
        self.source.read_exact(&mut bytes).map_err(|e| {
            cx.eof_or(e, || {
                cx.format(format, format!("{what} ends early: the file is truncated"))
            })
        })?;
        Ok(bytes)
    }

    /// Streams `count` items of `size` bytes from `offset` (checked against
    /// the file's length first) to `each`, in pieces of whole items.
    /// Memory: one piece.
    pub fn stream(
        &mut self,
        what: &str,
        offset: u64,
        count: u64,
        size: usize,
        mut each: impl FnMut(&[u8]),
    ) -> Result<(), ReadError> {
        self.check_within(what, offset, count, size as u64)?;
        self.source.seek(SeekFrom::Start(offset)).map_err(|e| self.cx.io(e))?;
        let per_piece = (CHUNK / size).max(1);
        let mut buf = vec![0u8; per_piece * size];
        let mut left = count;
        while left > 0 {
            let items = left.min(per_piece as u64) as usize;
            let piece = &mut buf[..items * size];
            let (cx, format) = (self.cx, self.format);
            self.source.read_exact(piece).map_err(|e| {
                cx.eof_or(e, || {
                    cx.format(format, format!("{what} ends early: the file is truncated"))
                })
            })?;
            for item in piece.chunks_exact(size) {
                each(item);
            }
            left -= items as u64;
        }
        Ok(())
    }
}

/// Little-endian fields read in order from a header's bytes. Reading past
/// the end gives zeros (the readers size their headers before reading
/// them, so this does not happen; it never panics).
pub(super) struct Fields<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Fields<'a> {
    /// The fields of `bytes` from the start.
    pub fn new(bytes: &'a [u8]) -> Fields<'a> {
        Fields { bytes, at: 0 }
    }

    /// The next `N` bytes.
    pub fn take<const N: usize>(&mut self) -> [u8; N] {
        let mut out = [0u8; N];
        if let Some(s) = self.at.checked_add(N).and_then(|end| self.bytes.get(self.at..end)) {
            out.copy_from_slice(s);
        }
        self.at = self.at.saturating_add(N);
        out
    }

    /// Skips `n` bytes.
    pub fn skip(&mut self, n: usize) {
        self.at = self.at.saturating_add(n);
    }

    pub fn u8(&mut self) -> u8 {
        self.take::<1>()[0]
    }

    pub fn u16(&mut self) -> u16 {
        u16::from_le_bytes(self.take())
    }

    pub fn i16(&mut self) -> i16 {
        i16::from_le_bytes(self.take())
    }

    pub fn u32(&mut self) -> u32 {
        u32::from_le_bytes(self.take())
    }

    pub fn i32(&mut self) -> i32 {
        i32::from_le_bytes(self.take())
    }

    pub fn f32(&mut self) -> f32 {
        f32::from_le_bytes(self.take())
    }

    pub fn f64(&mut self) -> f64 {
        f64::from_le_bytes(self.take())
    }

    /// A fixed-size text field of `n` bytes (see [`text`]).
    pub fn text(&mut self, n: usize) -> String {
        let start = self.at.min(self.bytes.len());
        let end = self.at.saturating_add(n).min(self.bytes.len());
        self.at = self.at.saturating_add(n);
        text(&self.bytes[start..end])
    }
}

/// A fixed-size text field: ISO 8859-1 (each byte a character), NULs and
/// then spaces trimmed at both ends.
pub(super) fn text(bytes: &[u8]) -> String {
    let s: String = bytes.iter().map(|&b| char::from(b)).collect();
    s.trim_matches('\0').trim_matches(' ').to_string()
}

/// A fixed-size field's bytes trimmed as [`text`] trims them: NULs at
/// both ends, then spaces.
pub(super) fn trim(bytes: &[u8]) -> &[u8] {
    fn strip(mut bytes: &[u8], c: u8) -> &[u8] {
        while let [first, rest @ ..] = bytes {
            if *first != c {
                break;
            }
            bytes = rest;
        }
        while let [rest @ .., last] = bytes {
            if *last != c {
                break;
            }
            bytes = rest;
        }
        bytes
    }
    strip(strip(bytes, 0), b' ')
}

/// Metres per unit of a length unit as instruments write it (`"mm"`,
/// `"µm"` with either micro sign, `"um"`, `"nm"`, `"Å"`, ...), by
/// [`LengthUnit::from_symbol`].
pub(super) fn metres_per(unit: &str) -> Option<f64> {
    LengthUnit::from_symbol(unit).ok().map(LengthUnit::metres)
}
