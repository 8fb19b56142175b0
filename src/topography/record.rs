//! The record of one measured-surface analysis: what `kefric surface
//! --json` prints and the web page shows (`web/`), one definition with its
//! field names (serde) for every front end.

use super::{Derivative, Detrend, Metadata, Sensitivity, Surface, SurfaceStats};
use crate::{Friction, Params, Warnings};

/// One surface (or pair) analysed: the files, what they said about the
/// measurement, the options, the statistics and, with materials, the
/// model's inputs and, with a load (or loads), μ; and the warnings.
/// Serialised with serde, its field names are the record's names in every
/// front end.
#[derive(Debug, Clone, serde::Serialize)]
#[non_exhaustive]
pub struct SurfaceRecord<'a> {
    /// The files as the user named them (a web page: the file names).
    pub files: Vec<String>,
    /// What each file said about its measurement (format, instrument,
    /// channel, ...), one a part.
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
    /// μ and the friction force, with a load; a list for a range of loads.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction: Option<Frictions<'a>>,
    /// The warnings, one a kind (the worst value and how many results gave
    /// it): the statistics' and, with [`with_warnings`](Self::with_warnings),
    /// the loads'. Serialised as the list of [`Warnings::summaries`].
    #[serde(serialize_with = "summaries")]
    pub warnings: Warnings,
}

/// The warnings as their summaries, one a kind.
fn summaries<S: serde::Serializer>(warnings: &Warnings, serializer: S) -> Result<S::Ok, S::Error> {
    serializer.collect_seq(warnings.summaries())
}

/// The friction of one load, or of a range of loads.
#[derive(Debug, Clone, serde::Serialize)]
#[serde(untagged)]
pub enum Frictions<'a> {
    /// One load's (a record).
    One(FrictionRecord<'a>),
    /// A range of loads' (a list of records).
    Many(Vec<FrictionRecord<'a>>),
}

/// One load's friction and, where computed, its sensitivity (μ under
/// each height model and at the ends of the band).
#[derive(Debug, Clone, serde::Serialize)]
pub struct FrictionRecord<'a> {
    /// The friction.
    #[serde(flatten)]
    pub friction: &'a Friction,
    /// μ under the other choices.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sensitivity: Option<&'a Sensitivity>,
}

impl<'a> SurfaceRecord<'a> {
    /// The record of `surface` read from `files`, with the model's inputs
    /// `model` and the friction `friction` where given; the warnings are
    /// the statistics' until [`with_warnings`](Self::with_warnings).
    pub fn new(
        files: Vec<String>,
        surface: &'a Surface,
        model: Option<&'a Params>,
        friction: Option<&'a Friction>,
    ) -> SurfaceRecord<'a> {
        let options = surface.options();
        let stats = surface.stats();
        let mut warnings = Warnings::new();
        warnings.extend(stats.warnings.iter().cloned());
        SurfaceRecord {
            files,
            metadata: surface.parts().iter().map(|(t, _)| t.metadata()).collect(),
            detrend: options.detrend,
            derivative: options.derivative,
            surface: stats,
            parts: (surface.parts().len() > 1).then(|| surface.parts().iter().map(|(_, s)| s).collect()),
            model,
            friction: friction.map(|friction| {
                Frictions::One(FrictionRecord {
                    friction,
                    sensitivity: None,
                })
            }),
            warnings,
        }
    }

    /// The record with the friction of `frictions`: none for none, one
    /// record for one load unless `range` (loads given as a range are a
    /// list, even of one).
    pub fn with_frictions(self, frictions: &'a [Friction], range: bool) -> SurfaceRecord<'a> {
        self.with_sensitivity(frictions, &[], range)
    }

    /// The record with the friction of `frictions` (as
    /// [`with_frictions`](Self::with_frictions)), each with its
    /// `sensitivity` (in the same order; none where the list is shorter).
    pub fn with_sensitivity(
        mut self,
        frictions: &'a [Friction],
        sensitivity: &'a [Sensitivity],
        range: bool,
    ) -> SurfaceRecord<'a> {
        let mut records = frictions.iter().enumerate().map(|(k, friction)| FrictionRecord {
            friction,
            sensitivity: sensitivity.get(k),
        });
        self.friction = match frictions.len() {
            0 => None,
            1 if !range => records.next().map(Frictions::One),
            _ => Some(Frictions::Many(records.collect())),
        };
        self
    }

    /// The record with `warnings` (which include the statistics' own) in
    /// place of the statistics' alone.
    pub fn with_warnings(mut self, warnings: &Warnings) -> SurfaceRecord<'a> {
        self.warnings = warnings.clone();
        self
    }
}
