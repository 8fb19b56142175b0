//! Structure-aware instruments' files, part a: Digital Surf `.sur`,
//! Sensofar `.plu`, Bruker/Veeco `.opd` and Alicona `.al3d`, built field
//! by field from `arbitrary` choices (sizes small, zero, negative or huge;
//! a point count, directory length, tag count or data offset right or off;
//! units, item sizes, block types and tag values the readers know or not;
//! data of the declared length or not), then damaged by a few byte flips
//! and maybe cut short; read by `read_bytes` under the format's extension,
//! with or without a channel chosen. A surface read keeps the invariant of
//! surface_check.rs; raw bytes would rarely get past the signatures.
#![no_main]

#[path = "instruments_a_grammar.rs"]
mod grammar;
#[path = "surface_check.rs"]
mod surface_check;

use grammar::Input;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: Input| {
    let (bytes, name, options) = grammar::file(&input);
    surface_check::read(&bytes, name, &options);
});
