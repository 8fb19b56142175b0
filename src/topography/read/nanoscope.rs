//! Bruker (Digital Instruments, Veeco) Nanoscope AFM files, versions 4.3
//! and later (`.di`, `.spm`, `.001`, ...): a text header of sections
//! (`\*File list`, `\*Scanner list`, `\*Ciao scan list`, one `\*Ciao image
//! list` a channel, ..., `\*File list end`) of `\Key: value` lines, then
//! the channels' data: little-endian integers (2 or 4 bytes), row after
//! row, at each channel's `Data offset`.
//!
//! A height channel's `@2:Z scale` (`V [Sens. Zsens] (0.0050354 V/LSB)
//! 2.910461 V`) gives the hard value per 2^(8·bytes) LSB, its soft scale
//! `@Sens. Zsens` (`V 20.82646 nm/V`) the metres per volt; a channel
//! whose soft scale is not a length per volt (phase, amplitude) holds no
//! heights and is read only if asked for, as an error saying so. The scan
//! size (`Scan Size: 500 500 nm`, or `Slow Axis Size` where given) gives
//! the intervals. Rows are stored top first: the first row here is the
//! file's last (y up), as Gwyddion and SurfaceTopography show it. Older
//! files' section names (`AFM image list`, `Microscope list`, ...), wrong
//! per-channel sizes corrected by the scan list's, and version 9.2's
//! 32-bit data are read as SurfaceTopography reads them.
//!
//! The header ends at a line `\*File list end` (text that only contains
//! it is a value) or, as SurfaceTopography reads it, at a blank line after
//! the image sections; a blank line before them is a damaged header, a
//! file ending within its header a truncated one. Only the sections read
//! are kept (the others' `Operating mode` alone), so a header's memory is
//! bounded by what the surface needs; `Bytes/pixel` other than 2 or 4 is
//! refused, never defaulted.

use std::collections::HashMap;

use super::binary::Binary;
use super::instrument::{self, Int};
use super::{clip, Ctx, Entry, ReadError, ReadOptions, Source};
use crate::topography::{Metadata, Topography};

/// The format's description (and the errors' name for it).
const DESCRIPTION: &str = "Bruker Nanoscope";

/// The registry's entry.
pub(super) const ENTRY: Entry = Entry {
    name: "nanoscope",
    description: "Bruker/Veeco Nanoscope AFM (several channels: the first height channel by default)",
    extensions: &["di", "spm", "001", "002", "003", "004", "005"],
    sniff: Some(sniff),
    read,
};

/// The bound on the text header (bytes).
const MAX_HEADER: u64 = 4 << 20;

/// The names of the sections (lower case), by role; older software and
/// Nanoscope E use other names for the same sections.
const FILE_LIST: [&str; 2] = ["file list", "ec file list"];
const SCANNER: [&str; 2] = ["scanner list", "microscope list"];
const SCAN: [&str; 4] = ["ciao scan list", "afm list", "stm list", "nc afm list"];
const IMAGE: [&str; 5] = [
    "ciao image list",
    "afm image list",
    "stm image list",
    "ncafm image list",
    "image list",
];

/// From version 9.2 the data are 32-bit integers whatever `Bytes/pixel`.
const VERSION_32BIT: u64 = 0x0920_0000;

fn sniff(head: &[u8]) -> bool {
    let lower: Vec<u8> = head.iter().take(16).map(u8::to_ascii_lowercase).collect();
    [&b"\\*file list"[..], b"\\*ec file list", b"?*file list"]
        .iter()
        .any(|s| lower.starts_with(s))
}

/// A section: its name (lower case) and its `key: value` pairs (keys
/// lower case; a later key replaces an earlier one).
type Section = (String, HashMap<String, String>);

/// The header's sections, in order.
fn sections(cx: &Ctx, text: &str, whole: bool) -> Result<Vec<Section>, ReadError> {
    let bad = |detail: String| cx.format(DESCRIPTION, detail);
    let mut out: Vec<Section> = Vec::new();
    let mut ended = false;
    for (number, line) in text.split('\n').map(str::trim).enumerate() {
        if line.eq_ignore_ascii_case("\\*file list end") {
            ended = true;
            break;
        }
        if line.is_empty() {
            // A blank line ends the header as SurfaceTopography reads it;
            // one before any image section is a damaged header.
            if !out.iter().any(|(n, _)| IMAGE.contains(&n.as_str())) {
                return Err(bad(format!(
                    "line {} of the header is blank, before any image section (\\*Ciao image list): the header is damaged",
                    number + 1
                )));
            }
            ended = true;
            break;
        }
        if let Some(name) = line.strip_prefix("\\*") {
            let name = name.to_lowercase();
            if out.is_empty() && !FILE_LIST.contains(&name.as_str()) {
                return Err(bad(format!(
                    "the header starts with the section \"{}\", not \"File list\"",
                    clip(&name, 40)
                )));
            }
            // Sections not read are kept as one (their "operating mode"
            // only): a 4 MiB header of other sections costs no memory.
            let known = [&FILE_LIST[..], &SCANNER, &SCAN, &IMAGE, &["equipment list"]]
                .iter()
                .any(|names| names.contains(&name.as_str()));
            if known {
                out.push((name, HashMap::new()));
            } else if out.last().is_none_or(|(n, _)| !n.is_empty()) {
                out.push((String::new(), HashMap::new()));
            }
        } else if let Some(entry) = line.strip_prefix('\\') {
            let Some((name, section)) = out.last_mut() else {
                return Err(bad("a key before the first section".into()));
            };
            let (key, value) = entry.split_once(": ").unwrap_or((entry, ""));
            let key = key.to_lowercase();
            if !name.is_empty() || key == "operating mode" {
                section.insert(key, value.trim().to_string());
            }
        } else {
            return Err(bad(format!(
                "a header line does not start with a backslash: \"{}\"",
                clip(line, 40)
            )));
        }
    }
    if !ended && whole {
        return Err(bad(format!(
            "the file ends within its text header, after {} bytes and before \"\\*File list end\": it is truncated",
            text.len()
        )));
    }
    if !ended {
        return Err(bad(format!("no \"\\*File list end\" in the first {MAX_HEADER} bytes")));
    }
    if out.is_empty() {
        return Err(bad("no sections in the header".into()));
    }
    Ok(out)
}

/// The parts of an `@` value such as `V [Sens. Zsens] (0.0050354 V/LSB)
/// 2.910461 V`: its type (`V`, `C`, `S`), the soft scale's name (in
/// brackets), the hard scale (in parentheses) and the rest.
fn parse_value(value: &str) -> Option<(char, Option<&str>, Option<&str>, &str)> {
    let value = value.trim();
    let kind = value.chars().next()?;
    let mut rest = value[kind.len_utf8()..].trim();
    let mut soft = None;
    if let Some(inner) = rest.strip_prefix('[') {
        let end = inner.find(']')?;
        soft = Some(inner[..end].trim()).filter(|s| !s.is_empty());
        rest = inner[end + 1..].trim();
    }
    let mut hard = None;
    if rest.starts_with('(') {
        // Units have parentheses of their own: log(Arb).
        let mut level = 0i32;
        let mut close = None;
        for (i, c) in rest.char_indices() {
            match c {
                '(' => level += 1,
                ')' => {
                    level -= 1;
                    if level == 0 {
                        close = Some(i);
                        break;
                    }
                }
                _ => {}
            }
        }
        let i = close?;
        hard = Some(rest[1..i].trim());
        rest = rest[i + 1..].trim();
    }
    Some((kind, soft, hard, rest))
}

/// `2.910461 V` → (2.910461, "V").
fn number_unit(text: &str) -> Option<(f64, &str)> {
    let text = text.trim();
    let (number, unit) = text.split_once(char::is_whitespace).unwrap_or((text, ""));
    Some((number.parse().ok()?, unit.trim()))
}

/// Scale of a unit of voltage (`V`, `mV`, ...), for the ratio of a hard
/// and a soft scale's units.
fn volts(unit: &str) -> Option<f64> {
    Some(match unit {
        "GV" => 1e9,
        "MV" => 1e6,
        "kV" => 1e3,
        "V" => 1.0,
        "mV" => 1e-3,
        "µV" | "uV" => 1e-6,
        "nV" => 1e-9,
        "pV" => 1e-12,
        _ => return None,
    })
}

/// Scale of a length or voltage unit, whichever it is.
fn scale(unit: &str) -> Option<(bool, f64)> {
    instrument::length_unit(unit, true)
        .map(|m| (true, m))
        .or_else(|| volts(unit).map(|v| (false, v)))
}

/// `a` in units of `b`: the conversion factor, if both are of a kind.
fn convert(a: &str, b: &str) -> Option<f64> {
    if a == b {
        return Some(1.0);
    }
    match (scale(a)?, scale(b)?) {
        ((ka, sa), (kb, sb)) if ka == kb => Some(instrument::ratio(sa, sb)),
        _ => None,
    }
}

/// A channel (an image section) as the header describes it.
struct Channel {
    name: String,
    nx: usize,
    ny: usize,
    /// Scan size (in `xy_unit`).
    size: (f64, f64),
    xy_unit: String,
    offset: u64,
    elsize: usize,
    /// The height per LSB in `height_unit`, for a height channel; else
    /// why not.
    height: Result<(f64, String), String>,
}

fn int(section: &HashMap<String, String>, key: &str) -> Option<u64> {
    section.get(key)?.trim().parse().ok()
}

fn read(cx: &Ctx, source: &mut dyn Source, len: u64, options: &ReadOptions) -> Result<Topography, ReadError> {
    let bad = |detail: String| cx.format(DESCRIPTION, detail);
    // The marker at the start of a line (a value may contain its text).
    let (bytes, whole) = instrument::head(cx, source, len, MAX_HEADER, b"\n\\*File list end")?;
    if bytes.starts_with(b"?*") {
        return Err(cx.unsupported("a Nanoscope file with its data stored as text (only binary data are read)"));
    }
    let text = instrument::latin1(&bytes);
    let sections = sections(cx, &text, whole)?;

    // The global sections, needed to read the image sections.
    let merged = |names: &[&str]| {
        let mut all = HashMap::new();
        for (_, s) in sections.iter().filter(|(n, _)| names.contains(&n.as_str())) {
            all.extend(s.iter().map(|(k, v)| (k.clone(), v.clone())));
        }
        all
    };
    let (file_list, equipment) = (merged(&FILE_LIST), merged(&["equipment list"]));
    let soft: Soft = (merged(&SCANNER), merged(&SCAN));
    let scan = &soft.1;
    let operating_mode = sections.iter().rev().find_map(|(_, s)| s.get("operating mode"));
    let version_text = file_list.get("version").map(|v| v.trim());
    let version = version_text
        .and_then(|v| u64::from_str_radix(v.trim_start_matches("0x").trim_start_matches("0X"), 16).ok())
        .unwrap_or(0);
    let context = file_list.get("start context").map_or("", |s| s.trim());
    if operating_mode.is_some_and(|m| m.trim() == "Force") || context == "FOL" {
        return Err(cx.unsupported("a Nanoscope file of force curves (only images are read)"));
    }
    if context.ends_with("VAR") && operating_mode.is_none_or(|m| m.trim() != "Force Volume") {
        return Err(cx.unsupported("a Nanoscope file of unevenly spaced profiles (only images are read)"));
    }
    let global = match (int(scan, "samps/line"), int(scan, "lines")) {
        (Some(nx), Some(ny)) => Some((nx, ny)),
        _ => None,
    };
    // Newer files give the slow axis's size on its own (the second number
    // of the scan size can then be wrong).
    let slow_axis = match (scan.get("scan size"), scan.get("slow axis size")) {
        (Some(fast), Some(slow)) => match (number_unit(fast), number_unit(slow)) {
            (Some((f, fu)), Some((s, su))) => convert(su, fu).map(|c| (f, s * c, mangle(fu))),
            _ => None,
        },
        _ => None,
    };

    let mut channels = Vec::new();
    for (_, p) in sections.iter().filter(|(n, _)| IMAGE.contains(&n.as_str())) {
        let i = channels.len();
        channels.push(
            channel(p, i, version, global, slow_axis.as_ref(), &soft).map_err(|e| bad(format!("channel {i}: {e}")))?,
        );
    }
    let names: Vec<String> = channels.iter().map(|c| c.name.clone()).collect();
    let default = channels.iter().position(|c| c.height.is_ok());
    let index = cx.channel(&names, default, options)?;
    let c = &channels[index];
    let (per_lsb, height_unit) = c.height.clone().map_err(|why| ReadError::Channel {
        path: cx.path(),
        detail: format!("channel {index} ({}) holds no heights: {why}", clip(&c.name, 40)),
        available: names.clone(),
    })?;
    let metres = instrument::length_unit(&height_unit, true).unwrap_or(f64::NAN);
    let xy = instrument::length_unit(&c.xy_unit, true).ok_or_else(|| {
        bad(format!(
            "channel {index}: the scan size's unit \"{}\" is not a length",
            clip(&c.xy_unit, 20)
        ))
    })?;
    // The sizes in the height unit, then metres (SurfaceTopography's
    // order of operations).
    let to_height = if c.xy_unit == height_unit {
        1.0
    } else {
        instrument::ratio(xy, metres)
    };
    let to_m = instrument::ratio(metres, 1.0);
    let (sx, sy) = (c.size.0 * to_height * to_m, c.size.1 * to_height * to_m);
    let int = Int {
        size: c.elsize,
        signed: true,
        big: false,
    };
    let topography = instrument::channel_map(
        &mut Binary::new(cx, source, len, DESCRIPTION),
        (index, &c.name),
        c.offset,
        (c.nx, c.ny),
        int,
        (sx, sy),
        options,
        &|v| v * per_lsb * to_m,
    )?;
    let name = equipment.get("microscope").or_else(|| equipment.get("description"));
    let instrument = match (name, version_text) {
        (Some(n), Some(v)) => format!("Bruker {n} (Nanoscope {v})"),
        (Some(n), None) => format!("Bruker {n}"),
        (None, Some(v)) => format!("Bruker Nanoscope {v}"),
        (None, None) => "Bruker Nanoscope".into(),
    };
    let metadata = Metadata {
        instrument: Some(instrument),
        date: file_list.get("date").filter(|d| !d.is_empty()).cloned(),
        channel: Some(c.name.clone()),
        channels: names,
        height_unit: Some(height_unit),
        ..Metadata::default()
    };
    Ok(topography.with_metadata(metadata))
}

/// The channel of image section `p` (the `i`-th).
fn channel(
    p: &HashMap<String, String>,
    i: usize,
    version: u64,
    global: Option<(u64, u64)>,
    slow_axis: Option<&(f64, f64, String)>,
    soft: &Soft,
) -> Result<Channel, String> {
    let name = ["@2:image data", "@3:image data", "@4:image data"]
        .iter()
        .find_map(|k| p.get(*k))
        .and_then(|v| {
            let (_, soft, _, rest) = parse_value(v)?;
            Some(soft.unwrap_or(rest.trim_matches('"')).to_string())
        })
        .or_else(|| p.get("image data").cloned())
        .unwrap_or_else(|| format!("channel {i}"));
    let need = |key: &str| int(p, key).ok_or_else(|| format!("no whole number \"{key}\""));
    let (mut nx, mut ny) = (need("samps/line")?, need("number of lines")?);
    let size = p.get("scan size").ok_or("no \"Scan Size\"")?;
    let words: Vec<&str> = size.split_whitespace().collect();
    let number = |w: Option<&&str>| w.and_then(|w| w.parse::<f64>().ok());
    let sx = number(words.first()).ok_or_else(|| format!("the scan size \"{}\"", clip(size, 40)))?;
    let (mut sx, mut sy, mut xy_unit): (f64, f64, String) = match number(words.get(1)) {
        Some(sy) => (sx, sy, words.get(2..).unwrap_or_default().join(" ")),
        None => (sx, sx, words.get(1..).unwrap_or_default().join(" ")),
    };
    xy_unit = mangle(&xy_unit);
    if let Some((fast, slow, fast_unit)) = slow_axis {
        match convert(fast_unit, &xy_unit) {
            Some(c) => (sx, sy) = (fast * c, slow * c),
            None => (sx, sy, xy_unit) = (*fast, *slow, fast_unit.clone()),
        }
    }
    let offset = need("data offset")?;
    let length = need("data length")?;
    let bpp = match p.get("bytes/pixel").map(|v| v.trim()) {
        None => 2,
        Some(v) => match v.parse::<u64>() {
            Ok(b @ (2 | 4)) => b,
            _ => return Err(format!("Bytes/pixel = \"{}\": must be 2 or 4", clip(v, 20))),
        },
    };
    let points = |nx: u64, ny: u64| nx.checked_mul(ny).ok_or_else(|| format!("{nx} x {ny} points"));
    let mut elsize = bpp;
    if version >= VERSION_32BIT && length / 4 >= points(nx, ny)? {
        elsize = 4;
    }
    // Some files give wrong sizes in the image sections; the scan list's
    // are right then.
    if let Some((gx, gy)) = global {
        let bytes = points(nx, ny)?.saturating_mul(elsize);
        let global_bytes = points(gx, gy)?.saturating_mul(elsize);
        if length != bytes && (length == global_bytes || (bytes > length && length >= global_bytes)) {
            if slow_axis.is_none() && nx > 0 && ny > 0 {
                sx *= gx as f64 / nx as f64;
                sy *= gy as f64 / ny as f64;
            }
            (nx, ny) = (gx, gy);
        } else if slow_axis.is_some() && non_square(p) && ny < gy {
            // Stopped early ("Capture Now"): the slow axis's size is the
            // full scan's.
            sy *= ny as f64 / gy as f64;
        }
    }
    let bytes = points(nx, ny)?.saturating_mul(elsize);
    if bytes > length {
        return Err(format!(
            "{nx} x {ny} points of {elsize} bytes make {bytes} bytes, over the data length {length}"
        ));
    }
    let nx = usize::try_from(nx).map_err(|_| format!("{nx} samples a line"))?;
    let ny = usize::try_from(ny).map_err(|_| format!("{ny} lines"))?;
    Ok(Channel {
        name,
        nx,
        ny,
        size: (sx, sy),
        xy_unit,
        offset,
        elsize: elsize as usize,
        height: height(p, bpp, soft),
    })
}

/// The height per LSB of image section `p` and its unit, or why it holds
/// no heights (`soft`: the scanner and scan lists' `@` values, where the
/// soft scales are).
fn height(p: &HashMap<String, String>, bpp: u64, soft: &Soft) -> Result<(f64, String), String> {
    let z = p
        .get("@4:z scale")
        .or_else(|| p.get("@2:z scale"))
        .ok_or("it has no \"@2:Z scale\" (files before version 4.3 are not read)")?;
    let malformed = || format!("a malformed Z scale \"{}\"", clip(z, 60));
    let (_, quantity, _, hard) = parse_value(z).ok_or_else(malformed)?;
    let (hard_value, hard_unit) = number_unit(hard).ok_or_else(malformed)?;
    let hard_scale = hard_value / 256f64.powi(bpp as i32);
    let quantity = quantity.ok_or("its Z scale has no soft scale")?;
    let key = format!("@{}", quantity.to_lowercase());
    let value = soft
        .0
        .get(&key)
        .or_else(|| soft.1.get(&key))
        .ok_or_else(|| format!("no soft scale \"{}\" in the header", clip(quantity, 40)))?;
    let (kind, _, _, rest) =
        parse_value(value).ok_or_else(|| format!("a malformed soft scale \"{}\"", clip(value, 60)))?;
    let (soft_scale, soft_unit) = number_unit(rest)
        .filter(|_| kind == 'V')
        .ok_or_else(|| format!("a malformed soft scale \"{}\"", clip(value, 60)))?;
    let (unit, per) = soft_unit.split_once('/').ok_or_else(|| match soft_unit {
        "" => "its soft scale has no unit (not a length per volt)".to_string(),
        unit => format!("its unit is \"{}\", not a length per volt", clip(unit, 20)),
    })?;
    let hard_to_soft = convert(hard_unit, per).ok_or_else(|| {
        format!(
            "its hard scale is in \"{}\", its soft scale per \"{}\"",
            clip(hard_unit, 20),
            clip(per, 20)
        )
    })?;
    if instrument::length_unit(unit, true).is_none() {
        return Err(format!("its unit is \"{}\", not a length", clip(unit, 20)));
    }
    Ok((hard_scale * hard_to_soft * soft_scale, mangle(unit)))
}

/// The scanner list's and the scan list's values.
type Soft = (HashMap<String, String>, HashMap<String, String>);

/// A length unit as SurfaceTopography spells it (`~m` and `um` are µm,
/// `A` is Å), so that units compare equal.
fn mangle(unit: &str) -> String {
    match unit.trim() {
        "~m" | "um" | "μm" => "µm".into(),
        "A" => "Å".into(),
        other => other.into(),
    }
}

/// Whether the section's aspect ratio is not 1:1.
fn non_square(p: &HashMap<String, String>) -> bool {
    match p.get("aspect ratio").map(|a| a.trim()) {
        None | Some("1:1") => false,
        Some(a) => a
            .split(':')
            .next()
            .and_then(|r| r.trim().parse::<f64>().ok())
            .is_some_and(|r| r > 0.0 && r != 1.0),
    }
}
