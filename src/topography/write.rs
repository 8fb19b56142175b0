//! Writing measured surfaces: ISO 25178-72 X3P files ([`write_x3p`]),
//! as the readers (read/x3p.rs) and SurfaceTopography read them.

use std::io::{Cursor, Write};
use std::path::Path;
use std::time::{SystemTime, UNIX_EPOCH};

use zip::write::SimpleFileOptions;
use zip::{CompressionMethod, ZipWriter};

use super::read::x3p::{md5_hex, ZType, DATA_BIN, VALID_BIN};
use super::Topography;

/// Writes `t` as an ISO 25178-72 X3P file at `path`, heights stored with
/// the z data type `z_type`: `'D'` (f64, exact), `'F'` (f32), `'L'` (i32)
/// or `'I'` (i16).
///
/// A map is FeatureType SUR, a profile PRF (SizeY = 1). For the integer
/// types the heights are quantised over the type's full range (CZ
/// Increment = range / (2ⁿ − 1), Offset = the lowest height minus
/// Increment · the type's minimum): within Increment / 2 of the heights.
/// Missing (NaN) points are marked invalid in `bindata/valid.bin` (and are
/// NaN in float data). `main.xml` has Records 1–4 as the standard and the
/// SurfaceTopography and openGPS readers expect; `md5checksum.hex` holds
/// the MD5 of `main.xml`.
///
/// Errors: `InvalidInput` for another `z_type`, or heights beyond f32's
/// range with `'F'`; otherwise I/O failures.
pub fn write_x3p(t: &Topography, path: &Path, z_type: char) -> std::io::Result<()> {
    let bytes = x3p_bytes(t, z_type)?;
    std::fs::write(path, bytes)
}

fn invalid_input(message: String) -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidInput, message)
}

/// The X3P file of `t` (see [`write_x3p`]).
fn x3p_bytes(t: &Topography, z_type: char) -> std::io::Result<Vec<u8>> {
    let z = ZType::from_char(z_type)
        .ok_or_else(|| invalid_input(format!("X3P z data type {z_type:?}: must be D, F, L or I")))?;
    let heights = t.heights();
    let (lo, hi) = heights
        .iter()
        .filter(|h| !h.is_nan())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &h| {
            (lo.min(h), hi.max(h))
        });
    let (lo, hi) = if lo <= hi { (lo, hi) } else { (0.0, 0.0) };

    let mut data = Vec::with_capacity(heights.len() * z.size());
    let (increment, offset) = match z {
        ZType::D => {
            heights.iter().for_each(|h| data.extend(h.to_le_bytes()));
            (1.0, 0.0)
        }
        ZType::F => {
            for &h in heights {
                let v = h as f32;
                if v.is_infinite() {
                    return Err(invalid_input(format!("height {h:e} m is beyond f32's range")));
                }
                data.extend(v.to_le_bytes());
            }
            (1.0, 0.0)
        }
        ZType::L | ZType::I => {
            let (min, max) = match z {
                ZType::L => (f64::from(i32::MIN), f64::from(i32::MAX)),
                _ => (f64::from(i16::MIN), f64::from(i16::MAX)),
            };
            let range = if hi > lo { hi - lo } else { lo.abs().max(1e-12) };
            let increment = range / (max - min);
            let offset = lo - min * increment;
            for &h in heights {
                // Missing points: any value (the mask marks them).
                let raw = if h.is_nan() {
                    min
                } else {
                    ((h - lo) / increment).round().clamp(0.0, max - min) + min
                };
                // In range by the clamp: the casts are exact.
                match z {
                    ZType::L => data.extend((raw as i32).to_le_bytes()),
                    _ => data.extend((raw as i16).to_le_bytes()),
                }
            }
            (increment, offset)
        }
    };
    let missing = heights.iter().any(|h| h.is_nan());
    let valid = missing.then(|| {
        let mut bits = vec![0u8; heights.len().div_ceil(8)];
        for (i, h) in heights.iter().enumerate() {
            if !h.is_nan() {
                bits[i / 8] |= 1 << (i % 8);
            }
        }
        bits
    });

    let xml = main_xml(t, z, increment, offset, &data, valid.as_deref());
    let mut zip = ZipWriter::new(Cursor::new(Vec::new()));
    let file_options = SimpleFileOptions::default()
        .compression_method(CompressionMethod::Deflated)
        .large_file(data.len() as u64 >= u64::from(u32::MAX));
    let checksum = format!("{} *main.xml\n", md5_hex(xml.as_bytes()).to_uppercase());
    let mut members = vec![("main.xml", xml.as_bytes()), (DATA_BIN, &data[..])];
    if let Some(valid) = &valid {
        members.push((VALID_BIN, valid));
    }
    members.push(("md5checksum.hex", checksum.as_bytes()));
    for (name, content) in members {
        zip.start_file(name, file_options).map_err(std::io::Error::other)?;
        zip.write_all(content)?;
    }
    Ok(zip.finish().map_err(std::io::Error::other)?.into_inner())
}

/// An indented XML document, element by element (the texts written here
/// need no escaping).
struct XmlOut {
    s: String,
    depth: usize,
}

impl XmlOut {
    fn indent(&mut self) {
        self.s.extend(std::iter::repeat_n("  ", self.depth));
    }

    fn open(&mut self, tag: &str) -> &mut XmlOut {
        self.indent();
        self.s.push_str(&format!("<{tag}>\n"));
        self.depth += 1;
        self
    }

    fn close(&mut self, tag: &str) -> &mut XmlOut {
        self.depth -= 1;
        self.indent();
        self.s.push_str(&format!("</{tag}>\n"));
        self
    }

    fn leaf(&mut self, tag: &str, text: impl std::fmt::Display) -> &mut XmlOut {
        self.indent();
        self.s.push_str(&format!("<{tag}>{text}</{tag}>\n"));
        self
    }

    /// An x, y or z axis.
    fn axis(&mut self, tag: &str, kind: char, data_type: char, increment: f64, offset: f64) -> &mut XmlOut {
        // xsd:double, shortest round trip: `1e-7`, `2.5e-11`; whole numbers plain.
        let num = |v: f64| {
            if v.fract() == 0.0 && v.abs() < 1e15 {
                format!("{v}")
            } else {
                format!("{v:e}")
            }
        };
        self.open(tag)
            .leaf("AxisType", kind)
            .leaf("DataType", data_type)
            .leaf("Increment", num(increment))
            .leaf("Offset", num(offset))
            .close(tag)
    }
}

/// The `main.xml` of an X3P file.
fn main_xml(t: &Topography, z: ZType, increment: f64, offset: f64, data: &[u8], valid: Option<&[u8]>) -> String {
    const NS: &str = "http://www.opengps.eu/2008/ISO5436_2";
    let date = now_iso8601();
    let version = env!("CARGO_PKG_VERSION");
    let mut x = XmlOut {
        s: format!(
            "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\" ?>\n<p:ISO5436_2 xmlns:p=\"{NS}\" \
             xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" \
             xsi:schemaLocation=\"{NS} {NS}/ISO5436_2_XML.xsd\">\n"
        ),
        depth: 1,
    };
    x.open("Record1")
        .leaf("Revision", "ISO5436 - 2000")
        .leaf("FeatureType", if t.is_profile() { "PRF" } else { "SUR" })
        .open("Axes")
        .axis("CX", 'I', 'D', t.dx(), 0.0)
        .axis("CY", 'I', 'D', t.dy().unwrap_or(t.dx()), 0.0)
        .axis("CZ", 'A', z.letter(), increment, offset)
        .close("Axes")
        .close("Record1");
    x.open("Record2")
        .leaf("Date", &date)
        .leaf("Creator", "ke-friction")
        .open("Instrument")
        .leaf("Manufacturer", "ke-friction")
        .leaf("Model", "write_x3p")
        .leaf("Serial", "not available")
        .leaf("Version", version)
        .close("Instrument")
        .leaf("CalibrationDate", &date)
        .open("ProbingSystem")
        .leaf("Type", "Software")
        .leaf("Identification", "ke-friction write_x3p")
        .close("ProbingSystem")
        .leaf("Comment", format!("Written by ke-friction {version}."))
        .close("Record2");
    x.open("Record3")
        .open("MatrixDimension")
        .leaf("SizeX", t.nx())
        .leaf("SizeY", t.ny())
        .leaf("SizeZ", 1)
        .close("MatrixDimension")
        .open("DataLink")
        .leaf("PointDataLink", DATA_BIN)
        .leaf("MD5ChecksumPointData", md5_hex(data).to_uppercase());
    if let Some(valid) = valid {
        x.leaf("ValidPointsLink", VALID_BIN)
            .leaf("MD5ChecksumValidPoints", md5_hex(valid).to_uppercase());
    }
    x.close("DataLink").close("Record3");
    x.open("Record4")
        .leaf("ChecksumFile", "md5checksum.hex")
        .close("Record4");
    x.s.push_str("</p:ISO5436_2>\n");
    x.s
}

/// The current UTC time as ISO 8601 (`2024-05-01T12:00:00+00:00`).
fn now_iso8601() -> String {
    let secs = SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
    super::read::iso_date_in(i64::try_from(secs).unwrap_or(i64::MAX), "+00:00")
}
