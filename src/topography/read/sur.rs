//! Digital Surf `.sur` (MountainsMap's own format, written by instruments
//! of several makers): a 512-byte header (little endian), a comment and a
//! private zone of the sizes it gives, then `ny` rows of `nx` 16- or 32-bit
//! integers (rows = y). A height is `value · scale` in the header's height
//! unit (negated when the header says the heights are inverted; a map
//! mirrored in x or y when it says so); with "special points" on, the value
//! `zmin − 2` marks a missing point. The intervals are the header's, in
//! its x and y units. Only the first object of a multi-object file is read
//! (as SurfaceTopography and Gwyddion's `surffile.c` do).

use super::binary::{metres_per, Binary, Fields};
use super::{clip, Ctx, Entry, ReadError, ReadOptions, Source};
use crate::topography::{Metadata, Topography};

/// The registry's entry.
pub(super) const ENTRY: Entry = Entry {
    name: "sur",
    description: "Digital Surf .sur (MountainsMap)",
    extensions: &["sur"],
    sniff: Some(|head| head.starts_with(MAGIC)),
    read,
};

/// The format, in errors.
const FORMAT: &str = "Digital Surf .sur";
const MAGIC: &[u8] = b"DIGITAL SURF";
/// The header's size (bytes).
const HEADER: usize = 512;
/// With special points on, `zmin + NON_MEASURED` marks a missing point.
const NON_MEASURED: i64 = -2;

/// Reads a `.sur` file of `len` bytes.
fn read(cx: &Ctx, source: &mut dyn Source, len: u64, options: &ReadOptions) -> Result<Topography, ReadError> {
    let mut bin = Binary::new(cx, source, len, FORMAT);
    let header = bin.block("the header", 0, HEADER)?;
    if !header.starts_with(MAGIC) {
        return Err(bin.err("no DIGITAL SURF signature at the start"));
    }
    let mut f = Fields::new(&header);
    f.skip(MAGIC.len());
    let _format = f.u16();
    let _objects = f.u16();
    let _version = f.u16();
    let _kind = f.u16();
    let _object_name = f.text(30);
    let instrument = f.text(30);
    f.skip(2 + 2 + 2); // material code, acquisition, range
    let special_points = f.u16();
    f.skip(2 + 4 + 4); // absolute, reserved
    let bits = f.u16();
    let zmin = f.i32();
    let _zmax = f.i32();
    let (nx, ny) = (f.i32(), f.i32());
    let points = f.u32();
    let (spacing_x, spacing_y) = (f.f32(), f.f32());
    let scale = f64::from(f.f32());
    f.skip(3 * 16); // the axes' names
    let [unit_x, unit_y, unit_z] = [f.text(16), f.text(16), f.text(16)];
    f.skip(3 * 16 + 3 * 4); // the axes' units and unit ratios
    f.skip(2); // imprint
    let inversion = f.u16();
    f.skip(2 + 3 * 4); // levelling, reserved
    let [second, minute, hour, day, month, year] = [f.u16(), f.u16(), f.u16(), f.u16(), f.u16(), f.u16()];
    f.skip(2 + 4 + 4 + 4 + 2); // day of week, duration, reserved
    let comment = f.u16();
    let private = f.u16();

    let size = if nx > 0 && ny > 0 {
        (nx as u64) * (ny as u64)
    } else {
        return Err(bin.err(format!("the header's size is {nx} x {ny} points: must be > 0")));
    };
    if u64::from(points) != size {
        return Err(bin.err(format!("the header says {points} points, its size {nx} x {ny}")));
    }
    let item = match bits {
        16 => 2,
        32 => 4,
        other => return Err(cx.unsupported(format!("{FORMAT}: {other}-bit heights (16 and 32 are read)"))),
    };
    let unit = |name: &str, unit: &str| {
        metres_per(unit).ok_or_else(|| cx.unsupported(format!("{FORMAT}: the {name} unit \"{}\" is not a length", clip(unit, 20))))
    };
    let (mx, my, mz) = (unit("x", &unit_x)?, unit("y", &unit_y)?, unit("height", &unit_z)?);
    let interval = |name: &str, v: f32, m: f64| {
        let v = f64::from(v) * m;
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(bin.err(format!("the header's {name} spacing is {v:e} m: must be > 0")))
        }
    };
    let (dx, dy) = (interval("x", spacing_x, mx)?, interval("y", spacing_y, my)?);
    // Inverted heights (1), and mirrored in x (2) or in y (3) as well.
    let sign = if matches!(inversion, 1..=3) { -1.0 } else { 1.0 };
    let z = sign * scale * mz;
    let missing = (special_points == 1).then_some(i64::from(zmin) + NON_MEASURED);

    let (nx, ny) = (nx as usize, ny as usize);
    let start = (HEADER + usize::from(comment) + usize::from(private)) as u64;
    // The data are in the file before anything is allocated for them.
    bin.check_within("the heights", start, size, item as u64)?;
    let mut heights = cx.heights(|| format!("the header's {nx} x {ny} points"), size, options)?;
    bin.stream("the heights", start, size, item, |raw| {
        let v = match *raw {
            [a, b] => i64::from(i16::from_le_bytes([a, b])),
            [a, b, c, d] => i64::from(i32::from_le_bytes([a, b, c, d])),
            _ => 0,
        };
        heights.push(if Some(v) == missing { f64::NAN } else { v as f64 * z });
    })?;
    match inversion {
        2 => heights.chunks_exact_mut(nx).for_each(|row| row.reverse()),
        3 => {
            for y in 0..ny / 2 {
                let (top, bottom) = heights.split_at_mut((ny - 1 - y) * nx);
                top[y * nx..(y + 1) * nx].swap_with_slice(&mut bottom[..nx]);
            }
        }
        _ => {}
    }
    let date = (year > 0).then(|| format!("{year:04}-{month:02}-{day:02} {hour:02}:{minute:02}:{second:02}"));
    let metadata = Metadata {
        instrument: Some(if instrument.is_empty() {
            "Digital Surf".to_string()
        } else {
            format!("Digital Surf: {instrument}")
        }),
        date,
        height_unit: Some(unit_z),
        ..Metadata::default()
    };
    Ok(cx
        .make(heights, (nx, ny), (Some(dx), Some(dy)), options, false)?
        .with_metadata(metadata))
}
