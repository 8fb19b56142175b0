//! The web page's analysis: `kefric surface` compiled to WebAssembly.
//!
//! The page (`web/static/`) hands a file's bytes and its options (the URL
//! query: `kefric surface`'s flags with `_` for `-`, [`keys`]) to
//! [`Analysis::new`], which makes them the core's request
//! ([`SurfaceRequest`]: the file read by the reader registry, the
//! statistics and, with materials and a load, μ and its sensitivity exactly
//! as `kefric surface --json` gives them; errors name the page's fields,
//! [`label`]), and keeps the core's record ([`SurfaceRecord`]). The curves (μ against load, μ, ψ and β against
//! λs, the PSD, the height map and histogram) are further methods. Every
//! result crosses to JavaScript as JSON text or a `Float64Array`. A
//! contact.engineering container is `container.rs`'s.

use ke_friction::topography::{
    complete_part, psd_all, scan, Analysis as Answer, Channel, Checked, Cutoff, Derivative, Detrend, Evaluation, Field,
    Format, LambdaS, LoadInputs, RequestError, ScanRange, Source, StatsOptions, Surface, SurfaceRecord, SurfaceRequest,
    Topography, Window, SENSITIVITY_FAMILIES,
};
use ke_friction::{
    Family, Fit, Friction, HeightDistribution, LengthUnit, Load, Materials, Model, ModelKind, Named, Params, Warnings,
};
use serde_json::{json, Value};
use std::collections::BTreeMap;
use wasm_bindgen::prelude::*;

mod container;

/// The options the page takes, as URL query keys, in the order the
/// equivalent command line gives them: the core request's fields
/// ([`Field`]) but the file, each `kefric surface`'s flag with `_` for
/// `-` (`lambda_s` is `--lambda-s`).
pub fn keys() -> Vec<&'static str> {
    Field::ALL
        .iter()
        .filter(|f| **f != Field::File)
        .map(|f| f.name())
        .collect()
}

/// The page's label of a request's input (the text of its field in
/// `static/index.html`, without the unit), how its messages name it.
pub fn label(field: Field) -> &'static str {
    match field {
        Field::File => "file",
        Field::Dx => "Δx",
        Field::Dy => "Δy",
        Field::ZUnit => "unit of heights",
        Field::XyUnit => "unit of Δx, Δy",
        Field::MaxPoints => "max points",
        Field::Channel => "channel",
        Field::Detrend => "detrend",
        Field::Derivative => "derivative",
        Field::LambdaS => "λs",
        Field::LambdaC => "λc",
        Field::TipRadius => "tip radius",
        Field::Resolution => "resolution",
        Field::E1 => "E₁",
        Field::Nu1 => "ν₁",
        Field::E2 => "E₂",
        Field::Nu2 => "ν₂",
        Field::Hardness => "hardness H",
        Field::DeltaGamma => "Δγ",
        Field::Epsilon => "ε",
        Field::Distribution => "heights",
        Field::Fit => "fit",
        Field::Model => "model",
        Field::Force => "force F",
        Field::Area => "area Aₙ",
        Field::Pressure => "pressure",
    }
}

/// An input named on the page: its label in quotes.
fn spell(field: Field) -> String {
    format!("“{}”", label(field))
}

/// A request's failure in the page's words: its fields by their labels;
/// a file's own failure without a prefix (the message names the file).
pub fn page_error(e: &RequestError) -> String {
    if e.field == Field::File {
        e.message.render(&spell)
    } else {
        e.render(&spell)
    }
}

/// The error of a field's own value: `“label”: why`.
fn field_error(field: Field, why: impl std::fmt::Display) -> String {
    format!("{}: {why}", spell(field))
}

/// The loads of the μ-against-load curve: the given load times
/// 10^(k/10) for k in this range (three decades below, one above).
const LOAD_STEPS: std::ops::RangeInclusive<i32> = -30..=10;

/// The page's options: key → value text, every key one of [`keys`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Options {
    values: BTreeMap<String, String>,
}

impl Options {
    /// The options of a JSON object of strings (the URL query's
    /// parameters); empty values count as not given.
    pub fn parse(json: &str) -> Result<Options, String> {
        let map: BTreeMap<String, String> =
            serde_json::from_str(json).map_err(|e| format!("options: not a JSON object of strings: {e}"))?;
        let mut values = BTreeMap::new();
        for (key, value) in map {
            if !keys().contains(&key.as_str()) {
                return Err(ke_friction::NameError::new("option", &key, keys()).to_string());
            }
            let value = value.trim().to_string();
            if !value.is_empty() {
                values.insert(key, value);
            }
        }
        Ok(Options { values })
    }

    fn get(&self, field: Field) -> Option<&str> {
        self.values.get(field.name()).map(String::as_str)
    }

    /// A number: finite, or an error naming the field.
    fn number(&self, field: Field) -> Result<Option<f64>, String> {
        let Some(text) = self.get(field) else { return Ok(None) };
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(Some(v)),
            Ok(_) => Err(field_error(field, format!("'{text}' is not a finite number"))),
            Err(_) => Err(field_error(
                field,
                format!("'{text}' is not a number (e.g. 0.5 or 1e-3)"),
            )),
        }
    }

    /// One of a core name list ([`Named`]), or `default`.
    fn named<T: Named>(&self, field: Field, default: T) -> Result<T, String> {
        match self.get(field) {
            None => Ok(default),
            Some(text) => T::parse(text).map_err(|e| field_error(field, e)),
        }
    }

    /// The core's request of these options (with the sensitivity).
    pub fn request(&self) -> Result<SurfaceRequest, String> {
        let max_points = match self.get(Field::MaxPoints) {
            None => SurfaceRequest::default().max_points,
            Some(text) => match text.parse::<u64>() {
                Ok(n) if n >= 1 => n,
                _ => {
                    return Err(field_error(
                        Field::MaxPoints,
                        format!("'{text}' is out of range: must be a whole number >= 1"),
                    ))
                }
            },
        };
        let mut materials = [None; 7];
        for (m, field) in materials.iter_mut().zip(Field::MATERIALS) {
            *m = self.number(field)?;
        }
        Ok(SurfaceRequest {
            dx: self.number(Field::Dx)?,
            dy: self.number(Field::Dy)?,
            z_unit: self.named(Field::ZUnit, LengthUnit::M)?.metres(),
            xy_unit: self.named(Field::XyUnit, LengthUnit::M)?.metres(),
            max_points,
            channel: self
                .get(Field::Channel)
                .map(|c| c.parse::<Channel>().unwrap_or_else(|never| match never {})),
            detrend: self.named(Field::Detrend, Detrend::Plane)?,
            derivative: self.named(Field::Derivative, Derivative::FiniteDifference)?,
            lambda_s: match self.get(Field::LambdaS) {
                None => None,
                Some("auto") => Some(LambdaS::Auto),
                Some(_) => self.number(Field::LambdaS)?.map(LambdaS::Metres),
            },
            lambda_c: self.number(Field::LambdaC)?,
            tip_radius: self.number(Field::TipRadius)?,
            resolution: self.number(Field::Resolution)?,
            materials,
            distribution: self
                .get(Field::Distribution)
                .map(|_| self.named(Field::Distribution, Family::Pearson))
                .transpose()?,
            fit: self.named(Field::Fit, Fit::Consistent)?,
            model: self.named(Field::Model, ModelKind::KogutEtsion)?,
            loads: LoadInputs::one(
                self.number(Field::Force)?,
                self.number(Field::Area)?,
                self.number(Field::Pressure)?,
            ),
            sensitivity: true,
        })
    }

    /// The equivalent command line: `kefric surface FILE … --json`.
    pub fn command(&self, file: &str) -> String {
        let mut words = vec!["kefric".to_string(), "surface".to_string(), quote(file)];
        for field in Field::ALL {
            if let Some(v) = self.get(field) {
                words.push(field.flag());
                words.push(quote(v));
            }
        }
        words.push("--json".to_string());
        words.join(" ")
    }
}

/// A word for a POSIX shell: as it is when it is plain, else single-quoted.
fn quote(word: &str) -> String {
    let plain = !word.is_empty()
        && word
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "._-+/=:,@%".contains(c));
    if plain {
        word.to_string()
    } else {
        format!("'{}'", word.replace('\'', "'\\''"))
    }
}

/// One measured surface analysed as `kefric surface` does.
#[wasm_bindgen]
pub struct Analysis {
    name: String,
    options: Options,
    request: SurfaceRequest,
    answer: Answer,
    load: Option<Load>,
    materials: Option<Materials>,
    record: String,
    /// Why the model's inputs or μ could not be had (the statistics are).
    failure: Option<String>,
}

impl Analysis {
    /// The measured topography (the surface's one part: its own, not a
    /// second copy of the heights).
    fn topography(&self) -> &Topography {
        &self.answer.surface.parts()[0].0
    }

    fn surface(&self) -> &Surface {
        &self.answer.surface
    }

    fn stats_options(&self) -> StatsOptions {
        self.answer.surface.options()
    }

    fn cutoff(&self) -> Option<f64> {
        match self.answer.cutoff {
            Cutoff::Unknown => None,
            Cutoff::Known(c) => c,
        }
    }

    fn params(&self) -> Option<&Params> {
        self.answer.evaluation.as_ref().map(|e| &e.params)
    }

    /// The warnings (the statistics' and the load's).
    fn warning_list(&self) -> &Warnings {
        &self.answer.warnings
    }

    /// The analysis of `bytes`, the file `name`, with `options`: the
    /// core's request; the error names the page's fields.
    pub fn analyse(bytes: &[u8], name: &str, options: Options) -> Result<Analysis, String> {
        let request = options.request()?;
        let checked = request.check().map_err(|e| page_error(&e))?;
        let (surface, cutoff) = request
            .surface(&[Source::Bytes { bytes, name }])
            .map_err(|e| page_error(&e))?;
        // A failed evaluation (a height model the surface does not admit,
        // inputs out of the model's range) keeps the statistics shown,
        // with the error beside them.
        let (mut answer, failure) = match request.analyse(surface.clone(), cutoff, &checked) {
            Ok(answer) => (answer, None),
            Err(e) => {
                let statistics = Checked {
                    materials: None,
                    loads: None,
                };
                let answer = request
                    .analyse(surface, cutoff, &statistics)
                    .map_err(|e| page_error(&e))?;
                (answer, Some(page_error(&e)))
            }
        };
        answer.notes = request.auto_without_cutoff(cutoff, name).into_iter().collect();
        let frictions: &[Friction] = answer.evaluation.as_ref().map_or(&[], |e| &e.frictions);
        let record = SurfaceRecord::new(
            vec![name.to_string()],
            &answer.surface,
            answer.evaluation.as_ref().map(|e| &e.params),
            None,
        )
        .with_sensitivity(frictions, &answer.sensitivity, false)
        .with_warnings(&answer.warnings);
        let record = serde_json::to_string(&record).map_err(|e| format!("the record: {e}"))?;
        let evaluated = failure.is_none();
        Ok(Analysis {
            name: name.to_string(),
            options,
            load: checked.loads.and_then(|l| l.into_iter().next()).filter(|_| evaluated),
            materials: checked.materials.filter(|_| evaluated),
            request,
            answer,
            record,
            failure,
        })
    }

    /// The model's inputs of `surface` with the materials and, with `load`,
    /// the friction and its warnings; `None` without materials.
    fn evaluate(&self, surface: &Surface, load: Option<Load>) -> Result<Option<Evaluation>, String> {
        let Some(materials) = self.materials else {
            return Ok(None);
        };
        self.request
            .evaluate(surface, materials, load.as_slice())
            .map(Some)
            .map_err(|e| page_error(&e))
    }

    /// μ at loads around the given one: (load in N or Pa, μ) rows.
    pub fn mu_against_load_rows(&self) -> Vec<(f64, f64)> {
        match self.params() {
            Some(params) => self.mu_against_load_of(params.clone()),
            None => Vec::new(),
        }
    }

    /// μ at loads around the given one under the height model `family`
    /// (the other choices the analysis's): (load, μ) rows, or why the
    /// surface admits no such model.
    pub fn mu_against_load_under(&self, family: Family) -> Result<Vec<(f64, f64)>, String> {
        let Some(materials) = self.materials else {
            return Ok(Vec::new());
        };
        let how = ke_friction::topography::SurfaceModel {
            family: Some(family),
            ..self.request.model_of(materials)
        };
        let params = self.surface().model_params(&how).map_err(|e| {
            page_error(&ke_friction::topography::evaluate_failure(
                &e,
                Some(family),
                Field::Force,
            ))
        })?;
        Ok(self.mu_against_load_of(params))
    }

    fn mu_against_load_of(&self, params: Params) -> Vec<(f64, f64)> {
        let (Some(load), Some(materials)) = (self.load, &self.materials) else {
            return Vec::new();
        };
        let Ok(model) = Model::new(params) else {
            return Vec::new();
        };
        let physical = self.surface().physical(materials);
        LOAD_STEPS
            .filter_map(|k| {
                let factor = 10f64.powf(f64::from(k) / 10.0);
                let (l, x) = match load {
                    Load::Force { force, area } => (
                        Load::Force {
                            force: force * factor,
                            area,
                        },
                        force * factor,
                    ),
                    Load::Pressure(p) => (Load::Pressure(p * factor), p * factor),
                };
                l.friction(&model, &physical).ok().map(|f| (x, f.mu))
            })
            .collect()
    }

    /// The scan over λs (the CLI's `--scan` default range): one JSON row a
    /// λs with its β, ψ and μ (or its error); `progress(done, total)`.
    pub fn scan_rows(&self, progress: impl FnMut(usize, usize)) -> Result<Value, String> {
        let range = ScanRange::default_for(self.topography());
        let rows = scan(
            self.topography(),
            &self.stats_options(),
            &range,
            self.cutoff(),
            progress,
        )
        .map_err(|e| format!("scan: {e}"))?;
        // Each row's warning kinds, and their summary once per kind (one
        // result a row), as `kefric surface --scan` records them.
        let mut all = Warnings::new();
        let rows: Vec<Value> = rows
            .iter()
            .map(|row| {
                let mut r = json!({ "lambda_s": row.lambda_s, "reliable": row.reliable });
                match &row.surface {
                    Ok(surface) => {
                        r["beta"] = surface.stats().beta.into();
                        let mut warnings = Warnings::new();
                        warnings.extend(surface.stats().warnings.iter().cloned());
                        match self.evaluate(surface, self.load) {
                            Ok(Some(e)) => {
                                e.note_into(&mut warnings);
                                r["psi"] = e.params.psi.into();
                                if let Some(f) = e.frictions.first() {
                                    r["mu"] = f.mu.into();
                                }
                            }
                            Ok(None) => {}
                            Err(e) => r["error"] = e.into(),
                        }
                        let kinds: Vec<&str> = warnings.summaries().map(|s| s.worst.kind().name()).collect();
                        r["warnings"] = kinds.into();
                        all.note(warnings.summaries().map(|s| s.worst.clone()));
                    }
                    Err(e) => r["error"] = e.to_string().into(),
                }
                r
            })
            .collect();
        let summaries: Vec<ke_friction::Summary<'_>> = all.summaries().collect();
        Ok(json!({ "cutoff": self.cutoff(), "rows": rows, "warnings": summaries }))
    }

    /// The height histogram of the heights the statistics see (`bins`
    /// bins over ±4σ), as densities (1/m), with the Gaussian and Pearson
    /// densities of the measured σ, Sk, K at the bins' centres.
    pub fn histogram_value(&self, bins: usize) -> Result<Value, String> {
        let bins = bins.clamp(4, 400);
        let heights = self
            .topography()
            .band_heights(&self.stats_options())
            .map_err(|e| e.to_string())?;
        let s = self.surface().stats();
        let (lo, hi) = (-4.0 * s.sigma, 4.0 * s.sigma);
        let width = (hi - lo) / bins as f64;
        let mut counts = vec![0usize; bins];
        let mut valid = 0usize;
        for &h in heights.iter().filter(|h| !h.is_nan()) {
            valid += 1;
            let k = ((h - lo) / width).floor();
            if k >= 0.0 && (k as usize) < bins {
                counts[k as usize] += 1;
            }
        }
        let centres: Vec<f64> = (0..bins).map(|k| lo + (k as f64 + 0.5) * width).collect();
        let density: Vec<f64> = counts
            .iter()
            .map(|&c| c as f64 / (valid.max(1) as f64 * width))
            .collect();
        let of = |d: Result<HeightDistribution, ke_friction::ParamError>| -> Value {
            match d.and_then(|d| d.density()) {
                Ok(g) => centres
                    .iter()
                    .map(|&z| g.pdf(z / s.sigma) / s.sigma)
                    .collect::<Vec<f64>>()
                    .into(),
                Err(e) => e.to_string().into(),
            }
        };
        Ok(json!({
            "z": centres,
            "density": density,
            "gaussian": of(Ok(HeightDistribution::GAUSSIAN)),
            "pearson": of(HeightDistribution::pearson(s.skewness, s.kurtosis)),
        }))
    }
}

#[wasm_bindgen]
impl Analysis {
    /// Analyses `bytes`, the content of the file `name`, with the options
    /// `options_json` (a JSON object of strings, keys of [`keys`]); a
    /// failure throws the CLI's message.
    #[wasm_bindgen(constructor)]
    pub fn new(bytes: &[u8], name: &str, options_json: &str) -> Result<Analysis, JsError> {
        let options = Options::parse(options_json).map_err(|e| JsError::new(&e))?;
        Analysis::analyse(bytes, name, options).map_err(|e| JsError::new(&e))
    }

    /// The record: exactly `kefric surface --json`'s (the statistics'
    /// alone where [`error`](Self::error) says why μ could not be had).
    pub fn record(&self) -> String {
        self.record.clone()
    }

    /// Why the model's inputs or μ could not be had, in the page's words
    /// (the statistics were; kefric refuses the whole command).
    pub fn error(&self) -> Option<String> {
        self.failure.clone()
    }

    /// The warnings (the statistics' and the load's), once a kind, as
    /// the CLI prints them on stderr (JSON list).
    pub fn warnings(&self) -> String {
        let notes = self
            .answer
            .notes
            .iter()
            .map(|n| format!("warning: {}", n.render(&spell)));
        let w: Vec<String> = notes
            .chain(self.warning_list().summaries().map(|s| format!("warning: {s}")))
            .collect();
        json!(w).to_string()
    }

    /// The equivalent command line.
    pub fn command(&self) -> String {
        self.options.command(&self.name)
    }

    /// μ against load (JSON: `unit` "N" or "Pa", `load`, `mu`); empty
    /// without materials and a load.
    pub fn mu_against_load(&self) -> String {
        let rows = self.mu_against_load_rows();
        let unit = if matches!(self.load, Some(Load::Pressure(_))) {
            "Pa"
        } else {
            "N"
        };
        let (load, mu): (Vec<f64>, Vec<f64>) = rows.into_iter().unzip();
        let chosen = self.params().map(|p| p.constants.distribution.family());
        json!({ "unit": unit, "load": load, "mu": mu, "chosen": chosen }).to_string()
    }

    /// μ against the same loads under each height model of the
    /// sensitivity (JSON: name → `{load, mu}` or `{error}`); drawn after
    /// the analysis' own curve.
    pub fn mu_against_load_models(&self) -> String {
        let mut models = serde_json::Map::new();
        if self.load.is_some() {
            let chosen = self.params().map(|p| p.constants.distribution.family_kind());
            for family in SENSITIVITY_FAMILIES {
                // The analysis' own family: its curve, not solved again.
                let rows = if chosen == Some(family) {
                    Ok(self.mu_against_load_rows())
                } else {
                    self.mu_against_load_under(family)
                };
                let value = match rows {
                    Ok(rows) => {
                        let (load, mu): (Vec<f64>, Vec<f64>) = rows.into_iter().unzip();
                        json!({ "load": load, "mu": mu })
                    }
                    Err(e) => json!({ "error": e }),
                };
                models.insert(family.name().to_string(), value);
            }
        }
        Value::Object(models).to_string()
    }

    /// The scan over λs (JSON), calling `progress(done, total)` after each row.
    pub fn scan(&self, progress: &js_sys::Function) -> Result<String, JsError> {
        let this = JsValue::NULL;
        self.scan_rows(|done, total| {
            // A progress callback that throws only loses the progress.
            let _ = progress.call2(&this, &JsValue::from(done as u32), &JsValue::from(total as u32));
        })
        .map(|v| v.to_string())
        .map_err(|e| JsError::new(&e))
    }

    /// The power spectral densities of the detrended heights (JSON: one
    /// `{q, c}` a direction, named as `kefric surface --psd` names them;
    /// with missing points, of the largest complete rectangle, which
    /// `note` names, as kefric's warning does).
    pub fn psd(&self) -> Result<String, JsError> {
        let (part, rectangle) =
            complete_part(self.topography()).map_err(|e| JsError::new(&format!("power spectral density: {e}")))?;
        let detrended = part
            .detrended_topography(self.stats_options().detrend)
            .map_err(|e| JsError::new(&e.to_string()))?;
        let spectra =
            psd_all(&detrended, Window::None).map_err(|e| JsError::new(&format!("power spectral density: {e}")))?;
        let mut doc = serde_json::Map::new();
        for (name, p) in &spectra {
            doc.insert(name.to_string(), json!({ "q": p.q, "c": p.c }));
        }
        if let Some(r) = rectangle {
            doc.insert("note".into(), json!(r.to_string()));
        }
        Ok(Value::Object(doc).to_string())
    }

    /// The height histogram (JSON, see [`Analysis::histogram_value`]).
    pub fn histogram(&self, bins: usize) -> Result<String, JsError> {
        self.histogram_value(bins)
            .map(|v| v.to_string())
            .map_err(|e| JsError::new(&e))
    }

    /// Points along x.
    pub fn nx(&self) -> usize {
        self.topography().nx()
    }

    /// Points along y (1 for a profile).
    pub fn ny(&self) -> usize {
        self.topography().ny()
    }

    /// The heights detrended as the statistics are (`detrend`; m,
    /// row-major, NaN where missing), every `step`-th point along x and y:
    /// a map of at most ⌈nx/step⌉ × ⌈ny/step⌉.
    pub fn heights(&self, step: usize) -> Result<Vec<f64>, JsError> {
        let step = step.max(1);
        let (nx, ny) = (self.topography().nx(), self.topography().ny());
        let detrended = self
            .topography()
            .detrended(self.stats_options().detrend)
            .map_err(|e| JsError::new(&e.to_string()))?;
        let z = &detrended;
        Ok((0..ny)
            .step_by(step)
            .flat_map(|j| (0..nx).step_by(step).map(move |i| z[j * nx + i]))
            .collect())
    }
}

/// The library's version.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// The page's names, from the core: the option keys ([`keys`]), the
/// surface formats of the reader registry (name, description,
/// extensions), and the values of each named option (JSON).
#[wasm_bindgen]
pub fn names() -> String {
    let formats: Vec<Value> = Format::all()
        .map(|f| json!({ "name": f.name(), "description": f.description(), "extensions": f.extensions() }))
        .collect();
    let labels: BTreeMap<&str, &str> = Field::ALL.iter().map(|f| (f.name(), label(*f))).collect();
    json!({
        "keys": keys(),
        "labels": labels,
        "formats": formats,
        "detrend": Detrend::names(),
        "derivative": Derivative::names(),
        "distribution": Family::names(),
        "fit": Fit::names(),
        "model": ModelKind::names(),
        "xy_unit": LengthUnit::names(),
        "z_unit": LengthUnit::names(),
    })
    .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_field_has_a_label_in_the_page() {
        let html = include_str!("../static/index.html");
        for f in Field::ALL.iter().filter(|f| **f != Field::File) {
            assert!(html.contains(&format!("name=\"{}\"", f.name())), "{f:?} has no field");
            let text = label(*f).trim_start_matches("or ");
            assert!(html.contains(text), "{f:?}: no label {text:?} on the page");
        }
    }

    #[test]
    fn an_unknown_option_is_refused_naming_the_valid_keys() {
        let e = Options::parse(r#"{"e3": "1"}"#).unwrap_err();
        assert!(e.starts_with("option 'e3' is unknown: must be one of dx, dy"), "{e}");
    }

    #[test]
    fn the_command_line_gives_the_flags_in_order_and_quotes_odd_words() {
        let o = Options::parse(r#"{"pressure": "1e6", "lambda_s": "2e-6", "dx": "1e-6", "fit": ""}"#).unwrap();
        assert_eq!(
            o.command("my file.x3p"),
            "kefric surface 'my file.x3p' --dx 1e-6 --lambda-s 2e-6 --pressure 1e6 --json"
        );
    }

    /// The analysis of [`text_map`] (Δx = 0.5 µm) with the README's
    /// aluminium on nickel and the options `extra` (replacing any of those).
    fn aluminium_on_the_map(extra: &[(&str, &str)]) -> Analysis {
        let mut options: BTreeMap<&str, &str> = [
            ("dx", "0.5"),
            ("xy_unit", "um"),
            ("z_unit", "um"),
            ("e1", "70e9"),
            ("nu1", "0.33"),
            ("e2", "200e9"),
            ("nu2", "0.31"),
            ("hardness", "1e9"),
            ("delta_gamma", "0.5"),
            ("epsilon", "0.4e-9"),
        ]
        .into();
        options.extend(extra.iter().copied());
        let json = serde_json::to_string(&options).unwrap();
        Analysis::analyse(&text_map(), "h.txt", Options::parse(&json).unwrap()).unwrap()
    }

    /// A 40 × 30 text map (heights in µm, a few incommensurate waves),
    /// shared with the core's request tests: `tests/data/text_map.txt`.
    fn text_map() -> Vec<u8> {
        include_bytes!("../../tests/data/text_map.txt").to_vec()
    }

    #[test]
    fn a_text_map_with_dx_alone_has_dy_equal_to_dx_in_the_record() {
        let options = Options::parse(r#"{"dx": "0.5", "xy_unit": "um", "z_unit": "um"}"#).unwrap();
        let a = Analysis::analyse(&text_map(), "h.txt", options).unwrap();
        let record: Value = serde_json::from_str(&a.record).unwrap();
        assert_eq!(record["files"], json!(["h.txt"]));
        assert_eq!(
            (record["surface"]["nx"].as_u64(), record["surface"]["ny"].as_u64()),
            (Some(40), Some(30))
        );
        assert_eq!(record["surface"]["dx"].as_f64(), Some(0.5e-6));
        assert_eq!(record["surface"]["dy"].as_f64(), Some(0.5e-6));
        assert!(
            record.get("model").is_none() && record.get("friction").is_none(),
            "{record}"
        );
    }

    #[test]
    fn the_loads_warnings_are_shown_and_recorded_as_the_cli_gives_them() {
        // 1 Pa on a hardness of 1 GPa: F* = 1e-9, below the paper's range.
        let a = aluminium_on_the_map(&[("pressure", "1")]);
        let shown: Vec<String> = serde_json::from_str(&a.warnings()).unwrap();
        assert!(
            shown.iter().any(|w| w.contains("is below the range the paper covers")),
            "{shown:?}"
        );
        let record: Value = serde_json::from_str(&a.record).unwrap();
        let kinds: Vec<&str> = record["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|w| w["kind"].as_str())
            .collect();
        assert!(kinds.contains(&"f_star_below_range"), "{kinds:?}");
        assert_eq!(shown.len(), kinds.len());
    }

    #[test]
    fn a_map_without_intervals_asks_for_dx_as_kefric_does() {
        let e = Analysis::analyse(&text_map(), "h.txt", Options::default())
            .err()
            .unwrap();
        assert_eq!(
            e,
            "h.txt: the file gives no sampling interval dx: give “Δx” (and “Δy” for a map, if it differs), in “unit of Δx, Δy”"
        );
    }

    /// A model the surface's inputs refuse: the statistics are kept and
    /// shown, the error beside them names the page's field.
    #[test]
    fn a_failed_evaluation_keeps_the_statistics() {
        let a = aluminium_on_the_map(&[("hardness", "-1"), ("pressure", "1e6")]);
        let e = a.error().unwrap();
        assert!(e.starts_with("“hardness H”: "), "{e}");
        let record: Value = serde_json::from_str(&a.record).unwrap();
        assert!(record["surface"]["sigma"].as_f64().unwrap() > 0.0);
        assert!(
            record.get("model").is_none() && record.get("friction").is_none(),
            "{record}"
        );
        assert!(a.mu_against_load_rows().is_empty());
    }

    #[test]
    fn materials_go_together_and_a_load_needs_them() {
        let run = |json: &str| {
            Analysis::analyse(&text_map(), "h.txt", Options::parse(json).unwrap())
                .err()
                .unwrap()
        };
        let e = run(r#"{"dx": "1e-6", "e1": "70e9"}"#);
        assert!(
            e.starts_with("“ν₁”: missing: the SI inputs go together (“E₁”, “ν₁”,"),
            "{e}"
        );
        let e = run(r#"{"dx": "1e-6", "pressure": "1e6"}"#);
        assert!(e.starts_with("“pressure”: needs the materials"), "{e}");
    }
}
