//! `KE_FRICTION_PORTABLE=1` at build time selects the portable kernels on
//! x86-64 (as on every other target), like `RUSTFLAGS='--cfg
//! ke_friction_portable'`, but for this package only: its dependencies
//! keep their compiled artefacts (CI's `portable` stage then rebuilds one
//! crate, not the whole tree).

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-env-changed=KE_FRICTION_PORTABLE");
    if std::env::var_os("KE_FRICTION_PORTABLE").is_some_and(|v| v == "1") {
        println!("cargo::rustc-cfg=ke_friction_portable");
    }
}
