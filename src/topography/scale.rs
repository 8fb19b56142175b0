//! Scale-dependent statistics of a measured surface: the rms slope and rms
//! curvature as functions of the length of the finite-difference stencil,
//! and the length below which a scanning probe's tip radius distorts the
//! data (Sanner, Nöhring, Thimons, Jacobs & Pastewka, "Scale-dependent
//! roughness parameters for topography analysis", Appl. Surf. Sci. Adv. 7,
//! 100190, 2022, doi 10.1016/j.apsadv.2021.100190).
//!
//! The definitions are SurfaceTopography's (`derivative` with its default,
//! non-periodic, linearly interpolated stencils, as used by
//! `scale_dependent_statistical_property` and
//! `scanning_probe_reliability_cutoff`), spelt out at [`ScaleRow`], and
//! checked against it by `tools/scale_check.py`.

use super::Topography;
use crate::ErrorKind;

/// Fewest derivative values a statistic is taken over (SurfaceTopography's
/// `threshold`); fewer give NaN.
const THRESHOLD: usize = 4;
/// Brent's method: absolute and relative tolerances and iteration cap of
/// `scanning_probe_reliability_cutoff` (scipy's `brentq` defaults there).
const XTOL: f64 = 2e-12;
const RTOL: f64 = 1e-8;
const MAX_ITERATIONS: usize = 100;

/// Why a scale-dependent statistic cannot be taken.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ScaleError {
    /// The surface has missing (NaN) points: the stencils need every point.
    #[error("{missing} missing points: scale-dependent statistics need every point")]
    MissingPoints {
        /// Missing points.
        missing: usize,
    },
    /// A distance that is not finite and > 0.
    #[error("distance = {value} is out of range: must be > 0 and finite (metres)")]
    Distance {
        /// The value given.
        value: f64,
    },
    /// A tip radius that is not finite and > 0.
    #[error("tip radius = {value} is out of range: must be > 0 and finite (metres)")]
    TipRadius {
        /// The value given.
        value: f64,
    },
    /// A safety factor that is not finite and > 0.
    #[error("safety factor = {value} is out of range: must be > 0 and finite")]
    SafetyFactor {
        /// The value given.
        value: f64,
    },
    /// Too few points along a direction for any stencil to keep the 4
    /// derivative values a statistic needs (every row would be NaN).
    #[error(
        "{name} = {count} is out of range: at least {min} points are needed along {direction} \
         for the scale-dependent {what}"
    )]
    TooFewPoints {
        /// `"nx"` or `"ny"`.
        name: &'static str,
        /// `"x"` or `"y"`.
        direction: &'static str,
        /// Points along that direction.
        count: usize,
        /// The fewest: 4 + the order of the derivative.
        min: usize,
        /// `"slope"` or `"curvature"`.
        what: &'static str,
    },
    /// Brent's method did not converge (not expected: the bracket holds a
    /// sign change and the iteration count is capped at 100).
    #[error("the reliability cut-off did not converge in {iterations} iterations")]
    NoConvergence {
        /// Iterations done.
        iterations: usize,
    },
}

/// What kind of failure this is (see [`ErrorKind`]): the caller's
/// argument ([`ErrorKind::Argument`]), except a root search that did not
/// converge ([`ErrorKind::Tolerance`]).
impl crate::Classify for ScaleError {
    fn kind(&self) -> ErrorKind {
        match self {
            ScaleError::NoConvergence { .. } => ErrorKind::Tolerance,
            _ => ErrorKind::Argument,
        }
    }
}

/// A scale-dependent statistic at one distance.
///
/// The definitions (SurfaceTopography's `derivative`, non-periodic, linear
/// interpolation; Sanner et al. 2022, doi 10.1016/j.apsadv.2021.100190):
///
/// * a distance `d` is the overall length of the stencil. Along x the
///   stencil step is `s·Δx` with the scale factor `s = d/(n·Δx)` (`n` the
///   order of the derivative; along y `s = d/(n·Δy)`);
/// * slope (n = 1, upwind): `h'(x_i) = [h(x_i + sΔx) − h(x_i)]/(sΔx)`;
/// * curvature (n = 2, central):
///   `h''(x_i) = [h(x_i − sΔx) − 2h(x_i) + h(x_i + sΔx)]/(sΔx)²`;
/// * heights between grid points (non-integer `s`) are interpolated
///   linearly between their two neighbours along the stencil's direction;
/// * only points whose stencil lies in the data are kept, trimmed as
///   SurfaceTopography trims them: for n = 1 the last `⌈s⌉` points, for
///   n = 2 the first and last `⌈s⌉`, and on a map along both directions
///   (with `s_x` along x and `s_y` along y) for the derivative along
///   either;
/// * the statistic is the root mean square over the kept points, NaN if
///   fewer than 4 are kept (SurfaceTopography's `threshold`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScaleRow {
    /// The stencil length (metres).
    pub distance: f64,
    /// The rms derivative along x (slope: 1; curvature: 1/m); NaN if fewer
    /// than 4 points have their stencil in the data.
    pub x: f64,
    /// The rms derivative along y of a map (NaN as for `x`); `None` for a
    /// profile.
    pub y: Option<f64>,
}

/// The scale-dependent rms slope at each distance (metres): along x of a
/// profile, along x and y of a map; upwind differences `[h(x + d) −
/// h(x)]/d` with linear interpolation between grid points (see
/// [`ScaleRow`] for the stencils and the trimmed edges).
/// SurfaceTopography's `scale_dependent_statistical_property(lambda x,
/// y=None: np.mean(x*x), n=1, distance=distances, reliable=False)`, square
/// rooted, per direction (Sanner et al. 2022, doi
/// 10.1016/j.apsadv.2021.100190).
///
/// ```
/// use ke_friction::topography::{scale_dependent_slope, Topography};
/// // h = 0.1·x: slope 0.1 at every scale.
/// let t = Topography::profile((0..100).map(|i| 0.1 * i as f64 * 1e-6).collect(), 1e-6).unwrap();
/// let rows = scale_dependent_slope(&t, &[1e-6, 2.5e-6, 10e-6]).unwrap();
/// for r in rows {
///     assert!((r.x - 0.1).abs() < 1e-9);
/// }
/// ```
pub fn scale_dependent_slope(t: &Topography, distances: &[f64]) -> Result<Vec<ScaleRow>, ScaleError> {
    scale_dependent(t, distances, Order::Slope, true)
}

/// The scale-dependent rms curvature (second derivative, 1/m) at each
/// distance (metres): along x of a profile, along x and y of a map;
/// central differences `[h(x − d/2) − 2h(x) + h(x + d/2)]/(d/2)²` with
/// linear interpolation between grid points (see [`ScaleRow`]).
/// SurfaceTopography's
/// `scale_dependent_statistical_property(lambda x, y=None: np.mean(x*x),
/// n=2, distance=distances, reliable=False)`, square rooted, per direction
/// (Sanner et al. 2022, doi 10.1016/j.apsadv.2021.100190).
///
/// ```
/// use ke_friction::topography::{scale_dependent_curvature, Topography};
/// // h = x²/(2R): curvature 1/R at every scale with an integer scale
/// // factor s = d/(2Δx) (a fraction f of s adds f(1 − f)/s² to it, the
/// // linear interpolation's error).
/// let r = 1e-3;
/// let dx = 1e-6;
/// let h = (0..200).map(|i| (i as f64 * dx).powi(2) / (2.0 * r)).collect();
/// let t = Topography::profile(h, dx).unwrap();
/// for row in scale_dependent_curvature(&t, &[2e-6, 6e-6, 40e-6]).unwrap() {
///     assert!((row.x * r - 1.0).abs() < 1e-6);
/// }
/// ```
pub fn scale_dependent_curvature(t: &Topography, distances: &[f64]) -> Result<Vec<ScaleRow>, ScaleError> {
    scale_dependent(t, distances, Order::Curvature, true)
}

/// The rms slope (`curvature` false) or curvature along x only at each
/// distance, as [`scale_dependent_slope`] and [`scale_dependent_curvature`]
/// give it (a map's y left out: what a container's statistics use).
pub(crate) fn scale_dependent_x(t: &Topography, distances: &[f64], curvature: bool) -> Result<Vec<f64>, ScaleError> {
    let order = if curvature { Order::Curvature } else { Order::Slope };
    Ok(scale_dependent(t, distances, order, false)?
        .into_iter()
        .map(|r| r.x)
        .collect())
}

/// The safety factor of [`tip_reliability_cutoff`] in the paper (Sanner
/// et al. 2022) and SurfaceTopography's default: what `--tip-radius` and
/// the web page use.
pub const TIP_SAFETY_FACTOR: f64 = 0.5;

/// Stencil lengths a decade of [`default_distances`].
pub const DISTANCES_PER_DECADE: u32 = 5;

/// The stencil lengths (metres) scale-dependent statistics of `t` are
/// taken at when none are given: log-spaced, [`DISTANCES_PER_DECADE`] a
/// decade, from `order`·max(dx, dy) (the shortest stencil of a slope, 1,
/// or a curvature, 2) to half the scan size (the shorter side of a map),
/// both ends included; the one shortest length when the scan is shorter
/// than twice it. What `kefric surface --scale-dependent` and Python's
/// `Surface.scale_dependent()` use.
pub fn default_distances(t: &Topography, order: u32) -> Vec<f64> {
    let dy = t.dy().unwrap_or(0.0);
    let lo = f64::from(order.max(1)) * t.dx().max(dy);
    let size = match t.dy() {
        None => t.nx() as f64 * t.dx(),
        Some(dy) => (t.nx() as f64 * t.dx()).min(t.ny() as f64 * dy),
    };
    let hi = size / 2.0;
    if hi <= lo {
        return vec![lo];
    }
    let per = f64::from(DISTANCES_PER_DECADE);
    let n = ((per * (hi / lo).log10()).ceil() as usize).max(1);
    let mut d: Vec<f64> = (0..n).map(|k| lo * 10f64.powf(k as f64 / per)).collect();
    d.push(hi);
    d
}

/// The length below which the tip of a scanning probe of radius
/// `tip_radius` (metres) distorts the data, or `None` if it does not at
/// the smallest scale (SurfaceTopography's
/// `scanning_probe_reliability_cutoff`, Sanner et al. 2022, doi
/// 10.1016/j.apsadv.2021.100190).
///
/// A tip of radius R cannot follow a valley sharper than −1/R: the
/// cut-off is the stencil length λ at which the smallest scale-dependent
/// second derivative along x (of a profile or a map) is
/// `−safety_factor/R`. With the bandwidth `(l, L)` (the mean pixel size
/// and the mean physical size, `Δx` and `N·Δx` for a profile) and
/// `f = √(l·L)`: `None` if the criterion holds at λ = 2l; `Some(L)` (no
/// reliable data) if it fails at λ = L/2; otherwise the root found by
/// Brent's method (scipy's `brentq`, ported, `xtol` = 2·10⁻¹², `rtol` =
/// 10⁻⁸) in λ/f over `[2l/f, L/(2f)]`. A stencil with no point left in
/// the data counts as fulfilling the criterion (as SurfaceTopography does
/// when no point is left along x; when some are along x but none along y
/// it would fail, this does not). `safety_factor` is ½ in the paper.
///
/// ```
/// use ke_friction::topography::{tip_reliability_cutoff, Topography};
/// // A sine of amplitude 1 µm and wavelength 20 µm: its sharpest valley has
/// // curvature −A(2π/L)² ≈ −1e5 /m; a 1 µm tip (f = ½) follows down to
/// // −5e5 /m, so nothing is cut off.
/// let dx = 0.1e-6;
/// let h = (0..1000).map(|i| 1e-6 * (2.0 * std::f64::consts::PI * i as f64 * dx / 20e-6).sin()).collect();
/// let t = Topography::profile(h, dx).unwrap();
/// assert_eq!(tip_reliability_cutoff(&t, 1e-6, 0.5).unwrap(), None);
/// // A 100 µm tip allows only −5e3 /m: scales below some λ are cut off.
/// let cut = tip_reliability_cutoff(&t, 100e-6, 0.5).unwrap().unwrap();
/// assert!(cut > 2.0 * dx && cut < 50e-6);
/// ```
pub fn tip_reliability_cutoff(t: &Topography, tip_radius: f64, safety_factor: f64) -> Result<Option<f64>, ScaleError> {
    complete(t)?;
    enough_points(t, Order::Curvature)?;
    if !(tip_radius.is_finite() && tip_radius > 0.0) {
        return Err(ScaleError::TipRadius { value: tip_radius });
    }
    if !(safety_factor.is_finite() && safety_factor > 0.0) {
        return Err(ScaleError::SafetyFactor { value: safety_factor });
    }
    let (lower, upper) = bandwidth(t);
    let mut buf = Vec::new();
    probe_cutoff(lower, upper, tip_radius, safety_factor, |d| {
        let sx = d / (2.0 * t.dx);
        let sy = t.dy.map(|py| d / (2.0 * py));
        let mut min = f64::INFINITY;
        let count = visit(t, Order::Curvature, Direction::X, sx, sy, &mut buf, |row| {
            for &v in row {
                // NaN cannot occur (missing points are refused).
                min = min.min(v);
            }
        });
        let step = sx * t.dx;
        (count > 0).then(|| min / (step * step))
    })
}

/// The bracket search of [`tip_reliability_cutoff`] over a bandwidth
/// `(lower, upper)`, with `min_curvature(d)` the smallest second
/// derivative along x at stencil length `d` (`None`: no point kept, which
/// fulfils the criterion). Shared with the nonuniform profiles of
/// containers, whose derivative interpolates differently.
pub(crate) fn probe_cutoff(
    lower: f64,
    upper: f64,
    tip_radius: f64,
    safety_factor: f64,
    mut min_curvature: impl FnMut(f64) -> Option<f64>,
) -> Result<Option<f64>, ScaleError> {
    let fac = ((lower.ln() + upper.ln()) / 2.0).exp();
    let target = fac * safety_factor / tip_radius;
    let mut objective = |u: f64| -> f64 {
        match min_curvature(fac * u) {
            None => target,
            Some(min) => target + fac * min,
        }
    };
    let a = 2.0 * lower / fac;
    let b = upper / (2.0 * fac);
    if objective(a) > 0.0 {
        return Ok(None);
    }
    if objective(b) < 0.0 {
        return Ok(Some(upper));
    }
    let root = brentq(objective, a, b, XTOL, RTOL, MAX_ITERATIONS)?;
    Ok(Some(fac * root))
}

/// The order of the derivative.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Order {
    Slope,
    Curvature,
}

impl Order {
    fn n(self) -> f64 {
        match self {
            Order::Slope => 1.0,
            Order::Curvature => 2.0,
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Direction {
    X,
    Y,
}

fn scale_dependent(
    t: &Topography,
    distances: &[f64],
    order: Order,
    along_y: bool,
) -> Result<Vec<ScaleRow>, ScaleError> {
    complete(t)?;
    enough_points(t, order)?;
    if let Some(&value) = distances.iter().find(|d| !(d.is_finite() && **d > 0.0)) {
        return Err(ScaleError::Distance { value });
    }
    let n = order.n();
    let mut buf = Vec::new();
    let rms = |direction: Direction, sx: f64, sy: Option<f64>, buf: &mut Vec<f64>| -> f64 {
        let mut sum = 0.0;
        let count = visit(t, order, direction, sx, sy, buf, |row| {
            sum += row.iter().map(|v| v * v).sum::<f64>();
        });
        if count < THRESHOLD {
            return f64::NAN;
        }
        let step = match direction {
            Direction::X => sx * t.dx,
            Direction::Y => sy.unwrap_or(f64::NAN) * t.dy.unwrap_or(f64::NAN),
        };
        let scale = step.powi(n as i32);
        (sum / count as f64).sqrt() / scale
    };
    Ok(distances
        .iter()
        .map(|&d| {
            let sx = d / (n * t.dx);
            let sy = t.dy.map(|py| d / (n * py));
            let x = rms(Direction::X, sx, sy, &mut buf);
            let y = sy.filter(|_| along_y).map(|_| rms(Direction::Y, sx, sy, &mut buf));
            ScaleRow { distance: d, x, y }
        })
        .collect())
}

/// A direction with fewer than `THRESHOLD` + the order points keeps fewer
/// than `THRESHOLD` derivative values even at the shortest stencil (one
/// step): refused, rather than rows of NaN.
fn enough_points(t: &Topography, order: Order) -> Result<(), ScaleError> {
    let (order, what) = match order {
        Order::Slope => (1, "slope"),
        Order::Curvature => (2, "curvature"),
    };
    let min = THRESHOLD + order;
    let along = [("nx", "x", t.nx)].into_iter().chain(t.dy.map(|_| ("ny", "y", t.ny)));
    for (name, direction, count) in along {
        if count < min {
            return Err(ScaleError::TooFewPoints {
                name,
                direction,
                count,
                min,
                what,
            });
        }
    }
    Ok(())
}

/// Missing points are refused.
fn complete(t: &Topography) -> Result<(), ScaleError> {
    match t.heights.iter().filter(|z| z.is_nan()).count() {
        0 => Ok(()),
        missing => Err(ScaleError::MissingPoints { missing }),
    }
}

/// SurfaceTopography's `bandwidth()`: the mean pixel size and the mean
/// physical size.
fn bandwidth(t: &Topography) -> (f64, f64) {
    let lx = t.nx as f64 * t.dx;
    match t.dy {
        None => (t.dx, lx),
        Some(dy) => ((t.dx + dy) / 2.0, (lx + t.ny as f64 * dy) / 2.0),
    }
}

/// The points `[lo, hi)` of `count` kept along a direction with scale
/// factor `s` (SurfaceTopography's `trim_nonperiodic`: the slice
/// `[⌈−s·min(l, 0)⌉ : ⌊−s·max(0, r − 1)⌋]` with the stencil's bounds
/// `l`, `r` = 0, 2 for n = 1 and −1, 2 for n = 2; an end of 0 keeps all).
fn kept(count: usize, order: Order, s: f64) -> (usize, usize) {
    let left = match order {
        Order::Slope => 0.0,
        Order::Curvature => s.ceil(),
    };
    let right = (-s).floor();
    let lo = if left >= count as f64 { count } else { left as usize };
    let hi = if right == 0.0 {
        count
    } else if -right >= count as f64 {
        0
    } else {
        count - (-right) as usize
    };
    (lo, hi.max(lo))
}

/// An offset `t` (in grid steps) split into its floor and the fraction
/// beyond it, for linear interpolation.
#[derive(Debug, Clone, Copy)]
struct Shift {
    whole: isize,
    frac: f64,
}

impl Shift {
    fn new(t: f64) -> Shift {
        let whole = t.floor();
        Shift {
            whole: whole as isize,
            frac: t - whole,
        }
    }
}

/// The interpolated value at `i + shift` of a line.
#[inline(always)]
fn sample(line: &[f64], i: usize, shift: Shift) -> f64 {
    let k = (i as isize + shift.whole) as usize;
    if shift.frac == 0.0 {
        line[k]
    } else {
        (1.0 - shift.frac) * line[k] + shift.frac * line[k + 1]
    }
}

/// The interpolated value at row `j + shift`, column `i`, of a map.
#[inline(always)]
fn sample_rows(h: &[f64], nx: usize, i: usize, j: usize, shift: Shift) -> f64 {
    let k = (j as isize + shift.whole) as usize;
    if shift.frac == 0.0 {
        h[k * nx + i]
    } else {
        (1.0 - shift.frac) * h[k * nx + i] + shift.frac * h[(k + 1) * nx + i]
    }
}

/// Hands `each` the stencil sums (not yet divided by the step to the power
/// n) of the derivative along `direction` on every kept row, and returns
/// how many points were kept. `sx`, `sy`: the scale factors (`sy` `None`
/// for a profile).
fn visit(
    t: &Topography,
    order: Order,
    direction: Direction,
    sx: f64,
    sy: Option<f64>,
    buf: &mut Vec<f64>,
    mut each: impl FnMut(&[f64]),
) -> usize {
    let (nx, h) = (t.nx, &t.heights[..]);
    let (x0, x1) = kept(nx, order, sx);
    let (y0, y1) = match sy {
        Some(sy) => kept(t.ny, order, sy),
        None => (0, 1),
    };
    let count = (x1 - x0) * (y1 - y0);
    if count == 0 {
        return 0;
    }
    buf.clear();
    buf.resize(x1 - x0, 0.0);
    let s = match direction {
        Direction::X => sx,
        Direction::Y => sy.unwrap_or(f64::NAN),
    };
    let up = Shift::new(s);
    let down = Shift::new(-s);
    for j in y0..y1 {
        let row = &h[j * nx..(j + 1) * nx];
        match (direction, order) {
            (Direction::X, Order::Slope) => {
                for (b, i) in buf.iter_mut().zip(x0..x1) {
                    *b = sample(row, i, up) - row[i];
                }
            }
            (Direction::X, Order::Curvature) => {
                for (b, i) in buf.iter_mut().zip(x0..x1) {
                    *b = sample(row, i, down) - 2.0 * row[i] + sample(row, i, up);
                }
            }
            (Direction::Y, Order::Slope) => {
                for (b, i) in buf.iter_mut().zip(x0..x1) {
                    *b = sample_rows(h, nx, i, j, up) - row[i];
                }
            }
            (Direction::Y, Order::Curvature) => {
                for (b, i) in buf.iter_mut().zip(x0..x1) {
                    *b = sample_rows(h, nx, i, j, down) - 2.0 * row[i] + sample_rows(h, nx, i, j, up);
                }
            }
        }
        each(buf);
    }
    count
}

/// scipy's `brentq` (scipy/optimize/Zeros/brentq.c), ported line by line
/// so that the same evaluations give the same root. `f(a)` and `f(b)`
/// must differ in sign (or one be zero).
fn brentq(
    mut f: impl FnMut(f64) -> f64,
    xa: f64,
    xb: f64,
    xtol: f64,
    rtol: f64,
    iterations: usize,
) -> Result<f64, ScaleError> {
    let (mut xpre, mut xcur) = (xa, xb);
    let (mut xblk, mut fblk, mut spre, mut scur) = (0.0, 0.0, 0.0, 0.0);
    let mut fpre = f(xpre);
    let mut fcur = f(xcur);
    if fpre == 0.0 {
        return Ok(xpre);
    }
    if fcur == 0.0 {
        return Ok(xcur);
    }
    for _ in 0..iterations {
        if fpre != 0.0 && fcur != 0.0 && (fpre.is_sign_negative() != fcur.is_sign_negative()) {
            xblk = xpre;
            fblk = fpre;
            spre = xcur - xpre;
            scur = spre;
        }
        if f64::abs(fblk) < f64::abs(fcur) {
            xpre = xcur;
            xcur = xblk;
            xblk = xpre;
            fpre = fcur;
            fcur = fblk;
            fblk = fpre;
        }
        let delta = (xtol + rtol * xcur.abs()) / 2.0;
        let sbis = (xblk - xcur) / 2.0;
        if fcur == 0.0 || sbis.abs() < delta {
            return Ok(xcur);
        }
        if spre.abs() > delta && fcur.abs() < fpre.abs() {
            let stry = if xpre == xblk {
                // interpolate
                -fcur * (xcur - xpre) / (fcur - fpre)
            } else {
                // extrapolate
                let dpre = (fpre - fcur) / (xpre - xcur);
                let dblk = (fblk - fcur) / (xblk - xcur);
                -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            };
            if 2.0 * stry.abs() < f64::min(spre.abs(), 3.0 * sbis.abs() - delta) {
                // good short step
                spre = scur;
                scur = stry;
            } else {
                spre = sbis;
                scur = sbis;
            }
        } else {
            spre = sbis;
            scur = sbis;
        }
        xpre = xcur;
        fpre = fcur;
        if scur.abs() > delta {
            xcur += scur;
        } else {
            xcur += if sbis > 0.0 { delta } else { -delta };
        }
        fcur = f(xcur);
    }
    Err(ScaleError::NoConvergence { iterations })
}
