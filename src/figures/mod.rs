//! The paper's figures 3–6, a μ(F*) curve for any parameters, and a
//! table's error map, drawn with plotters to PNG or SVG (chosen by the
//! file's extension).
//!
//! Each figure is first computed as data ([`Page`], [`ErrorMap`]: the
//! types of `chart.rs`), by `paper.rs` (the paper's figures) or
//! `compare.rs` (a table against direct integration) or `distributions.rs`
//! (non-Gaussian heights, not one of the paper's), then drawn by
//! `render.rs` ([`Page::save`], [`ErrorMap::save`]), the only part that
//! knows plotters.
//!
//! Curves follow the paper's range (its section "Results"): [`H_SAMPLES`]
//! separations equally spaced over 0 ≤ h* ≤ 3, keeping the loads
//! 0 < F* ≤ 0.1; where F*(h* = 0) > 0.1 the curve is closed exactly at
//! F* = 0.1 ([`paper_sweep`]).
//!
//! ```no_run
//! use ke_friction::figures::Figure;
//! Figure::Fig5.page()?.save("fig5.png".as_ref())?;
//! # Ok::<(), ke_friction::figures::FigureError>(())
//! ```

mod chart;
mod compare;
#[cfg(feature = "topography")]
mod container;
mod distributions;
mod paper;
mod render;
mod surface;

pub use chart::{Chart, ChartAxis, Corner, ErrorMap, LineStyle, Markers, Page, Series, Shape, BLACK_INDEX, PALETTE};
pub use compare::{curve_page, table_error};
#[cfg(feature = "topography")]
pub use container::{container_psd_page, container_scan_page, DRAWN_PER_DECADE};
pub use distributions::{
    distribution_set, distributions_page, DENSITY_X, DENSITY_Y, DISTRIBUTIONS_F_STAR, DISTRIBUTIONS_LOADS,
    DISTRIBUTION_SET,
};
pub use paper::paper_sweep;
#[cfg(feature = "topography")]
pub use surface::psd_page;
pub use surface::{scan_page, surface_page, LoadAxis, ScanPoint, SURFACE_BINS};

use crate::build::BuildError;
use crate::{EvalError, LookupError, ParamError};
use std::path::{Path, PathBuf};

/// Width and height of an image at scale 1, in pixels: the size every
/// length (fonts, lines, markers, margins) is designed for.
pub const BASE_SIZE: (u32, u32) = (1000, 750);
/// The scale [`Page::save`] and [`ErrorMap::save`] draw at.
pub const DEFAULT_SCALE: u32 = 2;
/// The largest scale: 3000 × 2250 pixels.
pub const MAX_SCALE: u32 = 3;
/// The scales an image may be drawn at: 1 to [`MAX_SCALE`] (its size
/// [`BASE_SIZE`] times the scale).
pub static SCALE: crate::bound::Bound = crate::bound::Bound::whole(1, MAX_SCALE as usize);
/// Width and height of an image at the default scale, in pixels:
/// [`BASE_SIZE`] × [`DEFAULT_SCALE`], 2000 × 1500.
pub const SIZE: (u32, u32) = (BASE_SIZE.0 * DEFAULT_SCALE, BASE_SIZE.1 * DEFAULT_SCALE);

/// The pixel size of an image at `scale` (1 to [`MAX_SCALE`]): every
/// length of [`BASE_SIZE`]'s design times `scale`, so fonts, lines and
/// markers grow with the canvas.
pub fn size_at(scale: u32) -> Result<(u32, u32), FigureError> {
    if SCALE.contains(f64::from(scale)) {
        Ok((BASE_SIZE.0 * scale, BASE_SIZE.1 * scale))
    } else {
        Err(FigureError::Scale { scale })
    }
}
/// Separations sampled per curve over 0 ≤ h* ≤ 3.
pub const H_SAMPLES: usize = 200;
/// θ of the paper's figures 3–5.
pub const PAPER_THETA: f64 = 0.003;

/// A figure that cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum FigureError {
    /// The output file's extension is neither `.png` nor `.svg`.
    #[error("{path}: unknown image format {ext:?}: the name must end in .png or .svg")]
    Format {
        /// The output path.
        path: String,
        /// Its extension (empty if none).
        ext: String,
    },
    /// Invalid model parameters.
    #[error(transparent)]
    Params(#[from] ParamError),
    /// An evaluation failed.
    #[error(transparent)]
    Eval(#[from] EvalError),
    /// A query outside the table's domain.
    #[error(transparent)]
    Lookup(#[from] LookupError),
    /// The table was built for other model constants than those asked for.
    #[error("the table holds {table}, not {asked}")]
    TableMismatch {
        /// The table's constants.
        table: String,
        /// The requested ones.
        asked: String,
    },
    /// Nothing to draw: no load in the plotted range.
    #[error("nothing to draw: {0}")]
    Empty(String),
    /// Direct integration at a point of the table failed.
    #[error(transparent)]
    Direct(#[from] BuildError),
    /// The scale is not one of [`SCALE`].
    #[error("scale = {scale} is out of range: must be {} ({} × {} pixels times the scale)", SCALE.range(), BASE_SIZE.0, BASE_SIZE.1)]
    Scale {
        /// The scale asked for.
        scale: u32,
    },
    /// The drawing or the writing of the file failed.
    #[error("cannot draw {path}: {message}")]
    Draw {
        /// The output path.
        path: String,
        /// What went wrong.
        message: String,
    },
}

/// An image format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// PNG bitmap.
    Png,
    /// SVG vector graphics.
    Svg,
}

impl Format {
    /// The format named by `path`'s extension (`.png` or `.svg`, any case).
    pub fn from_path(path: &Path) -> Result<Format, FigureError> {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase())
            .unwrap_or_default();
        match ext.as_str() {
            "png" => Ok(Format::Png),
            "svg" => Ok(Format::Svg),
            _ => Err(FigureError::Format {
                path: path.display().to_string(),
                ext,
            }),
        }
    }
}

/// The paper's figures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Figure {
    /// Fs*/P* against F* for ψ = 0.5, 1, 2, 4, 8 at θ = 0.003.
    Fig3,
    /// Q* against F* (log–log), same ψ and θ.
    Fig4,
    /// μ against F* for ψ = 0.5, 1, 2 at θ = 0.003, with the CEB-type model.
    Fig5,
    /// μ against F* for ψ = 0.5 and 2 at θ = 1e-4, 1e-3, 3e-3.
    Fig6,
}

impl Figure {
    /// All four, in order.
    pub const ALL: [Figure; 4] = [Figure::Fig3, Figure::Fig4, Figure::Fig5, Figure::Fig6];

    /// `fig3` … `fig6`.
    pub fn name(self) -> &'static str {
        match self {
            Figure::Fig3 => "fig3",
            Figure::Fig4 => "fig4",
            Figure::Fig5 => "fig5",
            Figure::Fig6 => "fig6",
        }
    }

    /// The figure as data.
    pub fn page(self) -> Result<Page, FigureError> {
        Ok(match self {
            Figure::Fig3 => Page::single(paper::fig3()?),
            Figure::Fig4 => Page::single(paper::fig4()?),
            Figure::Fig5 => paper::fig5()?,
            Figure::Fig6 => Page::single(paper::fig6()?),
        })
    }
}

/// Writes fig3.png … fig6.png into `dir` (which must exist) at `scale`
/// (see [`size_at`]); returns the paths written.
pub fn save_all(dir: &Path, scale: u32) -> Result<Vec<PathBuf>, FigureError> {
    size_at(scale)?;
    let mut out = Vec::new();
    for fig in Figure::ALL {
        let path = dir.join(format!("{}.png", fig.name()));
        fig.page()?.save_scaled(&path, scale)?;
        out.push(path);
    }
    Ok(out)
}

impl crate::Classify for FigureError {
    /// By cause (`Io` for a figure that cannot be written).
    fn kind(&self) -> crate::ErrorKind {
        use FigureError::*;
        match self {
            Format { .. } | Scale { .. } | Empty(_) | TableMismatch { .. } => crate::ErrorKind::Argument,
            Params(e) => e.kind(),
            Eval(e) => e.kind(),
            Lookup(e) => e.kind(),
            Direct(e) => e.kind(),
            Draw { .. } => crate::ErrorKind::Io,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn format_follows_the_extension() {
        assert_eq!(Format::from_path("a.PNG".as_ref()), Ok(Format::Png));
        assert_eq!(Format::from_path("a/b.svg".as_ref()), Ok(Format::Svg));
        assert!(Format::from_path("a.jpg".as_ref()).is_err());
        assert!(Format::from_path("a".as_ref()).is_err());
    }

    #[test]
    fn sizes_are_the_base_size_times_the_scale() {
        assert_eq!(SIZE, (2000, 1500));
        assert_eq!(size_at(1), Ok((1000, 750)));
        assert_eq!(size_at(3), Ok((3000, 2250)));
        assert_eq!(size_at(0), Err(FigureError::Scale { scale: 0 }));
        assert_eq!(size_at(4), Err(FigureError::Scale { scale: 4 }));
    }
}
