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
