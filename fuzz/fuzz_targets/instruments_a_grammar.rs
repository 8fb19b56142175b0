//! The grammar of the fuzz target surface_instruments_a (see that file): the
//! input's structure, decoded by `arbitrary`, and the file bytes built
//! from it. Shared with the seed generator (fuzz/examples/seeds.rs), which
//! encodes chosen inputs in the same structure.
use arbitrary::Arbitrary;
use ke_friction::topography::{Channel, ReadOptions};

use crate::surface_check::OptionsSpec;

/// The most values generated for the data.
pub const MAX_VALUES: usize = 4096;

/// A size: small, or one of the edges.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Dim {
    /// 1 … 24.
    Small(u8),
    Edge(u8),
}

impl Dim {
    pub fn get(self) -> i64 {
        const EDGES: [i64; 8] = [0, -1, 1, 65535, 65536, 1 << 31, (1 << 32) - 1, 1 << 20];
        match self {
            Dim::Small(k) => 1 + i64::from(k % 24),
            Dim::Edge(k) => EDGES[usize::from(k) % EDGES.len()],
        }
    }
}

/// A count or offset as written: what the content makes, that plus a
/// delta, or any value.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Declared {
    Right,
    Delta(i8),
    Raw(u32),
}

impl Declared {
    pub fn get(self, right: i64) -> i64 {
        match self {
            Declared::Right => right,
            Declared::Delta(d) => right + i64::from(d),
            Declared::Raw(v) => i64::from(v),
        }
    }
}

/// A value of the data.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Value {
    Small(i16),
    Special(u8),
    Raw(f64),
}

impl Value {
    pub fn get(self) -> f64 {
        const S: [f64; 10] = [
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            1_000_001.0,
            3e15,
            1e38,
            32766.0,
            -2.0,
            f64::MAX,
            0.0,
        ];
        match self {
            Value::Small(k) => f64::from(k),
            Value::Special(k) => S[usize::from(k) % S.len()],
            Value::Raw(v) => v,
        }
    }
}

/// A text field: one the reader knows, or any.
#[derive(Debug, Clone, Arbitrary)]
pub enum Text {
    Known(u8),
    Other(String),
}

impl Text {
    pub fn get(&self, known: &[&str]) -> Vec<u8> {
        match self {
            Text::Known(k) => known[usize::from(*k) % known.len()].as_bytes().to_vec(),
            Text::Other(s) => s.as_bytes().to_vec(),
        }
    }
}

pub const UNITS: [&str; 10] = ["m", "mm", "\u{b5}m", "um", "nm", "\u{e6}m", "A", "", "V", "furlong"];

#[derive(Debug, Arbitrary)]
pub struct Sur {
    pub nx: Dim,
    pub ny: Dim,
    pub points: Declared,
    /// 16, 32, or another.
    pub bits: u8,
    pub special_points: bool,
    pub zmin: i16,
    pub spacing: (Value, Value),
    pub scale: Value,
    pub units: [Text; 3],
    pub inversion: u8,
    pub zones: (u8, u8),
    pub values: Vec<i32>,
    pub len: Declared,
}

#[derive(Debug, Arbitrary)]
pub struct PluLayer {
    pub nx: Dim,
    pub ny: Dim,
    pub values: Vec<Value>,
    pub len: Declared,
}

#[derive(Debug, Arbitrary)]
pub struct Plu {
    /// 3 (a topography) or another.
    pub kind: u8,
    pub pixel: (Value, Value),
    pub layers: Declared,
    pub version: u8,
    pub hardware: u8,
    pub images: u8,
    pub data: Vec<PluLayer>,
}

#[derive(Debug, Arbitrary)]
pub enum OpdContent {
    Raster {
        nx: Dim,
        ny: Dim,
        /// 1, 2, 4 or another.
        item: u8,
        values: Vec<Value>,
    },
    Scalar(Value),
    Text(String),
}

#[derive(Debug, Arbitrary)]
pub struct OpdBlock {
    pub name: Text,
    /// 3, 5, 6, 7, 8, 12 or any.
    pub kind: u8,
    pub length: Declared,
    pub content: OpdContent,
}

#[derive(Debug, Arbitrary)]
pub struct Opd {
    pub directory: Declared,
    pub blocks: Vec<OpdBlock>,
}

#[derive(Debug, Arbitrary)]
pub struct Al3d {
    pub nx: Dim,
    pub ny: Dim,
    pub pixel: (Value, Value),
    pub invalid: Option<Value>,
    pub offset: Declared,
    pub count: Declared,
    pub extra: Vec<(String, String)>,
    pub bad_crlf: Option<u8>,
    pub values: Vec<Value>,
    pub len: Declared,
}

#[derive(Debug, Arbitrary)]
pub enum File {
    Sur(Sur),
    Plu(Plu),
    Opd(Opd),
    Al3d(Al3d),
}

#[derive(Debug, Arbitrary)]
pub enum ChannelSpec {
    None,
    Index(u8),
    Name(Text),
}

#[derive(Debug, Arbitrary)]
pub struct Input {
    pub options: OptionsSpec,
    pub channel: ChannelSpec,
    pub file: File,
    /// (position, xor mask) byte flips.
    pub flips: Vec<(u16, u8)>,
    pub cut: Option<u16>,
}

/// `text` in a field of `n` bytes (cut, NUL-padded).
pub fn field(out: &mut Vec<u8>, text: &[u8], n: usize) {
    let k = text.len().min(n);
    out.extend(&text[..k]);
    out.extend(std::iter::repeat_n(0u8, n - k));
}

/// Values cycled to `n` items (`fill` when there are none), at most
/// [`MAX_VALUES`].
pub fn cycled<T: Copy>(values: &[T], n: i64, fill: T) -> impl Iterator<Item = T> + '_ {
    let n = n.clamp(0, MAX_VALUES as i64) as usize;
    let mut i = 0;
    std::iter::from_fn(move || {
        let v = if values.is_empty() {
            fill
        } else {
            values[i % values.len()]
        };
        i += 1;
        Some(v)
    })
    .take(n)
}

pub fn sur(s: &Sur) -> Vec<u8> {
    let (nx, ny) = (s.nx.get(), s.ny.get());
    let bits: u16 = match s.bits % 4 {
        0 | 1 => 16,
        2 => 32,
        _ => u16::from(s.bits),
    };
    let mut h = Vec::with_capacity(512);
    field(&mut h, b"DIGITAL SURF", 12);
    for v in [0u16, 1, 1, 2] {
        h.extend(v.to_le_bytes());
    }
    field(&mut h, b"", 30);
    field(&mut h, b"fuzz", 30);
    h.extend([0u8; 6]);
    h.extend(u16::from(s.special_points).to_le_bytes());
    h.extend([0u8; 10]);
    h.extend(bits.to_le_bytes());
    h.extend(i32::from(s.zmin).to_le_bytes());
    h.extend(i32::MAX.to_le_bytes());
    h.extend((nx as i32).to_le_bytes());
    h.extend((ny as i32).to_le_bytes());
    h.extend((s.points.get(nx.saturating_mul(ny)) as u32).to_le_bytes());
    h.extend((s.spacing.0.get() as f32).to_le_bytes());
    h.extend((s.spacing.1.get() as f32).to_le_bytes());
    h.extend((s.scale.get() as f32).to_le_bytes());
    h.extend([0u8; 48]);
    for unit in &s.units {
        let unit: Vec<u8> = match unit {
            // ISO 8859-1, as the files write them.
            Text::Known(k) => UNITS[usize::from(*k) % UNITS.len()]
                .chars()
                .map(|c| c as u32 as u8)
                .collect(),
            other => other.get(&UNITS),
        };
        field(&mut h, &unit, 16);
    }
    h.extend([0u8; 60]);
    h.extend(0u16.to_le_bytes());
    h.extend(u16::from(s.inversion % 5).to_le_bytes());
    h.extend([0u8; 14]);
    for v in [1u16, 2, 3, 4, 5, 2020] {
        h.extend(v.to_le_bytes());
    }
    h.extend([0u8; 16]);
    let zones = (u16::from(s.zones.0 % 8), u16::from(s.zones.1 % 8));
    h.extend(zones.0.to_le_bytes());
    h.extend(zones.1.to_le_bytes());
    h.resize(512 + usize::from(zones.0 + zones.1), 0);
    let n = s.len.get(nx.saturating_mul(ny));
    for v in cycled(&s.values, n, i32::from(s.zmin) - 2) {
        if bits == 32 {
            h.extend(v.to_le_bytes());
        } else {
            h.extend((v as i16).to_le_bytes());
        }
    }
    h
}

pub fn plu(p: &Plu) -> Vec<u8> {
    let mut h = Vec::with_capacity(500);
    field(&mut h, b"Fri Mar 10 16:35:59 2023", 128);
    h.extend([0u8; 4]);
    field(&mut h, b"(None)", 256);
    h.extend([0u8; 16]);
    h.extend((p.pixel.0.get() as f32).to_le_bytes());
    h.extend((p.pixel.1.get() as f32).to_le_bytes());
    h.extend([0u8; 16]);
    let kind: u32 = if p.kind % 4 == 0 { u32::from(p.kind) } else { 3 };
    h.extend(kind.to_le_bytes());
    h.extend([0u8; 12]);
    h.extend(3u32.to_le_bytes());
    h.extend([0u8; 40]);
    let layers = p.layers.get(p.data.len().min(4) as i64) as u8;
    let images = p.images % 3;
    h.extend([0, layers, p.version, p.hardware, images, 0, 0, 0]);
    h.extend(1u32.to_le_bytes());
    for layer in p.data.iter().take(4) {
        let (nx, ny) = (layer.nx.get(), layer.ny.get());
        h.extend((ny as u32).to_le_bytes());
        h.extend((nx as u32).to_le_bytes());
        let n = layer.len.get(nx.saturating_mul(ny));
        for v in cycled(&layer.values, n, Value::Special(3)) {
            h.extend((v.get() as f32).to_le_bytes());
        }
        h.extend([0u8; 8]);
        let rgb = 3i64
            .saturating_mul(n)
            .saturating_mul(i64::from(images))
            .clamp(0, 3 * MAX_VALUES as i64) as usize;
        h.extend(std::iter::repeat_n(0x80u8, rgb));
    }
    h
}

pub fn opd(o: &Opd) -> Vec<u8> {
    pub const NAMES: [&str; 10] = [
        "Wavelength",
        "Mult",
        "Aspect",
        "Pixel_size",
        "Date",
        "Time",
        "RAW DATA",
        "Raw",
        "OPD",
        "Image",
    ];
    pub const KINDS: [i16; 6] = [3, 5, 6, 7, 8, 12];
    let blocks: Vec<(Vec<u8>, i16, Vec<u8>, i64)> = o
        .blocks
        .iter()
        .take(12)
        .map(|b| {
            let kind = match b.kind % 8 {
                k @ 0..=5 => KINDS[usize::from(k)],
                _ => i16::from(b.kind),
            };
            let content = match &b.content {
                OpdContent::Raster { nx, ny, item, values } => {
                    let (nx, ny) = (nx.get(), ny.get());
                    let item = match item % 4 {
                        0 => 1u16,
                        1 => 2,
                        2 => 4,
                        _ => u16::from(*item),
                    };
                    let mut c = Vec::new();
                    for v in [nx as u16, ny as u16, item] {
                        c.extend(v.to_le_bytes());
                    }
                    for v in cycled(values, nx.saturating_mul(ny), Value::Small(1)) {
                        match item {
                            1 => c.push(v.get() as u8),
                            2 => c.extend((v.get() as i16).to_le_bytes()),
                            _ => c.extend((v.get() as f32).to_le_bytes()),
                        }
                    }
                    c
                }
                OpdContent::Scalar(v) => match kind {
                    6 => (v.get() as i16).to_le_bytes().to_vec(),
                    8 => v.get().to_le_bytes().to_vec(),
                    12 => (v.get() as i32).to_le_bytes().to_vec(),
                    _ => (v.get() as f32).to_le_bytes().to_vec(),
                },
                OpdContent::Text(t) => t.as_bytes().to_vec(),
            };
            let length = b.length.get(content.len() as i64);
            (b.name.get(&NAMES), kind, content, length)
        })
        .collect();
    let mut f = vec![0u8, 0];
    let entry = |f: &mut Vec<u8>, name: &[u8], kind: i16, length: i64| {
        field(f, name, 16);
        f.extend(kind.to_le_bytes());
        f.extend((length as i32).to_le_bytes());
        f.extend(0u16.to_le_bytes());
    };
    entry(&mut f, b"Directory", 3, o.directory.get(24 * (blocks.len() as i64 + 1)));
    for (name, kind, _, length) in &blocks {
        entry(&mut f, name, *kind, *length);
    }
    for (_, _, content, length) in &blocks {
        // The content, padded or cut to its declared length.
        let n = (*length).clamp(0, 1 << 16) as usize;
        f.extend(content.iter().copied().chain(std::iter::repeat(0)).take(n));
    }
    f
}

pub fn al3d(a: &Al3d) -> Vec<u8> {
    let (nx, ny) = (a.nx.get(), a.ny.get());
    let mut tags: Vec<(String, String)> = vec![
        ("Cols".into(), nx.to_string()),
        ("Rows".into(), ny.to_string()),
        ("PixelSizeXMeter".into(), format!("{:e}", a.pixel.0.get())),
        ("PixelSizeYMeter".into(), format!("{:e}", a.pixel.1.get())),
        ("CreatingApplication".into(), "fuzz".into()),
    ];
    if let Some(v) = a.invalid {
        tags.push(("InvalidPixelValue".into(), format!("{:e}", v.get())));
    }
    tags.extend(a.extra.iter().take(4).cloned());
    let header = 17 + 52 * (tags.len() + 3) + 256;
    let offset = a.offset.get(header as i64);
    tags.push(("DepthImageOffset".into(), offset.to_string()));
    let mut f = b"AliconaImaging\x00\r\n".to_vec();
    let tag = |f: &mut Vec<u8>, k: &str, v: &str| {
        field(f, k.as_bytes(), 20);
        field(f, v.as_bytes(), 30);
        f.extend(b"\r\n");
    };
    tag(&mut f, "Version", "1");
    tag(&mut f, "TagCount", &a.count.get(tags.len() as i64).to_string());
    for (k, v) in &tags {
        tag(&mut f, k, v);
    }
    if let Some(at) = a.bad_crlf {
        let at = 17 + 52 * usize::from(at % 4) + 50;
        if let Some(b) = f.get_mut(at) {
            *b = b'X';
        }
    }
    f.extend([0u8; 256]);
    if let Ok(offset) = usize::try_from(offset) {
        if offset <= f.len() + 64 {
            f.resize(offset, 0);
        }
    }
    let stride = nx + nx % 2;
    let n = a.len.get(stride.saturating_mul(ny));
    for v in cycled(&a.values, n, Value::Small(0)) {
        f.extend((v.get() as f32).to_le_bytes());
    }
    f
}

/// The file `input` describes: its bytes, the name it is read under and
/// the read options.
pub fn file(input: &Input) -> (Vec<u8>, &'static str, ReadOptions) {
    let mut options = input.options.options(None);
    options.channel = match &input.channel {
        ChannelSpec::None => None,
        ChannelSpec::Index(i) => Some(Channel::Index(usize::from(*i % 4))),
        ChannelSpec::Name(t) => Some(Channel::Name(
            String::from_utf8_lossy(&t.get(&["Raw", "raw", "layer1", "OPD", "Image"])).into_owned(),
        )),
    };
    let (mut bytes, name) = match &input.file {
        File::Sur(s) => (sur(s), "surface.sur"),
        File::Plu(p) => (plu(p), "surface.plu"),
        File::Opd(o) => (opd(o), "surface.opd"),
        File::Al3d(a) => (al3d(a), "surface.al3d"),
    };
    if !bytes.is_empty() {
        for &(at, mask) in input.flips.iter().take(4) {
            let at = usize::from(at) % bytes.len();
            bytes[at] ^= mask;
        }
    }
    if let Some(cut) = input.cut {
        bytes.truncate(usize::from(cut));
    }
    (bytes, name, options)
}
