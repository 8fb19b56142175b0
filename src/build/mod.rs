//! The offline table builder: solve the model for the lookup grid's F*
//! nodes in parallel, fit the splines, and measure the result against
//! direct integration ([`verify`]).
//!
//! Deterministic: every number depends only on the options (parallel work
//! is collected in a fixed order, and the verification points come from a
//! seeded generator), so the same options give a byte-identical file on
//! any number of threads.

pub mod verify;

use crate::bound::{Bound, End};
use crate::checks::{check_count, check_in, ParamError};
use crate::model::{EvalError, Model, H_LIMIT};
use crate::num::Shortest;
use crate::params::{Constants, Params, PSI_MAX, PSI_MIN, THETA_MAX};
use crate::spline::{fit_3d, Axis, Scale, Start};
use crate::table::format::{self, AxisSpec, BuildSpec, Coefs, DistributionSpec, ModelSpec, Payload};
pub use crate::table::Precision;
use crate::table::{Table, TableError};
use rayon::prelude::*;

/// The largest F* a table may cover, ghost nodes included (a limit on the
/// builder's input, not the paper's range of loads): F* = F/(A_n·H)
/// above 1 would already mean a mean pressure above the hardness.
pub const F_STAR_LIMIT: f64 = 100.0;

// The ranges of the options ([`BuildOptions::validate`]).
/// A range's lower end for ψ and F*: > 0.
pub static POSITIVE: Bound = Bound::above(0.0);
/// A range's lower end for θ: >= 0.
pub static NON_NEGATIVE: Bound = Bound::at_least(0.0);
/// A range's upper end: finite.
pub static FINITE: Bound = Bound::new(End::Unbounded, End::Unbounded);
/// The F* range's upper end: at most the model's [`F_STAR_MAX`](crate::F_STAR_MAX).
pub static F_STAR_END: Bound = Bound::at_most(crate::F_STAR_MAX).unit("(a pressure at most the hardness)");
/// Nodes per axis.
pub static NODES: Bound = Bound::whole(5, 4096);
/// Ghost nodes beyond each open end.
pub static GHOSTS: Bound = Bound::whole(0, 8);
/// Both ends of the h* range (the model's [`H_LIMIT`]).
pub static H_STAR: Bound = Bound::new(End::Closed(-H_LIMIT), End::Closed(H_LIMIT));
/// Points of the h* integration grid.
pub static H_NODES: Bound = Bound::whole(2, 100_000);
/// The build's relative tolerance.
pub static TOLERANCE: Bound = Bound::new(End::Open(0.0), End::Closed(1.0));
/// ψ at every node, ghost nodes included.
pub static GHOST_PSI: Bound = Bound::new(End::Closed(PSI_MIN), End::Closed(PSI_MAX)).unit("(ghost nodes included)");
/// θ at every node, ghost nodes included.
pub static GHOST_THETA: Bound = Bound::at_most(THETA_MAX).unit("(ghost nodes included)");
/// F* at every node, ghost nodes included.
pub static GHOST_F_STAR: Bound = Bound::at_most(F_STAR_LIMIT).unit("(ghost nodes included)");
/// The table's coefficient arrays: the limit [`Table`] accepts.
pub static GRID_NODES: Bound = Bound::whole(0, 1 << 28).unit("(NP+2·ghosts+2)·(NT+ghosts+2)·(NF+2·ghosts+2)");
/// The integration grid's points.
pub static GRID_POINTS: Bound =
    Bound::whole(0, 1 << 26).unit("(psi nodes × theta nodes × h* points, ghost nodes included)");

/// Everything that shapes a table. [`Default`] gives the default table.
#[derive(Debug, Clone, PartialEq)]
pub struct BuildOptions {
    /// Range of ψ (> 0).
    pub psi: (f64, f64),
    /// Range of θ (≥ 0).
    pub theta: (f64, f64),
    /// Range of F* (> 0).
    pub f_star: (f64, f64),
    /// Nodes across the range of ψ, θ and F* (each ≥ 5).
    pub nodes: [usize; 3],
    /// Extra nodes beyond each end of the ψ and F* ranges, so that the
    /// spline's end conditions act outside the domain.
    pub ghosts: usize,
    /// The integration grid's h* axis: from, to, points.
    pub h_star: (f64, f64, usize),
    /// The model constants (β, ν, ε*, fit, model).
    pub constants: Constants,
    /// Stored precision.
    pub precision: Precision,
    /// The maximum relative error of μ the table must meet (else the build fails).
    pub tolerance: f64,
    /// Points checked against direct integration (half random, half cell centres).
    pub samples: usize,
    /// Seed of those points.
    pub seed: u64,
}

impl Default for BuildOptions {
    fn default() -> Self {
        BuildOptions {
            psi: (0.5, 8.0),
            theta: (0.0, 0.01),
            f_star: (1e-5, 0.1),
            nodes: [33, 33, 33],
            ghosts: 2,
            h_star: (-1.0, 6.0, 141),
            constants: Constants::default(),
            precision: Precision::F32,
            tolerance: 1e-4,
            samples: 10000,
            seed: 2004,
        }
    }
}

/// Why a build failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum BuildError {
    /// An option is out of range.
    #[error(transparent)]
    Option(#[from] ParamError),
    /// A range option whose lower end is not below its upper end.
    #[error("lower end {} must be below upper end {} (the range of {name})", Shortest(*.lo), Shortest(*.hi))]
    Range {
        /// The option: `"psi"`, `"theta"`, `"f_star"` or `"h_star"`.
        name: &'static str,
        /// The lower end given.
        lo: f64,
        /// The upper end given.
        hi: f64,
    },
    /// The model could not be evaluated somewhere on the grid.
    #[error("model evaluation failed at psi = {}, theta = {}: {error}", Shortest(*.psi), Shortest(*.theta))]
    Eval {
        /// ψ of the failing node.
        psi: f64,
        /// θ of the failing node.
        theta: f64,
        /// The model's error.
        error: EvalError,
    },
    /// The model fails at a ghost node: one beyond the F* range, which the
    /// spline's end conditions need.
    #[error(
        "model evaluation failed at psi = {}, theta = {}, F* = {}, a ghost node beyond the F* range [{}, {}]: {error}; with more F* nodes the ghost nodes lie closer to the range (or lower its upper end)",
        Shortest(*.psi), Shortest(*.theta), Shortest::rounded(*.f_star), Shortest(.range.0), Shortest(.range.1)
    )]
    Ghost {
        /// ψ of the node.
        psi: f64,
        /// θ of the node.
        theta: f64,
        /// F* of the ghost node.
        f_star: f64,
        /// The table's F* range.
        range: (f64, f64),
        /// The model's error.
        error: EvalError,
    },
    /// The finished table misses the tolerance.
    #[error(
        "the table misses its tolerance: max relative error {:.2e} > {} (worst at psi = {:.4}, theta = {:.4e}, f_star = {:.4e}); {}",
        .max_rel, Shortest(*.tolerance), .worst[0], .worst[1], .worst[2], tolerance_hint(*.max_rel, *.tolerance, *.nodes, *.precision)
    )]
    Tolerance {
        /// Measured maximum.
        max_rel: f64,
        /// Requested tolerance.
        tolerance: f64,
        /// Where.
        worst: [f64; 3],
        /// The nodes the table had (ψ, θ, F*, without ghost nodes).
        nodes: [usize; 3],
        /// The coefficients' precision.
        precision: Precision,
    },
    /// The fitted coefficients break a bound every table file must keep
    /// (see the format's invariants), e.g. ln μ beyond an f32 table's range
    /// at a ghost node far outside the domain.
    #[error("the built table cannot be stored: {0} (try f64 precision, more nodes or a narrower range)")]
    Unstorable(TableError),
}

/// Below this relative error of μ, rounding the coefficients to f32 (24
/// significant bits: ~6e-8 of ln μ, times |ln μ| ≤ ~5 over the paper's
/// range) is no longer small against the interpolation error, so f64
/// precision can help; above it only more nodes (or a narrower domain) can.
const F32_FLOOR: f64 = 1e-6;

/// What can actually make a build that missed its tolerance pass.
fn tolerance_hint(max_rel: f64, tolerance: f64, nodes: [usize; 3], precision: Precision) -> String {
    if precision == Precision::F32 && max_rel < F32_FLOOR {
        return "at this level f32 rounding matters: build with f64 precision".into();
    }
    // A cubic spline's error falls as the 4th power of the node spacing.
    let factor = (max_rel / tolerance).powf(0.25) * 1.05;
    let more = nodes.map(|n| ((n - 1) as f64 * factor).ceil() as usize + 1);
    format!(
        "more nodes would help (cubic interpolation's error falls as the 4th power of the node spacing): try nodes = {},{},{}, or a narrower domain, or a looser tolerance",
        more[0], more[1], more[2]
    )
}

/// Progress of long work, for a progress bar (all methods may be called
/// from several threads).
pub trait Progress: Sync {
    /// A stage with `total` units of work begins.
    fn stage(&self, name: &str, total: u64);
    /// `n` units are done.
    fn advance(&self, n: u64);
}

/// No progress reporting.
impl Progress for () {
    fn stage(&self, _: &str, _: u64) {}
    fn advance(&self, _: u64) {}
}

/// A finished build.
#[derive(Debug, Clone)]
pub struct Built {
    /// The table file's bytes.
    pub bytes: Vec<u8>,
    /// The decoded table.
    pub table: Table,
}

impl Built {
    /// Writes the table file to `path` atomically (a temporary file beside
    /// it, synced, then renamed over it; see [`check_output`]).
    pub fn write(&self, path: &std::path::Path) -> std::io::Result<()> {
        crate::io::write_atomic(path, &self.bytes)
    }
}

/// Whether `path` may be written as an output file (a table, an export, a
/// figure): a new file, or an existing regular file, which is replaced
/// whole; a symbolic link is followed (its target is replaced, the link
/// stays); an existing device, pipe, socket or directory is refused.
pub fn check_output(path: &std::path::Path) -> std::io::Result<()> {
    crate::io::output_target(path).map(|_| ())
}

/// The model's parameters at (ψ, θ) with the options' constants.
pub(crate) fn params_of(o: &BuildOptions, psi: f64, theta: f64) -> Params {
    o.constants.unchecked_at(psi, theta)
}

impl BuildOptions {
    /// Checks every option, naming the first bad one. Everything that
    /// would make the build fail or run out of memory for reasons known in
    /// advance is caught here, before any work.
    pub fn validate(&self) -> Result<(), BuildError> {
        let range = |name: &'static str, (lo, hi): (f64, f64), bound: &'static Bound| {
            check_in(name, lo, bound)?;
            check_in(name, hi, if std::ptr::eq(bound, &H_STAR) { bound } else { &FINITE })?;
            if lo < hi {
                Ok(())
            } else {
                Err(BuildError::Range { name, lo, hi })
            }
        };
        if DistributionSpec::of(&self.constants.distribution).is_none() {
            return Err(BuildError::Option(ParamError {
                name: "distribution",
                value: f64::NAN,
                range: "gaussian, pearson or weibull (a table does not hold an empirical density: use a curve)",
            }));
        }
        range("psi", self.psi, &POSITIVE)?;
        range("theta", self.theta, &NON_NEGATIVE)?;
        range("f_star", self.f_star, &POSITIVE)?;
        // A table answers up to its F* range's end: no further than the
        // model's F* <= 1 (its ghost nodes may lie beyond, up to F_STAR_LIMIT).
        check_in("f_star", self.f_star.1, &F_STAR_END)?;
        check_count("psi_nodes", self.nodes[0], &NODES)?;
        check_count("theta_nodes", self.nodes[1], &NODES)?;
        check_count("f_nodes", self.nodes[2], &NODES)?;
        check_count("ghosts", self.ghosts, &GHOSTS)?;
        let (h_lo, h_hi, h_n) = self.h_star;
        range("h_star", (h_lo, h_hi), &H_STAR)?;
        check_count("h_nodes", h_n, &H_NODES)?;
        check_in("tolerance", self.tolerance, &TOLERANCE)?;
        verify::check_samples(self.samples)?;
        // The model must be valid at every node, ghost nodes included: at
        // both ends of the ψ axis and at the top of the θ axis.
        let axes = self.axes();
        let [ax_p, ax_t, ax_f] = axes;
        let (psi_lo, psi_hi) = (ax_p.value(0), ax_p.value(ax_p.nodes - 1));
        let theta_hi = ax_t.value(ax_t.nodes - 1);
        params_of(self, self.psi.0, self.theta.0).validate()?;
        params_of(self, self.psi.1, self.theta.1).validate()?;
        check_in("psi", psi_lo, &GHOST_PSI)?;
        check_in("psi", psi_hi, &GHOST_PSI)?;
        check_in("theta", theta_hi, &GHOST_THETA)?;
        check_in("f_star", ax_f.value(ax_f.nodes - 1), &GHOST_F_STAR)?;
        // Sizes: the table's coefficient arrays (the limit `Table` accepts)
        // and the integration grid (five arrays of doubles, twice over).
        let lookup = axes.iter().map(|a| (a.nodes + 2) as f64).product::<f64>();
        check_in("grid_nodes", lookup, &GRID_NODES)?;
        let points = (ax_p.nodes * ax_t.nodes) as f64 * h_n as f64;
        check_in("grid_points", points, &GRID_POINTS)?;
        Ok(())
    }

    /// The lookup grid's axes (ψ, θ, F*), ghost nodes included.
    pub fn axes(&self) -> [Axis; 3] {
        let g = self.ghosts;
        let log_axis = |(lo, hi): (f64, f64), n: usize| {
            let step = (hi.ln() - lo.ln()) / (n - 1) as f64;
            Axis {
                scale: Scale::Log,
                first: lo.ln() - g as f64 * step,
                step,
                nodes: n + 2 * g,
            }
        };
        // θ enters as √θ: at small F* the friction coefficient turns from
        // its adhesion-free value to the adhesion-dominated one over a θ of
        // order F*, which a uniform grid in θ cannot resolve. μ is smooth in
        // θ itself, so it is even in √θ about 0: the spline's slope there is
        // exactly zero, and only the upper end needs ghost nodes.
        let (t_lo, t_hi) = (self.theta.0.sqrt(), self.theta.1.sqrt());
        let t_step = (t_hi - t_lo) / (self.nodes[1] - 1) as f64;
        [
            log_axis(self.psi, self.nodes[0]),
            Axis {
                scale: Scale::Sqrt,
                first: t_lo,
                step: t_step,
                nodes: self.nodes[1] + g,
            },
            log_axis(self.f_star, self.nodes[2]),
        ]
    }

    /// The integration grid's h* points.
    pub(crate) fn h_nodes(&self) -> Vec<f64> {
        let (lo, hi, n) = self.h_star;
        (0..n).map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64).collect()
    }
}

/// Builds a table: integrates, solves, fits, measures, encodes.
pub fn build(o: &BuildOptions, progress: &dyn Progress) -> Result<Built, BuildError> {
    o.validate()?;
    let axes = o.axes();
    let nodes = |k: usize| -> Vec<f64> { (0..axes[k].nodes).map(|i| axes[k].value(i)).collect() };
    let (psi, theta, f_nodes) = (nodes(0), nodes(1), nodes(2));
    let (np, nt, nf) = (axes[0].nodes, axes[1].nodes, axes[2].nodes);
    let h_grid = o.h_nodes();
    progress.stage("solving F*(h*) at the table's nodes", (np * nt) as u64);
    let columns: Vec<Result<Vec<(f64, f64)>, BuildError>> = (0..np * nt)
        .into_par_iter()
        .map(|ij| {
            let (p, t) = (psi[ij / nt], theta[ij % nt]);
            let model = Model::new(params_of(o, p, t))?;
            // F* along the h* grid (no friction integrals), for the guesses.
            let f_col: Vec<f64> = h_grid.iter().map(|&h| model.force(h).0).collect();
            let col = f_nodes
                .iter()
                .map(|&f| {
                    // A ghost node beyond the range: say so, as that is
                    // the cause to act on (more nodes bring it closer).
                    let beyond = !(o.f_star.0..=o.f_star.1).contains(&f);
                    let err = |error| {
                        if beyond {
                            BuildError::Ghost {
                                psi: p,
                                theta: t,
                                f_star: f,
                                range: o.f_star,
                                error,
                            }
                        } else {
                            BuildError::Eval {
                                psi: p,
                                theta: t,
                                error,
                            }
                        }
                    };
                    let h = model.solve_h(f, guess(&h_grid, &f_col, f)).map_err(err)?;
                    let c = model.at_h_star(h).map_err(err)?;
                    let mu = c.mu.filter(|m| *m > 0.0).ok_or_else(|| {
                        err(EvalError::NoMu {
                            f_star: c.f_star,
                            h_star: c.h_star,
                        })
                    })?;
                    Ok((mu.ln(), h))
                })
                .collect();
            progress.advance(1);
            col
        })
        .collect();
    let mut ln_mu = Vec::with_capacity(np * nt * nf);
    let mut h_star = Vec::with_capacity(np * nt * nf);
    for col in columns {
        for (m, h) in col? {
            ln_mu.push(m);
            h_star.push(h);
        }
    }
    let theta_start = if o.theta.0 == 0.0 {
        Start::Even
    } else {
        Start::Estimated
    };
    let starts = [Start::Estimated, theta_start, Start::Estimated];
    let store = |v: Vec<f64>| match o.precision {
        Precision::F32 => Coefs::F32(v.iter().map(|&x| x as f32).collect()),
        Precision::F64 => Coefs::F64(v),
    };
    let spec = |axis: &Axis, (lo, hi): (f64, f64)| AxisSpec {
        scale: axis.scale.code(),
        first: axis.first,
        step: axis.step,
        nodes: axis.nodes as u32,
        lo,
        hi,
    };
    let mut payload = Payload {
        model: ModelSpec::of(&o.constants),
        // validate() refused an empirical density.
        distribution: DistributionSpec::of(&o.constants.distribution).unwrap_or_default(),
        axes: [spec(&axes[0], o.psi), spec(&axes[1], o.theta), spec(&axes[2], o.f_star)],
        ln_mu: store(fit_3d(&ln_mu, [np, nt, nf], starts)),
        h_star: store(fit_3d(&h_star, [np, nt, nf], starts)),
        build: BuildSpec {
            nodes: o.nodes.map(|n| n as u32),
            ghosts: o.ghosts as u32,
            h_lo: o.h_star.0,
            h_hi: o.h_star.1,
            h_nodes: o.h_star.2 as u32,
            samples: o.samples as u32,
            seed: o.seed,
            generator: concat!("ke-friction ", env!("CARGO_PKG_VERSION")).to_string(),
        },
        // Measured below, on the decoded draft.
        accuracy: format::Accuracy::unmeasured(o.tolerance),
    };
    let draft = Table::from_payload(payload.clone()).map_err(BuildError::Unstorable)?;
    // The record is the exact interpolant's (the same on every machine);
    // the verdict also counts this machine's kernel, as `kefric verify` does.
    let checked = verify::verify(&draft, o.tolerance, o.samples, o.seed, false, progress)?;
    let accuracy = checked.accuracy;
    if !checked.passes() {
        return Err(BuildError::Tolerance {
            max_rel: checked.max_rel(),
            tolerance: o.tolerance,
            worst: accuracy.worst,
            nodes: o.nodes,
            precision: o.precision,
        });
    }
    payload.accuracy = format::Accuracy::record(o.tolerance, &accuracy);
    let bytes = format::encode(&payload);
    let table = Table::from_bytes(&bytes).expect("a freshly encoded table decodes");
    Ok(Built { bytes, table })
}

/// An initial h* for F* = `f` from the integration grid's column (where F*
/// is positive and decreasing), or 1 when the column does not bracket it.
fn guess(h: &[f64], f_col: &[f64], f: f64) -> f64 {
    for k in 1..h.len() {
        let (a, b) = (f_col[k - 1], f_col[k]);
        if a >= f && b < f && a > 0.0 && b > 0.0 {
            let t = (a.ln() - f.ln()) / (a.ln() - b.ln());
            return h[k - 1] + t * (h[k] - h[k - 1]);
        }
    }
    1.0
}

impl BuildOptions {
    /// The options a table was built with, reconstructed from what the
    /// file records: its domain and model constants, its tolerance, its
    /// build spec (nodes, ghost nodes, the h* grid, samples, seed) and the
    /// stored precision of its coefficients. [`crate::export::integrate_grid`] with these
    /// options integrates the model on the table's (ψ, θ, h*) grid (whose
    /// F* gave the builder its starting guesses; the file does not store it).
    pub fn from_table(table: &Table) -> BuildOptions {
        let info = table.info();
        let (d, b) = (&info.domain, &info.build);
        BuildOptions {
            psi: d.psi,
            theta: d.theta,
            f_star: d.f_star,
            nodes: b.nodes,
            ghosts: b.ghosts,
            h_star: b.h_star,
            constants: d.constants.clone(),
            precision: info.precision,
            tolerance: info.tolerance,
            samples: b.samples,
            seed: b.seed,
        }
    }
}

/// The threads a build runs on.
pub fn threads() -> usize {
    rayon::current_num_threads()
}

impl crate::Classify for BuildError {
    /// By cause: options are `Argument`/`Domain`, the model's error keeps
    /// its kind (a ghost node without μ is `NoMu`), a missed tolerance is
    /// `Tolerance`, coefficients a file cannot hold are `Domain` (the
    /// options' range).
    fn kind(&self) -> crate::ErrorKind {
        use BuildError::*;
        match self {
            Option(e) => e.kind(),
            Range { .. } => crate::ErrorKind::Domain,
            Eval { error, .. } | Ghost { error, .. } => error.kind(),
            Tolerance { .. } => crate::ErrorKind::Tolerance,
            Unstorable(_) => crate::ErrorKind::Domain,
        }
    }
}
