//! `kefric surface` and `eval --surface`: a measured surface to the
//! model's inputs and μ, against the library called directly, and bad
//! input.
use crate::common::TempDir;
use crate::support::{assert_bad_input, assert_stderr_has, kefric, stderr};
use ke_friction::topography::{write_x3p, StatsOptions, Surface, Topography};
use ke_friction::{Load, Materials, Model, Named};
use serde_json::Value;

/// Aluminium (softer) on a nickel coating, with adhesion: the pair.
pub(crate) const MATERIALS: Materials = Materials {
    e1: 70e9,
    nu1: 0.33,
    e2: 200e9,
    nu2: 0.31,
    hardness: 1e9,
    delta_gamma: 0.5,
    epsilon: 0.4e-9,
};

pub(crate) const MATERIAL_FLAGS: &[&str] = &[
    "--e1",
    "70e9",
    "--nu1",
    "0.33",
    "--e2",
    "200e9",
    "--nu2",
    "0.31",
    "--hardness",
    "1e9",
    "--delta-gamma",
    "0.5",
    "--epsilon",
    "0.4e-9",
];

/// A smooth synthetic map (n × n, metres) whose ψ lies in the paper's
/// range with [`MATERIALS`] at dx = 2 µm: a few long waves, skewed by a
/// square term.
fn heights(n: usize, phase: f64) -> Vec<f64> {
    (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f64, (k / n) as f64);
            let w = (x * 0.31 + phase).sin()
                + (y * 0.23).cos()
                + 0.7 * (x * 0.17 - y * 0.29 + phase).sin()
                + 0.5 * (x * 0.41 + y * 0.37).cos();
            0.2e-6 * (w + 0.15 * w * w)
        })
        .collect()
}

fn write_npy(dir: &TempDir, name: &str, z: &[f64], n: usize) -> String {
    let bytes: Vec<u8> = z.iter().flat_map(|v| v.to_le_bytes()).collect();
    std::fs::write(dir.join(name), crate::npy::npy("<f8", false, &[n, n], &bytes)).unwrap();
    dir.arg(name)
}

fn json(args: &[&str]) -> Value {
    let o = kefric(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    serde_json::from_slice(&o.stdout).unwrap()
}

fn run(args: &[&str], extra: &[&str]) -> Vec<String> {
    let mut all: Vec<String> = args.iter().map(|s| s.to_string()).collect();
    all.extend(extra.iter().map(|s| s.to_string()));
    all
}

/// `kefric surface` of the map `file` written by [`write_npy`] (dx = 2 µm)
/// with the flags `extra` and [`MATERIAL_FLAGS`].
fn map_args(file: &str, extra: &[&str]) -> Vec<String> {
    let mut args = run(&["surface", file, "--dx", "2", "--xy-unit", "um"], extra);
    args.extend(MATERIAL_FLAGS.iter().map(|s| s.to_string()));
    args
}

fn as_strs(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

#[test]
fn one_surface_force_and_area_give_the_librarys_mu_and_q() {
    let dir = TempDir::new("surface-one");
    let n = 96;
    let z = heights(n, 0.0);
    let file = write_npy(&dir, "map.npy", &z, n);
    let args = map_args(&file, &["--json", "--force", "10", "--area", "1e-5"]);
    let mut v = json(&as_strs(&args));
    // The sensitivity beside μ (checked in `sensitivity_values_are_the_single_runs`).
    assert!(v["friction"]["sensitivity"].is_object(), "{v}");
    v["friction"].as_object_mut().unwrap().remove("sensitivity");

    // The library, called directly.
    let surface = Surface::new(Topography::map(z, n, n, 2e-6, 2e-6).unwrap(), StatsOptions::default()).unwrap();
    let params = surface.params(&MATERIALS, surface.distribution(None).unwrap()).unwrap();
    let load = Load::Force {
        force: 10.0,
        area: 1e-5,
    };
    let friction = load
        .friction(&Model::new(params.clone()).unwrap(), &surface.physical(&MATERIALS))
        .unwrap();
    assert_eq!(v["surface"], serde_json::to_value(surface.stats()).unwrap());
    assert_eq!(v["model"], serde_json::to_value(&params).unwrap());
    assert_eq!(v["friction"], serde_json::to_value(friction).unwrap());
    assert!(v.get("parts").is_none());

    // What the record says: the default distribution is the measured
    // Pearson one; F* = F/(A_n H); Q = μF; h = h*σ.
    let s = &v["surface"];
    assert_eq!(v["model"]["distribution"], "pearson");
    assert_eq!(v["model"]["skewness"], s["skewness"]);
    assert_eq!(v["model"]["kurtosis"], s["kurtosis"]);
    let f = &v["friction"];
    let num = |v: &Value| v.as_f64().unwrap();
    assert!((num(&f["f_star"]) / 1e-3 - 1.0).abs() < 1e-12);
    assert_eq!(num(&f["friction_force"]), num(&f["mu"]) * 10.0);
    assert!((num(&f["separation"]) / (num(&f["h_star"]) * num(&s["sigma"])) - 1.0).abs() < 1e-15);
    let psi = num(&v["model"]["psi"]);
    assert!(
        (0.5..=8.0).contains(&psi),
        "psi = {psi}: the test surface should lie in the paper's range"
    );
    assert!(num(&f["mu"]) > 0.0);
    assert_eq!((num(&s["dx"]), num(&s["dy"])), (2e-6, 2e-6));
}

#[test]
fn text_output_shows_the_intervals_beside_beta_and_psi() {
    let dir = TempDir::new("surface-text");
    let n = 64;
    let file = write_npy(&dir, "map.npy", &heights(n, 0.3), n);
    let args = run(&["surface", &file, "--dx", "2e-6", "--pressure", "1e6"], MATERIAL_FLAGS);
    let o = kefric(&as_strs(&args));
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let line = |start: &str| {
        text.lines()
            .find(|l| l.starts_with(start))
            .unwrap_or_else(|| panic!("no line {start:?} in\n{text}"))
            .to_string()
    };
    assert!(
        line("beta = eta R sigma").contains("dx = 2e-6 m, dy = 2e-6 m"),
        "{text}"
    );
    assert!(line("# model inputs").contains("dx = 2e-6 m, dy = 2e-6 m"), "{text}");
    assert!(line("heights").contains("pearson (skewness"), "{text}");
    assert!(line("mu F/A_n (friction stress)").ends_with("Pa"), "{text}");
    // Without materials: the statistics and a hint, no model.
    let o = kefric(&["surface", &file, "--dx", "2e-6"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(
        text.contains("sigma (Sq)") && !text.contains("# model inputs"),
        "{text}"
    );
}

#[test]
fn two_surfaces_are_their_equivalent_surface() {
    let dir = TempDir::new("surface-pair");
    let n = 80;
    let (za, zb) = (
        heights(n, 0.0),
        heights(n, 1.1).iter().map(|h| -0.6 * h).collect::<Vec<_>>(),
    );
    let a = write_npy(&dir, "a.npy", &za, n);
    let b = write_npy(&dir, "b.npy", &zb, n);
    for family in ["pearson", "empirical"] {
        let args = run(
            &[
                "surface",
                &a,
                &b,
                "--dx",
                "2e-6",
                "--json",
                "--force",
                "5",
                "--area",
                "1e-5",
                "--distribution",
                family,
            ],
            MATERIAL_FLAGS,
        );
        let v = json(&as_strs(&args));
        let surface = Surface::pair(
            Topography::map(za.clone(), n, n, 2e-6, 2e-6).unwrap(),
            Topography::map(zb.clone(), n, n, 2e-6, 2e-6).unwrap(),
            StatsOptions::default(),
        )
        .unwrap();
        assert_eq!(v["surface"], serde_json::to_value(surface.stats()).unwrap());
        assert_eq!(v["parts"].as_array().map(Vec::len), Some(2));
        let params = surface
            .params(
                &MATERIALS,
                surface
                    .distribution(Some(ke_friction::Family::parse(family).unwrap()))
                    .unwrap(),
            )
            .unwrap();
        assert_eq!(v["model"], serde_json::to_value(&params).unwrap());
        let friction = Load::Force { force: 5.0, area: 1e-5 }
            .friction(&Model::new(params).unwrap(), &surface.physical(&MATERIALS))
            .unwrap();
        assert_eq!(v["friction"]["mu"].as_f64(), Some(friction.mu), "{family}");
        // Variances add.
        let var = |s: &Value| s["sigma"].as_f64().unwrap().powi(2);
        let sum = var(&v["parts"][0]) + var(&v["parts"][1]);
        assert!((var(&v["surface"]) / sum - 1.0).abs() < 1e-14);
    }
}

#[test]
fn eval_with_a_surface_agrees_with_surface() {
    let dir = TempDir::new("surface-eval");
    let n = 64;
    let z = heights(n, 0.7);
    let npy = write_npy(&dir, "map.npy", &z, n);
    // The same map as an X3P file, which carries its own intervals.
    let x3p = dir.join("map.x3p");
    write_x3p(&Topography::map(z, n, n, 2e-6, 2e-6).unwrap(), &x3p, 'D').unwrap();
    let x3p = x3p.display().to_string();
    let s = json(&as_strs(&run(
        &["surface", &x3p, "--json", "--pressure", "2e6"],
        MATERIAL_FLAGS,
    )));
    let s_npy = json(&as_strs(&run(
        &["surface", &npy, "--dx", "2e-6", "--json", "--pressure", "2e6"],
        MATERIAL_FLAGS,
    )));
    assert_eq!(s["friction"], s_npy["friction"]);
    let e = json(&as_strs(&run(
        &["eval", "--surface", &x3p, "--f-star", "2e-3", "--json"],
        MATERIAL_FLAGS,
    )));
    for key in [
        "psi",
        "theta",
        "beta",
        "nu",
        "eps_star",
        "distribution",
        "skewness",
        "kurtosis",
    ] {
        assert_eq!(e[key], s["model"][key], "{key}");
    }
    for key in ["mu", "h_star", "f_star"] {
        assert_eq!(e[key], s["friction"][key], "{key}");
    }
    assert_eq!((e["dx"].as_f64(), e["dy"].as_f64()), (Some(2e-6), Some(2e-6)));
    // The text form prints where σ, R, η came from, with the intervals.
    let o = kefric(&as_strs(&run(
        &[
            "eval",
            "--surface",
            &x3p,
            "--f-star",
            "2e-3",
            "--distribution",
            "gaussian",
        ],
        MATERIAL_FLAGS,
    )));
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(
        text.contains(&format!("# sigma, R, eta of {x3p} at dx = 2e-6 m, dy = 2e-6 m")),
        "{text}"
    );
    assert!(!text.contains("heights ="), "gaussian: {text}");
}

#[test]
fn bad_input_names_the_flag() {
    let dir = TempDir::new("surface-bad");
    let n = 64;
    let file = write_npy(&dir, "map.npy", &heights(n, 0.0), n);
    let with = |extra: &[&str]| run(&["surface", &file, "--dx", "2e-6"], extra);
    let with_materials = |extra: &[&str]| run(&as_strs(&with(extra)), MATERIAL_FLAGS);
    // `kefric eval --surface` at an F* with `extra` and the materials.
    let eval = |extra: &[&str]| {
        let args = run(&["eval", "--surface", &file, "--dx", "2e-6"], extra);
        run(&as_strs(&args), &[&["--f-star", "1e-3"][..], MATERIAL_FLAGS].concat())
    };
    let cases: Vec<(Vec<String>, &str)> = vec![
        (run(&["surface", &file], &[]), "--dx"),
        (with(&["--dx", "-1"]), "--dx"),
        (with(&["--force", "10", "--area", "1e-5"]), "--force"),
        (with(&["--distribution", "gaussian"]), "--distribution"),
        (with_materials(&["--force", "-1", "--area", "1e-5"]), "--force"),
        (with_materials(&["--pressure", "0"]), "--pressure"),
        (with(&["--e1", "70e9"]), "--nu1"),
        (
            run(
                &with(&["--hardness", "-1"])
                    .iter()
                    .map(String::as_str)
                    .collect::<Vec<_>>(),
                &MATERIAL_FLAGS[..8],
            ),
            "--hardness",
        ),
        (run(&["surface", &dir.arg("missing.x3p")], &[]), "missing.x3p"),
        (eval(&["--psi", "1"]), "--psi"),
        (eval(&["--sigma", "1e-7"]), "--sigma"),
        (eval(&["--kurtosis", "4"]), "--kurtosis"),
        (
            run(&["eval", "--surface", &file, "--dx", "2e-6", "--f-star", "1e-3"], &[]),
            "--e1",
        ),
    ];
    for (args, needle) in cases {
        let o = kefric(&as_strs(&args));
        assert_bad_input(&o, needle);
    }
    // A surface whose skewness is beyond Pearson's range: the message says
    // so and points to the empirical density.
    let spiky: Vec<f64> = (0..n * n)
        .map(|k| {
            if k % 997 == 0 {
                1e-5
            } else {
                1e-8 * ((k as f64) * 0.37).sin()
            }
        })
        .collect();
    let spiky = write_npy(&dir, "spiky.npy", &spiky, n);
    // The default falls back to the empirical density (Pearson refuses the
    // skewness; MODEL.md, "The default height model") and warns the spikes.
    let o = kefric(&as_strs(&run(&["surface", &spiky, "--dx", "2e-6"], MATERIAL_FLAGS)));
    assert!(o.status.success(), "{}", stderr(&o));
    assert_stderr_has(&o, "the heights have spikes");
    let o = kefric(&as_strs(&run(
        &["surface", &spiky, "--dx", "2e-6", "--distribution", "pearson"],
        MATERIAL_FLAGS,
    )));
    assert_bad_input(&o, "--distribution");
    assert_stderr_has(&o, "skewness");
    assert_stderr_has(&o, "empirical");
}

#[test]
fn plot_surface_draws_the_fits_and_the_histogram() {
    let dir = TempDir::new("surface-plot");
    let n = 64;
    let file = write_npy(&dir, "map.npy", &heights(n, 0.2), n);
    let out = dir.arg("surface.svg");
    let args = run(
        &[
            "plot",
            "surface",
            &file,
            "--dx",
            "2e-6",
            "--f-star",
            "1e-4:1e-2",
            "--out",
            &out,
        ],
        MATERIAL_FLAGS,
    );
    let o = kefric(&as_strs(&args));
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&out).unwrap();
    for text in [
        "gaussian",
        "pearson (Ssk ",
        "empirical (the measured heights)",
        "measured heights",
        "map.npy",
    ] {
        assert!(svg.contains(text), "no {text:?} in the figure");
    }
    // The intervals beside psi (the title may wrap between them).
    assert!(
        svg.contains("at dx = 2e-6 m,") && svg.contains("dy = 2e-6 m"),
        "the intervals beside psi"
    );
    // Materials are required; a bad range names its flag.
    assert_bad_input(
        &kefric(&["plot", "surface", &file, "--dx", "2e-6", "--out", &out]),
        "--e1",
    );
    let args = run(
        &[
            "plot", "surface", &file, "--dx", "2e-6", "--f-star", "1:0.1", "--out", &out,
        ],
        MATERIAL_FLAGS,
    );
    assert_bad_input(&kefric(&as_strs(&args)), "--f-star");
}

/// A file with its own dx and dy (here different): --dx alone does not
/// stand in for its dy (no conflict reported for a --dy never given, the
/// file's dy used); --dx or --dy against the file's are reported naming
/// the flag.
#[test]
fn dx_alone_keeps_the_files_own_dy() {
    let dir = TempDir::new("surface-own-intervals");
    let n = 64;
    let x3p = dir.join("map.x3p");
    write_x3p(&Topography::map(heights(n, 0.3), n, n, 2e-6, 5e-6).unwrap(), &x3p, 'D').unwrap();
    let x3p = x3p.display().to_string();
    let intervals = |extra: &[&str]| {
        let s = json(&as_strs(&run(&["surface", &x3p, "--json"], extra)));
        (s["surface"]["dx"].as_f64(), s["surface"]["dy"].as_f64())
    };
    let own = intervals(&[]);
    assert_eq!(own, (Some(2e-6), Some(5e-6)));
    // --dx that agrees with the file's, with or without --dy.
    assert_eq!(intervals(&["--dx", "2e-6"]), own);
    assert_eq!(intervals(&["--dx", "2", "--xy-unit", "um"]), own);
    // Every length unit of the core: km and angstrom too.
    assert_eq!(intervals(&["--dx", "20000", "--xy-unit", "angstrom"]), own);
    assert_eq!(intervals(&["--dx", "2e-9", "--xy-unit", "km"]), own);
    assert_eq!(intervals(&["--dx", "2e-6", "--dy", "5e-6"]), own);
    // A --dx that contradicts the file's names --dx, not dy.
    let o = kefric(&["surface", &x3p, "--dx", "5e-7"]);
    assert_bad_input(&o, "--dx");
    let e = stderr(&o);
    assert!(e.contains("the file gives dx = 2e-6 m, --dx 5e-7 m"), "{e}");
    assert!(!e.contains("dy ="), "{e}");
    // A --dy given that contradicts the file's names --dy.
    let o = kefric(&["surface", &x3p, "--dx", "2e-6", "--dy", "2e-6"]);
    assert_bad_input(&o, "--dy");
    let e = stderr(&o);
    assert!(e.contains("the file gives dy = 5e-6 m, --dy 2e-6 m"), "{e}");
    // A file with no intervals: --dy defaults to --dx.
    let npy = write_npy(&dir, "map.npy", &heights(n, 0.3), n);
    let s = json(&["surface", &npy, "--dx", "2e-6", "--json"]);
    assert_eq!(
        (s["surface"]["dx"].as_f64(), s["surface"]["dy"].as_f64()),
        (Some(2e-6), Some(2e-6))
    );
}

#[test]
fn surface_help_lists_every_format_of_the_registry_one_line_each() {
    let o = kefric(&["surface", "--help"]);
    assert!(o.status.success());
    let help = String::from_utf8_lossy(&o.stdout);
    for f in ke_friction::topography::Format::all().filter(|f| !f.extensions().is_empty()) {
        let lines: Vec<&str> = help
            .lines()
            .filter(|l| l.trim_start().starts_with(&format!("{} ", f.name())) && l.contains(f.description()))
            .collect();
        assert_eq!(lines.len(), 1, "{}: {lines:?}\n{help}", f.name());
        for e in f.extensions() {
            assert!(
                lines[0].contains(&format!(".{e}")),
                "{}: .{e} missing: {}",
                f.name(),
                lines[0]
            );
        }
    }
}

/// The README's list of formats names formats of the registry only (the
/// full list, from the registry, is `kefric surface --help`'s, which the
/// test above checks; the README points to it).
#[test]
fn the_readmes_formats_are_the_registrys() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../README.md")).unwrap();
    let known: Vec<String> = ke_friction::topography::Format::all()
        .flat_map(|f| f.extensions().iter().map(|e| format!(".{e}")))
        .collect();
    let mut listed = 0;
    for line in readme.lines().filter(|l| l.starts_with("- ")) {
        for word in line
            .split(['`', ' ', ',', '(', ')'])
            .filter(|w| w.len() > 1 && w.starts_with('.'))
        {
            let word = word.trim_end_matches(['.', ';', ':']).to_lowercase();
            if word.chars().skip(1).all(|c| c.is_ascii_alphanumeric()) && word.len() <= 6 {
                assert!(
                    known.contains(&word),
                    "README.md lists {word}, a format the registry does not read"
                );
                listed += 1;
            }
        }
    }
    assert!(listed > 0, "README.md lists no formats");
    assert!(
        readme.contains("kefric surface --help"),
        "README.md does not point to kefric surface --help"
    );
}

#[test]
fn law_with_a_surface_is_the_model_of_eval_with_that_surface() {
    let dir = TempDir::new("surface-law");
    let n = 64;
    let npy = write_npy(&dir, "map.npy", &heights(n, 0.7), n);
    let o = kefric(&as_strs(&run(
        &["law", "--surface", &npy, "--dx", "2e-6", "--pressure", "1e5:1e7:3"],
        MATERIAL_FLAGS,
    )));
    assert!(o.status.success(), "{}", stderr(&o));
    // The CSV's notes are on stderr.
    let notes = stderr(&o);
    assert!(
        notes.contains(&format!("# sigma, R, eta of {npy} at dx = 2e-6 m")),
        "{notes}"
    );
    assert!(notes.contains("# hardness H = 1e9 Pa"), "{notes}");
    let text = String::from_utf8(o.stdout).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("pressure"))
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 3);
    for row in &rows {
        // F* = p/H with H = 1e9 Pa, the material flags' hardness.
        let f = (row[0] / 1e9).to_string();
        let e = json(&as_strs(&run(
            &["eval", "--surface", &npy, "--dx", "2e-6", "--f-star", &f, "--json"],
            MATERIAL_FLAGS,
        )));
        let mu = e["mu"].as_f64().unwrap();
        assert!(
            (row[1] / mu - 1.0).abs() <= ke_friction::CURVE_ACCURACY,
            "{row:?}: {mu}"
        );
    }
}

#[test]
fn instruments_files_give_their_statistics_and_metadata_and_a_wrong_channel_lists_them() {
    for (name, format, nx) in [
        ("sur-2.sur", "sur", 563),
        ("plu-1.plu", "plu", 768),
        ("opd-1.opd", "opd", 640),
        ("al3d-1.al3d", "al3d", 200),
    ] {
        let Some(path) = crate::common::instrument_file(name) else {
            continue;
        };
        let path = path.to_str().unwrap();
        let o = kefric(&["surface", path, "--json"]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let v: Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(v["surface"]["nx"], nx, "{name}");
        assert_eq!(v["metadata"][0]["format"], format, "{name}");
        assert!(v["surface"]["sigma"].as_f64().unwrap() > 0.0, "{name}");
        if format == "opd" {
            assert_bad_input(&kefric(&["surface", path, "--channel", "Intensity"]), "0 Raw");
        }
    }
}

/// Every μ of a surface answer's sensitivity is the single run with that
/// option: each height model (`--distribution`), each end of the band
/// (`--lambda-s`); the text names the range and what gives its ends.
#[test]
fn sensitivity_values_are_the_single_runs() {
    let dir = TempDir::new("surface-sensitivity");
    let n = 96;
    let z = heights(n, 0.0);
    let file = write_npy(&dir, "map.npy", &z, n);
    let base = map_args(&file, &["--force", "10", "--area", "1e-5"]);
    let mut with_json = base.clone();
    with_json.push("--json".into());
    let v = json(&as_strs(&with_json));
    let s = &v["friction"]["sensitivity"];
    let single = |extra: &[&str]| {
        let mut args = with_json.clone();
        args.extend(extra.iter().map(|s| s.to_string()));
        args.extend(["--sensitivity".to_string(), "off".to_string()]);
        let v = json(&as_strs(&args));
        assert!(v["friction"].get("sensitivity").is_none(), "{v}");
        v["friction"]["mu"].as_f64().unwrap()
    };
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
    let families = s["distribution"].as_object().unwrap();
    let mut names = ke_friction::topography::SENSITIVITY_FAMILIES.map(|f| f.name()).to_vec();
    names.sort_unstable();
    assert_eq!(families.keys().map(String::as_str).collect::<Vec<_>>(), names);
    for (family, outcome) in families {
        let mu = outcome["mu"].as_f64().unwrap_or_else(|| panic!("{family}: {outcome}"));
        assert!(close(mu, single(&["--distribution", family])), "{family}");
    }
    let ends = s["lambda_s"].as_array().unwrap();
    assert_eq!(ends.len(), 2);
    // The short end: 2·max(dx, dy) without a cut-off.
    assert_eq!(ends[0]["lambda_s"].as_f64(), Some(4e-6));
    assert!(ends[1]["lambda_s"].as_f64().unwrap() > 4e-6);
    for end in ends {
        let lambda = format!("{:e}", end["lambda_s"].as_f64().unwrap());
        assert!(
            close(end["mu"].as_f64().unwrap(), single(&["--lambda-s", &lambda])),
            "{end}"
        );
    }
    let o = kefric(&as_strs(&base));
    let text = String::from_utf8_lossy(&o.stdout);
    let line = text
        .lines()
        .find(|l| l.starts_with("mu sensitivity"))
        .unwrap_or_else(|| panic!("{text}"));
    assert!(line.contains(" to ") && line.contains("height models"), "{line}");
}
