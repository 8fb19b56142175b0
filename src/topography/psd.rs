//! The power spectral density (PSD) of a measured surface, in the
//! conventions of SurfaceTopography (`power_spectrum_from_profile` and
//! `power_spectrum_from_area`, Jacobs, Junge & Pastewka, Surf. Topogr.
//! Metrol. Prop. 5, 013001, 2017), checked against it by
//! `tools/psd_check.py`.
//!
//! The heights are used as they are: no mean or plane is removed (the
//! q = 0 term holds the mean), and the data are taken as one period (the
//! discrete Fourier transform). With `N` points spaced `h` over `L = N·h`,
//! the transform of a line is h̃(q_k) = h·Σ_i z_i·e^{−i·q_k·x_i} at
//! q_k = 2πk/L, and C¹ᴰ(q_k) = |h̃(q_k)|²/L; on a map of `Lx × Ly`,
//! h̃(q) = Δx·Δy·Σ z_ij·e^{−i(q_x·x_i + q_y·y_j)} and C²ᴰ(q) = |h̃(q)|²/(Lx·Ly).
//!
//! Parseval's theorem in these units: Σ over the whole 2-D spectrum but
//! q = 0 of C²ᴰ·Δq_x·Δq_y/(2π)² is the mean square of the heights less
//! their mean (m0), and Σ q_x²·C²ᴰ·Δq_x·Δq_y/(2π)² (q_x⁴, and q_y², q_y⁴)
//! with the Nyquist column dropped is the spectral m20 (m40, m02, m04) of
//! [`Topography::stats`] with [`super::Derivative::Spectral`].
//!
//! The FFTs are the `realfft` crate's (real to complex, along x) and the
//! `rustfft` crate's (complex, along y, for the 2-D transform).

use super::Topography;
use crate::ErrorKind;
use realfft::num_complex::Complex;
use realfft::RealFftPlanner;
use rustfft::FftPlanner;
use std::f64::consts::PI;

/// Fewest points along a direction the spectrum is taken along.
const MIN_POINTS: usize = 4;
/// The points along a direction a spectrum is taken along: at least
/// 4 (`MIN_POINTS`).
pub static PSD_POINTS: crate::bound::Bound = crate::bound::Bound::whole(MIN_POINTS, usize::MAX);
/// Radial bins per decade of q ([`psd_area`]), SurfaceTopography's
/// `nb_points_per_decade` default.
const BINS_PER_DECADE: f64 = 10.0;
/// Decades added below the first and above the last bin edge
/// (SurfaceTopography's `dectol`).
const DECADE_TOLERANCE: f64 = 0.01;

/// A window the heights are multiplied by before the transform, against
/// the leakage of a non-periodic surface's edges.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Window {
    /// No window (SurfaceTopography's `window='None'`, its default for
    /// periodic data): right for periodic surfaces.
    #[default]
    None,
    /// The Hann window, scaled so that the mean of its square is 1
    /// (SurfaceTopography's `window='hann'`, its default for non-periodic
    /// data). Profiles: the periodic Hann window of scipy's
    /// `get_window('hann', N)`, w_i = ½ − ½·cos(2πi/N), along the profile.
    /// [`psd_area`]: the radial one of SurfaceTopography's `get_window_2D`,
    /// w = ½ + ½·cos(π·r/r_max) for r < r_max = min(Lx, Ly)/2 (else 0), r
    /// the distance from the point (Nx/2, Ny/2) (integer halves).
    Hann,
}

crate::named!(Window, "window", [None = "none", Hann = "hann"]);

/// A power spectral density: C at the wavevectors q, both in SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct Psd {
    /// Wavevectors, increasing (rad/m).
    pub q: Vec<f64>,
    /// The PSD at each q: m³ for a 1-D PSD, m⁴ for a 2-D one.
    pub c: Vec<f64>,
}

/// Why a power spectral density cannot be taken.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PsdError {
    /// The surface has missing (NaN) points: the PSD needs complete data.
    #[error("{missing} missing points: the power spectral density needs every point")]
    MissingPoints {
        /// Missing points.
        missing: usize,
    },
    /// A PSD of a map asked of a profile ([`psd_profile_y`], [`psd_area`]).
    #[error("the {what} needs a map, not a profile")]
    Profile {
        /// `"PSD along y"` or `"radially averaged 2-D PSD"`.
        what: &'static str,
    },
    /// Fewer than [`PSD_POINTS`] along a direction the spectrum is taken along.
    #[error("{name} = {count} is out of range: must be {} points", PSD_POINTS.range())]
    TooFewPoints {
        /// `"nx"` or `"ny"`.
        name: &'static str,
        /// Points along that direction.
        count: usize,
    },
}

/// What kind of failure this is (see [`ErrorKind`]): always
/// [`ErrorKind::Argument`].
impl crate::Classify for PsdError {
    fn kind(&self) -> ErrorKind {
        ErrorKind::Argument
    }
}

/// Every spectrum of `t`: `("x", …)` for a profile; `("x", …)`, `("y", …)`
/// and `("area", …)` for a map (the names are the JSON records' keys).
pub fn psd_all(t: &Topography, window: Window) -> Result<Vec<(&'static str, Psd)>, PsdError> {
    let mut spectra = vec![("x", psd_profile_x(t, window)?)];
    if !t.is_profile() {
        spectra.push(("y", psd_profile_y(t, window)?));
        spectra.push(("area", psd_area(t, window)?));
    }
    Ok(spectra)
}

/// The part of a topography with missing points that its spectra are
/// taken of ([`complete_part`]): the largest rectangle of valid points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rectangle {
    /// Its first column and row.
    pub x0: usize,
    /// Its first row.
    pub y0: usize,
    /// Its points along x.
    pub nx: usize,
    /// Its points along y (1 for a profile).
    pub ny: usize,
    /// The whole topography's points along x and y.
    pub of: (usize, usize),
    /// The whole topography's missing points.
    pub missing: usize,
}

impl std::fmt::Display for Rectangle {
    /// What the front ends say beside such spectra (the CLI's `--psd` on
    /// stderr, Python's `psd()` as a warning, the page in its PSD panel).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} missing points: the power spectral density of the largest complete rectangle, {} × {} points from column {}, row {} of {} × {}",
            self.missing, self.nx, self.ny, self.x0, self.y0, self.of.0, self.of.1
        )
    }
}

/// `t` itself if it has no missing point (`None`); else its largest
/// rectangle (the most points; the first such, row by row) without a
/// missing point, a topography of its own with the same intervals, and
/// where it lies. The spectra need every point: this is what `kefric
/// surface --psd`, Python's `Surface.psd()` and the page take them of
/// (rather than interpolating the gaps, which would add power that was
/// not measured). `None` as the rectangle and an error if no point is
/// valid. O(nx·ny): the largest rectangle under each row's histogram of
/// valid runs, by a stack.
///
/// ```
/// use ke_friction::topography::{complete_part, Topography};
/// let mut z = vec![1.0; 6 * 4];
/// z[0] = f64::NAN; // row 0, column 0
/// let t = Topography::map(z, 6, 4, 1e-6, 1e-6)?;
/// let (part, rect) = complete_part(&t)?;
/// let rect = rect.unwrap();
/// // Columns 1-5 of all 4 rows (20 points) beat rows 1-3 (18).
/// assert_eq!((rect.x0, rect.y0, rect.nx, rect.ny), (1, 0, 5, 4));
/// assert_eq!((part.nx(), part.ny()), (5, 4));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn complete_part(t: &Topography) -> Result<(std::borrow::Cow<'_, Topography>, Option<Rectangle>), PsdError> {
    let missing = t.heights.iter().filter(|z| z.is_nan()).count();
    if missing == 0 {
        return Ok((std::borrow::Cow::Borrowed(t), None));
    }
    let (nx, ny) = (t.nx, t.ny);
    let mut run = vec![0usize; nx]; // valid points ending at this row, per column
    let mut stack: Vec<usize> = Vec::with_capacity(nx + 1);
    let mut best = (0usize, 0usize, 0usize, 0usize, 0usize); // area, x0, y0, w, h
    for j in 0..ny {
        for (r, z) in run.iter_mut().zip(&t.heights[j * nx..(j + 1) * nx]) {
            *r = if z.is_nan() { 0 } else { *r + 1 };
        }
        stack.clear();
        for i in 0..=nx {
            let h = if i < nx { run[i] } else { 0 };
            while let Some(&top) = stack.last() {
                if run[top] < h {
                    break;
                }
                stack.pop();
                let height = run[top];
                let left = stack.last().map_or(0, |&k| k + 1);
                let width = i - left;
                if height * width > best.0 {
                    best = (height * width, left, j + 1 - height, width, height);
                }
            }
            stack.push(i);
        }
    }
    let (area, x0, y0, w, h) = best;
    if area == 0 {
        return Err(PsdError::MissingPoints { missing });
    }
    let heights: Vec<f64> = (y0..y0 + h)
        .flat_map(|j| t.heights[j * nx + x0..j * nx + x0 + w].iter().copied())
        .collect();
    let part = match t.dy {
        Some(dy) => Topography::map(heights, w, h, t.dx, dy),
        None => Topography::profile(heights, t.dx),
    }
    .map_err(|_| PsdError::MissingPoints { missing })?;
    let rect = Rectangle {
        x0,
        y0,
        nx: w,
        ny: h,
        of: (nx, ny),
        missing,
    };
    Ok((std::borrow::Cow::Owned(part), Some(rect)))
}

/// The 1-D PSD along x: of the profile, or the mean of the PSDs of the
/// rows of a map (SurfaceTopography's `power_spectrum_from_profile` with
/// `resampling_method=None`). q_k = 2πk/Lx for k = 0 … ⌊Nx/2⌋ − 1 (below
/// the Nyquist wavevector; for odd Nx the last k < Nx/2 is left out too, as
/// there), C(q_k) = Δx²·|Z_k|²/Lx with Z the DFT of a (windowed) row.
///
/// ```
/// use ke_friction::topography::{psd_profile_x, Topography, Window};
/// let n = 64;
/// let dx = 1e-6;
/// let heights: Vec<f64> = (0..n).map(|i| 1e-7 * (2.0 * std::f64::consts::PI * 5.0 * i as f64 / n as f64).sin()).collect();
/// let psd = psd_profile_x(&Topography::profile(heights, dx)?, Window::None)?;
/// assert_eq!(psd.q.len(), n / 2);
/// // All the power in the fifth wavevector.
/// let top = (0..psd.c.len()).max_by(|&a, &b| psd.c[a].total_cmp(&psd.c[b])).unwrap();
/// assert_eq!(top, 5);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn psd_profile_x(t: &Topography, window: Window) -> Result<Psd, PsdError> {
    complete(t)?;
    along("nx", t.nx)?;
    let rows: Vec<&[f64]> = t.heights.chunks_exact(t.nx).collect();
    Ok(lines_psd_with(t.ny, t.nx, t.dx, window, |j, line| {
        line.copy_from_slice(rows[j])
    }))
}

/// The 1-D PSD along y of a map: the mean of the PSDs of its columns, as
/// [`psd_profile_x`] along x (SurfaceTopography's
/// `power_spectrum_from_profile` of the transposed map).
pub fn psd_profile_y(t: &Topography, window: Window) -> Result<Psd, PsdError> {
    let Some(dy) = t.dy else {
        return Err(PsdError::Profile { what: "PSD along y" });
    };
    complete(t)?;
    along("ny", t.ny)?;
    let (nx, ny) = (t.nx, t.ny);
    // Blocks of COLUMN_BLOCK columns gathered at a time (whole cache
    // lines of each row), not a transposed copy of the map.
    let mut block = vec![0.0; COLUMN_BLOCK * ny];
    Ok(lines_psd_with(nx, ny, dy, window, |i, line| {
        let (i0, c) = (i - i % COLUMN_BLOCK, i % COLUMN_BLOCK);
        if c == 0 {
            let b = COLUMN_BLOCK.min(nx - i0);
            for (j, row) in t.heights.chunks_exact(nx).enumerate() {
                for (c, &z) in row[i0..i0 + b].iter().enumerate() {
                    block[c * ny + j] = z;
                }
            }
        }
        line.copy_from_slice(&block[c * ny..(c + 1) * ny]);
    }))
}

/// Columns gathered at once for the PSD along y.
const COLUMN_BLOCK: usize = 16;

/// The radially averaged 2-D PSD of a map (SurfaceTopography's
/// `power_spectrum_from_area`, its defaults: `collocation='log'`,
/// `nb_points_per_decade=10`, `resampling_method='bin-average'`, the only
/// one it has for a map).
///
/// C²ᴰ(q) = Δx²·Δy²·|Z(q)|²/(Lx·Ly) over the whole 2-D DFT grid, q_x =
/// 2πk/Lx and q_y = 2πl/Ly (|k| ≤ Nx/2, |l| ≤ Ny/2), is averaged within
/// bins of |q| whose edges are equally spaced in log10(q) from 0.01 decade
/// below min(Δq_x, Δq_y) to 0.01 decade above q_max = π·min(1/Δx, 1/Δy),
/// ⌈(log10(q_max) − log10(q_min) + 1)·10⌉ edges; a point on an edge
/// belongs to the bin below it. The q of a bin is the mean |q| of its
/// points. Bins without points are left out (SurfaceTopography masks them),
/// and so are q = 0 and the points beyond the last edge.
pub fn psd_area(t: &Topography, window: Window) -> Result<Psd, PsdError> {
    if t.is_profile() {
        return Err(PsdError::Profile {
            what: "radially averaged 2-D PSD",
        });
    }
    complete(t)?;
    along("nx", t.nx)?;
    along("ny", t.ny)?;
    let spectrum = AreaSpectrum::new(t, window);
    Ok(spectrum.radial_average())
}

/// Missing points are refused.
fn complete(t: &Topography) -> Result<(), PsdError> {
    match t.heights.iter().filter(|z| z.is_nan()).count() {
        0 => Ok(()),
        missing => Err(PsdError::MissingPoints { missing }),
    }
}

/// At least [`MIN_POINTS`] along a direction ([`PSD_POINTS`]).
fn along(name: &'static str, count: usize) -> Result<(), PsdError> {
    if !PSD_POINTS.contains(count as f64) {
        return Err(PsdError::TooFewPoints { name, count });
    }
    Ok(())
}

/// The periodic Hann window of n points, scaled to a mean square of 1
/// (scipy's `get_window('hann', n)`, then SurfaceTopography's scaling).
fn hann(n: usize) -> Vec<f64> {
    let mut w: Vec<f64> = (0..n)
        .map(|i| 0.5 - 0.5 * (2.0 * PI * i as f64 / n as f64).cos())
        .collect();
    scale_to_unit_mean_square(&mut w);
    w
}

/// w ← w·√(n/Σw²).
fn scale_to_unit_mean_square(w: &mut [f64]) {
    let s = (w.len() as f64 / w.iter().map(|v| v * v).sum::<f64>()).sqrt();
    w.iter_mut().for_each(|v| *v *= s);
}

/// The mean 1-D PSD of `count` lines of n points spaced h, line k
/// written by `fill(k, line)` (in the order k = 0, 1, …).
fn lines_psd_with(count: usize, n: usize, h: f64, window: Window, mut fill: impl FnMut(usize, &mut [f64])) -> Psd {
    let w = match window {
        Window::None => None,
        Window::Hann => Some(hann(n)),
    };
    let fft = RealFftPlanner::<f64>::new().plan_fft_forward(n);
    let mut input = fft.make_input_vec();
    let mut spectrum = fft.make_output_vec();
    let mut scratch = fft.make_scratch_vec();
    let kept = n / 2;
    let mut sums = vec![0.0; kept];
    for k in 0..count {
        fill(k, &mut input);
        if let Some(w) = &w {
            input.iter_mut().zip(w).for_each(|(z, w)| *z *= w);
        }
        fft.process_with_scratch(&mut input, &mut spectrum, &mut scratch)
            .expect("buffers of the plan's lengths");
        for (s, x) in sums.iter_mut().zip(&spectrum) {
            *s += x.norm_sqr();
        }
    }
    let length = n as f64 * h;
    let step = length / n as f64;
    let scale = step * step / length / count as f64;
    Psd {
        q: (0..kept).map(|k| 2.0 * PI / length * k as f64).collect(),
        c: sums.iter().map(|s| s * scale).collect(),
    }
}

/// The 2-D PSD of a map on the half of the DFT grid with k_x = 0 … Nx/2
/// (the other half mirrors it: C(−q) = C(q) for real heights), each point
/// counted `weight` times in the whole grid.
struct AreaSpectrum {
    /// Points along x and y of the map.
    nx: usize,
    ny: usize,
    /// Physical sizes Lx, Ly (metres).
    lx: f64,
    ly: f64,
    /// Columns of the half grid: k_x = 0 … Nx/2.
    half: usize,
    /// C²ᴰ at (k_x, l) in the real part, index l·half + k_x, l = 0 … Ny
    /// − 1 (m⁴): the DFT's own grid, reused (one map-sized buffer).
    c: Vec<Complex<f64>>,
}

impl AreaSpectrum {
    fn new(t: &Topography, window: Window) -> AreaSpectrum {
        let (nx, ny) = (t.nx, t.ny);
        let dy = t.dy.expect("a map");
        let (lx, ly) = (nx as f64 * t.dx, ny as f64 * dy);
        let w = match window {
            Window::None => None,
            Window::Hann => Some(HannRadial::new(nx, ny, lx, ly)),
        };
        let mut w_row = vec![0.0; nx];
        // Rows: real to complex along x.
        let rfft = RealFftPlanner::<f64>::new().plan_fft_forward(nx);
        let half = nx / 2 + 1;
        let mut input = rfft.make_input_vec();
        let mut scratch = rfft.make_scratch_vec();
        let mut grid = vec![Complex::new(0.0, 0.0); half * ny];
        for (j, (row, out)) in t.heights.chunks_exact(nx).zip(grid.chunks_exact_mut(half)).enumerate() {
            input.copy_from_slice(row);
            if let Some(w) = &w {
                w.row(j, &mut w_row);
                input.iter_mut().zip(&w_row).for_each(|(z, w)| *z *= w);
            }
            rfft.process_with_scratch(&mut input, out, &mut scratch)
                .expect("buffers of the plan's lengths");
        }
        // Columns: complex along y.
        let cfft = FftPlanner::<f64>::new().plan_fft_forward(ny);
        let mut column = vec![Complex::new(0.0, 0.0); ny];
        let mut scratch = vec![Complex::new(0.0, 0.0); cfft.get_inplace_scratch_len()];
        let area_per_point = (lx / nx as f64) * (ly / ny as f64);
        let scale = area_per_point * area_per_point / (lx * ly);
        for k in 0..half {
            for (l, v) in column.iter_mut().enumerate() {
                *v = grid[l * half + k];
            }
            cfft.process_with_scratch(&mut column, &mut scratch);
            // Column k of the grid is read: C²ᴰ takes its place.
            for (l, v) in column.iter().enumerate() {
                grid[l * half + k] = Complex::new(v.norm_sqr() * scale, 0.0);
            }
        }
        let c = grid;
        AreaSpectrum {
            nx,
            ny,
            lx,
            ly,
            half,
            c,
        }
    }

    /// How often the point k_x of the half grid stands in the whole grid:
    /// once for k_x = 0 and the Nyquist column (even Nx), else twice (k_x
    /// and −k_x).
    fn weight(&self, kx: usize) -> f64 {
        if kx == 0 || 2 * kx == self.nx {
            1.0
        } else {
            2.0
        }
    }

    /// The index of l along y folded to |l| ≤ Ny/2.
    fn folded(&self, l: usize) -> usize {
        if l > self.ny / 2 {
            self.ny - l
        } else {
            l
        }
    }

    /// The bin average of C²ᴰ over |q| (see [`psd_area`]).
    fn radial_average(&self) -> Psd {
        let (nx, ny) = (self.nx as f64, self.ny as f64);
        // The steps as SurfaceTopography forms them, from the "physical
        // size" 2π·N/L of the wavevector grid.
        let dqx = 2.0 * PI * nx / self.lx / nx;
        let dqy = 2.0 * PI * ny / self.ly / ny;
        let q_min = dqx.min(dqy);
        let q_max = PI * (nx / self.lx).min(ny / self.ly);
        let edges = log_edges(q_min, q_max);
        let bins = edges.len() - 1;
        let (mut weight, mut q_sum, mut c_sum) = (vec![0.0; bins], vec![0.0; bins], vec![0.0; bins]);
        for l in 0..self.ny {
            let qy = dqy * self.folded(l) as f64;
            for kx in 0..self.half {
                let qx = dqx * kx as f64;
                let q = (qx * qx + qy * qy).sqrt();
                // NumPy's searchsorted (side 'left'): the first edge ≥ q;
                // bin b lies between edges b and b + 1.
                let index = edges.partition_point(|&e| e < q);
                if index == 0 || index > bins {
                    continue;
                }
                let w = self.weight(kx);
                weight[index - 1] += w;
                q_sum[index - 1] += w * q;
                c_sum[index - 1] += w * self.c[l * self.half + kx].re;
            }
        }
        let mut psd = Psd {
            q: Vec::with_capacity(bins),
            c: Vec::with_capacity(bins),
        };
        for ((w, q), c) in weight.iter().zip(&q_sum).zip(&c_sum) {
            if *w > 0.0 {
                psd.q.push(q / w);
                psd.c.push(c / w);
            }
        }
        psd
    }
}

/// The bin edges of SurfaceTopography's `make_grid('log', …)`: NumPy's
/// `linspace` of the decades, 0.01 beyond each end, then 10^x.
fn log_edges(q_min: f64, q_max: f64) -> Vec<f64> {
    let (lo, hi) = (q_min.log10(), q_max.log10());
    let count = (((hi - lo + 1.0) * BINS_PER_DECADE).ceil() as usize).max(2);
    let (start, stop) = (lo - DECADE_TOLERANCE, hi + DECADE_TOLERANCE);
    let step = (stop - start) / (count - 1) as f64;
    (0..count)
        .map(|i| {
            let x = if i == count - 1 { stop } else { i as f64 * step + start };
            10f64.powf(x)
        })
        .collect()
}

/// The radial Hann window of SurfaceTopography's `get_window_2D`, scaled
/// to a mean square of 1, computed a row at a time (row j, column i).
struct HannRadial {
    nx: usize,
    lx: f64,
    ly: f64,
    ny: usize,
    r_max: f64,
    /// The scale to a mean square of 1.
    scale: f64,
}

impl HannRadial {
    fn new(nx: usize, ny: usize, lx: f64, ly: f64) -> HannRadial {
        let mut w = HannRadial {
            nx,
            lx,
            ly,
            ny,
            r_max: lx.min(ly) / 2.0,
            scale: 1.0,
        };
        // Σw² in the order scale_to_unit_mean_square sums (row-major), a
        // row at a time: the same scale to the bit, no map-sized window.
        let (mut row, mut sum) = (vec![0.0; nx], 0.0);
        for j in 0..ny {
            w.row(j, &mut row);
            for v in &row {
                sum += v * v;
            }
        }
        w.scale = ((nx * ny) as f64 / sum).sqrt();
        w
    }

    /// Row j of the window.
    fn row(&self, j: usize, out: &mut [f64]) {
        let HannRadial {
            nx,
            lx,
            ly,
            ny,
            r_max,
            scale,
        } = *self;
        let (cx, cy) = ((nx / 2) as f64, (ny / 2) as f64);
        let y = ly * (j as f64 - cy) / ny as f64;
        for (i, o) in out.iter_mut().enumerate() {
            let x = lx * (i as f64 - cx) / nx as f64;
            let r = (x * x + y * y).sqrt();
            let w = if r > r_max {
                0.0
            } else {
                0.5 + 0.5 * (PI * r / r_max).cos()
            };
            *o = w * scale;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::topography::{Derivative, Detrend, StatsOptions};
    use crate::Classify;

    /// Pseudo-random heights in [−½, ½)·1e-6 plus an offset and a wave.
    fn rough(nx: usize, ny: usize, seed: u64) -> Vec<f64> {
        let mut state = seed;
        (0..nx * ny)
            .map(|k| {
                state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
                let mut z = state;
                z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
                z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
                z ^= z >> 31;
                let u = (z >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
                let x = (k % nx) as f64;
                1e-6 * u + 3e-7 * (0.4 * x).sin() + 2e-6
            })
            .collect()
    }

    fn spectral_stats(t: &Topography) -> crate::topography::SurfaceStats {
        t.stats(&StatsOptions {
            detrend: Detrend::Mean,
            derivative: Derivative::Spectral,
            lambda_s: None,
            lambda_c: None,
        })
        .unwrap()
    }

    fn close(what: &str, got: f64, want: f64) {
        let rel = ((got - want) / want).abs();
        assert!(rel <= 1e-10, "{what}: {got} vs {want} ({rel:e} relative)");
    }

    /// Parseval on the unaveraged 2-D spectrum: Σ_{q≠0} C·Δq_x·Δq_y/(2π)²
    /// = m0 and Σ q_x^p·C·Δq_x·Δq_y/(2π)² (Nyquist column dropped) = the
    /// spectral m20, m40 (and along y m02, m04), so m2, m4.
    #[test]
    fn the_2d_spectrum_integrates_to_the_spectral_moments() {
        for (nx, ny) in [(64usize, 48usize), (45, 37), (100, 17), (33, 64)] {
            let (dx, dy) = (1.3e-6, 0.8e-6);
            let t = Topography::map(rough(nx, ny, 11 + nx as u64), nx, ny, dx, dy).unwrap();
            let s = AreaSpectrum::new(&t, Window::None);
            let (dqx, dqy) = (2.0 * PI / s.lx, 2.0 * PI / s.ly);
            let cell = dqx * dqy / (4.0 * PI * PI);
            let mut m = [0.0f64; 5]; // m0, m20, m40, m02, m04
            for l in 0..ny {
                let ly = s.folded(l);
                let qy = dqy * ly as f64;
                for kx in 0..s.half {
                    if kx == 0 && l == 0 {
                        continue;
                    }
                    let qx = dqx * kx as f64;
                    let v = s.weight(kx) * s.c[l * s.half + kx].re * cell;
                    m[0] += v;
                    if 2 * kx != nx {
                        m[1] += qx.powi(2) * v;
                        m[2] += qx.powi(4) * v;
                    }
                    if 2 * ly != ny {
                        m[3] += qy.powi(2) * v;
                        m[4] += qy.powi(4) * v;
                    }
                }
            }
            let stats = spectral_stats(&t);
            close("m0", m[0], stats.sigma * stats.sigma);
            close("m20", m[1], stats.m20);
            close("m40", m[2], stats.m40);
            close("m02", m[3], stats.m02.unwrap());
            close("m04", m[4], stats.m04.unwrap());
            close("m2", 0.5 * (m[1] + m[3]), stats.m2);
            close("m4", 0.5 * (m[2] + m[4]), stats.m4);
        }
    }

    /// The 1-D PSD of a profile of even N: (Δq/π)·Σ_{0<k<N/2} q_k^p·C_k
    /// is the spectral m2 (p = 2), m4 (p = 4), and m0 less the Nyquist
    /// term |Z_{N/2}|²/N² (p = 0); for a map along x and y, the mean over
    /// rows (columns) gives m20, m40 (m02, m04).
    #[test]
    fn the_profile_psd_integrates_to_the_spectral_moments() {
        let moments = |psd: &Psd, p: i32| -> f64 {
            let dq = psd.q[1];
            psd.q
                .iter()
                .zip(&psd.c)
                .skip(1)
                .map(|(q, c)| q.powi(p) * c)
                .sum::<f64>()
                * dq
                / PI
        };
        for n in [128usize, 1000, 250] {
            let z = rough(n, 1, n as u64);
            let t = Topography::profile(z.clone(), 0.7e-6).unwrap();
            let psd = psd_profile_x(&t, Window::None).unwrap();
            let stats = spectral_stats(&t);
            let nyquist = z
                .iter()
                .enumerate()
                .map(|(i, z)| if i % 2 == 0 { *z } else { -*z })
                .sum::<f64>()
                / n as f64;
            close("m0", moments(&psd, 0) + nyquist * nyquist, stats.sigma * stats.sigma);
            close("m2", moments(&psd, 2), stats.m2);
            close("m4", moments(&psd, 4), stats.m4);
        }
        let (nx, ny) = (80, 54);
        let t = Topography::map(rough(nx, ny, 5), nx, ny, 1.1e-6, 0.6e-6).unwrap();
        let stats = spectral_stats(&t);
        let x = psd_profile_x(&t, Window::None).unwrap();
        let y = psd_profile_y(&t, Window::None).unwrap();
        close("m20", moments(&x, 2), stats.m20);
        close("m40", moments(&x, 4), stats.m40);
        close("m02", moments(&y, 2), stats.m02.unwrap());
        close("m04", moments(&y, 4), stats.m04.unwrap());
    }

    /// The radial average keeps the total weight: every point of the grid
    /// with 0 < |q| ≤ q_max (and some beyond, up to the last edge) is in
    /// one bin, and the bins' q increase.
    #[test]
    fn radial_bins() {
        let (nx, ny) = (64, 40);
        let t = Topography::map(rough(nx, ny, 3), nx, ny, 1e-6, 1.5e-6).unwrap();
        for window in [Window::None, Window::Hann] {
            let psd = psd_area(&t, window).unwrap();
            assert!(psd.q.windows(2).all(|w| w[0] < w[1]), "{:?}", psd.q);
            assert!(psd.c.iter().all(|c| c.is_finite() && *c >= 0.0));
            let q_max = PI / 1.5e-6;
            assert!(*psd.q.last().unwrap() <= q_max * 10f64.powf(0.01));
        }
    }

    #[test]
    fn refusals() {
        let mut z = rough(32, 32, 1);
        z[5] = f64::NAN;
        z[900] = f64::NAN;
        let t = Topography::map(z, 32, 32, 1e-6, 1e-6).unwrap();
        for r in [
            psd_profile_x(&t, Window::None),
            psd_profile_y(&t, Window::Hann),
            psd_area(&t, Window::None),
        ] {
            let e = r.unwrap_err();
            assert_eq!(e, PsdError::MissingPoints { missing: 2 });
            assert_eq!(e.kind(), ErrorKind::Argument);
            assert!(e.to_string().contains("2 missing points"), "{e}");
        }
        let p = Topography::profile(rough(32, 1, 2), 1e-6).unwrap();
        assert!(matches!(psd_profile_y(&p, Window::None), Err(PsdError::Profile { .. })));
        assert!(matches!(psd_area(&p, Window::None), Err(PsdError::Profile { .. })));
        let short = Topography::map(rough(32, 3, 2), 32, 3, 1e-6, 1e-6).unwrap();
        assert_eq!(
            psd_area(&short, Window::None),
            Err(PsdError::TooFewPoints { name: "ny", count: 3 })
        );
        assert!(psd_profile_x(&short, Window::Hann).is_ok());
    }
}
