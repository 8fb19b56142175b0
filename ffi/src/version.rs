//! The library's version.

use std::ffi::{c_char, CStr};

/// The library's version ("MAJOR.MINOR.PATCH", the crate's version), a
/// static string: never NULL, not to free.
#[no_mangle]
pub extern "C" fn kef_version() -> *const c_char {
    ffi!(=> Ok(VERSION))
}

/// The crate's version, NUL-terminated.
const VERSION: &CStr = match CStr::from_bytes_with_nul(concat!(env!("CARGO_PKG_VERSION"), "\0").as_bytes()) {
    Ok(v) => v,
    Err(_) => panic!("the crate version has no NUL"),
};
