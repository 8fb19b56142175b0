//! The portable lookup kernel: the interpolant in f64 arithmetic without
//! fused multiply-adds, the same bits on every machine.

use super::layout::{Cell, Layout};
use crate::spline::weight_slopes;

/// Σ w_ψ·w_θ·w_F·c over the query's 4×4×4 block of `c`.
#[inline(always)]
pub fn blend(layout: &Layout, c: &[f64], cell: &Cell) -> f64 {
    let wf = &cell.w_f_star;
    let block = Block::new(layout, c, cell);
    let mut sum = 0.0;
    for a in 0..4 {
        let mut plane = 0.0;
        for b in 0..4 {
            let row = block.row(a, b);
            let r = row[0] * wf[0] + row[1] * wf[1] + row[2] * wf[2] + row[3] * wf[3];
            plane += cell.w_theta[b] * r;
        }
        sum += cell.w_psi[a] * plane;
    }
    sum
}

/// [`blend`] and its derivative along the F* cell coordinate, in one pass.
#[inline(always)]
pub fn blend_with_slope(layout: &Layout, c: &[f64], cell: &Cell) -> (f64, f64) {
    let (wf, df) = (&cell.w_f_star, weight_slopes(cell.f_star_offset));
    let block = Block::new(layout, c, cell);
    let (mut sum, mut dsum) = (0.0, 0.0);
    for a in 0..4 {
        let (mut plane, mut dplane) = (0.0, 0.0);
        for b in 0..4 {
            let row = block.row(a, b);
            let r = row[0] * wf[0] + row[1] * wf[1] + row[2] * wf[2] + row[3] * wf[3];
            let dr = row[0] * df[0] + row[1] * df[1] + row[2] * df[2] + row[3] * df[3];
            plane += cell.w_theta[b] * r;
            dplane += cell.w_theta[b] * dr;
        }
        sum += cell.w_psi[a] * plane;
        dsum += cell.w_psi[a] * dplane;
    }
    (sum, dsum)
}

/// A query's 4×4×4 block of coefficients, bounds-checked once.
struct Block<'a> {
    /// The coefficients from the block's first one on: exactly
    /// `3·s0 + 3·s1 + 4` of them.
    c: &'a [f64],
    /// The strides along ψ and θ.
    s0: usize,
    s1: usize,
}

impl<'a> Block<'a> {
    /// The block of `cell` in `c`. Panics if it does not fit, which a
    /// cell located by [`Layout::cell`] in an array of
    /// [`Layout::coefficients`] values always does.
    #[inline(always)]
    fn new(layout: &Layout, c: &'a [f64], cell: &Cell) -> Block<'a> {
        let [s0, s1, _] = layout.strides;
        Block {
            c: &c[cell.base..cell.base + 3 * s0 + 3 * s1 + 4],
            s0,
            s1,
        }
    }

    /// The four coefficients along F* on ψ plane `a` and θ row `b` of the
    /// block (each taken mod 4; the loops' constants fold the masks away).
    #[inline(always)]
    fn row(&self, a: usize, b: usize) -> &[f64] {
        let offset = (a & 3) * self.s0 + (b & 3) * self.s1;
        // SAFETY: offset + 4 ≤ 3·s0 + 3·s1 + 4 = self.c.len(), the length
        // `new` sliced.
        unsafe { self.c.get_unchecked(offset..offset + 4) }
    }
}
