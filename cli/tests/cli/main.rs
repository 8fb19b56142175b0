//! The tests of the `kefric` program, one crate (one binary to compile and
//! link): each module runs the binary built for the tests.

// Tolerances and `TempDir`, shared with the library's tests.
#[path = "../../../tests/it/common.rs"]
mod common;
mod support;
// The independent table encoder (crafted files).
#[path = "../../../tests/forge.rs"]
mod forge;
// The independent .npy encoder.
#[path = "../../../tests/npy.rs"]
mod npy;

mod cli_container;
mod cli_container_scale;
mod cli_eval;
mod cli_export;
mod cli_law;
mod cli_measurements;
mod cli_scale;
mod cli_surface;
mod cli_table;
mod cli_tools;
mod cli_warnings;
mod corrupted_tables;
mod figures;
mod hardening_build;
mod hardening_cli;
mod hostile_numerics;
mod untrusted;
mod validation_doc;
