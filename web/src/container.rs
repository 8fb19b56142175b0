//! A contact.engineering container dropped on the page (detected by its
//! content, [`is_container`]): its measurements, their combined power
//! spectrum, μ from the whole band and the scan over λs, exactly as
//! `kefric surface CONTAINER --json` (and `--psd`, `--scan`) give them:
//! the core's `topography::container` and its records; the page's
//! options are the same core request as for one file ([`Options`]).

use crate::{page_error, Options};
use ke_friction::topography::container::{
    combined_psd, container_analysis, container_scan, is_container_bytes, measurement_spectra, read_container_bytes,
    ContainerRecord, ContainerSurface, MeasurementPsd, MeasurementRecord, Resolved, ScanRecord,
    COMBINED_POINTS_PER_DECADE,
};
use ke_friction::topography::SurfaceRequest;
use ke_friction::{Materials, Summary, Warnings};
use serde_json::{json, Value};
use wasm_bindgen::prelude::*;

/// The scan's values of λs a decade (`kefric surface --scan`'s default
/// `--per-decade`).
const SCAN_PER_DECADE: u32 = 5;

/// Whether `bytes`, a whole file, are a contact.engineering container (a
/// zip with `meta.yml` or `index.json`; an X3P is not one).
#[wasm_bindgen]
pub fn is_container(bytes: &[u8]) -> bool {
    is_container_bytes(bytes)
}

/// A container's first surface analysed as `kefric surface CONTAINER`
/// does.
#[wasm_bindgen]
pub struct ContainerAnalysis {
    name: String,
    options: Options,
    request: SurfaceRequest,
    surface: ContainerSurface,
    spectra: Vec<MeasurementPsd>,
    materials: Option<Materials>,
    record: String,
    warnings: Warnings,
    /// Why μ could not be had (the measurements and spectra are shown).
    failure: Option<String>,
}

impl ContainerAnalysis {
    /// The analysis of the container `bytes`, the file `name`, with
    /// `options`: the record of `kefric surface CONTAINER --json` (with
    /// the materials), else the measurements alone and why there is no μ.
    pub fn analyse(bytes: &[u8], name: &str, options: Options) -> Result<ContainerAnalysis, String> {
        let request = options.request()?;
        let container_options = request.container_options().map_err(|e| page_error(&e))?;
        // μ needs the materials; without them the measurements and
        // spectra are shown, and why there is no μ (kefric refuses).
        request.check().map_err(|e| page_error(&e))?;
        let model = request.container_model();
        let mut surfaces = read_container_bytes(bytes, name, &container_options).map_err(|e| e.to_string())?;
        if surfaces.is_empty() {
            return Err(format!("{name}: the container lists no surface"));
        }
        // The page shows one surface: the first (kefric prints each).
        let surface = surfaces.swap_remove(0);
        let spectra = measurement_spectra(&surface.measurements);
        let mut warnings = Warnings::new();
        let files = vec![name.to_string()];
        let mut failure = None;
        let record = match &model {
            Err(e) => {
                failure = Some(page_error(e));
                json!({
                    "files": files, "name": surface.name,
                    "measurements": MeasurementRecord::all(&surface, &spectra),
                })
            }
            Ok((materials, loads)) => {
                let outcome = request.container_band(&Resolved::of(&spectra)).and_then(|band| {
                    container_analysis(
                        &surface.measurements,
                        &spectra,
                        band,
                        COMBINED_POINTS_PER_DECADE,
                        &request.model_of(*materials),
                        loads,
                    )
                    .map_err(|e| request.container_failure(&e, name))
                });
                match outcome {
                    Ok(a) => {
                        warnings.extend(a.warnings.iter().cloned());
                        let mut doc = serde_json::to_value(ContainerRecord::new(&surface, &spectra, &a))
                            .map_err(|e| format!("the record: {e}"))?;
                        doc["files"] = json!(files);
                        doc
                    }
                    Err(e) => {
                        failure = Some(page_error(&e));
                        json!({
                            "files": files, "name": surface.name,
                            "measurements": MeasurementRecord::all(&surface, &spectra),
                        })
                    }
                }
            }
        };
        Ok(ContainerAnalysis {
            name: name.to_string(),
            options,
            materials: model.ok().map(|m| m.0),
            request,
            surface,
            spectra,
            record: record.to_string(),
            warnings,
            failure,
        })
    }

    /// The spectra: the combined one (`q`, `c`, or `error`) and each
    /// measurement's own with its name and reliable range.
    pub fn psd_value(&self) -> Value {
        let combined = match combined_psd(&self.spectra, COMBINED_POINTS_PER_DECADE) {
            Some(c) => json!({ "q": c.psd.q, "c": c.psd.c }),
            None => json!({ "error": "no measurement has a reliable spectrum" }),
        };
        let measurements: Vec<Value> = self
            .surface
            .measurements
            .iter()
            .zip(&self.spectra)
            .map(|(m, p)| match &p.psd {
                Some(psd) => json!({ "name": m.name, "q": psd.q, "c": psd.c }),
                None => json!({ "name": m.name, "error": p.reason }),
            })
            .collect();
        json!({ "combined": combined, "measurements": measurements })
    }

    /// The scan over λs (`kefric surface CONTAINER --scan --json`'s rows
    /// at its default 5 a decade), or why there is none.
    pub fn scan_value(&self) -> Result<Value, String> {
        let Some(materials) = self.materials else {
            return Err("the scan over λs needs the materials".into());
        };
        let loads = self
            .request
            .loads
            .loads()
            .map_err(|e| page_error(&e))?
            .unwrap_or_default();
        let rows = container_scan(
            &self.surface.measurements,
            &self.spectra,
            self.request.lambda_c,
            SCAN_PER_DECADE,
            &self.request.model_of(materials),
            &loads,
        )
        .map_err(|e| page_error(&self.request.container_failure(&e, &self.name)))?;
        let mut all = Warnings::new();
        for row in &rows {
            if let Ok(a) = &row.result {
                all.note(a.warnings.iter().cloned());
            }
        }
        let records: Vec<ScanRecord<'_>> = rows.iter().map(|r| ScanRecord::new(&self.surface, r)).collect();
        let summaries: Vec<Summary<'_>> = all.summaries().collect();
        Ok(json!({ "rows": records, "warnings": summaries }))
    }
}

#[wasm_bindgen]
impl ContainerAnalysis {
    /// Analyses the container `bytes`, the file `name`, with the options
    /// `options_json` (as [`crate::Analysis::new`]'s); a failure throws
    /// kefric's message.
    #[wasm_bindgen(constructor)]
    pub fn new(bytes: &[u8], name: &str, options_json: &str) -> Result<ContainerAnalysis, JsError> {
        let options = Options::parse(options_json).map_err(|e| JsError::new(&e))?;
        ContainerAnalysis::analyse(bytes, name, options).map_err(|e| JsError::new(&e))
    }

    /// The record: `kefric surface CONTAINER --json`'s (the measurements
    /// alone where [`error`](Self::error) says why μ could not be had).
    pub fn record(&self) -> String {
        self.record.clone()
    }

    /// Why μ could not be had, in the page's words.
    pub fn error(&self) -> Option<String> {
        self.failure.clone()
    }

    /// The warnings, once a kind, as kefric prints them (JSON list).
    pub fn warnings(&self) -> String {
        let w: Vec<String> = self.warnings.summaries().map(|s| format!("warning: {s}")).collect();
        json!(w).to_string()
    }

    /// The equivalent command line.
    pub fn command(&self) -> String {
        self.options.command(&self.name)
    }

    /// The spectra (JSON, [`ContainerAnalysis::psd_value`]).
    pub fn psd(&self) -> String {
        self.psd_value().to_string()
    }

    /// The scan over λs (JSON, [`ContainerAnalysis::scan_value`]).
    pub fn scan(&self) -> Result<String, JsError> {
        self.scan_value().map(|v| v.to_string()).map_err(|e| JsError::new(&e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `$KEF_CONTAINERS/container-2.zip` (default: `../shared/containers`
    /// beside the checkout, as the library's tests).
    fn container_2() -> Option<Vec<u8>> {
        let dir = std::env::var_os("KEF_CONTAINERS").map_or_else(
            || std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/containers"),
            std::path::PathBuf::from,
        );
        let bytes = std::fs::read(dir.join("container-2.zip")).ok();
        if bytes.is_none() {
            println!("skipped: no {}/container-2.zip (set KEF_CONTAINERS)", dir.display());
        }
        bytes
    }

    #[test]
    fn a_container_gives_kefrics_record_and_an_x3p_is_not_one() {
        assert!(!is_container(b"PK\x03\x04 not really an archive"));
        let Some(bytes) = container_2() else { return };
        assert!(is_container(&bytes));
        let options = Options::parse(
            r#"{"e1": "70e9", "nu1": "0.33", "e2": "200e9", "nu2": "0.31", "hardness": "1e9",
                "delta_gamma": "0.5", "epsilon": "0.4e-9", "force": "10", "area": "1e-5"}"#,
        )
        .unwrap();
        let a = ContainerAnalysis::analyse(&bytes, "container-2.zip", options).unwrap();
        assert_eq!(a.error(), None);
        let record: Value = serde_json::from_str(&a.record()).unwrap();
        assert_eq!(record["files"], json!(["container-2.zip"]));
        assert_eq!(record["measurements"].as_array().unwrap().len(), 3);
        let mu = record["friction"][0]["mu"].as_f64().unwrap();
        assert!(mu > 0.0 && mu.is_finite(), "{mu}");
        let scan = a.scan_value().unwrap();
        assert!(scan["rows"].as_array().unwrap().len() > 10);
    }

    #[test]
    fn a_container_refuses_dx_as_kefric_does() {
        let Some(bytes) = container_2() else { return };
        let e = ContainerAnalysis::analyse(&bytes, "c.zip", Options::parse(r#"{"dx": "1e-6"}"#).unwrap())
            .err()
            .unwrap();
        assert_eq!(
            e,
            "“Δx”: not with a container (its meta.yml and data files give each measurement's)"
        );
    }

    #[test]
    fn without_materials_the_measurements_are_shown_and_mu_asked_for() {
        let Some(bytes) = container_2() else { return };
        let a = ContainerAnalysis::analyse(&bytes, "c.zip", Options::default()).unwrap();
        assert!(a.error().unwrap().contains("needs the materials"));
        let record: Value = serde_json::from_str(&a.record()).unwrap();
        assert_eq!(record["measurements"][1]["ny"], json!(512));
        assert!(a.psd_value()["combined"]["q"].as_array().unwrap().len() > 10);
    }
}
