//! contact.engineering containers ("digital surface twins"): a zip of the
//! data files of several measurements of one surface and `meta.yml` (or
//! `index.json`) listing them, as SurfaceTopography's
//! `Container.IO.read_container` reads them; the combined power spectrum
//! of the measurements ([`combined_psd`], SurfaceTopography's container
//! `power_spectrum`) and the spectral moments of a band of it
//! ([`spectral_moments`], MODEL.md's multi-measurement section).
//!
//! Each measurement is read as SurfaceTopography reads it: its data file
//! through the readers of [`super::read_bytes`] (same bounds), the unit
//! and size of `meta.yml` where the file gives none (a size the file
//! gives wins, as there), the heights multiplied by `height_scale`, then
//! detrended by `detrend_mode`. Two conventions of SurfaceTopography's
//! that differ from a loose file's: a `.npy` map is indexed `[x, y]`
//! (transposed here), and an `x z` text profile whose x are not evenly
//! spaced (to 10⁻⁶ of the file's unit) is a *nonuniform* line scan
//! ([`Heights::Nonuniform`]), interpolated onto a uniform grid for its
//! spectrum. A measurement with only a `squeezed-netcdf` file (what
//! SurfaceTopography's `write_containers` writes) is read from that
//! NetCDF-3 file (`netcdf.rs`) with its own unit, sizes and instrument
//! parameters, its height scale and detrending already applied. Lengths
//! are metres throughout.
//!
//! Untrusted input: the archive is bounded like an X3P
//! ([`ReadOptions::max_bytes`] for the archive and for each member once
//! inflated, whatever its header says), `meta.yml` to [`META_MAX_BYTES`]
//! and 64 levels of nesting (no aliases), at most
//! [`MAX_MEASUREMENTS`] measurements.

mod analysis;
mod heights;
mod loose;
mod netcdf;
mod record;
mod scale_dependent;
mod spectrum;
mod squeezed;
mod yaml;

pub use analysis::{
    container_analysis, container_scan, measurement_spectra, AnalysisError, Band, ContainerAnalysis, Resolved, ScanRow,
};

pub use loose::{read_loose, LooseError, LooseMeasurement, LooseOptions, LOOSE_KEYS};
pub use record::{
    is_container_bytes, CombinedRecord, ContainerRecord, MeasurementRecord, Reliable, ScanRecord, SpreadRecord,
};
pub use scale_dependent::{
    combine_scale_dependent, combined_scale_dependent, measurement_scale_dependent, measurement_scales, CombinedScale,
    MeasurementScale,
};

pub use spectrum::{
    combined_psd, measurement_psd, roughness_from_moments, spectral_moments, CombinedPsd, MeasurementPsd, Moments,
    Roughness, COMBINED_POINTS_PER_DECADE,
};

use std::io::{Cursor, Read, Seek};
use std::path::Path;

use super::read::{read_bytes, Format, ReadError, ReadOptions};
use super::Topography;
use crate::LengthUnit;
use heights::{detrend, scale_heights, transpose, xz_profile};

/// The largest `meta.yml` / `index.json` read (bytes): 1 MiB.
pub const META_MAX_BYTES: u64 = 1 << 20;
/// The most measurements a container may list.
pub const MAX_MEASUREMENTS: usize = 1024;
/// SurfaceTopography's tolerance for an `x z` profile's x to be on a
/// uniform grid (in the file's unit).
const UNIFORM_TOLERANCE: f64 = 1e-6;

/// How a measurement's heights are levelled (`detrend_mode`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DetrendMode {
    /// No `detrend_mode` in the metadata: heights as read.
    None,
    /// `center` (or `mean`): the mean height removed.
    Center,
    /// `height` (or `rms-tilt`): the least-squares line (profile) or
    /// plane (map) removed.
    Height,
    /// `curvature` (or `rms-curvature`): the least-squares parabola
    /// (profile) or quadric (map) removed.
    Curvature,
}

/// A measurement's heights.
#[derive(Debug, Clone)]
pub enum Heights {
    /// On a uniform grid (a map or a profile).
    Uniform(Topography),
    /// A nonuniform line scan: positions from 0, increasing, and heights
    /// (metres).
    Nonuniform {
        /// Positions (metres), from 0, strictly increasing.
        x: Vec<f64>,
        /// Heights (metres).
        z: Vec<f64>,
    },
}

/// One measurement of a container, read and detrended.
#[derive(Debug, Clone)]
pub struct Measurement {
    /// Its name in the metadata (else its data file's).
    pub name: String,
    /// The data file in the archive.
    pub data_file: String,
    /// The unit of the metadata (`nm`, `µm`, ...), if given.
    pub unit: Option<String>,
    /// The height scale applied (1 if none given).
    pub height_scale: f64,
    /// The detrending applied.
    pub detrend: DetrendMode,
    /// Whether the metadata says it is periodic.
    pub is_periodic: bool,
    /// The measurement date, as the metadata gives it.
    pub measurement_date: Option<String>,
    /// The instrument's tip radius (metres), from the metadata.
    pub tip_radius: Option<f64>,
    /// The instrument's lateral resolution (metres), from the metadata.
    pub resolution: Option<f64>,
    /// The heights (metres).
    pub heights: Heights,
}

impl Measurement {
    /// Points along x and y (a profile has ny = 1).
    pub fn grid(&self) -> (usize, usize) {
        match &self.heights {
            Heights::Uniform(t) => (t.nx(), t.ny()),
            Heights::Nonuniform { x, .. } => (x.len(), 1),
        }
    }

    /// The physical size along x (and y of a map), metres.
    pub fn size(&self) -> (f64, Option<f64>) {
        match &self.heights {
            Heights::Uniform(t) => (t.nx() as f64 * t.dx(), t.dy().map(|dy| t.ny() as f64 * dy)),
            Heights::Nonuniform { x, .. } => (x[x.len() - 1] - x[0], None),
        }
    }
}

/// One surface of a container: its measurements.
#[derive(Debug, Clone)]
pub struct ContainerSurface {
    /// The surface's name or description, if the metadata gives one.
    pub name: Option<String>,
    /// Its measurements, in the metadata's order.
    pub measurements: Vec<Measurement>,
}

/// What [`read_container`] needs beyond the archive.
#[derive(Debug, Clone, Default)]
pub struct ContainerOptions {
    /// The bounds for the archive, each member and each surface
    /// ([`ReadOptions::max_bytes`], [`ReadOptions::max_points`]); its
    /// intervals, units, format and channel are not used.
    pub read: ReadOptions,
    /// A tip radius (metres) for the measurements whose metadata gives no
    /// instrument parameters.
    pub tip_radius: Option<f64>,
    /// A lateral resolution (metres) for the measurements whose metadata
    /// gives no instrument parameters.
    pub resolution: Option<f64>,
}

/// Why a container cannot be read. Every message names the container,
/// and the member or metadata field at fault.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ContainerError {
    /// The container cannot be opened or read.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The container.
        path: String,
        /// The failure.
        source: std::io::Error,
    },
    /// Not a readable zip archive, or a member is damaged, missing or too
    /// large.
    #[error("{path}: {detail}")]
    Archive {
        /// The container.
        path: String,
        /// What is wrong.
        detail: String,
    },
    /// The metadata is malformed or a field is missing or out of range.
    #[error("{path}: {file}: {detail}")]
    Meta {
        /// The container.
        path: String,
        /// `meta.yml` or `index.json`.
        file: &'static str,
        /// What is wrong (naming the field).
        detail: String,
    },
    /// A data file cannot be read.
    #[error("{path}: {source}")]
    Member {
        /// The container.
        path: String,
        /// The reader's error (naming the member).
        source: ReadError,
    },
}

/// Bad metadata or data is the caller's ([`crate::ErrorKind::Argument`]);
/// a container that cannot be read at all is [`crate::ErrorKind::Io`].
impl crate::Classify for ContainerError {
    fn kind(&self) -> crate::ErrorKind {
        match self {
            ContainerError::Io { .. } => crate::ErrorKind::Io,
            ContainerError::Member { source, .. } => source.kind(),
            _ => crate::ErrorKind::Argument,
        }
    }
}

/// Whether `bytes` (a file's first bytes, or all of it) are a zip
/// archive: a container is one with `meta.yml` or `index.json`, which
/// [`read_container_bytes`] checks.
pub fn looks_like_zip(bytes: &[u8]) -> bool {
    bytes.starts_with(b"PK\x03\x04")
}

/// Whether the file at `path` is a container: a zip archive holding
/// `meta.yml` or `index.json` (only its central directory is read). An
/// X3P, also a zip, is not one.
pub fn is_container_file(path: &Path) -> bool {
    let Ok(mut file) = std::fs::File::open(path) else {
        return false;
    };
    let mut head = [0u8; 4];
    if file.read_exact(&mut head).is_err() || !looks_like_zip(&head) {
        return false;
    }
    match zip::ZipArchive::new(std::io::BufReader::new(file)) {
        Ok(zip) => zip.index_for_name("meta.yml").is_some() || zip.index_for_name("index.json").is_some(),
        Err(_) => false,
    }
}

/// Reads the container at `path` (see the module docs).
pub fn read_container(path: &Path, options: &ContainerOptions) -> Result<Vec<ContainerSurface>, ContainerError> {
    let name = path.display().to_string();
    let io = |source| ContainerError::Io {
        path: name.clone(),
        source,
    };
    let len = std::fs::metadata(path).map_err(io)?.len();
    if len > options.read.max_bytes {
        return Err(ContainerError::Archive {
            path: name,
            detail: format!(
                "the file is {len} bytes, over the limit of {} bytes",
                options.read.max_bytes
            ),
        });
    }
    let bytes = std::fs::read(path).map_err(io)?;
    read_container_bytes(&bytes, &name, options)
}

/// Reads a container from `bytes`, the content of a file called `name`
/// (for the errors): [`read_container`] for a program that holds the file.
pub fn read_container_bytes(
    bytes: &[u8],
    name: &str,
    options: &ContainerOptions,
) -> Result<Vec<ContainerSurface>, ContainerError> {
    let cx = Cx { name };
    if bytes.len() as u64 > options.read.max_bytes {
        return Err(cx.archive(format!(
            "the file is {} bytes, over the limit of {} bytes",
            bytes.len(),
            options.read.max_bytes
        )));
    }
    let mut zip =
        zip::ZipArchive::new(Cursor::new(bytes)).map_err(|e| cx.archive(format!("not a readable zip archive: {e}")))?;
    let (file, meta) = if zip.index_for_name("index.json").is_some() {
        ("index.json", member(&cx, &mut zip, "index.json", META_MAX_BYTES)?)
    } else if zip.index_for_name("meta.yml").is_some() {
        ("meta.yml", member(&cx, &mut zip, "meta.yml", META_MAX_BYTES)?)
    } else {
        return Err(cx.archive("not a contact.engineering container: neither meta.yml nor index.json in the archive"));
    };
    let meta_err = |detail: String| ContainerError::Meta {
        path: name.to_string(),
        file,
        detail,
    };
    let text = String::from_utf8(meta).map_err(|_| meta_err("not UTF-8".into()))?;
    let root = yaml::parse(&text).map_err(meta_err)?;
    let surfaces = root
        .get("surfaces")
        .and_then(|s| s.items())
        .ok_or_else(|| meta_err("no `surfaces` list".into()))?;
    let count: usize = surfaces
        .iter()
        .map(|s| s.get("topographies").and_then(|t| t.items()).map_or(0, |t| t.len()))
        .sum();
    if count > MAX_MEASUREMENTS {
        return Err(meta_err(format!(
            "{count} measurements, over the limit of {MAX_MEASUREMENTS}"
        )));
    }
    let mut out = Vec::with_capacity(surfaces.len());
    for (s, surface) in surfaces.iter().enumerate() {
        let entries = surface
            .get("topographies")
            .and_then(|t| t.items())
            .ok_or_else(|| meta_err(format!("surfaces[{s}]: no `topographies` list")))?;
        // The entries parsed in turn, their data files read (inflated,
        // parsed, detrended) in parallel with the `parallel` feature, each
        // worker on its own handle of the archive; the first failure in
        // the metadata's order is the one reported.
        let specs: Vec<(String, Result<Spec, String>)> = entries
            .iter()
            .enumerate()
            .map(|(i, entry)| (format!("surfaces[{s}].topographies[{i}]"), Spec::parse(entry, options)))
            .collect();
        let read = each(&specs, |(at, spec)| {
            let spec = spec.as_ref().ok()?;
            Some(spec.read(&cx, &mut zip.clone(), options, at))
        });
        let mut measurements = Vec::with_capacity(entries.len());
        for ((at, spec), read) in specs.iter().zip(read) {
            if let Err(d) = spec {
                return Err(meta_err(format!("{at}.{d}")));
            }
            measurements.push(read.expect("read where parsed").map_err(|e| match e {
                Failure::Meta(d) => meta_err(format!("{at}.{d}")),
                Failure::Other(e) => e,
            })?);
        }
        let name = surface.get("name").and_then(|n| n.text()).map(str::to_string);
        out.push(ContainerSurface { name, measurements });
    }
    Ok(out)
}

/// `f` of each of `items`, in their order: in parallel (rayon) with the
/// `parallel` feature, else in turn.
pub(crate) fn each<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync + Send) -> Vec<R> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        items.par_iter().map(f).collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        items.iter().map(f).collect()
    }
}

/// The container being read, for the errors.
#[derive(Clone, Copy)]
struct Cx<'a> {
    name: &'a str,
}

impl Cx<'_> {
    fn archive(&self, detail: impl Into<String>) -> ContainerError {
        ContainerError::Archive {
            path: self.name.to_string(),
            detail: detail.into(),
        }
    }
}

/// A member's bytes, at most `limit` of them whatever its header declares
/// (a zip bomb is refused once `limit` bytes have been inflated).
fn member<R: Read + Seek>(
    cx: &Cx,
    zip: &mut zip::ZipArchive<R>,
    name: &str,
    limit: u64,
) -> Result<Vec<u8>, ContainerError> {
    let file = zip
        .by_name(name)
        .map_err(|e| cx.archive(format!("member {name}: {e}")))?;
    let declared = file.size();
    if declared > limit {
        return Err(cx.archive(format!(
            "member {name} is {declared} bytes once inflated, over the limit of {limit} bytes"
        )));
    }
    // The header's size is not trusted for the allocation either.
    let mut bytes = Vec::with_capacity(declared.min(1 << 24) as usize);
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| cx.archive(format!("member {name}: {e}")))?;
    if bytes.len() as u64 > limit {
        return Err(cx.archive(format!(
            "member {name} inflates to more than {limit} bytes (its header says {declared})"
        )));
    }
    Ok(bytes)
}

/// A measurement's entry in the metadata.
struct Spec {
    name: Option<String>,
    data_file: String,
    unit: Option<(String, f64)>,
    size: Option<Vec<f64>>,
    height_scale: f64,
    detrend: DetrendMode,
    is_periodic: bool,
    measurement_date: Option<String>,
    tip_radius: Option<f64>,
    resolution: Option<f64>,
    data_source: usize,
    /// The data file is a `squeezed-netcdf` (pipeline already applied).
    squeezed: bool,
    /// The metadata gives the instrument's parameters (else the options',
    /// or a NetCDF file's own `info`).
    instrument_given: bool,
}

/// A failure reading a measurement: of its metadata (the field's path
/// and what is wrong), or else.
enum Failure {
    Meta(String),
    Other(ContainerError),
}

impl From<ContainerError> for Failure {
    fn from(e: ContainerError) -> Failure {
        Failure::Other(e)
    }
}

/// A length unit's metres (`nm` → 1e-9), or the error naming `field`.
fn unit_metres(field: &str, unit: &str) -> Result<f64, String> {
    LengthUnit::from_symbol(unit)
        .map(|u| u.metres())
        .map_err(|_| format!("{field} = {unit:?} is not a length unit (m, mm, um/µm, nm, pm, angstrom, ...)"))
}

/// A `{value, unit}` instrument parameter in metres.
fn parameter(node: &yaml::Node, field: &str, unit: Option<f64>) -> Result<f64, String> {
    let value = node
        .get("value")
        .and_then(|v| v.number().or_else(|| v.text().and_then(|t| t.trim().parse().ok())))
        .ok_or_else(|| format!("{field}.value: missing or not a number"))?;
    let metres = match node.get("unit").and_then(|u| u.text()) {
        Some(u) => unit_metres(&format!("{field}.unit"), u)?,
        None => unit.ok_or_else(|| format!("{field}.unit: missing"))?,
    };
    let v = value * metres;
    if !(v.is_finite() && v > 0.0) {
        return Err(format!(
            "{field}.value = {value} is out of range: must be > 0 and finite"
        ));
    }
    Ok(v)
}

impl Spec {
    fn parse(entry: &yaml::Node, options: &ContainerOptions) -> Result<Spec, String> {
        let datafile = entry.get("datafile").ok_or("datafile: missing")?;
        let (data_file, squeezed) = match datafile {
            yaml::Node::Map(_) => match datafile.get("original").and_then(|n| n.text()) {
                Some(f) => (f.to_string(), false),
                None => match datafile.get("squeezed-netcdf").and_then(|n| n.text()) {
                    // Its heights as the pipeline left them: no height
                    // scale and no detrending applied again.
                    Some(f) => (f.to_string(), true),
                    None => return Err("datafile: neither `original` nor `squeezed-netcdf`".into()),
                },
            },
            _ => (datafile.text().ok_or("datafile: not a file name")?.to_string(), false),
        };
        let unit = match entry.get("unit").and_then(|u| u.text()) {
            Some(u) => Some((u.to_string(), unit_metres("unit", u)?)),
            None => None,
        };
        let size = match entry.get("size").filter(|s| !s.is_null()) {
            None => None,
            Some(node) => {
                let values: Option<Vec<f64>> = match node.items() {
                    Some(items) => items.iter().map(|v| v.number()).collect(),
                    None => node.number().map(|v| vec![v]),
                };
                let values = values.ok_or("size: not a list of numbers")?;
                if values.is_empty() || values.len() > 2 {
                    return Err(format!(
                        "size: {} values; 1 (profile) or 2 (map) expected",
                        values.len()
                    ));
                }
                if let Some(bad) = values.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
                    return Err(format!("size = {bad} is out of range: must be > 0 and finite"));
                }
                Some(values)
            }
        };
        let height_scale = match entry.get("height_scale").filter(|s| !s.is_null()) {
            None => 1.0,
            Some(n) => {
                let v = n.number().ok_or("height_scale: not a number")?;
                if !(v.is_finite() && v != 0.0) {
                    return Err(format!(
                        "height_scale = {v} is out of range: must be finite and non-zero"
                    ));
                }
                v
            }
        };
        let detrend = match entry.get("detrend_mode").and_then(|d| d.text()) {
            None => DetrendMode::None,
            Some("center" | "mean") => DetrendMode::Center,
            Some("height" | "rms-tilt") => DetrendMode::Height,
            Some("curvature" | "rms-curvature") => DetrendMode::Curvature,
            Some(other) => {
                return Err(format!(
                    "detrend_mode = {other:?} is not supported: center, height or curvature"
                ))
            }
        };
        if let Some(mode) = entry.get("fill_undefined_data_mode").and_then(|d| d.text()) {
            if mode != "do-not-fill" {
                return Err(format!(
                    "fill_undefined_data_mode = {mode:?} is not supported: do-not-fill"
                ));
            }
        }
        let is_periodic = match entry.get("is_periodic").filter(|s| !s.is_null()) {
            None => false,
            Some(n) => n.boolean().ok_or("is_periodic: not true or false")?,
        };
        let data_source = match entry.get("data_source").filter(|s| !s.is_null()) {
            None => 0,
            Some(n) => n
                .number()
                .filter(|v| *v >= 0.0 && v.fract() == 0.0 && *v < 1e6)
                .ok_or("data_source: not a channel index (0, 1, ...)")? as usize,
        };
        let parameters = entry.get("instrument").and_then(|i| i.get("parameters"));
        let unit_m = unit.as_ref().map(|u| u.1);
        let tip_radius = match parameters.and_then(|p| p.get("tip_radius")) {
            Some(n) => Some(parameter(n, "instrument.parameters.tip_radius", unit_m)?),
            None => None,
        };
        let resolution = match parameters.and_then(|p| p.get("resolution")) {
            Some(n) if tip_radius.is_none() => Some(parameter(n, "instrument.parameters.resolution", unit_m)?),
            _ => None,
        };
        let instrument_given = tip_radius.is_some() || resolution.is_some();
        let (tip_radius, resolution) = if !instrument_given {
            (
                options.tip_radius,
                if options.tip_radius.is_none() {
                    options.resolution
                } else {
                    None
                },
            )
        } else {
            (tip_radius, resolution)
        };
        Ok(Spec {
            name: entry.get("name").and_then(|n| n.text()).map(str::to_string),
            data_file,
            unit,
            size,
            height_scale,
            detrend,
            is_periodic,
            measurement_date: entry.get("measurement_date").and_then(|n| n.text()).map(str::to_string),
            tip_radius,
            resolution,
            data_source,
            squeezed,
            instrument_given,
        })
    }

    fn read<R: Read + Seek>(
        &self,
        cx: &Cx,
        zip: &mut zip::ZipArchive<R>,
        options: &ContainerOptions,
        at: &str,
    ) -> Result<Measurement, Failure> {
        if zip.index_for_name(&self.data_file).is_none() {
            return Err(Failure::Other(cx.archive(format!(
                "{at}: its data file {} is not in the archive",
                self.data_file
            ))));
        }
        let bytes = member(cx, zip, &self.data_file, options.read.max_bytes)?;
        self.measurement_of_bytes(&bytes, cx, options, at, true)
    }

    /// The measurement from its data file's `bytes` (a container's member,
    /// or a loose file: `xy_npy` false, a `.npy` map then read as a loose
    /// file is, rows = y).
    fn measurement_of_bytes(
        &self,
        bytes: &[u8],
        cx: &Cx,
        options: &ContainerOptions,
        at: &str,
        xy_npy: bool,
    ) -> Result<Measurement, Failure> {
        if self.squeezed || bytes.starts_with(b"CDF") {
            return self.read_netcdf(bytes, cx, options, at);
        }
        let member_err = |source| {
            Failure::Other(ContainerError::Member {
                path: cx.name.to_string(),
                source,
            })
        };
        let unit = self.unit.as_ref().map(|u| u.1);
        let head = &bytes[..bytes.len().min(64)];
        let format = Format::detect(Path::new(&self.data_file), head);
        let base = ReadOptions {
            max_bytes: options.read.max_bytes,
            max_points: options.read.max_points,
            z_unit: unit.unwrap_or(1.0),
            xy_unit: unit.unwrap_or(1.0),
            channel: (self.data_source > 0).then_some(super::Channel::Index(self.data_source)),
            ..ReadOptions::default()
        };
        let mut heights = if format == Format::TEXT {
            // As a matrix first: an `x z` profile is read in
            // SurfaceTopography's XYZ convention (nonuniform when its x
            // are not evenly spaced).
            let matrix = ReadOptions {
                format: Some(Format::MATRIX),
                dx: Some(1.0),
                dy: Some(1.0),
                z_unit: 1.0,
                channel: None,
                ..base.clone()
            };
            let m = read_bytes(bytes, &self.data_file, &matrix).map_err(member_err)?;
            if m.nx() == 2 && m.ny() > 1 {
                let unit = unit.ok_or_else(|| Failure::Meta("unit: missing (the data file gives none)".into()))?;
                xz_profile(m.heights(), unit)
                    .map_err(|d| Failure::Other(cx.archive(format!("{at}: data file {}: {d}", self.data_file))))?
            } else {
                Heights::Uniform(self.read_sized(bytes, &base, cx)?)
            }
        } else {
            Heights::Uniform(self.read_sized(bytes, &base, cx)?)
        };
        if format == Format::NPY && xy_npy {
            if let Heights::Uniform(t) = &heights {
                heights = Heights::Uniform(transpose(t));
            }
        }
        Ok(self.measurement(heights, self.is_periodic, self.tip_radius, self.resolution))
    }

    /// The measurement of `heights` as read: the height scale and the
    /// detrending applied unless squeezed.
    fn measurement(
        &self,
        mut heights: Heights,
        is_periodic: bool,
        tip_radius: Option<f64>,
        resolution: Option<f64>,
    ) -> Measurement {
        let (height_scale, detrend_mode) = if self.squeezed {
            (1.0, DetrendMode::None)
        } else {
            (self.height_scale, self.detrend)
        };
        scale_heights(&mut heights, height_scale);
        detrend(&mut heights, detrend_mode);
        Measurement {
            name: self.name.clone().unwrap_or_else(|| self.data_file.clone()),
            data_file: self.data_file.clone(),
            unit: self.unit.as_ref().map(|u| u.0.clone()),
            height_scale,
            detrend: detrend_mode,
            is_periodic,
            measurement_date: self.measurement_date.clone(),
            tip_radius,
            resolution,
            heights,
        }
    }

    /// Reads a file through [`read_bytes`]: with its own intervals, else
    /// with those of the metadata's `size` (in its `unit`).
    fn read_sized(&self, bytes: &[u8], base: &ReadOptions, cx: &Cx) -> Result<Topography, Failure> {
        let member_err = |source| {
            Failure::Other(ContainerError::Member {
                path: cx.name.to_string(),
                source,
            })
        };
        match read_bytes(bytes, &self.data_file, base) {
            Err(ReadError::NeedInterval { .. }) => {}
            read => return read.map_err(member_err),
        }
        let Some(size) = &self.size else {
            return Err(Failure::Meta("size: missing (the data file gives none)".into()));
        };
        let Some((_, unit)) = self.unit else {
            return Err(Failure::Meta("unit: missing (the data file gives none)".into()));
        };
        let unit_options = ReadOptions {
            dx: Some(1.0),
            dy: Some(1.0),
            ..base.clone()
        };
        let t = read_bytes(bytes, &self.data_file, &unit_options).map_err(member_err)?;
        let map = !t.is_profile();
        if map != (size.len() == 2) {
            return Err(Failure::Meta(format!(
                "size: {} values for a {}",
                size.len(),
                if map { "map" } else { "profile" }
            )));
        }
        let metadata = t.metadata().clone();
        let (nx, ny) = (t.nx(), t.ny());
        let dx = size[0] * unit / nx as f64;
        let heights = t.heights().to_vec();
        let t = if map {
            Topography::map(heights, nx, ny, dx, size[1] * unit / ny as f64)
        } else {
            Topography::profile(heights, dx)
        };
        t.map(|t| t.with_metadata(metadata)).map_err(|source| {
            member_err(ReadError::Topography {
                path: self.data_file.clone().into(),
                source,
            })
        })
    }
}
