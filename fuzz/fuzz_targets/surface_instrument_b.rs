//! Structure-aware instrument files of part b: Zygo MetroPro `.dat` (a
//! binary header: signature, header size, intensity and phase sizes,
//! phase resolution, scale factors, lateral resolution), Bruker Nanoscope
//! (a text header of sections: version, soft scales, scan list, image
//! sections with offsets, lengths, sizes, Z scales) and Nanosurf `.nid`
//! (an INI header of groups and channels, `#!`, data), each with data of a
//! length right or off, a few bytes flipped afterwards, a channel chosen
//! or not, maybe cut short, read by `read_bytes` under the file's name; a surface read
//! keeps the invariant of surface_check.rs. Raw bytes rarely make a header
//! that parses: this target reaches the size, scale, unit and channel
//! handling every run.
#![no_main]

#[path = "instrument_b_grammar.rs"]
mod grammar;
#[path = "surface_check.rs"]
mod surface_check;

use grammar::Input;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: Input| {
    let (bytes, name, options) = grammar::file(&input);
    surface_check::read(&bytes, name, &options);
});
