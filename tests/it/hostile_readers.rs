//! The instrument readers against hostile files (issue 46): offsets that
//! would wrap, channels listed without their section, missing markers,
//! header tables of millions of entries, text from a file in messages,
//! truncated and damaged headers, device files. Every file is generated
//! here, small.

use std::time::Instant;

use ke_friction::topography::{read_bytes, read_file, Channel, ReadError, ReadOptions};

fn opts() -> ReadOptions {
    ReadOptions::default()
}

/// The message of a refused read (it must name the file and hold no
/// control character: text from the file is escaped).
fn refused(bytes: &[u8], name: &str, options: &ReadOptions) -> String {
    let e = read_bytes(bytes, name, options).expect_err("must be refused");
    let message = e.to_string();
    assert!(message.contains(name), "{message}");
    assert!(!message.chars().any(char::is_control), "{message:?}");
    assert!(!e.is_io(), "{message}");
    message
}

// ----- Nanosurf .nid -----

/// A channel of a generated `.nid`: its section's name, frame, unit, size
/// (Points, Lines) and bits.
struct NidChannel<'a> {
    section: &'a str,
    frame: &'a str,
    unit: &'a str,
    size: (u64, u64),
    bits: u64,
}

impl NidChannel<'_> {
    fn height(section: &str) -> NidChannel<'_> {
        NidChannel {
            section,
            frame: "Scan forward",
            unit: "m",
            size: (4, 4),
            bits: 16,
        }
    }
}

/// A `.nid` listing `listed` (section names) in group 0 and holding the
/// sections of `channels`, then the data: `data` bytes.
fn nid(listed: &[&str], channels: &[NidChannel], data: &[u8]) -> Vec<u8> {
    let mut t = format!(
        "[DataSet]\r\nVersion=2\r\nGroupCount=1\r\nGr0-Count={}\r\n",
        listed.len()
    );
    for (j, name) in listed.iter().enumerate() {
        t += &format!("Gr0-Ch{j}={name}\r\n");
    }
    for c in channels {
        t += &format!(
            "[{}]\r\nFrame={}\r\nPoints={}\r\nLines={}\r\nSaveMode=Binary\r\nSaveBits={}\r\nSaveSign=Signed\r\n\
             SaveOrder=Intel\r\nDim0Range=1e-6\r\nDim1Range=1e-6\r\nDim0Unit=m\r\nDim1Unit=m\r\nDim2Range=1e-7\r\n\
             Dim2Min=-5e-8\r\nDim2Unit={}\r\nDim2Name=Z-Axis\r\n",
            c.section, c.frame, c.size.0, c.size.1, c.bits, c.unit
        );
    }
    let mut out = t.into_bytes();
    out.extend_from_slice(b"#!");
    out.extend_from_slice(data);
    out
}

/// 4 x 4 16-bit heights.
fn data16() -> Vec<u8> {
    (0..16i16).flat_map(|v| (v * 1000 - 8000).to_le_bytes()).collect()
}

#[test]
fn a_generated_nid_reads() {
    let bytes = nid(&["DataSet-0:1"], &[NidChannel::height("DataSet-0:1")], &data16());
    let t = read_bytes(&bytes, "ok.nid", &opts()).unwrap();
    assert_eq!((t.nx(), t.ny()), (4, 4));
    assert!((t.dx() - 0.25e-6).abs() < 1e-18);
}

#[test]
fn a_nid_whose_earlier_channel_declares_2_to_the_64_bytes_is_refused() {
    // Channel 0 (a signal in V, not read) declares 64 x (2^58 - 1) =
    // 2^64 - 64 bytes: channel 1's data would start at data_start +
    // 2^64 - 64, which wraps to 64 bytes before the data (the header).
    // A file whose channel 0 (a signal) has `size` points before channel 1.
    let with_signal = |size: (u64, u64)| {
        let signal = NidChannel {
            section: "DataSet-0:0",
            frame: "Scan forward",
            unit: "V",
            size,
            bits: 8,
        };
        nid(
            &["DataSet-0:0", "DataSet-0:1"],
            &[signal, NidChannel::height("DataSet-0:1")],
            &data16(),
        )
    };
    let m = refused(&with_signal((64, (1 << 58) - 1)), "wrap.nid", &opts());
    assert!(m.contains("beyond any file"), "{m}");
    // 2^64 bytes and more before channel 1: said so.
    let bytes = with_signal((4_294_967_295, 4_294_967_297));
    let m = refused(&bytes, "wrap.nid", &opts());
    assert!(m.contains("more than 2^64 bytes"), "{m}");
    // Asked for by index, channel 0 is refused the same way (the sizes
    // are checked before a channel is chosen).
    let o = ReadOptions {
        channel: Some(Channel::Index(0)),
        ..opts()
    };
    let m = refused(&bytes, "wrap.nid", &o);
    assert!(m.contains("more than 2^64 bytes"), "{m}");
}

#[test]
fn a_nid_listing_a_channel_without_its_section_is_refused_naming_it() {
    let bytes = nid(
        &["DataSet-0:0", "DataSet-0:1"],
        &[NidChannel::height("DataSet-0:1")],
        &data16(),
    );
    let m = refused(&bytes, "missing.nid", &opts());
    assert!(
        m.contains("Gr0-Ch0 = DataSet-0:0") && m.contains("no section [DataSet-0:0]"),
        "{m}"
    );
}

#[test]
fn a_nid_cut_in_its_header_says_truncated() {
    let bytes = nid(&["DataSet-0:1"], &[NidChannel::height("DataSet-0:1")], &data16());
    let at = bytes.windows(5).position(|w| w == b"Lines").unwrap() + 2;
    let m = refused(&bytes[..at], "cut.nid", &opts());
    assert!(
        m.contains("ends within its text header") && m.contains("truncated"),
        "{m}"
    );
    assert!(!m.contains("key=value"), "{m}");
}

#[test]
fn a_channel_name_with_control_characters_is_escaped() {
    let bad = NidChannel {
        frame: "\x1b[2J\x1c\x1d\x0bx",
        unit: "V",
        ..NidChannel::height("DataSet-0:0")
    };
    let bytes = nid(&["DataSet-0:0"], &[bad], &data16());
    let o = ReadOptions {
        channel: Some(Channel::Index(0)),
        ..opts()
    };
    let m = refused(&bytes, "esc.nid", &o);
    assert!(m.contains("\\u{1b}[2J\\u{1c}\\u{1d}\\u{b}x"), "{m}");
}

// ----- Bruker Nanoscope -----

/// A Nanoscope file: `file_list` lines added to the File list section,
/// `images` image sections (4 x 4, 2 bytes a pixel, the first a height
/// channel named `name`), `image_extra` lines added to each.
fn nanoscope(file_list: &str, images: usize, name: &str, image_extra: &str) -> Vec<u8> {
    let mut t = format!("\\*File list\r\n\\Version: 0x05120000\r\n{file_list}");
    t += "\\*Scanner list\r\n\\@Sens. Zsens: V 20 nm/V\r\n";
    t += "\\*Ciao scan list\r\n\\Scan Size: 1 1 ~m\r\n";
    for i in 0..images {
        let name = if i == 0 { name.to_string() } else { format!("Phase {i}") };
        let quantity = if i == 0 { "Sens. Zsens" } else { "Sens. Phase" };
        t += &format!(
            "\\*Ciao image list\r\n\\Data offset: 65536\r\n\\Data length: 32\r\n\\Samps/line: 4\r\n\
             \\Number of lines: 4\r\n\\Scan Size: 1 1 ~m\r\n\\@2:Image Data: S [{name}] \"{name}\"\r\n\
             \\@2:Z scale: V [{quantity}] (0.006 V/LSB) 2 V\r\n{image_extra}"
        );
    }
    t += "\\*File list end\r\n\x1a";
    let mut out = t.into_bytes();
    assert!(out.len() <= 65536);
    out.resize(65536, 0);
    out.extend_from_slice(&data16());
    out
}

#[test]
fn a_generated_nanoscope_file_reads() {
    let t = read_bytes(&nanoscope("", 1, "Height", ""), "ok.spm", &opts()).unwrap();
    assert_eq!((t.nx(), t.ny()), (4, 4));
}

#[test]
fn a_value_holding_the_end_marker_is_a_value() {
    let bytes = nanoscope("\\Description: see \\*File list end here\r\n", 1, "Height", "");
    let t = read_bytes(&bytes, "marker.spm", &opts()).unwrap();
    assert_eq!((t.nx(), t.ny()), (4, 4));
}

#[test]
fn a_blank_line_or_a_cut_header_says_so() {
    let bytes = nanoscope("\r\n", 1, "Height", "");
    let m = refused(&bytes, "blank.spm", &opts());
    assert!(m.contains("line 3 of the header is blank"), "{m}");
    assert!(!m.contains("channels: none"), "{m}");
    let bytes = nanoscope("", 1, "Height", "");
    let at = bytes.windows(8).position(|w| w == b"Z scale:").unwrap();
    let m = refused(&bytes[..at], "cut.spm", &opts());
    assert!(
        m.contains("ends within its text header") && m.contains("truncated"),
        "{m}"
    );
}

#[test]
fn bytes_per_pixel_must_be_2_or_4() {
    for bad in ["-2", "3", "two"] {
        let bytes = nanoscope("", 1, "Height", &format!("\\Bytes/pixel: {bad}\r\n"));
        let m = refused(&bytes, "bpp.spm", &opts());
        assert!(m.contains(&format!("Bytes/pixel = \"{bad}\": must be 2 or 4")), "{m}");
    }
}

#[test]
fn long_channel_lists_are_cut_with_a_count() {
    let bytes = nanoscope("", 45, "Height", "");
    let o = ReadOptions {
        channel: Some(Channel::Name("nope".into())),
        ..opts()
    };
    let m = refused(&bytes, "many.spm", &o);
    assert!(m.contains("19 Phase 19 … and 25 more"), "{m}");
    assert!(!m.contains("Phase 20"), "{m}");
    // A name with an ESC and a CR, escaped in the list.
    let bytes = nanoscope("", 1, "He\x1b[2Jig\rht", "");
    let m = refused(&bytes, "esc.spm", &o);
    assert!(m.contains("He\\u{1b}[2Jig\\u{d}ht"), "{m}");
}

// ----- Bruker/Veeco .opd -----

/// An `.opd` directory entry.
fn opd_entry(name: &str, kind: i16, length: i32) -> Vec<u8> {
    let mut e = vec![0u8; 16];
    e[..name.len()].copy_from_slice(name.as_bytes());
    e.extend_from_slice(&kind.to_le_bytes());
    e.extend_from_slice(&length.to_le_bytes());
    e.extend_from_slice(&0u16.to_le_bytes());
    e
}

/// An `.opd` of one f32 raster `nx` x `ny` (`values`, column by column),
/// a wavelength and pixel size, after `junk` directory entries of no
/// block (length 0) and `rasters - 1` more rasters of the same data.
fn opd(nx: u16, ny: u16, values: &[f32], junk: usize, rasters: usize) -> Vec<u8> {
    let raster_len = 6 + 4 * values.len() as i32;
    let entries = 3 + junk + rasters;
    let mut out = vec![0u8, 0u8];
    out.extend(opd_entry("Directory", 3, 24 * (entries as i32 + 1)));
    out.extend(opd_entry("Wavelength", 7, 4));
    out.extend(opd_entry("Pixel_size", 7, 4));
    for _ in 0..junk {
        out.extend(opd_entry("Junk", 7, 0));
    }
    for _ in 0..rasters {
        out.extend(opd_entry("RAW DATA", 3, raster_len));
    }
    out.extend(opd_entry("Mult", 6, 2));
    out.extend(600.0f32.to_le_bytes());
    out.extend(0.001f32.to_le_bytes());
    for _ in 0..rasters {
        out.extend(nx.to_le_bytes());
        out.extend(ny.to_le_bytes());
        out.extend(4u16.to_le_bytes());
        out.extend(values.iter().flat_map(|v| v.to_le_bytes()));
    }
    out.extend(1i16.to_le_bytes());
    out
}

#[test]
fn the_opd_missing_marker_is_f32_1e38() {
    let mut values: Vec<f32> = (0..16).map(|i| i as f32 * 0.01).collect();
    values[5] = 1e38;
    values[6] = f32::MAX;
    values[7] = 9.9e37;
    let t = read_bytes(&opd(4, 4, &values, 0, 1), "marker.opd", &opts()).unwrap();
    let missing = t.heights().iter().filter(|h| h.is_nan()).count();
    // 1e38 and above are missing; 9.9e37 is a (huge) height.
    assert_eq!(missing, 2, "{:?}", t.heights());
}

#[test]
fn an_opd_directory_of_many_entries_is_streamed_and_rasters_are_bounded() {
    let values: Vec<f32> = (0..16).map(|i| i as f32 * 0.01).collect();
    let t0 = Instant::now();
    let t = read_bytes(&opd(4, 4, &values, 200_000, 1), "junk.opd", &opts()).unwrap();
    assert_eq!((t.nx(), t.ny()), (4, 4));
    // Generous: a debug build on a loaded machine (memory is the point,
    // measured by tools/hostile_surfaces.py).
    assert!(t0.elapsed().as_secs_f64() < 30.0);
    let m = refused(&opd(4, 4, &values, 0, 1025), "rasters.opd", &opts());
    assert!(m.contains("1025 height rasters: at most 1024 are read"), "{m}");
}

// ----- Alicona .al3d -----

fn al3d_tag(key: &str, value: &str) -> Vec<u8> {
    let mut t = vec![0u8; 52];
    t[..key.len()].copy_from_slice(key.as_bytes());
    t[20..20 + value.len()].copy_from_slice(value.as_bytes());
    t[50..].copy_from_slice(b"\r\n");
    t
}

/// An `.al3d` of a 3 x 2 map after `junk` tags nobody reads.
fn al3d(junk: usize) -> Vec<u8> {
    let count = 6 + junk;
    let header = 17 + 52 * (2 + count) + 256;
    let mut out = b"AliconaImaging\x00\r\n".to_vec();
    out.extend(al3d_tag("Version", "1"));
    out.extend(al3d_tag("TagCount", &count.to_string()));
    for _ in 0..junk {
        out.extend(al3d_tag("Junk", "0"));
    }
    for (k, v) in [
        ("Cols", "3".to_string()),
        ("Rows", "2".to_string()),
        ("PixelSizeXMeter", "1e-6".to_string()),
        ("PixelSizeYMeter", "1e-6".to_string()),
        ("DepthImageOffset", header.to_string()),
        ("InvalidPixelValue", "nan".to_string()),
    ] {
        out.extend(al3d_tag(k, &v));
    }
    out.resize(header, 0);
    // Rows of 3 padded to 4 values.
    for v in [1.0f32, 2.0, 3.0, 0.0, 4.0, 5.0, 6.0, 0.0] {
        out.extend((v * 1e-6).to_le_bytes());
    }
    out
}

#[test]
fn al3d_tags_are_streamed() {
    let t = read_bytes(&al3d(0), "ok.al3d", &opts()).unwrap();
    assert_eq!((t.nx(), t.ny()), (3, 2));
    let t0 = Instant::now();
    let t = read_bytes(&al3d(200_000), "junk.al3d", &opts()).unwrap();
    assert_eq!((t.nx(), t.ny()), (3, 2));
    assert!(t0.elapsed().as_secs_f64() < 30.0);
    // A tag without its CR LF is named.
    let mut bytes = al3d(10);
    let at = 17 + 52 * 7 + 50;
    bytes[at] = b'x';
    let m = refused(&bytes, "crlf.al3d", &opts());
    assert!(m.contains("tag 7 does not end in CR LF"), "{m}");
}

// ----- Zygo MetroPro -----

fn metropro(lateral: f32) -> Vec<u8> {
    let mut h = vec![0u8; 834];
    h[..4].copy_from_slice(&[0x88, 0x1b, 0x03, 0x6f]);
    h[6..10].copy_from_slice(&834u32.to_be_bytes());
    h[68..70].copy_from_slice(&4u16.to_be_bytes());
    h[70..72].copy_from_slice(&2u16.to_be_bytes());
    for (at, v) in [(164, 0.5f32), (168, 6e-7), (176, 1.0), (184, lateral)] {
        h[at..at + 4].copy_from_slice(&v.to_be_bytes());
    }
    h.extend((0..8i32).flat_map(|v| (v * 100).to_be_bytes()));
    h
}

#[test]
fn a_negative_lateral_res_says_negative() {
    let t = read_bytes(&metropro(1e-6), "ok.dat", &opts()).unwrap();
    assert_eq!((t.nx(), t.ny()), (4, 2));
    let m = refused(&metropro(-1e-6), "neg.dat", &opts());
    assert!(m.contains("lateral_res = -9.99") && m.contains("m is negative"), "{m}");
    let m = refused(&metropro(f32::NAN), "nan.dat", &opts());
    assert!(m.contains("is not a number"), "{m}");
    // 0: no interval in the file, and the message names the option in words.
    let m = refused(&metropro(0.0), "zero.dat", &opts());
    assert!(m.contains("give the sampling interval dx"), "{m}");
    assert!(!m.contains("ReadOptions"), "{m}");
}

// ----- Files that are not files -----

#[test]
fn devices_and_directories_are_refused_as_what_they_are() {
    if cfg!(unix) {
        let e = read_file("/dev/zero".as_ref(), &opts()).unwrap_err();
        assert!(e.is_io());
        assert!(e.to_string().contains("a character device, not a regular file"), "{e}");
        assert!(matches!(e, ReadError::Io { .. }));
        let e = read_file("/".as_ref(), &opts()).unwrap_err();
        assert!(e.to_string().contains("a directory, not a regular file"), "{e}");
    }
}
