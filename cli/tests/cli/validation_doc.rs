//! `docs/validation.md` is exactly what `kefric validate` prints, so that
//! the page stays true to the code. After a change that moves a number,
//! regenerate it: `cargo run --release -- validate > docs/validation.md`.
use std::process::Command;

#[test]
fn validation_doc_is_the_output_of_kefric_validate() {
    let o = Command::new(env!("CARGO_BIN_EXE_kefric"))
        .arg("validate")
        .output()
        .expect("kefric runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let doc_path = concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/validation.md");
    let doc = std::fs::read(doc_path).expect("docs/validation.md exists");
    if o.stdout != doc {
        let (out, doc) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&doc));
        let first = out
            .lines()
            .zip(doc.lines())
            .position(|(a, b)| a != b)
            .unwrap_or(out.lines().count().min(doc.lines().count()));
        panic!(
            "docs/validation.md differs from `kefric validate` from line {}:\n  doc:    {:?}\n  output: {:?}\n\
             regenerate it with `cargo run --release -- validate > docs/validation.md`",
            first + 1,
            doc.lines().nth(first),
            out.lines().nth(first)
        );
    }
}

/// The page states its tolerances once, and the CEB-type row at ψ = 1 is
/// no longer a plain "agrees": it says where it holds.
#[test]
fn validation_doc_says_where_the_ceb_row_at_psi_1_holds() {
    let doc_path = concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/validation.md");
    let doc = std::fs::read_to_string(doc_path).expect("docs/validation.md exists");
    assert_eq!(doc.matches("**Tolerances.**").count(), 1);
    let row = doc
        .lines()
        .find(|l| l.starts_with("| 11 |") && l.contains("the same at ψ = 1"))
        .expect("the CEB row at ψ = 1");
    let verdict = row.trim_end_matches('|').rsplit('|').next().unwrap().trim();
    assert!(verdict.starts_with("**partly**: only for F* in ["), "{verdict}");
    assert!(row.contains("within 2.5–4.5×"), "{row}");
}
