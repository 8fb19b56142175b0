//! Zygo MetroPro `.dat` (header formats 1–3): a binary header (834 bytes,
//! or 4096 for format 3), the intensity data, then the phase data: big-
//! endian `i32`, row after row (rows = y), values from 2147483640 up
//! marking invalid points (missing here). A height is the phase value times
//! `intf_scale_factor · obliquity_factor · wavelength / R` (R = 4096, 32768
//! or 131072 by `phase_res`), negated where `sign` is set; the interval is
//! `lateral_res` (none if 0). As Gwyddion's `metropro.c` and
//! SurfaceTopography's reader read it (MetroPro Reference Guide 0347).
//!
//! `.dat` is a common extension: a file without MetroPro's signature is
//! read as another format (text, usually).

use super::instrument::{self, Int};
use super::{Ctx, Entry, ReadError, ReadOptions, Source};
use crate::topography::{Metadata, Topography};

/// The format's description (and the errors' name for it).
const DESCRIPTION: &str = "Zygo MetroPro .dat";

/// The registry's entry.
pub(super) const ENTRY: Entry = Entry {
    name: "metropro",
    description: "Zygo MetroPro (white-light interferometer; invalid points missing)",
    extensions: &["dat"],
    sniff: Some(sniff),
    read,
};

/// The signatures of header formats 1, 2 and 3.
const MAGIC: [[u8; 4]; 3] = [
    [0x88, 0x1b, 0x03, 0x6f],
    [0x88, 0x1b, 0x03, 0x70],
    [0x88, 0x1b, 0x03, 0x71],
];
/// The header's size for formats 1 and 2 (bytes; the part read here).
const HEADER: usize = 834;
/// The header's size for format 3.
const HEADER3: u64 = 4096;
/// Phase values from this up mark invalid points.
const INVALID: f64 = 2_147_483_640.0;

fn sniff(head: &[u8]) -> bool {
    head.len() >= 4 && MAGIC.iter().any(|m| head[..4] == *m)
}

/// Big-endian integers and floats at byte offsets of the header.
struct Header([u8; HEADER]);

impl Header {
    fn u16(&self, at: usize) -> u16 {
        u16::from_be_bytes([self.0[at], self.0[at + 1]])
    }
    fn i16(&self, at: usize) -> i16 {
        self.u16(at) as i16
    }
    fn u32(&self, at: usize) -> u32 {
        u32::from_be_bytes([self.0[at], self.0[at + 1], self.0[at + 2], self.0[at + 3]])
    }
    fn f32(&self, at: usize) -> f64 {
        f64::from(f32::from_bits(self.u32(at)))
    }
}

fn read(cx: &Ctx, source: &mut dyn Source, len: u64, options: &ReadOptions) -> Result<Topography, ReadError> {
    let bad = |detail: String| cx.format(DESCRIPTION, detail);
    let mut h = Header([0; HEADER]);
    source
        .read_exact(&mut h.0)
        .map_err(|e| cx.eof_or(e, || bad(format!("shorter than the {HEADER}-byte header (truncated)"))))?;
    let Some(version) = MAGIC.iter().position(|m| h.0[..4] == *m) else {
        return Err(bad("no MetroPro signature (88 1b 03 6f/70/71) at the start".into()));
    };
    let header_size = u64::from(h.u32(6));
    let expected = if version == 2 { HEADER3 } else { HEADER as u64 };
    if header_size != expected {
        return Err(cx.unsupported(format!(
            "a MetroPro header of {header_size} bytes (format {} has {expected})",
            version + 1
        )));
    }
    let (ac_width, ac_height, buckets) = (h.u16(52), h.u16(54), h.u16(56));
    let (nx, ny) = (usize::from(h.u16(68)), usize::from(h.u16(70)));
    if nx == 0 || ny == 0 {
        return Err(cx.size(format!("the file has no phase (height) data: {nx} x {ny} points")));
    }
    let max_phase = match h.i16(218) {
        0 => 4096.0,
        1 => 32768.0,
        2 => 131072.0,
        other => return Err(bad(format!("phase_res = {other}: must be 0, 1 or 2"))),
    };
    let sign = if h.i16(232) != 0 { -1.0 } else { 1.0 };
    let (scale_factor, wavelength, obliquity) = (h.f32(164), h.f32(168), h.f32(176));
    // In SurfaceTopography's order of operations (the same heights to
    // the last bit).
    let scale = sign * scale_factor * obliquity * wavelength / max_phase;
    if !scale.is_finite() {
        return Err(bad(format!(
            "the height scale (intf_scale_factor {scale_factor:e} x obliquity {obliquity:e} x wavelength {wavelength:e} m) is not finite"
        )));
    }
    // 0: the file gives no interval; negative or not a number: damaged.
    let lateral = h.f32(184);
    if lateral < 0.0 || lateral.is_nan() {
        return Err(bad(format!(
            "lateral_res = {lateral:e} m is {}: the sampling interval must be > 0 (or 0 where the file gives none)",
            if lateral.is_nan() { "not a number" } else { "negative" }
        )));
    }
    let dx = (lateral > 0.0).then_some(lateral);
    // At most 2 x 65535^3 bytes and a 32-bit header size: no overflow in
    // u64, but checked all the same (every reader's offsets are).
    let intensity = [u64::from(buckets), u64::from(ac_height), u64::from(ac_width)]
        .iter()
        .try_fold(2u64, |a, &b| a.checked_mul(b))
        .and_then(|i| i.checked_add(header_size))
        .ok_or_else(|| bad("the intensity data's size overflows".into()))?;
    let int = Int {
        size: 4,
        signed: true,
        big: true,
    };
    let heights = instrument::grid(
        cx,
        source,
        len,
        DESCRIPTION,
        "the phase data",
        intensity,
        (nx, ny),
        int,
        false,
        options,
        &|v| if v >= INVALID { f64::NAN } else { v * scale },
    )?;
    let topography = cx.make(heights, (nx, ny), (dx, dx), options, false)?;

    // The serial number: all of it in `sys_serial2` (little-endian, newer
    // files), its lower 16 bits in `sys_serial`.
    let serial2 = u32::from_le_bytes([h.0[798], h.0[799], h.0[800], h.0[801]]);
    let serial = if serial2 != 0 { serial2 } else { u32::from(h.u16(242)) };
    let stamp = h.u32(76) as i32;
    let metadata = Metadata {
        instrument: Some(format!("Zygo (serial {serial})")),
        date: (stamp > 0).then(|| instrument::iso_date(i64::from(stamp))),
        ..Metadata::default()
    };
    Ok(topography.with_metadata(metadata))
}
