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
//!
//! # Unsafe code
//!
//! Two invariants make it sound, both established in [`Kernel::new`]:
//! - the CPU runs AVX2 and FMA. `Kernel::new` detects both before it makes
//!   the only [`Avx2Fma`] there is, the kernel's `cpu`; the helpers take
//!   that token by value, so calling them needs no `unsafe`, and inside
//!   them the intrinsics are sound because the token exists. The two
//!   entry points [`eval`] and [`batch`] are `#[target_feature]` functions
//!   (reached from [`Kernel::eval`] and [`Kernel::batch`]), into which
//!   every helper is inlined.
//! - every block read lies inside the coefficients: a block offset is a
//!   sum of cells clamped to `0..=last_cell` times the strides ([`cells`]),
//!   and `Kernel::new` refuses a table whose last block would end past the
//!   coefficients. The query and output slices are read and written in
//!   bounds by the batch loop's condition.
//!
//! The helpers are `#[inline(always)]` functions without
//! `#[target_feature]` (stable Rust does not allow the two together).
//! Making them safe `#[target_feature]` functions instead (Rust 1.86+,
//! their intrinsics then need no `unsafe`; `#[inline]` only) was measured:
//! `mu` and `mu_batch` kept their instruction counts, but LLVM, inlining
//! them later, scheduled the slope batch differently, and
//! `mu_with_slope_batch` ran 2.5% slower (`mu_with_slope` 0.5–1%). So the
//! kernel keeps the `#[inline(always)]` structure and its machine code.
//!
//! Variants measured and not kept (512-bit ψ-plane sums, θ rows in pairs)
//! are in docs/PERFORMANCE.md.

use super::layout::Layout;
use super::{BatchOutput, FastKernel};
use crate::spline::BASIS;
use core::arch::x86_64::*;

/// Proof that this CPU runs AVX2 and FMA: made only by [`Kernel::new`],
/// after detecting both (the field is private to this module, and nothing
/// else here makes one). A zero-sized token, free to pass around.
#[derive(Debug, Clone, Copy)]
struct Avx2Fma(());

/// The kernel's per-table constants.
#[derive(Debug, Clone)]
pub(super) struct Kernel {
    /// The proof that this CPU runs AVX2 and FMA.
    cpu: Avx2Fma,
    /// ln μ coefficients, with the four θ rows of each cell interleaved:
    /// `coefs[((i·cells_θ + j)·n_F + k)·4 + b]` is coefficient (i, j + b, k),
    /// so the 4×4 (θ, F*) part of a block on one ψ plane is 16 floats in a
    /// row (four times the file's coefficients: 0.83 MB for the default
    /// table, which stays in a 1 MB L2 cache).
    ///
    /// Invariant (checked in [`Kernel::new`]): the block of the last cell
    /// ends inside, `Σ last_cell[a]·stride[a] + 3·stride[0] + 15 <
    /// coefs.len()`; so does the block of every cell.
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

impl FastKernel for Kernel {
    /// The kernel for a table's layout and f32 coefficients, if this CPU
    /// runs it and the table suits it: a domain of normal f32 numbers,
    /// fewer than 2048 nodes per axis (so that cell coordinates keep their
    /// precision in f32, see `k_hi`) and offsets that fit an i32.
    ///
    /// The unsafe code relies on two checks made here: the CPU feature
    /// detection (the only place an [`Avx2Fma`] is made) and the last
    /// block's bound.
    fn new(layout: &Layout, coefs: &[f32]) -> Option<Kernel> {
        if !(std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma")) {
            return None;
        }
        let normal = |v: f64| v == 0.0 || (v.abs() >= f32::MIN_POSITIVE as f64 && v.abs() <= 1e30);
        if !layout.ranges.iter().all(|&(lo, hi)| normal(lo) && normal(hi)) {
            return None;
        }
        // Strides of the file's coefficients along ψ and θ (F*'s is 1).
        let [s0, s1, _] = layout.strides;
        let nodes = layout.axes.map(|a| a.nodes + 2);
        let cells_theta = layout.last_cell[1] + 1;
        let stride = [cells_theta * nodes[2] * 4, nodes[2] * 4, 4];
        let len = nodes[0] * stride[0];
        // The block of the last cell must end inside the coefficients.
        let last_block = (0..3).map(|a| layout.last_cell[a] * stride[a]).sum::<usize>() + 3 * stride[0] + 15;
        // The cell coordinate e·K + o (e the binary exponent of a query,
        // K = ln 2/step) is exact in f32 while K, |o| and the sum stay
        // below 2^12, as `k_hi` and `o_hi` carry 12 fractional bits; on the
        // ln axes |ln m|/step, m in [√½, √2), is then below 2048·0.35 and
        // the sum below 2^12. A table that loads may have finer steps or
        // farther offsets: the portable kernel looks it up.
        let ln_axes_fit = [0, 2].iter().all(|&a| layout.inv_step[a] < 2048.0);
        let offsets_fit = layout.offset.iter().all(|o| o.abs() < 4096.0);
        if nodes[0] * s0 != coefs.len()
            || !ln_axes_fit
            || !offsets_fit
            || nodes.iter().any(|&m| m >= 2048)
            || last_block >= len
            || len >= i32::MAX as usize
        {
            return None;
        }
        let mut interleaved = vec![0.0; len];
        for i in 0..nodes[0] {
            for j in 0..cells_theta {
                for k in 0..nodes[2] {
                    for b in 0..4 {
                        interleaved[i * stride[0] + j * stride[1] + k * 4 + b] = coefs[i * s0 + (j + b) * s1 + k];
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
                core::f64::consts::LN_2 * layout.inv_step[a]
            }
        });
        Some(Kernel {
            // Detected above.
            cpu: Avx2Fma(()),
            coefs: interleaved,
            k_hi: lanes(k.map(head)),
            k_lo: lanes(k.map(|v| v - head(v))),
            inv_step: lanes(layout.inv_step),
            o_hi: lanes(layout.offset.map(head)),
            o_lo: lanes(layout.offset.map(|v| v - head(v))),
            last_cell: lanes(layout.last_cell.map(|v| v as f64)),
            stride: [stride[0] as i32, stride[1] as i32, stride[2] as i32, 0, 0, 0, 0, 0],
            lo: [layout.ranges[0].0, layout.ranges[1].0, layout.ranges[2].0, 1.0],
            hi: [layout.ranges[0].1, layout.ranges[1].1, layout.ranges[2].1, 1.0],
            f_inv_step: layout.inv_step[2],
        })
    }

    /// One lookup (see [`eval`]): μ, NaN for a query outside the domain,
    /// and if `SLOPE`, d ln μ/d(cell coordinate of F*).
    #[inline(always)]
    fn eval<const SLOPE: bool>(&self, psi: f64, theta: f64, f_star: f64) -> (f64, f64) {
        // SAFETY: `eval` needs AVX2 and FMA; `self.cpu` proves both
        // (detected in `Kernel::new`).
        unsafe { eval::<SLOPE>(self, psi, theta, f_star) }
    }

    /// Readies the coefficients for `n` queries to come: reads them
    /// through into the L2 cache ([`prefetch_coefficients`]) if `n` is at
    /// least one query per 64-byte line of them (about 12,900 for the
    /// default table), where the queries would read every line several
    /// times over. Every batch does it first; a caller that splits a batch
    /// into smaller ones does it once for the whole.
    fn prepare(&self, n: usize) {
        if n >= self.coefs.len() / LINE_FLOATS {
            prefetch_coefficients(self);
        }
    }

    /// Many lookups (see [`batch`]); the slices must all have `out`'s
    /// length. Returns the index of the first query outside the domain.
    fn batch(&self, psi: &[f64], theta: &[f64], f_star: &[f64], out: BatchOutput) -> Option<usize> {
        let n = out.len();
        assert!(
            psi.len() == n && theta.len() == n && f_star.len() == n,
            "batch slices of one length"
        );
        // SAFETY: `batch` needs AVX2 and FMA, which `self.cpu` proves
        // (detected in `Kernel::new`), and slices of `out`'s length,
        // asserted above.
        unsafe { batch(self, psi, theta, f_star, out) }
    }
}

/// The per-lane constants of the map to cell coordinates.
struct CellMap {
    k_hi: __m256,
    k_lo: __m256,
    inv_step: __m256,
    o_hi: __m256,
    o_lo: __m256,
    last_cell: __m256,
    stride: __m256i,
}

/// Offsets in the cell and block offsets of eight coordinates e·ln 2 + q
/// (one per lane, each lane with its axis's constants).
///
/// The cell is clamped to `0..=last_cell` whatever the input (so that a
/// query a rounding error outside the domain's edge still reads inside the
/// table): `min` returns `last_cell` and then `max` returns it again for a
/// NaN lane. A lane's block offset is therefore at most
/// `last_cell·stride`, the bound the block reads rely on (and at least 0:
/// the i32 product cannot overflow, as `Kernel::new` keeps the
/// coefficients' length below `i32::MAX`).
#[inline(always)]
fn cells(_cpu: Avx2Fma, e: __m256, q: __m256, map: &CellMap) -> (__m256, __m256i) {
    // SAFETY: `_cpu` proves AVX2 and FMA; no memory is accessed.
    unsafe {
        let a = _mm256_fmadd_ps(e, map.k_hi, map.o_hi);
        let b = _mm256_fmadd_ps(e, map.k_lo, _mm256_fmadd_ps(q, map.inv_step, map.o_lo));
        let cell = _mm256_max_ps(
            _mm256_min_ps(_mm256_floor_ps(_mm256_add_ps(a, b)), map.last_cell),
            _mm256_setzero_ps(),
        );
        let offset = _mm256_mullo_epi32(_mm256_cvttps_epi32(cell), map.stride);
        (_mm256_add_ps(_mm256_sub_ps(a, cell), b), offset)
    }
}

/// The four B-spline weights at offset `f` (an offset per half: lanes
/// 0..4 hold the weights at f's lane 0, lanes 4..8 those at lane 4), by
/// Horner's rule.
#[inline(always)]
fn weights(cpu: Avx2Fma, f: __m256) -> __m256 {
    let [a, b, c, d] = [basis(cpu, 0), basis(cpu, 1), basis(cpu, 2), basis(cpu, 3)];
    // SAFETY: `cpu` proves AVX2 and FMA; no memory is accessed.
    unsafe { _mm256_fmadd_ps(_mm256_fmadd_ps(_mm256_fmadd_ps(a, f, b), f, c), f, d) }
}

/// Their derivatives, (3A·f + 2B)·f + C.
#[inline(always)]
fn weight_slopes(cpu: Avx2Fma, f: __m256) -> __m256 {
    let [a, b, c] = [basis(cpu, 0), basis(cpu, 1), basis(cpu, 2)];
    // SAFETY: `cpu` proves AVX2 and FMA; no memory is accessed.
    unsafe {
        let three_a = _mm256_mul_ps(a, _mm256_set1_ps(3.0));
        _mm256_fmadd_ps(_mm256_fmadd_ps(three_a, f, _mm256_add_ps(b, b)), f, c)
    }
}

/// `v` with its lanes picked by `idx`.
#[inline(always)]
fn pick(_cpu: Avx2Fma, v: __m256, idx: [i32; 8]) -> __m256 {
    let [i0, i1, i2, i3, i4, i5, i6, i7] = idx;
    // SAFETY: `_cpu` proves AVX2 and FMA; no memory is accessed.
    unsafe { _mm256_permutevar8x32_ps(v, _mm256_setr_epi32(i0, i1, i2, i3, i4, i5, i6, i7)) }
}

/// Row `r` of [`BASIS`] in f32, in both halves of a vector.
#[inline(always)]
fn basis(_cpu: Avx2Fma, r: usize) -> __m256 {
    let b = BASIS[r].map(|v| v as f32);
    // SAFETY: `_cpu` proves AVX2 and FMA; no memory is accessed.
    unsafe { _mm256_setr_ps(b[0], b[1], b[2], b[3], b[0], b[1], b[2], b[3]) }
}

/// One query's blend before the final horizontal sum: a vector whose
/// lanes add up to ln μ, and (if `SLOPE`) one whose lanes add up to its
/// derivative along the F* cell coordinate. `frac` holds the offset in
/// the cell along θ in lanes 0..4 and along F* in 4..8; `w_psi` the four
/// ψ weights, each in every lane.
///
/// # Safety
/// `base` must be a block offset the kernel formed: a sum over the axes
/// of cells clamped to `0..=last_cell` times `kernel.stride` (as [`cells`]
/// computes them), so that the block's last float, `base + 3·stride[0] +
/// 15`, lies inside `kernel.coefs` (the bound [`Kernel::new`] checked).
#[inline(always)]
unsafe fn blend<const SLOPE: bool>(kernel: &Kernel, base: usize, frac: __m256, w_psi: [__m256; 4]) -> (__m256, __m256) {
    let cpu = kernel.cpu;
    // [θ weights | F* weights].
    let w = weights(cpu, frac);
    // Each ψ plane's 16 floats: F* offsets 0|1, then 2|3, four θ rows each.
    // SAFETY: `psi_sum` reads the floats at base + i·psi_stride + half ..
    // base + i·psi_stride + half + 8 for i < 4 and half ∈ {0, 8}, which end
    // by base + 3·psi_stride + 16 ≤ kernel.coefs.len(): this function's
    // contract on `base` (the bound checked in `Kernel::new`, the cells
    // clamped in `cells`). So `block` and the rows are in bounds.
    let (f01_plane, f23_plane) = unsafe {
        let block = kernel.coefs.as_ptr().add(base);
        let psi_stride = kernel.stride[0] as usize;
        (
            psi_sum(cpu, block, psi_stride, &w_psi, 0),
            psi_sum(cpu, block, psi_stride, &w_psi, 8),
        )
    };
    // The (θ, F*) weights of the two halves, ready before the rows are.
    const F01: [i32; 8] = [4, 4, 4, 4, 5, 5, 5, 5];
    const F23: [i32; 8] = [6, 6, 6, 6, 7, 7, 7, 7];
    let w_theta = pick(cpu, w, [0, 1, 2, 3, 0, 1, 2, 3]);
    // SAFETY: `cpu` proves AVX2 and FMA; no memory is accessed.
    let ln_mu_terms = unsafe {
        _mm256_fmadd_ps(
            f23_plane,
            _mm256_mul_ps(w_theta, pick(cpu, w, F23)),
            _mm256_mul_ps(f01_plane, _mm256_mul_ps(w_theta, pick(cpu, w, F01))),
        )
    };
    if !SLOPE {
        return (ln_mu_terms, ln_mu_terms);
    }
    let dw = weight_slopes(cpu, frac);
    // SAFETY: `cpu` proves AVX2 and FMA; no memory is accessed.
    let slope_terms = unsafe {
        _mm256_fmadd_ps(
            f23_plane,
            _mm256_mul_ps(w_theta, pick(cpu, dw, F23)),
            _mm256_mul_ps(f01_plane, _mm256_mul_ps(w_theta, pick(cpu, dw, F01))),
        )
    };
    (ln_mu_terms, slope_terms)
}

/// Σᵢ `w_psi[i]`·(row i) over the four ψ planes, for the 8-float rows at
/// `block + i·psi_stride + half`, as a tree, (0 + 1) + (2 + 3): a shorter
/// chain.
///
/// # Safety
/// `block + i·psi_stride + half + 8` must lie in one allocation for i < 4.
#[inline(always)]
unsafe fn psi_sum(_cpu: Avx2Fma, block: *const f32, psi_stride: usize, w_psi: &[__m256; 4], half: usize) -> __m256 {
    // SAFETY: `_cpu` proves AVX2 and FMA; the four 8-float rows lie in
    // bounds by this function's contract.
    unsafe {
        let row = |i: usize| _mm256_loadu_ps(block.add(i * psi_stride + half));
        let a = _mm256_fmadd_ps(w_psi[1], row(1), _mm256_mul_ps(w_psi[0], row(0)));
        let b = _mm256_fmadd_ps(w_psi[3], row(3), _mm256_mul_ps(w_psi[2], row(2)));
        _mm256_add_ps(a, b)
    }
}

/// Widens lanes 0..4 and 4..8 of `v` to f64.
#[inline(always)]
fn widen(_cpu: Avx2Fma, v: __m256) -> [__m256d; 2] {
    // SAFETY: `_cpu` proves AVX2 and FMA; no memory is accessed.
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
#[target_feature(enable = "avx2,fma")]
fn eval<const SLOPE: bool>(kernel: &Kernel, psi: f64, theta: f64, f_star: f64) -> (f64, f64) {
    let cpu = kernel.cpu;
    // The domain check, all three at once (ordered comparisons: NaN fails).
    let query = _mm256_setr_pd(psi, theta, f_star, 1.0);
    // SAFETY: the loads read the 4 f64 of `kernel.lo` and of `kernel.hi`.
    let (lo, hi) = unsafe { (_mm256_loadu_pd(kernel.lo.as_ptr()), _mm256_loadu_pd(kernel.hi.as_ptr())) };
    let inside = _mm256_and_pd(
        _mm256_cmp_pd::<_CMP_GE_OQ>(query, lo),
        _mm256_cmp_pd::<_CMP_LE_OQ>(query, hi),
    );
    if _mm256_movemask_pd(inside) != 0b1111 {
        return (f64::NAN, f64::NAN);
    }
    let query_f32 = _mm256_set_m128(_mm_set1_ps(1.0), _mm256_cvtpd_ps(query));
    let (e, ln_m) = ln8(cpu, query_f32);
    let e = _mm256_blend_ps::<0b10>(e, _mm256_setzero_ps());
    let q = _mm256_blend_ps::<0b10>(ln_m, _mm256_sqrt_ps(query_f32));
    // SAFETY: each load reads the 8 lanes of one of the kernel's arrays.
    let map = unsafe {
        let lanes = |v: &[f32; 8]| _mm256_loadu_ps(v.as_ptr());
        CellMap {
            k_hi: lanes(&kernel.k_hi),
            k_lo: lanes(&kernel.k_lo),
            inv_step: lanes(&kernel.inv_step),
            o_hi: lanes(&kernel.o_hi),
            o_lo: lanes(&kernel.o_lo),
            last_cell: lanes(&kernel.last_cell),
            stride: _mm256_loadu_si256(kernel.stride.as_ptr().cast()),
        }
    };
    let (frac, offsets) = cells(cpu, e, q, &map);
    let low = _mm256_castsi256_si128(offsets);
    let base = _mm_cvtsi128_si32(low) + _mm_extract_epi32::<1>(low) + _mm_extract_epi32::<2>(low);
    let psi_weights = weights(cpu, pick(cpu, frac, [0; 8]));
    let w_psi = [
        pick(cpu, psi_weights, [0; 8]),
        pick(cpu, psi_weights, [1; 8]),
        pick(cpu, psi_weights, [2; 8]),
        pick(cpu, psi_weights, [3; 8]),
    ];
    // The block offset as usize, and [θ offset ×4 | F* offset ×4] as the
    // batch passes them.
    let (base, frac_theta_f_star) = (base as usize, pick(cpu, frac, [1, 1, 1, 1, 2, 2, 2, 2]));
    // SAFETY: `base` sums lanes 0..3 of `offsets`, the ψ, θ and F* cells
    // (clamped by `cells`) times the kernel's strides: a block offset the
    // kernel formed, as `blend` requires.
    let (ln_mu_terms, slope_terms) = unsafe { blend::<SLOPE>(kernel, base, frac_theta_f_star, w_psi) };
    // The batch's sum order: (t0 + t1) + (t2 + t3), plus the same of 4..8.
    let pairs = _mm256_hadd_ps(ln_mu_terms, slope_terms);
    let pairs = _mm256_hadd_ps(pairs, pairs);
    let sums = _mm_add_ps(_mm256_castps256_ps128(pairs), _mm256_extractf128_ps::<1>(pairs));
    let mu = exp8(cpu, _mm256_set1_ps(_mm_cvtss_f32(sums)));
    (_mm256_cvtss_f32(mu) as f64, _mm_cvtss_f32(_mm_movehdup_ps(sums)) as f64)
}

/// Eight located queries: block offsets, offsets in the cell on the θ
/// and F* axes, and the four ψ weights.
///
/// Invariant: every lane of `base` is a block offset the kernel formed
/// (see [`blend`]'s contract). [`locate`] writes it from [`cells`], and
/// the `Default` zeros are the block of cell (0, 0, 0); nothing else
/// writes it.
#[derive(Default)]
#[repr(C, align(32))]
struct Located {
    base: [i32; 8],
    frac_theta: [f32; 8],
    frac_f_star: [f32; 8],
    w_psi: [[f32; 8]; 4],
}

/// [`super::slope`] four at a time, its operations in its order (so the
/// same bits).
#[inline(always)]
fn slopes(kernel: &Kernel, mu: __m256d, d: __m256d, f_star: __m256d) -> __m256d {
    // SAFETY: `kernel.cpu` proves AVX2 and FMA; no memory is accessed.
    unsafe {
        let scaled = _mm256_mul_pd(_mm256_mul_pd(mu, d), _mm256_set1_pd(kernel.f_inv_step));
        _mm256_div_pd(scaled, f_star)
    }
}

/// μ (or μ and ∂μ/∂F*, as `out` asks) for every query, eight at a
/// time; returns the index of the first query outside the domain (`out`
/// is then partly written).
///
/// # Safety
/// The slices must have `out`'s length (the target features are the
/// other requirement of calling it).
#[target_feature(enable = "avx2,fma")]
unsafe fn batch(kernel: &Kernel, psi: &[f64], theta: &[f64], f_star: &[f64], out: BatchOutput) -> Option<usize> {
    // SAFETY: the slices have `out`'s length, by this function's contract.
    unsafe {
        match out {
            BatchOutput::Mu(_) => batch_with::<false>(kernel, psi, theta, f_star, out),
            BatchOutput::WithSlope(_) => batch_with::<true>(kernel, psi, theta, f_star, out),
        }
    }
}

/// [`batch`] with `SLOPE` true exactly when `out` is `BatchOutput::WithSlope`.
///
/// # Safety
/// `psi`, `theta` and `f_star` must have `out`'s length.
#[inline(always)]
unsafe fn batch_with<const SLOPE: bool>(
    kernel: &Kernel,
    psi: &[f64],
    theta: &[f64],
    f_star: &[f64],
    mut out: BatchOutput,
) -> Option<usize> {
    let n = out.len();
    // SAFETY: `kernel.cpu` proves AVX2 and FMA; no memory is accessed.
    let map = |a: usize| unsafe {
        CellMap {
            k_hi: _mm256_set1_ps(kernel.k_hi[a]),
            k_lo: _mm256_set1_ps(kernel.k_lo[a]),
            inv_step: _mm256_set1_ps(kernel.inv_step[a]),
            o_hi: _mm256_set1_ps(kernel.o_hi[a]),
            o_lo: _mm256_set1_ps(kernel.o_lo[a]),
            last_cell: _mm256_set1_ps(kernel.last_cell[a]),
            stride: _mm256_set1_epi32(kernel.stride[a]),
        }
    };
    let maps = [map(0), map(1), map(2)];
    let queries = [psi, theta, f_star];
    // Software pipelined: block i + 8 is located while block i is blended,
    // two independent chains the CPU overlaps. A block with a query
    // outside the domain ends the loop; the single-query kernel then
    // takes over from it (and finds which query it is).
    let mut located = [Located::default(), Located::default()];
    let mut i = 0;
    // SAFETY: each query slice has n elements (this function's contract),
    // and `locate` reads elements 0 .. 8 only if 8 ≤ n.
    let mut ready = n >= 8 && unsafe { locate(kernel, &maps, queries, 0, &mut located[0]) };
    while ready {
        // Here i + 8 ≤ n: `ready` is true only after a check that it is.
        let (even, odd) = located.split_at_mut(1);
        let (this, next) = if (i / 8) % 2 == 0 {
            (&even[0], &mut odd[0])
        } else {
            (&odd[0], &mut even[0])
        };
        // SAFETY: each query slice has n elements (this function's
        // contract), and `locate` reads elements i + 8 .. i + 16 only if
        // i + 16 ≤ n.
        ready = i + 16 <= n && unsafe { locate(kernel, &maps, queries, i + 8, next) };
        let (mu, d) = blend_located::<SLOPE>(kernel, this);
        match &mut out {
            BatchOutput::Mu(o) => {
                // SAFETY: `kernel.cpu` proves AVX2 and FMA; the stores write
                // o[i .. i + 8], and i + 8 ≤ n = o.len() (the loop's
                // condition, above).
                unsafe {
                    _mm256_storeu_pd(o.as_mut_ptr().add(i), mu[0]);
                    _mm256_storeu_pd(o.as_mut_ptr().add(i + 4), mu[1]);
                }
            }
            BatchOutput::WithSlope(o) => {
                let (mut mu_lanes, mut slope_lanes) = ([0.0; 8], [0.0; 8]);
                // SAFETY: `kernel.cpu` proves AVX2 and FMA; the stores write
                // elements 0..4 and 4..8 of the local arrays of 8 f64; the
                // loads read f_star[i .. i + 8], and i + 8 ≤ n = f_star.len()
                // (the loop's condition and this function's contract).
                unsafe {
                    _mm256_storeu_pd(mu_lanes.as_mut_ptr(), mu[0]);
                    _mm256_storeu_pd(mu_lanes.as_mut_ptr().add(4), mu[1]);
                    let f_lo = _mm256_loadu_pd(f_star.as_ptr().add(i));
                    _mm256_storeu_pd(slope_lanes.as_mut_ptr(), slopes(kernel, mu[0], d[0], f_lo));
                    let f_hi = _mm256_loadu_pd(f_star.as_ptr().add(i + 4));
                    _mm256_storeu_pd(slope_lanes.as_mut_ptr().add(4), slopes(kernel, mu[1], d[1], f_hi));
                }
                for j in 0..8 {
                    o[i + j] = (mu_lanes[j], slope_lanes[j]);
                }
            }
        }
        i += 8;
    }
    for j in i..n {
        // SAFETY: `eval` needs AVX2 and FMA; `kernel.cpu` proves both.
        let r = unsafe { eval::<SLOPE>(kernel, psi[j], theta[j], f_star[j]) };
        if r.0.is_nan() {
            return Some(j);
        }
        match &mut out {
            BatchOutput::Mu(o) => o[j] = r.0,
            BatchOutput::WithSlope(o) => o[j] = (r.0, super::slope(r.0, r.1, kernel.f_inv_step, f_star[j])),
        }
    }
    None
}

/// f32 coefficients in a 64-byte cache line.
const LINE_FLOATS: usize = 16;

/// Reads the coefficients through into the L2 cache, in order: one
/// software prefetch per 64-byte line (for large batches, see
/// [`Kernel::prepare`]).
///
/// It is for the caller whose caches other work has swept between
/// batches: the queries' scattered reads would find the table in memory,
/// one line at a time, and a sequential pass is far cheaper than those
/// misses (the measurements, cold and warm, are in docs/PERFORMANCE.md).
/// On warm caches the pass costs about 10 µs, which is why smaller batches
/// skip it.
#[inline(always)]
fn prefetch_coefficients(kernel: &Kernel) {
    for line in kernel.coefs.chunks(LINE_FLOATS) {
        // SAFETY: `kernel.cpu` proves AVX2 (so SSE); a prefetch reads
        // nothing into the program, and its address is in `coefs`.
        unsafe { _mm_prefetch::<_MM_HINT_T1>(line.as_ptr().cast()) };
    }
}

/// Checks, maps and locates the eight queries at `i` (one axis per
/// vector, eight queries in its lanes) into `located`; false if any is
/// outside the domain or NaN.
///
/// # Safety
/// Each slice of `queries` must hold at least `i + 8` elements.
#[inline(always)]
unsafe fn locate(kernel: &Kernel, maps: &[CellMap; 3], queries: [&[f64]; 3], i: usize, located: &mut Located) -> bool {
    let cpu = kernel.cpu;
    // SAFETY: `cpu` proves AVX2 and FMA. The loads read elements i .. i + 8
    // of each slice of `queries`, in bounds by this function's contract.
    // The aligned stores write whole 32-byte fields of `located`, each
    // 32-byte aligned (`Located` is `#[repr(C, align(32))]` and every field
    // is 32 bytes long); `base`, the sum over the axes of the clamped cells
    // times the strides (from `cells`), keeps `Located`'s invariant.
    unsafe {
        let mut inside = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
        let mut query_f32 = [_mm256_setzero_ps(); 3];
        for a in 0..3 {
            let halves = [
                _mm256_loadu_pd(queries[a].as_ptr().add(i)),
                _mm256_loadu_pd(queries[a].as_ptr().add(i + 4)),
            ];
            // Ordered comparisons: NaN fails them.
            let (lo, hi) = (_mm256_set1_pd(kernel.lo[a]), _mm256_set1_pd(kernel.hi[a]));
            for half in halves {
                inside = _mm256_and_pd(inside, _mm256_cmp_pd::<_CMP_GE_OQ>(half, lo));
                inside = _mm256_and_pd(inside, _mm256_cmp_pd::<_CMP_LE_OQ>(half, hi));
            }
            query_f32[a] = _mm256_set_m128(_mm256_cvtpd_ps(halves[1]), _mm256_cvtpd_ps(halves[0]));
        }
        if _mm256_movemask_pd(inside) != 0b1111 {
            return false;
        }
        let coords = [
            ln8(cpu, query_f32[0]),
            (_mm256_setzero_ps(), _mm256_sqrt_ps(query_f32[1])),
            ln8(cpu, query_f32[2]),
        ];
        let mut base = _mm256_setzero_si256();
        let mut frac = [_mm256_setzero_ps(); 3];
        for a in 0..3 {
            let (f, offset) = cells(cpu, coords[a].0, coords[a].1, &maps[a]);
            frac[a] = f;
            base = _mm256_add_epi32(base, offset);
        }
        _mm256_store_si256(located.base.as_mut_ptr().cast(), base);
        _mm256_store_ps(located.frac_theta.as_mut_ptr(), frac[1]);
        _mm256_store_ps(located.frac_f_star.as_mut_ptr(), frac[2]);
        for (j, field) in located.w_psi.iter_mut().enumerate() {
            let coef = |r: usize| _mm256_set1_ps(BASIS[r][j] as f32);
            let (c0, c1, c2, c3) = (coef(0), coef(1), coef(2), coef(3));
            let w = _mm256_fmadd_ps(
                _mm256_fmadd_ps(_mm256_fmadd_ps(c0, frac[0], c1), frac[0], c2),
                frac[0],
                c3,
            );
            _mm256_store_ps(field.as_mut_ptr(), w);
        }
        true
    }
}

/// Query `q` (< 8) of a located block, blended (see [`blend`]).
#[inline(always)]
fn blend_query<const SLOPE: bool>(kernel: &Kernel, located: &Located, q: usize) -> (__m256, __m256) {
    // SAFETY: `kernel.cpu` proves AVX2 and FMA; the broadcasts read
    // elements q of `located`'s arrays (bounds-checked indexing).
    let (frac, w_psi) = unsafe {
        (
            _mm256_set_m128(
                _mm_broadcast_ss(&located.frac_f_star[q]),
                _mm_broadcast_ss(&located.frac_theta[q]),
            ),
            [
                _mm256_broadcast_ss(&located.w_psi[0][q]),
                _mm256_broadcast_ss(&located.w_psi[1][q]),
                _mm256_broadcast_ss(&located.w_psi[2][q]),
                _mm256_broadcast_ss(&located.w_psi[3][q]),
            ],
        )
    };
    // SAFETY: `located.base[q]` is a block offset the kernel formed, by
    // `Located`'s invariant (written only by `locate`, from `cells`).
    unsafe { blend::<SLOPE>(kernel, located.base[q] as usize, frac, w_psi) }
}

/// The lane sums of eight vectors, in the single kernel's order.
#[inline(always)]
fn lane_sums(_cpu: Avx2Fma, terms: &[__m256; 8]) -> __m256 {
    let [t0, t1, t2, t3, t4, t5, t6, t7] = *terms;
    // SAFETY: `_cpu` proves AVX2 and FMA; no memory is accessed.
    unsafe {
        let sums03 = _mm256_hadd_ps(_mm256_hadd_ps(t0, t1), _mm256_hadd_ps(t2, t3));
        let sums47 = _mm256_hadd_ps(_mm256_hadd_ps(t4, t5), _mm256_hadd_ps(t6, t7));
        _mm256_add_ps(
            _mm256_permute2f128_ps::<0x20>(sums03, sums47),
            _mm256_permute2f128_ps::<0x31>(sums03, sums47),
        )
    }
}

/// Blends the eight located queries: their μ and (if `SLOPE`, else μ
/// again) d ln μ/d(cell coordinate of F*), in f64.
#[inline(always)]
fn blend_located<const SLOPE: bool>(kernel: &Kernel, located: &Located) -> ([__m256d; 2], [__m256d; 2]) {
    let cpu = kernel.cpu;
    // (Not `array::from_fn`, `map` or a closure: those are separate
    // functions, compiled without AVX2 and not always inlined.)
    let blended = [
        blend_query::<SLOPE>(kernel, located, 0),
        blend_query::<SLOPE>(kernel, located, 1),
        blend_query::<SLOPE>(kernel, located, 2),
        blend_query::<SLOPE>(kernel, located, 3),
        blend_query::<SLOPE>(kernel, located, 4),
        blend_query::<SLOPE>(kernel, located, 5),
        blend_query::<SLOPE>(kernel, located, 6),
        blend_query::<SLOPE>(kernel, located, 7),
    ];
    let [b0, b1, b2, b3, b4, b5, b6, b7] = blended;
    let mu = widen(
        cpu,
        exp8(cpu, lane_sums(cpu, &[b0.0, b1.0, b2.0, b3.0, b4.0, b5.0, b6.0, b7.0])),
    );
    if !SLOPE {
        return (mu, mu);
    }
    (
        mu,
        widen(cpu, lane_sums(cpu, &[b0.1, b1.1, b2.1, b3.1, b4.1, b5.1, b6.1, b7.1])),
    )
}

/// ln x = e·ln 2 + ln m on eight lanes of positive normal numbers: e and
/// ln m = 2·atanh(s), s = (m − 1)/(m + 1), error below 3e-8.
#[inline(always)]
fn ln8(_cpu: Avx2Fma, x: __m256) -> (__m256, __m256) {
    // SAFETY: `_cpu` proves AVX2 and FMA; no memory is accessed.
    unsafe {
        // x = 2^e·m, m in [√½, √2).
        let bits = _mm256_castps_si256(x);
        // Relative to the bits of √½, the exponent field counts e.
        let above_sqrt_half = _mm256_sub_epi32(bits, _mm256_set1_epi32(0x3f35_04f3));
        let e = _mm256_cvtepi32_ps(_mm256_srai_epi32::<23>(above_sqrt_half));
        let exponent_bits = _mm256_and_si256(above_sqrt_half, _mm256_set1_epi32(0xff80_0000u32 as i32));
        let m = _mm256_castsi256_ps(_mm256_sub_epi32(bits, exponent_bits));
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
#[inline(always)]
fn exp8(_cpu: Avx2Fma, x: __m256) -> __m256 {
    // SAFETY: `_cpu` proves AVX2 and FMA; no memory is accessed.
    unsafe {
        // x = n·ln 2 + r, |r| ≤ ln 2/2, with ln 2 in two parts.
        let n = _mm256_round_ps::<{ _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC }>(_mm256_mul_ps(
            x,
            _mm256_set1_ps(core::f32::consts::LOG2_E),
        ));
        let r = _mm256_fnmadd_ps(n, _mm256_set1_ps(0.693_359_4), x);
        let r = _mm256_fnmadd_ps(n, _mm256_set1_ps(-2.121_944_4e-4), r);
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
        // 2^n, by building the float's exponent bits.
        let scale = _mm256_slli_epi32::<23>(_mm256_add_epi32(_mm256_cvtps_epi32(n), _mm256_set1_epi32(127)));
        _mm256_mul_ps(y, _mm256_castsi256_ps(scale))
    }
}
