//! The lookup kernels for x86-64 CPUs with AVX2 and FMA (chosen at run time
//! by [`Table`]'s constructor).
//!
//! The B-spline weights of an axis form one vector (Horner's rule in the
//! cell offset); each row of four F* coefficients is one vector load, so a
//! lookup is 16 loads and 20 fused multiply-adds. The batch kernel also
//! maps, locates and weighs four queries at a time, then blends each and
//! takes the four exponentials at once. Every operation mirrors the
//! single-query kernel's, so a batch returns bit for bit what [`eval`]
//! returns for each of its queries.

use super::fastmath::{self, Num};
use super::Table;
use crate::spline::BASIS;
use core::arch::x86_64::*;

/// Four lanes.
#[derive(Clone, Copy)]
struct V(__m256d);

impl Num for V {
    #[inline(always)]
    fn splat(c: f64) -> Self {
        // SAFETY: AVX is available in every caller (the AVX2 kernels).
        V(unsafe { _mm256_set1_pd(c) })
    }
    #[inline(always)]
    fn madd(self, b: Self, c: Self) -> Self {
        // SAFETY: as above (FMA too).
        V(unsafe { _mm256_fmadd_pd(self.0, b.0, c.0) })
    }
    #[inline(always)]
    fn mul(self, b: Self) -> Self {
        // SAFETY: as above.
        V(unsafe { _mm256_mul_pd(self.0, b.0) })
    }
}

/// The four B-spline weights at offset `f` ([`BASIS`] by Horner's rule).
#[inline(always)]
unsafe fn weights(f: f64) -> __m256d {
    let f = _mm256_set1_pd(f);
    let [a, b, c, d] = BASIS.map(|v| _mm256_loadu_pd(v.as_ptr()));
    _mm256_fmadd_pd(_mm256_fmadd_pd(_mm256_fmadd_pd(a, f, b), f, c), f, d)
}

/// Their derivatives, (3A·f + 2B)·f + C.
#[inline(always)]
unsafe fn weight_slopes(f: f64) -> __m256d {
    let f = _mm256_set1_pd(f);
    let [a, b, c, _] = BASIS.map(|v| _mm256_loadu_pd(v.as_ptr()));
    let a3 = _mm256_mul_pd(a, _mm256_set1_pd(3.0));
    _mm256_fmadd_pd(_mm256_fmadd_pd(a3, f, _mm256_add_pd(b, b)), f, c)
}

/// Σ wp[a]·wt[b]·(row_ab · wf) over the block at `p`, and the same with
/// `df` in place of `wf` if `SLOPE`.
#[inline(always)]
unsafe fn blend<const SLOPE: bool>(
    p: *const f64,
    s0: usize,
    s1: usize,
    wp: &[f64; 4],
    wt: &[f64; 4],
    wf: __m256d,
    ff: f64,
) -> (f64, f64) {
    let mut acc = _mm256_setzero_pd();
    for (i, w) in wp.iter().enumerate() {
        let q = p.add(i * s0);
        let mut plane = _mm256_mul_pd(_mm256_set1_pd(wt[0]), _mm256_loadu_pd(q));
        plane = _mm256_fmadd_pd(_mm256_set1_pd(wt[1]), _mm256_loadu_pd(q.add(s1)), plane);
        plane = _mm256_fmadd_pd(_mm256_set1_pd(wt[2]), _mm256_loadu_pd(q.add(2 * s1)), plane);
        plane = _mm256_fmadd_pd(_mm256_set1_pd(wt[3]), _mm256_loadu_pd(q.add(3 * s1)), plane);
        acc = _mm256_fmadd_pd(_mm256_set1_pd(*w), plane, acc);
    }
    let v = _mm256_mul_pd(acc, wf);
    let dv = if SLOPE {
        _mm256_mul_pd(acc, weight_slopes(ff))
    } else {
        _mm256_setzero_pd()
    };
    let h = _mm256_hadd_pd(v, dv); // [v0+v1, d0+d1, v2+v3, d2+d3]
    let s = _mm_add_pd(_mm256_castpd256_pd128(h), _mm256_extractf128_pd(h, 1));
    (_mm_cvtsd_f64(s), _mm_cvtsd_f64(_mm_unpackhi_pd(s, s)))
}

/// One lookup: μ and, if `SLOPE`, d ln μ/d(cell coordinate of F*); μ is
/// NaN (never otherwise) for a query outside the domain. A pair of floats
/// comes back in registers, where a `Result` would go through memory.
///
/// # Safety
/// The CPU must support AVX2 and FMA.
#[target_feature(enable = "avx2,fma")]
pub unsafe fn eval<const SLOPE: bool>(t: &Table, psi: f64, theta: f64, f_star: f64) -> (f64, f64) {
    let Some((base, frac)) = t.locate::<true>(psi, theta, f_star) else {
        return (f64::NAN, f64::NAN);
    };
    let [s0, s1] = t.strides;
    let c = &t.ln_mu;
    // One bounds check for the whole block (its last element).
    let _ = c[base + 3 * s0 + 3 * s1 + 3];
    let mut wp = [0.0; 4];
    let mut wt = [0.0; 4];
    _mm256_storeu_pd(wp.as_mut_ptr(), weights(frac[0]));
    _mm256_storeu_pd(wt.as_mut_ptr(), weights(frac[1]));
    let (ln_mu, d) = blend::<SLOPE>(c.as_ptr().add(base), s0, s1, &wp, &wt, weights(frac[2]), frac[2]);
    (fastmath::exp::<true>(ln_mu), d)
}

/// μ for every query, four at a time; returns the index of the first
/// query outside the domain (`out` is then partly written).
///
/// # Safety
/// The CPU must support AVX2 and FMA; the slices have `out`'s length.
#[target_feature(enable = "avx2,fma")]
pub unsafe fn batch(t: &Table, psi: &[f64], theta: &[f64], f_star: &[f64], out: &mut [f64]) -> Option<usize> {
    let n = out.len();
    let d = &t.domain;
    let lo = [d.psi.0, d.theta.0, d.f_star.0].map(|v| _mm256_set1_pd(v));
    let hi = [d.psi.1, d.theta.1, d.f_star.1].map(|v| _mm256_set1_pd(v));
    let [s0, s1] = t.strides;
    let c = t.ln_mu.as_ptr();
    // The largest base offset any in-domain query can have: checked once.
    let max_base = (0..3).map(|k| t.last_cell[k] * t.stride3[k]).sum::<usize>();
    let _ = t.ln_mu[max_base + 3 * s0 + 3 * s1 + 3];
    let mut i = 0;
    while i + 4 <= n {
        let x = [
            _mm256_loadu_pd(psi.as_ptr().add(i)),
            _mm256_loadu_pd(theta.as_ptr().add(i)),
            _mm256_loadu_pd(f_star.as_ptr().add(i)),
        ];
        // Ordered comparisons: NaN fails them.
        let mut ok = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
        for k in 0..3 {
            ok = _mm256_and_pd(ok, _mm256_cmp_pd::<_CMP_GE_OQ>(x[k], lo[k]));
            ok = _mm256_and_pd(ok, _mm256_cmp_pd::<_CMP_LE_OQ>(x[k], hi[k]));
        }
        if _mm256_movemask_pd(ok) != 0b1111 {
            // Some query is out: the single-query kernel finds which.
            for j in i..i + 4 {
                out[j] = eval::<false>(t, psi[j], theta[j], f_star[j]).0;
                if out[j].is_nan() {
                    return Some(j);
                }
            }
            i += 4;
            continue;
        }
        let coords = [ln4(x[0]), _mm256_sqrt_pd(x[1]), ln4(x[2])];
        let mut base = _mm256_setzero_pd();
        let mut frac = [[0.0; 4]; 3];
        for k in 0..3 {
            let s = _mm256_fmadd_pd(coords[k], _mm256_set1_pd(t.inv_step[k]), _mm256_set1_pd(t.offset[k]));
            let cell = _mm256_min_pd(_mm256_floor_pd(s), _mm256_set1_pd(t.last_cell[k] as f64));
            _mm256_storeu_pd(frac[k].as_mut_ptr(), _mm256_sub_pd(s, cell));
            // Offsets are small integers: exact in f64.
            base = _mm256_fmadd_pd(cell, _mm256_set1_pd(t.stride3[k] as f64), base);
        }
        let mut offsets = [0i32; 4];
        _mm_storeu_si128(offsets.as_mut_ptr().cast(), _mm256_cvttpd_epi32(base));
        let mut ln_mu = [0.0; 4];
        for q in 0..4 {
            let mut wp = [0.0; 4];
            let mut wt = [0.0; 4];
            _mm256_storeu_pd(wp.as_mut_ptr(), weights(frac[0][q]));
            _mm256_storeu_pd(wt.as_mut_ptr(), weights(frac[1][q]));
            let p = c.add(offsets[q] as usize);
            ln_mu[q] = blend::<false>(p, s0, s1, &wp, &wt, weights(frac[2][q]), 0.0).0;
        }
        _mm256_storeu_pd(out.as_mut_ptr().add(i), exp4(_mm256_loadu_pd(ln_mu.as_ptr())));
        i += 4;
    }
    for j in i..n {
        out[j] = eval::<false>(t, psi[j], theta[j], f_star[j]).0;
        if out[j].is_nan() {
            return Some(j);
        }
    }
    None
}

/// [`fastmath::ln`] on four lanes, operation for operation.
#[inline(always)]
unsafe fn ln4(x: __m256d) -> __m256d {
    let bits = _mm256_castpd_si256(x);
    let tmp = _mm256_sub_epi64(bits, _mm256_set1_epi64x(fastmath::LN_OFFSET as i64));
    // e = tmp >> 52 (arithmetic). AVX2 has no 64-bit arithmetic shift:
    // shift logically (0 ≤ k < 4096), convert exactly through 2^52, and
    // fold k ≥ 2048 back to k − 4096.
    let k = _mm256_srli_epi64::<52>(tmp);
    let two52 = _mm256_set1_pd(4_503_599_627_370_496.0);
    let kf = _mm256_sub_pd(
        _mm256_castsi256_pd(_mm256_or_si256(k, _mm256_castpd_si256(two52))),
        two52,
    );
    let wrap = _mm256_and_pd(
        _mm256_cmp_pd::<_CMP_GE_OQ>(kf, _mm256_set1_pd(2048.0)),
        _mm256_set1_pd(4096.0),
    );
    let e = _mm256_sub_pd(kf, wrap);
    let top = _mm256_and_si256(tmp, _mm256_set1_epi64x(0xfff0_0000_0000_0000u64 as i64));
    let m = _mm256_castsi256_pd(_mm256_sub_epi64(bits, top));
    let one = _mm256_set1_pd(1.0);
    let s = _mm256_div_pd(_mm256_sub_pd(m, one), _mm256_add_pd(m, one));
    let z = _mm256_mul_pd(s, s);
    let p = _mm256_mul_pd(fastmath::ln_poly(V(z)).0, z);
    let two_s = _mm256_add_pd(s, s);
    let tail = _mm256_fmadd_pd(two_s, p, _mm256_mul_pd(e, _mm256_set1_pd(fastmath::LN2_LO)));
    _mm256_fmadd_pd(e, _mm256_set1_pd(fastmath::LN2_HI), _mm256_add_pd(two_s, tail))
}

/// [`fastmath::exp`] on four lanes, operation for operation.
#[inline(always)]
unsafe fn exp4(x: __m256d) -> __m256d {
    let shift = _mm256_set1_pd(fastmath::EXP_SHIFT);
    let shifted = _mm256_fmadd_pd(x, _mm256_set1_pd(core::f64::consts::LOG2_E), shift);
    let k = _mm256_sub_pd(shifted, shift);
    let k_int = _mm256_sub_epi64(_mm256_castpd_si256(shifted), _mm256_castpd_si256(shift));
    let nk = _mm256_sub_pd(_mm256_setzero_pd(), k);
    let r = _mm256_fmadd_pd(
        nk,
        _mm256_set1_pd(fastmath::LN2_LO),
        _mm256_fmadd_pd(nk, _mm256_set1_pd(fastmath::LN2_HI), x),
    );
    let p = fastmath::exp_poly(V(r)).0;
    let scale = _mm256_slli_epi64::<52>(_mm256_add_epi64(k_int, _mm256_set1_epi64x(1023)));
    _mm256_mul_pd(p, _mm256_castsi256_pd(scale))
}
