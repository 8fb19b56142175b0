//! ISO 25178-72 X3P (formerly ISO 5436-2 XML): a zip archive holding
//! `main.xml` (the axes, sizes, data link and checksums) and the binary
//! point data (`bindata/data.bin`: little-endian values, x fastest, then
//! y), with an optional validity mask (one bit per point, least
//! significant bit first, 1 = valid).
//!
//! Read: feature types SUR (surface) and PRF (profile), incremental x and
//! y axes, z data types D (f64), F (f32), L (i32), I (i16); a height is
//! `offset + increment · value` with the CZ axis's Increment (default 1)
//! and Offset (default 0), for every type. `MD5ChecksumPointData` and
//! `MD5ChecksumValidPoints` are checked where present; the archive's
//! `md5checksum.hex` (Record4) is not. The writer is topography/write.rs.

use std::collections::HashSet;
use std::io::{self, Read, SeekFrom};

use md5::{Digest, Md5};
use roxmltree::{Document, Node, ParsingOptions};
use zip::result::ZipError;
use zip::ZipArchive;

use super::{clip, Ctx, Entry, ReadError, ReadOptions, Source, CHUNK};
use crate::topography::Topography;

/// The registry's entry.
pub(super) const ENTRY: Entry = Entry {
    name: "x3p",
    description: "ISO 25178-72 X3P (a zip of main.xml and the point data)",
    extensions: &["x3p"],
    sniff: Some(|head| head.starts_with(b"PK\x03\x04")),
    read: |cx, source, _, options| read(cx, source, options),
};

/// The bound on `main.xml` (bytes).
const MAX_XML: u64 = 16 << 20;
/// The data member's usual name, and the validity mask's.
pub(in crate::topography) const DATA_BIN: &str = "bindata/data.bin";
pub(in crate::topography) const VALID_BIN: &str = "bindata/valid.bin";

/// A z data type: D, F, L or I.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::topography) enum ZType {
    D,
    F,
    L,
    I,
}

impl ZType {
    pub(in crate::topography) fn from_char(c: char) -> Option<ZType> {
        match c {
            'D' => Some(ZType::D),
            'F' => Some(ZType::F),
            'L' => Some(ZType::L),
            'I' => Some(ZType::I),
            _ => None,
        }
    }

    pub(in crate::topography) fn letter(self) -> char {
        match self {
            ZType::D => 'D',
            ZType::F => 'F',
            ZType::L => 'L',
            ZType::I => 'I',
        }
    }

    pub(in crate::topography) fn size(self) -> usize {
        match self {
            ZType::D => 8,
            ZType::F | ZType::L => 4,
            ZType::I => 2,
        }
    }

    /// The value of one little-endian item (`bytes.len() == self.size()`).
    fn decode(self, bytes: &[u8]) -> f64 {
        match (self, bytes) {
            (ZType::D, &[a, b, c, d, e, f, g, h]) => f64::from_le_bytes([a, b, c, d, e, f, g, h]),
            (ZType::F, &[a, b, c, d]) => f64::from(f32::from_le_bytes([a, b, c, d])),
            (ZType::L, &[a, b, c, d]) => f64::from(i32::from_le_bytes([a, b, c, d])),
            (ZType::I, &[a, b]) => f64::from(i16::from_le_bytes([a, b])),
            _ => f64::NAN,
        }
    }
}

fn archive_err(cx: &Ctx, detail: impl std::fmt::Display) -> ReadError {
    ReadError::Archive {
        path: cx.path(),
        detail: detail.to_string(),
    }
}

fn xml_err(cx: &Ctx, detail: impl Into<String>) -> ReadError {
    ReadError::Xml {
        path: cx.path(),
        detail: detail.into(),
    }
}

/// The lower-case hex of the MD5 of `bytes`.
pub(in crate::topography) fn md5_hex(bytes: &[u8]) -> String {
    hex(&Md5::digest(bytes))
}

/// Lower-case hex.
fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

/// Reads an X3P file from `source`: the archive's directory, `main.xml`
/// (bounded in size, depth and nodes), then the point data and validity
/// mask decoded piece by piece into the heights (never held as bytes).
pub(super) fn read(cx: &Ctx, source: &mut dyn Source, options: &ReadOptions) -> Result<Topography, ReadError> {
    let zip = ZipArchive::new(&mut *source).map_err(|e| match e {
        // No directory at the end: cut short, or not a zip file at all.
        ZipError::InvalidArchive(detail) => {
            archive_err(cx, format!("{detail}: the file is truncated, or not a zip archive"))
        }
        e => zip_err(cx, "the archive", e),
    })?;
    let dir_start = zip.central_directory_start();
    let source = zip.into_inner();
    unique_names(cx, source, dir_start)?;
    let mut zip = ZipArchive::new(source).map_err(|e| zip_err(cx, "the archive", e))?;
    let xml = member(cx, &mut zip, "main.xml", MAX_XML.min(options.max_bytes))?;
    let xml = String::from_utf8(xml).map_err(|e| xml_err(cx, format!("not UTF-8: {e}")))?;
    check_depth(&xml).map_err(|e| xml_err(cx, e))?;
    let parsing = ParsingOptions {
        allow_dtd: false,
        nodes_limit: MAX_XML_NODES,
    };
    let doc = Document::parse_with_options(&xml, parsing).map_err(|e| xml_err(cx, e.to_string()))?;
    let root = doc.root_element();
    if root.tag_name().name() != "ISO5436_2" {
        return Err(xml_err(
            cx,
            format!("the root element is {}, not ISO5436_2", clip(root.tag_name().name(), 40)),
        ));
    }
    let x = Xml { cx };

    let record1 = x.child(root, "Record1")?;
    let profile = match x.text(record1, "FeatureType")? {
        "SUR" => false,
        "PRF" => true,
        other => {
            return Err(cx.unsupported(format!(
                "FeatureType {} (only SUR surfaces and PRF profiles are read)",
                clip(other, 20)
            )))
        }
    };
    let axes = x.child(record1, "Axes")?;
    let dx = x.increment(x.child(axes, "CX")?, "CX")?;
    let dy = if profile {
        None
    } else {
        x.increment(x.child(axes, "CY")?, "CY")?
    };
    let cz = x.child(axes, "CZ")?;
    if let Some(kind) = x.opt_text(cz, "AxisType") {
        if kind != "A" {
            return Err(cx.unsupported(format!("CZ AxisType {} (must be A)", clip(kind, 20))));
        }
    }
    let z_type = x.text(cz, "DataType")?;
    let mut letters = z_type.chars();
    let z_type = match (letters.next(), letters.next()) {
        (Some(c), None) => ZType::from_char(c),
        _ => None,
    }
    .ok_or_else(|| {
        cx.unsupported(format!(
            "CZ DataType {} (only D, F, L and I are read)",
            clip(z_type, 20)
        ))
    })?;
    let increment = x.number(cz, "CZ", "Increment")?.unwrap_or(1.0);
    let offset = x.number(cz, "CZ", "Offset")?.unwrap_or(0.0);
    if increment == 0.0 {
        return Err(xml_err(cx, "CZ Increment is 0"));
    }

    let record3 = x.child(root, "Record3")?;
    let dims = x.child(record3, "MatrixDimension")?;
    let [nx, ny, nz] = ["SizeX", "SizeY", "SizeZ"].map(|name| x.size(dims, name));
    let (nx, ny, nz) = (nx?, ny?, nz?);
    if nz != 1 {
        return Err(cx.unsupported(format!("SizeZ = {nz} (volumetric data; only SizeZ = 1 is read)")));
    }
    if profile && ny != 1 {
        return Err(cx.size(format!("a profile (FeatureType PRF) with SizeY = {ny}, not 1")));
    }
    let points = nx.saturating_mul(ny);
    if points == 0 {
        return Err(cx.size(format!("SizeX x SizeY = {nx} x {ny}: no points")));
    }
    let declared = || format!("main.xml's SizeX x SizeY = {nx} x {ny}");
    cx.check_points(declared, points, options)?;
    let data_bytes = points.saturating_mul(z_type.size() as u64);
    if data_bytes > options.max_bytes {
        return Err(cx.too_large(
            format!(
                "the point data declared in main.xml ({nx} x {ny} of type {})",
                z_type.letter()
            ),
            data_bytes,
            options.max_bytes,
        ));
    }

    // The point data: binary in a member the DataLink names (with an
    // optional validity mask), or listed in main.xml (DataList: one Datum
    // per point, an empty one missing).
    let heights = if let Some(list) = x.opt_child(record3, "DataList") {
        let heights = cx.heights(declared, points, options)?;
        data_list(cx, list, z_type, heights, (offset, increment))?
    } else {
        let link = x
            .opt_child(record3, "DataLink")
            .ok_or_else(|| xml_err(cx, "no DataLink or DataList in Record3"))?;
        let data_name = x.text(link, "PointDataLink")?;
        let mut heights = cx.heights(declared, points, options)?;
        let md5 = x.opt_text(link, "MD5ChecksumPointData");
        stream(cx, &mut zip, data_name, data_bytes, md5, |piece| {
            heights.extend(
                piece
                    .chunks_exact(z_type.size())
                    .map(|raw| offset + increment * z_type.decode(raw)),
            );
        })?;

        let valid_name = match x.opt_text(link, "ValidPointsLink") {
            Some(name) => Some(name),
            None => zip.index_for_name(VALID_BIN).map(|_| VALID_BIN),
        };
        if let Some(valid_name) = valid_name {
            let md5 = x.opt_text(link, "MD5ChecksumValidPoints");
            let mut at = 0;
            stream(cx, &mut zip, valid_name, points.div_ceil(8), md5, |piece| {
                for &bits in piece {
                    for (bit, h) in heights[at..].iter_mut().take(8).enumerate() {
                        if bits >> bit & 1 == 0 {
                            *h = f64::NAN;
                        }
                    }
                    at += 8;
                }
            })?;
        }
        heights
    };
    // nx, ny <= points, which fit a usize (the heights are allocated).
    let (n, ny) = (heights.len(), ny as usize);
    cx.make(heights, (n / ny, ny), (dx, dy), options, profile)
}

/// The heights of a `DataList`, into `heights` (empty, with room for
/// exactly the `n` points declared): `n` `Datum` elements in row-major order,
/// each a number of the type `z_type` (scaled by `offset + increment·v`)
/// or empty (a missing point). Coordinate triples (`x;y;z`, irregular
/// grids) are not read.
fn data_list(
    cx: &Ctx,
    list: Node,
    z_type: ZType,
    mut heights: Vec<f64>,
    (offset, increment): (f64, f64),
) -> Result<Vec<f64>, ReadError> {
    let n = heights.capacity();
    for (i, datum) in list
        .children()
        .filter(|c| c.is_element() && c.tag_name().name() == "Datum")
        .enumerate()
    {
        if i >= n {
            return Err(cx.size(format!("DataList holds more than the {n} points of MatrixDimension")));
        }
        let text = datum.text().unwrap_or("").trim();
        if text.is_empty() {
            heights.push(f64::NAN);
            continue;
        }
        let bad = || {
            xml_err(
                cx,
                format!(
                    "Datum {i} is \"{}\": not a number of data type {}",
                    clip(text, 40),
                    z_type.letter()
                ),
            )
        };
        if text.contains(';') {
            return Err(cx.unsupported(format!(
                "Datum {i} is \"{}\": coordinate lists (x;y;z) are not read",
                clip(text, 40)
            )));
        }
        let v = match z_type {
            ZType::D => text.parse::<f64>().ok(),
            ZType::F => text.parse::<f32>().ok().map(f64::from),
            ZType::L => text.parse::<i32>().ok().map(f64::from),
            ZType::I => text.parse::<i16>().ok().map(f64::from),
        }
        .filter(|v| v.is_finite())
        .ok_or_else(bad)?;
        heights.push(offset + increment * v);
    }
    if heights.len() != n {
        return Err(cx.size(format!(
            "DataList holds {} points, MatrixDimension says {n}",
            heights.len()
        )));
    }
    Ok(heights)
}

/// The archive read from a file or from memory.
type Zip<'s> = ZipArchive<&'s mut dyn Source>;

/// An archive error: "truncated" for data that end early, the zip crate's
/// detail for a damaged archive, else an I/O failure.
fn zip_err(cx: &Ctx, what: &str, e: ZipError) -> ReadError {
    match e {
        ZipError::Io(e) => io_err(cx, what, e),
        ZipError::FileNotFound => archive_err(cx, format!("no {what}")),
        e => archive_err(cx, format!("{what}: {e}")),
    }
}

/// A failed read of `what`: "truncated" if it ended early; the zip
/// crate's checks (CRC, deflate) give invalid data; else an I/O failure.
fn io_err(cx: &Ctx, what: &str, e: io::Error) -> ReadError {
    match e.kind() {
        io::ErrorKind::UnexpectedEof => archive_err(cx, format!("{what} ends early: the file is truncated")),
        io::ErrorKind::InvalidData | io::ErrorKind::InvalidInput => archive_err(cx, format!("{what}: {e}")),
        _ => cx.io(e),
    }
}

/// Refuses an archive with two members of one name (the zip crate would
/// silently read the last): walks the central directory at `start`.
fn unique_names(cx: &Ctx, source: &mut dyn Source, start: u64) -> Result<(), ReadError> {
    const SIGNATURE: u32 = 0x0201_4b50;
    let what = "the archive's directory";
    source.seek(SeekFrom::Start(start)).map_err(|e| io_err(cx, what, e))?;
    let mut names = HashSet::new();
    let mut fixed = [0u8; 46];
    let mut name = Vec::new();
    loop {
        match source.read_exact(&mut fixed) {
            Ok(()) => {}
            Err(e) if e.kind() == io::ErrorKind::UnexpectedEof => break,
            Err(e) => return Err(io_err(cx, what, e)),
        }
        if u32::from_le_bytes([fixed[0], fixed[1], fixed[2], fixed[3]]) != SIGNATURE {
            break;
        }
        let field = |at: usize| usize::from(u16::from_le_bytes([fixed[at], fixed[at + 1]]));
        name.resize(field(28), 0);
        source.read_exact(&mut name).map_err(|e| io_err(cx, what, e))?;
        let skip = (field(30) + field(32)) as i64;
        source.seek(SeekFrom::Current(skip)).map_err(|e| io_err(cx, what, e))?;
        let text = String::from_utf8_lossy(&name).into_owned();
        if !names.insert(text.clone()) {
            return Err(archive_err(
                cx,
                format!(
                    "two members are named {} (which one is meant is ambiguous)",
                    clip(&text, 80)
                ),
            ));
        }
    }
    source.rewind().map_err(|e| io_err(cx, what, e))
}

/// The most nested elements `main.xml` may have (an X3P file has 6):
/// deeper is refused before parsing, whose recursion an attacker would
/// otherwise control.
const MAX_XML_DEPTH: usize = 64;

/// The most nodes `main.xml` may have (a DataList holds one per point).
const MAX_XML_NODES: u32 = 1 << 23;

/// Checks that the elements of `xml` nest at most [`MAX_XML_DEPTH`] deep,
/// without recursion: counts start and end tags, skipping comments,
/// processing instructions, CDATA, declarations and quoted attribute
/// values. Malformed markup is left to the parser.
fn check_depth(xml: &str) -> Result<(), String> {
    let b = xml.as_bytes();
    let (mut i, mut depth) = (0, 0usize);
    let skip_to = |from: usize, end: &[u8]| -> usize {
        b[from..]
            .windows(end.len())
            .position(|w| w == end)
            .map_or(b.len(), |p| from + p + end.len())
    };
    while i < b.len() {
        if b[i] != b'<' {
            i += 1;
            continue;
        }
        let rest = &b[i..];
        if rest.starts_with(b"<!--") {
            i = skip_to(i + 4, b"-->");
        } else if rest.starts_with(b"<![CDATA[") {
            i = skip_to(i + 9, b"]]>");
        } else if rest.starts_with(b"<?") {
            i = skip_to(i + 2, b"?>");
        } else if rest.starts_with(b"<!") || rest.starts_with(b"</") {
            if rest.starts_with(b"</") {
                depth = depth.saturating_sub(1);
            }
            i = skip_to(i + 2, b">");
        } else {
            // A start tag: to its '>' outside quotes; `/>` closes it.
            let mut j = i + 1;
            let mut quote = None;
            while j < b.len() {
                match (quote, b[j]) {
                    (Some(q), c) if c == q => quote = None,
                    (None, c @ (b'"' | b'\'')) => quote = Some(c),
                    (None, b'>') => break,
                    _ => {}
                }
                j += 1;
            }
            if j < b.len() && b[j - 1] != b'/' {
                depth += 1;
                if depth > MAX_XML_DEPTH {
                    return Err(format!(
                        "elements nest deeper than {MAX_XML_DEPTH} levels (an X3P file has 6)"
                    ));
                }
            }
            i = j + 1;
        }
    }
    Ok(())
}

/// The content of the archive's small member `name` (`main.xml`), at most
/// `limit` bytes.
fn member(cx: &Ctx, zip: &mut Zip, name: &str, limit: u64) -> Result<Vec<u8>, ReadError> {
    let what = format!("member {}", clip(name, 80));
    let file = zip.by_name(name).map_err(|e| zip_err(cx, &what, e))?;
    let size = file.size();
    if size > limit {
        return Err(cx.too_large(what, size, limit));
    }
    let mut bytes = cx.vec(size)?;
    file.take(size.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| io_err(cx, &what, e))?;
    if bytes.len() as u64 != size {
        return Err(archive_err(
            cx,
            format!("{what} holds {} bytes, its header says {size}", bytes.len()),
        ));
    }
    Ok(bytes)
}

/// Streams the archive's member `name`, exactly `expected` bytes (its
/// declared size is checked first), to `each` in pieces of [`CHUNK`] bytes
/// (whole items of any data type); checks its MD5 if `md5` is given, and
/// its CRC (the zip crate, at the end). Memory: one piece.
fn stream(
    cx: &Ctx,
    zip: &mut Zip,
    name: &str,
    expected: u64,
    md5: Option<&str>,
    mut each: impl FnMut(&[u8]),
) -> Result<(), ReadError> {
    let what = format!("member {}", clip(name, 80));
    let mut file = zip.by_name(name).map_err(|e| zip_err(cx, &what, e))?;
    let size = file.size();
    if size != expected {
        return Err(cx.size(format!(
            "{} holds {size} bytes, main.xml's sizes and data type make {expected}",
            clip(name, 80)
        )));
    }
    let mut hasher = Md5::new();
    let mut buf = vec![0u8; CHUNK];
    let mut left = size;
    while left > 0 {
        let piece = left.min(CHUNK as u64) as usize;
        file.read_exact(&mut buf[..piece]).map_err(|e| io_err(cx, &what, e))?;
        hasher.update(&buf[..piece]);
        each(&buf[..piece]);
        left -= piece as u64;
    }
    // The end, where the zip crate checks the CRC.
    match file.read(&mut buf[..1]) {
        Ok(0) => {}
        Ok(_) => {
            return Err(archive_err(
                cx,
                format!("{what} holds more than the {size} bytes its header says"),
            ))
        }
        Err(e) => return Err(io_err(cx, &what, e)),
    }
    if let Some(expected) = md5 {
        let actual = hex(&hasher.finalize());
        if !actual.eq_ignore_ascii_case(expected) {
            return Err(ReadError::Checksum {
                path: cx.path(),
                member: clip(name, 80),
                expected: clip(expected, 40),
                actual,
            });
        }
    }
    Ok(())
}

/// Lookups in `main.xml`, elements by local name (any namespace).
struct Xml<'c, 'p> {
    cx: &'c Ctx<'p>,
}

impl Xml<'_, '_> {
    fn opt_child<'a, 'i>(&self, node: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
        node.children().find(|c| c.is_element() && c.tag_name().name() == name)
    }

    fn child<'a, 'i>(&self, node: Node<'a, 'i>, name: &str) -> Result<Node<'a, 'i>, ReadError> {
        self.opt_child(node, name)
            .ok_or_else(|| xml_err(self.cx, format!("no {name} in {}", clip(node.tag_name().name(), 40))))
    }

    /// The trimmed text of the child `name`, if there is one and it is
    /// not empty.
    fn opt_text<'a>(&self, node: Node<'a, '_>, name: &str) -> Option<&'a str> {
        self.opt_child(node, name)
            .map(|c| c.text().unwrap_or("").trim())
            .filter(|t| !t.is_empty())
    }

    fn text<'a>(&self, node: Node<'a, '_>, name: &str) -> Result<&'a str, ReadError> {
        self.child(node, name).map(|c| c.text().unwrap_or("").trim())
    }

    /// A finite number, if the child `name` of the axis `axis` is there.
    fn number(&self, node: Node, axis: &str, name: &str) -> Result<Option<f64>, ReadError> {
        let Some(text) = self.opt_text(node, name) else {
            return Ok(None);
        };
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(Some(v)),
            _ => Err(xml_err(
                self.cx,
                format!("{axis} {name} '{}' is not a finite number", clip(text, 40)),
            )),
        }
    }

    /// An x or y axis's increment (metres): incremental axes only.
    fn increment(&self, axis: Node, name: &str) -> Result<Option<f64>, ReadError> {
        let kind = self.text(axis, "AxisType")?;
        if kind != "I" {
            return Err(self.cx.unsupported(format!(
                "{name} AxisType {} (only incremental axes, I, are read)",
                clip(kind, 20)
            )));
        }
        self.number(axis, name, "Increment")
    }

    fn size(&self, node: Node, name: &str) -> Result<u64, ReadError> {
        let text = self.text(node, name)?;
        text.parse::<u64>().map_err(|_| {
            xml_err(
                self.cx,
                format!("MatrixDimension {name} '{}' is not a size", clip(text, 40)),
            )
        })
    }
}
