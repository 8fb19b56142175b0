//! `kefric plot`: the paper's figures as PNGs of the promised size, the
//! curve and error-map subcommands on the embedded table, SVG output, and
//! bad input (exit 2, one line naming the flag).
use crate::common::TempDir;
use crate::support::{assert_bad_input, assert_stderr_has, kefric, stderr};
use std::path::Path;

/// Every image is 2000 × 1500 pixels by default (`ke_friction::figures::SIZE`:
/// 1000 × 750 times the default `--scale` 2).
const WIDTH: u32 = 2000;
const HEIGHT: u32 = 1500;
const PNG_MAGIC: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];

/// Asserts `path` is a PNG (signature, then an IHDR chunk) of WIDTH × HEIGHT.
#[track_caller]
fn assert_png(path: &Path) {
    assert_png_size(path, (WIDTH, HEIGHT));
}

/// Asserts `path` is a PNG of `size` pixels.
#[track_caller]
fn assert_png_size(path: &Path, size: (u32, u32)) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(bytes.len() > 10_000, "{}: only {} bytes", path.display(), bytes.len());
    assert_eq!(bytes[..8], PNG_MAGIC, "{}: not a PNG", path.display());
    assert_eq!(&bytes[12..16], b"IHDR", "{}: no IHDR chunk", path.display());
    let be = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    assert_eq!((be(16), be(20)), size, "{}: image size", path.display());
}

#[test]
fn the_default_size_is_twice_the_old_1000_by_750() {
    assert_eq!(ke_friction::figures::SIZE, (WIDTH, HEIGHT));
    assert_eq!(ke_friction::figures::BASE_SIZE, (1000, 750));
}

/// `--scale N` draws 1000·N × 750·N pixels, and draws everything N times
/// larger, not just on a bigger canvas: the SVG's curves are 3 px wide at
/// scale 1 and 9 px at scale 3, and its caption's font three times as large.
/// Scales outside 1–3 are bad input naming the flag.
#[test]
fn scale_sets_the_size_and_scales_lines_and_text_alike() {
    let dir = TempDir::new("scale");
    for (scale, size) in [("1", (1000, 750)), ("3", (3000, 2250))] {
        let name = format!("f3-{scale}.png");
        let o = kefric(&["plot", "fig3", "--scale", scale, "--out", &dir.arg(&name)]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert_png_size(&dir.join(&name), size);
        let o = kefric(&[
            "plot",
            "fig3",
            "--scale",
            scale,
            "--out",
            &dir.arg(&format!("f3-{scale}.svg")),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let svg = std::fs::read_to_string(dir.join(&format!("f3-{scale}.svg"))).unwrap();
        assert!(
            svg.contains(&format!(r#"width="{}" height="{}""#, size.0, size.1)),
            "{scale}"
        );
    }
    let svg1 = std::fs::read_to_string(dir.join("f3-1.svg")).unwrap();
    let svg3 = std::fs::read_to_string(dir.join("f3-3.svg")).unwrap();
    assert!(svg1.contains(r#"stroke-width="3""#), "scale 1: no 3 px line");
    assert!(!svg1.contains(r#"stroke-width="9""#), "scale 1: a 9 px line");
    assert!(svg3.contains(r#"stroke-width="9""#), "scale 3: no 9 px line");
    let caption_px = |svg: &str| -> f64 {
        let at = svg.find("font-size=\"").expect("a text") + "font-size=\"".len();
        svg[at..at + svg[at..].find('"').unwrap()].parse().unwrap()
    };
    let (f1, f3) = (caption_px(&svg1), caption_px(&svg3));
    assert!(
        (f3 / f1 - 3.0).abs() < 1e-9,
        "caption {f1} px at scale 1, {f3} px at scale 3"
    );
    for bad in ["0", "4", "x", "-1"] {
        let o = kefric(&["plot", "fig3", "--scale", bad, "--out", &dir.arg("bad.png")]);
        assert_bad_input(&o, "--scale");
    }
    assert!(!dir.join("bad.png").exists());
}

#[test]
fn plot_all_writes_four_pngs_of_2000_by_1500() {
    let dir = TempDir::new("all");
    let t0 = std::time::Instant::now();
    // A missing directory is created, with its parents.
    let o = kefric(&["plot", "all", "--out-dir", &dir.arg("new/figures")]);
    assert!(o.status.success(), "{}", stderr(&o));
    eprintln!("plot all: {:.2} s", t0.elapsed().as_secs_f64());
    for name in ["fig3.png", "fig4.png", "fig5.png", "fig6.png"] {
        assert_png(&dir.join("new/figures").join(name));
    }
}

#[test]
fn single_figures_write_png_or_svg_by_extension() {
    let dir = TempDir::new("single");
    let o = kefric(&["plot", "fig4", "--out", &dir.arg("f4.PNG")]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_png(&dir.join("f4.PNG"));
    let o = kefric(&["plot", "fig5", "--out", &dir.arg("f5.svg")]);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(dir.join("f5.svg")).unwrap();
    assert!(svg.starts_with("<svg"), "{}", &svg[..svg.len().min(80)]);
    assert!(svg.contains(r#"width="2000" height="1500""#));
    // Fig. 5 names the comparison model in its legend, and has a second
    // panel on a logarithmic μ axis.
    assert!(svg.contains("CEB-type (approx.)"));
    assert!(svg.contains("μ (log scale)"));
    // Fig. 6 gives the three θ markers of distinct shapes: the legend's
    // samples are filled polygons in the three colours.
    let o = kefric(&["plot", "fig6", "--out", &dir.arg("f6.svg")]);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(dir.join("f6.svg")).unwrap();
    for colour in ["#0072B2", "#D55E00", "#009E73"] {
        let polygons = svg.matches(&format!(r#"fill="{colour}" points="#)).count();
        assert!(polygons >= 10, "{colour}: {polygons} markers");
    }
}

/// Runs `kefric plot ARGS --out DIR/NAME` and asserts it wrote a PNG.
#[track_caller]
fn assert_plots(dir: &TempDir, args: &[&str], name: &str) {
    let out = dir.arg(name);
    let o = kefric(&[&["plot"], args, &["--out", &out]].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    assert_png(&dir.join(name));
}

#[test]
fn curve_overlays_the_embedded_table_and_a_table_file() {
    let dir = TempDir::new("curve");
    // `--table` alone: the embedded default table.
    assert_plots(&dir, &["curve", "--psi", "1", "--theta", "0.003", "--table"], "a.png");
    // The same table from its file.
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/../tables/default.kft");
    assert_plots(
        &dir,
        &["curve", "--psi", "0.7", "--theta", "0.001", "--table", file],
        "b.png",
    );
    // Without a table, and for the CEB-type model.
    assert_plots(
        &dir,
        &["curve", "--psi", "2", "--theta", "0.003", "--model", "ceb"],
        "c.png",
    );
}

#[test]
fn table_error_maps_the_embedded_table() {
    let dir = TempDir::new("table-error");
    assert_plots(&dir, &["table-error"], "e.png");
    assert_plots(&dir, &["table-error", "--theta", "0"], "e0.png");
}

#[test]
fn bad_input_exits_2_with_one_line_naming_the_flag() {
    let dir = TempDir::new("bad");
    let o = kefric(&["plot", "fig3", "--out", &dir.arg("fig3.jpg")]);
    assert_bad_input(&o, "--out");
    assert_stderr_has(&o, ".png or .svg");
    assert!(!dir.join("fig3.jpg").exists());
    let o = kefric(&["plot", "fig3", "--out", &dir.arg("missing/fig3.png")]);
    assert_bad_input(&o, "--out");
    assert_stderr_has(&o, "does not exist");
    let elsewhere = TempDir::new("bad-out-dir");
    std::fs::write(elsewhere.join("a_file"), b"x").unwrap();
    let o = kefric(&["plot", "all", "--out-dir", &elsewhere.arg("a_file")]);
    assert_bad_input(&o, "--out-dir");
    assert_stderr_has(&o, "is not a directory");
    let (c_png, e_png, none) = (dir.arg("c.png"), dir.arg("e.png"), dir.arg("none.kft"));
    let cases: [(&[&str], &str); 5] = [
        (
            &["curve", "--psi", "1", "--theta", "0.02", "--table", "--out", &c_png],
            "--theta",
        ),
        (
            &[
                "curve", "--psi", "1", "--theta", "0.003", "--beta", "0.05", "--table", "--out", &c_png,
            ],
            "--table",
        ),
        (&["curve", "--psi", "-1", "--theta", "0.003", "--out", &c_png], "--psi"),
        (&["table-error", "--theta", "0.5", "--out", &e_png], "--theta"),
        (&["table-error", "--table", &none, "--out", &e_png], "--table"),
    ];
    for (args, flag) in cases {
        assert_bad_input(&kefric(&[&["plot"], args].concat()), flag);
    }
    assert_eq!(std::fs::read_dir(&dir.0).unwrap().count(), 0, "bad input wrote a file");
}

/// `plot table-error --help` states the default θ and the embedded table's
/// ranges; they are the embedded table's own.
#[test]
fn table_error_help_states_the_default_and_the_tables_ranges() {
    let d = ke_friction::Table::embedded().domain().clone();
    assert_eq!((d.theta, d.psi, d.f_star), ((0.0, 0.01), (0.5, 8.0), (1e-5, 0.1)));
    let o = kefric(&["plot", "table-error", "--help"]);
    assert!(o.status.success());
    let help = String::from_utf8_lossy(&o.stdout).replace('\n', " ");
    for text in [
        "[default: 0.003]",
        "θ range (the embedded table's: 0 to 0.01)",
        "ψ 0.5 to 8, F* 1e-5 to 0.1",
        "N (a whole number from 1 to 3) [default: 2]",
    ] {
        assert!(help.contains(text), "{text:?} not in {help}");
    }
}

/// `plot distributions` draws μ(F*) for the Gaussian and the Pearson set
/// over their densities, as a PNG of the default size; bad values name
/// their flag (exit 2), and nothing is written for them.
#[test]
fn distributions_draws_a_png_and_bad_flags_exit_2() {
    let dir = TempDir::new("distributions");
    let o = kefric(&["plot", "distributions", "--out", &dir.arg("d.png")]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_png(&dir.join("d.png"));
    let o = kefric(&[
        "plot",
        "distributions",
        "--psi",
        "2",
        "--theta",
        "0.003",
        "--scale",
        "1",
        "--out",
        &dir.arg("d2.png"),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_png_size(&dir.join("d2.png"), (1000, 750));
    for (flag, value, out) in [
        ("--psi", "x", "bad.png"),
        ("--psi", "-1", "bad.png"),
        ("--theta", "1e9", "bad.png"),
        ("--out", "", "bad.jpg"),
    ] {
        let mut args = vec!["plot", "distributions"];
        if !value.is_empty() {
            args.extend([flag, value]);
        }
        let path = dir.arg(out);
        args.extend(["--out", &path]);
        let o = kefric(&args);
        assert_bad_input(&o, flag);
        assert!(!dir.join(out).exists(), "{flag} {value}: wrote {out}");
    }
}
