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

use ke_friction::topography::{write_x3p, Topography};
use std::f64::consts::PI;

/// Points along x and y, unless given.
const N: usize = 256;
/// Sampling interval, m.
const DX: f64 = 1e-6;
/// Waves summed.
const WAVES: usize = 600;

/// A uniform number in [0, 1) from a counter (splitmix64).
fn uniform(k: u64) -> f64 {
    let mut z = k
        .wrapping_add(0x9E37_79B9_7F4A_7C15)
        .wrapping_mul(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    ((z ^ (z >> 31)) >> 11) as f64 * 2f64.powi(-53)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let Some(path) = std::env::args_os().nth(1) else {
        return Err("usage: rough_surface OUT.x3p [N]".into());
    };
    let n = match std::env::args().nth(2) {
        None => N,
        Some(n) => match n.parse::<usize>() {
            Ok(n) if (2..=8192).contains(&n) => n,
            _ => return Err(format!("N = {n} is out of range: must be a whole number from 2 to 8192").into()),
        },
    };
    // Wavenumbers from 2π/256 µm to 2π/8 µm, uniform in log k, random
    // directions and phases; the amplitude of a self-affine surface,
    // A(k) ∝ k^−(1+H), times the k of the log spacing (two dimensions).
    let hurst = 0.8;
    let (k_lo, k_hi) = (2.0 * PI / (256.0 * DX), 2.0 * PI / (8.0 * DX));
    let waves: Vec<(f64, f64, f64, f64)> = (0..WAVES as u64)
        .map(|w| {
            let k = k_lo * (k_hi / k_lo).powf(uniform(3 * w));
            let angle = 2.0 * PI * uniform(3 * w + 1);
            let phase = 2.0 * PI * uniform(3 * w + 2);
            (k * angle.cos(), k * angle.sin(), phase, k.powf(-hurst))
        })
        .collect();
    let mut z: Vec<f64> = (0..n * n)
        .map(|p| {
            let (x, y) = ((p % n) as f64 * DX, (p / n) as f64 * DX);
            waves
                .iter()
                .map(|&(kx, ky, phase, a)| a * (kx * x + ky * y + phase).cos())
                .sum()
        })
        .collect();
    // Scale to σ = 0.5 µm about the mean.
    let mean = z.iter().sum::<f64>() / z.len() as f64;
    let sd = (z.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / z.len() as f64).sqrt();
    z.iter_mut().for_each(|v| *v = (*v - mean) / sd * 0.5e-6);
    write_x3p(&Topography::map(z, n, n, DX, DX)?, path.as_ref(), 'D')?;
    println!("wrote {}", path.to_string_lossy());
    Ok(())
}
