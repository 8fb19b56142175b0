//! The C ABI's committed header, `ffi/include/kefriction.h`, is exactly what
//! cbindgen generates from `ffi/src/lib.rs` with `ffi/cbindgen.toml`; exits
//! non-zero when it is not. With `KEF_BLESS` set, writes the generated
//! header instead.

use std::path::Path;
use std::process::ExitCode;

fn main() -> ExitCode {
    let ffi = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let config = match cbindgen::Config::from_file(ffi.join("cbindgen.toml")) {
        Ok(config) => config,
        Err(e) => {
            eprintln!("header-check: ffi/cbindgen.toml: {e}");
            return ExitCode::FAILURE;
        }
    };
    let bindings = match cbindgen::Builder::new().with_crate(&ffi).with_config(config).generate() {
        Ok(bindings) => bindings,
        Err(e) => {
            eprintln!("header-check: cbindgen cannot parse ffi/src/lib.rs: {e}");
            return ExitCode::FAILURE;
        }
    };
    let mut generated = Vec::new();
    bindings.write(&mut generated);
    let path = ffi.join("include/kefriction.h");
    if std::env::var_os("KEF_BLESS").is_some() {
        if let Err(e) = std::fs::write(&path, &generated) {
            eprintln!("header-check: cannot write ffi/include/kefriction.h: {e}");
            return ExitCode::FAILURE;
        }
        println!("header-check: wrote ffi/include/kefriction.h");
        return ExitCode::SUCCESS;
    }
    let committed = std::fs::read(&path).unwrap_or_default();
    if committed != generated {
        let newline = |&b: &u8| b == b'\n';
        let line = committed
            .split(newline)
            .zip(generated.split(newline))
            .take_while(|(a, b)| a == b)
            .count()
            + 1;
        eprintln!(
            "header-check: ffi/include/kefriction.h is stale (it differs from cbindgen's output from line {line} on): \
             run KEF_BLESS=1 cargo run -p ke-friction-ffi-header-check"
        );
        return ExitCode::FAILURE;
    }
    println!("header-check: ffi/include/kefriction.h is current");
    ExitCode::SUCCESS
}
