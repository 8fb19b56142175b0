//! contact.engineering containers: bytes that start like a zip are read
//! as the container; otherwise they are split at the first NUL into a
//! `meta.yml` and a data file `p.txt` (the name the seeds' metadata
//! uses; a NetCDF file when it starts with `CDF`), zipped, and read.
//! Bounds small (1 MiB a member, 2²⁰ points); nothing may panic, and a
//! read container's measurements, spectra, combined spectrum and combined
//! scale-dependent statistics are finite where they exist. Seeds
//! (tools/container_fuzz_seeds.py): a lying meta.yml, a missing member, a
//! deep YAML, a zip bomb (honest and lying headers), a NetCDF-only
//! measurement.
#![no_main]

use std::io::Write;

use ke_friction::topography::container::{
    combined_psd, combined_scale_dependent, measurement_psd, read_container_bytes, ContainerOptions, Heights,
};
use ke_friction::topography::ReadOptions;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let bytes = if data.starts_with(b"PK") {
        data.to_vec()
    } else {
        let cut = data.iter().position(|&b| b == 0).unwrap_or(data.len());
        let (meta, rest) = data.split_at(cut);
        let member = rest.get(1..).unwrap_or(&[]);
        let mut w = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
        let opts = zip::write::SimpleFileOptions::default();
        w.start_file("meta.yml", opts).unwrap();
        w.write_all(meta).unwrap();
        w.start_file("p.txt", opts).unwrap();
        w.write_all(member).unwrap();
        w.finish().unwrap().into_inner()
    };
    let options = ContainerOptions {
        read: ReadOptions {
            max_bytes: 1 << 20,
            max_points: 1 << 20,
            ..ReadOptions::default()
        },
        ..ContainerOptions::default()
    };
    let Ok(surfaces) = read_container_bytes(&bytes, "fuzz.zip", &options) else { return };
    for s in &surfaces {
        for m in &s.measurements {
            if let Heights::Nonuniform { x, .. } = &m.heights {
                assert!(x.windows(2).all(|w| w[1] > w[0]));
            }
        }
        let spectra: Vec<_> = s.measurements.iter().map(measurement_psd).collect();
        if let Some(c) = combined_psd(&spectra, 10) {
            assert_eq!(c.psd.q.len(), c.psd.c.len());
            assert!(c.psd.q.iter().all(|q| q.is_finite() && *q > 0.0));
        }
        for order in [1, 2] {
            if let Some(c) = combined_scale_dependent(&s.measurements, order, 10) {
                assert_eq!(c.distance.len(), c.mean_square.len());
                assert!(c.distance.iter().all(|d| d.is_finite() && *d > 0.0));
                assert!(c.mean_square.iter().all(|v| v.is_nan() || *v >= 0.0));
            }
        }
    }
});
