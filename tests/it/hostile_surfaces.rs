//! Surface files as untrusted input (issue 34): nesting that would
//! overflow a recursive parser, sizes that would inflate past memory, a
//! points limit on every format, line ends of every platform, ambiguous
//! and truncated archives; and `read_bytes` giving what `read_file` gives.

use std::time::Instant;

use ke_friction::topography::{read_bytes, read_file, Format, ReadError, ReadOptions, MAX_POINTS};

use crate::common::TempDir;
use crate::npy::npy;
use crate::topography_read_x3p::{stored_zip, X3p};

fn opts() -> ReadOptions {
    ReadOptions {
        dx: Some(1e-6),
        // X3p::new's own intervals.
        dy: Some(2e-6),
        ..ReadOptions::default()
    }
}

fn err(bytes: &[u8], name: &str, options: &ReadOptions) -> ReadError {
    let e = read_bytes(bytes, name, options).expect_err("must be refused");
    assert!(e.to_string().contains(name), "{e}");
    assert!(!e.is_io(), "{e}");
    e
}

#[test]
fn deeply_nested_xml_is_refused_before_parsing() {
    let x = X3p::new(&[1.0; 6]);
    let deep = format!("{}{}", "<a>".repeat(20_000), "</a>".repeat(20_000));
    let xml = x.xml().replace("<Record4>", &format!("{deep}<Record4>"));
    let bytes = stored_zip(&[("main.xml", xml.as_bytes()), ("bindata/data.bin", &x.data)]);
    let t0 = Instant::now();
    let e = err(&bytes, "deep.x3p", &opts());
    assert!(matches!(e, ReadError::Xml { .. }), "{e}");
    assert!(e.to_string().contains("nest deeper than 64"), "{e}");
    assert!(t0.elapsed().as_secs_f64() < 1.0);
    // Depth in comments, CDATA and attribute values is not nesting.
    let tricky = "<!-- <a><a><a> --><![CDATA[<a><a>]]><b c='x>y' d=\"/>\"/>".repeat(100);
    let xml = x.xml().replace("<Record4>", &format!("{tricky}<Record4>"));
    let bytes = stored_zip(&[("main.xml", xml.as_bytes()), ("bindata/data.bin", &x.data)]);
    assert!(read_bytes(&bytes, "tricky.x3p", &opts()).is_ok());
}

#[test]
fn declared_sizes_over_the_points_limit_are_refused_before_inflating() {
    // 32768 x 32768 16-bit points: 2 GiB of data, under the byte bound,
    // but 2^30 points of 8 bytes each once read.
    let mut x = X3p::new(&[1.0; 6]);
    x.z_type = "I";
    x.size = (32_768, 32_768, 1);
    let t0 = Instant::now();
    let e = err(&x.bytes(), "bomb.x3p", &opts());
    match &e {
        ReadError::TooManyPoints { points, limit, .. } => {
            assert_eq!((*points, *limit), (1 << 30, MAX_POINTS));
        }
        e => panic!("{e}"),
    }
    assert!(e.to_string().contains("32768 x 32768"), "{e}");
    assert!(t0.elapsed().as_secs_f64() < 1.0);
}

#[test]
fn the_points_limit_holds_for_every_format() {
    let v = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
    let x3p = X3p::new(&v).bytes();
    let data: Vec<u8> = v.iter().flat_map(|h| h.to_le_bytes()).collect();
    let npy_file = npy("<f8", false, &[2, 3], &data);
    let text = b"1\n2\n3\n4\n5\n6\n".to_vec();
    let xyz = b"0 0 1\n1 0 2\n2 0 3\n0 2 4\n1 2 5\n2 2 6\n".to_vec();
    for (bytes, name) in [
        (&x3p, "a.x3p"),
        (&npy_file, "a.npy"),
        (&text, "a.txt"),
        (&xyz, "xyz.txt"),
    ] {
        let at = |max_points| ReadOptions {
            max_points,
            xy_unit: 1e-6,
            ..opts()
        };
        let t = read_bytes(bytes, name, &at(6)).unwrap();
        assert_eq!(t.heights().len(), 6, "{name}");
        match err(bytes, name, &at(5)) {
            ReadError::TooManyPoints {
                points: 6, limit: 5, ..
            } => {}
            e => panic!("{name}: {e}"),
        }
    }
}

#[test]
fn cr_lf_and_crlf_all_end_lines() {
    // A 48 x 64 matrix (rows = y): the same map whatever the line ends.
    let rows: Vec<String> = (0..48)
        .map(|j| {
            (0..64)
                .map(|i| format!("{}", (i * 7 + j * 3) % 11))
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect();
    let reference = read_bytes(rows.join("\n").as_bytes(), "lf.txt", &opts()).unwrap();
    assert_eq!((reference.nx(), reference.ny()), (64, 48));
    for (end, name) in [("\r", "cr.txt"), ("\r\n", "crlf.txt")] {
        let text = format!("# a comment line{end}{}{end}", rows.join(end));
        let t = read_bytes(text.as_bytes(), name, &opts()).unwrap();
        assert_eq!(t, reference, "{name}");
    }
    // Mixed, with blank lines of each kind and a byte-order mark.
    let mixed = format!("\u{feff}{}\r\r\n\n{}", rows[..20].join("\r\n"), rows[20..].join("\r"));
    assert_eq!(read_bytes(mixed.as_bytes(), "mixed.txt", &opts()).unwrap(), reference);
    // Line numbers count CR ends too: the bad field is on line 3.
    match err(b"1 2\r3 4\r5 x\r", "bad.txt", &opts()) {
        ReadError::Text { line: 3, .. } => {}
        e => panic!("{e}"),
    }
}

#[test]
fn text_fields_and_separators() {
    let t = read_bytes(b"1,2;3\t4\n5 , 6 ;7 8\n", "sep.txt", &opts()).unwrap();
    assert_eq!(t.heights(), &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
    for (text, want) in [
        (&b"1 2\n, ;\n"[..], "only separators"),
        (b"1 2\n3 inf\n", "infinite"),
        (b"1 2\n3 \xff\n", "not UTF-8"),
        (b"1 2 3\n4 5\n", "2 numbers, line 1 has 3"),
    ] {
        let e = err(text, "t.txt", &opts());
        assert!(e.to_string().contains(want), "{e}");
    }
    let long = format!("1 {}\n", "9".repeat(5000));
    assert!(err(long.as_bytes(), "long.txt", &opts())
        .to_string()
        .contains("over 1024 bytes"));
}

#[test]
fn an_archive_with_two_members_of_one_name_is_refused() {
    let x = X3p::new(&[1.0; 6]);
    let xml = x.xml();
    let bytes = stored_zip(&[
        ("main.xml", xml.as_bytes()),
        ("bindata/data.bin", &x.data),
        ("main.xml", xml.as_bytes()),
    ]);
    let e = err(&bytes, "twice.x3p", &opts());
    assert!(matches!(e, ReadError::Archive { .. }), "{e}");
    assert!(e.to_string().contains("two members are named main.xml"), "{e}");
}

#[test]
fn truncated_files_say_truncated() {
    let x3p = X3p::new(&[1.0; 6]).bytes();
    for cut in [x3p.len() - 10, x3p.len() / 2, 30] {
        let e = err(&x3p[..cut], "cut.x3p", &opts());
        assert!(e.to_string().contains("truncated"), "cut at {cut}: {e}");
    }
    let data: Vec<u8> = [1.0f64; 6].iter().flat_map(|h| h.to_le_bytes()).collect();
    let file = npy("<f8", false, &[2, 3], &data);
    for cut in [file.len() - 1, 9] {
        let e = err(&file[..cut], "cut.npy", &opts());
        assert!(
            e.to_string().contains("truncated") || e.to_string().contains("bytes of data"),
            "{e}"
        );
    }
}

#[test]
fn read_bytes_reads_what_read_file_reads() {
    let dir = TempDir::new("read-bytes");
    let data: Vec<u8> = (0..12).flat_map(|k| (f64::from(k) * 1e-7).to_be_bytes()).collect();
    let files: [(&str, Vec<u8>); 4] = [
        ("m.x3p", X3p::new(&[1e-6, 2e-6, 0.5e-6, f64::NAN, 0.0, 3e-6]).bytes()),
        ("m.npy", npy(">f8", true, &[3, 4], &data)),
        ("m.txt", b"1 2 3 4\r\n5 nan 7 8\r\n".to_vec()),
        ("p.csv", b"0,1\n1e-6,2\n2e-6,4\n".to_vec()),
    ];
    for (name, bytes) in files {
        let path = dir.join(name);
        std::fs::write(&path, &bytes).unwrap();
        let from_file = read_file(&path, &opts()).unwrap();
        let from_bytes = read_bytes(&bytes, name, &opts()).unwrap();
        assert_eq!(format!("{from_file:?}"), format!("{from_bytes:?}"), "{name}");
    }
    // The format option beats the name.
    let m = read_bytes(
        b"1 2 3\n",
        "heights.dat",
        &ReadOptions {
            format: Some(Format::MATRIX),
            ..opts()
        },
    )
    .unwrap();
    assert_eq!(m.nx(), 3);
}

#[test]
fn a_negative_or_non_finite_unit_is_refused() {
    for z_unit in [-1e-6, 0.0, f64::NAN, f64::INFINITY] {
        let options = ReadOptions { z_unit, ..opts() };
        match err(b"1 2 3\n", "u.txt", &options) {
            ReadError::Options { name: "z_unit", .. } => {}
            e => panic!("{e}"),
        }
    }
}

#[test]
fn the_format_is_chosen_by_extension_and_content() {
    let x3p = X3p::new(&[1.0; 6]).bytes();
    let data: Vec<u8> = [1.0f64; 6].iter().flat_map(|h| h.to_le_bytes()).collect();
    let npy_file = npy("<f8", false, &[2, 3], &data);
    // Content with a signature wins over a text or unknown extension.
    for name in ["surface.dat", "surface.bin", "surface"] {
        assert_eq!(Format::detect(name.as_ref(), &x3p[..16]), Format::X3P, "{name}");
        assert_eq!(Format::detect(name.as_ref(), &npy_file[..16]), Format::NPY, "{name}");
        assert_eq!(read_bytes(&x3p, name, &opts()).unwrap().heights().len(), 6);
        assert_eq!(read_bytes(&npy_file, name, &opts()).unwrap().heights().len(), 6);
    }
    // A format's own extension is kept: its reader says what is wrong.
    assert_eq!(Format::detect("a.X3P".as_ref(), b"1 2 3"), Format::X3P);
    assert!(matches!(err(b"1 2 3\n", "a.x3p", &opts()), ReadError::Archive { .. }));
    assert_eq!(Format::detect("a.csv".as_ref(), b"1,2"), Format::TEXT);
    // The registry: names and extensions, each format once (asserted
    // against the registry, not a list: a new format needs no edit here).
    let names: Vec<&str> = Format::all().map(Format::name).collect();
    for (i, name) in names.iter().enumerate() {
        assert!(!names[..i].contains(name), "{name} twice");
    }
    for (constant, name) in [
        (Format::X3P, "x3p"),
        (Format::NPY, "npy"),
        (Format::TEXT, "text"),
        (Format::MATRIX, "matrix"),
    ] {
        assert_eq!(constant.name(), name);
    }
    for f in Format::all() {
        assert_eq!(Format::from_name(&f.name().to_uppercase()), Some(f));
        assert!(!f.description().is_empty());
    }
}
