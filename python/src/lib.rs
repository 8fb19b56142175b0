//! The native half of the Python package `ke_friction` (`ke_friction._core`):
//! tables, curves and the model over contiguous float64 arrays, with the
//! GIL released. `pysrc/ke_friction/__init__.py` adds NumPy broadcasting,
//! argument checks and the documented Python API on top.

use ke_friction::{Curve, Fit, Kind, LookupError, Model, Params, Physical, Table};
use numpy::{PyReadonlyArray1, PyReadwriteArray1};
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::borrow::Cow;
use std::ops::Range;
use std::sync::{Mutex, OnceLock, PoisonError};

/// A failed element: its index in the flat input and the message.
type Bad = Option<(usize, String)>;

/// Results a slope lookup writes per chunk (a stack buffer of pairs,
/// scattered into the two output arrays).
const CHUNK: usize = 256;

pyo3::create_exception!(
    _core,
    TableError,
    PyValueError,
    "A table file that is damaged, not a table, or inconsistent (a ValueError)."
);

fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

fn slice<'a>(name: &str, a: &'a PyReadonlyArray1<'_, f64>) -> PyResult<&'a [f64]> {
    a.as_slice()
        .map_err(|_| value_error(format!("{name} must be contiguous")))
}

fn slice_mut<'a>(name: &str, a: &'a mut PyReadwriteArray1<'_, f64>) -> PyResult<&'a mut [f64]> {
    a.as_slice_mut()
        .map_err(|_| value_error(format!("{name} must be contiguous")))
}

/// A `ValueError` unless every named length is `n` (the Python layer
/// always passes equal lengths; this keeps a direct call of `_core` from
/// panicking).
fn same_len(n: usize, named: &[(&str, usize)]) -> PyResult<()> {
    match named.iter().find(|(_, len)| *len != n) {
        None => Ok(()),
        Some((name, len)) => Err(value_error(format!("{name} has {len} elements, not {n}"))),
    }
}

/// Checks the lengths of a table lookup's inputs: each `n`, or 1 for an
/// argument the same for every element (broadcast here, a chunk at a time,
/// rather than copied `n` times by NumPy). True if one is (`repeats`).
fn table_inputs(n: usize, named: [(&str, &[f64]); 3]) -> PyResult<bool> {
    for (name, x) in named {
        if x.len() != n && x.len() != 1 {
            return Err(value_error(format!("{name} has {} elements, not {n} or 1", x.len())));
        }
    }
    Ok(n > 1 && named.iter().any(|(_, x)| x.len() == 1))
}

/// A chunk of [`CHUNK`] copies of `x[0]` if `x` is one value (else unused).
fn repeated(x: &[f64]) -> [f64; CHUNK] {
    [if x.len() == 1 { x[0] } else { 0.0 }; CHUNK]
}

/// The inputs of the elements `r` (at most [`CHUNK`] of them where `x` is
/// one value): `x[r]`, or that many copies of the one value.
fn part<'a>(x: &'a [f64], copies: &'a [f64; CHUNK], r: Range<usize>) -> &'a [f64] {
    if x.len() == 1 {
        &copies[..r.len()]
    } else {
        &x[r]
    }
}

/// Runs `batch` over `r` in pieces of at most [`CHUNK`] elements if
/// `repeats` (an input is one value, repeated), else at once; a bad
/// element's index is relative to `r`.
fn in_chunks<T>(
    repeats: bool,
    r: Range<usize>,
    out: &mut [T],
    batch: impl Fn(Range<usize>, &mut [T]) -> Result<(), LookupError>,
) -> Result<(), LookupError> {
    if !repeats {
        return batch(r, out);
    }
    let mut a = r.start;
    while a < r.end {
        let b = (a + CHUNK).min(r.end);
        let k = a - r.start;
        batch(a..b, &mut out[k..k + (b - a)]).map_err(|e| match e {
            LookupError::BatchElement {
                index,
                name,
                value,
                lo,
                hi,
            } => LookupError::BatchElement {
                index: index + k,
                name,
                value,
                lo,
                hi,
            },
            other => other,
        })?;
        a = b;
    }
    Ok(())
}

/// The index (in the slices passed) and message of a batch's error, and
/// whether it is one element's (the others, mismatched lengths, cannot be
/// skipped). An element's message is the scalar lookup's ("psi = 9 is
/// outside the range [0.5, 8]"); the Python layer adds the index in its
/// shape.
fn element(e: LookupError) -> (usize, String, bool) {
    match e {
        LookupError::BatchElement {
            index,
            name,
            value,
            lo,
            hi,
        } => (
            index,
            LookupError::OutOfDomain { name, value, lo, hi }.to_string(),
            true,
        ),
        other => (0, other.to_string(), false),
    }
}

/// Fills `out` by `batch` (which takes an index range of the inputs and
/// the matching part of `out`). At a bad element either stops (its index
/// and message) or, with `nan`, writes `bad` there and goes on after it.
fn fill_batch<T: Copy>(
    nan: bool,
    out: &mut [T],
    bad: T,
    batch: impl Fn(Range<usize>, &mut [T]) -> Result<(), LookupError>,
) -> Bad {
    let n = out.len();
    let mut start = 0;
    while start < n {
        let Err(e) = batch(start..n, &mut out[start..]) else {
            return None;
        };
        let (k, message, skip) = element(e);
        let i = start + k;
        if !(nan && skip) || i >= n {
            return Some((i, message));
        }
        // A failed batch promises only that `out` is partly written, so
        // the elements before the bad one (all in the domain) run again.
        if k > 0 {
            if let Err(e) = batch(start..i, &mut out[start..i]) {
                let (k, message, _) = element(e);
                return Some((start + k, message));
            }
        }
        out[i] = bad;
        start = i + 1;
    }
    None
}

/// μ and the slope into `mu` and `slope` through a batch of pairs, a chunk
/// at a time; bad elements as in [`fill_batch`].
fn fill_pairs(
    nan: bool,
    mu: &mut [f64],
    slope: &mut [f64],
    batch: impl Fn(Range<usize>, &mut [(f64, f64)]) -> Result<(), LookupError>,
) -> Bad {
    let mut pairs = [(0.0, 0.0); CHUNK];
    let mut a = 0;
    while a < mu.len() {
        let b = (a + CHUNK).min(mu.len());
        let chunk = &mut pairs[..b - a];
        let failed = fill_batch(nan, chunk, (f64::NAN, f64::NAN), |r, o| {
            batch(a + r.start..a + r.end, o)
        });
        if let Some((k, message)) = failed {
            return Some((a + k, message));
        }
        for (i, &(m, s)) in chunk.iter().enumerate() {
            (mu[a + i], slope[a + i]) = (m, s);
        }
        a = b;
    }
    None
}

/// How a kind of array work is shared out among threads.
struct Sharing {
    /// The fewest elements worth a thread of their own.
    per_thread: usize,
    /// The elements a thread takes at a time: small enough that a thread
    /// that starts late (waking an idle core of this VM took 80–260 µs)
    /// takes fewer, large enough that taking them costs nothing that shows.
    chunk: usize,
}

/// Table lookups: about 130 µs of work (at 8 ns a query) a thread, 35 µs
/// a chunk.
const TABLE_WORK: Sharing = Sharing {
    per_thread: 16_384,
    chunk: 4_096,
};
/// Curve lookups (about 1 ns each).
const CURVE_WORK: Sharing = Sharing {
    per_thread: 131_072,
    chunk: 32_768,
};
/// The model (microseconds to milliseconds a point).
const MODEL_WORK: Sharing = Sharing {
    per_thread: 4,
    chunk: 1,
};

impl Sharing {
    /// Runs `work` on `n` elements in chunks (a range of elements and its
    /// part of the output, from `parts`, which cuts the output for the
    /// chunks in order) on up to `threads` threads (0: one per core this
    /// process may use; 1 unless `n` is at least two threads' worth): the
    /// calling one and the others started here, each taking the next chunk
    /// until none is left, after `prepare` (told the elements a thread is
    /// to do). Returns the first bad element of all (each chunk's index is
    /// relative to its start), so the result does not depend on the
    /// threads; after a bad element the chunks not yet taken are dropped
    /// (they come after it). A thread the system refuses to start is done
    /// without.
    fn run<O: Send>(
        &self,
        n: usize,
        threads: usize,
        parts: impl FnOnce(&[Range<usize>]) -> Vec<O>,
        prepare: impl Fn(usize) + Sync,
        work: impl Fn(Range<usize>, O) -> Bad + Sync,
    ) -> Bad {
        static CORES: OnceLock<usize> = OnceLock::new();
        let threads = match (n / self.per_thread, threads) {
            (0 | 1, _) => 1,
            (most, 0) => most.min(*CORES.get_or_init(|| std::thread::available_parallelism().map_or(1, |c| c.get()))),
            (most, t) => most.min(t),
        };
        let chunks: Vec<_> = (0..n.div_ceil(self.chunk))
            .map(|i| i * self.chunk..((i + 1) * self.chunk).min(n))
            .collect();
        let parts = parts(&chunks);
        let queue = Mutex::new(chunks.into_iter().zip(parts));
        let take = || queue.lock().unwrap_or_else(PoisonError::into_inner);
        let worker = || {
            prepare(n / threads);
            // Each thread takes chunks in order, so its first bad element
            // is its lowest.
            loop {
                // (A statement of its own: the lock is not held while working.)
                let next = take().next();
                let (r, o) = next?;
                if let Some((i, message)) = work(r.clone(), o) {
                    take().by_ref().for_each(drop);
                    return Some((r.start + i, message));
                }
            }
        };
        if threads == 1 {
            return worker();
        }
        std::thread::scope(|s| {
            let others: Vec<_> = (1..threads)
                .map_while(|_| std::thread::Builder::new().spawn_scoped(s, worker).ok())
                .collect();
            let mine = worker();
            let theirs = others
                .into_iter()
                .map(|h| h.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic)));
            std::iter::once(mine).chain(theirs).flatten().min_by_key(|(i, _)| *i)
        })
    }
}

/// `out` cut into consecutive parts of `per` elements per element of each
/// range of `ranges` (which run consecutively from 0).
fn cut<'a, T>(mut out: &'a mut [T], per: usize, ranges: &[Range<usize>]) -> Vec<&'a mut [T]> {
    let mut parts = Vec::with_capacity(ranges.len());
    for r in ranges {
        let (part, rest) = std::mem::take(&mut out).split_at_mut(r.len() * per);
        parts.push(part);
        out = rest;
    }
    parts
}

/// `mu` and `slope` cut alike (see [`cut`]), in pairs.
fn cut_pairs<'a>(
    mu: &'a mut [f64],
    slope: &'a mut [f64],
    ranges: &[Range<usize>],
) -> Vec<(&'a mut [f64], &'a mut [f64])> {
    cut(mu, 1, ranges).into_iter().zip(cut(slope, 1, ranges)).collect()
}

/// Readies `table` for `n` lookups by this thread (its coefficients read
/// through into this core's cache, see [`Table::prepare_batch`]), unless
/// an argument is one value for all (`repeats`: the queries then touch few
/// of them).
fn read_through(table: &Table, repeats: bool, n: usize) {
    if !repeats {
        table.prepare_batch(n);
    }
}

/// `r` moved up by `by`.
fn shift(r: Range<usize>, by: usize) -> Range<usize> {
    r.start + by..r.end + by
}

/// A table of μ(ψ, θ, F*).
#[pyclass(frozen, module = "ke_friction._core")]
struct TableCore(Cow<'static, Table>);

#[pymethods]
impl TableCore {
    #[staticmethod]
    fn default() -> TableCore {
        TableCore(Cow::Borrowed(Table::embedded()))
    }

    #[staticmethod]
    fn load(path: std::path::PathBuf) -> PyResult<TableCore> {
        match Table::load(&path) {
            Ok(t) => Ok(TableCore(Cow::Owned(t))),
            Err(e @ ke_friction::TableError::Io { .. }) => Err(PyOSError::new_err(e.to_string())),
            Err(e) => Err(TableError::new_err(format!("{}: {e}", path.display()))),
        }
    }

    fn mu_scalar(&self, psi: f64, theta: f64, f_star: f64) -> PyResult<f64> {
        self.0.mu(psi, theta, f_star).map_err(value_error)
    }

    fn mu_with_slope_scalar(&self, psi: f64, theta: f64, f_star: f64) -> PyResult<(f64, f64)> {
        self.0.mu_with_slope(psi, theta, f_star).map_err(value_error)
    }

    /// μ into `out`; returns None, or (index, message) of the first bad
    /// element (with nan=False). Each input has `out`'s length or is one
    /// value for all. `threads`: the most threads to use, 0 for one per
    /// core (large arrays only, see [`TABLE_WORK`]).
    #[allow(clippy::too_many_arguments)]
    fn mu_into(
        &self,
        py: Python<'_>,
        psi: PyReadonlyArray1<'_, f64>,
        theta: PyReadonlyArray1<'_, f64>,
        f_star: PyReadonlyArray1<'_, f64>,
        mut out: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<Bad> {
        let (p, t, f) = (slice("psi", &psi)?, slice("theta", &theta)?, slice("f_star", &f_star)?);
        let out = slice_mut("out", &mut out)?;
        let repeats = table_inputs(out.len(), [("psi", p), ("theta", t), ("f_star", f)])?;
        let (cp, ct, cf) = (repeated(p), repeated(t), repeated(f));
        let table = &*self.0;
        let n = out.len();
        Ok(py.detach(|| {
            TABLE_WORK.run(
                n,
                threads,
                |chunks| cut(out, 1, chunks),
                |m| read_through(table, repeats, m),
                |chunk, out| {
                    fill_batch(nan, out, f64::NAN, |r, o| {
                        in_chunks(repeats, shift(r, chunk.start), o, |r, o| {
                            let (p, t, f) = (part(p, &cp, r.clone()), part(t, &ct, r.clone()), part(f, &cf, r));
                            table.mu_batch(p, t, f, o)
                        })
                    })
                },
            )
        }))
    }

    /// μ and ∂μ/∂F* into `mu` and `slope`; as `mu_into`.
    #[allow(clippy::too_many_arguments)]
    fn mu_with_slope_into(
        &self,
        py: Python<'_>,
        psi: PyReadonlyArray1<'_, f64>,
        theta: PyReadonlyArray1<'_, f64>,
        f_star: PyReadonlyArray1<'_, f64>,
        mut mu: PyReadwriteArray1<'_, f64>,
        mut slope: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<Bad> {
        let (p, t, f) = (slice("psi", &psi)?, slice("theta", &theta)?, slice("f_star", &f_star)?);
        let (mu, slope) = (slice_mut("mu", &mut mu)?, slice_mut("slope", &mut slope)?);
        same_len(mu.len(), &[("slope", slope.len())])?;
        let repeats = table_inputs(mu.len(), [("psi", p), ("theta", t), ("f_star", f)])?;
        let (cp, ct, cf) = (repeated(p), repeated(t), repeated(f));
        let table = &*self.0;
        let n = mu.len();
        Ok(py.detach(|| {
            TABLE_WORK.run(
                n,
                threads,
                |chunks| cut_pairs(mu, slope, chunks),
                |m| read_through(table, repeats, m),
                |chunk, (mu, slope)| {
                    fill_pairs(nan, mu, slope, |r, o| {
                        let r = shift(r, chunk.start);
                        let (p, t, f) = (part(p, &cp, r.clone()), part(t, &ct, r.clone()), part(f, &cf, r));
                        table.mu_with_slope_batch(p, t, f, o)
                    })
                },
            )
        }))
    }

    fn curve(&self, psi: f64, theta: f64) -> PyResult<CurveCore> {
        self.0.curve(psi, theta).map(CurveCore).map_err(value_error)
    }

    fn info<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let info = self.0.info();
        let d = &info.domain;
        let dict = PyDict::new(py);
        dict.set_item("psi", d.psi)?;
        dict.set_item("theta", d.theta)?;
        dict.set_item("f_star", d.f_star)?;
        dict.set_item("beta", d.constants.beta)?;
        dict.set_item("nu", d.constants.nu)?;
        dict.set_item("eps_star", d.constants.eps_star)?;
        dict.set_item("model", d.constants.kind.name())?;
        dict.set_item("fit", d.constants.fit.name())?;
        dict.set_item("tolerance", info.tolerance)?;
        dict.set_item("max_rel_error", info.accuracy.max_rel)?;
        dict.set_item("p99_rel_error", info.accuracy.p99_rel)?;
        dict.set_item("error_samples", info.accuracy.samples)?;
        dict.set_item("worst_point", info.accuracy.worst)?;
        dict.set_item("fast_kernel", self.0.fast_kernel())?;
        dict.set_item("nodes", info.build.nodes)?;
        dict.set_item("precision", info.precision.name())?;
        dict.set_item("format_version", info.format_version)?;
        dict.set_item("generator", info.build.generator.as_str())?;
        Ok(dict)
    }
}

/// μ(F*) of one surface pair.
#[pyclass(frozen, module = "ke_friction._core")]
struct CurveCore(Curve);

#[pymethods]
impl CurveCore {
    #[staticmethod]
    fn from_model(model: &ModelCore, f_star_min: f64, f_star_max: f64) -> PyResult<CurveCore> {
        Curve::from_model(&model.0, f_star_min, f_star_max)
            .map(CurveCore)
            .map_err(value_error)
    }

    fn range(&self) -> (f64, f64) {
        self.0.range()
    }

    fn max_error(&self) -> f64 {
        self.0.max_error()
    }

    fn mu_scalar(&self, f_star: f64) -> PyResult<f64> {
        self.0.mu(f_star).map_err(value_error)
    }

    fn mu_with_slope_scalar(&self, f_star: f64) -> PyResult<(f64, f64)> {
        self.0.mu_with_slope(f_star).map_err(value_error)
    }

    fn mu_into(
        &self,
        py: Python<'_>,
        f_star: PyReadonlyArray1<'_, f64>,
        mut out: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<Bad> {
        let f = slice("f_star", &f_star)?;
        let out = slice_mut("out", &mut out)?;
        same_len(out.len(), &[("f_star", f.len())])?;
        let curve = &self.0;
        let n = out.len();
        Ok(py.detach(|| {
            CURVE_WORK.run(
                n,
                threads,
                |chunks| cut(out, 1, chunks),
                |_| (),
                |chunk, out| fill_batch(nan, out, f64::NAN, |r, o| curve.mu_batch(&f[shift(r, chunk.start)], o)),
            )
        }))
    }

    #[allow(clippy::too_many_arguments)]
    fn mu_with_slope_into(
        &self,
        py: Python<'_>,
        f_star: PyReadonlyArray1<'_, f64>,
        mut mu: PyReadwriteArray1<'_, f64>,
        mut slope: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<Bad> {
        let f = slice("f_star", &f_star)?;
        let (mu, slope) = (slice_mut("mu", &mut mu)?, slice_mut("slope", &mut slope)?);
        same_len(mu.len(), &[("f_star", f.len()), ("slope", slope.len())])?;
        let curve = &self.0;
        let n = mu.len();
        Ok(py.detach(|| {
            CURVE_WORK.run(
                n,
                threads,
                |chunks| cut_pairs(mu, slope, chunks),
                |_| (),
                |chunk, (mu, slope)| {
                    fill_pairs(nan, mu, slope, |r, o| {
                        curve.mu_with_slope_batch(&f[shift(r, chunk.start)], o)
                    })
                },
            )
        }))
    }
}

/// The model by direct integration.
#[pyclass(frozen, module = "ke_friction._core")]
struct ModelCore(Model);

#[pymethods]
impl ModelCore {
    #[new]
    fn new(psi: f64, theta: f64, beta: f64, nu: f64, eps_star: f64, fit: &str, model: &str) -> PyResult<ModelCore> {
        let fit = Fit::from_name(fit)
            .ok_or_else(|| value_error(format!("fit = {fit:?}: must be \"consistent\" or \"as-printed\"")))?;
        let kind = Kind::from_name(model)
            .ok_or_else(|| value_error(format!("model = {model:?}: must be \"ke\" or \"ceb\"")))?;
        let params = Params::new(psi, theta)
            .beta(beta)
            .nu(nu)
            .eps_star(eps_star)
            .fit(fit)
            .kind(kind);
        Model::new(params).map(ModelCore).map_err(value_error)
    }

    /// The contacts at `x` (F* if `at_f_star`, else h*) into the seven
    /// output arrays (h*, d*, P*, Fs*, Q*, F*, μ); bad elements and
    /// `threads` as above.
    #[allow(clippy::too_many_arguments)]
    fn contacts_into(
        &self,
        py: Python<'_>,
        x: PyReadonlyArray1<'_, f64>,
        at_f_star: bool,
        mut out: PyReadwriteArray1<'_, f64>,
        nan: bool,
        threads: usize,
    ) -> PyResult<Bad> {
        let x = slice("x", &x)?;
        let out = slice_mut("out", &mut out)?;
        same_len(7 * x.len(), &[("out", out.len())])?;
        let model = &self.0;
        Ok(py.detach(|| {
            MODEL_WORK.run(
                x.len(),
                threads,
                |chunks| cut(out, 7, chunks),
                |_| (),
                |chunk, out| {
                    for (i, (&v, row)) in x[chunk].iter().zip(out.chunks_exact_mut(7)).enumerate() {
                        let c = if at_f_star {
                            model.at_f_star(v)
                        } else {
                            model.at_h_star(v)
                        };
                        match c {
                            Ok(c) => row.copy_from_slice(&[
                                c.h_star,
                                c.d_star,
                                c.p_star,
                                c.fs_star,
                                c.q_star,
                                c.f_star,
                                c.mu.unwrap_or(f64::NAN),
                            ]),
                            Err(_) if nan => row.fill(f64::NAN),
                            Err(e) => return Some((i, e.to_string())),
                        }
                    }
                    None
                },
            )
        }))
    }

    fn params<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let p = self.0.params();
        let dict = PyDict::new(py);
        dict.set_item("psi", p.psi)?;
        dict.set_item("theta", p.theta)?;
        dict.set_item("beta", p.constants.beta)?;
        dict.set_item("nu", p.constants.nu)?;
        dict.set_item("eps_star", p.constants.eps_star)?;
        dict.set_item("fit", p.constants.fit.name())?;
        dict.set_item("model", p.constants.kind.name())?;
        Ok(dict)
    }
}

/// ψ, θ, β, ν, ε* of SI inputs ([`Params::from_physical`]).
#[pyfunction]
#[allow(clippy::too_many_arguments)]
fn params_from_physical<'py>(
    py: Python<'py>,
    e1: f64,
    nu1: f64,
    e2: f64,
    nu2: f64,
    hardness: f64,
    sigma: f64,
    radius: f64,
    density: f64,
    delta_gamma: f64,
    epsilon: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let phys = Physical {
        e1,
        nu1,
        e2,
        nu2,
        hardness,
        sigma,
        radius,
        density,
        delta_gamma,
        epsilon,
    };
    let p = Params::from_physical(&phys).map_err(value_error)?;
    let dict = PyDict::new(py);
    dict.set_item("psi", p.psi)?;
    dict.set_item("theta", p.theta)?;
    dict.set_item("beta", p.constants.beta)?;
    dict.set_item("nu", p.constants.nu)?;
    dict.set_item("eps_star", p.constants.eps_star)?;
    Ok(dict)
}

#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<TableCore>()?;
    m.add_class::<CurveCore>()?;
    m.add_class::<ModelCore>()?;
    m.add_function(wrap_pyfunction!(params_from_physical, m)?)?;
    m.add("CURVE_ACCURACY", ke_friction::CURVE_ACCURACY)?;
    m.add("TableError", m.py().get_type::<TableError>())?;
    Ok(())
}
