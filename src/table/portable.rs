//! The portable lookup kernel: the interpolant in f64 arithmetic without
//! fused multiply-adds, the same bits on every machine.

use super::layout::{Cell, Layout};
use crate::spline::weight_slopes;

/// Σ w_ψ·w_θ·w_F·c over the query's 4×4×4 block of `c`.
#[inline(always)]
pub fn blend(layout: &Layout, c: &[f64], cell: &Cell) -> f64 {
    let [s0, s1, _] = layout.strides;
    let wf = &cell.w_f_star;
    // One bounds check for the whole block (its last element).
    let _ = c[cell.base + 3 * s0 + 3 * s1 + 3];
    let mut sum = 0.0;
    for a in 0..4 {
        let mut plane = 0.0;
        for b in 0..4 {
            let o = cell.base + a * s0 + b * s1;
            // SAFETY: a, b < 4, so o + 3 ≤ base + 3·s0 + 3·s1 + 3, the
            // index checked above.
            let row = unsafe { c.get_unchecked(o..o + 4) };
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
    let [s0, s1, _] = layout.strides;
    let (wf, df) = (&cell.w_f_star, weight_slopes(cell.f_star_offset));
    let _ = c[cell.base + 3 * s0 + 3 * s1 + 3];
    let (mut sum, mut dsum) = (0.0, 0.0);
    for a in 0..4 {
        let (mut plane, mut dplane) = (0.0, 0.0);
        for b in 0..4 {
            let o = cell.base + a * s0 + b * s1;
            // SAFETY: as in `blend`: o + 3 is at most the index checked above.
            let row = unsafe { c.get_unchecked(o..o + 4) };
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
