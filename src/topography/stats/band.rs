//! The filter pipeline before the statistics (ISO 25178-3): S-filter,
//! F-operation, L-filter.

use super::{Detrend, StatsError, StatsOptions};
use crate::topography::filter::l_filter_of;
use crate::topography::{s_filter, Topography};

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
        // One map-sized buffer at a time besides `self`: the S-filter's
        // result, the L-filter's (from the S-filtered or the given
        // heights less their plane, taken off row by row).
        let s = options.lambda_s.map(|lambda| s_filter(self, lambda)).transpose()?;
        let Some(lambda) = options.lambda_c else {
            // A clone shares the heights.
            return Ok(Some((s.unwrap_or_else(|| self.clone()), options.detrend)));
        };
        let source = s.as_ref().unwrap_or(self);
        let trend = source.trend(options.detrend)?;
        Ok(Some((l_filter_of(source, Some(&trend), lambda)?, Detrend::Mean)))
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
