//! The X3P reader (feature `topography`): round trips through the
//! library's writer for every z data type, profiles, Δx ≠ Δy and the
//! validity mask; X3P files built here independently (a stored zip and
//! main.xml of our own, `X3p` and `stored_zip`, which the hostile
//! surfaces reuse), their checksums, bad files and points listed in
//! main.xml; every kind of bad file giving its error, never a panic.

use ke_friction::topography::{read_file, write_x3p, ReadError, ReadOptions, Topography};

use crate::common::TempDir;
use crate::topography_read::{assert_heights, opts, read_err, sample_map};

/// The tolerance of a round trip through z data type `z` for heights
/// spanning `range`.
fn tolerance(z: char, range: f64, max: f64) -> f64 {
    match z {
        'D' => 0.0,
        'F' => max * f64::from(f32::EPSILON),
        'L' => 0.51 * range / (f64::from(u32::MAX)) + 1e-15 * max,
        _ => 0.51 * range / f64::from(u16::MAX) + 1e-15 * max,
    }
}

fn range_of(h: &[f64]) -> (f64, f64) {
    let finite = h.iter().filter(|v| !v.is_nan());
    let lo = finite.clone().fold(f64::INFINITY, |a, &b| a.min(b));
    let hi = finite.fold(f64::NEG_INFINITY, |a, &b| a.max(b));
    (hi - lo, lo.abs().max(hi.abs()))
}

#[test]
fn x3p_round_trip_every_z_type_with_dx_ne_dy() {
    let dir = TempDir::new("x3p-round-trip");
    let t = sample_map(37, 23, 0.5e-6, 1.25e-6);
    let (range, max) = range_of(t.heights());
    for z in ['D', 'F', 'L', 'I'] {
        let path = dir.join(&format!("map-{z}.x3p"));
        write_x3p(&t, &path, z).unwrap();
        let r = read_file(&path, &opts()).unwrap();
        assert_eq!(
            (r.nx(), r.ny(), r.dx(), r.dy()),
            (37, 23, 0.5e-6, Some(1.25e-6)),
            "type {z}"
        );
        assert!(!r.is_profile());
        assert_heights(r.heights(), t.heights(), tolerance(z, range, max));
        if z == 'D' {
            assert_eq!(r, t, "D is exact");
        }
    }
}

#[test]
fn x3p_profiles_and_masks() {
    let dir = TempDir::new("x3p-profile-mask");
    let mut h: Vec<f64> = (0..101).map(|i| 2e-7 * (0.2 * f64::from(i)).sin() - 3e-6).collect();
    h[0] = f64::NAN;
    h[50] = f64::NAN;
    h[100] = f64::NAN;
    let profile = Topography::profile(h, 0.1e-6).unwrap();
    let mut m = sample_map(9, 7, 1e-6, 2e-6).heights().to_vec();
    for k in [0, 8, 9, 31, 62] {
        m[k] = f64::NAN;
    }
    let map = Topography::map(m, 9, 7, 1e-6, 2e-6).unwrap();
    for t in [profile, map] {
        let (range, max) = range_of(t.heights());
        for z in ['D', 'F', 'L', 'I'] {
            let path = dir.join(&format!("masked-{z}.x3p"));
            write_x3p(&t, &path, z).unwrap();
            let r = read_file(&path, &opts()).unwrap();
            assert_eq!((r.nx(), r.ny(), r.dx(), r.dy()), (t.nx(), t.ny(), t.dx(), t.dy()));
            assert_eq!(r.is_profile(), t.is_profile());
            assert_heights(r.heights(), t.heights(), tolerance(z, range, max));
        }
    }
}

#[test]
fn x3p_writer_refuses_bad_arguments() {
    let dir = TempDir::new("x3p-writer-args");
    let t = sample_map(3, 3, 1.0, 1.0);
    let err = write_x3p(&t, &dir.join("a.x3p"), 'Q').unwrap_err();
    assert_eq!(err.kind(), std::io::ErrorKind::InvalidInput);
    let big = Topography::profile(vec![1e300, 0.0], 1.0).unwrap();
    let err = write_x3p(&big, &dir.join("b.x3p"), 'F').unwrap_err();
    assert_eq!(err.kind(), std::io::ErrorKind::InvalidInput);
    // A constant (and an all-missing) surface quantises without trouble.
    for h in [vec![2e-6; 4], vec![f64::NAN; 4]] {
        let t = Topography::profile(h.clone(), 1e-6).unwrap();
        write_x3p(&t, &dir.join("c.x3p"), 'I').unwrap();
        let r = read_file(&dir.join("c.x3p"), &opts()).unwrap();
        assert_heights(r.heights(), &h, 1e-18);
    }
}

/// An independent X3P encoder: `main.xml` from a template with fields to
/// override, and an uncompressed (stored) zip.
pub(crate) struct X3p {
    pub(crate) feature: &'static str,
    pub(crate) z_type: &'static str,
    pub(crate) cx: &'static str,
    pub(crate) cy: &'static str,
    pub(crate) cz_extra: String,
    pub(crate) size: (u64, u64, u64),
    pub(crate) md5: Option<String>,
    pub(crate) valid_link: Option<&'static str>,
    pub(crate) data: Vec<u8>,
    pub(crate) valid: Option<Vec<u8>>,
}

impl X3p {
    /// A 3 × 2 SUR map of f64, x interval 1 µm, y 2 µm.
    pub(crate) fn new(values: &[f64]) -> X3p {
        X3p {
            feature: "SUR",
            z_type: "D",
            cx: "<AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6</Increment><Offset>0</Offset>",
            cy: "<AxisType>I</AxisType><DataType>D</DataType><Increment>2.0E-6</Increment><Offset>0</Offset>",
            cz_extra: String::new(),
            size: (3, 2, 1),
            md5: None,
            valid_link: None,
            data: values.iter().flat_map(|v| v.to_le_bytes()).collect(),
            valid: None,
        }
    }

    pub(crate) fn xml(&self) -> String {
        let md5 = self
            .md5
            .as_ref()
            .map(|m| format!("<MD5ChecksumPointData>{m}</MD5ChecksumPointData>"))
            .unwrap_or_default();
        let valid = self
            .valid_link
            .map(|l| format!("<ValidPointsLink>{l}</ValidPointsLink>"))
            .unwrap_or_default();
        format!(
            r#"<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
 <Record1><Revision>ISO5436 - 2000</Revision><FeatureType>{}</FeatureType>
  <Axes><CX>{}</CX><CY>{}</CY><CZ><AxisType>A</AxisType><DataType>{}</DataType>{}</CZ></Axes></Record1>
 <Record2><Date>2024-01-01T00:00:00+00:00</Date></Record2>
 <Record3><MatrixDimension><SizeX>{}</SizeX><SizeY>{}</SizeY><SizeZ>{}</SizeZ></MatrixDimension>
  <DataLink><PointDataLink>bindata/data.bin</PointDataLink>{md5}{valid}</DataLink></Record3>
 <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>
"#,
            self.feature, self.cx, self.cy, self.z_type, self.cz_extra, self.size.0, self.size.1, self.size.2
        )
    }

    pub(crate) fn bytes(&self) -> Vec<u8> {
        let xml = self.xml();
        let mut members: Vec<(&str, &[u8])> = vec![("main.xml", xml.as_bytes()), ("bindata/data.bin", &self.data)];
        if let Some(valid) = &self.valid {
            members.push(("bindata/valid.bin", valid));
        }
        stored_zip(&members)
    }

    pub(crate) fn write(&self, dir: &TempDir, name: &str) -> std::path::PathBuf {
        let path = dir.join(name);
        std::fs::write(&path, self.bytes()).unwrap();
        path
    }
}

/// A zip archive of uncompressed (stored) members.
pub(crate) fn stored_zip(members: &[(&str, &[u8])]) -> Vec<u8> {
    let mut out = Vec::new();
    let mut central = Vec::new();
    for (name, data) in members {
        let offset = out.len() as u32;
        let crc = crc32fast::hash(data);
        let fields = |v: &mut Vec<u8>| {
            v.extend(20u16.to_le_bytes()); // version needed
            v.extend(0u16.to_le_bytes()); // flags
            v.extend(0u16.to_le_bytes()); // stored
            v.extend(0u16.to_le_bytes()); // time
            v.extend(0x21u16.to_le_bytes()); // date: 1980-01-01
            v.extend(crc.to_le_bytes());
            v.extend((data.len() as u32).to_le_bytes());
            v.extend((data.len() as u32).to_le_bytes());
            v.extend((name.len() as u16).to_le_bytes());
            v.extend(0u16.to_le_bytes()); // extra
        };
        out.extend(0x0403_4b50u32.to_le_bytes());
        fields(&mut out);
        out.extend(name.as_bytes());
        out.extend(*data);
        central.extend(0x0201_4b50u32.to_le_bytes());
        central.extend(20u16.to_le_bytes()); // made by
        fields(&mut central);
        central.extend([0; 8]); // comment length, disk, internal, external attributes (part)
        central.extend([0; 2]);
        central.extend(offset.to_le_bytes());
        central.extend(name.as_bytes());
    }
    let (cd_offset, cd_len) = (out.len() as u32, central.len() as u32);
    out.extend(central);
    out.extend(0x0605_4b50u32.to_le_bytes());
    out.extend([0; 4]);
    out.extend((members.len() as u16).to_le_bytes());
    out.extend((members.len() as u16).to_le_bytes());
    out.extend(cd_len.to_le_bytes());
    out.extend(cd_offset.to_le_bytes());
    out.extend([0; 2]);
    out
}

#[test]
fn x3p_independent_encoder() {
    let dir = TempDir::new("x3p-independent");
    let v = [1e-6, -2e-6, 3.5e-6, f64::NAN, 0.0, 7e-7];
    // Plain: NaN in float data is missing; Δx and Δy from the axes.
    let path = X3p::new(&v).write(&dir, "plain.x3p");
    let t = read_file(&path, &opts()).unwrap();
    assert_eq!((t.nx(), t.ny(), t.dx(), t.dy()), (3, 2, 1e-6, Some(2e-6)));
    assert_heights(t.heights(), &v, 0.0);

    // The z increment and offset apply to float data too.
    let mut f = X3p::new(&v);
    f.cz_extra = "<Increment>2</Increment><Offset>1e-6</Offset>".into();
    let t = read_file(&f.write(&dir, "scaled.x3p"), &opts()).unwrap();
    let want: Vec<f64> = v.iter().map(|h| 1e-6 + 2.0 * h).collect();
    assert_heights(t.heights(), &want, 0.0);

    // Integer types: z = offset + increment · value; the mask (bit per
    // point, LSB first, 1 = valid) makes points missing.
    let raw: [i16; 6] = [-32768, -1, 0, 1, 32767, 5];
    let mut x = X3p::new(&[]);
    x.z_type = "I";
    x.data = raw.iter().flat_map(|v| v.to_le_bytes()).collect();
    x.cz_extra = "<Increment>1e-9</Increment><Offset>-2e-6</Offset>".into();
    x.valid_link = Some("bindata/valid.bin");
    x.valid = Some(vec![0b0011_1011]);
    let t = read_file(&x.write(&dir, "int16.x3p"), &opts()).unwrap();
    let want: Vec<f64> = raw
        .iter()
        .enumerate()
        .map(|(k, &r)| if k == 2 { f64::NAN } else { -2e-6 + 1e-9 * f64::from(r) })
        .collect();
    assert_heights(t.heights(), &want, 0.0);

    let raw: [i32; 6] = [i32::MIN, -7, 0, 9, i32::MAX, 123_456];
    x.z_type = "L";
    x.data = raw.iter().flat_map(|v| v.to_le_bytes()).collect();
    x.valid = Some(vec![0b1111_1110]); // point 0 missing, padding bits ignored
    x.valid_link = None; // bindata/valid.bin is used without a link too
    let t = read_file(&x.write(&dir, "int32.x3p"), &opts()).unwrap();
    let want: Vec<f64> = raw
        .iter()
        .enumerate()
        .map(|(k, &r)| if k == 0 { f64::NAN } else { -2e-6 + 1e-9 * f64::from(r) })
        .collect();
    assert_heights(t.heights(), &want, 0.0);

    let raw: [f32; 6] = [1.5e-6, -0.25e-6, f32::NAN, 0.0, 3e-6, 1e-7];
    let mut x = X3p::new(&[]);
    x.z_type = "F";
    x.data = raw.iter().flat_map(|v| v.to_le_bytes()).collect();
    let t = read_file(&x.write(&dir, "f32.x3p"), &opts()).unwrap();
    let want: Vec<f64> = raw.iter().map(|&r| f64::from(r)).collect();
    assert_heights(t.heights(), &want, 0.0);

    // A profile; without CY.
    let mut p = X3p::new(&[1.0, 2.0, 3.0]);
    p.feature = "PRF";
    p.size = (3, 1, 1);
    p.cy = "<AxisType>I</AxisType>";
    let t = read_file(&p.write(&dir, "profile.x3p"), &opts()).unwrap();
    assert!(t.is_profile());
    assert_eq!((t.nx(), t.dx(), t.heights()), (3, 1e-6, &[1.0, 2.0, 3.0][..]));

    // No increment in the file: the options give it, or the error says so.
    let mut n = X3p::new(&v);
    n.cy = "<AxisType>I</AxisType>";
    let path = n.write(&dir, "no-dy.x3p");
    match read_err(&path, &opts()) {
        ReadError::NeedInterval { name: "dy", .. } => {}
        e => panic!("{e}"),
    }
    let t = read_file(
        &path,
        &ReadOptions {
            dy: Some(3e-6),
            ..opts()
        },
    )
    .unwrap();
    assert_eq!(t.dy(), Some(3e-6));
    // An option contradicting the file is an error; an agreeing one is fine.
    let path = X3p::new(&v).write(&dir, "with-dx.x3p");
    assert!(read_file(
        &path,
        &ReadOptions {
            dx: Some(1e-6),
            ..opts()
        }
    )
    .is_ok());
    match read_err(
        &path,
        &ReadOptions {
            dx: Some(1.1e-6),
            ..opts()
        },
    ) {
        ReadError::Conflict { name: "dx", .. } => {}
        e => panic!("{e}"),
    }
}

#[test]
fn x3p_checksums() {
    let dir = TempDir::new("x3p-md5");
    // The MD5 of 48 zero bytes (from Python's hashlib), either case.
    let md5 = "b203621a65475445e6fcdca717c667b5";
    let mut x = X3p::new(&[0.0; 6]);
    x.md5 = Some(md5.into());
    assert!(read_file(&x.write(&dir, "right.x3p"), &opts()).is_ok());
    x.md5 = Some(md5.to_uppercase());
    assert!(read_file(&x.write(&dir, "right-upper.x3p"), &opts()).is_ok());
    // The library's writer's checksum.
    let t = Topography::profile(vec![1e-6, 2e-6], 1e-6).unwrap();
    let good = dir.join("good.x3p");
    write_x3p(&t, &good, 'D').unwrap();
    assert!(read_file(&good, &opts()).is_ok());
    // One byte of data changed: refused.
    x.data[3] ^= 1;
    match read_err(&x.write(&dir, "wrong.x3p"), &opts()) {
        ReadError::Checksum {
            member,
            expected,
            actual,
            ..
        } => {
            assert_eq!(member, "bindata/data.bin");
            assert_eq!(expected, md5.to_uppercase());
            assert_ne!(actual, md5);
        }
        e => panic!("{e}"),
    }
}

#[test]
fn x3p_bad_files() {
    let dir = TempDir::new("x3p-bad");
    let v = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
    let check = |x: &X3p, name: &str, want: fn(&ReadError) -> bool| {
        let path = x.write(&dir, name);
        let err = read_err(&path, &opts());
        assert!(want(&err), "{name}: {err}");
    };
    // Sizes that do not match the data.
    let mut x = X3p::new(&v);
    x.size = (4, 2, 1);
    check(&x, "size.x3p", |e| matches!(e, ReadError::Size { .. }));
    x.size = (0, 2, 1);
    check(&x, "zero.x3p", |e| matches!(e, ReadError::Size { .. }));
    // Sizes declaring more than the bound, refused before allocating.
    x.size = (1_000_000, 1_000_000, 1);
    check(&x, "huge.x3p", |e| matches!(e, ReadError::TooManyPoints { .. }));
    x.size = (u64::MAX, 3, 1);
    check(&x, "overflow.x3p", |e| matches!(e, ReadError::TooManyPoints { .. }));
    // A mask of the wrong size.
    let mut x = X3p::new(&v);
    x.valid = Some(vec![0xff, 0xff]);
    check(&x, "mask-size.x3p", |e| matches!(e, ReadError::Size { .. }));
    // A mask link to no member.
    x.valid = None;
    x.valid_link = Some("bindata/nothere.bin");
    check(&x, "mask-link.x3p", |e| matches!(e, ReadError::Archive { .. }));
    // Unsupported types.
    let mut x = X3p::new(&v);
    x.z_type = "C";
    check(&x, "dtype.x3p", |e| matches!(e, ReadError::Unsupported { .. }));
    let mut x = X3p::new(&v);
    x.feature = "PCL";
    check(&x, "pcl.x3p", |e| matches!(e, ReadError::Unsupported { .. }));
    let mut x = X3p::new(&v);
    x.cx = "<AxisType>A</AxisType><DataType>D</DataType>";
    check(&x, "absolute-x.x3p", |e| matches!(e, ReadError::Unsupported { .. }));
    let mut x = X3p::new(&v);
    x.size = (3, 1, 2);
    check(&x, "volume.x3p", |e| matches!(e, ReadError::Unsupported { .. }));
    // A profile of two rows.
    let mut x = X3p::new(&v);
    x.feature = "PRF";
    check(&x, "prf-rows.x3p", |e| matches!(e, ReadError::Size { .. }));
    // Bad XML values.
    let mut x = X3p::new(&v);
    x.cz_extra = "<Increment>abc</Increment>".into();
    check(&x, "increment.x3p", |e| matches!(e, ReadError::Xml { .. }));
    x.cz_extra = "<Increment>0</Increment>".into();
    check(&x, "zero-increment.x3p", |e| matches!(e, ReadError::Xml { .. }));
    let mut x = X3p::new(&v);
    x.cx = "<AxisType>I</AxisType><Increment>-1e-6</Increment>";
    check(&x, "negative-dx.x3p", |e| matches!(e, ReadError::Topography { .. }));
    // An infinite height.
    let x = X3p::new(&[1.0, f64::INFINITY, 0.0, 0.0, 0.0, 0.0]);
    check(&x, "infinite.x3p", |e| matches!(e, ReadError::Topography { .. }));

    // Not XML; no main.xml; not a zip.
    let path = dir.join("not-xml.x3p");
    std::fs::write(&path, stored_zip(&[("main.xml", b"<a><b></a>")])).unwrap();
    assert!(matches!(read_err(&path, &opts()), ReadError::Xml { .. }));
    std::fs::write(&path, stored_zip(&[("other.xml", b"<a/>")])).unwrap();
    assert!(matches!(read_err(&path, &opts()), ReadError::Archive { .. }));
    std::fs::write(&path, b"just text").unwrap();
    assert!(matches!(read_err(&path, &opts()), ReadError::Archive { .. }));

    // Truncated archives (the library's writer, deflated): refused, at
    // every length.
    let t = sample_map(4, 3, 1e-6, 1e-6);
    let good = dir.join("good.x3p");
    write_x3p(&t, &good, 'D').unwrap();
    let bytes = std::fs::read(&good).unwrap();
    let cut = dir.join("truncated.x3p");
    std::fs::write(&cut, &bytes[..bytes.len() / 2]).unwrap();
    assert!(matches!(read_err(&cut, &opts()), ReadError::Archive { .. }));
    // (New files: rewriting one in place can wait for the disk.)
    for len in 0..bytes.len() {
        let cut = dir.join(&format!("cut-{len}.x3p"));
        std::fs::write(&cut, &bytes[..len]).unwrap();
        read_err(&cut, &opts());
    }
    // Damaged bytes: an error or (a flip in a name or a date) a read, never
    // a panic; a flip in the point data is caught by the CRC or the MD5.
    for k in 0..bytes.len() {
        let flipped = dir.join(&format!("flip-{k}.x3p"));
        let mut b = bytes.clone();
        b[k] ^= 0x20;
        std::fs::write(&flipped, &b).unwrap();
        if let Ok(r) = read_file(&flipped, &opts()) {
            assert_eq!(r.heights().len(), 12, "flip at {k}");
        }
    }
    // The byte bound.
    let small = ReadOptions {
        max_bytes: 100,
        ..opts()
    };
    assert!(matches!(read_err(&good, &small), ReadError::TooLarge { .. }));
}

/// An X3P file whose points are listed in main.xml (`DataList`), one
/// `Datum` each (`""`: an empty one).
fn x3p_data_list(z_type: &'static str, cz_extra: &str, datums: &[&str]) -> Vec<u8> {
    let mut x = X3p::new(&[]);
    x.z_type = z_type;
    x.cz_extra = cz_extra.into();
    let xml = x.xml();
    let list: String = datums
        .iter()
        .map(|d| {
            if d.is_empty() {
                "<Datum/>".to_string()
            } else {
                format!("<Datum>{d}</Datum>")
            }
        })
        .collect();
    let start = xml.find("<DataLink>").unwrap();
    let end = xml.find("</DataLink>").unwrap() + "</DataLink>".len();
    let xml = format!("{}<DataList>{list}</DataList>{}", &xml[..start], &xml[end..]);
    stored_zip(&[("main.xml", xml.as_bytes())])
}

#[test]
fn x3p_data_list_in_main_xml() {
    let dir = TempDir::new("x3p-data-list");
    let write = |name: &str, bytes: Vec<u8>| {
        let path = dir.join(name);
        std::fs::write(&path, bytes).unwrap();
        path
    };
    // Every z type; an empty Datum is a missing point; the CZ increment
    // and offset apply.
    let scale = "<Increment>1e-9</Increment><Offset>-2e-6</Offset>";
    let cases: [(&str, &[&str], [f64; 6]); 4] = [
        (
            "I",
            &["-32768", "-1", "", "1", "32767", "5"],
            [-32768.0, -1.0, f64::NAN, 1.0, 32767.0, 5.0],
        ),
        (
            "L",
            &["-2147483648", "0", "7", "", "2147483647", "-9"],
            [-2147483648.0, 0.0, 7.0, f64::NAN, 2147483647.0, -9.0],
        ),
        (
            "F",
            &["1.5", "-0.25", "0.1", "3", "", "1e-3"],
            [1.5, -0.25, f64::from(0.1f32), 3.0, f64::NAN, f64::from(1e-3f32)],
        ),
        (
            "D",
            &["1.5", "-0.25", "0.1", "3", "2", ""],
            [1.5, -0.25, 0.1, 3.0, 2.0, f64::NAN],
        ),
    ];
    for (z, datums, values) in cases {
        let path = write(&format!("{z}.x3p"), x3p_data_list(z, scale, datums));
        let t = read_file(&path, &opts()).unwrap();
        assert_eq!((t.nx(), t.ny(), t.dx(), t.dy()), (3, 2, 1e-6, Some(2e-6)));
        let want: Vec<f64> = values.iter().map(|v| -2e-6 + 1e-9 * v).collect();
        assert_heights(t.heights(), &want, 0.0);
    }
    // Bad lists name the problem: too few or too many points, a value
    // that is not of the type (or out of its range), coordinate triples.
    let bad: [(&str, &[&str], &str); 5] = [
        ("I", &["1", "2", "3", "4", "5"], "holds 5 points"),
        ("D", &["1", "2", "3", "4", "5", "6", "7"], "more than the 6 points"),
        ("I", &["1", "2", "40000", "4", "5", "6"], "Datum 2"),
        ("D", &["1", "x", "3", "4", "5", "6"], "Datum 1"),
        ("D", &["0;0;1", "2", "3", "4", "5", "6"], "coordinate lists"),
    ];
    for (k, (z, datums, needle)) in bad.into_iter().enumerate() {
        let path = write(&format!("bad{k}.x3p"), x3p_data_list(z, "", datums));
        let e = read_err(&path, &opts()).to_string();
        assert!(e.contains(needle) && e.contains(&format!("bad{k}.x3p")), "{e}");
    }
}
