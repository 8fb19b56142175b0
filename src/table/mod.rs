//! Precomputed tables of μ(ψ, θ, F*) and nanosecond lookups.
//!
//! A [`Table`] holds tensor cubic B-spline coefficients of ln μ and of h*
//! over (ln ψ, √θ, ln F*) (see `src/spline.rs`). A lookup blends 4×4×4
//! coefficients: no allocation, no lock, no branch on the data. The
//! interpolant is C², so μ and ∂μ/∂F* are continuous everywhere.
//!
//! Two kernels evaluate it. The portable one works in f64 and gives the
//! same bits on every machine ([`Table::mu_portable`]). On x86-64 CPUs
//! with AVX2 and FMA, tables stored in f32 (the default) are looked up by
//! a kernel in f32 arithmetic, eight queries to a vector in a batch; its
//! rounding moves μ by at most [`FAST_KERNEL_MAX_REL`] relative ([`Table::fast_kernel`]
//! says which kernel runs).
//!
//! The file format (`format.rs`) is private: what a file records reaches
//! users as a [`TableInfo`].

// The fast kernel on x86-64, and a stand-in that is never made: both
// implement `FastKernel`, and the stand-in is compiled on every target, so
// a method it lacks is a compile error on x86-64 too. `--cfg
// ke_friction_portable` selects the stand-in on x86-64 (the portable
// kernel then runs everywhere, as on other targets).
#[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
mod avx2;
mod batch;
mod error;
mod fastmath;
pub(crate) mod format;
mod layout;
mod no_avx2;
mod portable;

/// The fast kernel this build uses: AVX2 on x86-64, else the stand-in.
#[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
use avx2::Kernel as Fast;
#[cfg(not(all(target_arch = "x86_64", not(ke_friction_portable))))]
use no_avx2::Kernel as Fast;

/// What a fast lookup kernel offers the table (see `avx2.rs`); the
/// stand-in `no_avx2.rs` implements it too.
trait FastKernel: Sized + Clone {
    /// The kernel for a table's layout and f32 coefficients, if this CPU
    /// and the table suit it.
    fn new(layout: &Layout, coefs: &[f32]) -> Option<Self>;
    /// One lookup: μ (NaN outside the domain) and, if `SLOPE`, d ln μ/d(cell
    /// coordinate of F*).
    fn eval<const SLOPE: bool>(&self, psi: f64, theta: f64, f_star: f64) -> (f64, f64);
    /// Readies the kernel for `n` queries in smaller batches.
    fn prepare(&self, n: usize);
    /// Many lookups; the index of the first query whose μ is NaN.
    fn batch(&self, psi: &[f64], theta: &[f64], f_star: &[f64], out: BatchOutput) -> Option<usize>;
}

#[cfg(test)]
mod tests;

use crate::num::Shortest;
use crate::params::{Constants, Params};
use crate::spline::Axis;
pub(crate) use error::scatter_pairs;
pub use error::{ConstantsMismatch, LookupError, OnError};
use format::{Coefs, Payload};
pub use format::{TableError, FILE_MAX};

/// How far the fast f32 kernel's μ may lie from the exact f64 interpolant
/// ([`Table::mu_portable`]), relative: f32 rounding of the blend of ln μ
/// (measured at most 2.5e-6 over the default table; `kefric lookup
/// --exact` runs the exact one). Far below a table's own tolerance.
pub const FAST_KERNEL_MAX_REL: f64 = 3e-6;
use batch::BatchOutput;
use layout::Layout;

/// What a table covers: the ranges of its three arguments and the model
/// constants it was built with (the same at every point).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Domain {
    /// Range of ψ.
    pub psi: (f64, f64),
    /// Range of θ.
    pub theta: (f64, f64),
    /// Range of F*.
    pub f_star: (f64, f64),
    /// The model constants (β, ν, ε*, fit, model), serialised flat.
    #[serde(flatten)]
    pub constants: Constants,
}

impl Domain {
    /// The ranges of ψ, θ and F*, in that order.
    pub fn ranges(&self) -> [(f64, f64); 3] {
        [self.psi, self.theta, self.f_star]
    }

    /// The model's parameters at (ψ, θ), with the table's constants (not
    /// validated: ψ or θ may lie outside the table).
    pub fn params(&self, psi: f64, theta: f64) -> Params {
        self.constants.unchecked_at(psi, theta)
    }
}

/// Stored precision of a table's coefficients (serialised by its name).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Precision {
    /// 4 bytes a coefficient; enough for tolerances down to ~1e-6.
    F32,
    /// 8 bytes a coefficient.
    F64,
}

impl serde::Serialize for Precision {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl Precision {
    /// The name users type and read: `"f32"` or `"f64"`.
    pub const fn name(self) -> &'static str {
        match self {
            Precision::F32 => "f32",
            Precision::F64 => "f64",
        }
    }
}

/// The accuracy of μ measured against direct integration.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Accuracy {
    /// The maximum relative error of μ.
    pub max_rel: f64,
    /// Its 99th percentile.
    pub p99_rel: f64,
    /// Points measured.
    pub samples: usize,
    /// Where the maximum occurred: (ψ, θ, F*).
    pub worst: [f64; 3],
}

/// The options a table was built with, as its file records them.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct BuildRecord {
    /// Nodes across the domain on the ψ, θ, F* axes (ghost nodes excluded).
    pub nodes: [usize; 3],
    /// Ghost nodes beyond each end of the ψ and F* axes (and above θ's).
    pub ghosts: usize,
    /// The integration grid's h* axis: from, to, points.
    pub h_star: (f64, f64, usize),
    /// Points checked against direct integration at build time.
    pub samples: usize,
    /// Seed of those points.
    pub seed: u64,
    /// The crate and version that built the table, as the file says: text
    /// from a file, so control and bidirectional-format characters come
    /// escaped (`\u{1b}`) and a backslash doubled, safe to print.
    pub generator: String,
}

/// Everything a table file says about itself: the one record of a table
/// that every front end shows under these names (`kefric info --json`,
/// Python's `Table.info`, the `metadata` of a NumPy export). Serialised
/// with the domain's fields at the top level:
/// `psi`, `theta`, `f_star` (ranges), `beta`, `nu`, `eps_star`, `fit`,
/// `model`, `tolerance`, `accuracy` {`max_rel`, `p99_rel`, `samples`,
/// `worst`}, `build` {`nodes`, `ghosts`, `h_star`, `samples`, `seed`,
/// `generator`}, `precision`, `format_version`, `bytes`, `crc32`.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct TableInfo {
    /// The arguments' ranges and the model constants.
    #[serde(flatten)]
    pub domain: Domain,
    /// The maximum relative error of μ the table promises (its build
    /// failed unless the measured error, plus the fast kernel's rounding
    /// where it ran, stayed within it).
    pub tolerance: f64,
    /// The error of μ measured when the table was built (the exact f64
    /// interpolant's, the same on every machine).
    pub accuracy: Accuracy,
    /// The build options.
    pub build: BuildRecord,
    /// Stored precision of the coefficients.
    pub precision: Precision,
    /// The file format's version.
    pub format_version: u32,
    /// The file's size in bytes.
    pub bytes: u64,
    /// The file's CRC-32 (its last four bytes).
    pub crc32: u32,
}

/// A loaded table: immutable, `Send + Sync`, shareable across threads.
#[derive(Clone)]
pub struct Table {
    layout: Layout,
    info: TableInfo,
    /// The AVX2 kernel, where the CPU and the table suit it.
    avx2: Option<Fast>,
    /// Spline coefficients of ln μ and of h*, shape (nψ, nθ, nF), F* fastest.
    ln_mu: Vec<f64>,
    h_star: Vec<f64>,
}

/// What the table holds and which kernel runs (not its coefficients).
impl std::fmt::Debug for Table {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Table")
            .field("info", &self.info)
            .field("axes", &self.layout.axes)
            .field("fast_kernel", &self.fast_kernel())
            .finish_non_exhaustive()
    }
}

/// The default table, committed in `tables/` and compiled in.
static DEFAULT_TABLE: &[u8] = include_bytes!("../../tables/default.kft");

impl Table {
    /// The default table compiled into the library (decoded on first use).
    ///
    /// ```
    /// let table = ke_friction::Table::embedded();
    /// let mu = table.mu(1.0, 0.001, 0.01).unwrap();
    /// assert!((mu / 0.52521087083 - 1.0).abs() < 1e-4); // MODEL.md §7
    /// ```
    pub fn embedded() -> &'static Table {
        static TABLE: std::sync::OnceLock<Table> = std::sync::OnceLock::new();
        TABLE.get_or_init(|| {
            Table::from_bytes(DEFAULT_TABLE).expect("the embedded default table is valid (checked by the test suite)")
        })
    }

    /// The bytes of the embedded default table.
    pub fn embedded_bytes() -> &'static [u8] {
        DEFAULT_TABLE
    }

    /// Decodes and checks a table file's contents.
    pub fn from_bytes(bytes: &[u8]) -> Result<Table, TableError> {
        let mut table = Table::from_payload(format::decode(bytes)?)?;
        // `decode` checked the length and the CRC in the last four bytes.
        let crc = &bytes[bytes.len() - 4..];
        table.info.bytes = bytes.len() as u64;
        table.info.crc32 = u32::from_le_bytes([crc[0], crc[1], crc[2], crc[3]]);
        Ok(table)
    }

    /// Reads and checks a table file (see [`Table::read_file`]).
    pub fn load(path: impl AsRef<std::path::Path>) -> Result<Table, TableError> {
        let path = path.as_ref();
        Table::from_bytes(&Table::read_file(path)?).map_err(|e| e.in_file(path))
    }

    /// The bytes of a table file, read with bounds: a file that does not
    /// start like a table is refused after its first 20 bytes, and no more
    /// is read than the length its header declares (at most 1 GiB, see
    /// [`TableError::TooLarge`]), so special files such as `/dev/urandom`
    /// end in an error at once. The bytes are not yet checked: pass them
    /// to [`Table::from_bytes`].
    pub fn read_file(path: impl AsRef<std::path::Path>) -> Result<Vec<u8>, TableError> {
        let path = path.as_ref();
        let io = |e: std::io::Error| TableError::Io {
            path: path.display().to_string(),
            message: e.to_string(),
        };
        let mut file = std::fs::File::open(path).map_err(io)?;
        format::read(&mut file, io).map_err(|e| e.in_file(path))
    }

    /// Builds the lookup structure from a payload, checking every value.
    pub(crate) fn from_payload(payload: Payload) -> Result<Table, TableError> {
        let bad = |m: String| Err(TableError::Inconsistent(m));
        let layout = Layout::new(&payload.axes).map_err(TableError::Inconsistent)?;
        let [psi, theta, f_star] = layout.ranges;
        let constants = payload
            .model
            .constants()
            .map_err(TableError::Inconsistent)?
            .distribution(payload.distribution.distribution().map_err(TableError::Inconsistent)?);
        constants
            .validate()
            .map_err(|e| TableError::Inconsistent(format!("model constants: {e}")))?;
        let count = layout.coefficients();
        for (name, coefs) in [("ln_mu", &payload.ln_mu), ("h_star", &payload.h_star)] {
            if coefs.len() != count {
                return bad(format!(
                    "{name} has {} coefficients, the axes need {count}",
                    coefs.len()
                ));
            }
        }
        let ln_mu = payload.ln_mu.to_f64();
        let h_star = payload.h_star.to_f64();
        let ln_mu_range = bounded("ln_mu", &ln_mu, format::LN_MU_MAX).map_err(TableError::Inconsistent)?;
        bounded("h_star", &h_star, format::H_STAR_MAX).map_err(TableError::Inconsistent)?;
        // |∂μ/∂F*| ≤ μ_max·|d ln μ/d(cell coordinate)|·(1/step)/F*_lo, and
        // |d ln μ/d(cell coordinate)| ≤ 2·max|c| (the weights' slopes sum
        // to at most 1.5 in absolute value), μ_max ≤ e^(max c + 1e-3·max|c|)
        // (the weights are convex up to the rounding of the cell offset).
        let (c_max, c_abs) = ln_mu_range;
        let ln_slope_bound = c_max + 1e-3 * c_abs + (4.0 * c_abs + 1.0).ln() + layout.inv_step[2].ln() - f_star.0.ln();
        if ln_slope_bound.is_nan() || ln_slope_bound > format::LN_SLOPE_MAX {
            return bad(format!(
                "ln_mu coefficients up to {} with F* down to {} and an F* step of {}: dmu/dF* could overflow (bound e^{ln_slope_bound:.1}, at most e^{})",
                Shortest(c_max),
                Shortest(f_star.0),
                Shortest(layout.axes[2].step),
                format::LN_SLOPE_MAX
            ));
        }
        let acc = &payload.accuracy;
        if !(acc.tolerance.is_finite() && acc.tolerance > 0.0) {
            return bad(format!(
                "accuracy: tolerance {} (must be finite and > 0)",
                acc.tolerance
            ));
        }
        for (name, v) in [("max_rel", acc.max_rel), ("p99_rel", acc.p99_rel)] {
            if !(v.is_finite() && v >= 0.0) {
                return bad(format!("accuracy: {name} {v} (must be finite and >= 0)"));
            }
        }
        if !acc.worst.iter().all(|v| v.is_finite()) {
            return bad(format!("accuracy: worst point {:?} is not finite", acc.worst));
        }
        let b = &payload.build;
        if !(b.h_lo.is_finite() && b.h_hi.is_finite()) {
            return bad(format!("build: h* range [{}, {}] is not finite", b.h_lo, b.h_hi));
        }
        if b.generator.len() > format::GENERATOR_MAX {
            return bad(format!(
                "build: generator is {} bytes (at most {})",
                b.generator.len(),
                format::GENERATOR_MAX
            ));
        }
        let info = TableInfo {
            domain: Domain {
                psi,
                theta,
                f_star,
                constants,
            },
            tolerance: acc.tolerance,
            accuracy: acc.measured(),
            build: payload.build.record(),
            precision: match payload.ln_mu {
                Coefs::F32(_) => Precision::F32,
                Coefs::F64(_) => Precision::F64,
            },
            format_version: format::VERSION,
            // Set by `from_bytes`, which has the file.
            bytes: 0,
            crc32: 0,
        };
        let avx2 = match &payload.ln_mu {
            Coefs::F32(c) if ln_mu_range.1 <= format::FAST_LN_MU_MAX => Fast::new(&layout, c),
            _ => None,
        };
        Ok(Table {
            layout,
            info,
            avx2,
            ln_mu,
            h_star,
        })
    }

    /// The ranges of ψ, θ, F* this table covers, and its model constants.
    pub fn domain(&self) -> &Domain {
        &self.info.domain
    }

    /// Refuses `constants` other than the table's (β, ν, ε* within 1e-9
    /// relative; the fit, the model and the heights' distribution equal):
    /// a table answers for its own constants only, and μ at other
    /// constants is a different number, not a nearby one. The error names
    /// the first constant that differs, with both values.
    ///
    /// ```
    /// use ke_friction::{Constants, HeightDistribution, Table};
    /// let table = Table::embedded();
    /// assert!(table.check_constants(&Constants::default()).is_ok());
    /// let measured = Constants::default().beta(0.117).distribution(HeightDistribution::pearson(0.3, 3.5)?);
    /// let e = table.check_constants(&measured).unwrap_err();
    /// assert_eq!(e.to_string(), "beta = 0.117, but the table holds beta = 0.04: it answers for its own \
    ///     constants only (build a table for these, or use a curve or the model)");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn check_constants(&self, constants: &Constants) -> Result<(), ConstantsMismatch> {
        let held = &self.info.domain.constants;
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs();
        let differs = |name: &'static str, given: String, table: String| Err(ConstantsMismatch { name, given, table });
        let number = |x: f64| Shortest(x).to_string();
        for (name, given, table) in [
            ("beta", constants.beta, held.beta),
            ("nu", constants.nu, held.nu),
            ("eps_star", constants.eps_star, held.eps_star),
        ] {
            if !close(given, table) {
                return differs(name, number(given), number(table));
            }
        }
        if constants.fit != held.fit {
            return differs("fit", constants.fit.to_string(), held.fit.to_string());
        }
        if constants.kind != held.kind {
            return differs("model", constants.kind.to_string(), held.kind.to_string());
        }
        if constants.distribution != held.distribution {
            return differs(
                "distribution",
                constants.distribution.to_string(),
                held.distribution.to_string(),
            );
        }
        Ok(())
    }

    /// What the table's file records: domain, model, tolerance, measured
    /// accuracy, build options, precision.
    pub fn info(&self) -> &TableInfo {
        &self.info
    }

    /// The lookup grid's axes (ψ, θ, F*), ghost nodes included.
    pub fn axes(&self) -> &[Axis; 3] {
        &self.layout.axes
    }

    /// The spline coefficients of ln μ, shape (nψ + 2, nθ + 2, nF + 2) of
    /// [`Table::axes`]' node counts, F* fastest (for the NumPy export).
    #[cfg(feature = "builder")]
    pub(crate) fn ln_mu_coefficients(&self) -> &[f64] {
        &self.ln_mu
    }

    /// The static friction coefficient μ(ψ, θ, F*).
    ///
    /// Arguments outside [`domain`](Self::domain) (or NaN) are errors:
    /// nothing is clamped or extrapolated. Where [`fast_kernel`](Self::fast_kernel)
    /// is true this runs in f32 arithmetic, within [`FAST_KERNEL_MAX_REL`] of the
    /// exact interpolant [`mu_portable`](Self::mu_portable).
    #[inline]
    pub fn mu(&self, psi: f64, theta: f64, f_star: f64) -> Result<f64, LookupError> {
        match self.avx2_lookup::<false>(psi, theta, f_star) {
            Some(r) => r.map(|(mu, _)| mu),
            None => self.mu_portable(psi, theta, f_star),
        }
    }

    /// The AVX2 kernel's μ and (if `SLOPE`) d ln μ/d(cell coordinate of
    /// F*), or `None` where it does not run.
    #[inline(always)]
    fn avx2_lookup<const SLOPE: bool>(
        &self,
        psi: f64,
        theta: f64,
        f_star: f64,
    ) -> Option<Result<(f64, f64), LookupError>> {
        let kernel = self.avx2.as_ref()?;
        let (mu, d) = kernel.eval::<SLOPE>(psi, theta, f_star);
        Some(if mu.is_nan() {
            self.nan_from_kernel(psi, theta, f_star)
        } else {
            Ok((mu, d))
        })
    }

    /// What a NaN from the fast kernel means: a query outside the domain
    /// (the error naming it). For a query inside, the loader's bounds make
    /// a NaN impossible; should one occur all the same, the portable
    /// kernel answers (never a panic, never a NaN handed on as μ).
    #[cold]
    #[inline(never)]
    fn nan_from_kernel(&self, psi: f64, theta: f64, f_star: f64) -> Result<(f64, f64), LookupError> {
        self.layout.check(psi, theta, f_star)?;
        self.ln_slope_portable(psi, theta, f_star)
    }

    /// μ with each argument first clamped into the table's range — an
    /// explicit opt-in for callers that prefer the edge value to an error
    /// (e.g. a solver's trial step just outside the domain). NaN is still
    /// an error: it has no nearest value.
    #[inline]
    pub fn mu_clamped(&self, psi: f64, theta: f64, f_star: f64) -> Result<f64, LookupError> {
        let d = &self.info.domain;
        let clamp = |v: f64, (lo, hi): (f64, f64)| if v.is_nan() { v } else { v.clamp(lo, hi) };
        self.mu(clamp(psi, d.psi), clamp(theta, d.theta), clamp(f_star, d.f_star))
    }

    /// μ by the portable kernel: the interpolant in f64 arithmetic without
    /// fused multiply-adds, identical on every machine (so the accuracy a
    /// build records does not depend on where it ran).
    ///
    /// [`mu`](Self::mu) runs the same kernel unless the fast one applies
    /// (x86-64 with AVX2 and FMA, and a table stored in f32), which works
    /// in f32 and differs from this by at most [`FAST_KERNEL_MAX_REL`] relative
    /// (measured over the default table), far below the table's own error.
    pub fn mu_portable(&self, psi: f64, theta: f64, f_star: f64) -> Result<f64, LookupError> {
        let cell = self.layout.cell(psi, theta, f_star)?;
        Ok(fastmath::exp(portable::blend(&self.layout, &self.ln_mu, &cell)))
    }

    /// μ and its slope ∂μ/∂F* (for implicit solvers).
    #[inline]
    pub fn mu_with_slope(&self, psi: f64, theta: f64, f_star: f64) -> Result<(f64, f64), LookupError> {
        let (mu, d_ln_mu) = match self.avx2_lookup::<true>(psi, theta, f_star) {
            Some(r) => r?,
            None => self.ln_slope_portable(psi, theta, f_star)?,
        };
        Ok((mu, slope(mu, d_ln_mu, self.layout.inv_step[2], f_star)))
    }

    /// μ and d ln μ/d(cell coordinate of F*), portably.
    fn ln_slope_portable(&self, psi: f64, theta: f64, f_star: f64) -> Result<(f64, f64), LookupError> {
        let cell = self.layout.cell(psi, theta, f_star)?;
        let (ln_mu, d_ln_mu) = portable::blend_with_slope(&self.layout, &self.ln_mu, &cell);
        Ok((fastmath::exp(ln_mu), d_ln_mu))
    }

    /// [`mu_with_slope`](Self::mu_with_slope) by the portable kernel (see
    /// [`mu_portable`](Self::mu_portable)).
    pub fn mu_with_slope_portable(&self, psi: f64, theta: f64, f_star: f64) -> Result<(f64, f64), LookupError> {
        let (mu, d_ln_mu) = self.ln_slope_portable(psi, theta, f_star)?;
        Ok((mu, slope(mu, d_ln_mu, self.layout.inv_step[2], f_star)))
    }

    /// Whether lookups on this machine run the fast f32 kernel (see
    /// [`mu_portable`](Self::mu_portable)).
    pub fn fast_kernel(&self) -> bool {
        self.avx2.is_some()
    }

    /// The separation h*(ψ, θ, F*) at which the surfaces carry F*.
    #[inline]
    pub fn h_star(&self, psi: f64, theta: f64, f_star: f64) -> Result<f64, LookupError> {
        let cell = self.layout.cell(psi, theta, f_star)?;
        Ok(portable::blend(&self.layout, &self.h_star, &cell))
    }
}

/// Checks that every value of coefficient array `name` is finite and
/// within ±`max`; returns (the largest value, the largest magnitude).
fn bounded(name: &str, coefs: &[f64], max: f64) -> Result<(f64, f64), String> {
    let (mut top, mut size) = (f64::NEG_INFINITY, 0.0f64);
    for (i, &c) in coefs.iter().enumerate() {
        if !c.is_finite() || c.abs() > max {
            return Err(format!(
                "{name} coefficient {i} is {}: must be finite and within [-{}, {}]",
                Shortest(c),
                Shortest(max),
                Shortest(max)
            ));
        }
        top = top.max(c);
        size = size.max(c.abs());
    }
    Ok((top, size))
}

/// ∂μ/∂F* from μ and d ln μ/d(cell coordinate of F*), the coordinate
/// being v·`inv_step` + const: ln μ is splined in v = ln F*, so
/// dμ/dF* = μ · (d ln μ/dv) / F*. (The AVX2 batch does these operations,
/// in this order, four at a time.)
#[inline(always)]
fn slope(mu: f64, d_ln_mu: f64, inv_step: f64, f_star: f64) -> f64 {
    mu * d_ln_mu * inv_step / f_star
}
