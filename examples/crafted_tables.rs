//! Writes the crafted table files of `tests/forge.rs` (issue 23's attack:
//! valid checksums, hostile contents) into a directory, for the checks
//! that run other programs on them: valgrind on `kefric`, the C ABI, the
//! Python package. Not a user tool.
//!
//! `cargo run --release --example crafted_tables -- DIR` writes
//! `DIR/NN.kft` and `DIR/index.tsv`, one line per file:
//! `file<TAB>refused-field-or-ok<TAB>psi theta f_star<TAB>expected mu`
//! (the query and μ = e^c for the files that must load).

#[path = "../tests/forge.rs"]
mod forge;

fn main() -> std::io::Result<()> {
    let Some(dir) = std::env::args_os().nth(1) else {
        eprintln!("usage: crafted_tables DIR");
        std::process::exit(2);
    };
    let dir = std::path::PathBuf::from(dir);
    std::fs::create_dir_all(&dir)?;
    let mut index = String::new();
    for (i, (name, spec, refused)) in forge::crafted().into_iter().enumerate() {
        let file = format!("{i:02}.kft");
        std::fs::write(dir.join(&file), spec.encode())?;
        let [p, t, f] = spec.axes.map(|a| (a.lo * a.hi).sqrt().max(a.lo));
        let expected = spec.stored(spec.ln_mu[0]).exp();
        index.push_str(&format!(
            "{file}\t{}\t{p:e} {t:e} {f:e}\t{expected:e}\t{name}\n",
            refused.unwrap_or("ok")
        ));
    }
    std::fs::write(dir.join("index.tsv"), index)?;
    println!("wrote {} crafted tables into {}", forge::crafted().len(), dir.display());
    Ok(())
}
