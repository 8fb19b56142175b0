//! Writes the seeds of the grammar-based instrument targets
//! (surface_instruments_a, surface_instrument_b) for the hostile cases of
//! issue 46, in the targets' own encoding: each case is an `Input` of the
//! target's grammar (fuzz_targets/*_grammar.rs), encoded as the bytes that
//! `arbitrary` decodes back into it. The encoding is checked by decoding
//! it again (the same `Debug` text), and the file each seed makes is read
//! here and must give the case's answer (an error naming the fault, or a
//! surface with the marker masked).
//!
//! `cargo run --example seeds` writes fuzz/seeds/TARGET/issue46-*;
//! `cargo run --example seeds -- --check` fails when a committed seed
//! differs from what this program makes (the grammar changed).
//!
//! The encoder is our own: `arbitrary` decodes only, and no crate inverts
//! its derive. It follows arbitrary 1.5's decoding: integers little-endian,
//! a bool the low bit of a byte, an `Option`/`Result` a bool first, a
//! `Vec` a "one more" bool before each element and a false one after the
//! last, an enum's variant `i` of `n` a `u32` with `(v * n) >> 32 == i`,
//! and a string's length taken from the end of the data, in 1, 2 or 4
//! bytes by how much data is left.
#![allow(dead_code)]

#[path = "../fuzz_targets/surface_check.rs"]
mod surface_check;

#[path = "../fuzz_targets/instruments_a_grammar.rs"]
mod a;

#[path = "../fuzz_targets/instrument_b_grammar.rs"]
mod b;

use arbitrary::{Arbitrary, Unstructured};
use ke_friction::topography::{read_bytes, Topography};
use surface_check::{Interval, OptionsSpec, Unit};

/// The bytes being written: the front, read in order, and the strings'
/// lengths, read from the end.
#[derive(Default)]
struct Out {
    front: Vec<u8>,
    /// For each string: the front's length where its length is read, and
    /// the length.
    strings: Vec<(usize, usize)>,
}

impl Out {
    fn bytes(&mut self, b: &[u8]) {
        self.front.extend_from_slice(b);
    }

    fn variant(&mut self, i: u64, n: u64) {
        let v = ((i << 32).div_ceil(n)) as u32;
        assert_eq!((u64::from(v) * n) >> 32, i);
        v.enc(self);
    }

    fn string(&mut self, s: &str) {
        self.strings.push((self.front.len(), s.len()));
        self.bytes(s.as_bytes());
    }

    /// The whole input: the front, then the strings' length bytes, the
    /// first string's last (`Unstructured::arbitrary_byte_size` takes
    /// them from the end of what is left).
    fn finish(self) -> Vec<u8> {
        let mut tails: Vec<Vec<u8>> = Vec::new();
        let mut after = 0; // tail bytes of the later strings
        for &(at, len) in self.strings.iter().rev() {
            // What is left when this length is read.
            let left = self.front.len() - at + after;
            let (w, tail) = if left < 256 {
                (1, length_bytes(len, left, 1))
            } else if left < 65536 {
                (2, length_bytes(len, left, 2))
            } else {
                (4, length_bytes(len, left, 4))
            };
            after += w;
            tails.push(tail);
        }
        let mut out = self.front;
        // The last string's tail first: the first string's is at the end.
        for t in tails {
            out.extend(t);
        }
        out
    }
}

/// The `w` bytes that make `int_in_range(0..=max, bytes)` give `len`.
fn length_bytes(len: usize, max: usize, w: usize) -> Vec<u8> {
    assert!(len <= max);
    let mut used = 0;
    while used < w && (max >> (8 * used)) > 0 {
        used += 1;
    }
    let mut out = vec![0u8; w];
    for (k, b) in out.iter_mut().take(used).enumerate() {
        *b = (len >> (8 * (used - 1 - k))) as u8;
    }
    out
}

/// A value written as `arbitrary` reads it.
trait Enc {
    fn enc(&self, o: &mut Out);
}

macro_rules! int {
    ($($t:ty),*) => {$(
        impl Enc for $t {
            fn enc(&self, o: &mut Out) {
                o.bytes(&self.to_le_bytes());
            }
        }
    )*};
}
int!(u8, u16, u32, u64, i8, i16, i32, i64, f64);

impl Enc for bool {
    fn enc(&self, o: &mut Out) {
        o.bytes(&[u8::from(*self)]);
    }
}

impl Enc for String {
    fn enc(&self, o: &mut Out) {
        o.string(self);
    }
}

impl<T: Enc> Enc for Option<T> {
    fn enc(&self, o: &mut Out) {
        self.is_some().enc(o);
        if let Some(v) = self {
            v.enc(o);
        }
    }
}

impl<T: Enc, E: Enc> Enc for Result<T, E> {
    fn enc(&self, o: &mut Out) {
        self.is_ok().enc(o);
        match self {
            Ok(v) => v.enc(o),
            Err(e) => e.enc(o),
        }
    }
}

impl<T: Enc> Enc for Vec<T> {
    fn enc(&self, o: &mut Out) {
        for v in self {
            true.enc(o);
            v.enc(o);
        }
        false.enc(o);
    }
}

impl<T: Enc, const N: usize> Enc for [T; N] {
    fn enc(&self, o: &mut Out) {
        for v in self {
            v.enc(o);
        }
    }
}

impl<A: Enc, B: Enc> Enc for (A, B) {
    fn enc(&self, o: &mut Out) {
        self.0.enc(o);
        self.1.enc(o);
    }
}

impl<A: Enc, B: Enc, C: Enc> Enc for (A, B, C) {
    fn enc(&self, o: &mut Out) {
        self.0.enc(o);
        self.1.enc(o);
        self.2.enc(o);
    }
}

/// Struct fields in order.
macro_rules! fields {
    ($t:ty { $($f:ident),* }) => {
        impl Enc for $t {
            fn enc(&self, o: &mut Out) {
                $(self.$f.enc(o);)*
            }
        }
    };
}

/// An enum: its variant's index among all, then the variant's one field
/// (if any).
macro_rules! variants {
    ($t:ident { $($v:ident $(($f:ident))?),+ }) => {
        impl Enc for $t {
            #[allow(unused_assignments)]
            fn enc(&self, o: &mut Out) {
                let n = [$(stringify!($v)),+].len() as u64;
                let mut i = 0;
                $(
                    if let $t::$v $(($f))? = self {
                        o.variant(i, n);
                        $($f.enc(o);)?
                        return;
                    }
                    i += 1;
                )+
            }
        }
    };
}

variants!(Interval { None, Exp(e), Raw(v) });

variants!(Unit { One, Exp(e), Raw(v) });

impl Enc for OptionsSpec {
    fn enc(&self, o: &mut Out) {
        match self {
            OptionsSpec::Fixed => o.variant(0, 2),
            OptionsSpec::Chosen {
                dx,
                dy,
                z_unit,
                xy_unit,
                max_points_log2,
                max_bytes_log2,
            } => {
                o.variant(1, 2);
                dx.enc(o);
                dy.enc(o);
                z_unit.enc(o);
                xy_unit.enc(o);
                max_points_log2.enc(o);
                max_bytes_log2.enc(o);
            }
        }
    }
}

mod enc_a {
    use super::a::*;
    use super::{Enc, Out};

    variants!(Dim { Small(k), Edge(k) });

    variants!(Declared { Right, Delta(d), Raw(v) });

    variants!(Value { Small(k), Special(k), Raw(v) });

    variants!(Text { Known(k), Other(s) });

    fields!(Sur {
        nx,
        ny,
        points,
        bits,
        special_points,
        zmin,
        spacing,
        scale,
        units,
        inversion,
        zones,
        values,
        len
    });
    fields!(PluLayer { nx, ny, values, len });
    fields!(Plu {
        kind,
        pixel,
        layers,
        version,
        hardware,
        images,
        data
    });

    impl Enc for OpdContent {
        fn enc(&self, o: &mut Out) {
            match self {
                OpdContent::Raster { nx, ny, item, values } => {
                    o.variant(0, 3);
                    nx.enc(o);
                    ny.enc(o);
                    item.enc(o);
                    values.enc(o);
                }
                OpdContent::Scalar(v) => {
                    o.variant(1, 3);
                    v.enc(o)
                }
                OpdContent::Text(s) => {
                    o.variant(2, 3);
                    s.enc(o)
                }
            }
        }
    }

    fields!(OpdBlock {
        name,
        kind,
        length,
        content
    });
    fields!(Opd { directory, blocks });
    fields!(Al3d {
        nx,
        ny,
        pixel,
        invalid,
        offset,
        count,
        extra,
        bad_crlf,
        values,
        len
    });

    variants!(File { Sur(f), Plu(f), Opd(f), Al3d(f) });

    variants!(ChannelSpec { None, Index(i), Name(t) });

    fields!(Input {
        options,
        channel,
        file,
        flips,
        cut
    });
}

mod enc_b {
    use super::b::*;
    use super::{Enc, Out};

    variants!(Dim { Small(k), Edge(k) });

    variants!(Num { Exp(e), Special(k), Raw(v) });

    variants!(Len { Exact, Delta(d), Nothing });

    fields!(MetroPro {
        version,
        header_size_off,
        ac,
        cn,
        phase_res,
        sign,
        scale,
        lateral,
        serial2,
        stamp
    });
    fields!(Image {
        nx,
        ny,
        bytes_per_pixel,
        offset,
        length_off,
        size_form,
        size,
        unit,
        quantity,
        z_scale,
        hard_unit,
        name
    });
    fields!(Nanoscope {
        version,
        soft,
        global,
        slow_axis,
        mode,
        images,
        junk_line
    });
    fields!(NidChannel {
        points,
        lines,
        bits,
        signed,
        intel,
        binary,
        unit,
        lateral_unit,
        range,
        min,
        size
    });
    fields!(Nid {
        channels,
        count_off,
        groups,
        crlf,
        junk_line
    });

    variants!(File { MetroPro(f), Nanoscope(f), Nid(f) });

    fields!(Input {
        options,
        no_intervals,
        channel,
        file,
        len,
        values,
        flips,
        other_name,
        cut
    });
}

/// What a seed's file must read as.
enum Expect {
    /// Refused, the message holding each of these and no control character.
    Refused(&'static [&'static str]),
    /// Read, with at least this many missing points.
    Read { missing: usize },
}

/// A seed: its name, the target, its input bytes, and the file those
/// make (bytes, name, options) read by the target.
struct Seed {
    name: &'static str,
    target: &'static str,
    input: Vec<u8>,
    expect: Expect,
}

/// `input` encoded, and what it decodes into (checked to be `input`).
fn encode<T: Enc + for<'a> Arbitrary<'a> + std::fmt::Debug>(input: &T) -> (Vec<u8>, T) {
    let mut o = Out::default();
    input.enc(&mut o);
    let bytes = o.finish();
    let back = T::arbitrary_take_rest(Unstructured::new(&bytes)).expect("decodes");
    assert_eq!(
        format!("{back:?}"),
        format!("{input:?}"),
        "the encoding does not decode into the input"
    );
    (bytes, back)
}

fn check(seed: &Seed, read: Result<Topography, ke_friction::topography::ReadError>) {
    match (&seed.expect, read) {
        (Expect::Refused(words), Err(e)) => {
            let m = e.to_string();
            assert!(
                !m.chars().any(char::is_control),
                "{}: a control character in {m:?}",
                seed.name
            );
            for w in *words {
                assert!(m.contains(w), "{}: {m:?} does not say {w:?}", seed.name);
            }
            println!("{}: refused: {m}", seed.name);
        }
        (Expect::Read { missing }, Ok(t)) => {
            let n = t.heights().iter().filter(|h| h.is_nan()).count();
            assert!(n >= *missing, "{}: {n} missing points, want {missing}", seed.name);
            assert!(
                t.heights().iter().all(|h| h.is_nan() || h.abs() < 1e20),
                "{}: a huge height",
                seed.name
            );
            println!("{}: read {} x {}, {n} missing", seed.name, t.nx(), t.ny());
        }
        (_, Ok(t)) => panic!("{}: read {} x {}, must be refused", seed.name, t.nx(), t.ny()),
        (_, Err(e)) => panic!("{}: refused ({e}), must read", seed.name),
    }
}

fn seed_a(name: &'static str, input: a::Input, expect: Expect) -> Seed {
    let (bytes, back) = encode(&input);
    let (file, file_name, options) = a::file(&back);
    let seed = Seed {
        name,
        target: "surface_instruments_a",
        input: bytes,
        expect,
    };
    check(&seed, read_bytes(&file, file_name, &options));
    seed
}

fn seed_b(name: &'static str, input: b::Input, expect: Expect) -> Seed {
    let (bytes, back) = encode(&input);
    let (file, file_name, options) = b::file(&back);
    let seed = Seed {
        name,
        target: "surface_instrument_b",
        input: bytes,
        expect,
    };
    check(&seed, read_bytes(&file, file_name, &options));
    seed
}

/// Where `what` first occurs in the file `input` makes (for a flip or a
/// cut there).
fn position_b(input: &b::Input, what: &[u8]) -> u16 {
    let (file, _, _) = b::file(input);
    let at = file.windows(what.len()).position(|w| w == what).expect("in the file");
    u16::try_from(at).expect("within the first 64 KiB")
}

fn seeds_a() -> Vec<Seed> {
    use a::*;
    let raster = |values: Vec<Value>| OpdBlock {
        name: Text::Known(6), // RAW DATA
        kind: 0,              // 3: a raster
        length: Declared::Right,
        content: OpdContent::Raster {
            nx: Dim::Small(7),
            ny: Dim::Small(7),
            item: 2, // 4-byte floats
            values,
        },
    };
    let scalar = |name: Text, v: Value| OpdBlock {
        name,
        kind: 3, // 7: a float
        length: Declared::Right,
        content: OpdContent::Scalar(v),
    };
    let input = |file: File| Input {
        options: OptionsSpec::Fixed,
        channel: ChannelSpec::None,
        file,
        flips: vec![],
        cut: None,
    };
    let values: Vec<Value> = (0..13).map(|k| Value::Small(k * 37 % 101)).collect();
    // An OPD whose directory holds many entries of float blocks before the
    // raster (issue 46: 2 million; the grammar takes 12 blocks).
    let mut blocks = vec![
        scalar(Text::Known(0), Value::Small(600)),
        scalar(Text::Known(3), Value::Raw(0.001)),
    ];
    blocks.extend((0..9).map(|k| scalar(Text::Other(format!("Block{k}")), Value::Raw(1.5))));
    blocks.push(raster(values.clone()));
    let directory = input(File::Opd(Opd {
        directory: Declared::Right,
        blocks,
    }));
    // The OPD missing-point marker: f32 1e38 (9.99999968e37).
    let mut marked = values.clone();
    marked[5] = Value::Special(5);
    let marker = input(File::Opd(Opd {
        directory: Declared::Right,
        blocks: vec![
            scalar(Text::Known(0), Value::Small(600)),
            scalar(Text::Known(3), Value::Raw(0.001)),
            raster(marked),
        ],
    }));
    // An AL3D with extra tags (issue 46: 2 million; the grammar takes 4),
    // counted right, and one whose TagCount says 2,000,006.
    let al3d = |count: Declared| {
        input(File::Al3d(Al3d {
            nx: Dim::Small(7),
            ny: Dim::Small(7),
            pixel: (Value::Raw(1e-6), Value::Raw(1e-6)),
            invalid: Some(Value::Special(0)),
            offset: Declared::Right,
            count,
            extra: (0..4).map(|k| (format!("Tag{k}"), k.to_string())).collect(),
            bad_crlf: None,
            values: values.clone(),
            len: Declared::Right,
        }))
    };
    vec![
        seed_a("issue46-opd-directory", directory, Expect::Read { missing: 0 }),
        seed_a("issue46-opd-marker-1e38", marker, Expect::Read { missing: 1 }),
        seed_a("issue46-al3d-tags", al3d(Declared::Right), Expect::Read { missing: 0 }),
        seed_a(
            "issue46-al3d-tag-count-2m",
            al3d(Declared::Raw(2_000_006)),
            Expect::Refused(&["surface.al3d"]),
        ),
    ]
}

fn seeds_b() -> Vec<Seed> {
    use b::*;
    let input = |file: File| Input {
        options: OptionsSpec::Fixed,
        no_intervals: true,
        channel: None,
        file,
        len: Len::Exact,
        values: (0..32u8).map(|k| k.wrapping_mul(37)).collect(),
        flips: vec![],
        other_name: false,
        cut: None,
    };
    let channel = |points: Dim, lines: Dim, bits: u8, unit: u8| NidChannel {
        points,
        lines,
        bits,
        signed: true,
        intel: true,
        binary: true,
        unit,
        lateral_unit: Some(0),
        range: Num::Exp(-112), // 1e-7
        min: None,
        size: Num::Exp(-96), // 1e-6
    };
    let height = || channel(Dim::Small(4), Dim::Small(4), 1, 0);
    let nid = |channels: Vec<(bool, NidChannel)>| Nid {
        channels,
        count_off: 0,
        groups: 1,
        crlf: true,
        junk_line: None,
    };
    // A .nid whose earlier (unread) channel declares 64 x (2^58 - 1)
    // bytes: the height channel's data would start at 2^64 - 64 past the
    // data's start (issue 46: the offset wrapped into the header).
    let wrap = input(File::Nid(nid(vec![
        (true, channel(Dim::Edge(7), Dim::Edge(8), 0, 4)),
        (true, height()),
    ])));
    // A .nid listing a channel whose section is missing: section
    // [DataSet-0:0] renamed [DataSet-0:7] by a flip.
    let mut missing = input(File::Nid(nid(vec![(true, height()), (true, height())])));
    let at = position_b(&missing, b"[DataSet-0:0]") + 11;
    missing.flips = vec![(at, b'7')];
    // ESC sequences and a CR in a channel's frame, the channel asked for
    // (a signal in V, refused naming it).
    let mut esc = input(File::Nid(nid(vec![(
        true,
        channel(Dim::Small(4), Dim::Small(4), 1, 4),
    )])));
    esc.channel = Some(Ok(0));
    let at = position_b(&esc, b"Frame=Scan forward") + 6;
    esc.flips = b"\x1b[2J\x1b]0;\x07\r"
        .iter()
        .enumerate()
        .map(|(k, &c)| (at + k as u16, c))
        .collect();
    // A Nanoscope file of one height image.
    let nanoscope = || {
        input(File::Nanoscope(Nanoscope {
            version: 1,
            soft: vec![],
            global: None,
            slow_axis: None,
            mode: 0,
            images: vec![Image {
                nx: Dim::Small(8),
                ny: Dim::Small(8),
                bytes_per_pixel: 0, // 2
                offset: None,
                length_off: None,
                size_form: 0,
                size: Num::Exp(0),
                unit: 2, // um
                quantity: None,
                z_scale: Num::Exp(0),
                hard_unit: 0,
                name: 0,
            }],
            junk_line: None,
        }))
    };
    // Its header cut in the image section.
    let mut truncated = nanoscope();
    truncated.cut = Some(position_b(&truncated, b"Z scale:") + 3);
    // `Bytes/pixel: -2` (was read as 2): "2\r\n" made "-2\n".
    let mut negative = nanoscope();
    let at = position_b(&negative, b"Bytes/pixel: 2\r\n") + 13;
    negative.flips = vec![(at, b'-'), (at + 1, b'2')];
    // ESC sequences in the image's name, asked for by another name.
    let mut esc_name = nanoscope();
    esc_name.channel = Some(Err(1)); // "Phase"
    let at = position_b(&esc_name, b"[Height]") + 1;
    esc_name.flips = b"\x1b[2J\x07\r"
        .iter()
        .enumerate()
        .map(|(k, &c)| (at + k as u16, c))
        .collect();
    vec![
        seed_b(
            "issue46-nid-wrapped-offset",
            wrap,
            Expect::Refused(&["beyond any file"]),
        ),
        seed_b(
            "issue46-nid-missing-section",
            missing,
            Expect::Refused(&["no section [DataSet-0:0]"]),
        ),
        seed_b("issue46-nid-esc-in-frame", esc, Expect::Refused(&["\\u{1b}[2J"])),
        seed_b(
            "issue46-nanoscope-truncated-header",
            truncated,
            Expect::Refused(&["truncated"]),
        ),
        seed_b(
            "issue46-nanoscope-bytes-per-pixel-negative",
            negative,
            Expect::Refused(&["Bytes/pixel = \"-2\": must be 2 or 4"]),
        ),
        seed_b(
            "issue46-nanoscope-esc-in-name",
            esc_name,
            Expect::Refused(&["\\u{1b}[2J"]),
        ),
    ]
}

fn main() {
    let check_only = std::env::args().any(|a| a == "--check");
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("seeds");
    let mut stale = Vec::new();
    for seed in seeds_a().into_iter().chain(seeds_b()) {
        let path = dir.join(seed.target).join(seed.name);
        if check_only {
            if std::fs::read(&path).ok().as_deref() != Some(&seed.input[..]) {
                stale.push(path.display().to_string());
            }
        } else {
            std::fs::write(&path, &seed.input).expect("writes the seed");
            println!("  wrote {} ({} bytes)", path.display(), seed.input.len());
        }
    }
    if !stale.is_empty() {
        eprintln!("seeds differ from what fuzz/examples/seeds.rs makes (run it): {stale:?}");
        std::process::exit(1);
    }
}
