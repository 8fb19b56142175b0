//! The README's synthetic rough surface (`examples/rough_surface.rs`
//! writes it as X3P; the library's tests read it too): an isotropic,
//! Gaussian, self-affine height map (Hurst exponent 0.8) every 1 µm,
//! σ = 0.5 µm, wavelengths from 8 µm to 256 µm, made of random waves (a
//! fixed seed: the same map every time).

use ke_friction::topography::Topography;
use std::f64::consts::PI;

/// Points along x and y of the README's map.
pub const N: usize = 256;
/// Sampling interval, m.
pub const DX: f64 = 1e-6;
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

/// The map of `n` × `n` points (the same waves at every `n`).
pub fn surface(n: usize) -> Result<Topography, ke_friction::topography::TopographyError> {
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
    Topography::map(z, n, n, DX, DX)
}
