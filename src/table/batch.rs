//! The batch lookups: many queries at once into the caller's slices (no
//! allocation), with a policy for those outside the domain; the fast
//! kernel runs them eight to a vector where it can.

use super::{slope, FastKernel, LookupError, OnError, Table};

impl Table {
    /// μ for many queries at once, written into `out` (no allocation);
    /// bit for bit what [`mu`](Self::mu) gives for each. All four slices
    /// must have the same length; on an out-of-domain element the error
    /// names its index and `out` is left partly written.
    ///
    /// ```
    /// # use ke_friction::{LookupError, Table};
    /// let table = Table::embedded();
    /// let (psi, theta) = ([1.0; 3], [0.001; 3]);
    /// let mut mu = [0.0; 3];
    /// table.mu_batch(&psi, &theta, &[0.001, 0.01, 0.1], &mut mu)?;
    /// assert_eq!(mu[1], table.mu(1.0, 0.001, 0.01)?);
    /// // F* = 0.2 is outside the default table (1e-5 ≤ F* ≤ 0.1):
    /// let err = table.mu_batch(&psi, &theta, &[0.001, 0.2, 0.1], &mut mu).unwrap_err();
    /// assert!(matches!(err, LookupError::BatchElement { index: 1, name: "f_star", .. }));
    /// # Ok::<(), LookupError>(())
    /// ```
    pub fn mu_batch(&self, psi: &[f64], theta: &[f64], f_star: &[f64], out: &mut [f64]) -> Result<(), LookupError> {
        self.batch(psi, theta, f_star, BatchOutput::Mu(out), OnError::Stop)
            .map(|_| ())
    }

    /// [`mu_batch`](Self::mu_batch) with a policy for queries outside the
    /// domain: [`OnError::Stop`] as there, or [`OnError::Nan`], which writes
    /// NaN there and finishes the batch. Returns how many elements are NaN.
    ///
    /// ```
    /// # use ke_friction::{OnError, Table};
    /// let table = Table::embedded();
    /// let mut mu = [0.0; 3];
    /// let n_nan = table.mu_batch_with(&[1.0; 3], &[0.001; 3], &[0.01, f64::NAN, 0.2], &mut mu, OnError::Nan)?;
    /// assert_eq!(n_nan, 2);
    /// assert!(mu[0] == table.mu(1.0, 0.001, 0.01)? && mu[1].is_nan() && mu[2].is_nan());
    /// # Ok::<(), ke_friction::LookupError>(())
    /// ```
    pub fn mu_batch_with(
        &self,
        psi: &[f64],
        theta: &[f64],
        f_star: &[f64],
        out: &mut [f64],
        on_error: OnError,
    ) -> Result<usize, LookupError> {
        self.batch(psi, theta, f_star, BatchOutput::Mu(out), on_error)
    }

    /// [`mu_with_slope_batch`](Self::mu_with_slope_batch) with a policy
    /// (see [`mu_batch_with`](Self::mu_batch_with)); NaN pairs at bad queries.
    pub fn mu_with_slope_batch_with(
        &self,
        psi: &[f64],
        theta: &[f64],
        f_star: &[f64],
        out: &mut [(f64, f64)],
        on_error: OnError,
    ) -> Result<usize, LookupError> {
        self.batch(psi, theta, f_star, BatchOutput::WithSlope(out), on_error)
    }

    /// μ and ∂μ/∂F* for many queries at once, written into `out` as
    /// `(μ, ∂μ/∂F*)` pairs (no allocation): the batch form of
    /// [`mu_with_slope`](Self::mu_with_slope), bit for bit, for implicit
    /// solvers with many contacts. Lengths and errors as in
    /// [`mu_batch`](Self::mu_batch).
    ///
    /// ```
    /// # use ke_friction::Table;
    /// let table = Table::embedded();
    /// let loads = [0.001, 0.01, 0.1];
    /// let mut out = [(0.0, 0.0); 3];
    /// table.mu_with_slope_batch(&[2.0; 3], &[0.003; 3], &loads, &mut out)?;
    /// for (&f, &(mu, dmu)) in loads.iter().zip(&out) {
    ///     assert_eq!((mu, dmu), table.mu_with_slope(2.0, 0.003, f)?);
    ///     assert!(dmu < 0.0); // μ falls as the load rises
    /// }
    /// # Ok::<(), ke_friction::LookupError>(())
    /// ```
    pub fn mu_with_slope_batch(
        &self,
        psi: &[f64],
        theta: &[f64],
        f_star: &[f64],
        out: &mut [(f64, f64)],
    ) -> Result<(), LookupError> {
        self.batch(psi, theta, f_star, BatchOutput::WithSlope(out), OnError::Stop)
            .map(|_| ())
    }

    /// [`mu_with_slope_batch_with`](Self::mu_with_slope_batch_with) into
    /// two arrays, `mu` and `slope` (as C and NumPy hold them), through a
    /// stack buffer: no allocation. All five slices have one length
    /// ([`LookupError::LengthMismatch`] otherwise, `out` the first of `mu`
    /// and `slope` that differs); errors and NaNs as the pairs batch.
    pub fn mu_with_slope_into(
        &self,
        psi: &[f64],
        theta: &[f64],
        f_star: &[f64],
        mu: &mut [f64],
        slope: &mut [f64],
        on_error: OnError,
    ) -> Result<usize, LookupError> {
        let n = f_star.len();
        let out = if mu.len() != n { mu.len() } else { slope.len() };
        if psi.len() != n || theta.len() != n || out != n {
            return Err(LookupError::LengthMismatch {
                psi: psi.len(),
                theta: theta.len(),
                f_star: n,
                out,
            });
        }
        self.prepare_batch(n);
        super::error::scatter_pairs(mu, slope, |r, out| {
            self.mu_with_slope_batch_with(&psi[r.clone()], &theta[r.clone()], &f_star[r], out, on_error)
        })
    }

    /// Readies the table for `n` lookups made in smaller batches: what a
    /// batch of `n` queries does first by itself. On the fast kernel (see
    /// [`fast_kernel`](Self::fast_kernel)) a batch of at least one query
    /// per 64-byte line of coefficients (about 12,900 for the default
    /// table) reads them through into the L2 cache in order, far cheaper
    /// than the queries' scattered misses where other work has swept the
    /// caches; a smaller one, and the portable kernel, do nothing. Call it
    /// before a large batch split into pieces (as the Python package
    /// splits its work into chunks for its threads), so the pass runs once
    /// for the whole; on each thread that shares the work, since each
    /// core has its own L2 cache.
    ///
    /// ```
    /// # use ke_friction::Table;
    /// let table = Table::embedded();
    /// let (psi, theta, f_star) = (vec![1.0; 20_000], vec![0.001; 20_000], vec![0.01; 20_000]);
    /// let mut out = vec![(0.0, 0.0); 20_000];
    /// table.prepare_batch(out.len());
    /// for ((p, t), (f, o)) in psi.chunks(256).zip(theta.chunks(256)).zip(f_star.chunks(256).zip(out.chunks_mut(256))) {
    ///     table.mu_with_slope_batch(p, t, f, o)?;
    /// }
    /// assert_eq!(out[19_999], table.mu_with_slope(1.0, 0.001, 0.01)?);
    /// # Ok::<(), ke_friction::LookupError>(())
    /// ```
    pub fn prepare_batch(&self, n: usize) {
        if let Some(kernel) = &self.avx2 {
            kernel.prepare(n);
        }
    }

    /// Both batch forms: checks the lengths, runs the kernel, and applies
    /// `on_error` at each query outside the domain; returns the number of
    /// NaN elements.
    fn batch(
        &self,
        psi: &[f64],
        theta: &[f64],
        f_star: &[f64],
        mut out: BatchOutput,
        on_error: OnError,
    ) -> Result<usize, LookupError> {
        let n = out.len();
        if psi.len() != n || theta.len() != n || f_star.len() != n {
            return Err(LookupError::LengthMismatch {
                psi: psi.len(),
                theta: theta.len(),
                f_star: f_star.len(),
                out: n,
            });
        }
        let Some(kernel) = &self.avx2 else {
            let mut nan = 0;
            for i in 0..n {
                let r = match &out {
                    BatchOutput::Mu(_) => self.mu_portable(psi[i], theta[i], f_star[i]).map(|mu| (mu, 0.0)),
                    BatchOutput::WithSlope(_) => self.mu_with_slope_portable(psi[i], theta[i], f_star[i]),
                };
                match r {
                    Ok((mu, slope)) => out.set(i, mu, slope),
                    Err(e) => {
                        on_error.bad(i, e)?;
                        out.set(i, f64::NAN, f64::NAN);
                        nan += 1;
                    }
                }
            }
            return Ok(nan);
        };
        kernel.prepare(n);
        let (mut start, mut nan) = (0, 0);
        while start < n {
            let Some(j) = kernel.batch(&psi[start..], &theta[start..], &f_star[start..], out.tail(start)) else {
                break;
            };
            // A NaN from the fast kernel: the query is outside the domain,
            // or (impossible for a table that loads, see `nan_from_kernel`)
            // the portable kernel answers it and the batch goes on.
            let i = start + j;
            match self.nan_from_kernel(psi[i], theta[i], f_star[i]) {
                Ok((mu, d)) => out.set(i, mu, slope(mu, d, self.layout.inv_step[2], f_star[i])),
                Err(e) => {
                    on_error.bad(i, e)?;
                    out.set(i, f64::NAN, f64::NAN);
                    nan += 1;
                }
            }
            start = i + 1;
        }
        Ok(nan)
    }
}

/// Where a batch writes: μ alone, or (μ, ∂μ/∂F*) pairs.
pub(super) enum BatchOutput<'a> {
    /// [`Table::mu_batch`].
    Mu(&'a mut [f64]),
    /// [`Table::mu_with_slope_batch`].
    WithSlope(&'a mut [(f64, f64)]),
}

impl BatchOutput<'_> {
    /// The number of queries.
    pub(super) fn len(&self) -> usize {
        match self {
            BatchOutput::Mu(o) => o.len(),
            BatchOutput::WithSlope(o) => o.len(),
        }
    }

    /// The outputs from `start` on.
    pub(super) fn tail(&mut self, start: usize) -> BatchOutput<'_> {
        match self {
            BatchOutput::Mu(o) => BatchOutput::Mu(&mut o[start..]),
            BatchOutput::WithSlope(o) => BatchOutput::WithSlope(&mut o[start..]),
        }
    }

    /// Writes query `i`'s μ and, where asked for, its slope.
    pub(super) fn set(&mut self, i: usize, mu: f64, slope: f64) {
        match self {
            BatchOutput::Mu(o) => o[i] = mu,
            BatchOutput::WithSlope(o) => o[i] = (mu, slope),
        }
    }
}
