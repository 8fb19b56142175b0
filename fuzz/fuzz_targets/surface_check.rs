//! The invariant every surface that a reader returns must keep
//! (src/topography/read/): `nx·ny` heights, at most `max_points` of them,
//! finite intervals > 0, no infinite height (missing points are NaN). A bad
//! file is an error naming the file, never a panic (libFuzzer reports one as
//! a crash) and never a read outside a buffer (AddressSanitizer reports
//! one). Shared by the `surface_*` targets; the options are the fuzzer's
//! too ([`OptionsSpec`]).

use arbitrary::Arbitrary;
use ke_friction::topography::{read_bytes, Format, ReadOptions, Topography};

/// A sampling interval as the fuzzer picks it: none, a sane one, or any
/// bits (NaN, 0, negative, infinite: the reader must refuse those).
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Interval {
    None,
    /// 10^(−6 + e/32) metres: 1.0e−10 … 1.0e−2.
    Exp(i8),
    Raw(f64),
}

impl Interval {
    fn get(self) -> Option<f64> {
        match self {
            Interval::None => None,
            Interval::Exp(e) => Some(10f64.powf(-6.0 + e as f64 / 32.0)),
            Interval::Raw(v) => Some(v),
        }
    }
}

/// A unit (`z_unit`, `xy_unit`): 1, a power of ten, or any bits.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Unit {
    One,
    /// 10^(e/8): 1e−16 … 1e16.
    Exp(i8),
    Raw(f64),
}

impl Unit {
    fn get(self) -> f64 {
        match self {
            Unit::One => 1.0,
            Unit::Exp(e) => 10f64.powf(e as f64 / 8.0),
            Unit::Raw(v) => v,
        }
    }
}

/// The read options: the brief's fixed ones (1 µm intervals, 2²⁰ points,
/// 16 MiB), or the fuzzer's within bounds that keep a run's memory small
/// (at most 2²⁰ points and 16 MiB).
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum OptionsSpec {
    Fixed,
    Chosen {
        dx: Interval,
        dy: Interval,
        z_unit: Unit,
        xy_unit: Unit,
        /// max_points = 2^(k mod 21).
        max_points_log2: u8,
        /// max_bytes = 2^(k mod 25).
        max_bytes_log2: u8,
    },
}

impl OptionsSpec {
    /// The options, with `format` (`None`: by the file's extension).
    pub fn options(self, format: Option<Format>) -> ReadOptions {
        match self {
            OptionsSpec::Fixed => ReadOptions {
                dx: Some(1e-6),
                dy: Some(1e-6),
                max_points: 1 << 20,
                max_bytes: 1 << 24,
                format,
                ..Default::default()
            },
            OptionsSpec::Chosen {
                dx,
                dy,
                z_unit,
                xy_unit,
                max_points_log2,
                max_bytes_log2,
            } => ReadOptions {
                dx: dx.get(),
                dy: dy.get(),
                z_unit: z_unit.get(),
                xy_unit: xy_unit.get(),
                format,
                max_points: 1 << (max_points_log2 % 21),
                max_bytes: 1 << (max_bytes_log2 % 25),
                channel: None,
            },
        }
    }
}

/// Reads `bytes` as the file `name` and checks the result: a surface that
/// keeps the invariant ([`check`]), or an error that names the file and
/// prints.
pub fn read(bytes: &[u8], name: &str, options: &ReadOptions) -> Option<Topography> {
    match read_bytes(bytes, name, options) {
        Ok(t) => {
            check(&t, options);
            Some(t)
        }
        Err(e) => {
            assert_eq!(e.path().to_str(), Some(name), "the error names another file: {e}");
            assert!(!e.to_string().is_empty());
            None
        }
    }
}

/// The invariant of a surface read with `options`.
pub fn check(t: &Topography, options: &ReadOptions) {
    let (nx, ny) = (t.nx(), t.ny());
    let n = nx.checked_mul(ny).expect("nx * ny overflows");
    assert!(n > 0, "an empty surface ({nx} x {ny})");
    assert_eq!(
        n,
        t.heights().len(),
        "{nx} x {ny} points, {} heights",
        t.heights().len()
    );
    assert!(
        n as u64 <= options.max_points,
        "{nx} x {ny} = {n} points, over max_points = {}",
        options.max_points
    );
    assert!(t.dx().is_finite() && t.dx() > 0.0, "dx = {}", t.dx());
    match t.dy() {
        Some(dy) => assert!(dy.is_finite() && dy > 0.0, "dy = {dy}"),
        None => assert_eq!(ny, 1, "a profile of {ny} rows"),
    }
    if let Some(i) = t.heights().iter().position(|h| h.is_infinite()) {
        panic!("height {i} of {nx} x {ny} is {}", t.heights()[i]);
    }
}
