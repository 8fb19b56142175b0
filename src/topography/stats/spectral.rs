//! The spectral path: m2 and m4 from the discrete Fourier transforms of
//! the rows and columns. The FFTs are the `realfft` crate's (over
//! `rustfft`).

use super::sums::{centred, sum_slices, Plane, Sum, Sweep};
use crate::topography::Topography;
use realfft::{num_complex::Complex, RealFftPlanner};
use std::f64::consts::PI;

/// Moments of the heights as in the finite-difference sweep, m2 and m4
/// from the discrete Fourier transforms of the rows and the columns of the
/// detrended heights (no missing points): the mean over rows of the per-row moments equals
/// the 2-D spectral sum Σ (2π·f_x)^p·|Z|²/N² by Parseval's theorem along y.
///
/// The transforms are the `realfft` crate's (real input, the half spectrum
/// k = 0..=N/2; over `rustfft`).
pub(super) fn spectral(t: &Topography, z0: f64, plane: &Plane) -> Sweep {
    let (nx, ny) = (t.nx, t.ny);
    let mut out = sweep_moments_only(t, z0, plane);
    let u_of = centred(nx);
    let v_of = centred(ny);
    let residual = |i: usize, j: usize, z: f64| (z - z0) - (plane.a + plane.c * v_of(j) + plane.b * u_of(i));

    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(nx);
    let mut buf = fft.make_input_vec();
    let mut spectrum = fft.make_output_vec();
    let mut scratch = fft.make_scratch_vec();
    let (mut m20, mut m40) = (Sum::default(), Sum::default());
    for (j, row) in t.heights.chunks_exact(nx).enumerate() {
        for (i, (b, &z)) in buf.iter_mut().zip(row).enumerate() {
            *b = residual(i, j, z);
        }
        fft.process_with_scratch(&mut buf, &mut spectrum, &mut scratch)
            .expect("buffers of the plan's lengths");
        let (s2, s4) = line_moments(&spectrum, nx, t.dx);
        m20.add(s2);
        m40.add(s4);
    }
    let mut result = [m20.value() / ny as f64, m40.value() / ny as f64, 0.0, 0.0];

    if let Some(dy) = t.dy {
        // Columns, gathered a few at a time (one cache line of each row).
        const COLUMNS: usize = 8;
        let fft = planner.plan_fft_forward(ny);
        let mut spectrum = fft.make_output_vec();
        let mut scratch = fft.make_scratch_vec();
        let mut cols = vec![fft.make_input_vec(); COLUMNS];
        let (mut m02, mut m04) = (Sum::default(), Sum::default());
        let mut i0 = 0;
        while i0 < nx {
            let width = COLUMNS.min(nx - i0);
            for (j, row) in t.heights.chunks_exact(nx).enumerate() {
                for (k, col) in cols.iter_mut().take(width).enumerate() {
                    let i = i0 + k;
                    col[j] = residual(i, j, row[i]);
                }
            }
            for col in cols.iter_mut().take(width) {
                fft.process_with_scratch(col, &mut spectrum, &mut scratch)
                    .expect("buffers of the plan's lengths");
                let (s2, s4) = line_moments(&spectrum, ny, dy);
                m02.add(s2);
                m04.add(s4);
            }
            i0 += width;
        }
        result[2] = m02.value() / nx as f64;
        result[3] = m04.value() / nx as f64;
    }
    out.spectral = Some(result);
    out
}

/// The rms jump of the detrended heights across the edges (last point
/// minus first, of every row and, for a map, every column): the
/// discontinuity the spectral moments see in the periodic continuation.
/// Larger than the rms height, and the moments are the jump's
/// ([`crate::Warning::NonPeriodic`]).
pub(super) fn edge_mismatch(t: &Topography, z0: f64, plane: &Plane) -> f64 {
    let (nx, ny) = (t.nx, t.ny);
    let u_of = centred(nx);
    let v_of = centred(ny);
    let residual =
        |i: usize, j: usize| (t.heights[j * nx + i] - z0) - (plane.a + plane.c * v_of(j) + plane.b * u_of(i));
    let (mut sum, mut n) = (Sum::default(), 0usize);
    for j in 0..ny {
        let d = residual(nx - 1, j) - residual(0, j);
        sum.add(d * d);
        n += 1;
    }
    if t.dy.is_some() {
        for i in 0..nx {
            let d = residual(i, ny - 1) - residual(i, 0);
            sum.add(d * d);
            n += 1;
        }
    }
    (sum.value() / n as f64).sqrt()
}

/// Σ (2π·f_k)²·|X_k|²/N² and Σ (2π·f_k)⁴·|X_k|²/N² over the transform X
/// of one real line of N points spaced h, the Nyquist term (k = N/2, N
/// even) dropped; `half` is the half spectrum X_0..X_{N/2} of the line
/// (X_{N−k} = conj X_k counts each 0 < k < N/2 twice).
fn line_moments(half: &[Complex<f64>], n: usize, h: f64) -> (f64, f64) {
    let (mut s2, mut s4) = (Sum::default(), Sum::default());
    let scale = 2.0 * PI / (n as f64 * h);
    for (k, xk) in half.iter().enumerate().skip(1) {
        if 2 * k >= n {
            continue;
        }
        let w = (scale * k as f64).powi(2);
        let p = 2.0 * xk.norm_sqr();
        s2.add(w * p);
        s4.add(w * w * p);
    }
    let n2 = (n as f64) * (n as f64);
    (s2.value() / n2, s4.value() / n2)
}

/// The moments of the detrended heights alone (no missing points).
fn sweep_moments_only(t: &Topography, z0: f64, plane: &Plane) -> Sweep {
    let nx = t.nx;
    let u_of = centred(nx);
    let v_of = centred(t.ny);
    let lin: Vec<f64> = (0..nx).map(|i| plane.b * u_of(i)).collect();
    let mut out = Sweep::default();
    for (j, row) in t.heights.chunks_exact(nx).enumerate() {
        let p = plane.a + plane.c * v_of(j);
        sum_slices([row, &lin], &mut out.moments, |[z, l]| {
            let r = (z - z0) - (p + l);
            let r2 = r * r;
            [r, r2, r2 * r, r2 * r2]
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `line_moments` of the `realfft` half spectrum against the sums of
    /// a direct DFT over every k (both halves).
    #[test]
    fn line_moments_match_a_direct_dft() {
        let h = 0.7;
        for n in [2usize, 3, 8, 16, 17, 30, 100, 128, 243] {
            let x: Vec<f64> = (0..n).map(|j| (j as f64 * 0.37).sin() + 0.1 * j as f64).collect();
            let (mut w2, mut w4) = (0.0, 0.0);
            for k in 1..n {
                if 2 * k == n {
                    continue;
                }
                let (mut re, mut im) = (0.0, 0.0);
                for (j, v) in x.iter().enumerate() {
                    let (s, c) = (2.0 * PI * ((j * k) % n) as f64 / n as f64).sin_cos();
                    re += v * c;
                    im -= v * s;
                }
                let f = 2.0 * PI * k.min(n - k) as f64 / (n as f64 * h);
                let p = (re * re + im * im) / (n * n) as f64;
                w2 += f * f * p;
                w4 += f.powi(4) * p;
            }
            let fft = RealFftPlanner::<f64>::new().plan_fft_forward(n);
            let (mut input, mut half) = (x.clone(), fft.make_output_vec());
            fft.process(&mut input, &mut half).unwrap();
            let (g2, g4) = line_moments(&half, n, h);
            let scale = w2.abs().max(1e-300);
            assert!((g2 - w2).abs() <= 1e-12 * scale, "n = {n}: {g2} vs {w2}");
            assert!((g4 - w4).abs() <= 1e-12 * w4.abs().max(1e-300), "n = {n}: {g4} vs {w4}");
        }
    }
}
