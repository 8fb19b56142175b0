//! Checking a table against direct integration: the sample points, the
//! measurement, and the one verdict that both `kefric build` and
//! `kefric verify` give.

use super::{BuildError, Progress};
use crate::model::Model;
use crate::rng::SplitMix64;
use crate::table::{Accuracy, Table};
use rayon::prelude::*;

/// The accepted numbers of verification points.
pub static SAMPLES: crate::bound::Bound = crate::bound::Bound::whole(2, 10_000_000);

/// `Ok` for an accepted number of verification points, else a message
/// naming the range.
pub fn check_samples(samples: usize) -> Result<(), crate::ParamError> {
    crate::checks::check_count("samples", samples, &SAMPLES)
}

/// A table measured against direct integration, and its verdict.
#[derive(Debug, Clone, PartialEq)]
pub struct Verification {
    /// The exact (f64) interpolant's error, the same on every machine.
    pub accuracy: Accuracy,
    /// How far this machine's lookups ([`Table::mu`]) stray from the exact
    /// interpolant at the same points: 0 where the portable kernel runs.
    pub kernel_deviation: f64,
    /// The tolerance the table must meet.
    pub tolerance: f64,
    /// If asked for: the largest relative error of the slope ∂μ/∂F* (the
    /// exact interpolant's, [`Table::mu_with_slope_portable`]) against the
    /// model's ([`Model::mu_with_slope_at_f_star`]) at the same points.
    /// Reported, not part of the verdict: the tolerance is μ's.
    pub slope_max_rel: Option<f64>,
}

impl Verification {
    /// The worst relative error of μ as this machine looks it up: the
    /// interpolant's plus the fast kernel's rounding.
    pub fn max_rel(&self) -> f64 {
        self.accuracy.max_rel + self.kernel_deviation
    }

    /// Whether the table meets its tolerance (NaN never does).
    pub fn passes(&self) -> bool {
        self.max_rel() <= self.tolerance
    }
}

/// Measures `table` at `samples` seeded [`sample_points`] against direct
/// integration, and this machine's kernel against the exact interpolant at
/// the same points, for the verdict against `tolerance`; with `slope`,
/// also ∂μ/∂F* (four more model evaluations a point).
pub fn verify(
    table: &Table,
    tolerance: f64,
    samples: usize,
    seed: u64,
    slope: bool,
    progress: &dyn Progress,
) -> Result<Verification, BuildError> {
    check_samples(samples)?;
    let points = sample_points(table, samples, seed);
    progress.stage("checking against direct integration", points.len() as u64);
    let errors: Vec<Result<(f64, f64), BuildError>> = points
        .par_iter()
        .map(|&[psi, theta, f]| {
            let (mu_err, slope_err) = if slope {
                let model = Model::new(table.domain().params(psi, theta))?;
                let (mu, d_mu) =
                    model
                        .mu_with_slope_at_f_star(f)
                        .map_err(|error| BuildError::Eval { psi, theta, error })?;
                let (got, got_d) = table
                    .mu_with_slope_portable(psi, theta, f)
                    .unwrap_or((f64::NAN, f64::NAN));
                (relative(got, mu), relative(got_d, d_mu))
            } else {
                let mu = direct_mu(table, psi, theta, f)?;
                (relative(table.mu_portable(psi, theta, f).unwrap_or(f64::NAN), mu), 0.0)
            };
            progress.advance(1);
            Ok((mu_err, slope_err))
        })
        .collect();
    let errors = errors.into_iter().collect::<Result<Vec<_>, _>>()?;
    let mu_errors: Vec<f64> = errors.iter().map(|e| e.0).collect();
    Ok(Verification {
        accuracy: accuracy(&mu_errors, &points),
        kernel_deviation: kernel_deviation(table, &points),
        tolerance,
        slope_max_rel: slope.then(|| worst(errors.iter().map(|e| e.1)).1),
    })
}

/// |got − want|/|want|.
fn relative(got: f64, want: f64) -> f64 {
    ((got - want) / want).abs()
}

/// The index and value of the largest error; NaN counts as the largest.
fn worst(errors: impl Iterator<Item = f64>) -> (usize, f64) {
    let (mut at, mut max) = (0, 0.0f64);
    for (i, e) in errors.enumerate() {
        if !max.is_nan() && (e.is_nan() || e > max) {
            (at, max) = (i, e);
        }
    }
    (at, max)
}

/// The accuracy record of relative errors of μ at `points`.
fn accuracy(errors: &[f64], points: &[[f64; 3]]) -> Accuracy {
    let (at, max_rel) = worst(errors.iter().copied());
    let mut sorted = errors.to_vec();
    sorted.sort_by(f64::total_cmp);
    let p99 = sorted[((sorted.len() as f64 * 0.99).ceil() as usize).clamp(1, sorted.len()) - 1];
    Accuracy {
        max_rel,
        p99_rel: p99,
        samples: errors.len(),
        worst: points[at],
    }
}

/// μ at (ψ, θ, F*) by direct integration, with the table's model constants.
pub fn direct_mu(table: &Table, psi: f64, theta: f64, f_star: f64) -> Result<f64, BuildError> {
    let eval = |error| BuildError::Eval { psi, theta, error };
    let model = Model::new(table.domain().params(psi, theta))?;
    let contact = model.at_f_star(f_star).map_err(eval)?;
    contact.mu_or_err().map_err(eval)
}

/// How far this machine's lookups ([`Table::mu`], the f32 kernel where
/// [`Table::fast_kernel`]) stray from the exact interpolant
/// ([`Table::mu_portable`]) at `points`: the largest relative difference,
/// 0 where the portable kernel runs.
fn kernel_deviation(table: &Table, points: &[[f64; 3]]) -> f64 {
    if !table.fast_kernel() {
        return 0.0;
    }
    points
        .iter()
        .map(|&[p, t, f]| match (table.mu(p, t, f), table.mu_portable(p, t, f)) {
            (Ok(fast), Ok(exact)) => (fast / exact - 1.0).abs(),
            _ => f64::INFINITY,
        })
        .fold(0.0, f64::max)
}

/// The verification points: in the domain, half uniform in the axes'
/// coordinates, half at cell centres.
pub fn sample_points(table: &Table, samples: usize, seed: u64) -> Vec<[f64; 3]> {
    let d = table.domain();
    let ranges = d.ranges();
    let axes = table.axes();
    let mut rng = SplitMix64(seed);
    (0..samples)
        .map(|n| {
            let mut q = [0.0; 3];
            for k in 0..3 {
                let (lo, hi) = ranges[k];
                let (a, s) = (axes[k].scale, axes[k]);
                let (c_lo, c_hi) = (a.forward(lo), a.forward(hi));
                let c = if n % 2 == 0 {
                    c_lo + (c_hi - c_lo) * rng.unit()
                } else {
                    // Centre of a random cell lying inside the domain.
                    let first = ((c_lo - s.first) / s.step).round();
                    let cells = ((c_hi - c_lo) / s.step).round().max(1.0);
                    let i = (rng.unit() * cells).floor().min(cells - 1.0);
                    s.first + (first + i + 0.5) * s.step
                };
                q[k] = a.inverse(c).clamp(lo, hi);
            }
            q
        })
        .collect()
}
