//! The program with damaged table files: every subcommand that reads one
//! rejects it with status 2 and one line naming `--table`, and writes
//! nothing. (The file format's own hardening is a unit test of the
//! library, `src/table/tests.rs`.)

use crate::common::TempDir;
use crate::support::{bad_input_problem, kefric, stderr};
use ke_friction::Table;
use std::path::{Path, PathBuf};

/// The header's length: magic (8), version (4), payload length (8).
const HEADER: usize = 20;

/// Rewrites the CRC-32 at the end of a table file after a patch.
fn recrc(bytes: &mut [u8]) {
    let end = bytes.len() - 4;
    let crc = crc32fast::hash(&bytes[..end]);
    bytes[end..].copy_from_slice(&crc.to_le_bytes());
}

/// The default table with `patch` applied to its payload and a valid CRC:
/// well framed, wrong inside.
fn forged(patch: impl Fn(&mut [u8])) -> Vec<u8> {
    let mut b = Table::embedded_bytes().to_vec();
    let end = b.len() - 4;
    patch(&mut b[HEADER..end]);
    recrc(&mut b);
    b
}

/// Damaged table files, each with a short name.
fn corrupted_files(dir: &Path) -> Vec<(String, PathBuf)> {
    let g = Table::embedded_bytes();
    let mut files: Vec<(String, Vec<u8>)> = vec![];
    let mut flipped = g.to_vec();
    flipped[g.len() / 2] ^= 0x40;
    files.push(("payload byte flipped".into(), flipped));
    let mut crc = g.to_vec();
    let n = crc.len();
    crc[n - 1] ^= 1;
    files.push(("checksum byte flipped".into(), crc));
    files.push(("truncated".into(), g[..g.len() - 1].to_vec()));
    files.push(("header only".into(), g[..HEADER].to_vec()));
    let mut magic = g.to_vec();
    magic[0] = b'X';
    files.push(("wrong magic".into(), magic));
    let mut version = g.to_vec();
    version[8..12].copy_from_slice(&2u32.to_le_bytes());
    recrc(&mut version);
    files.push(("version 2".into(), version));
    let mut trailing = g.to_vec();
    trailing.extend_from_slice(b"junk");
    files.push(("trailing junk".into(), trailing));
    // The payload starts with the model constants β, ν, ε* (f64, little
    // endian), then the fit and model codes (one byte each), then the ψ
    // axis, whose first byte is its scale code.
    files.push((
        "NaN beta".into(),
        forged(|p| p[..8].copy_from_slice(&f64::NAN.to_le_bytes())),
    ));
    files.push(("unknown fit code".into(), forged(|p| p[24] = 9)));
    files.push(("unknown scale code".into(), forged(|p| p[26] = 7)));
    files
        .into_iter()
        .enumerate()
        .map(|(i, (what, bytes))| {
            let path = dir.join(format!("corrupt-{i}.kft"));
            std::fs::write(&path, bytes).unwrap();
            (what, path)
        })
        .collect()
}

#[test]
fn the_forged_files_are_rejected_by_the_library_for_what_was_forged() {
    let dir = TempDir::new("corrupted-tables-lib");
    for (what, path) in corrupted_files(&dir.0) {
        let e = Table::load(&path).expect_err(&what).to_string();
        let want = match what.as_str() {
            "NaN beta" => "model constants",
            "unknown fit code" => "unknown fit code 9",
            "unknown scale code" => "unknown scale code 7",
            _ => continue,
        };
        assert!(e.contains(want), "{what}: {e}");
    }
}

#[test]
fn the_cli_rejects_corrupted_tables_with_status_2_and_one_line() {
    let dir = TempDir::new("corrupted-tables");
    let npz = dir.join("out.npz");
    let mut failures = vec![];
    for (what, path) in corrupted_files(&dir.0) {
        let table = path.display().to_string();
        let npz = npz.display().to_string();
        let runs: [&[&str]; 3] = [
            &[
                "lookup", "--psi", "1", "--theta", "0.001", "--f-star", "0.01", "--table", &table,
            ],
            &["verify", "--quiet", "--samples", "10", "--table", &table],
            &["export", "--quiet", "--npz", &npz, "--table", &table],
        ];
        for args in runs {
            let o = kefric(args);
            let out = String::from_utf8_lossy(&o.stdout);
            if let Some(why) = bad_input_problem(o.status.code(), &out, &stderr(&o), "--table") {
                failures.push(format!("{} on {what}: {why}", args[0]));
            }
        }
    }
    assert!(!npz.exists(), "export wrote output from a corrupted table");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
