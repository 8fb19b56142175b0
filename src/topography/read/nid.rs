//! Nanosurf `.nid` (and `.ezd`) AFM files: an INI-style text header
//! (`[DataSet]`, `[DataSet-0:1]`, ... sections of `Key=Value` lines), then
//! `#!` and the channels' data one after the other, each `Points × Lines`
//! integers (`SaveBits`, `SaveSign`, `SaveOrder`) row after row. The
//! `[DataSet]` section lists the channels by group (`Gr0-Ch1=DataSet-0:1`);
//! a channel's section gives its frame and quantity (`Frame=Scan forward`,
//! `Dim2Name=Z-Axis`: the channel is called `Scan forward (Z-Axis)`), its
//! value range `Dim2Min` … `Dim2Min + Dim2Range` in `Dim2Unit`, spread over
//! the integers' range, and the scan size `Dim0Range`, `Dim1Range`. A
//! channel whose unit is not a length (deflection in N, a signal in V)
//! holds no heights and is read only if asked for, as an error saying so.
//! Rows are stored top first: the first row here is the file's last (y
//! up), as Gwyddion and SurfaceTopography show it. A channel listed in
//! `[DataSet]` whose section is missing is refused, naming it: its size,
//! and so where every later channel's data start, is unknown
//! (SurfaceTopography skips it and reads the later channels at the wrong
//! offsets). Offsets are checked arithmetic: channels declaring 2⁶⁴ bytes
//! or more are refused, never wrapped.

use std::collections::{HashMap, HashSet};

use super::binary::Binary;
use super::instrument::{self, Int};
use super::{clip, Ctx, Entry, ReadError, ReadOptions, Source};
use crate::topography::{Metadata, Topography};

/// The format's description (and the errors' name for it).
const DESCRIPTION: &str = "Nanosurf .nid";

/// The registry's entry.
pub(super) const ENTRY: Entry = Entry {
    name: "nid",
    description: "Nanosurf AFM (several channels: the first height channel by default)",
    extensions: &["nid", "ezd"],
    sniff: Some(sniff),
    read,
};

/// The bound on the text header (bytes).
const MAX_HEADER: u64 = 4 << 20;

/// The keys read (of `[DataSet]` also its `GroupCount`, `Gr…` entries).
const KEYS: [&str; 20] = [
    "Frame",
    "Points",
    "Lines",
    "SaveMode",
    "SaveBits",
    "SaveSign",
    "SaveOrder",
    "Dim0Range",
    "Dim1Range",
    "Dim2Range",
    "Dim2Min",
    "Dim0Unit",
    "Dim1Unit",
    "Dim2Unit",
    "Dim2Name",
    "Date",
    "Time",
    "Head type",
    "Controller S/N",
    "Version",
];

fn sniff(head: &[u8]) -> bool {
    head.starts_with(b"[DataSet]\r\n") || head.starts_with(b"[DataSet]\n")
}

/// A channel as the header describes it.
struct Channel {
    name: String,
    nx: usize,
    ny: usize,
    int: Int,
    /// Where its data start, from the first channel's.
    offset: u64,
    section: String,
}

fn read(cx: &Ctx, source: &mut dyn Source, len: u64, options: &ReadOptions) -> Result<Topography, ReadError> {
    let bad = |detail: String| cx.format(DESCRIPTION, detail);
    let (bytes, whole) = instrument::head(cx, source, len, MAX_HEADER, b"\n#!")?;
    if !sniff(&bytes) {
        return Err(bad("no \"[DataSet]\" line at the start".into()));
    }
    // `head` stops right after the marker, if it found one.
    if !bytes.ends_with(b"\n#!") {
        return Err(bad(if whole {
            format!(
                "the file ends within its text header, after {} bytes and before \"#!\" (the start of the data): it is truncated",
                bytes.len()
            )
        } else {
            format!("no \"#!\" (the start of the data) in the first {MAX_HEADER} bytes")
        }));
    }
    // The header's lines up to one that starts with `#!`, where the data
    // begin (right after the two bytes).
    let mut sections: HashMap<String, HashMap<String, String>> = HashMap::new();
    let mut current = String::from("DataSet");
    let mut named: HashSet<String> = HashSet::new();
    let mut at = 0usize;
    let data_start = loop {
        if at >= bytes.len() {
            return Err(bad(format!(
                "no \"#!\" (the start of the data) in the first {} bytes (truncated?)",
                bytes.len()
            )));
        }
        if bytes[at..].starts_with(b"#!") {
            break at as u64 + 2;
        }
        let end = bytes[at..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |i| at + i + 1);
        let line = instrument::latin1(&bytes[at..end]);
        let line = line.trim();
        if at > 0 && !line.is_empty() {
            if line.starts_with('[') && line.ends_with(']') {
                current = line[1..line.len() - 1].to_string();
            } else {
                let (key, value) = line
                    .split_once('=')
                    .ok_or_else(|| bad(format!("a header line is not key=value: \"{}\"", clip(line, 40))))?;
                // Only the keys read are kept, of the sections read:
                // [DataSet] (the first), [DataSet-Info] and the channels
                // [DataSet] lists before them (a 4 MiB header of other
                // keys or sections costs no memory).
                let key = key.trim();
                let value = value.trim();
                let keep = match current.as_str() {
                    "DataSet" if key.starts_with("Gr") => {
                        if key.contains("-Ch") {
                            named.insert(value.to_string());
                        }
                        true
                    }
                    "DataSet" | "DataSet-Info" => KEYS.contains(&key),
                    name => KEYS.contains(&key) && named.contains(name),
                };
                if keep {
                    sections
                        .entry(current.clone())
                        .or_default()
                        .insert(key.to_string(), value.to_string());
                }
            }
        }
        at = end;
    };
    let empty = HashMap::new();
    let section = |name: &str| sections.get(name).unwrap_or(&empty);
    let dataset = section("DataSet");
    let number = |s: &HashMap<String, String>, key: &str, what: &str| -> Result<u64, ReadError> {
        s.get(key)
            .and_then(|v| v.parse().ok())
            .ok_or_else(|| bad(format!("{what}: no whole number {key}")))
    };

    // Every channel the file lists, in order; each one's data follow the
    // previous one's.
    let mut channels = Vec::new();
    let mut offset = 0u64;
    let groups = number(dataset, "GroupCount", "[DataSet]")?;
    // The `Gr{g}-Ch{c}` entries of groups g < GroupCount and channels c <
    // Gr{g}-Count, in (g, c) order: found among the keys there are (not by
    // counting up to declared numbers, which a file can make huge).
    let mut listed: Vec<(u64, u64, &String)> = Vec::new();
    for (key, name) in dataset {
        let Some((g, c)) = key.strip_prefix("Gr").and_then(|k| k.split_once("-Ch")) else {
            continue;
        };
        let (Ok(g), Ok(c)) = (g.parse::<u64>(), c.parse::<u64>()) else {
            continue;
        };
        if g < groups && c < number(dataset, &format!("Gr{g}-Count"), "[DataSet]")? {
            listed.push((g, c, name));
        }
    }
    listed.sort_unstable();
    for (g, c, name) in listed {
        let what = format!("[{}]", clip(name, 40));
        // A channel listed without its section: its size, and so where
        // every later channel's data start, is unknown (SurfaceTopography
        // skips it and reads the later channels at the wrong offsets).
        let Some(s) = sections.get(name) else {
            return Err(bad(format!(
                "[DataSet] lists the channel Gr{g}-Ch{c} = {}, but the header has no section {what}",
                clip(name, 40)
            )));
        };
        if s.get("SaveMode").map(String::as_str) != Some("Binary") {
            return Err(cx.unsupported(format!("{what}: SaveMode other than Binary")));
        }
        let nx = number(s, "Points", &what)?;
        let ny = number(s, "Lines", &what)?;
        let bits = number(s, "SaveBits", &what)?;
        if !matches!(bits, 8 | 16 | 32 | 64) {
            return Err(cx.unsupported(format!("{what}: SaveBits = {bits} (8, 16, 32 or 64 are read)")));
        }
        let int = Int {
            size: (bits / 8) as usize,
            signed: s.get("SaveSign").map(String::as_str) == Some("Signed"),
            big: s.get("SaveOrder").map(String::as_str) != Some("Intel"),
        };
        let text = |key: &str| s.get(key).map_or("", String::as_str);
        let too_big = || bad(format!("{what}: {nx} x {ny} points of {bits} bits"));
        let bytes = nx
            .checked_mul(ny)
            .and_then(|n| n.checked_mul(bits / 8))
            .ok_or_else(too_big)?;
        channels.push(Channel {
            name: format!("{} ({})", text("Frame"), text("Dim2Name")),
            nx: usize::try_from(nx).map_err(|_| too_big())?,
            ny: usize::try_from(ny).map_err(|_| too_big())?,
            int,
            offset,
            section: name.clone(),
        });
        offset = offset.checked_add(bytes).ok_or_else(|| {
            bad(format!(
                "{what}: the channels up to this one declare more than 2^64 bytes of data (Points x Lines x SaveBits)"
            ))
        })?;
    }
    // A length unit (`A` is the ampere of a current here, not ångström).
    let length = |s: &HashMap<String, String>| s.get("Dim2Unit").and_then(|u| instrument::length_unit(u, false));
    let names: Vec<String> = channels.iter().map(|c| c.name.clone()).collect();
    let default = channels.iter().position(|c| length(section(&c.section)).is_some());
    let index = cx.channel(&names, default, options)?;
    let c = &channels[index];
    let s = section(&c.section);
    let unit = s.get("Dim2Unit").map_or("", String::as_str);
    let Some(metres) = length(s) else {
        return Err(ReadError::Channel {
            path: cx.path(),
            detail: format!(
                "channel {index} ({}) holds no heights: its unit is \"{}\", not a length",
                clip(&c.name, 40),
                clip(unit, 20)
            ),
            available: names,
        });
    };
    let what = format!("[{}]", clip(&c.section, 40));
    let real = |key: &str| -> Result<Option<f64>, ReadError> {
        match s.get(key) {
            None => Ok(None),
            Some(v) => v
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .map(Some)
                .ok_or_else(|| bad(format!("{what}: {key} = \"{}\" is not a number", clip(v, 20)))),
        }
    };
    let need = |key: &str| real(key)?.ok_or_else(|| bad(format!("{what}: no {key}")));
    let range = need("Dim2Range")?;
    // The lateral sizes in the height unit, then metres (SurfaceTopography's
    // order of operations).
    let lateral = |axis: u8| -> Result<f64, ReadError> {
        let size = need(&format!("Dim{axis}Range"))?;
        let factor = match s.get(&format!("Dim{axis}Unit")) {
            None => 1.0,
            Some(u) if u == unit => 1.0,
            Some(u) => match instrument::length_unit(u, false) {
                Some(m) => instrument::ratio(m, metres),
                None => {
                    return Err(bad(format!(
                        "{what}: Dim{axis}Unit \"{}\" is not a length",
                        clip(u, 20)
                    )))
                }
            },
        };
        Ok(size * factor)
    };
    let to_m = instrument::ratio(metres, 1.0);
    let (sx, sy) = (lateral(0)? * to_m, lateral(1)? * to_m);
    // Dim2Min … Dim2Min + Dim2Range over the integers' range; signed
    // integers are centred.
    let scale = range / 2f64.powi(8 * c.int.size as i32);
    let mut shift = real("Dim2Min")?.unwrap_or(0.0);
    if c.int.signed {
        shift += range / 2.0;
    }
    let shift = if shift != 0.0 && scale != 0.0 {
        shift / scale
    } else {
        0.0
    };
    // Checked: an earlier channel can declare ~2^64 bytes (a wrapped
    // offset would read the header's text as heights).
    let offset = data_start.checked_add(c.offset).ok_or_else(|| {
        bad(format!(
            "channel {index} ({}): its data start {} bytes after byte {data_start}, beyond any file (the earlier channels' sizes are wrong)",
            clip(&c.name, 40),
            c.offset
        ))
    })?;
    let topography = instrument::channel_map(
        &mut Binary::new(cx, source, len, DESCRIPTION),
        (index, &c.name),
        offset,
        (c.nx, c.ny),
        c.int,
        (sx, sy),
        options,
        &|v| (v + shift) * scale * to_m,
    )?;

    let info = section("DataSet-Info");
    let mut instrument = "Nanosurf".to_string();
    if let Some(head) = info.get("Head type") {
        instrument = format!("{instrument} {head}");
    }
    if let Some(serial) = info.get("Controller S/N") {
        instrument = format!("{instrument} (controller S/N {serial})");
    }
    let metadata = Metadata {
        instrument: Some(instrument),
        date: date(info.get("Date"), info.get("Time")),
        channel: Some(c.name.clone()),
        channels: names.clone(),
        height_unit: Some(unit.to_string()),
        ..Metadata::default()
    };
    Ok(topography.with_metadata(metadata))
}

/// `dd-mm-yyyy` and `hh:mm:ss` as ISO 8601 (`2022-11-03T11:46:25`), or as
/// the file gives them where they are not of that form.
fn date(day: Option<&String>, time: Option<&String>) -> Option<String> {
    let iso = day.and_then(|d| match d.split('-').collect::<Vec<_>>()[..] {
        [dd, mm, yyyy] if [dd, mm, yyyy].iter().all(|p| p.bytes().all(|b| b.is_ascii_digit())) => {
            Some(format!("{yyyy}-{mm}-{dd}"))
        }
        _ => None,
    });
    match (iso, day, time) {
        (Some(d), _, Some(t)) => Some(format!("{d}T{t}")),
        (Some(d), _, None) => Some(d),
        (None, Some(d), Some(t)) => Some(format!("{d} {t}")),
        (None, Some(d), None) => Some(d.clone()),
        (None, None, t) => t.cloned(),
    }
}
