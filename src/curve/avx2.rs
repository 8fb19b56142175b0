//! The curve's batch lookup on x86-64 CPUs with AVX2: four loads at a time,
//! with the very operations of the scalar [`cubic`](super::cubic) in the
//! same order (multiplies and adds, no fused multiply-adds), so a batch
//! gives bit for bit what single lookups give.

use super::{BatchKernel, Curve, MANTISSA, ONE};
use core::arch::x86_64::*;

/// Proof that this CPU runs AVX2: made only by [`Batch::detect`].
#[derive(Debug, Clone, Copy)]
pub(super) struct Batch(());

impl BatchKernel for Batch {
    /// The batch kernel, if this CPU has AVX2.
    fn detect() -> Option<Batch> {
        std::is_x86_feature_detected!("avx2").then_some(Batch(()))
    }

    /// μ for the loads of `f_star` four at a time into `out` (of the same
    /// length), up to the first group of four holding a load outside the
    /// range; returns how many loads it did (a multiple of four).
    fn mu(self, curve: &Curve, f_star: &[f64], out: &mut [f64]) -> usize {
        assert_eq!(f_star.len(), out.len(), "one output per load");
        // SAFETY: a `Batch` exists only where `detect` found AVX2.
        unsafe { mu_groups(curve, f_star, out) }
    }
}

/// [`Batch::mu`].
///
/// # Safety
/// The CPU must support AVX2.
#[target_feature(enable = "avx2")]
unsafe fn mu_groups(curve: &Curve, f_star: &[f64], out: &mut [f64]) -> usize {
    let lo = _mm256_set1_epi64x(curve.lo_bits as i64);
    // Unsigned `bits − lo > span` as a signed compare, both sides with
    // their sign bit flipped.
    let sign = _mm256_set1_epi64x(i64::MIN);
    let span = _mm256_xor_si256(_mm256_set1_epi64x(curve.span_bits as i64), sign);
    let shift = _mm_cvtsi64_si128(curve.shift as i64);
    let cell_bits = _mm_cvtsi64_si128(curve.cell_bits as i64);
    let first = _mm256_set1_epi64x(curve.first_cell as i64);
    let mantissa = _mm256_set1_epi64x(MANTISSA as i64);
    let one_bits = _mm256_set1_epi64x(ONE as i64);
    let one = _mm256_set1_pd(1.0);
    let mut done = 0;
    let mut split = _mm256_setzero_pd();
    for (f, o) in f_star.chunks_exact(4).zip(out.chunks_exact_mut(4)) {
        // SAFETY: `f` holds 4 f64 (chunks_exact).
        let bits = _mm256_castpd_si256(unsafe { _mm256_loadu_pd(f.as_ptr()) });
        let offset = _mm256_xor_si256(_mm256_sub_epi64(bits, lo), sign);
        if _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpgt_epi64(offset, span))) != 0 {
            break;
        }
        // The cells and the positions in them, as in `Curve::locate`.
        let cells = _mm256_sub_epi64(_mm256_srl_epi64(bits, shift), first);
        let t = _mm256_sub_pd(
            _mm256_castsi256_pd(_mm256_or_si256(
                _mm256_and_si256(_mm256_sll_epi64(bits, cell_bits), mantissa),
                one_bits,
            )),
            one,
        );
        let mut j = [0u64; 4];
        // SAFETY: `j` holds 4 u64.
        unsafe { _mm256_storeu_si256(j.as_mut_ptr().cast(), cells) };
        // Bounds-checked: a load in the range has its cell in `coefs`.
        let rows = j.map(|j| &curve.coefs[j as usize]);
        // SAFETY: each row is a `[f64; 4]`.
        let [r0, r1, r2, r3] = rows.map(|r| unsafe { _mm256_loadu_pd(r.as_ptr()) });
        // Transposed: c_k holds coefficient k of the four loads.
        let (t01, t23) = (_mm256_unpacklo_pd(r0, r1), _mm256_unpacklo_pd(r2, r3));
        let (u01, u23) = (_mm256_unpackhi_pd(r0, r1), _mm256_unpackhi_pd(r2, r3));
        let c0 = _mm256_permute2f128_pd::<0x20>(t01, t23);
        let c2 = _mm256_permute2f128_pd::<0x31>(t01, t23);
        let c1 = _mm256_permute2f128_pd::<0x20>(u01, u23);
        let c3 = _mm256_permute2f128_pd::<0x31>(u01, u23);
        // (c3·t + c2)·(t·t) + (c1·t + c0), as `cubic` computes it.
        let high = _mm256_add_pd(_mm256_mul_pd(c3, t), c2);
        let low = _mm256_add_pd(_mm256_mul_pd(c1, t), c0);
        let mu = _mm256_add_pd(_mm256_mul_pd(high, _mm256_mul_pd(t, t)), low);
        // SAFETY: `o` holds 4 f64 (chunks_exact_mut).
        unsafe { _mm256_storeu_pd(o.as_mut_ptr(), mu) };
        // A split cell's row is NaN, and nothing else gives NaN here.
        split = _mm256_or_pd(split, _mm256_cmp_pd::<_CMP_UNORD_Q>(mu, mu));
        done += 4;
    }
    if _mm256_movemask_pd(split) != 0 {
        // Loads in split cells, one at a time.
        for (&f, o) in f_star[..done].iter().zip(&mut out[..done]) {
            if o.is_nan() {
                *o = curve.mu(f).unwrap_or(f64::NAN);
            }
        }
    }
    done
}
