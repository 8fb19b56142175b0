//! The upper tail of the measured heights, kept small: the highest
//! [`TAIL_SAMPLE`] detrended heights (over σ) and the count of points
//! beyond [`SPIKE_SIGMA`]·σ either side, from one extra pass over the
//! heights at [`Topography::stats`](crate::topography::Topography::stats)
//! that allocates nothing of the map's size. What the `tail` and `spikes`
//! warnings ([`crate::Warning::Tail`], [`crate::Warning::Spikes`]) need,
//! without a copy of the heights.

use super::sums::{centred, Plane};
use crate::topography::Topography;
use crate::warning::SPIKE_SIGMA;

/// The highest heights kept: enough to count exactly the points above a
/// separation up to this many (the `tail` warning asks for
/// [`TAIL_MIN_POINTS`](crate::warning::TAIL_MIN_POINTS)).
pub const TAIL_SAMPLE: usize = 64;

/// The highest detrended heights of a surface over σ, and its spikes.
#[derive(Debug, Clone, PartialEq)]
pub struct HeightTail {
    /// The highest heights over σ, descending, at most [`TAIL_SAMPLE`]
    /// (heights measured from the mean plane of the heights).
    top: Vec<f64>,
    /// Points beyond ±[`SPIKE_SIGMA`]·σ.
    beyond: usize,
}

impl HeightTail {
    /// The tail of `t`'s heights detrended by `plane` about `z0`, their
    /// mean `mean` and rms `sigma` (the statistics' own).
    pub(super) fn of(t: &Topography, z0: f64, plane: &Plane, mean: f64, sigma: f64) -> HeightTail {
        let limit = SPIKE_SIGMA * sigma;
        #[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
        let (mut top, beyond) = if std::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2 (just detected).
            unsafe { scan_avx2(t, z0, plane, mean, limit) }
        } else {
            scan(t, z0, plane, mean, limit)
        };
        #[cfg(not(all(target_arch = "x86_64", not(ke_friction_portable))))]
        let (mut top, beyond) = scan(t, z0, plane, mean, limit);
        top.sort_by(|a, b| b.total_cmp(a));
        top.iter_mut().for_each(|x| *x /= sigma);
        HeightTail { top, beyond }
    }

    /// The highest measured height over σ.
    pub fn max(&self) -> f64 {
        self.top.first().copied().unwrap_or(f64::NAN)
    }

    /// How many measured heights lie above `level`·σ: exact below
    /// [`TAIL_SAMPLE`], else at least that many (`TAIL_SAMPLE` is returned).
    pub fn count_above(&self, level: f64) -> usize {
        self.top.iter().take_while(|&&x| x > level).count()
    }

    /// Points beyond ±[`SPIKE_SIGMA`]·σ of the mean plane.
    pub fn beyond(&self) -> usize {
        self.beyond
    }
}

/// [`scan`] with AVX2.
///
/// # Safety
/// The CPU must support AVX2.
#[cfg(all(target_arch = "x86_64", not(ke_friction_portable)))]
#[target_feature(enable = "avx2")]
unsafe fn scan_avx2(t: &Topography, z0: f64, plane: &Plane, mean: f64, limit: f64) -> (Vec<f64>, usize) {
    scan(t, z0, plane, mean, limit)
}

/// The [`TAIL_SAMPLE`] highest of the heights detrended by `plane` about
/// `z0` less `mean` (unsorted), and the count of those beyond ±`limit`.
///
/// Two passes. The first, without branches (vectorised), counts the
/// points beyond the limit and takes each row's largest residual. The
/// [`TAIL_SAMPLE`] highest heights are at or above the
/// [`TAIL_SAMPLE`]-th highest of those row maxima (that many rows reach
/// it), so the second pass reads only the rows whose maximum reaches the
/// floor (about [`TAIL_SAMPLE`] of them), keeping the candidates at or
/// above it; when 2·[`TAIL_SAMPLE`] are held, a selection keeps the
/// highest and raises the floor. One branchy loop over every point cost
/// 26 instructions a point on a 256² map (4.6 % of a `kefric surface`
/// run).
#[inline(always)]
fn scan(t: &Topography, z0: f64, plane: &Plane, mean: f64, limit: f64) -> (Vec<f64>, usize) {
    let (u_of, v_of) = (centred(t.nx), centred(t.ny));
    let lin: Vec<f64> = (0..t.nx).map(|i| plane.b * u_of(i)).collect();
    let offset = |j: usize| plane.a + plane.c * v_of(j) + mean;
    let rows = || t.heights.chunks_exact(t.nx).enumerate();
    let mut highest = Vec::with_capacity(t.ny);
    let mut beyond = 0usize;
    for (j, row) in rows() {
        let p = offset(j);
        // Four lanes (the compiler makes them one vector: a select on
        // `r > most` is a max instruction, where `f64::max`'s NaN rule
        // kept the loop scalar). NaN (missing) compares false: never
        // counted, never the largest.
        let (mut most, mut count) = ([f64::NEG_INFINITY; 4], [0u64; 4]);
        let mut lane = |k: usize, z: f64, l: f64| {
            let r = (z - z0) - (p + l);
            count[k] += u64::from(r.abs() > limit);
            most[k] = if r > most[k] { r } else { most[k] };
        };
        let (zs, ls) = (row.chunks_exact(4), lin.chunks_exact(4));
        let (z_rest, l_rest) = (zs.remainder(), ls.remainder());
        for (z, l) in zs.zip(ls) {
            for k in 0..4 {
                lane(k, z[k], l[k]);
            }
        }
        for (&z, &l) in z_rest.iter().zip(l_rest) {
            lane(0, z, l);
        }
        beyond += count.iter().sum::<u64>() as usize;
        highest.push(
            most.into_iter()
                .fold(f64::NEG_INFINITY, |m, r| if r > m { r } else { m }),
        );
    }
    let mut floor = if highest.len() >= TAIL_SAMPLE {
        let mut maxima = highest.clone();
        *maxima.select_nth_unstable_by(TAIL_SAMPLE - 1, |a, b| b.total_cmp(a)).1
    } else {
        f64::NEG_INFINITY
    };
    let mut top: Vec<f64> = Vec::with_capacity(2 * TAIL_SAMPLE);
    for (j, row) in rows() {
        // Neither is NaN (a row maximum starts at −∞).
        if highest[j] < floor {
            continue;
        }
        let p = offset(j);
        for (&z, &l) in row.iter().zip(&lin) {
            let r = (z - z0) - (p + l);
            if r >= floor {
                top.push(r);
                if top.len() == 2 * TAIL_SAMPLE {
                    floor = keep_highest(&mut top);
                }
            }
        }
    }
    if top.len() > TAIL_SAMPLE {
        keep_highest(&mut top);
    }
    (top, beyond)
}

/// Keeps the [`TAIL_SAMPLE`] highest of `top` (more than that many);
/// returns the lowest kept.
fn keep_highest(top: &mut Vec<f64>) -> f64 {
    let (_, &mut lowest, _) = top.select_nth_unstable_by(TAIL_SAMPLE - 1, |a, b| b.total_cmp(a));
    top.truncate(TAIL_SAMPLE);
    lowest
}

#[cfg(test)]
mod tests {
    use crate::topography::{StatsOptions, Topography};

    /// The kept maximum and counts are those of the detrended heights,
    /// computed plainly from a full copy.
    #[test]
    fn the_tail_matches_the_detrended_heights() {
        let n = 80;
        let mut heights: Vec<f64> = (0..n * n)
            .map(|k| {
                let (x, y) = ((k % n) as f64, (k / n) as f64);
                1e-7 * ((x * 0.7).sin() + (y * 0.9).cos() + (x * 0.31 + y * 0.27).sin()) + 3e-9 * x - 2e-9 * y
            })
            .collect();
        heights[1234] = 5e-6; // a spike
        heights[77] = f64::NAN;
        let t = Topography::map(heights, n, n, 1e-6, 1e-6).unwrap();
        let stats = t.stats(&StatsOptions::default()).unwrap();
        let tail = stats.tail.as_ref().unwrap();
        let d: Vec<f64> = t.detrended(Default::default()).unwrap();
        let valid: Vec<f64> = d.iter().copied().filter(|v| !v.is_nan()).collect();
        let mean = valid.iter().sum::<f64>() / valid.len() as f64;
        let z: Vec<f64> = valid.iter().map(|v| (v - mean) / stats.sigma).collect();
        let max = z.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        assert!((tail.max() - max).abs() < 1e-9 * max, "{} {}", tail.max(), max);
        for level in [0.5, 1.0, 1.2, 1.5, 3.0, 60.0] {
            let exact = z.iter().filter(|&&x| x > level).count();
            assert_eq!(tail.count_above(level), exact.min(super::TAIL_SAMPLE), "level {level}");
        }
        assert_eq!(tail.beyond(), z.iter().filter(|x| x.abs() > 6.0).count());
        assert_eq!(tail.beyond(), 1);
    }

    /// All the kept heights are the highest, in order, when every point
    /// is a new candidate (heights rising along the map after the plane:
    /// the kept set turns over all the time).
    #[test]
    fn the_kept_heights_are_the_highest_when_they_keep_rising() {
        let n = 64;
        let heights: Vec<f64> = (0..n * n)
            .map(|k| {
                let (x, y) = ((k % n) as f64, (k / n) as f64);
                1e-10 * ((x + n as f64 * y) / 64.0).powi(2)
                    + 1e-7 * ((x * 0.7).sin() + (y * 0.9).cos() + (x * 0.31 + y * 0.27).sin())
            })
            .collect();
        let t = Topography::map(heights, n, n, 1e-6, 1e-6).unwrap();
        let stats = t.stats(&StatsOptions::default()).unwrap();
        let tail = stats.tail.as_ref().unwrap();
        let d: Vec<f64> = t.detrended(Default::default()).unwrap();
        let mean = d.iter().sum::<f64>() / d.len() as f64;
        let mut z: Vec<f64> = d.iter().map(|v| (v - mean) / stats.sigma).collect();
        z.sort_by(|a, b| b.total_cmp(a));
        assert_eq!(tail.top.len(), super::TAIL_SAMPLE);
        for (k, (got, want)) in tail.top.iter().zip(&z).enumerate() {
            assert!((got - want).abs() < 1e-9 * want.abs(), "{k}: {got} vs {want}");
        }
    }
}
