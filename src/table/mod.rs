//! Precomputed tables of μ(ψ, θ, F*) and nanosecond lookups.
//!
//! A [`Table`] holds tensor cubic B-spline coefficients of ln μ and of h*
//! over (ln ψ, √θ, ln F*) (see [`crate::spline`]). A lookup blends 4×4×4
//! coefficients: no allocation, no lock, no branch on the data. The
//! interpolant is C², so μ and ∂μ/∂F* are continuous everywhere.
//!
//! Two kernels evaluate it. The portable one works in f64 and gives the
//! same bits on every machine ([`Table::mu_portable`]). On x86-64 CPUs
//! with AVX2 and FMA, tables stored in f32 (the default) are looked up by
//! a kernel in f32 arithmetic, eight queries to a vector in a batch; its
//! rounding moves μ by at most about 3e-6 relative ([`Table::fast_kernel`]
//! says which kernel runs).

#[cfg(target_arch = "x86_64")]
mod avx2;
mod fastmath;
pub mod format;

use crate::params::Params;
use crate::spline::{weight_slopes, weights, Axis, Scale};
pub use format::TableError;
use format::{Accuracy, AxisSpec, BuildSpec, Payload};

/// A lookup argument outside the table's domain, or not a number.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum LookupError {
    /// The argument is NaN or outside `[lo, hi]`.
    #[error("{name} = {value} is outside the table's range [{lo:e}, {hi:e}]")]
    OutOfDomain {
        /// `"psi"`, `"theta"` or `"f_star"`.
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// Lower end of the table's range.
        lo: f64,
        /// Upper end.
        hi: f64,
    },
    /// Batch slices of different lengths.
    #[error("batch slices differ in length: psi {psi}, theta {theta}, f_star {f_star}, out {out}")]
    LengthMismatch {
        /// Length of `psi`.
        psi: usize,
        /// Length of `theta`.
        theta: usize,
        /// Length of `f_star`.
        f_star: usize,
        /// Length of `out`.
        out: usize,
    },
    /// A batch element was NaN or out of the domain; `index` says which.
    #[error("batch element {index}: {name} = {value} is outside the table's range [{lo:e}, {hi:e}]")]
    BatchElement {
        /// Position in the slices.
        index: usize,
        /// `"psi"`, `"theta"` or `"f_star"`.
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// Lower end of the table's range.
        lo: f64,
        /// Upper end.
        hi: f64,
    },
}

/// What a table covers: its domain and the model it was built from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Domain {
    /// Range of ψ.
    pub psi: (f64, f64),
    /// Range of θ.
    pub theta: (f64, f64),
    /// Range of F*.
    pub f_star: (f64, f64),
    /// The model constants and fit (ψ and θ of this `Params` are the lower
    /// ends of their ranges).
    pub params: Params,
    /// The maximum relative error of μ the table promises (checked at build time).
    pub tolerance: f64,
}

/// A loaded table: immutable, `Send + Sync`, shareable across threads.
#[derive(Debug, Clone)]
pub struct Table {
    axes: [Axis; 3],
    domain: Domain,
    /// Strides of the coefficient arrays along ψ, θ, F* (the last is 1).
    strides: [usize; 3],
    /// Per axis: 1/spacing.
    inv_step: [f64; 3],
    /// −first/spacing: the cell coordinate is `c·inv_step + offset`.
    offset: [f64; 3],
    /// Per axis: the index of the last cell.
    last_cell: [usize; 3],
    /// The fast kernel, where the CPU and the table suit it.
    #[cfg(target_arch = "x86_64")]
    fast: Option<avx2::Kernel>,
    ln_mu: Vec<f64>,
    h_star: Vec<f64>,
    accuracy: Accuracy,
    build: BuildSpec,
    /// Whether the file stores f32 coefficients.
    single: bool,
}

impl Domain {
    /// The ranges of ψ, θ and F*, in that order.
    pub fn ranges(&self) -> [(f64, f64); 3] {
        [self.psi, self.theta, self.f_star]
    }

    /// `Ok` for a query inside the domain; otherwise the error naming the
    /// first argument outside its range (or NaN).
    #[inline(always)]
    pub fn check(&self, psi: f64, theta: f64, f_star: f64) -> Result<(), LookupError> {
        let names = ["psi", "theta", "f_star"];
        for ((name, value), (lo, hi)) in names.into_iter().zip([psi, theta, f_star]).zip(self.ranges()) {
            if !(value >= lo && value <= hi) {
                return Err(LookupError::OutOfDomain { name, value, lo, hi });
            }
        }
        Ok(())
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
        Table::from_payload(format::decode(bytes)?)
    }

    /// Reads and checks a table file.
    pub fn load(path: impl AsRef<std::path::Path>) -> Result<Table, TableError> {
        let path = path.as_ref();
        let bytes = std::fs::read(path).map_err(|e| TableError::Io {
            path: path.display().to_string(),
            message: e.to_string(),
        })?;
        Table::from_bytes(&bytes)
    }

    /// Builds the lookup structure from a payload, checking every value.
    pub(crate) fn from_payload(payload: Payload) -> Result<Table, TableError> {
        let bad = |m: String| Err(TableError::Inconsistent(m));
        let axis =
            |k: usize| check_axis(["psi", "theta", "f_star"][k], &payload.axes[k]).map_err(TableError::Inconsistent);
        let axes = [axis(0)?, axis(1)?, axis(2)?];
        // The lookup kernels map ψ, θ, F* through ln, √, ln: a file with
        // other maps would be misread, not just read slowly.
        if axes.map(|a| a.scale) != [Scale::Log, Scale::Sqrt, Scale::Log] {
            return bad("the axes must map psi, theta, f_star by ln, sqrt, ln".into());
        }
        let [a, b, c] = payload.axes;
        let params = payload.model.params(a.lo, b.lo).map_err(TableError::Inconsistent)?;
        params
            .validate()
            .map_err(|e| TableError::Inconsistent(format!("model constants: {e}")))?;
        let count = axes
            .iter()
            .map(|x| x.nodes + 2)
            .try_fold(1usize, |acc, n| acc.checked_mul(n));
        let Some(count) = count.filter(|&n| n <= 1 << 28) else {
            return bad("grid is too large".into());
        };
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
        if ln_mu.iter().chain(&h_star).any(|v| !v.is_finite()) {
            return bad("non-finite coefficient".into());
        }
        let acc = &payload.accuracy;
        if !(acc.tolerance.is_finite() && acc.tolerance > 0.0 && acc.max_rel.is_finite() && acc.p99_rel.is_finite()) {
            return bad("accuracy record is not finite and positive".into());
        }
        let strides = [(axes[1].nodes + 2) * (axes[2].nodes + 2), axes[2].nodes + 2, 1];
        let mut table = Table {
            axes,
            domain: Domain {
                psi: (a.lo, a.hi),
                theta: (b.lo, b.hi),
                f_star: (c.lo, c.hi),
                params,
                tolerance: acc.tolerance,
            },
            strides,
            inv_step: axes.map(|a| 1.0 / a.step),
            offset: axes.map(|a| -a.first / a.step),
            last_cell: axes.map(|a| a.nodes - 2),
            #[cfg(target_arch = "x86_64")]
            fast: None,
            ln_mu,
            h_star,
            accuracy: payload.accuracy,
            single: matches!(payload.ln_mu, format::Coefs::F32(_)),
            build: payload.build,
        };
        #[cfg(target_arch = "x86_64")]
        if let format::Coefs::F32(c) = &payload.ln_mu {
            table.fast = avx2::Kernel::new(&table, c);
        }
        Ok(table)
    }

    /// The ranges of ψ, θ, F* this table covers, and its model constants.
    pub fn domain(&self) -> &Domain {
        &self.domain
    }

    /// The accuracy measured when the table was built.
    pub fn accuracy(&self) -> &Accuracy {
        &self.accuracy
    }

    /// The build options recorded in the table.
    pub fn build_spec(&self) -> &BuildSpec {
        &self.build
    }

    /// The lookup grid's axes (ψ, θ, F*), ghost nodes included.
    pub fn axes(&self) -> &[Axis; 3] {
        &self.axes
    }

    /// Whether the file stores its coefficients in single precision (f32).
    pub fn single_precision(&self) -> bool {
        self.single
    }

    /// The static friction coefficient μ(ψ, θ, F*).
    ///
    /// Arguments outside [`domain`](Self::domain) (or NaN) are errors:
    /// nothing is clamped or extrapolated. Where [`fast_kernel`](Self::fast_kernel)
    /// is true this runs in f32 arithmetic, within ~3e-6 relative of the
    /// exact interpolant [`mu_portable`](Self::mu_portable).
    #[inline]
    pub fn mu(&self, psi: f64, theta: f64, f_star: f64) -> Result<f64, LookupError> {
        match self.fast::<false>(psi, theta, f_star) {
            Some(r) => r.map(|(mu, _)| mu),
            None => self.mu_portable(psi, theta, f_star),
        }
    }

    /// The fast kernel's μ and (if `SLOPE`) d ln μ/d(cell coordinate of
    /// F*), or `None` where it does not run.
    #[inline(always)]
    fn fast<const SLOPE: bool>(&self, psi: f64, theta: f64, f_star: f64) -> Option<Result<(f64, f64), LookupError>> {
        #[cfg(target_arch = "x86_64")]
        if let Some(k) = &self.fast {
            // SAFETY: a kernel exists only where the CPU has AVX2 and FMA.
            let (mu, d) = unsafe { avx2::eval::<SLOPE>(k, psi, theta, f_star) };
            return Some(if mu.is_nan() {
                Err(self.domain_error(psi, theta, f_star))
            } else {
                Ok((mu, d))
            });
        }
        None
    }

    /// μ with each argument first clamped into the table's range — an
    /// explicit opt-in for callers that prefer the edge value to an error
    /// (e.g. a solver's trial step just outside the domain). NaN is still
    /// an error: it has no nearest value.
    #[inline]
    pub fn mu_clamped(&self, psi: f64, theta: f64, f_star: f64) -> Result<f64, LookupError> {
        let d = &self.domain;
        let clamp = |v: f64, (lo, hi): (f64, f64)| if v.is_nan() { v } else { v.clamp(lo, hi) };
        self.mu(clamp(psi, d.psi), clamp(theta, d.theta), clamp(f_star, d.f_star))
    }

    /// μ by the portable kernel: the interpolant in f64 arithmetic without
    /// fused multiply-adds, identical on every machine (so the accuracy a
    /// build records does not depend on where it ran).
    ///
    /// [`mu`](Self::mu) runs the same kernel unless the fast one applies
    /// (x86-64 with AVX2 and FMA, and a table stored in f32), which works
    /// in f32 and differs from this by at most about 3e-6 relative
    /// (measured over the default table), far below the table's own error.
    pub fn mu_portable(&self, psi: f64, theta: f64, f_star: f64) -> Result<f64, LookupError> {
        let cell = self.cell(psi, theta, f_star)?;
        Ok(fastmath::exp(self.blend(&self.ln_mu, &cell)))
    }

    /// μ and its slope ∂μ/∂F* (for implicit solvers).
    #[inline]
    pub fn mu_with_slope(&self, psi: f64, theta: f64, f_star: f64) -> Result<(f64, f64), LookupError> {
        let (mu, d_ln_mu) = match self.fast::<true>(psi, theta, f_star) {
            Some(r) => r?,
            None => self.slope_portable(psi, theta, f_star)?,
        };
        Ok((mu, self.slope_from(mu, d_ln_mu, f_star)))
    }

    /// μ and d ln μ/d(cell coordinate of F*), portably.
    fn slope_portable(&self, psi: f64, theta: f64, f_star: f64) -> Result<(f64, f64), LookupError> {
        let cell = self.cell(psi, theta, f_star)?;
        let (ln_mu, d_ln_mu) = self.blend2(&self.ln_mu, &cell);
        Ok((fastmath::exp(ln_mu), d_ln_mu))
    }

    /// [`mu_with_slope`](Self::mu_with_slope) by the portable kernel (see
    /// [`mu_portable`](Self::mu_portable)).
    pub fn mu_with_slope_portable(&self, psi: f64, theta: f64, f_star: f64) -> Result<(f64, f64), LookupError> {
        let (mu, d_ln_mu) = self.slope_portable(psi, theta, f_star)?;
        Ok((mu, self.slope_from(mu, d_ln_mu, f_star)))
    }

    /// ∂μ/∂F* from μ and d ln μ/d(cell coordinate) (see [`slope`]).
    #[inline(always)]
    fn slope_from(&self, mu: f64, d_ln_mu: f64, f_star: f64) -> f64 {
        slope(mu, d_ln_mu, self.inv_step[2], f_star)
    }

    /// Whether lookups on this machine run the fast f32 kernel (see
    /// [`mu_portable`](Self::mu_portable)).
    pub fn fast_kernel(&self) -> bool {
        #[cfg(target_arch = "x86_64")]
        return self.fast.is_some();
        #[cfg(not(target_arch = "x86_64"))]
        false
    }

    /// The separation h*(ψ, θ, F*) at which the surfaces carry F*.
    #[inline]
    pub fn h_star(&self, psi: f64, theta: f64, f_star: f64) -> Result<f64, LookupError> {
        let cell = self.cell(psi, theta, f_star)?;
        Ok(self.blend(&self.h_star, &cell))
    }

    /// μ for many queries at once, written into `out` (no allocation);
    /// bit for bit what [`mu`](Self::mu) gives for each. All four slices
    /// must have the same length; on an out-of-domain element the error
    /// names its index and `out` is left partly written.
    ///
    /// ```
    /// # use ke_friction::{LookupError, Table};
    /// let table = Table::embedded();
    /// let (psi, theta) = ([1.0; 3], [0.001; 3]);
    /// let mut mu = [0.0; 3];
    /// table.mu_batch(&psi, &theta, &[0.001, 0.01, 0.1], &mut mu)?;
    /// assert_eq!(mu[1], table.mu(1.0, 0.001, 0.01)?);
    /// // F* = 0.2 is outside the default table (1e-5 ≤ F* ≤ 0.1):
    /// let err = table.mu_batch(&psi, &theta, &[0.001, 0.2, 0.1], &mut mu).unwrap_err();
    /// assert!(matches!(err, LookupError::BatchElement { index: 1, name: "f_star", .. }));
    /// # Ok::<(), LookupError>(())
    /// ```
    pub fn mu_batch(&self, psi: &[f64], theta: &[f64], f_star: &[f64], out: &mut [f64]) -> Result<(), LookupError> {
        self.batch(psi, theta, f_star, Out::Mu(out))
    }

    /// μ and ∂μ/∂F* for many queries at once, written into `out` as
    /// `(μ, ∂μ/∂F*)` pairs (no allocation): the batch form of
    /// [`mu_with_slope`](Self::mu_with_slope), bit for bit, for implicit
    /// solvers with many contacts. Lengths and errors as in
    /// [`mu_batch`](Self::mu_batch).
    ///
    /// ```
    /// # use ke_friction::Table;
    /// let table = Table::embedded();
    /// let loads = [0.001, 0.01, 0.1];
    /// let mut out = [(0.0, 0.0); 3];
    /// table.mu_with_slope_batch(&[2.0; 3], &[0.003; 3], &loads, &mut out)?;
    /// for (&f, &(mu, dmu)) in loads.iter().zip(&out) {
    ///     assert_eq!((mu, dmu), table.mu_with_slope(2.0, 0.003, f)?);
    ///     assert!(dmu < 0.0); // μ falls as the load rises
    /// }
    /// # Ok::<(), ke_friction::LookupError>(())
    /// ```
    pub fn mu_with_slope_batch(
        &self,
        psi: &[f64],
        theta: &[f64],
        f_star: &[f64],
        out: &mut [(f64, f64)],
    ) -> Result<(), LookupError> {
        self.batch(psi, theta, f_star, Out::WithSlope(out))
    }

    /// Both batch forms: checks the lengths, runs the kernel, and turns
    /// the index of the first query outside the domain into the error.
    fn batch(&self, psi: &[f64], theta: &[f64], f_star: &[f64], out: Out) -> Result<(), LookupError> {
        let n = out.len();
        if psi.len() != n || theta.len() != n || f_star.len() != n {
            return Err(LookupError::LengthMismatch {
                psi: psi.len(),
                theta: theta.len(),
                f_star: f_star.len(),
                out: n,
            });
        }
        let failed = 'run: {
            #[cfg(target_arch = "x86_64")]
            if let Some(k) = &self.fast {
                // SAFETY: as in `fast`; the lengths are checked above.
                break 'run unsafe { avx2::batch(k, psi, theta, f_star, out) };
            }
            match out {
                Out::Mu(o) => fill(o, |i| self.mu_portable(psi[i], theta[i], f_star[i])),
                Out::WithSlope(o) => fill(o, |i| self.mu_with_slope_portable(psi[i], theta[i], f_star[i])),
            }
        };
        let Some(i) = failed else {
            return Ok(());
        };
        Err(match self.domain_error(psi[i], theta[i], f_star[i]) {
            LookupError::OutOfDomain { name, value, lo, hi } => LookupError::BatchElement {
                index: i,
                name,
                value,
                lo,
                hi,
            },
            other => other,
        })
    }

    /// Locates a query: the offset of its 4×4×4 block and the ψ, θ, F*
    /// weights; the error names the first argument outside the domain.
    #[inline(always)]
    fn cell(&self, psi: f64, theta: f64, f_star: f64) -> Result<Cell, LookupError> {
        self.domain.check(psi, theta, f_star)?;
        let coords = [fastmath::ln(psi), theta.sqrt(), fastmath::ln(f_star)];
        let mut base = 0;
        let mut frac = [0.0; 3];
        for k in 0..3 {
            let s = coords[k] * self.inv_step[k] + self.offset[k];
            // i64 conversions are single instructions (usize ones, and
            // floor without SSE4.1, are not); s ≥ 0 inside the domain.
            let i = (s as i64).min(self.last_cell[k] as i64);
            base += i as usize * self.strides[k];
            frac[k] = s - i as f64;
        }
        Ok(Cell {
            base,
            wp: weights(frac[0]),
            wt: weights(frac[1]),
            wf: weights(frac[2]),
            f_f: frac[2],
        })
    }

    /// The error for a query outside the domain (the first bad argument).
    #[cold]
    fn domain_error(&self, psi: f64, theta: f64, f_star: f64) -> LookupError {
        match self.domain.check(psi, theta, f_star) {
            Err(e) => e,
            Ok(()) => unreachable!("domain_error is called only for a query outside the domain"),
        }
    }

    /// Σ wp·wt·wf·c over the 4×4×4 block.
    #[inline(always)]
    fn blend(&self, c: &[f64], cell: &Cell) -> f64 {
        let [s0, s1, _] = self.strides;
        let wf = &cell.wf;
        // One bounds check for the whole block (the last element it reads).
        let _ = c[cell.base + 3 * s0 + 3 * s1 + 3];
        let mut sum = 0.0;
        for a in 0..4 {
            let mut plane = 0.0;
            for b in 0..4 {
                let o = cell.base + a * s0 + b * s1;
                // SAFETY: o + 3 <= base + 3·s0 + 3·s1 + 3, checked above.
                let row = unsafe { c.get_unchecked(o..o + 4) };
                let r = row[0] * wf[0] + row[1] * wf[1] + row[2] * wf[2] + row[3] * wf[3];
                plane += cell.wt[b] * r;
            }
            sum += cell.wp[a] * plane;
        }
        sum
    }

    /// The blend and its derivative along the F* coordinate, in one pass.
    #[inline(always)]
    fn blend2(&self, c: &[f64], cell: &Cell) -> (f64, f64) {
        let [s0, s1, _] = self.strides;
        let df = weight_slopes(cell.f_f);
        let _ = c[cell.base + 3 * s0 + 3 * s1 + 3];
        let (mut sum, mut dsum) = (0.0, 0.0);
        for a in 0..4 {
            let (mut plane, mut dplane) = (0.0, 0.0);
            for b in 0..4 {
                let o = cell.base + a * s0 + b * s1;
                // SAFETY: as in `blend`.
                let row = unsafe { c.get_unchecked(o..o + 4) };
                let r = row[0] * cell.wf[0] + row[1] * cell.wf[1] + row[2] * cell.wf[2] + row[3] * cell.wf[3];
                let dr = row[0] * df[0] + row[1] * df[1] + row[2] * df[2] + row[3] * df[3];
                plane += cell.wt[b] * r;
                dplane += cell.wt[b] * dr;
            }
            sum += cell.wp[a] * plane;
            dsum += cell.wp[a] * dplane;
        }
        (sum, dsum)
    }
}

/// ∂μ/∂F* from μ and d ln μ/d(cell coordinate of F*), the coordinate
/// being v·`inv_step` + const: ln μ is splined in v = ln F*, so
/// dμ/dF* = μ · (d ln μ/dv) / F*. (The AVX2 batch does these operations,
/// in this order, four at a time.)
#[inline(always)]
fn slope(mu: f64, d_ln_mu: f64, inv_step: f64, f_star: f64) -> f64 {
    mu * d_ln_mu * inv_step / f_star
}

/// Where a batch writes: μ alone, or (μ, ∂μ/∂F*) pairs.
enum Out<'a> {
    /// [`Table::mu_batch`].
    Mu(&'a mut [f64]),
    /// [`Table::mu_with_slope_batch`].
    WithSlope(&'a mut [(f64, f64)]),
}

impl Out<'_> {
    /// The number of queries.
    fn len(&self) -> usize {
        match self {
            Out::Mu(o) => o.len(),
            Out::WithSlope(o) => o.len(),
        }
    }
}

/// Sets `out[i] = f(i)` in order; returns the first `i` where `f` fails.
fn fill<T>(out: &mut [T], f: impl Fn(usize) -> Result<T, LookupError>) -> Option<usize> {
    for (i, o) in out.iter_mut().enumerate() {
        match f(i) {
            Ok(v) => *o = v,
            Err(_) => return Some(i),
        }
    }
    None
}

/// A located query.
struct Cell {
    base: usize,
    wp: [f64; 4],
    wt: [f64; 4],
    wf: [f64; 4],
    /// The cell offset along F* (for the weights' slopes).
    f_f: f64,
}

/// Validates a stored axis and converts it.
fn check_axis(name: &str, s: &AxisSpec) -> Result<Axis, String> {
    let scale = s.scale;
    let nodes = s.nodes as usize;
    if !(s.first.is_finite() && s.step.is_finite() && s.step > 0.0 && (5..=1 << 20).contains(&nodes)) {
        return Err(format!("{name} axis: bad node spacing or count"));
    }
    let axis = Axis {
        scale,
        first: s.first,
        step: s.step,
        nodes,
    };
    let (c_lo, c_hi) = (axis.coord(0), axis.coord(nodes - 1));
    let ok = s.lo.is_finite()
        && s.hi.is_finite()
        && s.lo < s.hi
        && (scale != Scale::Log || s.lo > 0.0)
        && (scale != Scale::Sqrt || s.lo >= 0.0);
    if !ok {
        return Err(format!("{name} axis: bad domain [{}, {}]", s.lo, s.hi));
    }
    // The domain must lie within the nodes (tolerating rounding of the map).
    let slack = 1e-9 * axis.step;
    if scale.forward(s.lo) < c_lo - slack || scale.forward(s.hi) > c_hi + slack {
        return Err(format!(
            "{name} axis: domain [{}, {}] extends beyond the grid",
            s.lo, s.hi
        ));
    }
    Ok(axis)
}

/// Writes `bytes` to `path` atomically: to a temporary file in the same
/// directory, flushed to disk, then renamed over `path`. An interrupted
/// write leaves any previous file at `path` intact and no partial file
/// under its name.
pub fn write_atomic(path: &std::path::Path, bytes: &[u8]) -> std::io::Result<()> {
    write_atomic_with(path, |mut file| {
        std::io::Write::write_all(&mut file, bytes)?;
        file.sync_all()
    })
}

/// [`write_atomic`] with the file's contents written (and synced) by `write`.
pub(crate) fn write_atomic_with(
    path: &std::path::Path,
    write: impl FnOnce(std::fs::File) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let name = path
        .file_name()
        .ok_or_else(|| std::io::Error::new(std::io::ErrorKind::InvalidInput, "no file name"))?;
    let tmp = path.with_file_name(format!(".{}.tmp-{}", name.to_string_lossy(), std::process::id()));
    let result = std::fs::File::create(&tmp)
        .and_then(write)
        .and_then(|()| std::fs::rename(&tmp, path));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}
