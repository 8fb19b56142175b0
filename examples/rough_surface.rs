//! Writes a synthetic rough surface as an ISO 25178-72 X3P file, to try
//! `kefric surface` on (or to start from when writing surfaces of your
//! own): an isotropic, Gaussian, self-affine height map (Hurst exponent
//! 0.8) of 256 × 256 points every 1 µm, σ = 0.5 µm, wavelengths from 8 µm
//! to 256 µm, made of random waves (a fixed seed: the same file every
//! time).
//!
//! `cargo run --release --features topography --example rough_surface -- /tmp/rough.x3p`
//!
//! (`... -- OUT.x3p N`: N × N points, the same waves; the web page's
//! timing test reads a 1024 × 1024 one.)
//!
//! then, for an aluminium pin on a nickel-coated disk, 10 N on 10 mm²:
//!
//! `kefric surface /tmp/rough.x3p --e1 70e9 --nu1 0.33 --e2 200e9 --nu2 0.31 --hardness 1e9 --delta-gamma 0.5 --epsilon 0.4e-9 --force 10 --area 1e-5`

#[path = "rough/mod.rs"]
mod rough;

use ke_friction::bound::Bound;
use ke_friction::topography::write_x3p;
use rough::N;

/// The points along x and y a map may have.
static SIZE: Bound = Bound::whole(2, 8192);

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let Some(path) = std::env::args_os().nth(1) else {
        return Err("usage: rough_surface OUT.x3p [N]".into());
    };
    let n = match std::env::args().nth(2) {
        None => N,
        Some(n) => match n.parse::<usize>() {
            Ok(n) if SIZE.contains(n as f64) => n,
            _ => return Err(format!("N = {n} is out of range: must be {}", SIZE.range()).into()),
        },
    };
    write_x3p(&rough::surface(n)?, path.as_ref(), 'D')?;
    println!("wrote {}", path.to_string_lossy());
    Ok(())
}
