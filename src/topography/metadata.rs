//! What a file says about its measurement, beside the heights.

use serde::Serialize;

/// What a surface file says about its measurement: shown to the user (the
/// `--json` record's `metadata`), never used in a computation. Each field
/// is `None` (or empty) when the file does not say.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
#[non_exhaustive]
pub struct Metadata {
    /// The file's format ([`Format::name`](super::Format::name)).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub format: Option<&'static str>,
    /// The instrument (maker, model, as the file gives it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub instrument: Option<String>,
    /// When the measurement was made, as the file gives it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub date: Option<String>,
    /// The channel read, for files with several (AFM: height, amplitude,
    /// phase, ...).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub channel: Option<String>,
    /// Every channel of the file, in its order (empty for single-channel
    /// formats).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub channels: Vec<String>,
    /// The unit the file stores heights in (the heights here are metres).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub height_unit: Option<String>,
}

impl Metadata {
    /// Whether the file said nothing.
    pub fn is_empty(&self) -> bool {
        *self == Metadata::default()
    }
}
