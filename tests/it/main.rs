//! The library's integration tests, one crate (one binary to compile and
//! link): the model against reference values and an independent
//! implementation, its properties and hardening, the paper's statements,
//! and the tables against direct integration.

mod batch_contract;
mod common;
mod container;
mod container_loose;
mod crafted_tables;
mod curve;
// The independent table encoder, shared with the CLI's, the C ABI's tests
// and the fuzz targets.
#[path = "../forge.rs"]
mod forge;
mod hardening_numerics;
mod hostile_numerics;
mod hostile_readers;
mod hostile_surfaces;
mod nongaussian;
#[path = "../npy.rs"]
mod npy;
mod paper_statements;
mod properties;
mod reference_points;
mod reference_values;
// The README's synthetic map, shared with `examples/rough_surface.rs`.
#[path = "../../examples/rough/mod.rs"]
mod rough;
mod surface_friction;
mod table_lookup;
mod topography_filter;
mod topography_instruments_a;
mod topography_instruments_b;
mod topography_read;
mod topography_read_x3p;
mod topography_scale;
mod topography_stats;
mod validity_warnings;
