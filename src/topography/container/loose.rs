//! Loose files as the measurements of one surface: the same
//! [`ContainerSurface`] a container of these files would give, each file
//! read by the same code as a container's member ([`super`]'s `Spec`),
//! its settings those of a `meta.yml` entry (`unit`, `size`,
//! `height_scale`, `detrend_mode`, `is_periodic`, `data_source`, `name`)
//! and its instrument's `tip_radius` or `resolution` (metres).
//!
//! Two conventions differ from a container's member, so that a file reads
//! as it does alone: a `.npy` map is rows = y (a container's is indexed
//! `[x, y]`), and a file without `unit` or `detrend_mode` takes
//! [`LooseOptions`]'s (metres and the least-squares plane, as `kefric
//! surface FILE`) where a container's would be unscaled and not detrended.
//! An `x z` text profile is read as SurfaceTopography reads it (uniform if
//! its steps agree to 10⁻⁶ of the unit, else a nonuniform line scan).

use std::path::{Path, PathBuf};

use super::yaml::Node;
use super::{ContainerError, ContainerOptions, ContainerSurface, Cx, DetrendMode, Failure, Spec, MAX_MEASUREMENTS};
use crate::topography::ReadError;
use crate::LengthUnit;

/// The settings a loose measurement may carry (`FILE@KEY=VALUE,...`): a
/// container `meta.yml` entry's fields, and the instrument's reliability
/// parameters in metres.
pub const LOOSE_KEYS: [&str; 9] = [
    "name",
    "unit",
    "size",
    "height_scale",
    "detrend_mode",
    "is_periodic",
    "data_source",
    "tip_radius",
    "resolution",
];

/// One loose file and its settings.
#[derive(Debug, Clone, PartialEq)]
pub struct LooseMeasurement {
    /// The data file.
    pub path: PathBuf,
    /// Its settings: keys of [`LOOSE_KEYS`] (each at most once) and their
    /// values as text: `unit=nm`, `size=100` (a profile) or `size=100x80`
    /// (a map; in `unit`, for a file that gives no size), `height_scale=0.5`,
    /// `detrend_mode=center|height|curvature`, `is_periodic=true`,
    /// `data_source=1` (the channel's index), `tip_radius=2e-8` or
    /// `resolution=1e-6` (metres), `name=...`.
    pub settings: Vec<(String, String)>,
}

impl std::str::FromStr for LooseMeasurement {
    type Err = String;

    /// `FILE` or `FILE@KEY=VALUE,KEY=VALUE...`: the settings follow the
    /// last `@` when what follows it holds a `=` (a file name with an `@`
    /// and no settings reads as it is). Values hold no comma.
    fn from_str(text: &str) -> Result<LooseMeasurement, String> {
        let (file, settings) = match text.rsplit_once('@') {
            Some((file, rest)) if rest.contains('=') => (file, Some(rest)),
            _ => (text, None),
        };
        if file.is_empty() {
            return Err(format!("{text:?}: no file name before the settings"));
        }
        let mut out = Vec::new();
        for pair in settings.into_iter().flat_map(|s| s.split(',')) {
            let Some((key, value)) = pair.split_once('=') else {
                return Err(format!(
                    "{file}: setting {pair:?} is not KEY=VALUE (keys: {})",
                    LOOSE_KEYS.join(", ")
                ));
            };
            let key = key.trim();
            if !LOOSE_KEYS.contains(&key) {
                return Err(format!(
                    "{file}: unknown setting {key:?}: one of {}",
                    LOOSE_KEYS.join(", ")
                ));
            }
            if out.iter().any(|(k, _): &(String, String)| k == key) {
                return Err(format!("{file}: setting {key} given twice"));
            }
            out.push((key.to_string(), value.trim().to_string()));
        }
        Ok(LooseMeasurement {
            path: PathBuf::from(file),
            settings: out,
        })
    }
}

/// What [`read_loose`] needs beyond the files.
#[derive(Debug, Clone)]
pub struct LooseOptions {
    /// The bounds (each file as a container's member) and the tip radius
    /// or resolution of the files that give none.
    pub container: ContainerOptions,
    /// The unit of the files that give none and have no `unit` setting.
    pub unit: LengthUnit,
    /// The detrending of the files without a `detrend_mode` setting.
    pub detrend: DetrendMode,
}

impl Default for LooseOptions {
    /// Metres, the least-squares plane (line of a profile): a loose file's
    /// defaults.
    fn default() -> LooseOptions {
        LooseOptions {
            container: ContainerOptions::default(),
            unit: LengthUnit::M,
            detrend: DetrendMode::Height,
        }
    }
}

/// Why loose measurements cannot be read. Every message names the file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum LooseError {
    /// No files, or more than [`MAX_MEASUREMENTS`].
    #[error("{0}")]
    Count(String),
    /// A setting is malformed or out of range, or the file's data do not
    /// make a measurement.
    #[error("{file}: {detail}")]
    Measurement {
        /// The file.
        file: String,
        /// What is wrong (naming the setting).
        detail: String,
    },
    /// The file cannot be read (the reader's error, naming it).
    #[error(transparent)]
    Read(ReadError),
}

/// A file that cannot be read is the reader's kind (I/O); the rest are
/// the caller's ([`crate::ErrorKind::Argument`]).
impl crate::Classify for LooseError {
    fn kind(&self) -> crate::ErrorKind {
        match self {
            LooseError::Read(e) => e.kind(),
            _ => crate::ErrorKind::Argument,
        }
    }
}

/// The measurements of one surface from loose files: each file read and
/// levelled as a container's member with the same settings is (see the
/// module docs), in the order given.
pub fn read_loose(measurements: &[LooseMeasurement], options: &LooseOptions) -> Result<ContainerSurface, LooseError> {
    if measurements.is_empty() {
        return Err(LooseError::Count("no measurement files".into()));
    }
    if measurements.len() > MAX_MEASUREMENTS {
        return Err(LooseError::Count(format!(
            "{} measurement files, over the limit of {MAX_MEASUREMENTS}",
            measurements.len()
        )));
    }
    let mut out = Vec::with_capacity(measurements.len());
    for (i, m) in measurements.iter().enumerate() {
        out.push(read_one(m, i, options)?);
    }
    Ok(ContainerSurface {
        name: None,
        measurements: out,
    })
}

fn read_one(m: &LooseMeasurement, i: usize, options: &LooseOptions) -> Result<super::Measurement, LooseError> {
    let file = m.path.display().to_string();
    let bad = |detail: String| LooseError::Measurement {
        file: file.clone(),
        detail,
    };
    let entry = entry(m, options).map_err(&bad)?;
    let spec = Spec::parse(&entry, &options.container).map_err(&bad)?;
    let bytes = read_bounded(&m.path, options.container.read.max_bytes).map_err(LooseError::Read)?;
    let cx = Cx { name: &file };
    spec.measurement_of_bytes(
        &bytes,
        &cx,
        &options.container,
        &format!("measurement {}", i + 1),
        false,
    )
    .map_err(|f| match f {
        Failure::Meta(d) => bad(format!("{d}: give it as a setting ({file}@KEY=VALUE)")),
        Failure::Other(ContainerError::Member { source, .. }) => LooseError::Read(source),
        Failure::Other(ContainerError::Archive { detail, .. }) => bad(detail),
        Failure::Other(e) => bad(e.to_string()),
    })
}

/// The `meta.yml` entry of a loose measurement: its settings, the
/// defaults of `options` where it has none.
fn entry(m: &LooseMeasurement, options: &LooseOptions) -> Result<Node, String> {
    let plain = |v: &str| Node::Scalar(v.to_string(), true);
    let quoted = |v: &str| Node::Scalar(v.to_string(), false);
    let get = |key: &str| m.settings.iter().find(|(k, _)| k == key).map(|(_, v)| v.as_str());
    let mut map = vec![("datafile".to_string(), quoted(&m.path.display().to_string()))];
    let name = get("name").map(str::to_string).unwrap_or_else(|| {
        m.path
            .file_name()
            .map_or_else(|| m.path.display().to_string(), |n| n.to_string_lossy().into_owned())
    });
    map.push(("name".into(), quoted(&name)));
    map.push((
        "unit".into(),
        quoted(get("unit").unwrap_or_else(|| options.unit.name())),
    ));
    if let Some(size) = get("size") {
        map.push(("size".into(), Node::Seq(size.split('x').map(plain).collect())));
    }
    let detrend = match options.detrend {
        DetrendMode::None => None,
        DetrendMode::Center => Some("center"),
        DetrendMode::Height => Some("height"),
        DetrendMode::Curvature => Some("curvature"),
    };
    if let Some(mode) = get("detrend_mode").or(detrend) {
        map.push(("detrend_mode".into(), quoted(mode)));
    }
    for key in ["height_scale", "is_periodic", "data_source"] {
        if let Some(v) = get(key) {
            map.push((key.into(), plain(v)));
        }
    }
    let mut parameters = Vec::new();
    for key in ["tip_radius", "resolution"] {
        if let Some(v) = get(key) {
            let metres: f64 = v
                .parse()
                .map_err(|_| format!("{key} = {v:?} is not a number (metres)"))?;
            if !(metres.is_finite() && metres > 0.0) {
                return Err(format!("{key} = {v} is out of range: must be > 0 and finite (metres)"));
            }
            parameters.push((
                key.to_string(),
                Node::Map(vec![("value".into(), plain(v)), ("unit".into(), quoted("m"))]),
            ));
        }
    }
    if parameters.len() == 2 {
        return Err("tip_radius and resolution: give one".into());
    }
    if !parameters.is_empty() {
        map.push((
            "instrument".into(),
            Node::Map(vec![("parameters".into(), Node::Map(parameters))]),
        ));
    }
    Ok(Node::Map(map))
}

/// The file's bytes, at most `limit` of them, a regular file only.
fn read_bounded(path: &Path, limit: u64) -> Result<Vec<u8>, ReadError> {
    use std::io::Read;
    let io = |source| ReadError::Io {
        path: path.to_path_buf(),
        source,
    };
    // Checked before it is opened (opening a pipe waits for a writer),
    // and again once open.
    let regular = |m: &std::fs::Metadata| {
        if m.is_file() {
            Ok(())
        } else {
            Err(io(std::io::Error::other("not a regular file: only files are read")))
        }
    };
    regular(&std::fs::metadata(path).map_err(io)?)?;
    let file = std::fs::File::open(path).map_err(io)?;
    let metadata = file.metadata().map_err(io)?;
    regular(&metadata)?;
    if metadata.len() > limit {
        return Err(ReadError::TooLarge {
            path: path.to_path_buf(),
            what: "the file".into(),
            bytes: metadata.len(),
            limit,
        });
    }
    let mut bytes = Vec::with_capacity(metadata.len() as usize);
    file.take(limit + 1).read_to_end(&mut bytes).map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(ReadError::TooLarge {
            path: path.to_path_buf(),
            what: "the file".into(),
            bytes: bytes.len() as u64,
            limit,
        });
    }
    Ok(bytes)
}
