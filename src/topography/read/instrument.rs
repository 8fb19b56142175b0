//! What the readers of the instruments' own binary formats (MetroPro
//! `.dat`, Nanoscope, `.nid`) share: a bounded read of a text header, a
//! grid of binary integers decoded into heights, the unit spellings the
//! files use, and dates.

use std::io::{Read, SeekFrom};

use super::binary::Binary;
use super::{clip, Ctx, ReadError, ReadOptions, Source, CHUNK};
use crate::topography::Topography;
use crate::LengthUnit;

/// The file's text header: its bytes from the start up to and including
/// the first `end` marker (bytes), read piece by piece; or up to
/// `min(len, max)` bytes where the marker is not there (the bound keeps a
/// hostile header's memory small), and whether that is the whole file.
/// The caller says what a missing marker means.
pub(super) fn head(
    cx: &Ctx,
    source: &mut dyn Source,
    len: u64,
    max: u64,
    end: &[u8],
) -> Result<(Vec<u8>, bool), ReadError> {
    let take = len.min(max);
    let mut bytes = Vec::new();
    source.rewind().map_err(|e| cx.io(e))?;
    let mut source = source.take(take);
    let mut piece = vec![0u8; CHUNK];
    loop {
        let got = match source.read(&mut piece) {
            Ok(0) => return Ok((bytes, take == len)),
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(cx.io(e)),
        };
        // Search from where a marker cut by the previous piece can start.
        let from = bytes.len().saturating_sub(end.len());
        bytes.extend_from_slice(&piece[..got]);
        let found = bytes[from..]
            .windows(end.len())
            .position(|w| w.eq_ignore_ascii_case(end));
        if let Some(i) = found {
            bytes.truncate(from + i + end.len());
            return Ok((bytes, false));
        }
    }
}

/// How the integers of a grid are stored.
#[derive(Debug, Clone, Copy)]
pub(super) struct Int {
    /// Bytes an integer: 1, 2, 4 or 8.
    pub size: usize,
    /// Two's complement (else unsigned).
    pub signed: bool,
    /// Big-endian (else little-endian).
    pub big: bool,
}

impl Int {
    /// The value of one item (`bytes.len() == self.size`).
    pub fn decode(self, bytes: &[u8]) -> f64 {
        let mut b = [0u8; 8];
        let n = self.size.min(8).min(bytes.len());
        // Widen to 8 bytes little-endian, sign-extending when signed.
        if self.big {
            for (i, &v) in bytes[..n].iter().rev().enumerate() {
                b[i] = v;
            }
        } else {
            b[..n].copy_from_slice(&bytes[..n]);
        }
        if self.signed && n > 0 && b[n - 1] & 0x80 != 0 {
            b[n..].fill(0xff);
        }
        if self.signed {
            i64::from_le_bytes(b) as f64
        } else {
            u64::from_le_bytes(b) as f64
        }
    }
}

/// The map of a scanning probe file's channel `index` (called `name`):
/// its `nx` × `ny` integers at `offset` ([`grid`], the rows flipped), each
/// `height(v)` metres, over the scan's `size` (m, x and y).
#[allow(clippy::too_many_arguments)]
pub(super) fn channel_map(
    bin: &mut Binary,
    (index, name): (usize, &str),
    offset: u64,
    (nx, ny): (usize, usize),
    int: Int,
    size: (f64, f64),
    options: &ReadOptions,
    height: &dyn Fn(f64) -> f64,
) -> Result<Topography, ReadError> {
    let what = format!("channel {index} ({})", clip(name, 40));
    let heights = grid(
        bin.cx,
        bin.source,
        bin.len,
        bin.format,
        &what,
        offset,
        (nx, ny),
        int,
        true,
        options,
        height,
    )?;
    let (dx, dy) = (size.0 / nx as f64, size.1 / ny as f64);
    bin.cx.make(heights, (nx, ny), (Some(dx), Some(dy)), options, false)
}

/// A grid of `nx × ny` integers stored row after row at `offset`: read
/// into heights by `height` (of the integer's value; NaN = missing),
/// rows in the file's order or reversed (`flip`: the file's first row is
/// the last here). The size is checked against the file's length `len`
/// and [`ReadOptions::max_points`] before anything is allocated; `what`
/// names the data for the errors.
#[allow(clippy::too_many_arguments)]
pub(super) fn grid(
    cx: &Ctx,
    source: &mut dyn Source,
    len: u64,
    format: &'static str,
    what: &str,
    offset: u64,
    (nx, ny): (usize, usize),
    int: Int,
    flip: bool,
    options: &ReadOptions,
    height: &dyn Fn(f64) -> f64,
) -> Result<Vec<f64>, ReadError> {
    let points = (nx as u64).checked_mul(ny as u64).filter(|&n| n > 0);
    let Some(points) = points else {
        return Err(cx.size(format!("{what}: {nx} x {ny} points")));
    };
    let bytes = points.checked_mul(int.size as u64);
    let end = bytes.and_then(|b| b.checked_add(offset));
    match end {
        Some(end) if end <= len => {}
        _ => {
            return Err(cx.format(
                format,
                format!(
                    "{what}: {nx} x {ny} values of {} bytes at byte {offset} end beyond the file's {len} bytes (truncated?)",
                    int.size
                ),
            ))
        }
    }
    let mut heights = cx.heights(|| format!("{what}: {nx} x {ny}"), points, options)?;
    source.seek(SeekFrom::Start(offset)).map_err(|e| cx.io(e))?;
    let mut left = points * int.size as u64;
    let mut buf = vec![0u8; CHUNK - CHUNK % int.size];
    while left > 0 {
        let piece = left.min(buf.len() as u64) as usize;
        source.read_exact(&mut buf[..piece]).map_err(|e| {
            cx.eof_or(e, || {
                cx.format(format, format!("{what}: the data end early (truncated)"))
            })
        })?;
        heights.extend(buf[..piece].chunks_exact(int.size).map(|b| height(int.decode(b))));
        left -= piece as u64;
    }
    if flip {
        for r in 0..ny / 2 {
            let (top, bottom) = heights.split_at_mut((ny - 1 - r) * nx);
            top[r * nx..(r + 1) * nx].swap_with_slice(&mut bottom[..nx]);
        }
    }
    Ok(heights)
}

/// Metres per unit of a length unit as instrument files spell it (`nm`,
/// `um`, `µm` with the micro sign or the Greek mu, Nanoscope's `~m`, `Å`;
/// `A` for ångström where `angstrom_a`), else `None`.
pub(super) fn length_unit(spelling: &str, angstrom_a: bool) -> Option<f64> {
    let unit = match spelling.trim() {
        "km" => LengthUnit::Km,
        "m" => LengthUnit::M,
        "mm" => LengthUnit::Mm,
        "um" | "µm" | "μm" | "~m" => LengthUnit::Um,
        "nm" => LengthUnit::Nm,
        "pm" => LengthUnit::Pm,
        "Å" => LengthUnit::Angstrom,
        "A" if angstrom_a => LengthUnit::Angstrom,
        _ => return None,
    };
    Some(unit.metres())
}

/// The ratio `a / b` of two units' scales, as the nearest power of ten
/// where it is one to 1e-12 (`1e-9 / 1e-6` is not exactly `1e-3` in
/// binary).
pub(super) fn ratio(a: f64, b: f64) -> f64 {
    let r = a / b;
    let decade = r.log10().round();
    let power = 10f64.powf(decade);
    if (r - power).abs() <= 1e-12 * power {
        power
    } else {
        r
    }
}

/// `seconds` since 1970-01-01 00:00 UTC as ISO 8601 (`2011-07-23T16:49:36Z`),
/// with `zone` (`"Z"` or `"+00:00"`) after the time. Days to a civil date
/// by H. Hinnant's algorithm (public domain): the library has no date
/// crate, and a dependency for one line of metadata is not worth it. The
/// X3P writer's date is this too.
pub(in crate::topography) fn iso_date_in(seconds: i64, zone: &str) -> String {
    let (days, secs) = (seconds.div_euclid(86_400), seconds.rem_euclid(86_400));
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}{zone}",
        secs / 3600,
        secs / 60 % 60,
        secs % 60
    )
}

/// [`iso_date_in`] with `Z` for UTC.
pub(super) fn iso_date(seconds: i64) -> String {
    iso_date_in(seconds, "Z")
}

/// Latin-1 bytes as text (every byte is a character: never fails).
pub(super) fn latin1(bytes: &[u8]) -> String {
    bytes.iter().map(|&b| char::from(b)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates() {
        assert_eq!(iso_date(0), "1970-01-01T00:00:00Z");
        assert_eq!(iso_date(1_311_439_776), "2011-07-23T16:49:36Z");
        assert_eq!(iso_date(951_782_400), "2000-02-29T00:00:00Z");
        assert_eq!(iso_date(-1), "1969-12-31T23:59:59Z");
    }

    #[test]
    fn integers() {
        let i = |size, signed, big| Int { size, signed, big };
        assert_eq!(i(2, true, false).decode(&[0xff, 0xff]), -1.0);
        assert_eq!(i(2, false, false).decode(&[0xff, 0xff]), 65535.0);
        assert_eq!(i(4, true, true).decode(&[0x80, 0, 0, 0]), f64::from(i32::MIN));
        assert_eq!(i(4, true, true).decode(&[0, 0, 1, 2]), 258.0);
        assert_eq!(i(1, true, false).decode(&[0x80]), -128.0);
    }

    #[test]
    fn units() {
        assert_eq!(length_unit("~m", true), Some(1e-6));
        assert_eq!(length_unit("A", false), None);
        assert_eq!(ratio(1e-9, 1e-6), 1e-3);
        assert_eq!(ratio(2.0, 1.0), 2.0);
    }
}
