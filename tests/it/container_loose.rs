//! Loose files as the measurements of one surface (issue 50): the same
//! measurements and combined spectrum as the container of those files,
//! the settings' syntax, and bad settings or files.
//!
//! container-2.zip: `$KEF_CONTAINERS`, else `../shared/containers` beside
//! the repository (skipped if absent).

use std::io::Read;
use std::path::{Path, PathBuf};

use crate::common::{container_2, TempDir};
use ke_friction::topography::container::{
    combined_psd, measurement_spectra, read_container, read_loose, ContainerOptions, ContainerSurface, DetrendMode,
    Heights, LooseError, LooseMeasurement, LooseOptions, COMBINED_POINTS_PER_DECADE,
};
use ke_friction::{Classify, ErrorKind};

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/container");

/// Every member of the zip at `zip` written into `dir`.
fn unzip(zip: &Path, dir: &TempDir) {
    let mut z = zip::ZipArchive::new(std::fs::File::open(zip).unwrap()).unwrap();
    for i in 0..z.len() {
        let mut f = z.by_index(i).unwrap();
        let mut bytes = Vec::new();
        f.read_to_end(&mut bytes).unwrap();
        std::fs::write(dir.join(f.name()), bytes).unwrap();
    }
}

fn loose(dir: &TempDir, specs: &[&str]) -> Result<ContainerSurface, LooseError> {
    let ms: Vec<LooseMeasurement> = specs.iter().map(|s| dir.arg(s).parse().unwrap()).collect();
    read_loose(&ms, &LooseOptions::default())
}

/// Each bin's q and C agree to `tol` relative.
#[track_caller]
fn assert_same_combined(a: &ContainerSurface, b: &ContainerSurface, tol: f64) {
    let ca = combined_psd(&measurement_spectra(&a.measurements), COMBINED_POINTS_PER_DECADE).unwrap();
    let cb = combined_psd(&measurement_spectra(&b.measurements), COMBINED_POINTS_PER_DECADE).unwrap();
    assert_eq!(ca.psd.q.len(), cb.psd.q.len());
    assert_eq!(ca.contributors, cb.contributors);
    for k in 0..ca.psd.q.len() {
        for (x, y) in [(ca.psd.q[k], cb.psd.q[k]), (ca.psd.c[k], cb.psd.c[k])] {
            assert!((x / y - 1.0).abs() <= tol, "bin {k}: {x} against {y}");
        }
    }
}

/// container-2.zip's three files given loose, with the settings of its
/// meta.yml that the files do not carry (the unit of the text files and of
/// the Nanoscope file's meta entry, the AFM's height_scale, the stylus's
/// curvature detrending; the TEM's and the AFM's `height` detrending is a
/// loose file's default): the same measurements (grids, sizes) and the
/// same combined spectrum, to 1e-12 (measured: bit for bit).
#[test]
fn loose_files_of_container_2_give_its_combined_spectrum() {
    let Some(zip) = container_2() else { return };
    let dir = TempDir::new("loose-c2");
    unzip(&zip, &dir);
    let c = &read_container(&zip, &ContainerOptions::default()).unwrap()[0];
    let l = loose(
        &dir,
        &[
            "80_Scale10.472_FIXEDv2p1_D7eHXiT.asc@unit=nm",
            "gain_control_uncd_35_z03tr3R.001@unit=nm,height_scale=0.112075538798523",
            "uncd_stylus_300um_5mar_3_k0HpKJt.txt@unit=mm,detrend_mode=curvature",
        ],
    )
    .unwrap();
    assert_eq!(l.measurements.len(), 3);
    for (a, b) in c.measurements.iter().zip(&l.measurements) {
        assert_eq!(a.grid(), b.grid(), "{}", a.name);
        assert_eq!(a.size(), b.size(), "{}", a.name);
        assert_eq!(a.detrend, b.detrend, "{}", a.name);
    }
    // The TEM profile is a nonuniform line scan there and here.
    assert!(matches!(l.measurements[0].heights, Heights::Nonuniform { .. }));
    assert_same_combined(c, &l, 1e-12);
    // Without the AFM's height_scale its spectrum is that of heights
    // 1/0.112 times larger: the combined spectrum differs.
    let unscaled = loose(
        &dir,
        &[
            "80_Scale10.472_FIXEDv2p1_D7eHXiT.asc@unit=nm",
            "gain_control_uncd_35_z03tr3R.001@unit=nm",
            "uncd_stylus_300um_5mar_3_k0HpKJt.txt@unit=mm,detrend_mode=curvature",
        ],
    )
    .unwrap();
    let s = measurement_spectra(&unscaled.measurements);
    let r = measurement_spectra(&l.measurements);
    let (a, b) = (s[1].psd.as_ref().unwrap(), r[1].psd.as_ref().unwrap());
    let ratio = a.c[3] / b.c[3];
    assert!((ratio * 0.112075538798523f64.powi(2) - 1.0).abs() < 1e-9, "{ratio}");
}

/// The synthetic container's files given loose: the text profile and the
/// nonuniform profile with its tip radius read as in the container; the
/// `.npy` map read as a loose `.npy` is (rows = y), the transpose of the
/// container's (indexed [x, y]).
#[test]
fn loose_files_of_the_synthetic_container() {
    let zip = PathBuf::from(format!("{DATA}/synthetic.zip"));
    let dir = TempDir::new("loose-synthetic");
    unzip(&zip, &dir);
    let c = &read_container(&zip, &ContainerOptions::default()).unwrap()[0];
    let l = loose(
        &dir,
        &[
            "coarse.txt@unit=mm,size=0.001",
            "map.npy@unit=mm,size=1.5625e-05x1.5625e-05,height_scale=2,detrend_mode=center",
            "nonuniform.txt@unit=mm,detrend_mode=curvature,tip_radius=40e-9",
        ],
    )
    .unwrap();
    assert_eq!(l.measurements[2].tip_radius, Some(40e-9));
    let (sc, sl) = (
        measurement_spectra(&c.measurements),
        measurement_spectra(&l.measurements),
    );
    for i in [0, 2] {
        assert_eq!(sc[i], sl[i], "measurement {i}");
    }
    assert!(sl[2].cutoff.is_some());
    let (Heights::Uniform(tc), Heights::Uniform(tl)) = (&c.measurements[1].heights, &l.measurements[1].heights) else {
        panic!("a map")
    };
    let (nx, ny) = (tl.nx(), tl.ny());
    assert_eq!((tc.nx(), tc.ny()), (ny, nx));
    let scale = tl.heights().iter().fold(0.0f64, |m, z| m.max(z.abs()));
    for j in 0..ny {
        for i in 0..nx {
            let (a, b) = (tl.heights()[j * nx + i], tc.heights()[i * ny + j]);
            assert!((a - b).abs() <= 1e-12 * scale, "({i}, {j}): {a} against {b}");
        }
    }
}

/// `FILE@KEY=VALUE,...`: the settings after the last `@` holding a `=`;
/// unknown or repeated keys and pairs without `=` refused, naming them.
#[test]
fn loose_settings_syntax() {
    let m: LooseMeasurement = "a/b@c.txt@unit=nm, size=2x3".parse().unwrap();
    assert_eq!(m.path, PathBuf::from("a/b@c.txt"));
    assert_eq!(
        m.settings,
        vec![("unit".into(), "nm".into()), ("size".into(), "2x3".into())]
    );
    let m: LooseMeasurement = "me@host.txt".parse().unwrap();
    assert_eq!((m.path, m.settings.len()), (PathBuf::from("me@host.txt"), 0));
    for (text, says) in [
        ("f.txt@units=nm", "unknown setting \"units\""),
        ("f.txt@unit=nm,unit=mm", "unit given twice"),
        ("f.txt@unit=nm,oops", "\"oops\" is not KEY=VALUE"),
        ("@unit=nm", "no file name"),
    ] {
        let e = text.parse::<LooseMeasurement>().unwrap_err();
        assert!(e.contains(says), "{text}: {e}");
    }
}

/// Bad files and settings: one message naming the file and the setting; a
/// file that cannot be read is an I/O error naming it.
#[test]
fn loose_errors_name_the_file_and_setting() {
    let dir = TempDir::new("loose-errors");
    std::fs::write(dir.join("p.txt"), "1\n2\n3\n2\n1\n0\n1\n2\n").unwrap();
    let e = read_loose(&[], &LooseOptions::default()).unwrap_err();
    assert!(e.to_string().contains("no measurement files"), "{e}");
    let e = loose(&dir, &["gone.txt"]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Io);
    assert!(e.to_string().contains("gone.txt"), "{e}");
    for (spec, says) in [
        ("p.txt", "size: missing"),
        ("p.txt@size=8x8", "2 values for a profile"),
        ("p.txt@size=-8", "size = -8"),
        ("p.txt@size=8,unit=furlong", "unit = \"furlong\""),
        ("p.txt@size=8,detrend_mode=wobble", "detrend_mode"),
        ("p.txt@size=8,height_scale=0", "height_scale"),
        ("p.txt@size=8,tip_radius=0", "tip_radius = 0 is out of range"),
        ("p.txt@size=8,tip_radius=1e-8,resolution=1e-6", "give one"),
        ("p.txt@size=8,is_periodic=perhaps", "is_periodic"),
    ] {
        let e = loose(&dir, &[spec]).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::Argument, "{spec}");
        let text = e.to_string();
        assert!(text.contains(says) && text.contains("p.txt"), "{spec}: {text}");
    }
    // A file over the bound is refused before it is read whole.
    let small = LooseOptions {
        container: ContainerOptions {
            read: ke_friction::topography::ReadOptions {
                max_bytes: 8,
                ..Default::default()
            },
            ..ContainerOptions::default()
        },
        ..LooseOptions::default()
    };
    let m: LooseMeasurement = format!("{}@size=8", dir.arg("p.txt")).parse().unwrap();
    let e = read_loose(&[m], &small).unwrap_err();
    assert!(
        e.to_string().contains("over the limit of 8 bytes") && e.to_string().contains("p.txt"),
        "{e}"
    );
    // A directory is not read.
    let e = read_loose(&[dir.arg("").parse().unwrap()], &LooseOptions::default()).unwrap_err();
    assert!(e.to_string().contains("not a regular file"), "{e}");
}

/// A loose file without `detrend_mode` takes the options' detrending: the
/// least-squares line by default (a tilted line reads as zeros), the heights
/// as read with `DetrendMode::None`.
#[test]
fn loose_defaults_detrend_and_unit() {
    let dir = TempDir::new("loose-defaults");
    std::fs::write(dir.join("tilt.txt"), "0\n1\n2\n3\n4\n5\n").unwrap();
    let m: LooseMeasurement = format!("{}@size=6", dir.arg("tilt.txt")).parse().unwrap();
    let heights = |options: &LooseOptions| match read_loose(std::slice::from_ref(&m), options)
        .unwrap()
        .measurements
        .remove(0)
        .heights
    {
        Heights::Uniform(t) => t.heights().to_vec(),
        Heights::Nonuniform { .. } => panic!("uniform"),
    };
    assert!(heights(&LooseOptions::default()).iter().all(|z| z.abs() < 1e-12));
    let raw = LooseOptions {
        detrend: DetrendMode::None,
        unit: ke_friction::LengthUnit::Um,
        ..LooseOptions::default()
    };
    for (k, z) in heights(&raw).into_iter().enumerate() {
        assert!((z - k as f64 * 1e-6).abs() < 1e-18, "{k}: {z}");
    }
}
