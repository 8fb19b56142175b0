//! The record of one measured-surface analysis: what `kefric surface
//! --json` prints and the web page shows (`web/`), one definition with its
//! field names (serde) for every front end.

use super::{Derivative, Detrend, Metadata, Surface, SurfaceStats};
use crate::{Friction, Params};

/// One surface (or pair) analysed: the files, the options, the statistics
/// and, with materials, the model's inputs and, with a load, μ. Serialised
/// with serde, its field names are the record's names in every front end.
#[derive(Debug, Clone, serde::Serialize)]
#[non_exhaustive]
pub struct SurfaceRecord<'a> {
    /// The files as the user named them (a web page: the file names).
    pub files: Vec<String>,
    /// What each file said about its measurement (instrument, date, ...).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub metadata: Vec<&'a Metadata>,
    /// The detrending of the statistics.
    pub detrend: Detrend,
    /// The derivative of the slope and curvature moments.
    pub derivative: Derivative,
    /// The statistics (of the equivalent surface, for a pair).
    pub surface: &'a SurfaceStats,
    /// Each surface's own statistics, for a pair.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub parts: Option<Vec<&'a SurfaceStats>>,
    /// The model's inputs, with materials.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub model: Option<&'a Params>,
    /// μ and the friction force, with a load.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction: Option<&'a Friction>,
}

impl<'a> SurfaceRecord<'a> {
    /// The record of `surface` read from `files`, with the model's inputs
    /// `model` and the friction `friction` where given.
    pub fn new(
        files: Vec<String>,
        surface: &'a Surface,
        model: Option<&'a Params>,
        friction: Option<&'a Friction>,
    ) -> SurfaceRecord<'a> {
        let options = surface.options();
        SurfaceRecord {
            files,
            metadata: surface.parts().iter().map(|(t, _)| t.metadata()).collect(),
            detrend: options.detrend,
            derivative: options.derivative,
            surface: surface.stats(),
            parts: (surface.parts().len() > 1).then(|| surface.parts().iter().map(|(_, s)| s).collect()),
            model,
            friction,
        }
    }
}
