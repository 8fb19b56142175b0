//! Alicona `.al3d` (Alicona Imaging, now Bruker Alicona: focus-variation
//! microscopes such as the InfiniteFocus). A signature, then tags of 52
//! bytes (a 20-byte key, a 30-byte value as text, CR LF): `Version`,
//! `TagCount`, then that many (`Cols`, `Rows`, `PixelSizeXMeter`,
//! `PixelSizeYMeter`, `DepthImageOffset`, `InvalidPixelValue`, ...), a
//! 256-byte comment; the depth image at `DepthImageOffset`: `Rows` rows of
//! f32 heights in metres (rows = y), each padded to a multiple of 8 bytes.
//! NaN, or the `InvalidPixelValue` (to 1.5e-7 relative), marks a missing
//! point.

use std::collections::HashMap;

use super::binary::{text, trim, Binary};
use super::{clip, Ctx, Entry, ReadError, ReadOptions, Source};
use crate::topography::{Metadata, Topography};

/// The registry's entry.
pub(super) const ENTRY: Entry = Entry {
    name: "al3d",
    description: "Alicona .al3d (focus-variation microscopes)",
    extensions: &["al3d"],
    sniff: Some(|head| head.starts_with(MAGIC)),
    read,
};

/// The format, in errors.
const FORMAT: &str = "Alicona .al3d";
const MAGIC: &[u8] = b"AliconaImaging\x00\r\n";
/// A tag's size: key, value, CR LF (bytes).
const TAG: usize = 52;
const KEY: usize = 20;
/// The comment after the tags (bytes).
const COMMENT: u64 = 256;
/// The tags read (the others are skipped).
const KEYS: [&str; 7] = [
    "Cols",
    "Rows",
    "PixelSizeXMeter",
    "PixelSizeYMeter",
    "DepthImageOffset",
    "InvalidPixelValue",
    "CreatingApplication",
];
/// A value within this fraction of the `InvalidPixelValue` is missing.
const INVALID_RELTOL: f64 = 1.5e-7;

/// Reads an `.al3d` file of `len` bytes.
fn read(cx: &Ctx, source: &mut dyn Source, len: u64, options: &ReadOptions) -> Result<Topography, ReadError> {
    let mut bin = Binary::new(cx, source, len, FORMAT);
    let head = bin.block("the signature and first tags", 0, MAGIC.len() + 2 * TAG)?;
    if !head.starts_with(MAGIC) {
        return Err(bin.err("no AliconaImaging signature at the start"));
    }
    let first = |bin: &Binary, i: usize, key: &str| -> Result<u64, ReadError> {
        let at = MAGIC.len() + i * TAG;
        let (k, v) = tag(bin, &head[at..at + TAG], i)?;
        if k != key {
            return Err(bin.err(format!("tag {i} is \"{}\", not {key}", clip(&k, KEY))));
        }
        v.trim().parse::<u64>().map_err(|_| {
            bin.err(format!(
                "the {key} tag's value \"{}\" is not a whole number",
                clip(&v, 30)
            ))
        })
    };
    let _version = first(&bin, 0, "Version")?;
    let count = first(&bin, 1, "TagCount")?;
    let start = (MAGIC.len() + 2 * TAG) as u64;
    let end = bin.check_within("the tags", start, count, TAG as u64)?;
    // The tags, streamed (a file can declare millions): only those the
    // surface needs (KEYS) are kept; a later tag of a key replaces an
    // earlier one.
    let mut tags: HashMap<&'static str, String> = HashMap::new();
    let mut i = 2u64;
    let mut failed = None;
    bin.stream("the tags", start, count, TAG, |raw| {
        if failed.is_none() {
            if raw.get(TAG - 2..TAG) != Some(b"\r\n") {
                failed = Some(i);
            } else {
                // By bytes: no text made of the tags skipped.
                let name = trim(&raw[..KEY]);
                if let Some(&key) = KEYS.iter().find(|k| k.as_bytes() == name) {
                    tags.insert(key, text(&raw[KEY..TAG - 2]));
                }
            }
        }
        i += 1;
    })?;
    if let Some(i) = failed {
        return Err(bin.err(format!("tag {i} does not end in CR LF")));
    }
    bin.check_within("the comment", end, COMMENT, 1)?;
    let get = |key: &str| {
        tags.get(key)
            .ok_or_else(|| bin.err(format!("no {key} tag")))
            .map(|v| v.trim())
    };
    let whole = |key: &str| {
        let v = get(key)?;
        v.parse::<u64>().map_err(|_| {
            bin.err(format!(
                "the {key} tag's value \"{}\" is not a whole number",
                clip(v, 30)
            ))
        })
    };
    let real = |key: &str| {
        let v = get(key)?;
        v.parse::<f64>()
            .map_err(|_| bin.err(format!("the {key} tag's value \"{}\" is not a number", clip(v, 30))))
    };
    let (nx, ny) = (whole("Cols")?, whole("Rows")?);
    if nx == 0 || ny == 0 {
        return Err(bin.err(format!("Cols x Rows = {nx} x {ny}: no points")));
    }
    let (dx, dy) = (real("PixelSizeXMeter")?, real("PixelSizeYMeter")?);
    let offset = whole("DepthImageOffset")?;
    // A missing InvalidPixelValue tag, or NaN: only NaN heights are missing.
    let invalid = match tags.get("InvalidPixelValue") {
        Some(_) => real("InvalidPixelValue")?,
        None => f64::NAN,
    };
    // Rows are padded to a multiple of 8 bytes (2 values).
    let stride = nx.saturating_add(nx % 2);
    let stored = stride.saturating_mul(ny);
    bin.check_within("the depth image", offset, stored, 4)?;
    let points = nx.checked_mul(ny).ok_or_else(|| bin.err(format!("Cols x Rows = {nx} x {ny} overflows")))?;
    let declared = || format!("the tags' Cols x Rows = {nx} x {ny}");
    let mut heights = cx.heights(declared, points, options)?;
    let mut column = 0;
    bin.stream("the depth image", offset, stored, 4, |raw| {
        if column < nx {
            let v = match *raw {
                [a, b, c, d] => f64::from(f32::from_le_bytes([a, b, c, d])),
                _ => f64::NAN,
            };
            let missing = v.is_nan() || (v - invalid).abs() < INVALID_RELTOL * invalid.abs();
            heights.push(if missing { f64::NAN } else { v });
        }
        column = (column + 1) % stride;
    })?;

    let application = tags
        .get("CreatingApplication")
        .map(|a| a.trim())
        .filter(|a| !a.is_empty());
    let metadata = Metadata {
        instrument: Some(match application {
            Some(a) => format!("Alicona Imaging ({a})"),
            None => "Alicona Imaging".to_string(),
        }),
        height_unit: Some("m".to_string()),
        ..Metadata::default()
    };
    let shape = (nx as usize, ny as usize);
    Ok(cx.make(heights, shape, (Some(dx), Some(dy)), options, false)?.with_metadata(metadata))
}

/// The key and value of the tag `raw` (the `i`-th), checked to end in CR LF.
fn tag(bin: &Binary, raw: &[u8], i: usize) -> Result<(String, String), ReadError> {
    if raw.get(TAG - 2..TAG) != Some(b"\r\n") {
        return Err(bin.err(format!("tag {i} does not end in CR LF")));
    }
    Ok((text(&raw[..KEY]), text(&raw[KEY..TAG - 2])))
}
