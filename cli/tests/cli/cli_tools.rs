//! What a new user meets: the default build's safety, one voice for bad
//! numbers, `info`, `params` and the SI flags, `lookup --csv`, and the
//! hints of a failed build.
use crate::common::TempDir;
use crate::support::{assert_bad_input, assert_stderr_has, kefric, kefric_stdin, stderr, SMALL_BUILD};
use ke_friction::{Params, Physical, Table};
use std::process::Command;

fn kefric_in(dir: &std::path::Path, args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_kefric"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

#[test]
fn only_the_default_build_may_write_the_embedded_table() {
    // A scratch copy of the repository's table folder.
    let dir = TempDir::new("safe-build");
    std::fs::create_dir(dir.join("tables")).unwrap();
    let committed = dir.join("tables/default.kft");
    std::fs::write(&committed, Table::embedded_bytes()).unwrap();
    let o = kefric_in(
        &dir.0,
        &[
            "build",
            "--psi",
            "1:2",
            "--theta",
            "0:0.003",
            "--f-star",
            "1e-4:1e-2",
            "--nodes",
            "12,8,12",
            "--tolerance",
            "1e-3",
            "--quiet",
        ],
    );
    assert_bad_input(&o, "--out");
    assert_stderr_has(&o, "tables/default.kft");
    // Any single option off its default is enough.
    let o = kefric_in(&dir.0, &["build", "--seed", "7", "--quiet"]);
    assert_bad_input(&o, "--out");
    assert_eq!(std::fs::read(&committed).unwrap(), Table::embedded_bytes());
    assert_eq!(dir.names("tables"), ["default.kft"]);
    // With --out the same build goes where it is told.
    let mut args = SMALL_BUILD.to_vec();
    args.extend(["--out", "small.kft"]);
    let o = kefric_in(&dir.0, &args);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(dir.join("small.kft").is_file());
    assert_eq!(std::fs::read(&committed).unwrap(), Table::embedded_bytes());
    // The default build alone writes tables/default.kft: the same bytes.
    std::fs::write(&committed, b"stale").unwrap();
    let o = kefric_in(&dir.0, &["build", "--quiet"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(std::fs::read(&committed).unwrap(), Table::embedded_bytes());
}

#[test]
fn every_subcommand_words_a_bad_number_alike() {
    let want = |flag: &str| format!("error: {flag}: 'abc' is not a number (e.g. 0.5 or 1e-3)\n");
    let cases: [(&[&str], &str); 7] = [
        (
            &["eval", "--psi", "1", "--theta", "0.001", "--f-star", "abc"],
            "--f-star",
        ),
        (
            &["eval", "--psi", "abc", "--theta", "0.001", "--f-star", "0.01"],
            "--psi",
        ),
        (
            &["lookup", "--psi", "1", "--theta", "0.001", "--f-star", "abc"],
            "--f-star",
        ),
        (&["build", "--beta", "abc"], "--beta"),
        (&["build", "--psi", "abc:2"], "--psi"),
        (&["params", "--e1", "abc"], "--e1"),
        (&["plot", "table-error", "--theta", "abc", "--out", "x.png"], "--theta"),
    ];
    for (args, flag) in cases {
        let o = kefric(args);
        assert_bad_input(&o, flag);
        assert_eq!(stderr(&o), want(flag), "{args:?}");
    }
    // Ranges say what is wrong, in shortest round-trip numbers.
    let o = kefric(&["build", "--psi", "8:0.5", "--out", "x.kft"]);
    assert_bad_input(&o, "--psi");
    assert_stderr_has(&o, "--psi: lower end 8 must be below upper end 0.5");
    let o = kefric(&["eval", "--psi", "1", "--theta", "0.001", "--f-star", "0.000001:-1:3"]);
    assert_bad_input(&o, "--f-star");
    assert_stderr_has(&o, "-1 is out of range: must be > 0");
    let o = kefric(&["lookup", "--psi", "1", "--theta", "0.001", "--f-star", "0.000001"]);
    assert_bad_input(&o, "--f-star");
    assert_stderr_has(&o, "f_star = 1e-6 is outside the range [1e-5, 0.1]");
    let o = kefric(&[
        "eval", "--fit", "bogus", "--psi", "1", "--theta", "0", "--f-star", "0.01",
    ]);
    assert_bad_input(&o, "--fit");
    assert_stderr_has(
        &o,
        "--fit: fit 'bogus' is unknown: must be one of consistent, as-printed",
    );
    // A switch of the CLI's own: the same wording (the core's NameError).
    let o = kefric(&["build", "--precision", "f16", "--out", "/nonexistent/t.kft"]);
    assert_bad_input(&o, "--precision");
    assert_stderr_has(&o, "--precision: value 'f16' is unknown: must be one of f32, f64");
}

#[test]
fn a_build_that_misses_its_tolerance_suggests_what_can_help() {
    let dir = TempDir::new("hint");
    let mut args: Vec<&str> = SMALL_BUILD.iter().map(|a| if *a == "1" { "1e-5" } else { a }).collect();
    let out = dir.arg("t.kft");
    args.extend(["--out", out.as_str()]);
    let o = kefric(&args);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    // Far above the f32 floor: more nodes (by the 4th-power rule), not f64.
    assert!(err.contains("try nodes = "), "{err}");
    assert!(!err.contains("f64"), "{err}");
    let nodes: Vec<usize> = err
        .split("try nodes = ")
        .nth(1)
        .unwrap()
        .split(|c: char| !(c.is_ascii_digit() || c == ','))
        .next()
        .unwrap()
        .trim_end_matches(',')
        .split(',')
        .map(|n| n.parse().unwrap())
        .collect();
    assert_eq!(nodes.len(), 3);
    assert!(nodes.iter().all(|&n| n > 9), "{nodes:?}");
}

#[test]
fn info_shows_what_a_table_holds() {
    let o = kefric(&["info", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let info = Table::embedded().info();
    assert_eq!(v["model"], "ke");
    assert_eq!(v["fit"], "consistent");
    assert_eq!(v["bytes"].as_u64(), Some(Table::embedded_bytes().len() as u64));
    assert_eq!(v["accuracy"]["max_rel"].as_f64(), Some(info.accuracy.max_rel));
    assert_eq!(v["accuracy"]["p99_rel"].as_f64(), Some(info.accuracy.p99_rel));
    assert_eq!(v["tolerance"].as_f64(), Some(info.tolerance));
    assert_eq!(v["psi"][0].as_f64(), Some(0.5));
    assert_eq!(v["psi"][1].as_f64(), Some(8.0));
    assert_eq!(v["build"]["nodes"], serde_json::json!([33, 33, 33]));
    assert_eq!(v["precision"], "f32");
    // Exactly the core's record.
    assert_eq!(v, serde_json::to_value(info).unwrap());
    let bytes = Table::embedded_bytes();
    let stored = u32::from_le_bytes(bytes[bytes.len() - 4..].try_into().unwrap());
    assert_eq!(v["crc32"].as_u64(), Some(stored.into()));
    assert_eq!(stored, crc32fast::hash(&bytes[..bytes.len() - 4]));
    let o = kefric(&["info"]);
    let text = String::from_utf8_lossy(&o.stdout);
    // The slope's error, measured now: positive, and far below 1.
    let slope: f64 = text
        .split("slope dmu/dF* max relative error ")
        .nth(1)
        .and_then(|t| t.split_whitespace().next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("{text}"));
    assert!(slope > 0.0 && slope < 1e-2, "{slope}");
    assert!(text.contains(&format!("CRC-32 {stored:08x}")), "{text}");
    assert!(text.contains("model:      ke, fit = consistent"), "{text}");
    assert!(
        text.contains("domain:     psi [0.5, 8], theta [0, 0.01], F* [1e-5, 0.1]"),
        "{text}"
    );
    let o = kefric(&["info", "--table", "/no/such/file.kft"]);
    assert_bad_input(&o, "--table");
}

/// Steel on steel (the README's worked example).
pub(crate) const SI: [&str; 20] = [
    "--e1",
    "200e9",
    "--nu1",
    "0.3",
    "--e2",
    "200e9",
    "--nu2",
    "0.3",
    "--hardness",
    "2e9",
    "--sigma",
    "100e-9",
    "--radius",
    "10e-6",
    "--density",
    "4e10",
    "--delta-gamma",
    "0.3",
    "--epsilon",
    "0.4e-9",
];

#[test]
fn params_and_the_si_flags_give_the_librarys_numbers() {
    let phys = Physical {
        e1: 200e9,
        nu1: 0.3,
        e2: 200e9,
        nu2: 0.3,
        hardness: 2e9,
        sigma: 100e-9,
        radius: 10e-6,
        density: 4e10,
        delta_gamma: 0.3,
        epsilon: 0.4e-9,
    };
    let p = Params::from_physical(&phys).unwrap();
    let o = kefric(&[&["params", "--json"][..], &SI].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    for (key, want) in [
        ("psi", p.psi),
        ("theta", p.theta),
        ("beta", p.constants.beta),
        ("nu", p.constants.nu),
        ("eps_star", p.constants.eps_star),
    ] {
        assert_eq!(v[key].as_f64(), Some(want), "{key}");
    }
    // eval with the SI flags is eval at those ψ, θ, β, ν, ε*.
    let o = kefric(&[&["eval", "--json", "--f-star", "0.01"][..], &SI].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let model = ke_friction::Model::new(p.clone()).unwrap();
    assert_eq!(v["psi"].as_f64(), Some(p.psi));
    assert!((v["mu"].as_f64().unwrap() / model.at_f_star(0.01).unwrap().mu.unwrap() - 1.0).abs() < 1e-15);
    // lookup: the SI inputs' β, ν, ε* are the default table's.
    let o = kefric(&[&["lookup", "--json", "--f-star", "0.01"][..], &SI].concat());
    // ψ = 5.66 and θ = 0.0015 lie in the table.
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(
        v["mu"].as_f64(),
        Some(Table::embedded().mu(p.psi, p.theta, 0.01).unwrap())
    );
    // Errors name the flag: one missing, an unphysical one, a mix.
    let o = kefric(&["params", "--e1", "70e9"]);
    assert_bad_input(&o, "--nu1");
    let mut bad = SI.to_vec();
    bad[9] = "-1e9";
    let o = kefric(&[&["params"][..], &bad].concat());
    assert_bad_input(&o, "--hardness");
    let mut low = SI.to_vec();
    low[15] = "1e9";
    let o = kefric(&[&["params"][..], &low].concat());
    assert_bad_input(&o, "--density");
    let o = kefric(&[&["eval", "--psi", "1", "--f-star", "0.01"][..], &SI].concat());
    assert_bad_input(&o, "--psi");
    let mut other = SI.to_vec();
    other[15] = "5e10";
    let o = kefric(&[&["lookup", "--f-star", "0.01"][..], &other].concat());
    assert_bad_input(&o, "--density");
    // The core's refusal (Table::check_constants), naming both values.
    assert_bad_input(&o, "but the table holds beta = 0.04");
    let o = kefric(&[
        "lookup",
        "--psi",
        "1",
        "--theta",
        "0.001",
        "--f-star",
        "0.01",
        "--skewness",
        "0.3",
        "--kurtosis",
        "3.5",
    ]);
    assert_bad_input(
        &o,
        "--kurtosis: distribution = pearson (skewness 0.3, kurtosis 3.5), but the table holds",
    );
}

#[test]
fn lookup_csv_streams_rows_and_stops_at_a_bad_one() {
    let table = Table::embedded();
    let input = "psi,theta,f_star\n1,0.001,0.01\n\n2,0,1e-4\n";
    let o = kefric_stdin(&["lookup", "--csv"], input.as_bytes());
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines[0], "psi,theta,f_star,mu,dmu_df_star,h_star");
    assert_eq!(lines.len(), 3, "{out}");
    for (line, (p, t, f)) in lines[1..].iter().zip([(1.0, 0.001, 0.01), (2.0, 0.0, 1e-4)]) {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let (mu, slope) = table.mu_with_slope(p, t, f).unwrap();
        assert_eq!(v, [p, t, f, mu, slope, table.h_star(p, t, f).unwrap()], "{line}");
    }
    // Without a header, the same rows.
    let o = kefric_stdin(&["lookup", "--csv"], b"1,0.001,0.01\n");
    assert_eq!(String::from_utf8(o.stdout).unwrap().lines().nth(1), Some(lines[1]));
    // A bad row: its line number, exit 2, the rows before it whole, nothing after.
    for (input, needle) in [
        (
            "1,0.001,0.01\n2,abc,0.01\n3,0,0.01\n",
            "line 2: theta: 'abc' is not a number",
        ),
        ("1,0.001,0.01\n2,0,0.01,4\n", "line 2: expected 3 fields"),
        (
            "1,0.001,0.01\n9,0,0.01\n",
            "line 2: psi = 9 is outside the range [0.5, 8]",
        ),
    ] {
        let o = kefric_stdin(&["lookup", "--csv"], input.as_bytes());
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert_stderr_has(&o, needle);
        assert_eq!(stderr(&o).lines().count(), 1);
        let out = String::from_utf8(o.stdout).unwrap();
        assert!(out.ends_with('\n'), "{out:?}");
        assert_eq!(out.lines().count(), 2, "{out}");
        assert_eq!(out.lines().nth(1), Some(lines[1]));
    }
    let o = kefric(&["lookup", "--csv", "--psi", "1"]);
    assert_bad_input(&o, "--csv");
}

#[test]
fn help_states_defaults_and_ranges() {
    let help = |args: &[&str]| String::from_utf8(kefric(args).stdout).unwrap();
    let build = help(&["build", "--help"]);
    for needle in [
        "[default: 33,33,33]",
        "[default: 0.0001]",
        "[default: 10000]",
        "[default: 2]",
        "[default: -1:6:141]",
        "[default: 0.5:8]",
        "[default: 1e-5:0.1]",
    ] {
        assert!(build.contains(needle), "build --help lacks {needle}");
    }
    let eval = help(&["eval", "--help"]);
    for needle in [
        ke_friction::bounds::PSI.range(),
        ke_friction::bounds::BETA.range(),
        "[default: 0.04]",
        "--delta-gamma",
        "J/m²",
    ] {
        assert!(eval.contains(needle), "eval --help lacks {needle}");
    }
    for sub in ["build", "verify", "export", "lookup", "eval", "info", "params"] {
        let text = help(&[sub, "--help"]);
        // Every flag has a description.
        for line in text.lines().filter(|l| l.trim_start().starts_with("--")) {
            let described = line.split("  ").filter(|s| !s.trim().is_empty()).count() > 1;
            let next_line_describes = text.contains(&format!("{line}\n          "));
            assert!(
                described || next_line_describes,
                "{sub} --help: {line:?} has no description"
            );
        }
    }
}

/// Flags the README mentions that belong to other programs (cargo, pip,
/// farm-bench, the compilers), not to kefric.
const NOT_KEFRIC: &[&str] = &[
    "--release",
    "--path",
    "--profile",
    "--bench",
    "--benches",
    "--vs",
    "--root",
    "--target-dir",
    "--locked",
    "--lib",
    "--all-features",
    "--no-deps",
    "--features",
    "--example",
    "--crate-type",
    "--print",
    "--upgrade",
    "--cfg",
    "--cflags",
    "--libs",
    "--system-site-packages",
];

#[test]
fn every_flag_in_the_readme_is_in_some_help() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../README.md")).unwrap();
    let mut help = String::new();
    let subs: &[&[&str]] = &[
        &["eval"],
        &["build"],
        &["verify"],
        &["lookup"],
        &["info"],
        &["params"],
        &["law"],
        &["surface"],
        &["export"],
        &["validate"],
        &["plot", "fig3"],
        &["plot", "curve"],
        &["plot", "table-error"],
        &["plot", "all"],
        &["plot", "surface"],
    ];
    for sub in subs {
        let o = kefric(&[*sub, &["--help"][..]].concat());
        assert!(o.status.success(), "{sub:?} --help");
        help.push_str(&String::from_utf8(o.stdout).unwrap());
    }
    let mut missing = vec![];
    for (i, _) in readme.match_indices("--") {
        let flag: String = readme[i + 2..]
            .chars()
            .take_while(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || *c == '-')
            .collect();
        let flag = format!("--{}", flag.trim_end_matches('-'));
        let starts_with_letter = flag.chars().nth(2).is_some_and(|c| c.is_ascii_lowercase());
        if !starts_with_letter || NOT_KEFRIC.contains(&flag.as_str()) {
            continue;
        }
        let in_help = help.lines().any(|l| l.split([' ', ',', '=']).any(|w| w == flag));
        if !in_help && !missing.contains(&flag) {
            missing.push(flag);
        }
    }
    assert!(missing.is_empty(), "README flags that no --help lists: {missing:?}");
}

/// Whether `name` (a source file in the folder `rel`) is a module that
/// its folder's registry lists: a law (`=> toy::Toy` in
/// src/model/laws/registry.rs), a family (`=> toy::Toy` in
/// src/distribution/mod.rs) or a format (`toy => [ENTRY]` in
/// src/topography/read/mod.rs).
fn registered(root: &std::path::Path, rel: &std::path::Path, name: &str) -> bool {
    let registries = [
        ("src/model/laws", "registry.rs"),
        ("src/distribution", "mod.rs"),
        ("src/topography/read", "mod.rs"),
    ];
    let module = name.trim_end_matches(".rs");
    registries.iter().any(|(folder, file)| {
        rel == std::path::Path::new(folder)
            && std::fs::read_to_string(root.join(folder).join(file))
                .is_ok_and(|text| text.contains(&format!("=> {module}::")) || text.contains(&format!("{module} => [")))
    })
}

#[test]
fn the_architecture_map_lists_every_folder_and_source_file() {
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let map = std::fs::read_to_string(root.join("docs/ARCHITECTURE.md")).unwrap();
    let skip = [
        "target",
        ".git",
        "corpus",
        "artifacts",
        "__pycache__",
        ".pytest_cache",
        "node_modules",
    ];
    let mut missing = vec![];
    let mut stack = vec![std::path::PathBuf::new()];
    while let Some(rel) = stack.pop() {
        for entry in std::fs::read_dir(root.join(&rel)).unwrap() {
            let entry = entry.unwrap();
            let name = entry.file_name().to_string_lossy().into_owned();
            if skip.contains(&name.as_str())
                || name.ends_with(".egg-info")
                || name.starts_with('.') && rel.as_os_str().is_empty() && name != ".ci"
            {
                continue;
            }
            let path = rel.join(&name);
            if entry.file_type().unwrap().is_dir() {
                let shown = format!("`{}/`", path.display());
                if !map.contains(&shown) {
                    missing.push(shown);
                }
                stack.push(path);
            } else if path.starts_with("src") && name.ends_with(".rs") && name != "mod.rs" {
                // Every library source file is named (in backticks) in its
                // row, but for a file of a registry folder that its
                // registry names (one file and one line: a new law, family
                // or format needs no edit of the map).
                let shown = format!("`{name}`");
                if !map.contains(&shown) && !registered(root, &rel, &name) {
                    missing.push(path.display().to_string());
                }
            }
        }
    }
    missing.sort();
    assert!(
        missing.is_empty(),
        "folders and source files docs/ARCHITECTURE.md does not list: {missing:?}"
    );
}

#[test]
fn the_readme_stays_a_short_manual() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../README.md")).unwrap();
    let lines = readme.lines().count();
    assert!(
        lines <= 250,
        "README.md has {lines} lines: move reference text to docs/ (the limit is 250)"
    );
    for doc in [
        "docs/REFERENCE.md",
        "docs/RELIABILITY.md",
        "docs/ARCHITECTURE.md",
        "docs/MODEL.md",
    ] {
        assert!(readme.contains(doc), "the README does not link {doc}");
    }
}

/// The numbers of a line of text output (`2.08`, `1.0e-2`; the words
/// and `name = value` pairs' names skipped).
fn numbers_of(line: &str) -> Vec<f64> {
    line.split([' ', ',', '='])
        .filter_map(|w| w.trim().parse::<f64>().ok())
        .collect()
}

/// The README's first example (`kefric eval` of steel on steel) shows
/// what the program prints: the same columns, the same numbers (to the
/// 6 digits printed), and a definition of every column below it.
#[test]
fn the_readmes_first_example_shows_its_output_and_defines_its_columns() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../README.md")).unwrap();
    let start = readme.find("kefric eval --e1").expect("the README's first example");
    let command: String = readme[start..]
        .lines()
        .take_while(|l| !l.starts_with("```"))
        .map(|l| l.trim().trim_end_matches('\\'))
        .collect::<Vec<_>>()
        .join(" ");
    let args: Vec<&str> = command.split_whitespace().skip(1).collect();
    let o = kefric(&args);
    assert!(o.status.success(), "{command}: {}", stderr(&o));
    let printed = String::from_utf8(o.stdout).unwrap();
    let block_at = start + readme[start..].find("```text\n").expect("its output, in a text block") + 8;
    let block_end = block_at + readme[block_at..].find("```").unwrap();
    let shown: Vec<&str> = readme[block_at..block_end].lines().collect();
    let printed: Vec<&str> = printed.lines().collect();
    assert_eq!(shown.len(), printed.len(), "shown:\n{shown:#?}\nprinted:\n{printed:#?}");
    for (s, p) in shown.iter().zip(&printed) {
        let words = |l: &str| -> Vec<String> {
            l.split([' ', ',', '='])
                .filter(|w| !w.is_empty() && w.parse::<f64>().is_err())
                .map(str::to_string)
                .collect()
        };
        assert_eq!(words(s), words(p), "the README shows {s:?}, the program prints {p:?}");
        let (a, b) = (numbers_of(s), numbers_of(p));
        assert_eq!(a.len(), b.len(), "{s:?} against {p:?}");
        for (x, y) in a.iter().zip(&b) {
            // The README's numbers are the program's, as printed (at
            // least 6 significant digits): 1e-5 relative.
            assert!(
                (x - y).abs() <= 1e-5 * y.abs(),
                "the README shows {x}, the program prints {y}"
            );
        }
    }
    // Every column of the table is defined in the paragraph below it.
    let header = printed
        .iter()
        .find(|l| l.trim_start().starts_with("h*"))
        .expect("a header line");
    let after = readme[block_end + 3..].trim_start();
    let paragraph = &after[..after.find("\n\n").unwrap_or(after.len())];
    for column in header.split_whitespace() {
        assert!(
            paragraph.contains(&format!("`{column}`")),
            "the README does not define the column {column} below its first example"
        );
    }
}

/// Every compiler line the docs and examples show (`cc`, `gcc`,
/// `gfortran`) optimises (`-O2`): an unoptimised build of the examples
/// is slower by half again (issue 37); and the CMake example defaults
/// to Release.
#[test]
fn every_build_line_shown_optimises() {
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let mut files = vec![
        root.join("README.md"),
        root.join("docs/REFERENCE.md"),
        root.join("ffi/install.sh"),
    ];
    for entry in std::fs::read_dir(root.join("ffi/examples")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "c" || e == "f90") {
            files.push(path);
        }
    }
    let mut lines = 0;
    let mut unoptimised = vec![];
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        for line in text.lines() {
            // The command after comment leaders and labels (`#   C:      cc …`).
            let command = line.trim_start_matches(['#', '!', '*', '/', ' ']);
            let command = command.split_once(": ").map_or(command, |(label, rest)| {
                if label.split_whitespace().count() == 1 {
                    rest.trim_start()
                } else {
                    command
                }
            });
            if ["cc ", "gcc ", "gfortran "].iter().any(|c| command.starts_with(c)) {
                lines += 1;
                if !command.contains("-O") {
                    unoptimised.push(format!("{}: {line}", file.display()));
                }
            }
        }
    }
    assert!(lines >= 6, "only {lines} build lines found");
    assert!(unoptimised.is_empty(), "build lines without -O2: {unoptimised:#?}");
    let cmake = std::fs::read_to_string(root.join("ffi/examples/cmake/CMakeLists.txt")).unwrap();
    assert!(
        cmake.contains("set(CMAKE_BUILD_TYPE Release CACHE STRING"),
        "the CMake example does not default to Release"
    );
}
