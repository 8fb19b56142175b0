//! What the `*_dump` examples (`psd_dump`, `read_dump`, `scale_dump`)
//! share: run on the command line's arguments, print the JSON answer on
//! stdout, or the error on stderr with a failure status.

use std::process::ExitCode;

/// What an example computes from its arguments.
pub type Run = fn(&[String]) -> Result<serde_json::Value, Box<dyn std::error::Error>>;

/// The example `name`'s `main`: `run` on the arguments after the program's.
pub fn main(name: &str, run: Run) -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(v) => {
            println!("{v}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{name}: {e}");
            ExitCode::FAILURE
        }
    }
}
