//! The grammar of the fuzz target surface_instrument_b (see that file): the
//! input's structure, decoded by `arbitrary`, and the file bytes built
//! from it. Shared with the seed generator (fuzz/examples/seeds.rs), which
//! encodes chosen inputs in the same structure.
use arbitrary::Arbitrary;
use ke_friction::topography::{Channel, ReadOptions};

use crate::surface_check::OptionsSpec;

/// The most data bytes generated.
pub const MAX_DATA: usize = 1 << 16;

/// A grid size: small, or one of the edge cases.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Dim {
    /// 0 … 31.
    Small(u8),
    Edge(u8),
}

impl Dim {
    pub fn get(self) -> u64 {
        // 64 x (2^58 - 1) bytes of an earlier .nid channel put a later
        // one's data at 2^64 - 64 (issue 46: the offset must not wrap).
        const EDGE: [u64; 9] = [
            0,
            1,
            65535,
            65536,
            1 << 31,
            u32::MAX as u64,
            u64::MAX,
            64,
            (1 << 58) - 1,
        ];
        match self {
            Dim::Small(k) => u64::from(k % 32),
            Dim::Edge(k) => EDGE[k as usize % EDGE.len()],
        }
    }
}

/// A number as a header gives it: a sane one, a special one, or any bits.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Num {
    /// 10^(e/16).
    Exp(i8),
    Special(u8),
    Raw(f64),
}

impl Num {
    pub fn get(self) -> f64 {
        const S: [f64; 7] = [0.0, -1.0, f64::NAN, f64::INFINITY, -0.0, 1e308, 5e-324];
        match self {
            Num::Exp(e) => 10f64.powf(f64::from(e) / 16.0),
            Num::Special(k) => S[k as usize % S.len()],
            Num::Raw(v) => v,
        }
    }
}

/// The data's length: what the header makes, that ± a few bytes, or none.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Len {
    Exact,
    Delta(i8),
    Nothing,
}

/// The data: `want` bytes (or that ± a few), from the fuzzer's values.
pub fn data(out: &mut Vec<u8>, want: u64, len: Len, values: &[u8]) {
    let n = match len {
        Len::Exact => want,
        Len::Delta(d) => want.saturating_add_signed(i64::from(d)),
        Len::Nothing => 0,
    };
    let n = n.min(MAX_DATA as u64) as usize;
    if values.is_empty() {
        out.extend(std::iter::repeat_n(0x5a, n));
    } else {
        out.extend(values.iter().copied().cycle().take(n));
    }
}

#[derive(Debug, Arbitrary)]
pub struct MetroPro {
    /// 0, 1, 2: formats 1 to 3; else a wrong signature.
    pub version: u8,
    pub header_size_off: Option<i16>,
    pub ac: (u8, u8, u8),
    pub cn: (Dim, Dim),
    pub phase_res: i16,
    pub sign: i16,
    pub scale: [Num; 3],
    pub lateral: Num,
    pub serial2: u32,
    pub stamp: i32,
}

impl MetroPro {
    pub fn bytes(&self, len: Len, values: &[u8]) -> Vec<u8> {
        let magic = [0x6f, 0x70, 0x71, 0x72][self.version as usize % 4];
        let size: u32 = if self.version % 4 == 2 { 4096 } else { 834 };
        let size = (i64::from(size) + i64::from(self.header_size_off.unwrap_or(0))).max(0) as u32;
        let mut h = vec![0u8; 834];
        h[..4].copy_from_slice(&[0x88, 0x1b, 0x03, magic]);
        h[6..10].copy_from_slice(&size.to_be_bytes());
        let (aw, ah, buckets) = (
            u16::from(self.ac.0 % 8),
            u16::from(self.ac.1 % 8),
            u16::from(self.ac.2 % 3),
        );
        h[52..54].copy_from_slice(&aw.to_be_bytes());
        h[54..56].copy_from_slice(&ah.to_be_bytes());
        h[56..58].copy_from_slice(&buckets.to_be_bytes());
        let (w, hgt) = (self.cn.0.get() as u16, self.cn.1.get() as u16);
        h[68..70].copy_from_slice(&w.to_be_bytes());
        h[70..72].copy_from_slice(&hgt.to_be_bytes());
        h[76..80].copy_from_slice(&self.stamp.to_be_bytes());
        for (at, v) in [164, 168, 176].into_iter().zip(self.scale) {
            h[at..at + 4].copy_from_slice(&(v.get() as f32).to_be_bytes());
        }
        h[184..188].copy_from_slice(&(self.lateral.get() as f32).to_be_bytes());
        h[218..220].copy_from_slice(&(self.phase_res % 4).to_be_bytes());
        h[232..234].copy_from_slice(&self.sign.to_be_bytes());
        h[798..802].copy_from_slice(&self.serial2.to_le_bytes());
        h.resize(size.min(8192) as usize, 0);
        let want = 2 * u64::from(buckets) * u64::from(aw) * u64::from(ah) + 4 * u64::from(w) * u64::from(hgt);
        data(&mut h, want, len, values);
        h
    }
}

/// A Nanoscope image section.
#[derive(Debug, Arbitrary)]
pub struct Image {
    pub nx: Dim,
    pub ny: Dim,
    pub bytes_per_pixel: u8,
    /// Where the data are: right after the previous section's, or any.
    pub offset: Option<u32>,
    pub length_off: Option<i16>,
    /// `Scan Size` form: two numbers and a unit, one and a unit, garbage.
    pub size_form: u8,
    pub size: Num,
    pub unit: u8,
    /// The soft scale's name: `Sens. Zsens` (a length per volt), one of
    /// the fuzzer's, or none.
    pub quantity: Option<u8>,
    pub z_scale: Num,
    pub hard_unit: u8,
    pub name: u8,
}

#[derive(Debug, Arbitrary)]
pub struct Nanoscope {
    pub version: u8,
    /// Soft scales: `@Sens. Q{i}: V {value} {unit}/{per}`.
    pub soft: Vec<(Num, u8, u8)>,
    pub global: Option<(Dim, Dim)>,
    pub slow_axis: Option<(Num, u8)>,
    pub mode: u8,
    pub images: Vec<Image>,
    pub junk_line: Option<String>,
}

pub const UNITS: [&str; 10] = ["nm", "~m", "um", "µm", "m", "pm", "Å", "deg", "V", ""];
pub const VOLTS: [&str; 4] = ["V", "mV", "LSB", ""];

impl Nanoscope {
    pub fn bytes(&self, len: Len, values: &[u8]) -> Vec<u8> {
        let version = ["0x07200000", "0x09200000", "0x09010201", "0x05120000", "zz"][self.version as usize % 5];
        let mode = ["Image", "Force", "Force Volume"][self.mode as usize % 3];
        let mut t = format!("\\*File list\r\n\\Version: {version}\r\n\\Date: 09:57:48 AM Tue Jan 12 2016\r\n");
        t += "\\*Equipment list\r\n\\Microscope: Dimension V\r\n\\*Scanner list\r\n";
        t += "\\@Sens. Zsens: V 20.82646 nm/V\r\n";
        for (i, (value, unit, per)) in self.soft.iter().take(4).enumerate() {
            let unit = UNITS[*unit as usize % UNITS.len()];
            let per = VOLTS[*per as usize % VOLTS.len()];
            t += &format!("\\@Sens. Q{i}: V {} {unit}/{per}\r\n", value.get());
        }
        t += &format!("\\*Ciao scan list\r\n\\Operating mode: {mode}\r\n\\Scan Size: 500 nm\r\n");
        if let Some((gx, gy)) = self.global {
            t += &format!("\\Samps/line: {}\r\n\\Lines: {}\r\n", gx.get(), gy.get());
        }
        if let Some((size, unit)) = self.slow_axis {
            t += &format!(
                "\\Slow Axis Size: {} {}\r\n",
                size.get(),
                UNITS[unit as usize % UNITS.len()]
            );
        }
        if let Some(junk) = &self.junk_line {
            t += junk;
            t += "\r\n";
        }
        // The data follow the header, each channel's after the previous.
        let header = 4096u64;
        let mut next = header;
        let mut blocks = Vec::new();
        for (i, im) in self.images.iter().take(4).enumerate() {
            let (nx, ny) = (im.nx.get(), im.ny.get());
            let bpp = [2u64, 4, 1, 3][im.bytes_per_pixel as usize % 4];
            let want = nx.saturating_mul(ny).saturating_mul(bpp);
            let length = (want as i64)
                .saturating_add(i64::from(im.length_off.unwrap_or(0)))
                .max(0);
            let offset = im.offset.map_or(next, u64::from);
            let unit = UNITS[im.unit as usize % UNITS.len()];
            let size = im.size.get();
            let size = match im.size_form % 3 {
                0 => format!("{size} {size} {unit}"),
                1 => format!("{size} {unit}"),
                _ => unit.to_string(),
            };
            let quantity = im.quantity.map_or("[Sens. Zsens] ".to_string(), |q| match q % 6 {
                5 => String::new(),
                q => format!("[Sens. Q{q}] "),
            });
            let hard = VOLTS[im.hard_unit as usize % VOLTS.len()];
            let name = ["Height", "Phase", "ZSensor", "Height"][im.name as usize % 4];
            t += &format!(
                "\\*Ciao image list\r\n\\Data offset: {offset}\r\n\\Data length: {length}\r\n\\Bytes/pixel: {bpp}\r\n\\Samps/line: {nx}\r\n\\Number of lines: {ny}\r\n\\Scan Size: {size}\r\n\\@2:Image Data: S [{name}] \"{name} {i}\"\r\n\\@2:Z scale: V {quantity}(0.005 {hard}/LSB) {} {hard}\r\n",
                im.z_scale.get()
            );
            blocks.push(want.min(MAX_DATA as u64));
            next = next.saturating_add(want);
        }
        t += "\\*File list end\r\n\x1a";
        let mut out = t.into_bytes();
        out.resize(out.len().max(header as usize), 0);
        data(&mut out, blocks.iter().sum(), len, values);
        out
    }
}

#[derive(Debug, Arbitrary)]
pub struct NidChannel {
    pub points: Dim,
    pub lines: Dim,
    pub bits: u8,
    pub signed: bool,
    pub intel: bool,
    pub binary: bool,
    pub unit: u8,
    pub lateral_unit: Option<u8>,
    pub range: Num,
    pub min: Option<Num>,
    pub size: Num,
}

#[derive(Debug, Arbitrary)]
pub struct Nid {
    /// Channels of group 0, each listed or not.
    pub channels: Vec<(bool, NidChannel)>,
    pub count_off: i8,
    pub groups: u8,
    pub crlf: bool,
    pub junk_line: Option<String>,
}

impl Nid {
    pub fn bytes(&self, len: Len, values: &[u8]) -> Vec<u8> {
        let eol = if self.crlf { "\r\n" } else { "\n" };
        let channels: Vec<&(bool, NidChannel)> = self.channels.iter().take(6).collect();
        let count = (channels.len() as i64 + i64::from(self.count_off % 3)).max(0);
        let mut t = format!(
            "[DataSet]{eol}GroupCount={}{eol}Gr0-Count={count}{eol}",
            self.groups % 3
        );
        for (j, (listed, _)) in channels.iter().enumerate() {
            if *listed {
                t += &format!("Gr0-Ch{j}=DataSet-0:{j}{eol}");
            }
        }
        t += &format!("[DataSet-Info]{eol}Date=03-11-2022{eol}Time=11:46:25{eol}Head type=DriveAFM{eol}");
        if let Some(junk) = &self.junk_line {
            t += junk;
            t += eol;
        }
        let mut want = 0u64;
        for (j, (_, c)) in channels.iter().enumerate() {
            let bits = [8u64, 16, 32, 64, 12][c.bits as usize % 5];
            let unit = ["m", "nm", "um", "N", "V", "A", "deg"][c.unit as usize % 7];
            t += &format!(
                "[DataSet-0:{j}]{eol}Points={}{eol}Lines={}{eol}Frame=Scan forward{eol}Dim0Range={}{eol}Dim1Range={}{eol}Dim2Name=Z{j}{eol}Dim2Unit={unit}{eol}Dim2Range={}{eol}SaveMode={}{eol}SaveBits={bits}{eol}SaveSign={}{eol}SaveOrder={}{eol}",
                c.points.get(),
                c.lines.get(),
                c.size.get(),
                c.size.get(),
                c.range.get(),
                if c.binary { "Binary" } else { "Text" },
                if c.signed { "Signed" } else { "Unsigned" },
                if c.intel { "Intel" } else { "Motorola" },
            );
            if let Some(u) = c.lateral_unit {
                let u = ["m", "um", "nm", "V"][u as usize % 4];
                t += &format!("Dim0Unit={u}{eol}Dim1Unit={u}{eol}");
            }
            if let Some(min) = c.min {
                t += &format!("Dim2Min={}{eol}", min.get());
            }
            want = want.saturating_add(c.points.get().saturating_mul(c.lines.get()).saturating_mul(bits / 8));
        }
        t += "#!";
        let mut out = t.into_bytes();
        data(&mut out, want, len, values);
        out
    }
}

#[derive(Debug, Arbitrary)]
pub enum File {
    MetroPro(MetroPro),
    Nanoscope(Nanoscope),
    Nid(Nid),
}

#[derive(Debug, Arbitrary)]
pub struct Input {
    pub options: OptionsSpec,
    /// The file's intervals win: the options' are dropped (else they must
    /// agree with the file's).
    pub no_intervals: bool,
    pub channel: Option<Result<u8, u8>>,
    pub file: File,
    pub len: Len,
    pub values: Vec<u8>,
    pub flips: Vec<(u16, u8)>,
    /// Read under another file name (the format then by the signature).
    pub other_name: bool,
    /// Cut short after this many bytes (a truncated header or data).
    pub cut: Option<u16>,
}

/// The file `input` describes: its bytes, the name it is read under and
/// the read options.
pub fn file(input: &Input) -> (Vec<u8>, &'static str, ReadOptions) {
    let mut options: ReadOptions = input.options.options(None);
    if input.no_intervals {
        options.dx = None;
        options.dy = None;
    }
    options.channel = input.channel.map(|c| match c {
        Ok(i) => Channel::Index(usize::from(i % 10)),
        Err(k) => Channel::Name(["Height", "Phase", "Scan forward (Z1)", "zsensor"][k as usize % 4].to_string()),
    });
    let (mut bytes, name) = match &input.file {
        File::MetroPro(f) => (f.bytes(input.len, &input.values), "surface.dat"),
        File::Nanoscope(f) => (f.bytes(input.len, &input.values), "surface.di"),
        File::Nid(f) => (f.bytes(input.len, &input.values), "surface.nid"),
    };
    if !bytes.is_empty() {
        for &(at, value) in input.flips.iter().take(8) {
            let n = bytes.len();
            bytes[at as usize % n] = value;
        }
    }
    if let Some(cut) = input.cut {
        bytes.truncate(usize::from(cut));
    }
    let name = if input.other_name { "surface.bin" } else { name };
    (bytes, name, options)
}
