//! The table file format, versions 1 and 2.
//!
//! ```text
//! offset  size  content
//! 0       8     magic  b"KEFRICTB"
//! 8       4     format version, u32 little-endian (1 or 2)
//! 12      8     payload length N, u64 little-endian
//! 20      N     payload: a `Payload`, postcard-encoded; in version 2
//!               followed by a `DistributionSpec`, postcard-encoded
//! 20+N    4     CRC-32 (IEEE) of bytes 0 .. 20+N, u32 little-endian
//! ```
//!
//! Version 2 adds the asperity heights' distribution (MODEL.md §9). A
//! table for Gaussian heights is written as version 1, byte for byte as
//! before (so the default table is unchanged and older readers still read
//! it); a version-1 file is a Gaussian table.
//!
//! Nothing may follow the checksum. postcard's wire format is stable and
//! specified (floats little-endian IEEE 754, lengths as varints); bincode is
//! not used because it is unmaintained. Decoding checks, in order: the
//! magic, the version, the length, the checksum, the payload's structure,
//! and then every value; any failure is a [`TableError`] naming the field
//! and the bound, never a panic.
//!
//! # What a table that loads guarantees
//!
//! A file is untrusted input: its checksum proves only that it was not
//! damaged, not that its author meant well. The loader (`Table::from_payload`
//! and `Layout::new`) proves what the lookup kernels assume:
//!
//! 1. **Axes.** Each has 5 to 2^20 nodes, a finite first coordinate, a
//!    finite step > 0 of at least [`MIN_RELATIVE_STEP`](super::layout::MIN_RELATIVE_STEP)
//!    times max(1, its largest |node coordinate|) (so a query's cell
//!    coordinate is accurate to about 1e-4 of a cell), the maps ln ψ, √θ,
//!    ln F*, and a finite domain inside its nodes.
//! 2. **Sizes.** Both coefficient arrays hold exactly (nψ+2)(nθ+2)(nF+2)
//!    values, at most 2^28. With the cell index clamped to
//!    `0..=last_cell` on every axis (in every kernel), every 4×4×4 block
//!    lies inside them.
//! 3. **Coefficients.** ln μ coefficients are finite and within
//!    ±[`LN_MU_MAX`], the range of the portable kernel's exponential (the
//!    fast f32 kernel runs only within ±[`FAST_LN_MU_MAX`], the range of
//!    its own); h* coefficients within ±[`H_STAR_MAX`]. The B-spline weights are convex (up to the rounding
//!    of the cell offset), so a blend is bounded by its coefficients:
//!    μ is finite and > 0.
//! 4. **Slopes.** The bound on |∂μ/∂F*| that the coefficients, the F*
//!    step and the lowest F* imply stays below e^[`LN_SLOPE_MAX`]: slopes
//!    are finite.
//! 5. **Records.** The model constants are valid (`Params::validate`), the
//!    accuracy record and the h* range are finite, the generator string is
//!    at most [`GENERATOR_MAX`] bytes (it is data: front ends print it
//!    escaped).
//!
//! So every in-domain query of a table that loads has a finite μ > 0 and a
//! finite slope, from every kernel; `src/table/tests.rs` and the fuzz
//! targets in `fuzz/` check each point with crafted files.

use crate::distribution::{Family, HeightDistribution};
use crate::params::{Constants, Fit, ModelKind};
use serde::de::{self, EnumAccess, VariantAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// The first eight bytes of every table file.
pub const MAGIC: [u8; 8] = *b"KEFRICTB";
/// The newest format version this crate writes and reads (tables for
/// non-Gaussian heights).
pub const VERSION: u32 = 2;
/// The version of tables for Gaussian heights (and of every older table).
pub const VERSION_GAUSSIAN: u32 = 1;
const HEADER: usize = 20;

/// The largest |ln μ| coefficient a table may have, in either precision:
/// the portable kernel's exponential is accurate for |x| < 708, and a
/// blend exceeds its largest coefficient by at most 1e-3 of it. (The fast
/// f32 kernel runs only on tables whose coefficients stay within
/// ±[`FAST_LN_MU_MAX`].)
pub const LN_MU_MAX: f64 = 700.0;
/// The largest |ln μ| coefficient of a table the fast f32 kernel looks up:
/// its exponential gives a normal, finite f32 for |x| < 87.3. (Small
/// tables reach −86 at their ghost nodes: they run the portable kernel.)
pub const FAST_LN_MU_MAX: f64 = 86.0;
/// The largest |h*| coefficient (separations are a few σ).
pub const H_STAR_MAX: f64 = 1e6;
/// The largest ln of the bound on |∂μ/∂F*| a table may imply (f64 reaches
/// e^709.8).
pub const LN_SLOPE_MAX: f64 = 690.0;
/// The longest generator string, in bytes.
pub const GENERATOR_MAX: usize = 4096;
/// The largest table file a program reads (1 GiB): larger files are
/// refused before they are read in full.
pub const FILE_MAX: u64 = 1 << 30;

/// Why a table file was rejected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum TableError {
    /// Fewer bytes than a header and a checksum.
    #[error("not a ke-friction table: {len} bytes is too short (at least 24)")]
    TooShort {
        /// The length found.
        len: usize,
    },
    /// The file does not start with `KEFRICTB`.
    #[error("not a ke-friction table: wrong magic bytes")]
    WrongMagic,
    /// A format version this crate cannot read.
    #[error("unsupported table format version {found} (this build reads versions {VERSION_GAUSSIAN} and {VERSION})")]
    UnsupportedVersion {
        /// The version in the file.
        found: u32,
    },
    /// The length field disagrees with the file's size.
    #[error("table is truncated or has trailing bytes: header says {expected} bytes, file has {found}")]
    Length {
        /// Size implied by the header.
        expected: u64,
        /// Actual size.
        found: u64,
    },
    /// The stored checksum does not match the contents.
    #[error("table checksum mismatch (stored {stored:#010x}, computed {computed:#010x}): the file is corrupted")]
    Checksum {
        /// Checksum in the file.
        stored: u32,
        /// Checksum of the contents.
        computed: u32,
    },
    /// The payload does not decode.
    #[error("table payload does not decode: {0}")]
    Payload(String),
    /// The payload decodes but its contents are inconsistent.
    #[error("table is inconsistent: {0}")]
    Inconsistent(String),
    /// The file is larger than [`FILE_MAX`] (refused before it is read).
    #[error("table file is {size} bytes, more than the {max} bytes a table may have")]
    TooLarge {
        /// The size the header declares (or the file has).
        size: u64,
        /// [`FILE_MAX`].
        max: u64,
    },
    /// A table file that was read but is refused: the path and why (any of
    /// the other variants but `Io`). [`Table::load`](crate::Table::load)
    /// and [`Table::read_file`](crate::Table::read_file) name the file
    /// this way, once.
    #[error("{path}: {error}")]
    File {
        /// The path.
        path: String,
        /// Why it is refused.
        error: Box<TableError>,
    },
    /// The file could not be read.
    #[error("cannot read table {path}: {message}")]
    Io {
        /// The path.
        path: String,
        /// The system's message.
        message: String,
    },
}

impl TableError {
    /// This error as the error of the file at `path` (once: an error that
    /// names its file already is returned as it is), for a caller that read
    /// the file's bytes itself and decoded them with
    /// [`Table::from_bytes`](crate::Table::from_bytes).
    pub fn in_file(self, path: &std::path::Path) -> TableError {
        match self {
            e @ (TableError::Io { .. } | TableError::File { .. }) => e,
            e => TableError::File {
                path: path.display().to_string(),
                error: Box::new(e),
            },
        }
    }

    /// The error itself, without the file it came from.
    pub fn cause(&self) -> &TableError {
        match self {
            TableError::File { error, .. } => error.cause(),
            e => e,
        }
    }
}

/// One axis of the lookup grid, as stored.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct AxisSpec {
    /// Coordinate map, by [`crate::spline::Scale::code`].
    pub scale: u8,
    /// Coordinate of the first node (a ghost node, if any, lies below the domain).
    pub first: f64,
    /// Coordinate spacing.
    pub step: f64,
    /// Number of nodes, ghost nodes included.
    pub nodes: u32,
    /// The domain on this axis, in physical units: lookups outside are errors.
    pub lo: f64,
    /// Upper end of the domain.
    pub hi: f64,
}

/// Stored coefficients, in single or double precision. On the wire: the
/// code [`Coefs::F32_CODE`] or [`Coefs::F64_CODE`] (a varint), then the
/// array; the codes are explicit, not the variants' order.
#[derive(Debug, Clone, PartialEq)]
pub enum Coefs {
    /// Single precision (relative rounding 6e-8).
    F32(Vec<f32>),
    /// Double precision.
    F64(Vec<f64>),
}

impl Coefs {
    /// The code of f32 coefficients.
    pub const F32_CODE: u32 = 0;
    /// The code of f64 coefficients.
    pub const F64_CODE: u32 = 1;

    /// Number of coefficients.
    pub fn len(&self) -> usize {
        match self {
            Coefs::F32(v) => v.len(),
            Coefs::F64(v) => v.len(),
        }
    }

    /// As doubles.
    pub fn to_f64(&self) -> Vec<f64> {
        match self {
            Coefs::F32(v) => v.iter().map(|&x| x as f64).collect(),
            Coefs::F64(v) => v.clone(),
        }
    }
}

impl Serialize for Coefs {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Coefs::F32(v) => s.serialize_newtype_variant("Coefs", Coefs::F32_CODE, "F32", v),
            Coefs::F64(v) => s.serialize_newtype_variant("Coefs", Coefs::F64_CODE, "F64", v),
        }
    }
}

impl<'de> Deserialize<'de> for Coefs {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Coefs, D::Error> {
        struct Codes;
        impl<'de> Visitor<'de> for Codes {
            type Value = Coefs;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("coefficients with precision code 0 (f32) or 1 (f64)")
            }
            fn visit_enum<A: EnumAccess<'de>>(self, data: A) -> Result<Coefs, A::Error> {
                let (code, array): (u32, _) = data.variant()?;
                match code {
                    Coefs::F32_CODE => array.newtype_variant().map(Coefs::F32),
                    Coefs::F64_CODE => array.newtype_variant().map(Coefs::F64),
                    other => Err(de::Error::custom(format_args!("unknown precision code {other}"))),
                }
            }
        }
        d.deserialize_enum("Coefs", &["F32", "F64"], Codes)
    }
}

/// Model constants the table was built with.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ModelSpec {
    /// β.
    pub beta: f64,
    /// ν.
    pub nu: f64,
    /// ε*.
    pub eps_star: f64,
    /// 0 = consistent, 1 = as printed.
    pub fit: u8,
    /// 0 = Kogut–Etsion, 1 = CEB-type.
    pub kind: u8,
}

impl ModelSpec {
    /// The stored form of a set of model constants.
    #[cfg(any(feature = "builder", test))]
    pub fn of(c: &Constants) -> ModelSpec {
        ModelSpec {
            beta: c.beta,
            nu: c.nu,
            eps_star: c.eps_star,
            fit: match c.fit {
                Fit::Consistent => 0,
                Fit::AsPrinted => 1,
            },
            kind: c.kind.law().code,
        }
    }

    /// The constants these values describe, or why the codes are invalid
    /// (the values themselves are checked by `Constants::validate`).
    pub fn constants(&self) -> Result<Constants, String> {
        let fit = match self.fit {
            0 => Fit::Consistent,
            1 => Fit::AsPrinted,
            f => return Err(format!("unknown fit code {f}")),
        };
        let kind = match ModelKind::from_code(self.kind) {
            Some(kind) => kind,
            None => return Err(format!("unknown model code {}", self.kind)),
        };
        Ok(Constants {
            beta: self.beta,
            nu: self.nu,
            eps_star: self.eps_star,
            fit,
            kind,
            distribution: crate::HeightDistribution::GAUSSIAN,
        })
    }
}

/// The asperity heights' distribution a table was built for (format
/// version 2; version 1 is Gaussian).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct DistributionSpec {
    /// The family's [`code`](Family::code): 0 = Gaussian, 1 = Pearson, 2 = Weibull.
    pub family: u8,
    /// Skewness ([`HeightDistribution::stored`]).
    pub skewness: f64,
    /// Kurtosis, not excess (0 for Weibull: [`HeightDistribution::stored`]).
    pub kurtosis: f64,
}

impl Default for DistributionSpec {
    fn default() -> DistributionSpec {
        DistributionSpec {
            family: Family::Gaussian.code(),
            skewness: 0.0,
            kurtosis: 3.0,
        }
    }
}

impl DistributionSpec {
    /// The stored form of a distribution; `None` for an empirical density,
    /// which tables do not hold.
    #[cfg(any(feature = "builder", test))]
    pub fn of(d: &HeightDistribution) -> Option<DistributionSpec> {
        if d.is_gaussian() {
            return Some(DistributionSpec::default());
        }
        let [skewness, kurtosis] = d.stored()?;
        Some(DistributionSpec {
            family: d.family_kind().code(),
            skewness,
            kurtosis,
        })
    }

    /// The distribution these values describe, or why the code is invalid
    /// (the values are checked by `HeightDistribution::validate`).
    pub fn distribution(&self) -> Result<HeightDistribution, String> {
        Family::from_code(self.family)
            .and_then(|f| HeightDistribution::of_family(f, self.skewness, self.kurtosis))
            .ok_or_else(|| format!("unknown distribution code {}", self.family))
    }

    /// Whether this is the Gaussian (a version-1 table).
    pub fn is_gaussian(&self) -> bool {
        self.family == Family::Gaussian.code()
    }
}

/// The build options that shaped the table (for provenance and rebuilds).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BuildSpec {
    /// Nodes across the domain on the ψ, θ, F* axes (ghost nodes excluded).
    pub nodes: [u32; 3],
    /// Ghost nodes beyond each end of the ψ and F* axes.
    pub ghosts: u32,
    /// The (ψ, θ, h*) integration grid: h* from `h_lo` to `h_hi` in `h_nodes` points.
    pub h_lo: f64,
    /// Upper end of h*.
    pub h_hi: f64,
    /// Number of h* points.
    pub h_nodes: u32,
    /// Random points checked against direct integration.
    pub samples: u32,
    /// Seed of those points.
    pub seed: u64,
    /// The producing crate and version.
    pub generator: String,
}

/// Accuracy of μ measured against direct integration at build time.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Accuracy {
    /// The tolerance the table promises (max relative error of μ).
    pub tolerance: f64,
    /// Measured maximum relative error of μ.
    pub max_rel: f64,
    /// Measured 99th percentile.
    pub p99_rel: f64,
    /// Points measured.
    pub samples: u32,
    /// Where the maximum occurred: (ψ, θ, F*).
    pub worst: [f64; 3],
}

impl Accuracy {
    /// The stored form of a measured accuracy and the tolerance it met.
    #[cfg(any(feature = "builder", test))]
    pub fn record(tolerance: f64, measured: &super::Accuracy) -> Accuracy {
        Accuracy {
            tolerance,
            max_rel: measured.max_rel,
            p99_rel: measured.p99_rel,
            samples: measured.samples as u32,
            worst: measured.worst,
        }
    }

    /// The record of a draft table, before it is measured: its tolerance,
    /// and zeros (the builder measures the draft, then records the result).
    #[cfg(any(feature = "builder", test))]
    pub fn unmeasured(tolerance: f64) -> Accuracy {
        Accuracy {
            tolerance,
            max_rel: 0.0,
            p99_rel: 0.0,
            samples: 0,
            worst: [0.0; 3],
        }
    }

    /// The measured accuracy, as the public API reports it.
    pub fn measured(&self) -> super::Accuracy {
        super::Accuracy {
            max_rel: self.max_rel,
            p99_rel: self.p99_rel,
            samples: self.samples as usize,
            worst: self.worst,
        }
    }
}

impl BuildSpec {
    /// The build options, as the public API reports them.
    pub fn record(&self) -> super::BuildRecord {
        super::BuildRecord {
            nodes: self.nodes.map(|n| n as usize),
            ghosts: self.ghosts as usize,
            h_star: (self.h_lo, self.h_hi, self.h_nodes as usize),
            samples: self.samples as usize,
            seed: self.seed,
            generator: escape_text(&self.generator),
        }
    }
}

/// Text from a file made safe to print: control characters (C0, DEL, C1)
/// and the invisible and bidirectional format characters a file could
/// use to forge or hide output are written as `\u{…}`, and a backslash as
/// `\\` (so the escaped form is unambiguous). Printable text, ASCII or
/// not, is unchanged.
pub fn escape_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        let hidden =
            matches!(c, '\u{200b}'..='\u{200f}' | '\u{202a}'..='\u{202e}' | '\u{2060}'..='\u{2069}' | '\u{feff}');
        if c == '\\' {
            out.push_str("\\\\");
        } else if c.is_control() || hidden {
            out.push_str(&format!("\\u{{{:x}}}", c as u32));
        } else {
            out.push(c);
        }
    }
    out
}

/// Everything in a table file between the header and the checksum.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Payload {
    /// Model constants.
    pub model: ModelSpec,
    /// ψ, θ, F* axes.
    pub axes: [AxisSpec; 3],
    /// Spline coefficients of ln μ, shape (ψ+2, θ+2, F*+2), F* fastest.
    pub ln_mu: Coefs,
    /// Spline coefficients of h*, same shape.
    pub h_star: Coefs,
    /// Build options.
    pub build: BuildSpec,
    /// Measured accuracy.
    pub accuracy: Accuracy,
    /// The heights' distribution: stored after the payload, in version 2 only.
    #[serde(skip)]
    pub distribution: DistributionSpec,
}

/// Serialises a payload into a complete table file (the builder's, and
/// the tests' forgeries).
#[cfg(any(feature = "builder", test))]
pub fn encode(payload: &Payload) -> Vec<u8> {
    let mut body = postcard::to_allocvec(payload).expect("postcard serialises plain data");
    let version = if payload.distribution.is_gaussian() {
        VERSION_GAUSSIAN
    } else {
        body.extend(postcard::to_allocvec(&payload.distribution).expect("postcard serialises plain data"));
        VERSION
    };
    let mut out = Vec::with_capacity(HEADER + body.len() + 4);
    out.extend_from_slice(&MAGIC);
    out.extend_from_slice(&version.to_le_bytes());
    out.extend_from_slice(&(body.len() as u64).to_le_bytes());
    out.extend_from_slice(&body);
    let crc = crc32fast::hash(&out);
    out.extend_from_slice(&crc.to_le_bytes());
    out
}

/// Reads a table file from `r`, bounded: the header first (so that a file
/// that is not a table, even an endless one such as `/dev/urandom`, is
/// refused after 20 bytes), then exactly the length it declares, at most
/// [`FILE_MAX`] bytes in all, and one byte more to detect trailing data.
/// Read errors are `io`'s.
pub fn read(r: &mut impl std::io::Read, io: impl Fn(std::io::Error) -> TableError) -> Result<Vec<u8>, TableError> {
    use std::io::Read;
    let mut bytes = Vec::with_capacity(HEADER);
    r.by_ref().take(HEADER as u64).read_to_end(&mut bytes).map_err(&io)?;
    if bytes.len() < HEADER {
        // Too short, or the wrong magic: `decode` says which.
        return decode(&bytes).map(|_| bytes);
    }
    let len = header(&bytes)?;
    let total = (HEADER as u64 + 4).saturating_add(len);
    if total > FILE_MAX {
        return Err(TableError::TooLarge {
            size: total,
            max: FILE_MAX,
        });
    }
    // Grows as data arrives: a false length costs no memory up front.
    bytes.reserve((total as usize - HEADER).min(1 << 26));
    r.take(total - HEADER as u64 + 1).read_to_end(&mut bytes).map_err(&io)?;
    Ok(bytes)
}

/// Checks the magic and the version of a 20-byte header; returns the
/// payload length it declares.
fn header(bytes: &[u8]) -> Result<u64, TableError> {
    if bytes[..8] != MAGIC {
        return Err(TableError::WrongMagic);
    }
    let version = u32::from_le_bytes(bytes[8..12].try_into().expect("4 bytes"));
    if version != VERSION && version != VERSION_GAUSSIAN {
        return Err(TableError::UnsupportedVersion { found: version });
    }
    Ok(u64::from_le_bytes(bytes[12..20].try_into().expect("8 bytes")))
}

/// Checks the framing and decodes the payload (values are checked by the caller).
pub fn decode(bytes: &[u8]) -> Result<Payload, TableError> {
    if bytes.len() < HEADER + 4 {
        if bytes.len() >= 8 && bytes[..8] != MAGIC {
            return Err(TableError::WrongMagic);
        }
        return Err(TableError::TooShort { len: bytes.len() });
    }
    let len = header(bytes)?;
    let expected = (HEADER as u64 + 4).saturating_add(len);
    if expected != bytes.len() as u64 {
        return Err(TableError::Length {
            expected,
            found: bytes.len() as u64,
        });
    }
    let end = bytes.len() - 4;
    let stored = u32::from_le_bytes(bytes[end..].try_into().expect("4 bytes"));
    let computed = crc32fast::hash(&bytes[..end]);
    if stored != computed {
        return Err(TableError::Checksum { stored, computed });
    }
    let (mut payload, mut rest) =
        postcard::take_from_bytes::<Payload>(&bytes[HEADER..end]).map_err(|e| TableError::Payload(e.to_string()))?;
    if bytes[8..12] == VERSION.to_le_bytes() {
        let (spec, after) = postcard::take_from_bytes::<DistributionSpec>(rest)
            .map_err(|e| TableError::Payload(format!("distribution: {e}")))?;
        if spec.is_gaussian() {
            return Err(TableError::Payload(
                "a version-2 table for Gaussian heights (they are version 1)".into(),
            ));
        }
        payload.distribution = spec;
        rest = after;
    }
    if !rest.is_empty() {
        return Err(TableError::Payload(format!(
            "{} unread bytes after the payload",
            rest.len()
        )));
    }
    Ok(payload)
}

impl crate::Classify for TableError {
    /// [`crate::ErrorKind::Io`] for a file that cannot be read, else
    /// [`crate::ErrorKind::Table`].
    fn kind(&self) -> crate::ErrorKind {
        match self {
            TableError::Io { .. } => crate::ErrorKind::Io,
            TableError::File { error, .. } => error.kind(),
            _ => crate::ErrorKind::Table,
        }
    }
}
