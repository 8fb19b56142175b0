//! The filter pipeline before the statistics (ISO 25178-3): S-filter,
//! F-operation, L-filter.

use super::{Detrend, StatsError, StatsOptions};
use crate::topography::{l_filter, s_filter, Topography};

impl Topography {
    /// The surface in the band `options` states, and the detrending left
    /// for the statistics to do: S-filter (λs), then the F-operation and
    /// the L-filter (λc) if there is one (the roughness, detrended: the
    /// statistics only take its mean out). `None` without filters.
    pub(super) fn band(&self, options: &StatsOptions) -> Result<Option<(Topography, Detrend)>, StatsError> {
        if options.lambda_s.is_none() && options.lambda_c.is_none() {
            return Ok(None);
        }
        options.check()?;
        let s = match options.lambda_s {
            Some(lambda) => s_filter(self, lambda)?,
            None => self.clone(),
        };
        let Some(lambda) = options.lambda_c else {
            return Ok(Some((s, options.detrend)));
        };
        Ok(Some((
            l_filter(&s.detrended_topography(options.detrend)?, lambda)?,
            Detrend::Mean,
        )))
    }

    /// The surface detrended as `detrend` says (missing points stay
    /// missing): what the L-filter and the power spectra start from.
    pub fn detrended_topography(&self, detrend: Detrend) -> Result<Topography, StatsError> {
        Ok(Topography::new(
            self.detrended(detrend)?,
            self.nx,
            self.ny,
            self.dx,
            self.dy,
        )?)
    }

    /// The heights the statistics see: in the band `options` states
    /// (filtered as [`Topography::stats`] does) and detrended, missing
    /// points NaN. What an empirical height density is built from.
    pub fn band_heights(&self, options: &StatsOptions) -> Result<Vec<f64>, StatsError> {
        match self.band(options)? {
            Some((band, detrend)) => band.detrended(detrend),
            None => self.detrended(options.detrend),
        }
    }
}
