//! What every front end (`kefric surface CONTAINER --json`, the Python
//! package's `Container`, the web page) says of a container: the
//! records of its measurements, of μ from the whole band and of a scan
//! row, defined once here; and a [`SurfaceRequest`]'s inputs as a
//! container takes them (the reading options, the band, an analysis'
//! failure naming the input to blame).

use std::f64::consts::PI;
use std::io::Cursor;

use super::analysis::warning_records;
use super::{AnalysisError, Band, ContainerAnalysis, ContainerOptions, ContainerSurface, Measurement, MeasurementPsd};
use super::{Heights, Moments, Resolved, Roughness, ScanRow};
use crate::topography::request::materials_needed;
use crate::topography::{evaluate_failure, Field, LambdaS, Message, ReadOptions, RequestError, SurfaceRequest};
use crate::{Classify, ErrorKind, Friction, Load, Materials, Params, Shortest, Warning};

/// Whether `bytes`, a whole file, are a container: a zip archive holding
/// `meta.yml` or `index.json` ([`super::is_container_file`] for a file on
/// disk; an X3P, also a zip, is not one).
pub fn is_container_bytes(bytes: &[u8]) -> bool {
    super::looks_like_zip(bytes)
        && zip::ZipArchive::new(Cursor::new(bytes))
            .is_ok_and(|zip| zip.index_for_name("meta.yml").is_some() || zip.index_for_name("index.json").is_some())
}

/// A measurement's reliable range: its spectrum's smallest nonzero and
/// largest q (rad/m) and the wavelengths 2π/q.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Reliable {
    /// The smallest nonzero wavevector (rad/m).
    pub q_min: Option<f64>,
    /// The largest wavevector (rad/m).
    pub q_max: Option<f64>,
    /// 2π / `q_max` (m).
    pub lambda_min: Option<f64>,
    /// 2π / `q_min` (m).
    pub lambda_max: Option<f64>,
}

/// A measurement's record (`measurements[]` of `kefric surface CONTAINER
/// --json`): its data file, name, unit, instrument, grid (a profile has
/// ny = 1), spacing and size (metres), the reliability cut-off and the
/// reliable range, or why it has no spectrum (`note`).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct MeasurementRecord<'a> {
    /// The data file in the archive.
    pub file: &'a str,
    /// The measurement's name.
    pub name: &'a str,
    /// The unit of the metadata, if given.
    pub unit: Option<&'a str>,
    /// The instrument, as its data file names it.
    pub instrument: Option<&'a str>,
    /// Points along x.
    pub nx: usize,
    /// Points along y (1 for a profile).
    pub ny: usize,
    /// The mean spacing along x (m).
    pub dx: f64,
    /// The size along x and y (m; y `None` for a profile).
    pub size: (f64, Option<f64>),
    /// The tip radius of the metadata or the options (m).
    pub tip_radius: Option<f64>,
    /// The lateral resolution of the metadata or the options (m).
    pub resolution: Option<f64>,
    /// The short reliability cut-off (m), if any.
    pub cutoff: Option<f64>,
    /// The reliable range, `None` without a reliable spectrum.
    pub reliable: Option<Reliable>,
    /// Why there is no reliable spectrum.
    pub note: Option<&'a str>,
}

impl<'a> MeasurementRecord<'a> {
    /// The record of `m` with its reliable spectrum `p`
    /// ([`super::measurement_psd`]).
    pub fn new(m: &'a Measurement, p: &'a MeasurementPsd) -> MeasurementRecord<'a> {
        let (nx, ny) = m.grid();
        let (sx, sy) = m.size();
        let reliable = p.psd.as_ref().map(|p| {
            let (q_min, q_max) = (p.q.get(1).copied(), p.q.last().copied());
            Reliable {
                q_min,
                q_max,
                lambda_min: q_max.map(|q| 2.0 * PI / q),
                lambda_max: q_min.map(|q| 2.0 * PI / q),
            }
        });
        let instrument = match &m.heights {
            Heights::Uniform(t) => t.metadata().instrument.as_deref(),
            Heights::Nonuniform { .. } => None,
        };
        MeasurementRecord {
            file: &m.data_file,
            name: &m.name,
            unit: m.unit.as_deref(),
            instrument,
            nx,
            ny,
            dx: sx / nx as f64,
            size: (sx, sy),
            tip_radius: m.tip_radius,
            resolution: m.resolution,
            cutoff: p.cutoff,
            reliable,
            note: p.reason.as_deref(),
        }
    }

    /// The records of a surface's measurements and their spectra.
    pub fn all(surface: &'a ContainerSurface, spectra: &'a [MeasurementPsd]) -> Vec<MeasurementRecord<'a>> {
        surface
            .measurements
            .iter()
            .zip(spectra)
            .map(|(m, p)| MeasurementRecord::new(m, p))
            .collect()
    }
}

/// The combined spectrum's part of a [`ContainerRecord`].
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct CombinedRecord<'a> {
    /// The band integrated over.
    pub band: Band,
    /// The moments of the combined spectrum over it.
    pub moments: Moments,
    /// The roughness of the moments.
    pub roughness: Roughness,
    /// The measurement whose heights give the height distribution.
    pub heights_from: &'a str,
    /// The measurements whose reliable range overlaps the band.
    pub rests_on: Vec<&'a str>,
}

/// μ from the whole band of a container's surface, as `kefric surface
/// CONTAINER --json` prints it for one surface (its `files` apart): the
/// surface's name, its measurements, the combined spectrum's band,
/// moments and roughness, the model's inputs, the friction at each load
/// and the warnings (`{kind, message}` each).
#[derive(Debug, Clone, serde::Serialize)]
pub struct ContainerRecord<'a> {
    /// The surface's name, if the metadata gives one.
    pub name: Option<&'a str>,
    /// The measurements' records.
    pub measurements: Vec<MeasurementRecord<'a>>,
    /// The combined spectrum over the band.
    pub combined: CombinedRecord<'a>,
    /// The model's inputs.
    pub model: &'a Params,
    /// The friction at each load.
    pub friction: &'a [Friction],
    /// The warnings.
    #[serde(serialize_with = "warning_records")]
    pub warnings: &'a [Warning],
}

/// The measurements' names at `indices`.
fn names<'a>(surface: &'a ContainerSurface, indices: &[usize]) -> Vec<&'a str> {
    indices.iter().map(|&i| surface.measurements[i].name.as_str()).collect()
}

impl<'a> ContainerRecord<'a> {
    /// The record of `analysis` ([`super::container_analysis`]) of
    /// `surface`, whose measurements' spectra are `spectra`.
    pub fn new(
        surface: &'a ContainerSurface,
        spectra: &'a [MeasurementPsd],
        analysis: &'a ContainerAnalysis,
    ) -> ContainerRecord<'a> {
        ContainerRecord {
            name: surface.name.as_deref(),
            measurements: MeasurementRecord::all(surface, spectra),
            combined: CombinedRecord {
                band: analysis.band,
                moments: analysis.moments,
                roughness: analysis.roughness,
                heights_from: &surface.measurements[analysis.heights_from].name,
                rests_on: names(surface, &analysis.measurements),
            },
            model: &analysis.model,
            friction: &analysis.frictions,
            warnings: &analysis.warnings,
        }
    }
}

/// Each load's μ from the measurements taken alone, at their extremes.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SpreadRecord {
    /// The smallest μ.
    pub mu_min: f64,
    /// The largest μ.
    pub mu_max: f64,
}

/// A row of a container's scan over λs ([`super::container_scan`]), as
/// `kefric surface CONTAINER --scan --json` prints it: the band, the
/// measurements it rests on (names), the spread; the moments, roughness,
/// model, warnings and the first load's friction, or the error.
#[derive(Debug, Clone, serde::Serialize)]
pub struct ScanRecord<'a> {
    /// λs (m).
    pub lambda_s: f64,
    /// λc (m).
    pub lambda_c: f64,
    /// The measurements whose reliable range overlaps the band.
    pub measurements: Vec<&'a str>,
    /// Each load's spread across the measurements taken alone.
    pub spread: Option<Vec<SpreadRecord>>,
    /// The moments of the combined spectrum over the band.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub moments: Option<Moments>,
    /// Their roughness.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub roughness: Option<Roughness>,
    /// The model's inputs.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub model: Option<&'a Params>,
    /// The row's warnings.
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "some_warnings")]
    pub warnings: Option<&'a [Warning]>,
    /// The first load's friction (`None` without a load).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction: Option<Option<&'a Friction>>,
    /// Why the row has no result.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

fn some_warnings<S: serde::Serializer>(w: &Option<&[Warning]>, s: S) -> Result<S::Ok, S::Error> {
    warning_records(w.unwrap_or_default(), s)
}

impl<'a> ScanRecord<'a> {
    /// The record of `row` of a scan of `surface`.
    pub fn new(surface: &'a ContainerSurface, row: &'a ScanRow) -> ScanRecord<'a> {
        let spread = row.spread.as_ref().map(|v| {
            v.iter()
                .map(|&(mu_min, mu_max)| SpreadRecord { mu_min, mu_max })
                .collect()
        });
        let ok = row.result.as_ref().ok();
        ScanRecord {
            lambda_s: row.band.lambda_s,
            lambda_c: row.band.lambda_c,
            measurements: names(surface, &row.measurements),
            spread,
            moments: ok.map(|a| a.moments),
            roughness: ok.map(|a| a.roughness),
            model: ok.map(|a| &a.model),
            warnings: ok.map(|a| a.warnings.as_slice()),
            friction: ok.map(|a| a.frictions.first()),
            error: row.result.as_ref().err().map(ToString::to_string),
        }
    }
}

/// A request's input refused with a container: `field: message`.
fn refused(field: Field, message: Message) -> RequestError {
    RequestError {
        field,
        message,
        kind: ErrorKind::Argument,
        out_of_memory: false,
    }
}

/// A length of the band, > 0 and finite where given.
fn band_length(field: Field, v: Option<f64>) -> Result<Option<f64>, RequestError> {
    match v {
        Some(v) if !(v.is_finite() && v > 0.0) => Err(RequestError {
            kind: ErrorKind::of_value(v),
            ..refused(
                field,
                Message::text(format!(
                    "{} is out of range: must be > 0 and finite (metres)",
                    Shortest(v)
                )),
            )
        }),
        v => Ok(v),
    }
}

impl SurfaceRequest {
    /// The options of reading a container with this request: its points
    /// limit, and its tip radius or resolution (the resolution first, as
    /// for one file) for the measurements whose metadata gives neither.
    /// The inputs a container's metadata gives for each measurement
    /// (`dx`, `dy`, `channel`) are refused rather than ignored.
    pub fn container_options(&self) -> Result<ContainerOptions, RequestError> {
        for (field, given) in [
            (Field::Dx, self.dx.is_some()),
            (Field::Dy, self.dy.is_some()),
            (Field::Channel, self.channel.is_some()),
        ] {
            if given {
                return Err(refused(
                    field,
                    Message::text("not with a container (its meta.yml and data files give each measurement's)"),
                ));
            }
        }
        self.check()?;
        Ok(ContainerOptions {
            read: ReadOptions {
                max_points: self.max_points,
                ..ReadOptions::default()
            },
            tip_radius: self.tip_radius.filter(|_| self.resolution.is_none()),
            resolution: self.resolution,
        })
    }

    /// The band asked for (`lambda_s` in metres, `lambda_c`), its missing
    /// end from `resolved`'s default band; `None` if neither is given
    /// (`lambda_s` auto is the default: the smallest reliable scale).
    pub fn container_band(&self, resolved: &Resolved) -> Result<Option<Band>, RequestError> {
        let lambda_s = match self.lambda_s {
            Some(LambdaS::Metres(v)) => band_length(Field::LambdaS, Some(v))?,
            Some(LambdaS::Auto) | None => None,
        };
        let lambda_c = band_length(Field::LambdaC, self.lambda_c)?;
        if lambda_s.is_none() && lambda_c.is_none() {
            return Ok(None);
        }
        let default = resolved.default_band();
        Ok(Some(Band {
            lambda_s: lambda_s.or(default.map(|b| b.lambda_s)).unwrap_or(f64::NAN),
            lambda_c: lambda_c.or(default.map(|b| b.lambda_c)).unwrap_or(f64::NAN),
        }))
    }

    /// The materials and the loads (none: the model's inputs alone),
    /// checked: μ from a container needs the materials.
    pub fn container_model(&self) -> Result<(Materials, Vec<Load>), RequestError> {
        let checked = self.check()?;
        let materials = checked.materials.ok_or_else(|| RequestError {
            kind: ErrorKind::Domain,
            ..refused(
                Field::File,
                Message::text("μ from a container ").then_message(materials_needed()),
            )
        })?;
        Ok((materials, checked.loads.unwrap_or_default()))
    }

    /// An analysis' failure on the container `name`, naming the input to
    /// blame: a step of the model's (as for one surface), the band's ends
    /// where given, else the container.
    pub fn container_failure(&self, e: &AnalysisError, name: &str) -> RequestError {
        match e {
            AnalysisError::Evaluate(e) => evaluate_failure(e, self.distribution, self.loads.field()),
            AnalysisError::Band(_) if matches!(self.lambda_s, Some(LambdaS::Metres(_))) => {
                refused(Field::LambdaS, Message::text(e.to_string()))
            }
            AnalysisError::Band(_) if self.lambda_c.is_some() => refused(Field::LambdaC, Message::text(e.to_string())),
            e => RequestError {
                kind: e.kind(),
                ..refused(Field::File, Message::text(format!("{name}: {e}")))
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    fn zip_of(members: &[(&str, &[u8])]) -> Vec<u8> {
        let mut w = zip::ZipWriter::new(Cursor::new(Vec::new()));
        for (name, bytes) in members {
            w.start_file(*name, zip::write::SimpleFileOptions::default()).unwrap();
            w.write_all(bytes).unwrap();
        }
        w.finish().unwrap().into_inner()
    }

    #[test]
    fn a_container_is_a_zip_with_its_metadata() {
        assert!(is_container_bytes(&zip_of(&[("meta.yml", b"surfaces: []\n")])));
        assert!(is_container_bytes(&zip_of(&[("index.json", b"{}")])));
        // An X3P (a zip with main.xml), junk after a zip's signature, text.
        assert!(!is_container_bytes(&zip_of(&[("main.xml", b"<x/>")])));
        assert!(!is_container_bytes(b"PK\x03\x04 not really an archive"));
        assert!(!is_container_bytes(b"surfaces: []\n"));
    }

    #[test]
    fn the_inputs_a_container_gives_are_refused_naming_them() {
        let e = SurfaceRequest {
            dy: Some(1e-6),
            ..SurfaceRequest::default()
        }
        .container_options()
        .unwrap_err();
        assert_eq!(e.field, Field::Dy);
        assert_eq!(
            e.to_string(),
            "dy: not with a container (its meta.yml and data files give each measurement's)"
        );
        let e = SurfaceRequest {
            tip_radius: Some(-1.0),
            ..SurfaceRequest::default()
        }
        .container_options()
        .unwrap_err();
        assert_eq!(e.field, Field::TipRadius);
        // The resolution before the tip radius, as for one file.
        let o = SurfaceRequest {
            tip_radius: Some(1e-8),
            resolution: Some(2e-9),
            max_points: 1000,
            ..SurfaceRequest::default()
        }
        .container_options()
        .unwrap();
        assert_eq!(
            (o.tip_radius, o.resolution, o.read.max_points),
            (None, Some(2e-9), 1000)
        );
    }

    #[test]
    fn the_band_takes_its_missing_end_from_the_default_and_refuses_bad_ends() {
        let resolved = Resolved {
            ranges: vec![Some((1e-9, 1e-6)), None, Some((1e-7, 1e-4))],
        };
        assert_eq!(SurfaceRequest::default().container_band(&resolved), Ok(None));
        let auto = SurfaceRequest {
            lambda_s: Some(LambdaS::Auto),
            ..SurfaceRequest::default()
        };
        assert_eq!(auto.container_band(&resolved), Ok(None));
        let r = SurfaceRequest {
            lambda_s: Some(LambdaS::Metres(1e-8)),
            ..SurfaceRequest::default()
        };
        assert_eq!(
            r.container_band(&resolved),
            Ok(Some(Band {
                lambda_s: 1e-8,
                lambda_c: 1e-4
            }))
        );
        let bad = SurfaceRequest {
            lambda_c: Some(f64::INFINITY),
            ..SurfaceRequest::default()
        };
        let e = bad.container_band(&resolved).unwrap_err();
        assert_eq!(e.field, Field::LambdaC);
        assert_eq!(
            e.to_string(),
            "lambda_c: inf is out of range: must be > 0 and finite (metres)"
        );
        // A band the spectrum cannot fill blames the end given.
        let e = r.container_failure(&AnalysisError::Band("too narrow".into()), "c.zip");
        assert_eq!(
            (e.field, e.to_string()),
            (Field::LambdaS, "lambda_s: band: too narrow".into())
        );
        let e = SurfaceRequest::default().container_model().unwrap_err();
        assert_eq!(
            (e.field, e.message.to_string()),
            (
                Field::File,
                "μ from a container needs the materials (e1, nu1, e2, nu2, hardness, delta_gamma, epsilon)".into()
            )
        );
        let e = SurfaceRequest::default().container_failure(&AnalysisError::NoSpectrum, "c.zip");
        assert_eq!(e.to_string(), "file: c.zip: no measurement has a reliable spectrum");
        assert_eq!(e.kind, ErrorKind::Domain);
    }
}
