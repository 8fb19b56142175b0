//! The readers of Zygo MetroPro `.dat`, Bruker Nanoscope and Nanosurf
//! `.nid` files on real instruments' files (`../shared/topographies/`, or
//! the folder `KEF_TOPOGRAPHIES` names; skipped with a message where
//! absent): sizes, intervals and heights against SurfaceTopography 1.27.1's
//! reading of the same files (values copied from its `heights()`, indexed
//! [x, y]; python/tests/test_formats_b.py compares every height), the
//! metadata, the channel choice; every sampled truncation and many byte
//! flips give an error or the same heights, never a panic or other heights.
//! Files of other programs with the shared extensions (`.dat`, `.di`) fall
//! through to the text reader.

use ke_friction::topography::{read_bytes, read_file, Channel, Format, ReadError, ReadOptions, Topography};

use crate::common::{instrument_file as file, TempDir};

/// A file as SurfaceTopography 1.27.1 reads it (`to_unit('m')`): its
/// format, points, physical sizes (m) and four heights (m) at [x, y] =
/// [0, 0], [1, 0], [0, 1], [nx - 1, ny - 1].
struct Known {
    name: &'static str,
    format: Format,
    n: (usize, usize),
    size: (f64, f64),
    heights: [f64; 4],
    channel: Option<&'static str>,
}

const KNOWN: [Known; 4] = [
    Known {
        name: "metropro-1.dat",
        format: Format::METROPRO,
        n: (640, 480),
        size: (0.0007028812979115173, 0.000527160973433638),
        heights: [
            5.05753145602552e-05,
            5.057560157807617e-05,
            5.057604515107221e-05,
            5.085188667204241e-05,
        ],
        channel: None,
    },
    Known {
        name: "di-1.di",
        format: Format::NANOSCOPE,
        n: (512, 512),
        size: (5.000000000000001e-07, 5.000000000000001e-07),
        heights: [
            6.059980111183002e-09,
            6.0812529351386196e-09,
            6.2468109998366895e-09,
            -3.030637489364063e-08,
        ],
        channel: Some("Height"),
    },
    Known {
        name: "di-3.di",
        format: Format::NANOSCOPE,
        n: (256, 256),
        size: (1e-05, 1e-05),
        heights: [
            5.6401630244078e-07,
            5.613488580256634e-07,
            5.637199197279894e-07,
            -6.164760426047413e-07,
        ],
        channel: Some("ZSensor"),
    },
    Known {
        name: "nid-1.nid",
        format: Format::NID,
        n: (256, 256),
        size: (2e-05, 2e-05),
        heights: [
            -9.253918035998941e-07,
            -9.266565515175462e-07,
            -9.262948113754393e-07,
            -1.982578380569816e-06,
        ],
        channel: Some("Scan forward (Z-Axis)"),
    },
];

fn close(got: f64, want: f64, tol: f64) -> bool {
    (got - want).abs() <= tol * want.abs()
}

/// The height at [x, y] (row-major, rows = y).
fn at(t: &Topography, x: usize, y: usize) -> f64 {
    t.heights()[y * t.nx() + x]
}

#[test]
fn real_files_match_surface_topography() {
    for k in &KNOWN {
        let Some(path) = file(k.name) else { continue };
        let t = read_file(&path, &ReadOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((t.nx(), t.ny()), k.n, "{}", k.name);
        let (nx, ny) = k.n;
        let dy = t.dy().expect("a map");
        assert!(close(t.dx() * nx as f64, k.size.0, 1e-12), "{}: dx {}", k.name, t.dx());
        assert!(close(dy * ny as f64, k.size.1, 1e-12), "{}: dy {dy}", k.name);
        let got = [at(&t, 0, 0), at(&t, 1, 0), at(&t, 0, 1), at(&t, nx - 1, ny - 1)];
        for (g, w) in got.iter().zip(k.heights) {
            assert!(close(*g, w, 1e-12), "{}: height {g:e}, SurfaceTopography {w:e}", k.name);
        }
        assert!(t.heights().iter().all(|h| h.is_finite()), "{}", k.name);
        let m = t.metadata();
        assert_eq!(m.format, Some(k.format.name()), "{}", k.name);
        assert!(m.instrument.is_some() && m.date.is_some(), "{}: {m:?}", k.name);
        assert_eq!(m.channel.as_deref(), k.channel, "{}", k.name);
        assert_eq!(Format::detect(&path, &std::fs::read(&path).unwrap()[..64]), k.format);
    }
}

#[test]
fn metadata_of_the_real_files() {
    if let Some(path) = file("metropro-1.dat") {
        let m = read_file(&path, &ReadOptions::default()).unwrap().metadata().clone();
        assert_eq!(m.instrument.as_deref(), Some("Zygo (serial 59407)"));
        assert_eq!(m.date.as_deref(), Some("2011-07-23T16:49:36Z"));
    }
    if let Some(path) = file("di-1.di") {
        let m = read_file(&path, &ReadOptions::default()).unwrap().metadata().clone();
        assert_eq!(
            m.instrument.as_deref(),
            Some("Bruker Dimension V (Nanoscope 0x07200000)")
        );
        assert_eq!(m.date.as_deref(), Some("09:57:48 AM Tue Jan 12 2016"));
        assert_eq!(m.channels, ["Height", "Height", "Phase", "AmplitudeError"]);
        assert_eq!(m.height_unit.as_deref(), Some("nm"));
    }
    if let Some(path) = file("nid-1.nid") {
        let m = read_file(&path, &ReadOptions::default()).unwrap().metadata().clone();
        assert_eq!(m.date.as_deref(), Some("2022-11-03T11:46:25"));
        assert_eq!(m.channels.len(), 8);
        assert_eq!(m.channels[3], "Scan forward (Z-AxisSensor)");
        assert_eq!(m.height_unit.as_deref(), Some("m"));
    }
}

fn with_channel(channel: &str) -> ReadOptions {
    ReadOptions {
        channel: Some(channel.parse::<Channel>().unwrap()),
        ..ReadOptions::default()
    }
}

#[test]
fn channels_are_chosen_by_index_or_name() {
    if let Some(path) = file("di-1.di") {
        let first = read_file(&path, &ReadOptions::default()).unwrap();
        // The second Height channel (SurfaceTopography's channel 1): at
        // [0, 0] 0.10486797588653565 nm per LSB times its value.
        let second = read_file(&path, &with_channel("1")).unwrap();
        assert_eq!(second.metadata().channel.as_deref(), Some("Height"));
        assert_ne!(first.heights(), second.heights());
        // Two channels are called Height: the name is ambiguous.
        let e = read_file(&path, &with_channel("height")).unwrap_err();
        assert!(matches!(e, ReadError::Channel { .. }), "{e}");
        assert!(e.to_string().contains("give its index"), "{e}");
        // Phase holds no heights; a wrong index lists the channels.
        let e = read_file(&path, &with_channel("Phase")).unwrap_err();
        assert!(e.to_string().contains("holds no heights"), "{e}");
        assert!(e.to_string().contains("2 Phase"), "{e}");
        let e = read_file(&path, &with_channel("7")).unwrap_err();
        assert!(e.to_string().contains("0 to 3"), "{e}");
    }
    if let Some(path) = file("di-3.di") {
        let t = read_file(&path, &with_channel("Height")).unwrap();
        assert_eq!(t.metadata().channel.as_deref(), Some("Height"));
        assert_eq!((t.nx(), t.ny()), (256, 256));
    }
    if let Some(path) = file("nid-1.nid") {
        let forward = read_file(&path, &ReadOptions::default()).unwrap();
        let backward = read_file(&path, &with_channel("scan backward (z-axis)")).unwrap();
        assert_eq!(backward.metadata().channel.as_deref(), Some("Scan backward (Z-Axis)"));
        assert_ne!(forward.heights(), backward.heights());
        let e = read_file(&path, &with_channel("Scan forward (Deflection)")).unwrap_err();
        assert!(e.to_string().contains("\"N\", not a length"), "{e}");
    }
    if let Some(path) = file("metropro-1.dat") {
        let e = read_file(&path, &with_channel("0")).unwrap_err();
        assert!(matches!(e, ReadError::Channel { .. }), "{e}");
    }
}

#[test]
fn the_points_limit_is_checked_before_reading() {
    for k in &KNOWN {
        let Some(path) = file(k.name) else { continue };
        let options = ReadOptions {
            max_points: 1000,
            ..ReadOptions::default()
        };
        let e = read_file(&path, &options).unwrap_err();
        assert!(matches!(e, ReadError::TooManyPoints { .. }), "{}: {e}", k.name);
    }
}

#[test]
fn other_programs_files_with_shared_extensions_are_text() {
    let dir = TempDir::new("instruments-b-shared");
    for name in ["heights.dat", "heights.di", "heights.spm", "scan.001"] {
        let path = dir.join(name);
        std::fs::write(&path, "1 2 3 7\n4 5 6 8\n").unwrap();
        let options = ReadOptions {
            dx: Some(1e-6),
            dy: Some(1e-6),
            ..ReadOptions::default()
        };
        let t = read_file(&path, &options).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!((t.nx(), t.ny()), (4, 2), "{name}");
        assert_eq!(t.metadata().format, Some("text"), "{name}");
    }
    // An instrument's file under another name is found by its signature;
    // a .nid that is not one is refused as a .nid (not a shared extension).
    if let Some(path) = file("metropro-1.dat") {
        let bytes = std::fs::read(&path).unwrap();
        let t = read_bytes(&bytes, "measurement.bin", &ReadOptions::default()).unwrap();
        assert_eq!(t.metadata().format, Some("metropro"));
    }
    let e = read_bytes(b"1 2 3\n", "scan.nid", &ReadOptions::default()).unwrap_err();
    assert!(e.to_string().contains("not a readable Nanosurf .nid file"), "{e}");
}

/// Every sampled prefix of each file: an error, or (where what is cut is
/// data the reading does not need) the same heights; never a panic.
#[test]
fn truncated_files_give_errors_never_other_heights() {
    for k in &KNOWN {
        let Some(path) = file(k.name) else { continue };
        let bytes = std::fs::read(&path).unwrap();
        let full = read_bytes(&bytes, k.name, &ReadOptions::default()).unwrap();
        let n = bytes.len();
        let mut cuts: Vec<usize> = vec![0, 1, 2, 3, 4, 10, 63, 64, 100, 833, 834, 835, 4095, 4096, 4097];
        cuts.extend((1..40).map(|i| i * n / 40));
        cuts.extend([n - 4, n - 1]);
        for cut in cuts.into_iter().filter(|&c| c < n) {
            match read_bytes(&bytes[..cut], k.name, &ReadOptions::default()) {
                Ok(t) => {
                    assert!(cut > n / 4, "{}: cut to {cut} bytes, read", k.name);
                    assert_eq!(t.heights(), full.heights(), "{}: cut to {cut}", k.name);
                }
                Err(e) => {
                    let message = e.to_string();
                    assert!(message.contains(k.name), "{message}");
                    assert!(!e.is_io(), "{message}");
                }
            }
        }
    }
}

/// Bytes of each file's header flipped: an error or a topography, never
/// a panic.
#[test]
fn flipped_header_bytes_never_panic() {
    for k in &KNOWN {
        let Some(path) = file(k.name) else { continue };
        let mut bytes = std::fs::read(&path).unwrap();
        let header = bytes.len().min(if k.format == Format::METROPRO { 834 } else { 40_000 });
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..200 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let at = (seed % header as u64) as usize;
            let value = (seed >> 32) as u8;
            let old = bytes[at];
            bytes[at] = value;
            if let Ok(t) = read_bytes(&bytes, k.name, &ReadOptions::default()) {
                assert_eq!(t.heights().len(), t.nx() * t.ny());
            }
            bytes[at] = old;
        }
    }
}
