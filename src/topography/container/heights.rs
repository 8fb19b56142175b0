//! A measurement's heights as a container gives them: `x z` profiles,
//! maps indexed `[x, y]`, the `height_scale` and the `detrend_mode`
//! (SurfaceTopography's conventions).

use super::{DetrendMode, Heights, UNIFORM_TOLERANCE};
use crate::topography::Topography;

/// An `x z` profile (rows of `x, z` in the file's unit, `unit` metres
/// each) in SurfaceTopography's XYZ convention: x shifted to start at 0;
/// uniform if every step is within 10⁻⁶ (file units) of the mean step,
/// with the size `n` times that step; else nonuniform (x must increase).
pub(super) fn xz_profile(rows: &[f64], unit: f64) -> Result<Heights, String> {
    let n = rows.len() / 2;
    if rows.chunks_exact(2).any(|r| r[0].is_nan()) {
        return Err("missing (NaN) x in an x z profile".into());
    }
    let min = rows.chunks_exact(2).map(|r| r[0]).fold(f64::INFINITY, f64::min);
    let x: Vec<f64> = rows.chunks_exact(2).map(|r| r[0] - min).collect();
    let z: Vec<f64> = rows.chunks_exact(2).map(|r| r[1] * unit).collect();
    if z.iter().any(|v| v.is_nan()) {
        return Err("missing (NaN) heights in an x z profile".into());
    }
    let step = (x[n - 1] - x[0]) / (n - 1) as f64;
    let uniform = x.windows(2).all(|w| ((w[1] - w[0]) - step).abs() < UNIFORM_TOLERANCE);
    if uniform {
        return Topography::profile(z, step * unit)
            .map(Heights::Uniform)
            .map_err(|e| e.to_string());
    }
    if x.windows(2).any(|w| w[1] <= w[0]) {
        return Err("the x of an x z profile do not increase (a reentrant profile is not read)".into());
    }
    Ok(Heights::Nonuniform {
        x: x.iter().map(|v| v * unit).collect(),
        z,
    })
}

/// A map indexed `[x, y]` (a container's `.npy`) from one read as rows of
/// y.
pub(super) fn transpose(t: &Topography) -> Topography {
    let Some(dy) = t.dy() else { return t.clone() };
    let (nx, ny) = (t.nx(), t.ny());
    let h = t.heights();
    let mut out = Vec::with_capacity(h.len());
    for i in 0..nx {
        for j in 0..ny {
            out.push(h[j * nx + i]);
        }
    }
    Topography::map(out, ny, nx, dy, t.dx())
        .expect("the transposed grid of a valid map")
        .with_metadata(t.metadata().clone())
}

pub(super) fn scale_heights(h: &mut Heights, scale: f64) {
    if scale == 1.0 {
        return;
    }
    match h {
        Heights::Uniform(t) => {
            let heights = t.heights().iter().map(|z| z * scale).collect();
            *t = rebuilt(t, heights);
        }
        Heights::Nonuniform { z, .. } => z.iter_mut().for_each(|v| *v *= scale),
    }
}

/// `t` with other heights (same grid).
fn rebuilt(t: &Topography, heights: Vec<f64>) -> Topography {
    let r = match t.dy() {
        Some(dy) => Topography::map(heights, t.nx(), t.ny(), t.dx(), dy),
        None => Topography::profile(heights, t.dx()),
    };
    r.expect("finite heights on a valid grid")
        .with_metadata(t.metadata().clone())
}

/// Removes the polynomial of `mode` as SurfaceTopography's `detrend` does
/// (least squares over the defined points; nonuniform: over the piecewise
/// linear profile). Own code: the fits are of 1 to 6 terms, and the
/// library's plane fit (stats) has no quadric and no nonuniform profile.
// Index loops: the normal equations read as the formulas they are.
#[allow(clippy::needless_range_loop)]
pub(super) fn detrend(h: &mut Heights, mode: DetrendMode) {
    let deg = match mode {
        DetrendMode::None => return,
        DetrendMode::Center => 0,
        DetrendMode::Height => 1,
        DetrendMode::Curvature => 2,
    };
    match h {
        Heights::Uniform(t) => {
            let (nx, ny) = (t.nx(), t.ny());
            // Normalised coordinates x/Lx = i/nx, y/Ly = j/ny, centred
            // for the conditioning of the normal equations.
            let cx = (nx as f64 - 1.0) / (2.0 * nx as f64);
            let cy = (ny as f64 - 1.0) / (2.0 * ny as f64);
            let basis = |i: usize, j: usize, out: &mut [f64; 6]| -> usize {
                let x = i as f64 / nx as f64 - cx;
                let y = j as f64 / ny as f64 - cy;
                out[0] = 1.0;
                match (deg, ny > 1) {
                    (0, _) => 1,
                    (1, false) => {
                        out[1] = x;
                        2
                    }
                    (2, false) => {
                        out[1] = x;
                        out[2] = x * x;
                        3
                    }
                    (1, true) => {
                        out[1] = x;
                        out[2] = y;
                        3
                    }
                    _ => {
                        out[1] = x;
                        out[2] = y;
                        out[3] = x * x;
                        out[4] = y * y;
                        out[5] = x * y;
                        6
                    }
                }
            };
            let z = t.heights();
            let mut a = [[0.0; 6]; 6];
            let mut b = [0.0; 6];
            let mut f = [0.0; 6];
            let mut k = 1;
            for j in 0..ny {
                for i in 0..nx {
                    let v = z[j * nx + i];
                    if v.is_nan() {
                        continue;
                    }
                    k = basis(i, j, &mut f);
                    for r in 0..k {
                        b[r] += f[r] * v;
                        for c in 0..k {
                            a[r][c] += f[r] * f[c];
                        }
                    }
                }
            }
            let Some(coef) = solve(&mut a, &mut b, k) else { return };
            let mut out = Vec::with_capacity(z.len());
            for j in 0..ny {
                for i in 0..nx {
                    let k = basis(i, j, &mut f);
                    let p: f64 = (0..k).map(|r| coef[r] * f[r]).sum();
                    out.push(z[j * nx + i] - p);
                }
            }
            *t = rebuilt(t, out);
        }
        Heights::Nonuniform { x, z } => {
            // SurfaceTopography's nonuniform polyfit: the normal equations
            // of the piecewise linear profile, in coordinates centred on
            // the scan.
            let n = x.len();
            let x0 = (x[0] + x[n - 1]) / 2.0;
            let xs: Vec<f64> = x.iter().map(|v| v - x0).collect();
            let k = deg + 1;
            let mut a = [[0.0; 6]; 6];
            let mut b = [0.0; 6];
            for s in 0..n - 1 {
                let (x1, x2, h1, h2) = (xs[s], xs[s + 1], z[s], z[s + 1]);
                let d = x2 - x1;
                for r in 0..k {
                    let r_ = r as i32;
                    b[r] += ((2.0 * h1 + h2) * x1.powi(r_) + (2.0 * h2 + h1) * x2.powi(r_)) * d;
                    for c in 0..k {
                        let c_ = c as i32;
                        a[r][c] += (2.0 * x1.powi(r_ + c_)
                            + 2.0 * x2.powi(r_ + c_)
                            + x1.powi(r_) * x2.powi(c_)
                            + x2.powi(r_) * x1.powi(c_))
                            * d;
                    }
                }
            }
            let Some(coef) = solve(&mut a, &mut b, k) else { return };
            for (v, xv) in z.iter_mut().zip(&xs) {
                let p: f64 = (0..k).map(|r| coef[r] * xv.powi(r as i32)).sum();
                *v -= p;
            }
        }
    }
}

/// Solves the k × k system by Gaussian elimination with partial pivoting;
/// `None` if singular.
#[allow(clippy::needless_range_loop)]
fn solve(a: &mut [[f64; 6]; 6], b: &mut [f64; 6], k: usize) -> Option<[f64; 6]> {
    for col in 0..k {
        let p = (col..k).max_by(|&r, &s| a[r][col].abs().total_cmp(&a[s][col].abs()))?;
        if a[p][col] == 0.0 || !a[p][col].is_finite() {
            return None;
        }
        a.swap(col, p);
        b.swap(col, p);
        for r in col + 1..k {
            let f = a[r][col] / a[col][col];
            for c in col..k {
                a[r][c] -= f * a[col][c];
            }
            b[r] -= f * b[col];
        }
    }
    let mut x = [0.0; 6];
    for r in (0..k).rev() {
        let s: f64 = (r + 1..k).map(|c| a[r][c] * x[c]).sum();
        x[r] = (b[r] - s) / a[r][r];
    }
    Some(x)
}
