//! The surface readers (feature `topography`), X3P apart
//! (`topography_read_x3p.rs`): `.npy` in both byte orders and memory orders;
//! text columns, matrices and `x y z` grids; and every kind of bad file
//! giving its error, never a panic.

use std::path::Path;

use ke_friction::topography::{read_file, Format, ReadError, ReadOptions, Topography};

use crate::common::TempDir;
use crate::npy::npy;

pub(crate) fn opts() -> ReadOptions {
    ReadOptions::default()
}

/// A deterministic map with structure in both directions, heights ~1 µm.
pub(crate) fn sample_map(nx: usize, ny: usize, dx: f64, dy: f64) -> Topography {
    let heights = (0..nx * ny)
        .map(|k| {
            let (i, j) = ((k % nx) as f64, (k / nx) as f64);
            1e-6 * ((0.7 * i).sin() + 0.3 * (1.3 * j).cos() + 0.01 * i * j / (nx * ny) as f64)
        })
        .collect();
    Topography::map(heights, nx, ny, dx, dy).unwrap()
}

/// Both NaN or equal within `tol`.
pub(crate) fn assert_heights(got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len());
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            (g.is_nan() && w.is_nan()) || (g - w).abs() <= tol,
            "point {k}: got {g:e}, want {w:e} (tol {tol:e})"
        );
    }
}

pub(crate) fn read_err(path: &Path, options: &ReadOptions) -> ReadError {
    let err = read_file(path, options).expect_err("the file must be refused");
    let message = err.to_string();
    let name = path.file_name().unwrap().to_str().unwrap();
    assert!(message.contains(name), "message does not name the file: {message}");
    assert_eq!(err.path(), path);
    assert!(!err.is_io(), "{message}");
    err
}

// ---------------------------------------------------------------- .npy

#[test]
fn npy_orders_and_types() {
    let dir = TempDir::new("npy");
    let (nx, ny) = (5, 3);
    // Row-major heights: h[j][i] = j·10 + i (µm), one missing.
    let mut want: Vec<f64> = (0..nx * ny).map(|k| 1e-6 * ((k / nx) * 10 + k % nx) as f64).collect();
    want[7] = f64::NAN;
    let options = ReadOptions {
        dx: Some(1e-6),
        dy: Some(2e-6),
        ..opts()
    };
    let fortran: Vec<f64> = (0..nx * ny).map(|k| want[(k % ny) * nx + k / ny]).collect();
    let cases: Vec<(&str, &str, bool, Vec<u8>)> = vec![
        (
            "c-f8-le",
            "<f8",
            false,
            want.iter().flat_map(|v| v.to_le_bytes()).collect(),
        ),
        (
            "c-f8-be",
            ">f8",
            false,
            want.iter().flat_map(|v| v.to_be_bytes()).collect(),
        ),
        (
            "c-f4-le",
            "<f4",
            false,
            want.iter().flat_map(|&v| (v as f32).to_le_bytes()).collect(),
        ),
        (
            "c-f4-be",
            ">f4",
            false,
            want.iter().flat_map(|&v| (v as f32).to_be_bytes()).collect(),
        ),
        (
            "f-f8-le",
            "<f8",
            true,
            fortran.iter().flat_map(|v| v.to_le_bytes()).collect(),
        ),
        (
            "f-f4-be",
            ">f4",
            true,
            fortran.iter().flat_map(|&v| (v as f32).to_be_bytes()).collect(),
        ),
    ];
    for (name, descr, fortran, data) in cases {
        let path = dir.join(&format!("{name}.npy"));
        std::fs::write(&path, npy(descr, fortran, &[ny, nx], &data)).unwrap();
        let t = read_file(&path, &options).unwrap();
        assert_eq!((t.nx(), t.ny(), t.dx(), t.dy()), (nx, ny, 1e-6, Some(2e-6)), "{name}");
        let tol = if descr.ends_with('4') {
            3e-5 * f64::from(f32::EPSILON)
        } else {
            0.0
        };
        assert_heights(t.heights(), &want, tol);
    }
    // A 1-D array is a profile; z_unit scales it.
    let path = dir.join("profile.npy");
    let data: Vec<u8> = [1.0f64, 2.0, 3.0].iter().flat_map(|v| v.to_le_bytes()).collect();
    std::fs::write(&path, npy("<f8", false, &[3], &data)).unwrap();
    let t = read_file(
        &path,
        &ReadOptions {
            dx: Some(1e-7),
            z_unit: 1e-6,
            ..opts()
        },
    )
    .unwrap();
    assert!(t.is_profile());
    assert_eq!(t.heights(), &[1e-6, 2e-6, 3e-6]);
    // No interval: the error names the option.
    match read_err(&path, &opts()) {
        ReadError::NeedInterval { name: "dx", .. } => {
            assert!(read_err(&path, &opts())
                .to_string()
                .contains("the sampling interval dx"))
        }
        e => panic!("{e}"),
    }
    // The format option overrides the extension.
    let renamed = dir.join("profile.dat");
    std::fs::copy(&path, &renamed).unwrap();
    let t = read_file(
        &renamed,
        &ReadOptions {
            dx: Some(1e-7),
            format: Some(Format::NPY),
            ..opts()
        },
    )
    .unwrap();
    assert_eq!(t.nx(), 3);
}

#[test]
fn npy_bad_files() {
    let dir = TempDir::new("npy-bad");
    let options = ReadOptions {
        dx: Some(1.0),
        dy: Some(1.0),
        ..opts()
    };
    let data: Vec<u8> = (0..6).flat_map(|v| f64::from(v).to_le_bytes()).collect();
    let check = |name: &str, bytes: Vec<u8>, want: fn(&ReadError) -> bool| {
        let path = dir.join(name);
        std::fs::write(&path, bytes).unwrap();
        let err = read_err(&path, &options);
        assert!(want(&err), "{name}: {err}");
    };
    check("int.npy", npy("<i4", false, &[6], &data[..24]), |e| {
        matches!(e, ReadError::Unsupported { .. })
    });
    check("complex.npy", npy("<c16", false, &[3], &data), |e| {
        matches!(e, ReadError::Unsupported { .. })
    });
    check("3d.npy", npy("<f8", false, &[1, 2, 3], &data), |e| {
        matches!(e, ReadError::Unsupported { .. })
    });
    check("short.npy", npy("<f8", false, &[2, 4], &data), |e| {
        matches!(e, ReadError::Size { .. })
    });
    check("long.npy", npy("<f8", false, &[5], &data), |e| {
        matches!(e, ReadError::Size { .. })
    });
    check("huge.npy", npy("<f8", false, &[1 << 40, 1 << 40], &data), |e| {
        matches!(e, ReadError::Size { .. })
    });
    check("empty.npy", npy("<f8", false, &[0], &[]), |e| {
        matches!(e, ReadError::Size { .. })
    });
    check("magic.npy", b"NUMPY\x01\x00".to_vec(), |e| {
        matches!(e, ReadError::Npy { .. })
    });
    let mut bad = npy("<f8", false, &[6], &data);
    bad[20] = b'#';
    check("header.npy", bad, |e| matches!(e, ReadError::Npy { .. }));
    let mut infinite = data.clone();
    infinite[..8].copy_from_slice(&f64::INFINITY.to_le_bytes());
    check("infinite.npy", npy("<f8", false, &[6], &infinite), |e| {
        matches!(e, ReadError::Topography { .. })
    });
    // Every truncation and every flipped byte: an error or a read, never
    // a panic.
    let good = npy(">f4", true, &[2, 3], &data[..24]);
    for len in 0..good.len() {
        let path = dir.join(&format!("cut-{len}.npy"));
        std::fs::write(&path, &good[..len]).unwrap();
        read_err(&path, &options);
    }
    for k in 0..good.len() {
        let path = dir.join(&format!("flip-{k}.npy"));
        let mut b = good.clone();
        b[k] ^= 0x41;
        std::fs::write(&path, &b).unwrap();
        let _ = read_file(&path, &options);
    }
}

// ---------------------------------------------------------------- text

fn write_text(dir: &TempDir, name: &str, text: &str) -> std::path::PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn text_column_matrix_and_pairs() {
    let dir = TempDir::new("text");
    // One column: a profile; comments, blank lines, nan.
    let path = write_text(&dir, "col.txt", "# heights (um)\n1.5\n\n-2\nnan\n3e-1\n");
    let options = ReadOptions {
        dx: Some(0.5e-6),
        z_unit: 1e-6,
        ..opts()
    };
    let t = read_file(&path, &options).unwrap();
    assert!(t.is_profile());
    assert_heights(t.heights(), &[1.5e-6, -2e-6, f64::NAN, 0.3e-6], 1e-21);
    // A matrix, white space or commas: rows = y.
    let options = ReadOptions {
        dx: Some(1e-6),
        dy: Some(2e-6),
        ..opts()
    };
    for (name, text) in [
        ("m.txt", "1 2 3 4\n5 6 7 8\n"),
        ("m.csv", "1,2,3,4\r\n5, 6,7 ,8\r\n"),
        ("m.dat", "\u{feff}1;2;3;4\n\t5\t6\t7\t8"),
    ] {
        let t = read_file(&write_text(&dir, name, text), &options).unwrap();
        assert_eq!((t.nx(), t.ny(), t.dx(), t.dy()), (4, 2, 1e-6, Some(2e-6)), "{name}");
        assert_eq!(t.heights(), &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    }
    // Three columns read as a matrix on request.
    let path = write_text(&dir, "three.txt", "1 2 3\n4 5 6\n");
    let t = read_file(
        &path,
        &ReadOptions {
            format: Some(Format::MATRIX),
            ..options.clone()
        },
    )
    .unwrap();
    assert_eq!((t.nx(), t.ny()), (3, 2));
    // A single line: a profile.
    let t = read_file(&write_text(&dir, "line.txt", "1 2 3 4 5\n"), &options).unwrap();
    assert!(t.is_profile());
    assert_eq!(t.nx(), 5);
    // `x z` pairs: a profile whose interval comes from x (xy_unit scales
    // it), in any order.
    let path = write_text(&dir, "xz.txt", "0.2 3\n0 1\n0.1 2\n0.3 nan\n");
    let t = read_file(
        &path,
        &ReadOptions {
            xy_unit: 1e-6,
            ..opts()
        },
    )
    .unwrap();
    assert!(t.is_profile());
    assert!((t.dx() - 0.1e-6).abs() < 1e-18);
    assert_heights(t.heights(), &[1.0, 2.0, 3.0, f64::NAN], 0.0);
    // A matrix with dx alone: dy = dx; with neither, dx is asked for.
    let need = write_text(&dir, "need.txt", "1 2\n3 4\n5 6\n7 8\n");
    let t = read_file(
        &need,
        &ReadOptions {
            format: Some(Format::MATRIX),
            dx: Some(1.0),
            ..opts()
        },
    )
    .unwrap();
    assert_eq!(t.dy(), Some(1.0));
    match read_err(
        &need,
        &ReadOptions {
            format: Some(Format::MATRIX),
            ..opts()
        },
    ) {
        ReadError::NeedInterval { name: "dx", .. } => {}
        e => panic!("{e}"),
    }
}

#[test]
fn text_xyz_grid() {
    let dir = TempDir::new("xyz");
    // A 4 × 3 grid, Δx = 0.1, Δy = 0.25 (µm), y descending and shuffled,
    // coordinates printed with rounding.
    let (nx, ny) = (4, 3);
    let mut lines = Vec::new();
    for j in (0..ny).rev() {
        for i in [2, 0, 3, 1] {
            let z = if (i, j) == (1, 1) {
                "NaN".to_string()
            } else {
                format!("{}", j * 10 + i)
            };
            lines.push(format!("{:.7} {:.7} {z}", 0.1 * i as f64 + 5.0, 0.25 * j as f64 - 1.0));
        }
    }
    let path = write_text(&dir, "grid.xyz", &format!("# x y z\n{}\n", lines.join("\n")));
    let t = read_file(
        &path,
        &ReadOptions {
            xy_unit: 1e-6,
            z_unit: 1e-9,
            ..opts()
        },
    )
    .unwrap();
    assert_eq!((t.nx(), t.ny()), (nx, ny));
    assert!((t.dx() - 0.1e-6).abs() < 1e-15 && (t.dy().unwrap() - 0.25e-6).abs() < 1e-15);
    let want: Vec<f64> = (0..nx * ny)
        .map(|k| {
            if k == nx + 1 {
                f64::NAN
            } else {
                1e-9 * ((k / nx) * 10 + k % nx) as f64
            }
        })
        .collect();
    assert_heights(t.heights(), &want, 1e-24);

    // Irregular grids: refused.
    let irregular = |name: &str, text: &str| match read_err(&write_text(&dir, name, text), &opts()) {
        ReadError::Irregular { .. } => {}
        e => panic!("{name}: {e}"),
    };
    irregular(
        "jitter.xyz",
        "0 0 1\n1 0 1\n2.05 0 1\n3 0 1\n0 1 1\n1 1 1\n2 1 1\n3 1 1\n",
    );
    irregular("missing.xyz", "0 0 1\n1 0 1\n2 0 1\n0 1 1\n1 1 1\n");
    irregular("gap.xyz", "0 0 1\n1 0 1\n3 0 1\n0 1 1\n1 1 1\n3 1 1\n");
    irregular("duplicate.xyz", "0 0 1\n1 0 1\n1 0 2\n0 1 1\n");
    irregular("scatter.xyz", "0 0 1\n0.3 0.9 1\n1.7 0.2 1\n2.2 1.4 1\n");
    irregular("xz-repeat.txt", "0 1\n1 2\n1 3\n2 4\n");
    // A single row of points: the y interval from the options.
    let path = write_text(&dir, "row.xyz", "0 5 1\n1 5 2\n2 5 3\n");
    assert!(matches!(
        read_err(&path, &opts()),
        ReadError::NeedInterval { name: "dy", .. }
    ));
    let t = read_file(
        &path,
        &ReadOptions {
            dy: Some(1.0),
            ..opts()
        },
    )
    .unwrap();
    assert_eq!((t.nx(), t.ny(), t.dx()), (3, 1, 1.0));
    // NaN coordinates: refused with the line.
    match read_err(&write_text(&dir, "nan-x.xyz", "0 0 1\nnan 0 1\n"), &opts()) {
        ReadError::Text { line: 2, .. } => {}
        e => panic!("{e}"),
    }
}

#[test]
fn text_bad_files() {
    let dir = TempDir::new("text-bad");
    let options = ReadOptions {
        dx: Some(1.0),
        dy: Some(1.0),
        ..opts()
    };
    let line_of = |name: &str, text: &[u8]| -> (usize, String) {
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        match read_err(&path, &options) {
            ReadError::Text { line, detail, .. } => (line, detail),
            e => panic!("{name}: {e}"),
        }
    };
    let (line, detail) = line_of("word.txt", b"1 2\n3 4\n\n5 abc\n");
    assert_eq!(line, 4);
    assert!(detail.contains("abc"), "{detail}");
    assert_eq!(line_of("inf.txt", b"1\ninf\n").0, 2);
    assert_eq!(line_of("ragged.txt", b"1 2 3 4\n5 6 7 8\n9 10 11\n").0, 3);
    assert_eq!(line_of("binary.txt", b"1 2\n3 4\n\xff\xfe\n").0, 3);
    assert_eq!(line_of("commas.txt", b"# header\n,,\n").0, 2);
    assert_eq!(line_of("commas-later.txt", b"1\n2\n ; \n").0, 3);
    let path = write_text(&dir, "empty.txt", "# nothing\n\n");
    assert!(matches!(read_err(&path, &options), ReadError::Size { .. }));
    // Every byte of an `x y z` file and of a matrix replaced by a
    // separator, a digit, a letter, a comment or a line break: an error or
    // a read, never a panic.
    let mut k = 0;
    for good in [
        "0 0 1\n1 0 2\n0 1 3\n1 1 4\n",
        "1,2,3,4\n5,6,7,8\n",
        "0 1\n1 2\n2 nan\n",
    ] {
        for at in 0..good.len() {
            for c in [b' ', b',', b'\n', b'7', b'x', b'#', b'.', b'-'] {
                let mut b = good.as_bytes().to_vec();
                b[at] = c;
                k += 1;
                let path = dir.join(&format!("mutant-{k}.txt"));
                std::fs::write(&path, &b).unwrap();
                let _ = read_file(&path, &options);
            }
        }
    }
    // Bad options.
    let path = write_text(&dir, "ok.txt", "1\n2\n");
    let bad = ReadOptions {
        z_unit: f64::NAN,
        ..options.clone()
    };
    assert!(matches!(
        read_err(&path, &bad),
        ReadError::Options { name: "z_unit", .. }
    ));
    let bad = ReadOptions {
        dx: Some(-1.0),
        ..options.clone()
    };
    assert!(matches!(read_err(&path, &bad), ReadError::Topography { .. }));
}

#[test]
fn io_errors_are_told_apart() {
    let dir = TempDir::new("io");
    let path = dir.join("does-not-exist.x3p");
    let err = read_file(&path, &opts()).unwrap_err();
    assert!(err.is_io(), "{err}");
    assert!(err.to_string().contains("does-not-exist.x3p"));
    // A directory is an I/O failure too (cannot be read).
    let err = read_file(&dir.0, &opts()).unwrap_err();
    assert!(err.is_io(), "{err}");
}

#[test]
fn every_reading_names_its_format_in_the_metadata() {
    let options = ReadOptions {
        dx: Some(1e-6),
        dy: Some(1e-6),
        ..opts()
    };
    let t = ke_friction::topography::read_bytes(b"1 2 3 4\n5 6 7 8\n", "h.txt", &options).unwrap();
    assert_eq!(t.metadata().format, Some("text"));
    assert_eq!(t.metadata().channels, Vec::<String>::new());
    // Heights made in memory carry none.
    assert!(sample_map(3, 2, 1e-6, 1e-6).metadata().is_empty());
}

#[test]
fn a_channel_chosen_for_a_single_channel_file_is_refused() {
    use ke_friction::topography::Channel;
    assert_eq!("2".parse::<Channel>(), Ok(Channel::Index(2)));
    assert_eq!(" Height ".parse::<Channel>(), Ok(Channel::Name("Height".into())));
    let options = ReadOptions {
        dx: Some(1e-6),
        dy: Some(1e-6),
        channel: Some(Channel::Index(0)),
        ..opts()
    };
    let e = ke_friction::topography::read_bytes(b"1 2 3 4\n5 6 7 8\n", "h.txt", &options).unwrap_err();
    assert!(matches!(e, ReadError::Channel { .. }), "{e}");
    assert!(e.to_string().contains("only one"), "{e}");
}
