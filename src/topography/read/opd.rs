//! Bruker (formerly Veeco, Wyko) Vision `.opd`: white-light
//! interferometers. Two bytes, then a directory of 24-byte entries (name,
//! type, length, attributes; little endian), the first the directory's own;
//! the blocks follow in the directory's order, each of its declared length.
//! A height raster (an array block named `RAW DATA`, `RAW_DATA`, `OPD`,
//! `Raw` or `SAMPLE_DATA`) is `nx`, `ny`, the item size (1, 2 or 4: u8,
//! i16, f32) and the values stored column by column (x slowest), y running
//! down; a value is in waves of the `Wavelength` block (nm), divided by
//! `Mult`; values that are not finite or at least 32766 (i16) or 1e38 (f32: as an f32, 9.99999968e37)
//! are missing. The pixel size (`Pixel_size`, mm; `Aspect` the ratio dy/dx)
//! gives the intervals. Each raster is a channel (by its block name), the
//! first by default; intensity arrays are not read.

use std::collections::HashMap;

use super::binary::{text, trim, Binary, Fields};
use super::{clip, Ctx, Entry, ReadError, ReadOptions, Source};
use crate::topography::{Metadata, Topography};
use crate::LengthUnit;

/// The registry's entry.
pub(super) const ENTRY: Entry = Entry {
    name: "opd",
    description: "Bruker/Veeco Vision .opd (white-light interferometers)",
    extensions: &["opd"],
    sniff: Some(|head| head.get(2..2 + DIRECTORY.len()) == Some(DIRECTORY)),
    read,
};

/// The format, in errors.
const FORMAT: &str = "Bruker/Veeco .opd";
const DIRECTORY: &[u8] = b"Directory";
/// A directory entry's size (bytes).
const ENTRY_SIZE: u64 = 24;
/// The directory's offset: after a two-byte prelude.
const PRELUDE: u64 = 2;
/// Block types.
const ARRAY: i16 = 3;
const TEXT: i16 = 5;
const SHORT: i16 = 6;
const FLOAT: i16 = 7;
const DOUBLE: i16 = 8;
const LONG: i16 = 12;
/// The longest text block read.
const MAX_TEXT: i32 = 256;
/// The names of the arrays that hold heights (others hold intensities).
const HEIGHT_ARRAYS: [&str; 5] = ["RAW DATA", "RAW_DATA", "OPD", "Raw", "SAMPLE_DATA"];
/// A raster's header: nx, ny, item size (u16 each).
const RASTER_HEADER: u64 = 6;
/// The most height rasters (channels) a file may have: a directory of
/// millions is refused rather than listed.
const MAX_RASTERS: usize = 1024;
/// The scalar and text blocks read (the others are skipped).
const VALUES: [&str; 6] = ["Wavelength", "Mult", "Aspect", "Pixel_size", "Date", "Time"];

/// A scalar or text block's value.
#[derive(Debug, Clone)]
enum Value {
    Number(f64),
    Text(String),
}

/// Reads an `.opd` file of `len` bytes.
fn read(cx: &Ctx, source: &mut dyn Source, len: u64, options: &ReadOptions) -> Result<Topography, ReadError> {
    let mut bin = Binary::new(cx, source, len, FORMAT);
    let head = bin.block("the directory's entry", PRELUDE, ENTRY_SIZE as usize)?;
    let (name, _, length) = entry(&head);
    if name != "Directory" {
        return Err(bin.err("no Directory at the start"));
    }
    let length = u64::try_from(length).unwrap_or(0);
    if length < ENTRY_SIZE || length % ENTRY_SIZE != 0 {
        return Err(bin.err(format!(
            "the directory's length {length} is not a positive multiple of {ENTRY_SIZE} bytes"
        )));
    }
    let count = length / ENTRY_SIZE - 1;
    let first = PRELUDE + ENTRY_SIZE;
    bin.check_within("the directory", first, count, ENTRY_SIZE)?;

    // The directory, streamed: the entries are read a piece at a time
    // (a file can declare millions), and only what the surface needs is
    // kept: the blocks' positions (the sum of the lengths before them),
    // the values of the blocks named in VALUES, and the rasters (at most
    // MAX_RASTERS). Then the values are read at their positions.
    let mut wanted: Vec<(usize, i16, u64, u64)> = Vec::new();
    let mut rasters: Vec<(&'static str, u64, u64)> = Vec::new();
    let mut at = PRELUDE.checked_add(length).ok_or_else(|| bin.err("the directory's length overflows"))?;
    let mut failed = None;
    let mut too_many = 0u64;
    bin.stream("the directory", first, count, ENTRY_SIZE as usize, |raw| {
        if failed.is_some() {
            return;
        }
        // The name by its bytes: no text made of the entries skipped.
        let mut f = Fields::new(raw);
        f.skip(16);
        let (kind, length) = (f.i16(), f.i32());
        let name = trim(&raw[..16]);
        let Ok(length @ 1..) = u64::try_from(length) else {
            return;
        };
        let start = at;
        match at.checked_add(length).filter(|&end| end <= len) {
            Some(end) => at = end,
            None => {
                failed = Some((text(name), start, length));
                return;
            }
        }
        match kind {
            ARRAY => {
                if let Some(&raster) = HEIGHT_ARRAYS.iter().find(|h| h.as_bytes() == name) {
                    if rasters.len() < MAX_RASTERS {
                        rasters.push((raster, start, length));
                    } else {
                        too_many += 1;
                    }
                }
            }
            _ => {
                // A later block of a name replaces an earlier one.
                if let Some(i) = VALUES.iter().position(|v| v.as_bytes() == name) {
                    wanted.retain(|w| w.0 != i);
                    wanted.push((i, kind, start, length));
                }
            }
        }
    })?;
    if let Some((name, start, length)) = failed {
        bin.check_within(&format!("the block {}", clip(&name, 16)), start, length, 1)?;
    }
    if too_many > 0 {
        return Err(bin.err(format!(
            "{} height rasters: at most {MAX_RASTERS} are read",
            too_many + MAX_RASTERS as u64
        )));
    }
    let mut values: HashMap<&'static str, Value> = HashMap::new();
    for (i, kind, start, length) in wanted {
        if let Some(value) = scalar(&mut bin, kind, start, length)? {
            values.insert(VALUES[i], value);
        }
    }
    let number = |name: &str| match values.get(name) {
        Some(Value::Number(v)) => Some(*v),
        _ => None,
    };
    let text_of = |name: &str| match values.get(name) {
        Some(Value::Text(t)) if !t.is_empty() => Some(t.clone()),
        _ => None,
    };
    let wavelength = number("Wavelength")
        .filter(|w| w.is_finite())
        .ok_or_else(|| bin.err("no Wavelength block: the heights' scale is unknown"))?;
    let mult = number("Mult").unwrap_or(1.0);
    if !(mult.is_finite() && mult != 0.0) {
        return Err(bin.err(format!(
            "the Mult block is {mult}: must be a finite number other than 0"
        )));
    }
    let aspect = number("Aspect").unwrap_or(1.0);
    let mm = LengthUnit::Mm.metres();
    let pixel = number("Pixel_size");
    let (dx, dy) = (pixel.map(|p| p * mm), pixel.map(|p| p * aspect * mm));

    let names: Vec<String> = rasters.iter().map(|(name, ..)| name.to_string()).collect();
    let chosen = cx.channel(&names, Some(0), options)?;
    let (_, at, length) = rasters[chosen];
    let header = bin.block("a raster's header", at, RASTER_HEADER as usize)?;
    let mut f = Fields::new(&header);
    let (nx, ny, item) = (f.u16(), f.u16(), f.u16());
    if nx == 0 || ny == 0 {
        return Err(bin.err(format!(
            "the raster {} is {nx} x {ny} points: must be > 0",
            names[chosen]
        )));
    }
    // SurfaceTopography compares the f32 values with 1e38 as an f32
    // (9.99999968e37): a value of f32 1e38 is missing too.
    let limit = match item {
        1 => f64::INFINITY,
        2 => 32766.0,
        4 => f64::from(1e38_f32),
        other => return Err(cx.unsupported(format!("{FORMAT}: {other}-byte raster values (1, 2 and 4 are read)"))),
    };
    let (nx, ny) = (usize::from(nx), usize::from(ny));
    let points = (nx as u64) * (ny as u64);
    if RASTER_HEADER + points * u64::from(item) > length {
        return Err(bin.err(format!(
            "the raster {} ({nx} x {ny} of {item} bytes) is longer than its block ({length} bytes)",
            names[chosen]
        )));
    }
    // Heights in nm: waves · wavelength / Mult.
    let z = wavelength / mult * LengthUnit::Nm.metres();
    let mut heights = cx.heights(|| format!("the raster's {nx} x {ny} points"), points, options)?;
    heights.resize(nx * ny, f64::NAN);
    // Stored x slowest, y from the top: the k-th value is at x = k / ny,
    // y = ny − 1 − k mod ny.
    let mut k = 0;
    bin.stream("the raster", at + RASTER_HEADER, points, usize::from(item), |raw| {
        let v = match *raw {
            [a] => f64::from(a),
            [a, b] => f64::from(i16::from_le_bytes([a, b])),
            [a, b, c, d] => f64::from(f32::from_le_bytes([a, b, c, d])),
            _ => f64::NAN,
        };
        let (x, y) = (k / ny, ny - 1 - k % ny);
        if let Some(h) = heights.get_mut(y * nx + x) {
            *h = if v.is_finite() && v < limit { v * z } else { f64::NAN };
        }
        k += 1;
    })?;

    let date = match (text_of("Date"), text_of("Time")) {
        (Some(date), Some(time)) => Some(format!("{date} {time}")),
        (date, _) => date,
    };
    let metadata = Metadata {
        date,
        channel: Some(names[chosen].clone()),
        channels: names,
        height_unit: Some(format!("waves of {wavelength} nm / {mult}")),
        ..Metadata::default()
    };
    Ok(cx
        .make(heights, (nx, ny), (dx, dy), options, false)?
        .with_metadata(metadata))
}

/// A directory entry's name, type and length.
fn entry(raw: &[u8]) -> (String, i16, i32) {
    let mut f = Fields::new(raw);
    let name = f.text(16);
    (name, f.i16(), f.i32())
}

/// The value of a scalar or text block of type `kind` and `length` bytes
/// at `at`, as its length says (some files declare a type that is not the
/// size of their value); `None` for other blocks.
fn scalar(bin: &mut Binary, kind: i16, at: u64, length: u64) -> Result<Option<Value>, ReadError> {
    let size = match (kind, length) {
        (TEXT, 1..) if length <= MAX_TEXT as u64 => length,
        (SHORT, 2 | 4) | (FLOAT, 2) => length,
        (FLOAT | LONG, 4..) => 4,
        (DOUBLE, 8..) => 8,
        _ => return Ok(None),
    };
    let raw = bin.block("a block", at, size as usize)?;
    let mut f = Fields::new(&raw);
    Ok(Some(match (kind, size) {
        (TEXT, _) => Value::Text(text(&raw)),
        (_, 2) => Value::Number(f64::from(f.i16())),
        (SHORT | LONG, 4) => Value::Number(f64::from(f.i32())),
        (FLOAT, _) => Value::Number(f64::from(f.f32())),
        _ => Value::Number(f.f64()),
    }))
}
