//! The fast lookup kernel: x86-64 CPUs with AVX2 and FMA, tables stored in
//! single precision (chosen at run time by the table's constructor).
//!
//! It works in f32 throughout, eight queries to a vector: the maps ln ψ,
//! √θ, ln F*, the cell search, the ψ weights and the final exponential
//! are computed for eight queries at once; each query's 4×4×4 block is
//! then blended with eight fused multiply-adds, one per half of each ψ
//! plane's 16 contiguous (θ, F*) coefficients. The single-query kernel
//! runs the very same operations on one query (its three axes in the
//! lanes of one vector), so a batch returns bit for bit what [`eval`]
//! returns.
//!
//! f32 arithmetic moves μ by up to ~3e-6 relative (mostly from summing
//! ln μ, which reaches −9 in the default table, in f32; the coefficients
//! are f32 already); the portable f64 kernel is the exact interpolant.

use super::layout::Layout;
use super::BatchOutput;
use crate::spline::BASIS;
use core::arch::x86_64::*;

/// The kernel's per-table constants.
#[derive(Debug, Clone)]
pub(super) struct Kernel {
    /// ln μ coefficients, with the four θ rows of each cell interleaved:
    /// `coefs[((i·cells_θ + j)·n_F + k)·4 + b]` is coefficient (i, j + b, k),
    /// so the 4×4 (θ, F*) part of a block on one ψ plane is 16 floats in a
    /// row (four times the file's coefficients: 0.7 MB for the default
    /// table, which stays in a 1 MB L2 cache).
    coefs: Vec<f32>,
    /// Per axis (ψ, θ, F* in lanes 0, 1, 2; zeros in the others), the
    /// map to cell coordinates, s = e·K + q/spacing + O for a coordinate
    /// e·ln 2 + q (ln axes: x = 2^e·m, q = ln m; the √ axis: e = 0,
    /// q = √x), with K = ln 2/spacing and O = −first/spacing each split
    /// into a head with 12 fraction bits and a tail: e·K_hi + O_hi is then
    /// exact (|s| < 2048), and the offset in the cell keeps f32 precision
    /// though s reaches 30 or more.
    k_hi: [f32; 8],
    k_lo: [f32; 8],
    inv_step: [f32; 8],
    o_hi: [f32; 8],
    o_lo: [f32; 8],
    /// The last cell and the stride in `coefs`, per axis.
    last_cell: [f32; 8],
    stride: [i32; 8],
    /// The domain's lower and upper ends (ψ, θ, F*, then 1 in both for
    /// the padding lane of a single query).
    lo: [f64; 4],
    hi: [f64; 4],
    /// 1/spacing of the F* axis, in f64, for ∂μ/∂F* (see [`super::slope`]).
    f_inv_step: f64,
}

impl Kernel {
    /// The kernel for a table's layout and f32 coefficients, if this CPU
    /// runs it and the table suits it: a domain of normal f32 numbers,
    /// fewer than 2048 nodes per axis (so that cell coordinates keep their
    /// precision in f32, see `k_hi`) and offsets that fit an i32.
    pub(super) fn new(t: &Layout, coefs: &[f32]) -> Option<Kernel> {
        if !(std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma")) {
            return None;
        }
        let normal = |v: f64| v == 0.0 || (v.abs() >= f32::MIN_POSITIVE as f64 && v.abs() <= 1e30);
        if !t.ranges.iter().all(|&(lo, hi)| normal(lo) && normal(hi)) {
            return None;
        }
        let [s0, s1, _] = t.strides;
        let n = t.axes.map(|a| a.nodes + 2);
        let cells_theta = t.last_cell[1] + 1;
        let stride = [cells_theta * n[2] * 4, n[2] * 4, 4];
        let len = n[0] * stride[0];
        // The block of the last cell must end inside the coefficients.
        let last_block = (0..3).map(|a| t.last_cell[a] * stride[a]).sum::<usize>() + 3 * stride[0] + 15;
        if n[0] * s0 != coefs.len() || n.iter().any(|&m| m >= 2048) || last_block >= len || len >= i32::MAX as usize {
            return None;
        }
        let mut inter = vec![0.0; len];
        for i in 0..n[0] {
            for j in 0..cells_theta {
                for k in 0..n[2] {
                    for b in 0..4 {
                        inter[i * stride[0] + j * stride[1] + k * 4 + b] = coefs[i * s0 + (j + b) * s1 + k];
                    }
                }
            }
        }
        let lanes = |v: [f64; 3]| [v[0], v[1], v[2], 0.0, 0.0, 0.0, 0.0, 0.0].map(|v| v as f32);
        let head = |v: f64| (v * 4096.0).round() / 4096.0;
        // K = ln 2/spacing on the ln axes, 0 on the √θ one.
        let k = [0, 1, 2].map(|a| {
            if a == 1 {
                0.0
            } else {
                core::f64::consts::LN_2 * t.inv_step[a]
            }
        });
        Some(Kernel {
            coefs: inter,
            k_hi: lanes(k.map(head)),
            k_lo: lanes(k.map(|v| v - head(v))),
            inv_step: lanes(t.inv_step),
            o_hi: lanes(t.offset.map(head)),
            o_lo: lanes(t.offset.map(|v| v - head(v))),
            last_cell: lanes(t.last_cell.map(|v| v as f64)),
            stride: [stride[0] as i32, stride[1] as i32, stride[2] as i32, 0, 0, 0, 0, 0],
            lo: [t.ranges[0].0, t.ranges[1].0, t.ranges[2].0, 1.0],
            hi: [t.ranges[0].1, t.ranges[1].1, t.ranges[2].1, 1.0],
            f_inv_step: t.inv_step[2],
        })
    }

    /// One lookup (see [`eval`]): μ, NaN for a query outside the domain,
    /// and if `SLOPE`, d ln μ/d(cell coordinate of F*).
    #[inline(always)]
    pub(super) fn eval<const SLOPE: bool>(&self, psi: f64, theta: f64, f_star: f64) -> (f64, f64) {
        // SAFETY: a `Kernel` exists only where `new` found AVX2 and FMA.
        unsafe { eval::<SLOPE>(self, psi, theta, f_star) }
    }

    /// Many lookups (see [`batch`]); the slices must all have `out`'s
    /// length. Returns the index of the first query outside the domain.
    pub(super) fn batch(&self, psi: &[f64], theta: &[f64], f_star: &[f64], out: BatchOutput) -> Option<usize> {
        let n = out.len();
        assert!(
            psi.len() == n && theta.len() == n && f_star.len() == n,
            "batch slices of one length"
        );
        // SAFETY: AVX2 and FMA as in `eval`; the lengths are checked above.
        unsafe { batch(self, psi, theta, f_star, out) }
    }
}

/// The per-lane constants of the map to cell coordinates.
struct Map {
    k_hi: __m256,
    k_lo: __m256,
    inv_step: __m256,
    o_hi: __m256,
    o_lo: __m256,
    last_cell: __m256,
    stride: __m256i,
}

/// Cell offsets and block offsets of eight coordinates e·ln 2 + q (one
/// per lane, each lane with its axis's constants). The cell is clamped,
/// so that a query a rounding error outside the domain's edge still
/// reads inside the table.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
#[inline(always)]
unsafe fn cells(e: __m256, q: __m256, m: &Map) -> (__m256, __m256i) {
    // SAFETY: AVX2 and FMA are available, as this function's contract requires;
    // no memory is accessed.
    unsafe {
        let a = _mm256_fmadd_ps(e, m.k_hi, m.o_hi);
        let b = _mm256_fmadd_ps(e, m.k_lo, _mm256_fmadd_ps(q, m.inv_step, m.o_lo));
        let cell = _mm256_max_ps(
            _mm256_min_ps(_mm256_floor_ps(_mm256_add_ps(a, b)), m.last_cell),
            _mm256_setzero_ps(),
        );
        let offset = _mm256_mullo_epi32(_mm256_cvttps_epi32(cell), m.stride);
        (_mm256_add_ps(_mm256_sub_ps(a, cell), b), offset)
    }
}

/// The four B-spline weights at offset `f` (an offset per half: lanes
/// 0..4 hold the weights at f's lane 0, lanes 4..8 those at lane 4), by
/// Horner's rule.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
#[inline(always)]
unsafe fn weights(f: __m256) -> __m256 {
    // SAFETY: AVX2 and FMA are available, as this function's contract requires;
    // no memory is accessed.
    unsafe {
        let [a, b, c, d] = [basis(0), basis(1), basis(2), basis(3)];
        _mm256_fmadd_ps(_mm256_fmadd_ps(_mm256_fmadd_ps(a, f, b), f, c), f, d)
    }
}

/// Their derivatives, (3A·f + 2B)·f + C.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
#[inline(always)]
unsafe fn weight_slopes(f: __m256) -> __m256 {
    // SAFETY: AVX2 and FMA are available, as this function's contract requires;
    // no memory is accessed.
    unsafe {
        let [a, b, c] = [basis(0), basis(1), basis(2)];
        let three_a = _mm256_mul_ps(a, _mm256_set1_ps(3.0));
        _mm256_fmadd_ps(_mm256_fmadd_ps(three_a, f, _mm256_add_ps(b, b)), f, c)
    }
}

/// `v` with its lanes picked by `idx`.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
#[inline(always)]
unsafe fn pick(v: __m256, idx: [i32; 8]) -> __m256 {
    // SAFETY: AVX2 and FMA are available, as this function's contract requires;
    // the load reads the 8 i32 of `idx`, a local array.
    unsafe { _mm256_permutevar8x32_ps(v, _mm256_loadu_si256(idx.as_ptr().cast())) }
}

/// Row `r` of [`BASIS`] in f32, in both halves of a vector.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
#[inline(always)]
unsafe fn basis(r: usize) -> __m256 {
    // SAFETY: AVX2 and FMA are available, as this function's contract requires;
    // no memory is accessed.
    unsafe {
        let b = BASIS[r].map(|v| v as f32);
        _mm256_setr_ps(b[0], b[1], b[2], b[3], b[0], b[1], b[2], b[3])
    }
}

/// One query's blend before the final horizontal sum: a vector whose
/// lanes add up to ln μ, and (if `SLOPE`) one whose lanes add up to its
/// derivative along the F* cell coordinate. `f` holds the θ cell offset
/// in lanes 0..4 and the F* one in 4..8; `wp` the four ψ weights, each
/// in every lane.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
/// `base` must be the block offset of a located query (a sum of clamped
/// cells times strides, as [`cells`] computes it), so that the block's
/// last float, `base + 3·stride[0] + 15`, lies inside `k.coefs`.
#[inline(always)]
unsafe fn blend<const SLOPE: bool>(k: &Kernel, base: usize, f: __m256, wp: [__m256; 4]) -> (__m256, __m256) {
    // SAFETY: AVX2 and FMA as the contract requires. `base + i·s0 + off + 8
    // ≤ base + 3·s0 + 16 ≤ coefs.len()` for i < 4, off ≤ 8: the contract on
    // `base`, and `Kernel::new` rejected tables whose last block (the
    // largest `base`) would end past the coefficients.
    unsafe {
        // [θ weights | F* weights].
        let w = weights(f);
        // Each plane's 16 floats: F* offsets 0|1, then 2|3, four θ rows each.
        let p = k.coefs.as_ptr().add(base);
        let s0 = k.stride[0] as usize;
        let (t0, t1) = (plane(p, s0, &wp, 0), plane(p, s0, &wp, 8));
        // The (θ, F*) weights of the two halves, ready before the rows are.
        const F01: [i32; 8] = [4, 4, 4, 4, 5, 5, 5, 5];
        const F23: [i32; 8] = [6, 6, 6, 6, 7, 7, 7, 7];
        let wt = pick(w, [0, 1, 2, 3, 0, 1, 2, 3]);
        let g = _mm256_fmadd_ps(
            t1,
            _mm256_mul_ps(wt, pick(w, F23)),
            _mm256_mul_ps(t0, _mm256_mul_ps(wt, pick(w, F01))),
        );
        if !SLOPE {
            return (g, g);
        }
        let dw = weight_slopes(f);
        let dg = _mm256_fmadd_ps(
            t1,
            _mm256_mul_ps(wt, pick(dw, F23)),
            _mm256_mul_ps(t0, _mm256_mul_ps(wt, pick(dw, F01))),
        );
        (g, dg)
    }
}

/// Σᵢ `wp[i]`·(row i) for the 8-float rows at `p + i·s0 + off`, as a
/// tree, (0 + 1) + (2 + 3): a shorter chain.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
/// `p + i·s0 + off + 8` must be in bounds of one allocation for i < 4.
#[inline(always)]
unsafe fn plane(p: *const f32, s0: usize, wp: &[__m256; 4], off: usize) -> __m256 {
    // SAFETY: AVX2 and FMA as the contract requires; the four 8-float rows
    // lie in bounds, as the contract requires.
    unsafe {
        let row = |i: usize| _mm256_loadu_ps(p.add(i * s0 + off));
        let a = _mm256_fmadd_ps(wp[1], row(1), _mm256_mul_ps(wp[0], row(0)));
        let b = _mm256_fmadd_ps(wp[3], row(3), _mm256_mul_ps(wp[2], row(2)));
        _mm256_add_ps(a, b)
    }
}

/// Widens lanes 0..4 and 4..8 of `v` to f64.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
#[inline(always)]
unsafe fn widen(v: __m256) -> [__m256d; 2] {
    // SAFETY: AVX2 and FMA are available, as this function's contract requires;
    // no memory is accessed.
    unsafe {
        [
            _mm256_cvtps_pd(_mm256_castps256_ps128(v)),
            _mm256_cvtps_pd(_mm256_extractf128_ps::<1>(v)),
        ]
    }
}

/// One lookup: μ and, if `SLOPE`, d ln μ/d(cell coordinate of F*); μ is
/// NaN (never otherwise) for a query outside the domain. A pair of floats
/// comes back in registers, where a `Result` would go through memory.
///
/// The three axes share one vector (lanes 0, 1, 2), and each lane goes
/// through the operations the batch applies to that axis, so the result
/// is the batch's bit for bit.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
#[target_feature(enable = "avx2,fma")]
unsafe fn eval<const SLOPE: bool>(k: &Kernel, psi: f64, theta: f64, f_star: f64) -> (f64, f64) {
    // SAFETY: AVX2 and FMA are enabled here, as the contract requires. The
    // loads read the 4 f64 of `k.lo`, `k.hi` and the 8 lanes of the
    // kernel's constant arrays; the block offset `base` comes from `cells`
    // (clamped cells), as `blend` requires.
    unsafe {
        // The domain check, all three at once (ordered comparisons: NaN fails).
        let xd = _mm256_setr_pd(psi, theta, f_star, 1.0);
        let ok = _mm256_and_pd(
            _mm256_cmp_pd::<_CMP_GE_OQ>(xd, _mm256_loadu_pd(k.lo.as_ptr())),
            _mm256_cmp_pd::<_CMP_LE_OQ>(xd, _mm256_loadu_pd(k.hi.as_ptr())),
        );
        if _mm256_movemask_pd(ok) != 0b1111 {
            return (f64::NAN, f64::NAN);
        }
        let x = _mm256_set_m128(_mm_set1_ps(1.0), _mm256_cvtpd_ps(xd));
        let (e, ln_m) = ln8(x);
        let e = _mm256_blend_ps::<0b10>(e, _mm256_setzero_ps());
        let q = _mm256_blend_ps::<0b10>(ln_m, _mm256_sqrt_ps(x));
        let lanes = |v: &[f32; 8]| _mm256_loadu_ps(v.as_ptr());
        let map = Map {
            k_hi: lanes(&k.k_hi),
            k_lo: lanes(&k.k_lo),
            inv_step: lanes(&k.inv_step),
            o_hi: lanes(&k.o_hi),
            o_lo: lanes(&k.o_lo),
            last_cell: lanes(&k.last_cell),
            stride: _mm256_loadu_si256(k.stride.as_ptr().cast()),
        };
        let (frac, offsets) = cells(e, q, &map);
        let o = _mm256_castsi256_si128(offsets);
        let base = _mm_cvtsi128_si32(o) + _mm_extract_epi32::<1>(o) + _mm_extract_epi32::<2>(o);
        let w_psi = weights(pick(frac, [0; 8]));
        let wp = [
            pick(w_psi, [0; 8]),
            pick(w_psi, [1; 8]),
            pick(w_psi, [2; 8]),
            pick(w_psi, [3; 8]),
        ];
        let (g, dg) = blend::<SLOPE>(k, base as usize, pick(frac, [1, 1, 1, 1, 2, 2, 2, 2]), wp);
        // The batch's sum order: (g0 + g1) + (g2 + g3), plus the same of 4..8.
        let h = _mm256_hadd_ps(g, dg);
        let h = _mm256_hadd_ps(h, h);
        let s = _mm_add_ps(_mm256_castps256_ps128(h), _mm256_extractf128_ps::<1>(h));
        let mu = exp8(_mm256_set1_ps(_mm_cvtss_f32(s)));
        (_mm256_cvtss_f32(mu) as f64, _mm_cvtss_f32(_mm_movehdup_ps(s)) as f64)
    }
}

/// Eight located queries: block offsets, cell offsets on the θ and F*
/// axes, and the four ψ weights.
#[derive(Default)]
#[repr(C, align(32))]
struct Located {
    base: [i32; 8],
    f_theta: [f32; 8],
    f_f: [f32; 8],
    w_psi: [[f32; 8]; 4],
}

/// [`super::slope`] four at a time, its operations in its order (so the
/// same bits).
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
/// `f_star` must point to 4 readable f64.
#[inline(always)]
unsafe fn slopes(k: &Kernel, mu: __m256d, d: __m256d, f_star: *const f64) -> __m256d {
    // SAFETY: AVX2 and FMA as the contract requires; the load reads the 4
    // f64 at `f_star`, readable by the contract.
    unsafe {
        let scaled = _mm256_mul_pd(_mm256_mul_pd(mu, d), _mm256_set1_pd(k.f_inv_step));
        _mm256_div_pd(scaled, _mm256_loadu_pd(f_star))
    }
}

/// μ (or μ and ∂μ/∂F*, as `out` asks) for every query, eight at a
/// time; returns the index of the first query outside the domain (`out`
/// is then partly written).
///
/// # Safety
/// The CPU must support AVX2 and FMA; the slices have `out`'s length.
#[target_feature(enable = "avx2,fma")]
unsafe fn batch(k: &Kernel, psi: &[f64], theta: &[f64], f_star: &[f64], out: BatchOutput) -> Option<usize> {
    // SAFETY: AVX2 and FMA, and the slices' lengths, as the contract
    // requires and `run` needs.
    unsafe {
        match out {
            BatchOutput::Mu(_) => run::<false>(k, psi, theta, f_star, out),
            BatchOutput::WithSlope(_) => run::<true>(k, psi, theta, f_star, out),
        }
    }
}

/// [`batch`] with `SLOPE` true exactly when `out` is `BatchOutput::WithSlope`.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
/// `psi`, `theta` and `f_star` must have `out`'s length.
#[inline(always)]
unsafe fn run<const SLOPE: bool>(
    k: &Kernel,
    psi: &[f64],
    theta: &[f64],
    f_star: &[f64],
    mut out: BatchOutput,
) -> Option<usize> {
    // SAFETY: AVX2 and FMA as the contract requires. The vector loads and
    // stores touch elements i .. i + 8 of slices of length n, and run only
    // while i + 8 ≤ n (the loop's condition, `ready`); the scratch arrays
    // `m`, `s` hold 8 f64. Blocks come from `locate` on this kernel.
    unsafe {
        let n = out.len();
        let map = |a: usize| Map {
            k_hi: _mm256_set1_ps(k.k_hi[a]),
            k_lo: _mm256_set1_ps(k.k_lo[a]),
            inv_step: _mm256_set1_ps(k.inv_step[a]),
            o_hi: _mm256_set1_ps(k.o_hi[a]),
            o_lo: _mm256_set1_ps(k.o_lo[a]),
            last_cell: _mm256_set1_ps(k.last_cell[a]),
            stride: _mm256_set1_epi32(k.stride[a]),
        };
        let maps = [map(0), map(1), map(2)];
        let x = [psi, theta, f_star];
        // Software pipelined: block i + 8 is located while block i is blended,
        // two independent chains the CPU overlaps. A block with a query
        // outside the domain ends the loop; the single-query kernel then
        // takes over from it (and finds which query it is).
        let mut l = [Located::default(), Located::default()];
        let mut i = 0;
        let mut ready = n >= 8 && locate(k, &maps, x, 0, &mut l[0]);
        while ready {
            let (even, odd) = l.split_at_mut(1);
            let (this, next) = if (i / 8) % 2 == 0 {
                (&even[0], &mut odd[0])
            } else {
                (&odd[0], &mut even[0])
            };
            ready = i + 16 <= n && locate(k, &maps, x, i + 8, next);
            let (mu, d) = finish::<SLOPE>(k, this);
            match &mut out {
                BatchOutput::Mu(o) => {
                    _mm256_storeu_pd(o.as_mut_ptr().add(i), mu[0]);
                    _mm256_storeu_pd(o.as_mut_ptr().add(i + 4), mu[1]);
                }
                BatchOutput::WithSlope(o) => {
                    let (mut m, mut s) = ([0.0; 8], [0.0; 8]);
                    _mm256_storeu_pd(m.as_mut_ptr(), mu[0]);
                    _mm256_storeu_pd(m.as_mut_ptr().add(4), mu[1]);
                    _mm256_storeu_pd(s.as_mut_ptr(), slopes(k, mu[0], d[0], f_star.as_ptr().add(i)));
                    _mm256_storeu_pd(
                        s.as_mut_ptr().add(4),
                        slopes(k, mu[1], d[1], f_star.as_ptr().add(i + 4)),
                    );
                    for j in 0..8 {
                        o[i + j] = (m[j], s[j]);
                    }
                }
            }
            i += 8;
        }
        for j in i..n {
            let r = eval::<SLOPE>(k, psi[j], theta[j], f_star[j]);
            if r.0.is_nan() {
                return Some(j);
            }
            match &mut out {
                BatchOutput::Mu(o) => o[j] = r.0,
                BatchOutput::WithSlope(o) => o[j] = (r.0, super::slope(r.0, r.1, k.f_inv_step, f_star[j])),
            }
        }
        None
    }
}

/// Checks, maps and locates the eight queries at `i` (one axis per
/// vector, eight queries in its lanes) into `l`; false if any is outside
/// the domain or NaN.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
/// Each slice of `x` must hold at least `i + 8` elements.
#[inline(always)]
unsafe fn locate(k: &Kernel, maps: &[Map; 3], x: [&[f64]; 3], i: usize, l: &mut Located) -> bool {
    // SAFETY: AVX2 and FMA as the contract requires; the loads read elements
    // i .. i + 8 of each slice of `x`, in bounds by the contract; the aligned
    // stores write whole arrays of `l`, which is 32-byte aligned
    // (`#[repr(C, align(32))]`, each field 32 bytes).
    unsafe {
        let mut ok = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
        let mut v = [_mm256_setzero_ps(); 3];
        for a in 0..3 {
            let h = [
                _mm256_loadu_pd(x[a].as_ptr().add(i)),
                _mm256_loadu_pd(x[a].as_ptr().add(i + 4)),
            ];
            // Ordered comparisons: NaN fails them.
            let (lo, hi) = (_mm256_set1_pd(k.lo[a]), _mm256_set1_pd(k.hi[a]));
            for h in h {
                ok = _mm256_and_pd(ok, _mm256_cmp_pd::<_CMP_GE_OQ>(h, lo));
                ok = _mm256_and_pd(ok, _mm256_cmp_pd::<_CMP_LE_OQ>(h, hi));
            }
            v[a] = _mm256_set_m128(_mm256_cvtpd_ps(h[1]), _mm256_cvtpd_ps(h[0]));
        }
        if _mm256_movemask_pd(ok) != 0b1111 {
            return false;
        }
        let coords = [ln8(v[0]), (_mm256_setzero_ps(), _mm256_sqrt_ps(v[1])), ln8(v[2])];
        let mut base = _mm256_setzero_si256();
        let mut frac = [_mm256_setzero_ps(); 3];
        for a in 0..3 {
            let (f, o) = cells(coords[a].0, coords[a].1, &maps[a]);
            frac[a] = f;
            base = _mm256_add_epi32(base, o);
        }
        _mm256_store_si256(l.base.as_mut_ptr().cast(), base);
        _mm256_store_ps(l.f_theta.as_mut_ptr(), frac[1]);
        _mm256_store_ps(l.f_f.as_mut_ptr(), frac[2]);
        for (j, out) in l.w_psi.iter_mut().enumerate() {
            let c = |r: usize| _mm256_set1_ps(BASIS[r][j] as f32);
            let (c0, c1, c2, c3) = (c(0), c(1), c(2), c(3));
            let w = _mm256_fmadd_ps(
                _mm256_fmadd_ps(_mm256_fmadd_ps(c0, frac[0], c1), frac[0], c2),
                frac[0],
                c3,
            );
            _mm256_store_ps(out.as_mut_ptr(), w);
        }
        true
    }
}

/// Query `q` of a located block, blended (see [`blend`]).
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
/// `l` must have been filled by [`locate`] on this kernel, and `q < 8`.
#[inline(always)]
unsafe fn blend_query<const SLOPE: bool>(k: &Kernel, l: &Located, q: usize) -> (__m256, __m256) {
    // SAFETY: AVX2 and FMA as the contract requires; the broadcasts read
    // fields of `l` at q < 8; `l.base[q]` is a located block offset, as
    // `blend` requires, because `locate` computed it with `cells`.
    unsafe {
        let f = _mm256_set_m128(_mm_broadcast_ss(&l.f_f[q]), _mm_broadcast_ss(&l.f_theta[q]));
        let wp = [
            _mm256_broadcast_ss(&l.w_psi[0][q]),
            _mm256_broadcast_ss(&l.w_psi[1][q]),
            _mm256_broadcast_ss(&l.w_psi[2][q]),
            _mm256_broadcast_ss(&l.w_psi[3][q]),
        ];
        blend::<SLOPE>(k, l.base[q] as usize, f, wp)
    }
}

/// The lane sums of eight vectors, in the single kernel's order.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
#[inline(always)]
unsafe fn sums(g: &[__m256; 8]) -> __m256 {
    // SAFETY: AVX2 and FMA are available, as this function's contract requires;
    // no memory is accessed.
    unsafe {
        let h0 = _mm256_hadd_ps(_mm256_hadd_ps(g[0], g[1]), _mm256_hadd_ps(g[2], g[3]));
        let h1 = _mm256_hadd_ps(_mm256_hadd_ps(g[4], g[5]), _mm256_hadd_ps(g[6], g[7]));
        _mm256_add_ps(
            _mm256_permute2f128_ps::<0x20>(h0, h1),
            _mm256_permute2f128_ps::<0x31>(h0, h1),
        )
    }
}

/// Blends the eight located queries: their μ and (if `SLOPE`, else μ
/// again) d ln μ/d(cell coordinate of F*), in f64.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
/// `l` must have been filled by [`locate`] on this kernel.
#[inline(always)]
unsafe fn finish<const SLOPE: bool>(k: &Kernel, l: &Located) -> ([__m256d; 2], [__m256d; 2]) {
    // SAFETY: AVX2 and FMA, and `l` from `locate`, as the contract requires
    // and `blend_query` needs.
    unsafe {
        // (Not `array::from_fn`, `map` or a closure: those are separate
        // functions, compiled without AVX2 and not always inlined.)
        let r = [
            blend_query::<SLOPE>(k, l, 0),
            blend_query::<SLOPE>(k, l, 1),
            blend_query::<SLOPE>(k, l, 2),
            blend_query::<SLOPE>(k, l, 3),
            blend_query::<SLOPE>(k, l, 4),
            blend_query::<SLOPE>(k, l, 5),
            blend_query::<SLOPE>(k, l, 6),
            blend_query::<SLOPE>(k, l, 7),
        ];
        let g = [r[0].0, r[1].0, r[2].0, r[3].0, r[4].0, r[5].0, r[6].0, r[7].0];
        let mu = widen(exp8(sums(&g)));
        if !SLOPE {
            return (mu, mu);
        }
        let dg = [r[0].1, r[1].1, r[2].1, r[3].1, r[4].1, r[5].1, r[6].1, r[7].1];
        (mu, widen(sums(&dg)))
    }
}

/// ln x = e·ln 2 + ln m on eight lanes of positive normal numbers: e and
/// ln m = 2·atanh(s), s = (m − 1)/(m + 1), error below 3e-8.
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
#[inline(always)]
unsafe fn ln8(x: __m256) -> (__m256, __m256) {
    // SAFETY: AVX2 and FMA are available, as this function's contract requires;
    // no memory is accessed.
    unsafe {
        // x = 2^e·m, m in [√½, √2).
        let bits = _mm256_castps_si256(x);
        let tmp = _mm256_sub_epi32(bits, _mm256_set1_epi32(0x3f35_04f3));
        let e = _mm256_cvtepi32_ps(_mm256_srai_epi32::<23>(tmp));
        let top = _mm256_and_si256(tmp, _mm256_set1_epi32(0xff80_0000u32 as i32));
        let m = _mm256_castsi256_ps(_mm256_sub_epi32(bits, top));
        let one = _mm256_set1_ps(1.0);
        // |s| ≤ 0.172: 2·atanh(s) = 2s·(1 + z/3 + z²/5 + z³/7 + …), z = s²,
        // and the first term left out, 2|s|·z⁴/9, is below 3e-8.
        let s = _mm256_div_ps(_mm256_sub_ps(m, one), _mm256_add_ps(m, one));
        let two_s = _mm256_add_ps(s, s);
        let z = _mm256_mul_ps(s, s);
        let p = _mm256_fmadd_ps(
            _mm256_fmadd_ps(z, _mm256_set1_ps(1.0 / 7.0), _mm256_set1_ps(0.2)),
            z,
            _mm256_set1_ps(1.0 / 3.0),
        );
        (e, _mm256_fmadd_ps(_mm256_mul_ps(two_s, z), p, two_s))
    }
}

/// e^x on eight lanes, |x| < 80 (Cephes' `expf`, error about 1e-7 relative).
///
/// # Safety
/// The CPU must support AVX2 and FMA (as [`Kernel::new`] checked).
#[inline(always)]
unsafe fn exp8(x: __m256) -> __m256 {
    // SAFETY: AVX2 and FMA are available, as this function's contract requires;
    // no memory is accessed.
    unsafe {
        let k = _mm256_round_ps::<{ _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC }>(_mm256_mul_ps(
            x,
            _mm256_set1_ps(core::f32::consts::LOG2_E),
        ));
        let r = _mm256_fnmadd_ps(k, _mm256_set1_ps(0.693_359_4), x);
        let r = _mm256_fnmadd_ps(k, _mm256_set1_ps(-2.121_944_4e-4), r);
        // Σ c_k·r^k by Estrin's scheme.
        let c = |v: f32| _mm256_set1_ps(v);
        let pair = |hi: f32, lo: f32| _mm256_fmadd_ps(c(hi), r, c(lo));
        let r2 = _mm256_mul_ps(r, r);
        let p = _mm256_fmadd_ps(
            pair(1.987_569_1e-4, 1.398_199_9e-3),
            _mm256_mul_ps(r2, r2),
            _mm256_fmadd_ps(pair(8.333_452e-3, 4.166_579_6e-2), r2, pair(0.166_666_66, 0.5)),
        );
        let y = _mm256_fmadd_ps(r2, p, _mm256_add_ps(r, _mm256_set1_ps(1.0)));
        let scale = _mm256_slli_epi32::<23>(_mm256_add_epi32(_mm256_cvtps_epi32(k), _mm256_set1_epi32(127)));
        _mm256_mul_ps(y, _mm256_castsi256_ps(scale))
    }
}
