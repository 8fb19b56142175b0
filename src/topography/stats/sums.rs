//! The finite-difference path: the compensated sums, the least-squares
//! fit and the detrending (pass 1), the sweep of the moments and the
//! differences (pass 2), and their dispatch to AVX2 or portable code.

use super::{finite, positive, Detrend, StatsError, DIFFERENCES};
use crate::topography::filter::Trend;
use crate::topography::Topography;

// ---------------------------------------------------------------------------
// Summation.

/// Lanes of the inner loops (independent partial sums, vectorised).
const LANES: usize = 4;
/// Points per block: lane sums are folded into the compensated totals
/// after each block, so no plain running sum grows beyond BLOCK/LANES terms.
const BLOCK: usize = 512;

/// Neumaier's compensated sum.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Sum {
    sum: f64,
    comp: f64,
}

impl Sum {
    #[inline]
    pub(super) fn add(&mut self, x: f64) {
        let t = self.sum + x;
        if self.sum.abs() >= x.abs() {
            self.comp += (self.sum - t) + x;
        } else {
            self.comp += (x - t) + self.sum;
        }
        self.sum = t;
    }

    pub(super) fn value(&self) -> f64 {
        self.sum + self.comp
    }
}

/// `(value, 1)` for a valid value, `(0, 0)` for a missing one (NaN); with
/// `MASKED == false` every value is valid.
#[inline(always)]
fn mask<const MASKED: bool>(x: f64) -> (f64, f64) {
    if MASKED && x.is_nan() {
        (0.0, 0.0)
    } else {
        (x, 1.0)
    }
}

/// Sums `K` quantities over the points of `M` slices of the same length,
/// `kernel` giving the `K` terms from the `M` values at one index: four
/// lanes (a chunk of four indices at a time, vectorised), folded into
/// compensated totals every [`BLOCK`] indices.
#[inline(always)]
#[allow(clippy::needless_range_loop)] // lanes by index: the shape that vectorises
pub(super) fn sum_slices<const M: usize, const K: usize>(
    inputs: [&[f64]; M],
    totals: &mut [Sum; K],
    kernel: impl Fn([f64; M]) -> [f64; K],
) {
    let len = inputs.iter().map(|s| s.len()).min().unwrap_or(0);
    let mut start = 0;
    while start < len {
        let end = (start + BLOCK).min(len);
        let block = inputs.map(|s| &s[start..end]);
        let n = end - start;
        let full = n - n % LANES;
        let mut lanes = [[0.0f64; LANES]; K];
        let mut c = 0;
        while c < full {
            let chunk = block.map(|s| &s[c..c + LANES]);
            for l in 0..LANES {
                let terms = kernel(std::array::from_fn(|m| chunk[m][l]));
                for k in 0..K {
                    lanes[k][l] += terms[k];
                }
            }
            c += LANES;
        }
        for i in full..n {
            let terms = kernel(std::array::from_fn(|m| block[m][i]));
            for k in 0..K {
                lanes[k][0] += terms[k];
            }
        }
        for k in 0..K {
            totals[k].add((lanes[k][0] + lanes[k][2]) + (lanes[k][1] + lanes[k][3]));
        }
        start = end;
    }
}

/// The two passes compiled twice: for any x86-64 CPU (SSE2), and for one
/// with AVX2 (wider vectors), chosen at run time. The code and the order of
/// every operation are the same (no fused multiply-adds), so the results are
/// the same bit for bit.
pub(super) mod dispatch {
    use super::{FitSums, Plane, Sweep, Topography};

    #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
    fn avx2() -> bool {
        std::is_x86_feature_detected!("avx2")
    }

    /// [`super::fit_sums`].
    pub(in crate::topography::stats) fn fit_sums(t: &Topography, z0: f64) -> FitSums {
        #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
        if avx2() {
            // SAFETY: the CPU supports AVX2 (just detected).
            return unsafe { fit_sums_avx2(t, z0) };
        }
        super::fit_sums(t, z0)
    }

    /// [`super::sweep`].
    pub(in crate::topography::stats) fn sweep<const MASKED: bool>(t: &Topography, z0: f64, plane: &Plane) -> Sweep {
        #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
        if avx2() {
            // SAFETY: the CPU supports AVX2 (just detected).
            return unsafe { sweep_avx2::<MASKED>(t, z0, plane) };
        }
        super::sweep::<MASKED>(t, z0, plane)
    }

    /// [`super::fit_sums`] with AVX2.
    ///
    /// # Safety
    /// The CPU must support AVX2.
    #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
    #[target_feature(enable = "avx2")]
    unsafe fn fit_sums_avx2(t: &Topography, z0: f64) -> FitSums {
        super::fit_sums(t, z0)
    }

    /// [`super::sweep`] with AVX2.
    ///
    /// # Safety
    /// The CPU must support AVX2.
    #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
    #[target_feature(enable = "avx2")]
    unsafe fn sweep_avx2<const MASKED: bool>(t: &Topography, z0: f64, plane: &Plane) -> Sweep {
        super::sweep::<MASKED>(t, z0, plane)
    }
}

// ---------------------------------------------------------------------------
// Pass 1: the sums of the least-squares fit.

/// Sums over the valid points, with u = i − (nx − 1)/2 and v = j − (ny −
/// 1)/2 the centred sample indices and z' = z − z0.
#[derive(Default)]
pub(super) struct FitSums {
    pub(super) n: Sum,
    su: Sum,
    sv: Sum,
    suu: Sum,
    svv: Sum,
    suv: Sum,
    sz: Sum,
    suz: Sum,
    svz: Sum,
    /// |z0| + rms(z − z0) (metres): the scale of the rounding of the
    /// detrended heights.
    pub(super) scale: f64,
}

/// The fitted trend z − z0 = a + b·u + c·v (per sample index).
pub(super) struct Plane {
    pub(super) a: f64,
    pub(super) b: f64,
    pub(super) c: f64,
}

pub(super) fn centred(n: usize) -> impl Fn(usize) -> f64 {
    let centre = 0.5 * (n as f64 - 1.0);
    move |i| i as f64 - centre
}

#[inline(always)]
fn fit_sums(t: &Topography, z0: f64) -> FitSums {
    let (nx, ny) = (t.nx, t.ny);
    let u_of = centred(nx);
    let v_of = centred(ny);
    let u: Vec<f64> = (0..nx).map(&u_of).collect();
    let mut fit = FitSums::default();
    let mut szz = Sum::default();
    for (j, row) in t.heights.chunks_exact(nx).enumerate() {
        let v = v_of(j);
        let mut row_sums = [Sum::default(); 6];
        sum_slices([row, &u], &mut row_sums, |[z, u]| {
            let (z, w) = mask::<true>(z - z0);
            let uw = u * w;
            [w, uw, uw * u, z, uw * z, z * z]
        });
        let [n, su, suu, sz, suz, zz] = row_sums.map(|s| s.value());
        fit.n.add(n);
        fit.su.add(su);
        fit.suu.add(suu);
        fit.sz.add(sz);
        fit.suz.add(suz);
        fit.sv.add(v * n);
        fit.svv.add(v * v * n);
        fit.suv.add(v * su);
        fit.svz.add(v * sz);
        szz.add(zz);
    }
    let n = fit.n.value();
    fit.scale = z0.abs() + if n > 0.0 { (szz.value() / n).sqrt() } else { 0.0 };
    fit
}

impl FitSums {
    pub(super) fn solve(&self, detrend: Detrend) -> Result<Plane, StatsError> {
        let n = self.n.value();
        let (su, sv, sz) = (self.su.value(), self.sv.value(), self.sz.value());
        let cuu = self.suu.value() - su * su / n;
        let cvv = self.svv.value() - sv * sv / n;
        let cuv = self.suv.value() - su * sv / n;
        let cuz = self.suz.value() - su * sz / n;
        let cvz = self.svz.value() - sv * sz / n;
        let (b, c) = match detrend {
            Detrend::Mean => (0.0, 0.0),
            Detrend::Line => {
                if cuu.is_nan() || cuu <= 0.0 {
                    return Err(StatsError::Undetermined { detrend });
                }
                (cuz / cuu, 0.0)
            }
            Detrend::Plane => {
                let det = cuu * cvv - cuv * cuv;
                if det.is_nan() || det <= 1e-12 * cuu * cvv {
                    return Err(StatsError::Undetermined { detrend });
                }
                ((cuz * cvv - cvz * cuv) / det, (cvz * cuu - cuz * cuv) / det)
            }
        };
        Ok(Plane {
            a: (sz - b * su - c * sv) / n,
            b,
            c,
        })
    }
}

// ---------------------------------------------------------------------------
// Pass 2: moments of the detrended heights and the differences.

/// The sums of the second pass.
#[derive(Default)]
pub(super) struct Sweep {
    /// Σr, Σr², Σr³, Σr⁴ of the detrended heights r.
    pub(super) moments: [Sum; 4],
    /// Σ d², Σ e², count(d), count(e) along x: d the first differences of
    /// the detrended heights, e the second differences.
    x: [Sum; 4],
    /// The same along y (zero for a profile).
    y: [Sum; 4],
    /// Spectral moments instead: m20, m40, m02, m04 directly.
    pub(super) spectral: Option<[f64; 4]>,
}

impl Sweep {
    /// m20, m40, and for a map m02, m04.
    pub(super) fn derivatives(&self, t: &Topography) -> Result<(f64, f64, Option<f64>, Option<f64>), StatsError> {
        if let Some([m20, m40, m02, m04]) = self.spectral {
            positive("m20", m20)?;
            finite("m40", m40)?;
            return Ok(match t.dy {
                Some(_) => (m20, m40, Some(positive("m02", m02)?), Some(finite("m04", m04)?)),
                None => (m20, m40, None, None),
            });
        }
        let (m20, m40) = moments_of(&self.x, t.dx, "m20", "m40")?;
        match t.dy {
            Some(dy) => {
                let (m02, m04) = moments_of(&self.y, dy, "m02", "m04")?;
                Ok((m20, m40, Some(m02), Some(m04)))
            }
            None => Ok((m20, m40, None, None)),
        }
    }
}

/// The mean squares of the first and second differences along one
/// direction, over the sampling interval h squared and to the fourth.
fn moments_of(sums: &[Sum; 4], h: f64, m2: &'static str, m4: &'static str) -> Result<(f64, f64), StatsError> {
    let [d2, e2, nd, ne] = sums.map(|s| s.value());
    for (name, count) in [(m2, nd), (m4, ne)] {
        if !DIFFERENCES.contains(count) {
            return Err(StatsError::TooFewDifferences {
                name,
                count: count as usize,
            });
        }
    }
    let h2 = h * h;
    let m2v = positive(m2, d2 / nd / h2)?;
    let m4v = finite(m4, e2 / ne / (h2 * h2))?;
    Ok((m2v, m4v))
}

/// The second pass: every row once, with its neighbours above and below.
#[inline(always)]
fn sweep<const MASKED: bool>(t: &Topography, z0: f64, plane: &Plane) -> Sweep {
    let (nx, ny) = (t.nx, t.ny);
    let u_of = centred(nx);
    let v_of = centred(ny);
    // The plane's x part, b·u, for one row (a row's worth, not a map's).
    let lin: Vec<f64> = (0..nx).map(|i| plane.b * u_of(i)).collect();
    let mut out = Sweep::default();
    let rows: Vec<&[f64]> = t.heights.chunks_exact(nx).collect();
    for (j, &row) in rows.iter().enumerate() {
        // Moments of r = (z − z0) − (a + c·v + b·u).
        let p = plane.a + plane.c * v_of(j);
        sum_slices([row, &lin], &mut out.moments, |[z, l]| {
            let (r, _) = mask::<MASKED>((z - z0) - (p + l));
            let r2 = r * r;
            [r, r2, r2 * r, r2 * r2]
        });
        // Along x: first differences (less the plane's slope b) and
        // second differences, centred at i + 1.
        differences::<MASKED>(&mut out.x, row, plane.b);
        // Along y: between this row and the one before, and centred on
        // this row.
        if j >= 1 {
            let prev = rows[j - 1];
            if let Some(&next) = rows.get(j + 1) {
                let mut s = [Sum::default(); 4];
                sum_slices([prev, row, next], &mut s, |[z0, z1, z2]| {
                    let (d, wd) = mask::<MASKED>((z1 - z0) - plane.c);
                    let (e, we) = mask::<MASKED>((z2 - z1) - (z1 - z0));
                    [d * d, e * e, wd, we]
                });
                for (total, s) in out.y.iter_mut().zip(&s) {
                    total.add(s.value());
                }
            } else {
                let mut s = [Sum::default(); 2];
                sum_slices([prev, row], &mut s, |[z0, z1]| {
                    let (d, wd) = mask::<MASKED>((z1 - z0) - plane.c);
                    [d * d, wd]
                });
                out.y[0].add(s[0].value());
                out.y[2].add(s[1].value());
            }
        }
    }
    out
}

/// First and second differences along a line `z` of n ≥ 3 points: Σd²,
/// Σe² and their counts added to `totals`, d = (z\[i+1\] − z\[i\]) − slope,
/// e = (z\[i+2\] − z\[i+1\]) − (z\[i+1\] − z\[i\]) (differences of neighbours
/// first: exact for heights with a large offset).
#[inline(always)]
fn differences<const MASKED: bool>(totals: &mut [Sum; 4], z: &[f64], slope: f64) {
    let n = z.len();
    if n < 3 {
        return;
    }
    let mut s = [Sum::default(); 4];
    sum_slices([&z[..n - 2], &z[1..n - 1], &z[2..]], &mut s, |[z0, z1, z2]| {
        let (d, wd) = mask::<MASKED>((z1 - z0) - slope);
        let (e, we) = mask::<MASKED>((z2 - z1) - (z1 - z0));
        [d * d, e * e, wd, we]
    });
    // The last pair.
    let (d, wd) = mask::<MASKED>((z[n - 1] - z[n - 2]) - slope);
    s[0].add(d * d);
    s[2].add(wd);
    for (total, s) in totals.iter_mut().zip(&s) {
        total.add(s.value());
    }
}

impl Topography {
    /// The heights less their least-squares plane, line or mean (as
    /// `detrend` says, fitted over the valid points; a profile's plane is
    /// its line), row-major, missing points still NaN: the heights whose
    /// moments [`Topography::stats`] takes, for an empirical density.
    pub fn detrended(&self, detrend: Detrend) -> Result<Vec<f64>, StatsError> {
        let trend = self.trend(detrend)?;
        let (mut out, mut row_buffer) = (Vec::with_capacity(self.heights.len()), Vec::new());
        for (j, row) in self.heights.chunks_exact(self.nx).enumerate() {
            out.extend_from_slice(trend.row(j, row, &mut row_buffer));
        }
        Ok(out)
    }

    /// The least-squares plane, line or mean of [`Topography::detrended`]
    /// (fitted over the valid points), to take off row by row.
    pub(crate) fn trend(&self, detrend: Detrend) -> Result<Trend, StatsError> {
        let Some(z0) = self.heights.iter().copied().find(|h| !h.is_nan()) else {
            return Err(StatsError::TooFewValid {
                valid: 0,
                missing: self.heights.len(),
            });
        };
        let detrend = match detrend {
            Detrend::Plane if self.is_profile() => Detrend::Line,
            other => other,
        };
        let plane = dispatch::fit_sums(self, z0).solve(detrend)?;
        let (u_of, v_of) = (centred(self.nx), centred(self.ny));
        Ok(Trend {
            z0,
            rows: (0..self.ny).map(|j| plane.a + plane.c * v_of(j)).collect(),
            columns: (0..self.nx).map(|i| plane.b * u_of(i)).collect(),
        })
    }
}
