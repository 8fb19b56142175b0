//! Hardening of the file format: `Table::from_bytes` against truncated,
//! corrupted, forged and random input (it must return an error, never
//! panic, never hand back a table). The forgeries use the private format
//! (`format::Payload`, `encode`), so these are unit tests of the crate;
//! `cli/tests/cli/corrupted_tables.rs` runs the program on damaged files.

use super::format::{self, Coefs, Payload};
use super::{Table, TableError};
use crate::spline::Scale;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Decodes `bytes`, turning a panic into a test failure that names `what`.
fn decode(what: &str, bytes: &[u8]) -> Result<Table, TableError> {
    match catch_unwind(AssertUnwindSafe(|| Table::from_bytes(bytes))) {
        Ok(r) => r,
        Err(_) => panic!("Table::from_bytes panicked on {what}"),
    }
}

/// Asserts that `bytes`, a well-framed file (valid header and CRC), is
/// rejected for its payload: it does not decode or is inconsistent.
#[track_caller]
fn payload_rejected(what: &str, bytes: &[u8]) {
    let e = rejected(what, bytes);
    assert!(
        matches!(e, TableError::Payload(_) | TableError::Inconsistent(_)),
        "{what}: {e:?}"
    );
}

/// Asserts that `bytes` is rejected, and returns the error.
#[track_caller]
fn rejected(what: &str, bytes: &[u8]) -> TableError {
    match decode(what, bytes) {
        Ok(_) => panic!("{what}: accepted as a table"),
        Err(e) => e,
    }
}

fn good() -> &'static [u8] {
    Table::embedded_bytes()
}

/// Rewrites the CRC of a table file after its header or payload was patched.
fn recrc(bytes: &mut [u8]) {
    let end = bytes.len() - 4;
    let crc = crc32fast::hash(&bytes[..end]);
    bytes[end..].copy_from_slice(&crc.to_le_bytes());
}

/// A file with the real magic and version, `payload` as its payload, its
/// true length and a valid CRC.
fn framed(payload: &[u8]) -> Vec<u8> {
    let mut b = good()[..12].to_vec();
    b.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    b.extend_from_slice(payload);
    b.extend_from_slice(&[0; 4]);
    recrc(&mut b);
    b
}

/// The default table's payload, for forging consistent-looking files.
fn payload() -> Payload {
    format::decode(good()).expect("the embedded table decodes")
}

#[test]
fn the_embedded_table_round_trips() {
    let t = decode("the embedded table", good()).expect("valid");
    assert!(t.mu(1.0, 0.001, 0.01).is_ok());
    // encode(decode(x)) == x: forged files below differ only where patched.
    assert_eq!(format::encode(&payload()), good());
}

#[test]
fn every_truncation_is_rejected() {
    let bytes = good();
    for n in 0..bytes.len() {
        let e = rejected(&format!("the first {n} bytes"), &bytes[..n]);
        assert!(
            matches!(e, TableError::TooShort { .. } | TableError::Length { .. }),
            "{n} bytes: {e:?}"
        );
    }
    // And a header that claims exactly the truncated length (valid CRC):
    // the payload itself is cut short.
    for cut in [1, 2, 3, 7, 100, 4096, bytes.len() / 2, bytes.len() - 25] {
        let forged = framed(&bytes[20..bytes.len() - 4 - cut]);
        payload_rejected(&format!("a payload cut by {cut} bytes, CRC valid"), &forged);
    }
}

#[test]
fn random_corruptions_are_rejected() {
    let bytes = good();
    let mut rng = ChaCha8Rng::seed_from_u64(0x6b65_6672);
    let mut copy = bytes.to_vec();
    for trial in 0..3000 {
        // 1 to 4 bytes flipped (bursts), or up to 64 scattered ones.
        let mut touched = vec![];
        let scattered = trial % 3 == 2;
        let n = if scattered {
            rng.gen_range(2..=64)
        } else {
            rng.gen_range(1..=4)
        };
        let start = rng.gen_range(0..bytes.len());
        for k in 0..n {
            let i = if scattered {
                rng.gen_range(0..bytes.len())
            } else {
                (start + k) % bytes.len()
            };
            copy[i] ^= rng.gen_range(1..=255u8);
            touched.push(i);
        }
        if copy != bytes {
            rejected(&format!("trial {trial}: bytes {touched:?} corrupted"), &copy);
        }
        for &i in &touched {
            copy[i] = bytes[i];
        }
    }
    // Every single bit of the header and the checksum.
    for i in (0..20).chain(bytes.len() - 4..bytes.len()) {
        for bit in 0..8 {
            copy[i] ^= 1 << bit;
            rejected(&format!("bit {bit} of byte {i} flipped"), &copy);
            copy[i] ^= 1 << bit;
        }
    }
}

#[test]
fn wrong_magic_is_rejected_as_such() {
    for i in 0..8 {
        let mut b = good().to_vec();
        b[i] ^= 0x20;
        recrc(&mut b);
        assert_eq!(rejected("wrong magic", &b), TableError::WrongMagic, "byte {i}");
    }
    let mut b = good().to_vec();
    b[..8].copy_from_slice(b"KEFRICTA");
    assert_eq!(rejected("wrong magic", &b), TableError::WrongMagic);
}

#[test]
fn a_future_version_is_rejected_by_the_version_check() {
    for v in [0u32, 3, 255, 256, u32::MAX] {
        let mut b = good().to_vec();
        b[8..12].copy_from_slice(&v.to_le_bytes());
        recrc(&mut b);
        assert_eq!(
            rejected(&format!("version {v}"), &b),
            TableError::UnsupportedVersion { found: v }
        );
    }
}

#[test]
fn wrong_lengths_are_rejected() {
    let len = good().len() as u64 - 24;
    for claimed in [0, 1, len - 1, len + 1, len * 2, u64::MAX / 2, u64::MAX - 23, u64::MAX] {
        let mut b = good().to_vec();
        b[12..20].copy_from_slice(&claimed.to_le_bytes());
        recrc(&mut b);
        let e = rejected(&format!("length field {claimed}"), &b);
        assert!(matches!(e, TableError::Length { .. }), "{claimed}: {e:?}");
    }
    // Trailing bytes after the checksum.
    let mut b = good().to_vec();
    b.extend_from_slice(&[0; 16]);
    assert!(matches!(rejected("trailing bytes", &b), TableError::Length { .. }));
    // Trailing bytes inside the payload (header and CRC made to agree).
    let mut b = good()[..good().len() - 4].to_vec();
    b.extend_from_slice(&[0, 0, 0]);
    b[12..20].copy_from_slice(&(len + 3).to_le_bytes());
    b.extend_from_slice(&[0; 4]);
    recrc(&mut b);
    assert!(matches!(
        rejected("bytes after the payload", &b),
        TableError::Payload(_)
    ));
}

/// Every way of making the payload inconsistent while keeping the file's
/// framing and checksum valid.
fn inconsistent_payloads() -> Vec<(&'static str, Payload)> {
    let mut v: Vec<(&'static str, Payload)> = vec![];
    let mut add = |what: &'static str, f: &dyn Fn(&mut Payload)| {
        let mut p = payload();
        f(&mut p);
        v.push((what, p));
    };
    add("one more psi node", &|p| p.axes[0].nodes += 1);
    add("one fewer theta node", &|p| p.axes[1].nodes -= 1);
    add("one more F* node", &|p| p.axes[2].nodes += 1);
    add("4 F* nodes", &|p| p.axes[2].nodes = 4);
    add("0 psi nodes", &|p| p.axes[0].nodes = 0);
    add("u32::MAX nodes on every axis", &|p| {
        for a in &mut p.axes {
            a.nodes = u32::MAX;
        }
    });
    add("2^20 nodes on every axis", &|p| {
        for a in &mut p.axes {
            a.nodes = 1 << 20;
        }
    });
    add("ln_mu one short", &|p| match &mut p.ln_mu {
        Coefs::F32(c) => {
            c.pop();
        }
        Coefs::F64(c) => {
            c.pop();
        }
    });
    add("ln_mu empty", &|p| p.ln_mu = Coefs::F32(vec![]));
    add("h_star one too many", &|p| match &mut p.h_star {
        Coefs::F32(c) => c.push(0.0),
        Coefs::F64(c) => c.push(0.0),
    });
    add("h_star in f64, one short", &|p| {
        let mut c = p.h_star.to_f64();
        c.pop();
        p.h_star = Coefs::F64(c);
    });
    for (what, bad) in [
        ("NaN in ln_mu", f64::NAN),
        ("+inf in ln_mu", f64::INFINITY),
        ("-inf in ln_mu", f64::NEG_INFINITY),
    ] {
        add(what, &move |p| {
            let mut c = p.ln_mu.to_f64();
            let mid = c.len() / 2;
            c[mid] = bad;
            p.ln_mu = Coefs::F64(c);
        });
    }
    add("NaN in h_star (f32)", &|p| match &mut p.h_star {
        Coefs::F32(c) => c[0] = f32::NAN,
        Coefs::F64(c) => c[0] = f64::NAN,
    });
    add("inf as the last ln_mu (f32)", &|p| match &mut p.ln_mu {
        Coefs::F32(c) => *c.last_mut().unwrap() = f32::INFINITY,
        Coefs::F64(c) => *c.last_mut().unwrap() = f64::INFINITY,
    });
    add("zero psi spacing", &|p| p.axes[0].step = 0.0);
    add("negative F* spacing", &|p| p.axes[2].step = -p.axes[2].step);
    add("NaN theta spacing", &|p| p.axes[1].step = f64::NAN);
    add("infinite first psi node", &|p| p.axes[0].first = f64::INFINITY);
    add("NaN first F* node", &|p| p.axes[2].first = f64::NAN);
    add("reversed psi domain", &|p| {
        let a = &mut p.axes[0];
        std::mem::swap(&mut a.lo, &mut a.hi);
    });
    add("empty F* domain", &|p| p.axes[2].hi = p.axes[2].lo);
    add("NaN theta domain end", &|p| p.axes[1].hi = f64::NAN);
    add("psi domain beyond the grid", &|p| p.axes[0].hi *= 10.0);
    add("F* domain below the grid", &|p| p.axes[2].lo /= 10.0);
    add("zero psi on a log axis", &|p| p.axes[0].lo = 0.0);
    add("negative theta", &|p| p.axes[1].lo = -1e-3);
    add("theta axis made logarithmic", &|p| p.axes[1].scale = Scale::Log.code());
    add(
        "theta axis made linear (valid on its own, but not the map the lookup applies)",
        &|p| p.axes[1].scale = 2,
    );
    add("unknown scale code on psi", &|p| p.axes[0].scale = 3);
    add("unknown scale code on F*", &|p| p.axes[2].scale = 255);
    add("invalid beta", &|p| p.model.beta = 0.01);
    add("NaN nu", &|p| p.model.nu = f64::NAN);
    add("nu = 0.5", &|p| p.model.nu = 0.5);
    add("zero eps_star", &|p| p.model.eps_star = 0.0);
    add("unknown fit code", &|p| p.model.fit = 2);
    add("unknown model code", &|p| p.model.kind = 255);
    add("NaN tolerance", &|p| p.accuracy.tolerance = f64::NAN);
    add("zero tolerance", &|p| p.accuracy.tolerance = 0.0);
    add("infinite max error", &|p| p.accuracy.max_rel = f64::INFINITY);
    add("NaN 99th percentile", &|p| p.accuracy.p99_rel = f64::NAN);
    v
}

#[test]
fn inconsistent_payloads_with_valid_checksums_are_rejected() {
    for (what, p) in inconsistent_payloads() {
        let bytes = format::encode(&p);
        // The framing is valid: only the contents are wrong.
        assert!(format::decode(&bytes).is_ok(), "{what}: framing rejected");
        let e = rejected(what, &bytes);
        assert!(matches!(e, TableError::Inconsistent(_)), "{what}: {e:?}");
    }
}

#[test]
fn payloads_that_do_not_decode_are_rejected() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let body_len = good().len() - 24;
    for trial in 0..300 {
        let len = match trial % 3 {
            0 => rng.gen_range(0..64),
            1 => rng.gen_range(0..4096),
            _ => body_len,
        };
        let mut body = vec![0u8; len];
        rng.fill(&mut body[..]);
        if trial % 5 == 0 && len > 40 {
            // Start like the real payload, then turn to noise.
            let keep = rng.gen_range(1..40);
            body[..keep].copy_from_slice(&good()[20..20 + keep]);
        }
        let b = framed(&body);
        payload_rejected(&format!("random payload {trial} ({len} bytes)"), &b);
    }
}

#[test]
fn random_byte_strings_are_rejected() {
    let mut rng = ChaCha8Rng::seed_from_u64(42);
    for trial in 0..3000 {
        let len = match trial % 4 {
            0 => rng.gen_range(0..32),
            1 => rng.gen_range(0..1024),
            2 => rng.gen_range(0..65536),
            _ => good().len(),
        };
        let mut b = vec![0u8; len];
        rng.fill(&mut b[..]);
        if trial % 2 == 1 && len >= 12 {
            // With the right magic and version, so that later checks run.
            b[..8].copy_from_slice(&format::MAGIC);
            b[8..12].copy_from_slice(&format::VERSION.to_le_bytes());
        }
        rejected(&format!("random bytes {trial} ({len} bytes)"), &b);
    }
}

#[test]
fn coefficients_are_stored_with_their_explicit_precision_codes() {
    let f32_bytes = postcard::to_allocvec(&Coefs::F32(vec![1.5])).unwrap();
    let f64_bytes = postcard::to_allocvec(&Coefs::F64(vec![1.5])).unwrap();
    // Code, then the length (a varint), then the little-endian values.
    assert_eq!(f32_bytes, [&[0u8, 1][..], &1.5f32.to_le_bytes()].concat());
    assert_eq!(f64_bytes, [&[1u8, 1][..], &1.5f64.to_le_bytes()].concat());
    for c in [Coefs::F32(vec![1.5, -2.0]), Coefs::F64(vec![1.5, -2.0])] {
        let back: Coefs = postcard::from_bytes(&postcard::to_allocvec(&c).unwrap()).unwrap();
        assert_eq!(back, c);
    }
}

#[test]
fn an_unknown_precision_code_is_rejected_as_a_payload_error() {
    let p = payload();
    // The ln μ coefficients follow the model constants and the three axes.
    let prefix = postcard::to_allocvec(&p.model).unwrap().len()
        + p.axes
            .iter()
            .map(|a| postcard::to_allocvec(a).unwrap().len())
            .sum::<usize>();
    let mut body = postcard::to_allocvec(&p).unwrap();
    assert_eq!(body[prefix], Coefs::F32_CODE as u8, "the default table stores f32");
    body[prefix] = 2;
    // (postcard reports a custom serde error without its text.)
    let e = rejected("precision code 2", &framed(&body));
    assert!(matches!(e, TableError::Payload(_)), "{e:?}");
    body[prefix] = Coefs::F64_CODE as u8;
    let e = rejected("f32 data read as f64", &framed(&body));
    assert!(matches!(e, TableError::Payload(_)), "{e:?}");
}
