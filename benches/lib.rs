//! Nothing but a home for the criterion benchmarks `model.rs` and
//! `lookup.rs`: `cargo bench -p ke-friction-bench --bench lookup`.
