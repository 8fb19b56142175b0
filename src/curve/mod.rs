//! μ(F*) for one surface pair: a piecewise cubic in F* for simulators in
//! which ψ and θ are fixed for a run and only the load changes.
//!
//! The cells are quasi-logarithmic and found from the bits of F* alone: an
//! f64's exponent and the top `k` bits of its mantissa name the cell (2^k
//! cells per octave, uniform in F* within an octave), and the remaining
//! mantissa bits are the position `t ∈ [0, 1)` in the cell, exactly. On each
//! cell μ is the cubic Hermite interpolant of μ and dμ/dF* at the cell's
//! ends (so μ and its slope are continuous), stored as a polynomial in `t`.
//! A lookup is a shift, a mask, one load of four coefficients and a cubic:
//! no logarithm, no exponential, no search. The range's own ends are nodes,
//! so nothing outside the range is ever evaluated, and the first and last
//! cells are cut to it.
//!
//! ```
//! use ke_friction::{Curve, Model, Params};
//! let model = Model::new(Params::new(1.0, 0.001))?;
//! let curve = Curve::from_model(&model, 1e-5, 0.1)?;
//! let mu = curve.mu(0.01)?;
//! assert!((mu / 0.52521087083 - 1.0).abs() < 1e-6); // MODEL.md §7
//! assert!(curve.max_error() <= 1e-6);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

// The AVX2 batch on x86-64, and a stand-in that is never detected, compiled
// on every target (both implement `BatchKernel`, so the stand-in cannot
// fall behind); `--cfg ke_friction_portable` selects it on x86-64 too.
#[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
mod avx2;
mod no_avx2;

#[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
use avx2::Batch;
#[cfg(not(all(target_arch = "x86_64", not(ke_friction_portable))))]
use no_avx2::Batch;

/// What a batch kernel offers a curve (see `avx2.rs`).
trait BatchKernel: Sized + Copy {
    /// The kernel, if this CPU runs it.
    fn detect() -> Option<Self>;
    /// μ for the loads of `f_star` four at a time into `out`, up to the
    /// first group holding a load outside the range; how many it did.
    fn mu(self, curve: &Curve, f_star: &[f64], out: &mut [f64]) -> usize;
}

use crate::model::{EvalError, Model};
use crate::num::Shortest;
use crate::rng::SplitMix64;
use crate::table::OnError;
use crate::table::{LookupError, Table};

/// The accuracy [`Curve::from_model`] builds to: the largest relative
/// error of μ against direct integration, measured at build time.
pub const CURVE_ACCURACY: f64 = 1e-6;

/// The F* range of a measured surface's μ(F*) by default, in every front
/// end (`kefric plot surface`, Python's `Surface.curve`): from 1e-7 (a
/// nominal pressure of 100 Pa on a hardness of 1 GPa: the light loads
/// `kefric surface --pressure` answers, below the paper's 1e-5) to the
/// paper's 0.1.
pub const SURFACE_F_STAR: (f64, f64) = (1e-7, 0.1);

/// The fewest cells per octave, as a power of two (16 cells).
const MIN_CELL_BITS: u32 = 4;
/// The most (256 cells per octave), which any smooth μ meets.
const MAX_CELL_BITS: u32 = 8;
/// At most this many cells: a range of 64 octaves at 256 cells each.
const MAX_CELLS: u64 = 1 << 14;
/// With at most this many cells missing the accuracy, those cells are
/// split (bisected where they miss it) instead of refining every cell.
const SPLIT_CELLS: usize = 32;
/// How often a cell may be bisected (its t has 52 − 8 bits below a
/// cell's at 256 cells per octave).
const MAX_SPLIT_DEPTH: u32 = 40;

/// The mantissa bits of an f64.
const MANTISSA: u64 = (1 << 52) - 1;
/// The bits of 1.0.
const ONE: u64 = 0x3ff0_0000_0000_0000;

/// Why a curve misses its accuracy when the heights' density is infinite
/// at an end of its support (a U- or J-shaped Pearson type I density): a
/// finite share of the summits sits at that end, so where the contacts
/// reach it exactly at a boundary of the contact law's regimes (x = 1, 6,
/// 110, where the law steps by a few percent), P*, Fs* and μ(F*) have a
/// cusp |F* − F₀|^α with α = 1 + the end's power < 1. The integrals there
/// are right (to 1e-12 of a brute-force sum, tests); the cusp is the
/// model's, not rounding.
pub(crate) const SINGULAR_END: &str = "the height density is infinite at an end of its support, so mu(F*) has a cusp \
                                where the contacts reach that end at a boundary of the contact law's regimes";

/// Why a curve cannot be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CurveError {
    /// The range is not two positive, finite, normal numbers in order.
    #[error("f_star range [{}, {}] is invalid: f_star_min and f_star_max must be positive, finite and normal, with f_star_min < f_star_max", Shortest(*.lo), Shortest(*.hi))]
    Range {
        /// `f_star_min`.
        lo: f64,
        /// `f_star_max`.
        hi: f64,
    },
    /// The range spans too many cells (more than 64 octaves).
    #[error("f_star range [{}, {}] spans more than 64 octaves", Shortest(*.lo), Shortest(*.hi))]
    TooWide {
        /// `f_star_min`.
        lo: f64,
        /// `f_star_max`.
        hi: f64,
    },
    /// The model cannot be solved at a load of the range.
    #[error("the model cannot be solved at F* = {}: {error}", Shortest(*.f_star))]
    Model {
        /// The load.
        f_star: f64,
        /// Why.
        error: EvalError,
    },
    /// The model has no positive μ at a load of the range.
    #[error("the model gives no positive friction coefficient at F* = {} (mu = {})", Shortest(*.f_star), Shortest(*.mu))]
    NoMu {
        /// The load.
        f_star: f64,
        /// What it gives there (NaN where F* ≤ 0).
        mu: f64,
    },
    /// A table lookup for a node failed (ψ or θ outside the table, or the
    /// range outside its F*).
    #[error(transparent)]
    Lookup(#[from] LookupError),
    /// A cell bisected 40 times still misses the accuracy asked for (μ(F*)
    /// jumps near `f_star`: finer cells cannot help, so this is known at
    /// the first cell count where it happens), or even 256 cells per
    /// octave miss it in more cells than are bisected: μ(F*) is not
    /// smooth over more than a few cells.
    #[error(
        "the curve misses its accuracy: max relative error {max_error:e} > {accuracy:e} at F* = {f_star} \
         with {cells_per_octave} cells per octave and the cells that miss it bisected up to 40 times; \
         mu(F*) jumps or is not smooth enough there for cubic cells; build curves on ranges either side \
         of it, or use direct integration{}", .cause.map(|c| format!(" ({c})")).unwrap_or_default()
    )]
    Accuracy {
        /// The cells per octave of the last attempt (16 to 256).
        cells_per_octave: u32,
        /// The measured error.
        max_error: f64,
        /// The accuracy asked for.
        accuracy: f64,
        /// Where the error is largest.
        f_star: f64,
        /// Why μ(F*) is not smooth, where the model knows (the heights'
        /// density infinite at an end of its support).
        cause: Option<&'static str>,
    },
}

/// μ(F*) for one surface pair over a range of F*: immutable, `Send + Sync`,
/// allocation-free lookups. Built by [`Curve::from_model`] (direct
/// integration) or [`Table::curve`] (from a table, in microseconds).
#[derive(Clone)]
pub struct Curve {
    /// The range of F*.
    range: (f64, f64),
    /// The bits of the range's ends.
    lo_bits: u64,
    /// `hi_bits − lo_bits`: a query is in the range iff its bits minus
    /// `lo_bits` (wrapping) are at most this.
    span_bits: u64,
    /// Cells per octave, as a power of two.
    cell_bits: u32,
    /// `52 − cell_bits`: the bits of F* shifted right by this are the cell.
    shift: u32,
    /// The cell of `lo`, as `lo_bits >> shift`.
    first_cell: u64,
    /// Per cell: μ = c0 + c1·t + c2·t² + c3·t³.
    coefs: Vec<[f64; 4]>,
    /// Per cell: 1/(its full width in F*), for dμ/dF* = (dμ/dt)/width.
    inv_width: Vec<f64>,
    /// The largest relative error of μ measured at build time.
    max_error: f64,
    /// The cells split into sub-cells, by cell; their `coefs` rows are NaN.
    splits: Vec<Split>,
    /// The AVX2 batch, where the CPU has it.
    batch: Option<Batch>,
}

/// A cell split into sub-cells where μ(F*) is not smooth enough for one
/// cubic (where a J- or U-shaped density's infinite end meets the contact
/// point or a regime boundary of the asperity laws, μ goes like
/// |F* − F₀|^α, α < 1): bisected in its coordinate t where it misses the
/// accuracy, each piece a cubic Hermite interpolant of its own.
#[derive(Debug, Clone)]
struct Split {
    /// The cell.
    cell: usize,
    /// The pieces' starts in t, ascending.
    starts: Vec<f64>,
    /// Per piece: μ as a cubic in `s = (t − start)·inv_dt ∈ [0, 1)`.
    coefs: Vec<[f64; 4]>,
    /// Per piece: 1/(its width in t).
    inv_dt: Vec<f64>,
}

/// A piece of a cell being split: its ends in t and F*, (μ, dμ/dF*) there.
#[derive(Debug, Clone, Copy)]
struct Piece {
    t: (f64, f64),
    f: (f64, f64),
    at: ((f64, f64), (f64, f64)),
    depth: u32,
}

/// The range, the cells and the measured error (not the coefficients).
impl std::fmt::Debug for Curve {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Curve")
            .field("range", &self.range)
            .field("cells", &self.coefs.len())
            .field("cells_per_octave", &(1u32 << self.cell_bits))
            .field("split_cells", &self.splits.len())
            .field("max_error", &self.max_error)
            .field("avx2_batch", &self.batch.is_some())
            .finish_non_exhaustive()
    }
}

/// What a curve interpolates: μ and dμ/dF* at a load.
type Source<'a> = dyn Fn(f64) -> Result<(f64, f64), CurveError> + 'a;

impl Curve {
    /// The curve of `model` over `[f_star_min, f_star_max]`, by direct
    /// integration at its nodes, refined (16, 32, … up to 256 cells per
    /// octave) until its relative error of μ, measured against direct
    /// integration at every cell's midpoint and at a seeded random point in
    /// every cell, is at most [`CURVE_ACCURACY`] (1e-6). Where at most a
    /// few cells miss it (μ(F*) not smooth at a load: a J- or U-shaped
    /// density), those cells are bisected where they miss it instead, down
    /// to 2⁻⁴⁰ of a cell. The error is [`max_error`](Self::max_error).
    pub fn from_model(model: &Model, f_star_min: f64, f_star_max: f64) -> Result<Curve, CurveError> {
        let exact = |f: f64| -> Result<f64, CurveError> {
            let c = model
                .at_f_star(f)
                .map_err(|error| CurveError::Model { f_star: f, error })?;
            match c.mu {
                Some(mu) if mu > 0.0 => Ok(mu),
                other => Err(CurveError::NoMu {
                    f_star: f,
                    mu: other.unwrap_or(f64::NAN),
                }),
            }
        };
        let node = |f: f64| model_node(model, f);
        Curve::refined(f_star_min, f_star_max, &node, &exact, CURVE_ACCURACY).map_err(|e| match e {
            CurveError::Accuracy {
                cells_per_octave,
                max_error,
                accuracy,
                f_star,
                cause: None,
            } if model
                .params()
                .constants
                .distribution
                .density()
                .is_ok_and(|d| d.has_infinite_end()) =>
            {
                CurveError::Accuracy {
                    cells_per_octave,
                    max_error,
                    accuracy,
                    f_star,
                    cause: Some(SINGULAR_END),
                }
            }
            e => e,
        })
    }

    /// Builds at 16, 32, … cells per octave until `accuracy` is met, or
    /// at most [`SPLIT_CELLS`] cells miss it and splitting them meets it.
    fn refined(
        lo: f64,
        hi: f64,
        node: &Source,
        exact: &dyn Fn(f64) -> Result<f64, CurveError>,
        accuracy: f64,
    ) -> Result<Curve, CurveError> {
        let mut worst = (f64::NAN, f64::NAN);
        for cell_bits in MIN_CELL_BITS..=MAX_CELL_BITS {
            let (mut curve, data) = Curve::build(lo, hi, cell_bits, node)?;
            let errors = curve.measure(exact)?;
            // A NaN error (a μ that is not finite) misses the accuracy.
            let misses = |e: f64| e > accuracy || e.is_nan();
            let missed: Vec<usize> = (0..errors.len()).filter(|&j| misses(errors[j].0)).collect();
            worst = errors.iter().fold((0.0, lo), |w, &e| if e.0 > w.0 { e } else { w });
            if missed.len() <= SPLIT_CELLS {
                match curve.split(&missed, &data, node, exact, accuracy)? {
                    Ok(max_split) => {
                        let kept = errors.iter().map(|e| e.0).filter(|&e| !misses(e));
                        curve.max_error = kept.fold(max_split, f64::max);
                        return Ok(curve);
                    }
                    // A piece 40 halvings narrow that misses. Where μ has
                    // a cusp |F* − F₀|^α (α ≤ 1: with α > 1 the halvings
                    // meet it long before), the error of the narrowest
                    // piece falls by at most 2 a bit of cell count, so
                    // if it misses by more than 2^(bits left) the finer
                    // builds cannot meet it either (a jump, α = 0): said
                    // now, not after them (issue 46: 4.7 s for a Pearson
                    // density near its bound).
                    Err(missed_by) if missed_by.0 > accuracy * f64::from(1u32 << (MAX_CELL_BITS - cell_bits)) => {
                        return Err(CurveError::Accuracy {
                            cells_per_octave: 1 << cell_bits,
                            max_error: missed_by.0,
                            accuracy,
                            f_star: missed_by.1,
                            cause: None,
                        })
                    }
                    Err(missed_by) => worst = missed_by,
                }
            }
        }
        Err(CurveError::Accuracy {
            cells_per_octave: 1 << MAX_CELL_BITS,
            max_error: worst.0,
            accuracy,
            f_star: worst.1,
            cause: None,
        })
    }

    /// Splits the cells `missed` (with `data`, the nodes at the cells'
    /// starts) until each piece meets `accuracy` at its midpoint and at a
    /// seeded random point: the largest error of the pieces, or the error
    /// and load of a piece that misses it after [`MAX_SPLIT_DEPTH`] halvings.
    fn split(
        &mut self,
        missed: &[usize],
        data: &[(f64, f64)],
        node: &Source,
        exact: &dyn Fn(f64) -> Result<f64, CurveError>,
        accuracy: f64,
    ) -> Result<Result<f64, (f64, f64)>, CurveError> {
        let mut rng = SplitMix64(0x2545_F491_4F6C_DD1D ^ self.lo_bits);
        let mut max_error = 0.0f64;
        for &j in missed {
            let (x0, width) = self.cell(j as u64);
            let (a, b) = (x0.max(self.range.0), (x0 + width).min(self.range.1));
            let mut stack = vec![Piece {
                t: ((a - x0) / width, (b - x0) / width),
                f: (a, b),
                at: (data[j], data[j + 1]),
                depth: 0,
            }];
            let mut pieces = Vec::new();
            while let Some(p) = stack.pop() {
                let width_f = p.f.1 - p.f.0;
                let c = hermite_in_t(p.f.0, p.f.1, p.f.0, width_f, p.at.0, p.at.1);
                let piece = |f: f64| Ok(cubic(&c, (f - p.f.0) / width_f));
                let error = sampled_error(p.f, &mut rng, &piece, exact)?;
                if error.0 <= accuracy {
                    max_error = max_error.max(error.0);
                    pieces.push((p.t.0, c, 1.0 / (p.t.1 - p.t.0)));
                    continue;
                }
                let t = 0.5 * (p.t.0 + p.t.1);
                let f = x0 + t * width;
                if p.depth >= MAX_SPLIT_DEPTH || !(f > p.f.0 && f < p.f.1) {
                    return Ok(Err(error));
                }
                let mid = node(f)?;
                let depth = p.depth + 1;
                stack.push(Piece {
                    t: (p.t.0, t),
                    f: (p.f.0, f),
                    at: (p.at.0, mid),
                    depth,
                });
                stack.push(Piece {
                    t: (t, p.t.1),
                    f: (f, p.f.1),
                    at: (mid, p.at.1),
                    depth,
                });
            }
            pieces.sort_by(|p, q| p.0.total_cmp(&q.0));
            self.coefs[j] = [f64::NAN; 4];
            self.splits.push(Split {
                cell: j,
                starts: pieces.iter().map(|p| p.0).collect(),
                coefs: pieces.iter().map(|p| p.1).collect(),
                inv_dt: pieces.iter().map(|p| p.2).collect(),
            });
        }
        self.splits.sort_by_key(|s| s.cell);
        Ok(Ok(max_error))
    }

    /// Cell `j`'s start in F* and its full width.
    fn cell(&self, j: u64) -> (f64, f64) {
        let x0 = f64::from_bits((self.first_cell + j) << self.shift);
        (x0, f64::from_bits((self.first_cell + j + 1) << self.shift) - x0)
    }

    /// The Hermite cubics at `2^cell_bits` cells per octave over [lo, hi].
    /// Also returns the nodes: (μ, dμ/dF*) at each cell's start and at `hi`.
    fn build(lo: f64, hi: f64, cell_bits: u32, node: &Source) -> Result<(Curve, Vec<(f64, f64)>), CurveError> {
        let normal = |v: f64| v.is_normal() && v > 0.0;
        if !(normal(lo) && normal(hi) && lo < hi) {
            return Err(CurveError::Range { lo, hi });
        }
        let shift = 52 - cell_bits;
        let (lo_bits, hi_bits) = (lo.to_bits(), hi.to_bits());
        let first_cell = lo_bits >> shift;
        let cells = (hi_bits >> shift) - first_cell + 1;
        if cells > MAX_CELLS {
            return Err(CurveError::TooWide { lo, hi });
        }
        // Node j is the start of cell j, cut to [lo, hi] (so the first
        // node is lo, and the last hi).
        let start = |j: u64| f64::from_bits((first_cell + j) << shift);
        let data = (0..=cells)
            .map(|j| node(start(j).clamp(lo, hi)))
            .collect::<Result<Vec<_>, _>>()?;
        let mut coefs = Vec::with_capacity(cells as usize);
        let mut inv_width = Vec::with_capacity(cells as usize);
        for j in 0..cells {
            let (x0, x1) = (start(j), start(j + 1));
            let width = x1 - x0;
            // b = a only for a last cell that starts exactly at hi, where
            // only t = 0 is ever evaluated.
            let (a, b) = (x0.max(lo), x1.min(hi));
            let j = j as usize;
            coefs.push(hermite_in_t(a, b, x0, width, data[j], data[j + 1]));
            inv_width.push(1.0 / width);
        }
        let curve = Curve {
            range: (lo, hi),
            lo_bits,
            span_bits: hi_bits - lo_bits,
            cell_bits,
            shift,
            first_cell,
            coefs,
            inv_width,
            max_error: f64::NAN,
            splits: Vec::new(),
            batch: Batch::detect(),
        };
        Ok((curve, data))
    }

    /// Per cell, the largest relative error against `exact` at its
    /// midpoint and at one seeded random point in it (within the range),
    /// and where it is.
    fn measure(&self, exact: &dyn Fn(f64) -> Result<f64, CurveError>) -> Result<Vec<(f64, f64)>, CurveError> {
        let mut rng = SplitMix64(self.lo_bits);
        let mut errors = Vec::with_capacity(self.coefs.len());
        for j in 0..self.coefs.len() as u64 {
            let (x0, width) = self.cell(j);
            let (a, b) = (x0.max(self.range.0), (x0 + width).min(self.range.1));
            let got = |f: f64| Ok(self.mu(f)?);
            errors.push(if b > a {
                sampled_error((a, b), &mut rng, &got, exact)?
            } else {
                (0.0, a)
            });
        }
        Ok(errors)
    }

    /// The range of F* this curve covers.
    pub fn range(&self) -> (f64, f64) {
        self.range
    }

    /// The largest relative error of μ measured when the curve was built
    /// (against direct integration for [`Curve::from_model`], against the
    /// table's exact interpolant for [`Table::curve`]).
    pub fn max_error(&self) -> f64 {
        self.max_error
    }

    /// The number of cells.
    pub fn cells(&self) -> usize {
        self.coefs.len()
    }

    /// The cell of `f_star`'s bits and the position in it, or `None`
    /// outside the range (NaN, ±∞, zero, negatives and subnormals all are).
    #[inline(always)]
    fn locate(&self, f_star: f64) -> Option<(&[f64; 4], f64, usize)> {
        let bits = f_star.to_bits();
        if bits.wrapping_sub(self.lo_bits) > self.span_bits {
            return None;
        }
        let j = ((bits >> self.shift) - self.first_cell) as usize;
        // The mantissa bits below the cell's, moved to the top: 1 + t exactly.
        let t = f64::from_bits(((bits << self.cell_bits) & MANTISSA) | ONE) - 1.0;
        Some((self.coefs.get(j)?, t, j))
    }

    /// μ at `f_star`. Outside [`range`](Self::range) (or NaN) it is an
    /// error naming the value and the range: nothing is extrapolated.
    #[inline]
    pub fn mu(&self, f_star: f64) -> Result<f64, LookupError> {
        match self.locate(f_star) {
            Some((c, t, j)) => {
                if self.is_split(c) {
                    return Ok(self.split_mu(j, t).0);
                }
                Ok(cubic(c, t))
            }
            None => Err(self.domain_error(f_star)),
        }
    }

    /// μ and dμ/dF* at `f_star` (for implicit solvers); errors as in
    /// [`mu`](Self::mu).
    #[inline]
    pub fn mu_with_slope(&self, f_star: f64) -> Result<(f64, f64), LookupError> {
        match self.locate(f_star) {
            Some((c, t, j)) => {
                if self.is_split(c) {
                    let (mu, slope) = self.split_mu(j, t);
                    return Ok((mu, slope * self.inv_width[j]));
                }
                Ok((cubic(c, t), cubic_slope(c, t) * self.inv_width[j]))
            }
            None => Err(self.domain_error(f_star)),
        }
    }

    /// Whether the cell of row `c` is split: its row is NaN (the first test
    /// is false for every curve without split cells, a branch predicted
    /// once).
    #[inline(always)]
    fn is_split(&self, c: &[f64; 4]) -> bool {
        !self.splits.is_empty() && c[0].is_nan()
    }

    /// μ and dμ/dt in split cell `j` at `t` (NaN if `j` is not split).
    #[cold]
    #[inline(never)]
    fn split_mu(&self, j: usize, t: f64) -> (f64, f64) {
        let Ok(i) = self.splits.binary_search_by_key(&j, |s| s.cell) else {
            return (f64::NAN, f64::NAN);
        };
        let split = &self.splits[i];
        let k = split.starts.partition_point(|&start| start <= t).saturating_sub(1);
        let s = (t - split.starts[k]) * split.inv_dt[k];
        let c = &split.coefs[k];
        (cubic(c, s), cubic_slope(c, s) * split.inv_dt[k])
    }

    /// μ for many loads, written into `out` (no allocation), bit for bit
    /// what [`mu`](Self::mu) gives (four at a time with AVX2 where the CPU
    /// has it). The batch contract of [`OnError::Stop`]: on the first load
    /// `i` outside the range (or NaN), `out[..i]` holds the results,
    /// `out[i..]` is untouched and the error is
    /// [`LookupError::BatchElement`] with index `i`.
    pub fn mu_batch(&self, f_star: &[f64], out: &mut [f64]) -> Result<(), LookupError> {
        self.mu_batch_with(f_star, out, OnError::Stop).map(|_| ())
    }

    /// [`mu_batch`](Self::mu_batch) with a policy for loads outside the
    /// range: [`OnError::Stop`] as there, or [`OnError::Nan`], which writes
    /// NaN at each such load and finishes the batch. Returns how many
    /// elements are NaN.
    ///
    /// ```
    /// # use ke_friction::{Curve, OnError, Table};
    /// let curve = Table::embedded().curve(1.0, 0.001)?;
    /// let mut mu = [0.0; 3];
    /// let n_nan = curve.mu_batch_with(&[0.01, f64::NAN, 0.02], &mut mu, OnError::Nan)?;
    /// assert!(n_nan == 1 && mu[1].is_nan() && mu[0] == curve.mu(0.01)?);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn mu_batch_with(&self, f_star: &[f64], out: &mut [f64], on_error: OnError) -> Result<usize, LookupError> {
        self.check_lengths(f_star.len(), out.len())?;
        let mut start = 0;
        let mut nan = 0;
        loop {
            let done = match self.batch {
                Some(kernel) => start + kernel.mu(self, &f_star[start..], &mut out[start..]),
                None => start,
            };
            match self.batch_from(done, f_star, out, |f| self.mu(f)) {
                None => return Ok(nan),
                Some(i) => {
                    on_error.bad(i, self.domain_error(f_star[i]))?;
                    out[i] = f64::NAN;
                    nan += 1;
                    start = i + 1;
                }
            }
        }
    }

    /// (μ, dμ/dF*) for many loads, written into `out`; the contract of
    /// [`mu_batch`](Self::mu_batch).
    pub fn mu_with_slope_batch(&self, f_star: &[f64], out: &mut [(f64, f64)]) -> Result<(), LookupError> {
        self.mu_with_slope_batch_with(f_star, out, OnError::Stop).map(|_| ())
    }

    /// [`mu_with_slope_batch`](Self::mu_with_slope_batch) with a policy
    /// (see [`mu_batch_with`](Self::mu_batch_with)); NaN pairs at bad loads.
    pub fn mu_with_slope_batch_with(
        &self,
        f_star: &[f64],
        out: &mut [(f64, f64)],
        on_error: OnError,
    ) -> Result<usize, LookupError> {
        self.check_lengths(f_star.len(), out.len())?;
        let (mut start, mut nan) = (0, 0);
        while let Some(i) = self.batch_from(start, f_star, out, |f| self.mu_with_slope(f)) {
            on_error.bad(i, self.domain_error(f_star[i]))?;
            out[i] = (f64::NAN, f64::NAN);
            nan += 1;
            start = i + 1;
        }
        Ok(nan)
    }

    /// [`mu_with_slope_batch_with`](Self::mu_with_slope_batch_with) into
    /// two arrays, `mu` and `slope` (as C and NumPy hold them), through a
    /// stack buffer: no allocation. The three slices have one length
    /// ([`LookupError::CurveLengthMismatch`] otherwise, `out` the first of
    /// `mu` and `slope` that differs); errors and NaNs as the pairs batch.
    pub fn mu_with_slope_into(
        &self,
        f_star: &[f64],
        mu: &mut [f64],
        slope: &mut [f64],
        on_error: OnError,
    ) -> Result<usize, LookupError> {
        self.check_lengths(f_star.len(), mu.len())?;
        self.check_lengths(f_star.len(), slope.len())?;
        crate::table::scatter_pairs(mu, slope, |r, out| {
            self.mu_with_slope_batch_with(&f_star[r], out, on_error)
        })
    }

    /// The error for slices of different lengths.
    fn check_lengths(&self, f_star: usize, out: usize) -> Result<(), LookupError> {
        if f_star == out {
            Ok(())
        } else {
            Err(LookupError::CurveLengthMismatch { f_star, out })
        }
    }

    /// The loop from load `start` on (those before it are done) up to the
    /// first bad load, whose index it returns (`out` untouched from it).
    #[inline(always)]
    fn batch_from<T>(
        &self,
        start: usize,
        f_star: &[f64],
        out: &mut [T],
        one: impl Fn(f64) -> Result<T, LookupError>,
    ) -> Option<usize> {
        for (i, (&f, o)) in f_star.iter().zip(out.iter_mut()).enumerate().skip(start) {
            match one(f) {
                Ok(v) => *o = v,
                Err(_) => return Some(i),
            }
        }
        None
    }

    /// The error for a load outside the range.
    #[cold]
    fn domain_error(&self, value: f64) -> LookupError {
        LookupError::OutOfDomain {
            name: "f_star",
            value,
            lo: self.range.0,
            hi: self.range.1,
        }
    }
}

impl Table {
    /// The curve μ(F*) of this table at fixed (ψ, θ), over the table's
    /// range of F*: built in microseconds from the table's exact (f64)
    /// interpolant, for simulators with many surface pairs. Its error
    /// against direct integration is at most the table's
    /// ([`TableInfo::tolerance`](crate::TableInfo::tolerance)) plus what the
    /// curve adds ([`Curve::max_error`], measured against the interpolant
    /// when it is built).
    pub fn curve(&self, psi: f64, theta: f64) -> Result<Curve, CurveError> {
        let (lo, hi) = self.domain().f_star;
        let node = |f: f64| -> Result<(f64, f64), CurveError> { Ok(self.mu_with_slope_portable(psi, theta, f)?) };
        let exact = |f: f64| -> Result<f64, CurveError> { Ok(self.mu_portable(psi, theta, f)?) };
        Curve::refined(lo, hi, &node, &exact, CURVE_ACCURACY)
    }
}

/// μ and dμ/dF* of `model` at F* = `f` ([`Model::mu_with_slope_at_f_star`]),
/// μ positive.
fn model_node(model: &Model, f: f64) -> Result<(f64, f64), CurveError> {
    let (mu, slope) = model
        .mu_with_slope_at_f_star(f)
        .map_err(|error| CurveError::Model { f_star: f, error })?;
    if mu > 0.0 {
        Ok((mu, slope))
    } else {
        Err(CurveError::NoMu { f_star: f, mu })
    }
}

/// The larger relative error of `got` against `exact` at the midpoint of
/// `[a, b]` and at a random point in it, and where it is (NaN, a μ that is
/// not finite, counts as the larger).
fn sampled_error(
    (a, b): (f64, f64),
    rng: &mut SplitMix64,
    got: &dyn Fn(f64) -> Result<f64, CurveError>,
    exact: &dyn Fn(f64) -> Result<f64, CurveError>,
) -> Result<(f64, f64), CurveError> {
    let mut worst = (0.0f64, a);
    for f in [0.5 * (a + b), a + rng.unit() * (b - a)] {
        let want = exact(f)?;
        let error = ((got(f)? - want) / want).abs();
        if error > worst.0 || error.is_nan() {
            worst = (error, f);
        }
    }
    Ok(worst)
}

/// The cubic Hermite interpolant of (μ, dμ/dF*) at `a` and `b`, as a
/// polynomial in the cell coordinate t, where F* = x0 + t·width.
fn hermite_in_t(a: f64, b: f64, x0: f64, width: f64, (mu_a, d_a): (f64, f64), (mu_b, d_b): (f64, f64)) -> [f64; 4] {
    if b <= a {
        // A cell of one point (its start, t = 0): the value and the slope.
        return [mu_a, d_a * width, 0.0, 0.0];
    }
    // In u = (F* − a)/(b − a) ∈ [0, 1].
    let w = b - a;
    let c = [
        mu_a,
        w * d_a,
        3.0 * (mu_b - mu_a) - w * (2.0 * d_a + d_b),
        2.0 * (mu_a - mu_b) + w * (d_a + d_b),
    ];
    // u = α + β·t: a Taylor expansion of the cubic about u = α.
    let (alpha, beta) = ((x0 - a) / w, width / w);
    [
        ((c[3] * alpha + c[2]) * alpha + c[1]) * alpha + c[0],
        beta * ((3.0 * c[3] * alpha + 2.0 * c[2]) * alpha + c[1]),
        beta * beta * (3.0 * c[3] * alpha + c[2]),
        beta * beta * beta * c[3],
    ]
}

/// c0 + c1·t + c2·t² + c3·t³ by Estrin's scheme (two short chains).
#[inline(always)]
fn cubic(c: &[f64; 4], t: f64) -> f64 {
    (c[3] * t + c[2]) * (t * t) + (c[1] * t + c[0])
}

/// d/dt of [`cubic`].
#[inline(always)]
fn cubic_slope(c: &[f64; 4], t: f64) -> f64 {
    (3.0 * c[3] * t + 2.0 * c[2]) * t + c[1]
}

impl crate::Classify for CurveError {
    /// By cause: a bad range is `Argument`, the model's or lookup's error
    /// keeps its kind, no positive μ is `NoMu`, a missed accuracy is
    /// `Tolerance`.
    fn kind(&self) -> crate::ErrorKind {
        use CurveError::*;
        match self {
            Range { .. } => crate::ErrorKind::Argument,
            TooWide { .. } => crate::ErrorKind::Domain,
            Model { error, .. } => error.kind(),
            NoMu { .. } => crate::ErrorKind::NoMu,
            Lookup(e) => e.kind(),
            Accuracy { .. } => crate::ErrorKind::Tolerance,
        }
    }
}

#[cfg(test)]
mod tests;
