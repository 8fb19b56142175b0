//! The equivalent surface of two rough surfaces.

use super::{finite, positive, StatsError, SurfaceStats, Warning, INTERVAL_TOLERANCE};

/// The equivalent surface of two independent rough surfaces pressed
/// together, against a flat (the composite of Greenwood & Tripp): the sum
/// of their heights, each measured from its own mean plane toward the
/// other surface.
///
/// Variances and slope and curvature moments add, and so do the third and
/// fourth cumulants:
///
/// - m0 = σ² = σa² + σb²; m20, m02, m40, m04, m2 and m4 add likewise;
/// - Sk·σ³ = Ska·σa³ + Skb·σb³;
/// - (K − 3)·σ⁴ = (Ka − 3)·σa⁴ + (Kb − 3)·σb⁴;
///
/// and α, η, R, β, σ_s, y_s follow from m0, m2, m4 as for one surface
/// (refused if α ≤ 0.8968). The result keeps the points, sizes and sampling
/// intervals of `a`: both surfaces should be sampled alike (same band),
/// and a warning is added if dx (or dy) differ by more than 1 %. Both must
/// be profiles or both maps.
pub fn combine(a: &SurfaceStats, b: &SurfaceStats) -> Result<SurfaceStats, StatsError> {
    let add = |x: Option<f64>, y: Option<f64>| -> Result<Option<f64>, StatsError> {
        match (x, y) {
            (Some(x), Some(y)) => Ok(Some(x + y)),
            (None, None) => Ok(None),
            _ => Err(StatsError::Mismatch),
        }
    };
    let dy = add(a.dy, b.dy).map(|_| a.dy)?;
    let m02 = add(a.m02, b.m02)?;
    let m04 = add(a.m04, b.m04)?;
    let (va, vb) = (a.sigma * a.sigma, b.sigma * b.sigma);
    let m0 = va + vb;
    positive("m0", m0)?;
    let sigma = m0.sqrt();
    let skewness = (a.skewness * va * a.sigma + b.skewness * vb * b.sigma) / (m0 * sigma);
    let kurtosis = 3.0 + ((a.kurtosis - 3.0) * va * va + (b.kurtosis - 3.0) * vb * vb) / (m0 * m0);
    finite("skewness", skewness)?;
    positive("kurtosis", kurtosis)?;
    let mut stats = SurfaceStats::from_moments(
        (a.points, a.missing, a.nx, a.ny, a.dx, dy),
        [m0, skewness, kurtosis],
        (a.m20 + b.m20, m02, a.m40 + b.m40, m04),
    )?;
    (stats.lambda_s, stats.lambda_c) = (a.lambda_s, a.lambda_c);
    for (name, first, second) in [("dx", Some(a.dx), Some(b.dx)), ("dy", a.dy, b.dy)] {
        if let (Some(first), Some(second)) = (first, second) {
            if (first - second).abs() > INTERVAL_TOLERANCE * first.abs().max(second.abs()) {
                stats.warnings.push(Warning::IntervalMismatch { name, first, second });
            }
        }
    }
    Ok(stats)
}
