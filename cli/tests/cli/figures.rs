//! `kefric plot`: the paper's figures as PNGs of the promised size, the
//! curve and error-map subcommands on the embedded table, SVG output, and
//! bad input (exit 2, one line naming the flag).
use crate::common::TempDir;
use crate::support::{assert_bad_input, kefric, stderr};
use std::path::Path;

/// Every image is 1000 × 750 pixels (`ke_friction::figures::SIZE`).
const WIDTH: u32 = 1000;
const HEIGHT: u32 = 750;
const PNG_MAGIC: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];

/// Asserts `path` is a PNG (signature, then an IHDR chunk) of WIDTH × HEIGHT.
#[track_caller]
fn assert_png(path: &Path) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(bytes.len() > 10_000, "{}: only {} bytes", path.display(), bytes.len());
    assert_eq!(bytes[..8], PNG_MAGIC, "{}: not a PNG", path.display());
    assert_eq!(&bytes[12..16], b"IHDR", "{}: no IHDR chunk", path.display());
    let be = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    assert_eq!((be(16), be(20)), (WIDTH, HEIGHT), "{}: image size", path.display());
}

#[test]
fn plot_all_writes_four_pngs_of_1000_by_750() {
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
    assert!(svg.contains(r#"width="1000" height="750""#));
    // Fig. 5 names the comparison model in its legend.
    assert!(svg.contains("CEB-type (approx.)"));
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
    assert!(stderr(&o).contains(".png or .svg"), "{}", stderr(&o));
    assert!(!dir.join("fig3.jpg").exists());
    let o = kefric(&["plot", "fig3", "--out", &dir.arg("missing/fig3.png")]);
    assert_bad_input(&o, "--out");
    assert!(stderr(&o).contains("does not exist"), "{}", stderr(&o));
    let elsewhere = TempDir::new("bad-out-dir");
    std::fs::write(elsewhere.join("a_file"), b"x").unwrap();
    let o = kefric(&["plot", "all", "--out-dir", &elsewhere.arg("a_file")]);
    assert_bad_input(&o, "--out-dir");
    assert!(stderr(&o).contains("is not a directory"), "{}", stderr(&o));
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
