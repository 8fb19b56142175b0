//! Sensofar `.plu` (and `.apx`): confocal, interferometric and
//! focus-variation profilers. A 500-byte header (little endian: the date as
//! text, a comment, the calibration with the lateral pixel size in µm, the
//! measurement's type, the format version and hardware, the number of
//! layers and of images after each), then each layer: its size (rows,
//! columns), `ny` rows of `nx` f32 heights in µm (rows = y; 1000001 marks a
//! missing point), its minimum and maximum, and the layer's RGB images.
//! Only topographies (type 3) are read; a file of several layers has one
//! channel a layer (`layer0`, `layer1`, ...), the first by default.

use super::binary::{Binary, Fields};
use super::{Ctx, Entry, ReadError, ReadOptions, Source};
use crate::topography::{Metadata, Topography};
use crate::LengthUnit;

/// The registry's entry. The format has no signature: it is chosen by its
/// extensions only.
pub(super) const ENTRY: Entry = Entry {
    name: "plu",
    description: "Sensofar .plu (confocal, interferometric profilers)",
    extensions: &["plu", "apx"],
    sniff: None,
    read,
};

/// The format, in errors.
const FORMAT: &str = "Sensofar .plu";
/// The header's size, up to the first layer (bytes).
const HEADER: usize = 500;
/// The measurement type of a topography (1 is a profile, not read).
const TOPOGRAPHY: u32 = 3;
/// The value of a missing point.
const UNDEFINED: f32 = 1_000_001.0;
/// Versions 2012 and later (counted down from 0xff, 2006) say the hardware
/// (version 0 is 2000, when they did not).
const VERSION_2012: u8 = 0xfb;
/// The hardware, by the header's id (format 2012 and later).
const HARDWARE: [&str; 12] = [
    "PLu",
    "PLu 2300 XGA",
    "PLu 2300 XGA T5",
    "PLu 2300 SXGA",
    "PLu 3300",
    "DCM 3D",
    "PLu neox",
    "DCM 3D rev. 2",
    "PLu Apex (prototype)",
    "S neox",
    "DCM8",
    "PLu Apex",
];

/// Reads a `.plu` file of `len` bytes.
fn read(cx: &Ctx, source: &mut dyn Source, len: u64, options: &ReadOptions) -> Result<Topography, ReadError> {
    let mut bin = Binary::new(cx, source, len, FORMAT);
    let header = bin.block("the header", 0, HEADER)?;
    let mut f = Fields::new(&header);
    let date = f.text(128);
    f.skip(4 + 256); // time, comment
    f.skip(3 * 4 + 4); // the calibration's size, dy multiplier
    let (um_x, um_y) = (f.f32(), f.f32());
    f.skip(4 * 4); // offsets, z calibration
    let kind = f.u32();
    f.skip(3 * 4); // algorithm, method, objective
                   // The area type, then the scan settings: 40 bytes in either layout
                   // (a tracking profiler's, area type 6, or the others').
    f.skip(4 + 40);
    let _restore = f.u8();
    let layers = f.u8();
    let version = f.u8();
    let hardware = f.u8();
    let images = f.u8();

    if kind != TOPOGRAPHY {
        return Err(cx.unsupported(format!(
            "{FORMAT}: measurement type {kind} (only topographies, type {TOPOGRAPHY}, are read)"
        )));
    }
    if layers == 0 {
        return Err(bin.err("the header says the file has no layers"));
    }
    let um = LengthUnit::Um.metres();
    let interval = |name: &str, v: f32| {
        let v = f64::from(v) * um;
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(bin.err(format!("the calibration's {name} pixel size is {v:e} m: must be > 0")))
        }
    };
    let (dx, dy) = (interval("x", um_x)?, interval("y", um_y)?);

    let names: Vec<String> = (0..layers).map(|i| format!("layer{i}")).collect();
    let chosen = if layers > 1 {
        cx.channel(&names, Some(0), options)?
    } else {
        0
    };
    // Walks the layers before the one chosen: each is its size, heights,
    // minimum and maximum, and its images (3 bytes a point each).
    let mut at = HEADER as u64;
    let (mut nx, mut ny);
    let mut layer = 0;
    loop {
        let size = bin.block("a layer's size", at, 8)?;
        let mut s = Fields::new(&size);
        ny = s.u32();
        nx = s.u32();
        if nx == 0 || ny == 0 {
            return Err(bin.err(format!("layer {layer} is {nx} x {ny} points: must be > 0")));
        }
        at += 8;
        if layer == chosen {
            break;
        }
        let points = u64::from(nx) * u64::from(ny);
        let bytes = points
            .checked_mul(4 + 3 * u64::from(images))
            .and_then(|b| b.checked_add(8));
        at = match bytes.and_then(|b| b.checked_add(at)) {
            Some(next) if next <= len => next,
            _ => {
                return Err(bin.err(format!(
                    "layer {layer} runs past the end of the file: the file is truncated"
                )))
            }
        };
        layer += 1;
    }
    let points = u64::from(nx) * u64::from(ny);
    // The whole layer (its heights, minimum and maximum, and images) is
    // in the file: a file cut short in its images is truncated too.
    let end = bin.check_within("the layer", at, points, 4 + 3 * u64::from(images))?;
    bin.check_within("the layer's minimum and maximum", end, 8, 1)?;
    let mut heights = cx.heights(|| format!("layer {chosen}'s {nx} x {ny} points"), points, options)?;
    bin.stream("the heights", at, points, 4, |raw| {
        let v = match *raw {
            [a, b, c, d] => f32::from_le_bytes([a, b, c, d]),
            _ => f32::NAN,
        };
        heights.push(if v == UNDEFINED { f64::NAN } else { f64::from(v) * um });
    })?;

    let instrument = match hardware as usize {
        i if version != 0 && version <= VERSION_2012 && i < HARDWARE.len() => format!("Sensofar {}", HARDWARE[i]),
        _ => "Sensofar".to_string(),
    };
    let metadata = Metadata {
        instrument: Some(instrument),
        date: (!date.is_empty()).then_some(date),
        channel: (layers > 1).then(|| names[chosen].clone()),
        channels: if layers > 1 { names } else { Vec::new() },
        height_unit: Some("µm".to_string()),
        ..Metadata::default()
    };
    let shape = (nx as usize, ny as usize);
    Ok(cx.make(heights, shape, (Some(dx), Some(dy)), options, false)?.with_metadata(metadata))
}
