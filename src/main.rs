//! `kefric`: the Kogut–Etsion static friction model from the command line.
//!
//! Thin by design: it parses, calls the library, prints. Bad input exits
//! with status 2 and a one-line message naming the input and its range.

mod cli;

fn main() {
    std::process::exit(cli::run());
}
