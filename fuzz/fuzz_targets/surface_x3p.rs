//! Structure-aware X3P: an `arbitrary` description of an archive (feature
//! type, axis and data types, increments and offsets, sizes including huge
//! ones, a DataList or a DataLink, MD5 checksums right, wrong or absent,
//! extra nested elements, point data and a validity mask of fuzzed length,
//! sometimes a duplicate member or a damaged archive) is written as a zip
//! with the `zip` crate and read by `read_bytes` as `surface.x3p`; a surface
//! read keeps the invariant of surface_check.rs. Raw bytes almost never make
//! a zip whose main.xml parses: this target reaches the XML lookups, the
//! size checks, the decoders and the mask every run.
//!
//! The nesting of extra elements is at most [`MAX_DEPTH`]: deeper XML
//! overflows the stack in roxmltree (a known issue of the current reader).
#![no_main]

#[path = "surface_check.rs"]
mod surface_check;

use std::io::{Cursor, Write};

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use md5::{Digest, Md5};
use surface_check::OptionsSpec;
use zip::write::SimpleFileOptions;
use zip::{CompressionMethod, ZipWriter};

/// The deepest nesting of extra elements generated (see the module docs).
const MAX_DEPTH: usize = 300;
/// The most point-data bytes generated (a larger declared size gets the
/// fuzzer's bytes as they are).
const MAX_DATA: usize = 1 << 16;

/// A number in main.xml as the fuzzer writes it.
#[derive(Debug, Clone, Arbitrary)]
enum Num {
    /// 1e-6 (the fixed options' interval: no conflict).
    Micro,
    /// k·10⁻⁹ (0 and negatives included).
    Small(i16),
    /// Edge cases, as text.
    Edge(u8),
    /// Any bits, formatted by Rust.
    Raw(f64),
    /// Any text (escaped).
    Text(String),
}

impl Num {
    fn text(&self) -> String {
        match self {
            Num::Micro => "1e-6".to_string(),
            Num::Small(k) => format!("{:e}", *k as f64 * 1e-9),
            Num::Edge(k) => {
                const EDGES: [&str; 14] = [
                    "0", "-0", "1e-6", "-1e-6", "1e-300", "1e300", "NaN", "INF", "-inf", "1e999", " 2.5e-7 ", "1",
                    "0x10", "",
                ];
                EDGES[*k as usize % EDGES.len()].to_string()
            }
            Num::Raw(v) => format!("{v:e}"),
            Num::Text(s) => escape(s),
        }
    }
}

/// A short name: the standard one, one of a few usual ones, or the
/// fuzzer's.
#[derive(Debug, Clone, Arbitrary)]
enum Word {
    Standard,
    Usual(u8),
    Other(String),
}

impl Word {
    fn get(&self, usual: &[&str]) -> String {
        match self {
            Word::Standard => usual[0].to_string(),
            Word::Usual(k) => usual[*k as usize % usual.len()].to_string(),
            Word::Other(s) => escape(&s.chars().take(24).collect::<String>()),
        }
    }
}

/// The elements a fault can leave out.
const REQUIRED: [&str; 15] = [
    "Record1",
    "FeatureType",
    "Axes",
    "CX",
    "CY",
    "CZ",
    "AxisType",
    "DataType",
    "Record3",
    "MatrixDimension",
    "SizeX",
    "SizeY",
    "SizeZ",
    "PointDataLink",
    "Increment",
];

/// One thing wrong with an otherwise well-formed main.xml. The fuzzer's
/// list of faults is often empty or short, so that most archives get far
/// into the reader and each fault is met on its own.
#[derive(Debug, Clone, Arbitrary)]
enum Fault {
    /// A feature type other than SUR / PRF (or the other one of the two).
    Feature(Word),
    /// Axis 0–2's AxisType.
    AxisType(u8, Word),
    /// CZ's DataType.
    DataType(Word),
    /// Axis 0–2's Increment.
    Increment(u8, Num),
    /// Axis 0–2's Offset.
    Offset(u8, Num),
    /// Leave out an element of [`REQUIRED`] (wherever it occurs).
    Omit(u8),
    /// SizeX, SizeY or SizeZ: huge.
    Huge(u8, u8),
    /// SizeX, SizeY or SizeZ: any number's text.
    Size(u8, Num),
    /// Another root element.
    Root(String),
}

/// An MD5 checksum element.
#[derive(Debug, Clone, Copy, Arbitrary)]
enum Md5Spec {
    Right,
    Absent,
    RightUpper,
    /// The right one with a digit changed.
    Wrong,
    Empty,
}

/// How many bytes a member holds: what main.xml makes, that ± a few, or
/// the fuzzer's bytes as they are.
#[derive(Debug, Clone, Copy, Arbitrary)]
enum Len {
    Exact,
    Delta(i8),
    Raw,
}

impl Len {
    /// `want` bytes (if known and at most [`MAX_DATA`]) or ±, filled by
    /// cycling `bytes`.
    fn make(self, want: Option<u64>, bytes: &[u8]) -> Vec<u8> {
        let want = want.filter(|&w| w <= MAX_DATA as u64).map(|w| w as usize);
        let len = match (self, want) {
            (Len::Exact, Some(w)) => w,
            (Len::Delta(d), Some(w)) => w.saturating_add_signed(d as isize),
            _ => return bytes.to_vec(),
        };
        if bytes.is_empty() {
            vec![0; len]
        } else {
            bytes.iter().copied().cycle().take(len).collect()
        }
    }
}

/// Where the point data come from.
#[derive(Debug, Clone, Arbitrary)]
enum Data {
    /// A DataLink to a member.
    Link {
        name: Word,
        /// Whether the member named is left out of the archive.
        missing: bool,
        md5: Md5Spec,
        len: Len,
        mask: Option<Mask>,
    },
    /// A DataList of Datum elements (one per point unless `short`).
    List { data: Vec<Datum>, short: bool },
    /// Neither.
    None,
}

#[derive(Debug, Clone, Arbitrary)]
enum Datum {
    Value(Num),
    Empty,
    Triple,
}

/// A validity mask.
#[derive(Debug, Clone, Arbitrary)]
struct Mask {
    /// A ValidPointsLink element (else the reader looks for valid.bin).
    link: Option<Word>,
    missing: bool,
    md5: Md5Spec,
    len: Len,
    bytes: Vec<u8>,
}

/// Extra elements nested `depth` deep, at one of a few places.
#[derive(Debug, Clone, Copy, Arbitrary)]
struct Nest {
    depth: u16,
    place: u8,
}

/// Damage to the finished archive.
#[derive(Debug, Clone, Copy, Arbitrary)]
enum Damage {
    None,
    Truncate(u16),
    Flip(u16, u8),
}

#[derive(Debug, Arbitrary)]
struct Input {
    options: OptionsSpec,
    /// PRF (one row) rather than SUR.
    profile: bool,
    /// D, F, L or I.
    z_type: u8,
    /// The sizes (1 … 64 each) and the axes' increments (CX, CY, CZ).
    nx: u8,
    ny: u8,
    increments: [Option<Num>; 3],
    data: Data,
    faults: Vec<Fault>,
    points: Vec<u8>,
    nest: Option<Nest>,
    /// Write a second member of this name (0: main.xml, 1: the data, 2: the
    /// mask) with other content.
    duplicate: Option<(u8, Vec<u8>)>,
    stored: bool,
    namespace: bool,
    damage: Damage,
}

/// Text with XML's special characters escaped.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

fn md5_hex(bytes: &[u8]) -> String {
    Md5::digest(bytes).iter().map(|b| format!("{b:02x}")).collect()
}

/// The checksum element `tag` for `bytes`, if any.
fn md5_leaf(xml: &mut String, tag: &str, spec: Md5Spec, bytes: &[u8]) {
    let hex = md5_hex(bytes);
    let text = match spec {
        Md5Spec::Absent => return,
        Md5Spec::Right => hex,
        Md5Spec::RightUpper => hex.to_uppercase(),
        Md5Spec::Wrong => {
            let flip = if hex.starts_with('0') { "1" } else { "0" };
            format!("{flip}{}", &hex[1..])
        }
        Md5Spec::Empty => String::new(),
    };
    xml.push_str(&format!("<{tag}>{text}</{tag}>"));
}

/// main.xml as it is written: the elements left out by faults are skipped.
struct Xml {
    s: String,
    omit: Vec<&'static str>,
}

impl Xml {
    fn leaf(&mut self, tag: &str, text: &str) {
        if !self.omit.contains(&tag) {
            self.s.push_str(&format!("<{tag}>{text}</{tag}>"));
        }
    }

    fn open(&mut self, tag: &str) {
        let t = if self.omit.contains(&tag) { "Omitted" } else { tag };
        self.s.push_str(&format!("<{t}>"));
    }

    fn close(&mut self, tag: &str) {
        let t = if self.omit.contains(&tag) { "Omitted" } else { tag };
        self.s.push_str(&format!("</{t}>"));
    }

    /// `depth` nested extra elements.
    fn nest(&mut self, depth: usize) {
        self.s.extend(std::iter::repeat_n("<e>", depth));
        self.s.push('x');
        self.s.extend(std::iter::repeat_n("</e>", depth));
    }
}

/// The bytes of one value of data type `t` (D when unknown).
fn type_size(t: &str) -> u64 {
    match t {
        "F" | "L" => 4,
        "I" => 2,
        _ => 8,
    }
}

fuzz_target!(|input: Input| {
    let options = input.options.options(None);
    let depth = input.nest.map_or(0, |n| n.depth as usize % (MAX_DEPTH + 1));
    let place = input.nest.map_or(0, |n| n.place % 3);
    let faults = &input.faults[..input.faults.len().min(4)];

    // The fields, standard ones changed by the faults.
    let mut feature = if input.profile { "PRF" } else { "SUR" }.to_string();
    let mut z_type = ["D", "F", "L", "I"][input.z_type as usize % 4].to_string();
    let mut kinds = ["I", "I", "A"].map(String::from);
    let mut increments = input.increments.clone().map(|n| n.map(|n| n.text()));
    let mut offsets: [Option<String>; 3] = Default::default();
    let nx = 1 + input.nx as u64 % 64;
    let ny = if input.profile { 1 } else { 1 + input.ny as u64 % 64 };
    let mut sizes = [nx, ny, 1].map(|v| v.to_string());
    let mut root = "ISO5436_2".to_string();
    let mut xml = Xml {
        s: String::new(),
        omit: vec![],
    };
    for fault in faults {
        match fault {
            Fault::Feature(w) => feature = w.get(&["PRF", "SUR", "VOL", "sur", ""]),
            Fault::AxisType(k, w) => kinds[*k as usize % 3] = w.get(&["R", "A", "I", ""]),
            Fault::DataType(w) => z_type = w.get(&["B", "DD", "d", "", "D"]),
            Fault::Increment(k, n) => increments[*k as usize % 3] = Some(n.text()),
            Fault::Offset(k, n) => offsets[*k as usize % 3] = Some(n.text()),
            Fault::Omit(k) => xml.omit.push(REQUIRED[*k as usize % REQUIRED.len()]),
            Fault::Huge(k, h) => {
                const HUGE: [&str; 9] = [
                    "4294967295",
                    "4294967296",
                    "18446744073709551615",
                    "18446744073709551616",
                    "9223372036854775808",
                    "1099511627776",
                    "1048577",
                    "-1",
                    "+7",
                ];
                sizes[*k as usize % 3] = HUGE[*h as usize % HUGE.len()].to_string();
            }
            Fault::Size(k, n) => sizes[*k as usize % 3] = n.text(),
            Fault::Root(r) => root = escape(&r.chars().take(16).collect::<String>()),
        }
    }
    let size_values: Vec<Option<u64>> = sizes.iter().map(|s| s.trim().parse().ok()).collect();
    let points = match (size_values[0], size_values[1]) {
        (Some(x), Some(y)) => x.checked_mul(y),
        _ => None,
    };

    // main.xml
    let (p, ns) = if input.namespace {
        ("p:", " xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\"")
    } else {
        ("", "")
    };
    xml.s = format!("<?xml version=\"1.0\" encoding=\"UTF-8\"?><{p}{root}{ns}>");
    xml.open("Record1");
    xml.leaf("Revision", "ISO5436 - 2000");
    xml.leaf("FeatureType", &feature);
    if place == 0 {
        xml.nest(depth);
    }
    xml.open("Axes");
    for (k, tag) in ["CX", "CY", "CZ"].iter().enumerate() {
        xml.open(tag);
        xml.leaf("AxisType", &kinds[k]);
        xml.leaf("DataType", if k == 2 { &z_type } else { "D" });
        if let Some(v) = &increments[k] {
            xml.leaf("Increment", v);
        }
        if let Some(v) = &offsets[k] {
            xml.leaf("Offset", v);
        }
        xml.close(tag);
    }
    xml.close("Axes");
    xml.close("Record1");
    xml.s.push_str("<Record2>");
    if place == 1 {
        xml.nest(depth);
    }
    xml.s.push_str("</Record2>");
    xml.open("Record3");
    xml.open("MatrixDimension");
    for (tag, size) in ["SizeX", "SizeY", "SizeZ"].iter().zip(&sizes) {
        xml.leaf(tag, size);
    }
    xml.close("MatrixDimension");
    if place == 2 {
        xml.nest(depth);
    }

    // The members beside main.xml: (name, content).
    let mut members: Vec<(String, Vec<u8>)> = vec![];
    match &input.data {
        Data::List { data, short } => {
            xml.s.push_str("<DataList>");
            let n = match (short, points) {
                (false, Some(n)) if n <= 4096 && !data.is_empty() => n as usize,
                _ => data.len().min(4096),
            };
            for datum in data.iter().cycle().take(n) {
                match datum {
                    Datum::Value(v) => xml.leaf("Datum", &v.text()),
                    Datum::Empty => xml.s.push_str("<Datum/>"),
                    Datum::Triple => xml.leaf("Datum", "1;2;3"),
                }
            }
            xml.s.push_str("</DataList>");
        }
        Data::Link {
            name,
            missing,
            md5,
            len,
            mask,
        } => {
            let data_name = name.get(&["bindata/data.bin", "data.bin", "main.xml", "bindata/valid.bin"]);
            let want = points.map(|n| n.saturating_mul(type_size(&z_type)));
            let data = len.make(want, &input.points);
            xml.s.push_str("<DataLink>");
            xml.leaf("PointDataLink", &data_name);
            md5_leaf(&mut xml.s, "MD5ChecksumPointData", *md5, &data);
            if !*missing {
                members.push((
                    data_name
                        .replace("&amp;", "&")
                        .replace("&lt;", "<")
                        .replace("&gt;", ">"),
                    data,
                ));
            }
            if let Some(m) = mask {
                let mask_name = m.link.as_ref().map_or("bindata/valid.bin".to_string(), |w| {
                    w.get(&["bindata/valid.bin", "valid.bin", "bindata/data.bin"])
                });
                let bytes = m.len.make(points.map(|n| n.div_ceil(8)), &m.bytes);
                if m.link.is_some() {
                    xml.leaf("ValidPointsLink", &mask_name);
                }
                md5_leaf(&mut xml.s, "MD5ChecksumValidPoints", m.md5, &bytes);
                if !m.missing {
                    members.push((
                        mask_name
                            .replace("&amp;", "&")
                            .replace("&lt;", "<")
                            .replace("&gt;", ">"),
                        bytes,
                    ));
                }
            }
            xml.s.push_str("</DataLink>");
        }
        Data::None => {}
    }
    xml.close("Record3");
    xml.s.push_str(&format!("</{p}{root}>"));
    members.insert(0, ("main.xml".to_string(), xml.s.into_bytes()));

    // A duplicate member: written under a placeholder name of the same
    // length (the zip crate refuses duplicate names), renamed in the bytes.
    let mut rename = None;
    if let Some((which, content)) = &input.duplicate {
        let k = *which as usize % members.len();
        let name = members[k].0.clone();
        if !name.is_empty() && name.is_ascii() {
            let placeholder: String = name[..name.len() - 1].to_string() + "\u{1}";
            rename = Some((placeholder.clone(), name));
            members.push((placeholder, content.clone()));
        }
    }

    let mut zip = ZipWriter::new(Cursor::new(Vec::new()));
    let method = if input.stored {
        CompressionMethod::Stored
    } else {
        CompressionMethod::Deflated
    };
    let file_options = SimpleFileOptions::default().compression_method(method);
    for (name, content) in &members {
        if zip.start_file(name.as_str(), file_options).is_err() {
            return; // a name the writer refuses (a duplicate link name)
        }
        zip.write_all(content).expect("writing to memory");
    }
    let mut bytes = zip.finish().expect("finishing in memory").into_inner();
    if let Some((placeholder, name)) = rename {
        let (from, to) = (placeholder.as_bytes(), name.as_bytes());
        let mut i = 0;
        while i + from.len() <= bytes.len() {
            if &bytes[i..i + from.len()] == from {
                bytes[i..i + from.len()].copy_from_slice(to);
                i += from.len();
            } else {
                i += 1;
            }
        }
    }
    match input.damage {
        Damage::None => {}
        Damage::Truncate(k) => {
            let keep = k as usize % (bytes.len() + 1);
            bytes.truncate(keep);
        }
        Damage::Flip(k, x) => {
            if !bytes.is_empty() {
                let i = k as usize % bytes.len();
                bytes[i] ^= x;
            }
        }
    }
    surface_check::read(&bytes, "surface.x3p", &options);
});
