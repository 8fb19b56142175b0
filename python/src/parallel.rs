//! The batch and thread machinery of array work: the work cut into chunks
//! that threads take in turn ([`Sharing::run`]), inputs that are one value
//! for all ([`Inputs`]); slope pairs go into two arrays by the core's
//! `mu_with_slope_into`. What a bad element does is the core's
//! [`OnError`](ke_friction::OnError) contract, handed on unchanged.

use crate::error::{value_error, Failure};
use pyo3::PyResult;
use std::ops::Range;
use std::sync::{Mutex, OnceLock, PoisonError};

/// What a piece of array work gives: the number of elements set to NaN
/// (with `OnError::Nan`), or the first element that failed (its index in
/// the flat input).
pub type Outcome = Result<usize, Failure>;

/// The elements a batch takes at a time where an input is one value for
/// all.
pub const CHUNK: usize = 256;

/// How a kind of array work is shared out among threads.
pub struct Sharing {
    /// The fewest elements worth a thread of their own.
    per_thread: usize,
    /// The elements a thread takes at a time: small enough that a thread
    /// that starts late (waking an idle core of this VM took 80–260 µs)
    /// takes fewer, large enough that taking them costs nothing that shows.
    chunk: usize,
}

/// Table lookups: about 130 µs of work (at 8 ns a query) a thread, 35 µs
/// a chunk.
pub const TABLE_WORK: Sharing = Sharing {
    per_thread: 16_384,
    chunk: 4_096,
};
/// Curve lookups (about 1 ns each).
pub const CURVE_WORK: Sharing = Sharing {
    per_thread: 131_072,
    chunk: 32_768,
};
/// The model (microseconds to milliseconds a point).
pub const MODEL_WORK: Sharing = Sharing {
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
    /// to do). Returns the NaN elements of all chunks, or the first failed
    /// element of all, so the result does not depend on the threads; after
    /// a failure the chunks not yet taken are dropped (they come after
    /// it). A thread the system refuses to start is done without.
    pub fn run<O: Send>(
        &self,
        n: usize,
        threads: usize,
        parts: impl FnOnce(&[Range<usize>]) -> Vec<O>,
        prepare: impl Fn(usize) + Sync,
        work: impl Fn(Range<usize>, O) -> Outcome + Sync,
    ) -> Outcome {
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
            // Each thread takes chunks in order, so its first failure is
            // its lowest.
            let mut nan = 0;
            loop {
                // (A statement of its own: the lock is not held while working.)
                let next = take().next();
                let Some((r, o)) = next else {
                    return Ok(nan);
                };
                match work(r, o) {
                    Ok(k) => nan += k,
                    Err(failure) => {
                        take().by_ref().for_each(drop);
                        return Err(failure);
                    }
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
            let (mut nan, mut first): (usize, Option<Failure>) = (0, None);
            for outcome in std::iter::once(mine).chain(theirs) {
                match outcome {
                    Ok(k) => nan += k,
                    Err(f) if first.as_ref().is_none_or(|g| f.index < g.index) => first = Some(f),
                    Err(_) => {}
                }
            }
            first.map_or(Ok(nan), Err)
        })
    }
}

/// `out` cut into consecutive parts of `per` elements per element of each
/// range of `ranges` (which run consecutively from 0).
pub fn cut<'a, T>(mut out: &'a mut [T], per: usize, ranges: &[Range<usize>]) -> Vec<&'a mut [T]> {
    let mut parts = Vec::with_capacity(ranges.len());
    for r in ranges {
        let (part, rest) = std::mem::take(&mut out).split_at_mut(r.len() * per);
        parts.push(part);
        out = rest;
    }
    parts
}

/// `mu` and `slope` cut alike (see [`cut`]), in pairs.
pub fn cut_pairs<'a>(
    mu: &'a mut [f64],
    slope: &'a mut [f64],
    ranges: &[Range<usize>],
) -> Vec<(&'a mut [f64], &'a mut [f64])> {
    cut(mu, 1, ranges).into_iter().zip(cut(slope, 1, ranges)).collect()
}

/// Runs `work` on `r` in consecutive pieces of at most `piece` elements,
/// in order; the NaN elements of all, or the first failure.
pub fn in_pieces(r: Range<usize>, piece: usize, mut work: impl FnMut(Range<usize>) -> Outcome) -> Outcome {
    let mut nan = 0;
    let mut a = r.start;
    while a < r.end {
        let b = a + piece.min(r.end - a);
        nan += work(a..b)?;
        a = b;
    }
    Ok(nan)
}

/// `K` inputs of a batch of `n` elements, each `n` values or one value for
/// all (repeated here, a [`CHUNK`] at a time, rather than copied `n` times
/// by NumPy).
pub struct Inputs<'a, const K: usize> {
    values: [&'a [f64]; K],
    /// [`CHUNK`] copies of each one value (unused for the others).
    copies: [[f64; CHUNK]; K],
    /// Whether an input is one value for all (of more than one element).
    pub repeats: bool,
}

impl<'a, const K: usize> Inputs<'a, K> {
    /// The inputs `named`, after a check of their lengths (each `n` or 1).
    pub fn new(n: usize, named: [(&str, &'a [f64]); K]) -> PyResult<Inputs<'a, K>> {
        for (name, x) in named {
            if x.len() != n && x.len() != 1 {
                return Err(value_error(format!("{name} has {} elements, not {n} or 1", x.len())));
            }
        }
        let values = named.map(|(_, x)| x);
        Ok(Inputs {
            values,
            copies: values.map(|x| [if x.len() == 1 { x[0] } else { 0.0 }; CHUNK]),
            repeats: n > 1 && values.iter().any(|x| x.len() == 1),
        })
    }

    /// The most elements [`Inputs::slices`] takes at once.
    pub fn piece(&self) -> usize {
        if self.repeats {
            CHUNK
        } else {
            usize::MAX
        }
    }

    /// The inputs of the elements `r` (at most [`Inputs::piece`] of them):
    /// `x[r]`, or that many copies of the one value.
    pub fn slices(&self, r: Range<usize>) -> [&[f64]; K] {
        std::array::from_fn(|i| {
            let x = self.values[i];
            if x.len() == 1 {
                &self.copies[i][..r.len()]
            } else {
                &x[r.clone()]
            }
        })
    }
}

/// A one-input curve-like batch (`Curve::mu_batch_with`,
/// `FrictionLaw::mu_batch`) from the array `input` (called `name` in
/// errors) into `out`, shared out as [`CURVE_WORK`]: `batch(start, input,
/// out)` runs the core's batch on one chunk starting at element `start`.
/// The NaN count, or the first bad element's error.
pub fn curve_batch(
    py: pyo3::Python<'_>,
    name: &str,
    input: &numpy::PyReadonlyArray1<'_, f64>,
    out: &mut numpy::PyReadwriteArray1<'_, f64>,
    threads: usize,
    batch: impl Fn(usize, &[f64], &mut [f64]) -> Outcome + Sync,
) -> PyResult<usize> {
    let x = crate::convert::slice(name, input)?;
    let out = crate::convert::slice_mut("out", out)?;
    let n = out.len();
    crate::convert::same_len(n, &[(name, x.len())])?;
    py.detach(|| {
        CURVE_WORK.run(
            n,
            threads,
            |chunks| cut(out, 1, chunks),
            |_| (),
            |chunk, out| batch(chunk.start, &x[chunk], out),
        )
    })
    .map_err(|failure| failure.into_pyerr(py))
}
