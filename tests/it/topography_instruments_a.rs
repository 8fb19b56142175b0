//! The instruments' own formats, part a (Digital Surf `.sur`, Sensofar
//! `.plu`, Bruker/Veeco `.opd`, Alicona `.al3d`) on the real files of
//! SurfaceTopography's test suite: their grids, intervals, missing points
//! and a few heights as SurfaceTopography 1.27.1 reads them
//! (`read_topography(path).to_unit('m')`, the independent oracle; the full
//! comparison is python/tests/test_formats_a.py); every truncation (a
//! sample of prefix lengths) and byte flips give an error or the same
//! surface, never a panic or a different one.
//!
//! The files: `$KEF_TOPOGRAPHIES`, else `../shared/topographies` beside the
//! repository; each test says so and passes when they are absent.

use ke_friction::topography::{read_bytes, Channel, Format, ReadError, ReadOptions, Topography};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Heights and intervals against SurfaceTopography's: the same numbers
/// from the same bytes, up to the order of the unit conversions.
const REL: f64 = 1e-12;

/// A file and what SurfaceTopography reads from it.
struct Known {
    name: &'static str,
    format: Format,
    nx: usize,
    ny: usize,
    /// `physical_sizes` (m).
    size: (f64, f64),
    missing: usize,
    /// Heights (m) at SurfaceTopography's `[x, y]`.
    heights: [((usize, usize), f64); 2],
}

const FILES: [Known; 4] = [
    Known {
        name: "sur-2.sur",
        format: Format::SUR,
        nx: 563,
        ny: 484,
        size: (0.0019614921233151107, 0.0016862561060115694),
        missing: 117,
        heights: [((0, 0), 1.014770011858701e-05), ((1, 2), 1.0148900118601034e-05)],
    },
    Known {
        name: "plu-1.plu",
        format: Format::PLU,
        nx: 768,
        ny: 576,
        size: (0.0012748800659179687, 0.0009561600494384765),
        missing: 0,
        heights: [((0, 0), -0.0001112265625), ((1, 2), -0.00011121484375)],
    },
    Known {
        name: "opd-1.opd",
        format: Format::OPD,
        nx: 640,
        ny: 480,
        size: (0.0001259091403335333, 9.443185525014996e-05),
        missing: 116,
        heights: [((0, 0), -2.6550621614908414e-07), ((1, 2), -2.6922706615956855e-07)],
    },
    Known {
        name: "al3d-1.al3d",
        format: Format::AL3D,
        nx: 200,
        ny: 296,
        size: (8.76054e-05, 0.000129655992),
        missing: 0,
        heights: [((0, 0), 0.07635815441608429), ((1, 2), 0.07635805010795593)],
    },
];

/// The bytes of each file present.
fn files() -> Vec<(&'static Known, Vec<u8>)> {
    let Some(dir) = crate::common::topographies() else {
        return Vec::new();
    };
    FILES
        .iter()
        .filter_map(|k| match std::fs::read(dir.join(k.name)) {
            Ok(bytes) => Some((k, bytes)),
            Err(e) => {
                println!("skipped {}: {e}", k.name);
                None
            }
        })
        .collect()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= REL * a.abs().max(b.abs())
}

#[test]
fn each_file_reads_as_surface_topography_reads_it() {
    for (k, bytes) in files() {
        let t = read_bytes(&bytes, k.name, &ReadOptions::default()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((t.nx(), t.ny()), (k.nx, k.ny), "{}", k.name);
        let dy = t.dy().expect("a map");
        assert!(close(t.dx() * k.nx as f64, k.size.0), "{}: dx = {}", k.name, t.dx());
        assert!(close(dy * k.ny as f64, k.size.1), "{}: dy = {dy}", k.name);
        let missing = t.heights().iter().filter(|h| h.is_nan()).count();
        assert_eq!(missing, k.missing, "{}", k.name);
        for ((x, y), want) in k.heights {
            let got = t.heights()[y * k.nx + x];
            assert!(
                close(got, want),
                "{} [{x}, {y}]: {got:e}, SurfaceTopography {want:e}",
                k.name
            );
        }
        let m = t.metadata();
        assert_eq!(m.format, Some(k.format.name()), "{}", k.name);
        assert!(m.height_unit.is_some(), "{}", k.name);
    }
}

#[test]
fn the_format_comes_from_the_content_where_there_is_a_signature() {
    for (k, bytes) in files() {
        let renamed = format!("{}.bin", k.name);
        match read_bytes(&bytes, &renamed, &ReadOptions::default()) {
            Ok(t) => {
                assert_ne!(k.format, Format::PLU, "a .plu file has no signature");
                assert_eq!(t.metadata().format, Some(k.format.name()));
            }
            // A .plu file named otherwise is read as text, and is not text.
            Err(e) => assert_eq!(k.format, Format::PLU, "{}: {e}", k.name),
        }
    }
}

#[test]
fn max_points_refuses_a_file_before_reading_its_heights() {
    for (k, bytes) in files() {
        let options = ReadOptions {
            max_points: 1000,
            ..ReadOptions::default()
        };
        let e = read_bytes(&bytes, k.name, &options).expect_err("over max_points");
        assert!(matches!(e, ReadError::TooManyPoints { .. }), "{}: {e}", k.name);
    }
}

#[test]
fn a_channel_is_chosen_by_name_or_index_and_a_wrong_one_lists_the_channels() {
    for (k, bytes) in files().into_iter().filter(|(k, _)| k.format == Format::OPD) {
        let read = |channel: Channel| {
            let options = ReadOptions {
                channel: Some(channel),
                ..ReadOptions::default()
            };
            read_bytes(&bytes, k.name, &options)
        };
        let by_name = read(Channel::Name("raw".into())).unwrap();
        let by_index = read(Channel::Index(0)).unwrap();
        assert!(same(&by_name, &by_index));
        assert_eq!(by_name.metadata().channel.as_deref(), Some("Raw"));
        let e = read(Channel::Index(1)).expect_err("one raster");
        assert!(e.to_string().contains("0 Raw"), "{e}");
    }
}

/// The same grid and heights (NaN where the other is NaN).
fn same(a: &Topography, b: &Topography) -> bool {
    (a.nx(), a.ny(), a.dx(), a.dy()) == (b.nx(), b.ny(), b.dx(), b.dy())
        && a.heights()
            .iter()
            .zip(b.heights())
            .all(|(x, y)| x.to_bits() == y.to_bits())
}

/// The surface a damaged file gives, if any, keeps the readers' invariant.
fn check(t: &Topography) {
    assert_eq!(t.nx() * t.ny(), t.heights().len());
    assert!(t.dx().is_finite() && t.dx() > 0.0);
    assert!(t.heights().iter().all(|h| !h.is_infinite()));
}

#[test]
fn every_truncation_is_an_error_or_the_whole_surface() {
    for (k, bytes) in files() {
        let whole = read_bytes(&bytes, k.name, &ReadOptions::default()).unwrap();
        // Every length through the headers, then 200 spread over the rest.
        let n = bytes.len();
        let lengths = (0..1200.min(n)).chain((0..200).map(|i| 1200 + i * (n - 1200) / 200));
        let mut refused = 0;
        for cut in lengths {
            match read_bytes(&bytes[..cut], k.name, &ReadOptions::default()) {
                Err(e) => {
                    assert!(e.to_string().contains(k.name), "{e}");
                    refused += 1;
                }
                // Past the heights (a trailing image the reader skips).
                Ok(t) => assert!(same(&t, &whole), "{} cut at {cut} of {n} bytes", k.name),
            }
        }
        assert!(refused >= 1200.min(n), "{}: only {refused} cuts refused", k.name);
    }
}

#[test]
fn byte_flips_give_an_error_or_a_surface_never_a_panic() {
    let mut rng = ChaCha8Rng::seed_from_u64(39);
    for (k, bytes) in files() {
        for trial in 0..300 {
            let mut damaged = bytes.clone();
            for _ in 0..1 + trial % 4 {
                // Mostly in the headers, where the sizes and offsets are.
                let at = if rng.gen_bool(0.8) {
                    rng.gen_range(0..1300.min(damaged.len()))
                } else {
                    rng.gen_range(0..damaged.len())
                };
                damaged[at] ^= 1 << rng.gen_range(0..8);
            }
            let options = ReadOptions {
                max_points: 1 << 22,
                ..ReadOptions::default()
            };
            match read_bytes(&damaged, k.name, &options) {
                Ok(t) => check(&t),
                Err(e) => assert!(e.to_string().contains(k.name), "{e}"),
            }
        }
    }
}
