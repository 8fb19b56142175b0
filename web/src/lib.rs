//! The web page's analysis: `kefric surface` compiled to WebAssembly.
//!
//! The page (`web/static/`) hands a file's bytes and its options (the URL
//! query: `kefric surface`'s flags with `_` for `-`, [`KEYS`]) to
//! [`Analysis::new`], which reads the file with the core's reader registry
//! ([`read_bytes`]), takes the statistics and, with materials and a load,
//! μ exactly as `kefric surface --json` does, and keeps the core's record
//! ([`SurfaceRecord`]). The curves (μ against load, μ, ψ and β against
//! λs, the PSD, the height map and histogram) are further methods. Every
//! result crosses to JavaScript as JSON text or a `Float64Array`.

use ke_friction::flags::{self, flag};
use ke_friction::topography::{
    complete_part, psd_all, read_bytes, read_dy_defaulting_to_dx, scan, Channel, Derivative, Detrend, Evaluation,
    Format, ReadError, ReadOptions, ScanRange, StatsOptions, Surface, SurfaceModel, SurfaceRecord, Topography, Window,
    MAX_POINTS,
};
use ke_friction::{
    Family, Fit, Friction, HeightDistribution, LengthUnit, Load, Materials, Model, ModelKind, Named, Params, Shortest,
    Warnings,
};
use serde_json::{json, Value};
use std::collections::BTreeMap;
use wasm_bindgen::prelude::*;

/// The options the page takes, as URL query keys, in the order the
/// equivalent command line gives them: each is `kefric surface`'s flag
/// with `_` for `-` (`lambda_s` is `--lambda-s`).
pub const KEYS: &[&str] = &[
    "dx",
    "dy",
    "xy_unit",
    "z_unit",
    "max_points",
    "channel",
    "detrend",
    "derivative",
    "lambda_s",
    "lambda_c",
    "tip_radius",
    "resolution",
    "e1",
    "nu1",
    "e2",
    "nu2",
    "hardness",
    "delta_gamma",
    "epsilon",
    "distribution",
    "fit",
    "model",
    "force",
    "area",
    "pressure",
];

/// The loads of the μ-against-load curve: the given load times
/// 10^(k/10) for k in this range (three decades below, one above).
const LOAD_STEPS: std::ops::RangeInclusive<i32> = -30..=10;

/// The page's options: key → value text, every key one of [`KEYS`].
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
            if !KEYS.contains(&key.as_str()) {
                return Err(format!("{key}: unknown option: must be one of {}", KEYS.join(", ")));
            }
            let value = value.trim().to_string();
            if !value.is_empty() {
                values.insert(key, value);
            }
        }
        Ok(Options { values })
    }

    fn get(&self, key: &str) -> Option<&str> {
        self.values.get(key).map(String::as_str)
    }

    /// A number: finite, or an error naming the flag (the CLI's wording).
    fn number(&self, key: &str) -> Result<Option<f64>, String> {
        let Some(text) = self.get(key) else { return Ok(None) };
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(Some(v)),
            Ok(_) => Err(format!("{}: '{text}' is not a finite number", flag(key))),
            Err(_) => Err(format!("{}: '{text}' is not a number (e.g. 0.5 or 1e-3)", flag(key))),
        }
    }

    /// One of a core name list ([`Named`]), or `default`.
    fn named<T: Named>(&self, key: &str, default: T) -> Result<T, String> {
        match self.get(key) {
            None => Ok(default),
            Some(text) => T::parse(text).map_err(|e| format!("{}: {e}", flag(key))),
        }
    }

    /// The equivalent command line: `kefric surface FILE … --json`.
    pub fn command(&self, file: &str) -> String {
        let mut words = vec!["kefric".to_string(), "surface".to_string(), quote(file)];
        for key in KEYS {
            if let Some(v) = self.get(key) {
                words.push(flag(key));
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
    stats_options: StatsOptions,
    cutoff: Option<f64>,
    surface: Surface,
    materials: Option<Materials>,
    family: Option<Family>,
    fit: Fit,
    model_kind: ModelKind,
    load: Option<Load>,
    params: Option<Params>,
    friction: Option<Friction>,
    /// The statistics' and the load's warnings, as the CLI gives them.
    warnings: Warnings,
    /// The CLI's other `warning:` lines (`flags::auto_without_cutoff`).
    notes: Vec<String>,
    record: String,
}

impl Analysis {
    /// The measured topography (the surface's one part: its own, not a
    /// second copy of the heights).
    fn topography(&self) -> &Topography {
        &self.surface.parts()[0].0
    }

    /// The analysis of `bytes`, the file `name`, with `options`; the error
    /// is the CLI's message (without its `error: `).
    pub fn analyse(bytes: &[u8], name: &str, options: Options) -> Result<Analysis, String> {
        let xy_unit = options.named("xy_unit", LengthUnit::M)?.metres();
        let interval = |key: &str| -> Result<Option<f64>, String> {
            match options.number(key)? {
                Some(v) if v <= 0.0 => Err(format!("{}: {} is out of range: must be > 0", flag(key), Shortest(v))),
                v => Ok(v.map(|v| v * xy_unit)),
            }
        };
        let max_points = match options.get("max_points") {
            None => MAX_POINTS,
            Some(text) => match text.parse::<u64>() {
                Ok(n) if n >= 1 => n,
                _ => {
                    return Err(format!(
                        "--max-points: '{text}' is out of range: must be a whole number >= 1"
                    ))
                }
            },
        };
        let read_options = ReadOptions {
            dx: interval("dx")?,
            dy: interval("dy")?,
            z_unit: options.named("z_unit", LengthUnit::M)?.metres(),
            xy_unit,
            max_points,
            channel: options
                .get("channel")
                .map(|c| c.parse::<Channel>().unwrap_or_else(|never| match never {})),
            ..ReadOptions::default()
        };
        let topography =
            read_dy_defaulting_to_dx(&read_options, |o| read_bytes(bytes, name, o)).map_err(|e| match e {
                ReadError::NeedInterval { name: which, .. } => flags::no_interval(format!("surface: {name}"), which),
                e => format!("surface: {e}"),
            })?;

        // The reliability cut-off and λs as `--tip-radius`, `--resolution`
        // and `--lambda-s [auto]` give them.
        let (resolution, tip_radius) = (options.number("resolution")?, options.number("tip_radius")?);
        let reliability = || flags::reliability_cutoff(&topography, resolution, tip_radius);
        let mut notes = Vec::new();
        let lambda_s = match options.get("lambda_s") {
            None => None,
            Some("auto") => {
                let cutoff = reliability().map_err(|e| format!("surface: {name}: --lambda-s auto: {e}"))?;
                if cutoff.is_none() {
                    notes.push(flags::auto_without_cutoff(
                        name,
                        flags::LAMBDA_S_TIP_FLAGS,
                        tip_radius.unwrap_or(f64::NAN),
                    ));
                }
                cutoff
            }
            Some(_) => options.number("lambda_s")?,
        };
        let cutoff = match (resolution, tip_radius) {
            (None, None) => None,
            _ => reliability().map_err(|e| format!("surface: {name}: {e}"))?,
        };
        let stats_options = StatsOptions {
            detrend: options.named("detrend", Detrend::Plane)?,
            derivative: options.named("derivative", Derivative::FiniteDifference)?,
            lambda_s,
            lambda_c: options.number("lambda_c")?,
        };
        let mut surface = Surface::new(topography, stats_options).map_err(|e| format!("surface {name}: {e}"))?;
        if let Some(cutoff) = cutoff {
            surface.check_reliability(cutoff);
        }

        let load = Load::from_parts(
            options.number("force")?,
            options.number("area")?,
            options.number("pressure")?,
        )
        .map_err(|e| format!("--force: {e} (--pressure)"))?;
        if let Some(load) = &load {
            load.pressure()
                .map_err(|e| format!("{}: {e}", flag(e.name.split(' ').next().unwrap_or(e.name))))?;
        }
        let names: Vec<String> = Materials::FIELDS.iter().map(|k| flag(k)).collect();
        let given: Vec<(&str, Option<f64>)> = names
            .iter()
            .zip(Materials::FIELDS)
            .map(|(name, k)| Ok((name.as_str(), options.number(k)?)))
            .collect::<Result<_, String>>()?;
        let materials = if given.iter().any(|(_, v)| v.is_some()) {
            let mut seven = [0.0; 7];
            seven.copy_from_slice(&flags::together(&given)?);
            Some(Materials::from_array(seven))
        } else {
            let needs = if options.get("distribution").is_some() {
                Some("--distribution")
            } else if load.is_some() {
                Some(if options.get("pressure").is_some() {
                    "--pressure"
                } else {
                    "--force"
                })
            } else {
                None
            };
            if let Some(needs) = needs {
                return Err(flags::materials_needed(needs));
            }
            None
        };
        let family = options
            .get("distribution")
            .map(Family::parse)
            .transpose()
            .map_err(|e| format!("--distribution: {e}"))?;
        let fit = options.named("fit", Fit::Consistent)?;
        let model_kind = options.named("model", ModelKind::KogutEtsion)?;
        let mut analysis = Analysis {
            name: name.to_string(),
            options,
            stats_options,
            cutoff,
            surface,
            materials,
            family,
            fit,
            model_kind,
            load,
            params: None,
            friction: None,
            warnings: Warnings::new(),
            notes,
            record: String::new(),
        };
        let evaluation = analysis.evaluate(&analysis.surface, analysis.load)?;
        // The warnings as the CLI records them: the statistics' and the load's.
        let mut warnings = Warnings::new();
        warnings.extend(analysis.surface.stats().warnings.iter().cloned());
        if let Some(e) = &evaluation {
            e.note_into(&mut warnings);
        }
        let (params, friction) = match evaluation {
            Some(mut e) => (Some(e.params), e.frictions.pop()),
            None => (None, None),
        };
        let record = SurfaceRecord::new(
            vec![name.to_string()],
            &analysis.surface,
            params.as_ref(),
            friction.as_ref(),
        )
        .with_warnings(&warnings);
        analysis.record = serde_json::to_string(&record).map_err(|e| format!("the record: {e}"))?;
        analysis.params = params;
        analysis.friction = friction;
        analysis.warnings = warnings;
        Ok(analysis)
    }

    /// The model's inputs of `surface` with the materials and, with `load`,
    /// the friction and its warnings ([`Surface::evaluate`], its failure
    /// in the CLI's words); `None` without materials.
    fn evaluate(&self, surface: &Surface, load: Option<Load>) -> Result<Option<Evaluation>, String> {
        let Some(materials) = self.materials else {
            return Ok(None);
        };
        let how = SurfaceModel {
            materials,
            family: self.family,
            fit: self.fit,
            kind: self.model_kind,
        };
        surface
            .evaluate(&how, load.as_slice())
            .map(Some)
            .map_err(|e| flags::evaluate_failure(&e, self.family, self.load_flag()))
    }

    fn load_flag(&self) -> &'static str {
        if self.options.get("pressure").is_some() {
            "--pressure"
        } else {
            "--force"
        }
    }

    /// μ at loads around the given one: (load in N or Pa, μ) rows.
    pub fn mu_against_load_rows(&self) -> Vec<(f64, f64)> {
        let (Some(load), Some(params), Some(materials)) = (self.load, &self.params, &self.materials) else {
            return Vec::new();
        };
        let Ok(model) = Model::new(params.clone()) else {
            return Vec::new();
        };
        let physical = self.surface.physical(materials);
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
        let rows = scan(self.topography(), &self.stats_options, &range, self.cutoff, progress)
            .map_err(|e| format!("--scan: {e}"))?;
        let rows: Vec<Value> = rows
            .iter()
            .map(|row| {
                let mut r = json!({ "lambda_s": row.lambda_s, "reliable": row.reliable });
                match &row.surface {
                    Ok(surface) => {
                        r["beta"] = surface.stats().beta.into();
                        match self.evaluate(surface, self.load) {
                            Ok(Some(e)) => {
                                r["psi"] = e.params.psi.into();
                                if let Some(f) = e.frictions.first() {
                                    r["mu"] = f.mu.into();
                                }
                            }
                            Ok(None) => {}
                            Err(e) => r["error"] = e.into(),
                        }
                    }
                    Err(e) => r["error"] = e.to_string().into(),
                }
                r
            })
            .collect();
        Ok(json!({ "cutoff": self.cutoff, "rows": rows }))
    }

    /// The height histogram of the heights the statistics see (`bins`
    /// bins over ±4σ), as densities (1/m), with the Gaussian and Pearson
    /// densities of the measured σ, Sk, K at the bins' centres.
    pub fn histogram_value(&self, bins: usize) -> Result<Value, String> {
        let bins = bins.clamp(4, 400);
        let heights = self
            .topography()
            .band_heights(&self.stats_options)
            .map_err(|e| e.to_string())?;
        let s = self.surface.stats();
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
    /// `options_json` (a JSON object of strings, keys of [`KEYS`]); a
    /// failure throws the CLI's message.
    #[wasm_bindgen(constructor)]
    pub fn new(bytes: &[u8], name: &str, options_json: &str) -> Result<Analysis, JsError> {
        let options = Options::parse(options_json).map_err(|e| JsError::new(&e))?;
        Analysis::analyse(bytes, name, options).map_err(|e| JsError::new(&e))
    }

    /// The record: exactly `kefric surface --json`'s.
    pub fn record(&self) -> String {
        self.record.clone()
    }

    /// The warnings (the statistics' and the load's), once a kind, as
    /// the CLI prints them on stderr (JSON list).
    pub fn warnings(&self) -> String {
        let notes = self.notes.iter().map(|s| format!("warning: {s}"));
        let w: Vec<String> = notes
            .chain(self.warnings.summaries().map(|s| format!("warning: {s}")))
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
        json!({ "unit": unit, "load": load, "mu": mu }).to_string()
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
        let (part, rectangle) = complete_part(self.topography()).map_err(|e| JsError::new(&format!("--psd: {e}")))?;
        let detrended = part
            .detrended_topography(self.stats_options.detrend)
            .map_err(|e| JsError::new(&e.to_string()))?;
        let spectra = psd_all(&detrended, Window::None).map_err(|e| JsError::new(&format!("--psd: {e}")))?;
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
            .detrended(self.stats_options.detrend)
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

/// The page's names, from the core: the option keys ([`KEYS`]), the
/// surface formats of the reader registry (name, description,
/// extensions), and the values of each named option (JSON).
#[wasm_bindgen]
pub fn names() -> String {
    let formats: Vec<Value> = Format::all()
        .map(|f| json!({ "name": f.name(), "description": f.description(), "extensions": f.extensions() }))
        .collect();
    json!({
        "keys": KEYS,
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
    fn an_unknown_option_is_refused_naming_the_valid_keys() {
        let e = Options::parse(r#"{"e3": "1"}"#).unwrap_err();
        assert!(e.starts_with("e3: unknown option: must be one of dx, dy"), "{e}");
    }

    #[test]
    fn the_command_line_gives_the_flags_in_order_and_quotes_odd_words() {
        let o = Options::parse(r#"{"pressure": "1e6", "lambda_s": "2e-6", "dx": "1e-6", "fit": ""}"#).unwrap();
        assert_eq!(
            o.command("my file.x3p"),
            "kefric surface 'my file.x3p' --dx 1e-6 --lambda-s 2e-6 --pressure 1e6 --json"
        );
    }

    /// A 40 × 30 text map (heights in µm, a few incommensurate waves).
    fn text_map() -> Vec<u8> {
        let mut text = String::new();
        for j in 0..30 {
            let row: Vec<String> = (0..40)
                .map(|i| {
                    format!(
                        "{:.6}",
                        (0.37 * i as f64).sin() + (0.23 * j as f64 + 0.11 * i as f64).cos()
                    )
                })
                .collect();
            text.push_str(&row.join(" "));
            text.push('\n');
        }
        text.into_bytes()
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
        let options = Options::parse(
            r#"{"dx": "0.5", "xy_unit": "um", "z_unit": "um", "e1": "70e9", "nu1": "0.33", "e2": "200e9",
                "nu2": "0.31", "hardness": "1e9", "delta_gamma": "0.5", "epsilon": "0.4e-9", "pressure": "1"}"#,
        )
        .unwrap();
        let a = Analysis::analyse(&text_map(), "h.txt", options).unwrap();
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
            "surface: h.txt: the file gives no sampling interval dx: give --dx (and --dy for a map, if it differs), in --xy-unit"
        );
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
            e.starts_with("--nu1: missing: the SI inputs go together (--e1, --nu1,"),
            "{e}"
        );
        let e = run(r#"{"dx": "1e-6", "pressure": "1e6"}"#);
        assert!(e.starts_with("--pressure: needs the materials"), "{e}");
    }
}
