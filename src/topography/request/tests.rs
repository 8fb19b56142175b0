//! The request's tests: each error names its input in each spelling.

use super::*;

/// A 40 × 30 text map (a few incommensurate waves), shared with the web
/// page's tests: `tests/data/text_map.txt`.
fn map_text() -> Vec<u8> {
    include_bytes!("../../../tests/data/text_map.txt").to_vec()
}

fn cli(f: Field) -> String {
    f.flag()
}

#[test]
fn every_field_has_a_name_and_a_flag() {
    assert_eq!(Field::TipRadius.flag(), "--tip-radius");
    assert_eq!(Field::of_name("pressure (= force/area)"), Some(Field::Pressure));
    for (f, name) in Field::MATERIALS.iter().zip(Materials::FIELDS) {
        assert_eq!(f.name(), name);
    }
}

#[test]
fn a_map_without_dx_names_the_fields_in_each_spelling() {
    let bytes = map_text();
    let e = SurfaceRequest::default()
        .run(&[Source::Bytes {
            bytes: &bytes,
            name: "h.txt",
        }])
        .unwrap_err();
    assert_eq!(e.field, Field::File);
    assert_eq!(
        e.message.render(&cli),
        "h.txt: the file gives no sampling interval dx: give --dx (and --dy for a map, if it differs), in --xy-unit"
    );
    assert_eq!(
        e.to_string(),
        "file: h.txt: the file gives no sampling interval dx: give dx (and dy for a map, if it differs), in xy_unit"
    );
}

#[test]
fn dy_defaults_to_dx_in_one_read() {
    let bytes = map_text();
    let request = SurfaceRequest {
        dx: Some(0.5),
        xy_unit: 1e-6,
        ..SurfaceRequest::default()
    };
    let a = request
        .run(&[Source::Bytes {
            bytes: &bytes,
            name: "h.txt",
        }])
        .unwrap();
    assert_eq!(a.surface.stats().dy, Some(0.5e-6));
    assert!(a.evaluation.is_none());
}

#[test]
fn the_materials_go_together_and_a_load_needs_them() {
    let mut materials = [None; 7];
    materials[0] = Some(70e9);
    let r = SurfaceRequest {
        materials,
        ..SurfaceRequest::default()
    };
    let e = r.check().unwrap_err();
    assert_eq!(e.field, Field::Nu1);
    assert!(
        e.render(&cli)
            .starts_with("--nu1: missing: the SI inputs go together (--e1, --nu1,"),
        "{e}"
    );
    let r = SurfaceRequest {
        loads: LoadInputs::one(None, None, Some(1e6)),
        ..SurfaceRequest::default()
    };
    let e = r.check().unwrap_err();
    assert!(
        e.render(&cli).starts_with("--pressure: needs the materials (--e1"),
        "{e}"
    );
    let r = SurfaceRequest {
        loads: LoadInputs::one(Some(-1.0), Some(1e-5), None),
        ..SurfaceRequest::default()
    };
    assert_eq!(r.check().unwrap_err().field, Field::Force);
    let r = SurfaceRequest {
        lambda_s: Some(LambdaS::Auto),
        dx: Some(1e-6),
        ..SurfaceRequest::default()
    };
    let bytes = map_text();
    let e = r
        .run(&[Source::Bytes {
            bytes: &bytes,
            name: "h.txt",
        }])
        .unwrap_err();
    assert_eq!(
        e.render(&cli),
        "--file: h.txt: --lambda-s auto: give --tip-radius or --resolution for the reliability cut-off"
    );
}
