//! Where a query falls in a table: the domain check, the map to cell
//! coordinates, and the offset of the 4×4×4 block of coefficients the
//! lookup blends. Both kernels are built from a [`Layout`].

use super::format::AxisSpec;
use super::LookupError;
use crate::num::Shortest;
use crate::spline::{weights, Axis, Scale};

/// The argument names, in axis order (as [`LookupError`] reports them).
pub const NAMES: [&str; 3] = ["psi", "theta", "f_star"];

/// The largest coefficient array a table may have (2^28 values per array).
pub const MAX_COEFS: usize = 1 << 28;

/// An axis's spacing relative to its coordinates: each step must be at
/// least this times max(1, the largest |coordinate| of its nodes). The
/// maps (ln, √) are accurate to about 1e-16 of max(1, |coordinate|), so a
/// query's cell coordinate is then accurate to about 1e-4 of a cell; a
/// finer step would make it noise (a step of 1e-17 at ln 0.01 would put an
/// in-domain query hundreds of cells before the first).
pub const MIN_RELATIVE_STEP: f64 = 1e-12;

/// The lookup grid of a table: its axes, its domain and the strides of its
/// coefficient arrays (shape (nψ, nθ, nF), F* fastest).
#[derive(Debug, Clone)]
pub struct Layout {
    /// The ψ, θ, F* axes, ghost nodes included.
    pub axes: [Axis; 3],
    /// Per axis, the domain `[lo, hi]`: lookups outside are errors.
    pub ranges: [(f64, f64); 3],
    /// Strides of the coefficient arrays along ψ, θ, F* (the last is 1).
    pub strides: [usize; 3],
    /// Per axis: 1/spacing.
    pub inv_step: [f64; 3],
    /// Per axis, −first/spacing: the cell coordinate of a query is
    /// `coordinate·inv_step + offset`.
    pub offset: [f64; 3],
    /// Per axis: the index of the last cell (each cell spans 4 nodes).
    pub last_cell: [usize; 3],
}

/// A located query: the offset of its block and the B-spline weights.
#[derive(Debug, Clone, Copy)]
pub struct Cell {
    /// Index of the block's first coefficient.
    pub base: usize,
    /// The four weights along ψ.
    pub w_psi: [f64; 4],
    /// The four weights along θ.
    pub w_theta: [f64; 4],
    /// The four weights along F*.
    pub w_f_star: [f64; 4],
    /// The query's offset in its cell along F* (for the weights' slopes).
    pub f_star_offset: f64,
}

impl Layout {
    /// The layout of a stored grid, or why it is unusable. Only the maps
    /// the kernels implement are accepted: ln ψ, √θ, ln F*.
    pub fn new(specs: &[AxisSpec; 3]) -> Result<Layout, String> {
        let axes = [axis(0, specs)?, axis(1, specs)?, axis(2, specs)?];
        // The lookup kernels map ψ, θ, F* through ln, √, ln: a file with
        // other maps would be misread, not just read slowly.
        if axes.map(|a| a.scale) != [Scale::Log, Scale::Sqrt, Scale::Log] {
            return Err("the axes must map psi, theta, f_star by ln, sqrt, ln".into());
        }
        let count = axes
            .iter()
            .map(|x| x.nodes + 2)
            .try_fold(1usize, |acc, n| acc.checked_mul(n));
        if count.is_none_or(|n| n > MAX_COEFS) {
            return Err("grid is too large".into());
        }
        Ok(Layout {
            axes,
            ranges: specs.map(|s| (s.lo, s.hi)),
            strides: [(axes[1].nodes + 2) * (axes[2].nodes + 2), axes[2].nodes + 2, 1],
            inv_step: axes.map(|a| 1.0 / a.step),
            offset: axes.map(|a| -a.first / a.step),
            last_cell: axes.map(|a| a.nodes - 2),
        })
    }

    /// The number of coefficients per array: (nψ + 2)(nθ + 2)(nF + 2).
    pub fn coefficients(&self) -> usize {
        self.strides[0] * (self.axes[0].nodes + 2)
    }

    /// `Ok` for a query inside the domain; otherwise the error naming the
    /// first argument outside its range (or NaN).
    #[inline(always)]
    pub fn check(&self, psi: f64, theta: f64, f_star: f64) -> Result<(), LookupError> {
        for ((name, value), (lo, hi)) in NAMES.into_iter().zip([psi, theta, f_star]).zip(self.ranges) {
            if !(value >= lo && value <= hi) {
                return Err(LookupError::OutOfDomain { name, value, lo, hi });
            }
        }
        Ok(())
    }

    /// Checks and locates a query (ln ψ, √θ, ln F* by the portable maps).
    #[inline(always)]
    pub fn cell(&self, psi: f64, theta: f64, f_star: f64) -> Result<Cell, LookupError> {
        self.check(psi, theta, f_star)?;
        let coords = [super::fastmath::ln(psi), theta.sqrt(), super::fastmath::ln(f_star)];
        let mut base = 0;
        let mut frac = [0.0; 3];
        for k in 0..3 {
            let s = coords[k] * self.inv_step[k] + self.offset[k];
            // i64 conversions are single instructions (usize ones, and
            // floor without SSE4.1, are not). The cell is clamped at both
            // ends whatever `s` is (NaN converts to 0), so the block lies
            // inside the coefficients by construction: base + 3·s0 + 3·s1
            // + 3 ≤ the last index, as `portable::blend` checks.
            let i = (s as i64).clamp(0, self.last_cell[k] as i64);
            base += i as usize * self.strides[k];
            frac[k] = s - i as f64;
        }
        Ok(Cell {
            base,
            w_psi: weights(frac[0]),
            w_theta: weights(frac[1]),
            w_f_star: weights(frac[2]),
            f_star_offset: frac[2],
        })
    }
}

/// Validates stored axis `k` and converts it.
fn axis(k: usize, specs: &[AxisSpec; 3]) -> Result<Axis, String> {
    let (name, s) = (NAMES[k], &specs[k]);
    let Some(scale) = Scale::from_code(s.scale) else {
        return Err(format!("{name} axis: unknown scale code {}", s.scale));
    };
    let nodes = s.nodes as usize;
    if !(5..=1 << 20).contains(&nodes) {
        return Err(format!("{name} axis: {nodes} nodes (must be 5 to {})", 1 << 20));
    }
    if !(s.first.is_finite() && s.step.is_finite() && s.step > 0.0) {
        return Err(format!(
            "{name} axis: first node {} and step {} (must be finite, step > 0)",
            Shortest(s.first),
            Shortest(s.step)
        ));
    }
    // The largest |coordinate| of a node: the cell coordinate of a query is
    // computed to about 1e-16 of it (or of 1), which must be small next to
    // a step.
    let extent = s.first.abs().max((s.first + s.step * (nodes - 1) as f64).abs());
    if !(extent.is_finite() && s.step >= MIN_RELATIVE_STEP * extent.max(1.0)) {
        return Err(format!(
            "{name} axis: step {} is below {MIN_RELATIVE_STEP:e} of max(1, largest |node coordinate| = {}): cell coordinates would not be accurate",
            Shortest(s.step),
            Shortest(extent)
        ));
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
