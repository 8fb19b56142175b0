//! Fixed-order Gauss rules: Gauss–Legendre and Gauss–Jacobi with weight `t^b` on `[0, 1]`.
//!
//! The rules come from the Golub–Welsch algorithm (the eigen-decomposition of
//! the Jacobi matrix of the orthogonal polynomials), computed once when a
//! [`Model`](crate::Model) is built. Every surface integral of MODEL.md §4 is
//! split into panels on which the integrand is analytic; an `n`-point rule
//! then converges geometrically. Where a panel starts at an asperity's
//! contact point (`x = 0`), the factor `x^b` with non-integer `b` is not
//! analytic, and the Gauss–Jacobi rule with that very weight integrates it
//! exactly (MODEL.md §5).

/// Number of nodes of every rule used by the surface integrals.
///
/// Panels are sized so that the Gaussian changes by at most about `e^9` across
/// one of them; 12 nodes then reach ~1e-16 relative (tested against an
/// adaptive high-precision quadrature in `tests/`).
pub(crate) const NODES: usize = 12;

/// An `NODES`-point rule on `[0, 1]`: `∫₀¹ t^b f(t) dt ≈ Σ wᵢ f(tᵢ)`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Rule {
    /// Nodes in `(0, 1)`, ascending.
    pub t: [f64; NODES],
    /// Weights, already including `t^b`.
    pub w: [f64; NODES],
}

impl Rule {
    /// The Gauss–Legendre rule, computed once per process.
    pub fn shared_legendre() -> &'static Rule {
        static RULE: std::sync::OnceLock<Rule> = std::sync::OnceLock::new();
        RULE.get_or_init(Rule::legendre)
    }

    /// Gauss–Legendre on `[0, 1]` (weight 1).
    pub fn legendre() -> Rule {
        Rule::jacobi(0.0)
    }

    /// Gauss–Jacobi on `[0, 1]` with weight `t^b`, `b > -1`.
    pub fn jacobi(b: f64) -> Rule {
        // Monic Jacobi recurrence on [-1, 1] for the weight (1 + x)^b
        // (α = 0, β = b in the usual notation), then mapped to t = (1 + x)/2.
        let mut diag = [0.0; NODES];
        let mut off = [0.0; NODES];
        for (k, dk) in diag.iter_mut().enumerate() {
            let kf = k as f64;
            let s = 2.0 * kf + b;
            *dk = if k == 0 { b / (b + 2.0) } else { b * b / (s * (s + 2.0)) };
        }
        for (k, ok) in off.iter_mut().enumerate().take(NODES - 1) {
            let kf = (k + 1) as f64;
            let s = 2.0 * kf + b;
            let beta = 4.0 * kf * kf * (kf + b) * (kf + b) / (s * s * (s + 1.0) * (s - 1.0));
            *ok = beta.sqrt();
        }
        let mut first = [0.0; NODES];
        first[0] = 1.0;
        symmetric_tridiagonal_eigen(&mut diag, &mut off, &mut first);
        let mut idx: [usize; NODES] = core::array::from_fn(|i| i);
        idx.sort_by(|&i, &j| diag[i].total_cmp(&diag[j]));
        let mu0 = 1.0 / (b + 1.0);
        Rule {
            t: idx.map(|i| 0.5 * (1.0 + diag[i])),
            w: idx.map(|i| mu0 * first[i] * first[i]),
        }
    }
}

/// Eigenvalues of a symmetric tridiagonal matrix by the implicit QL method,
/// tracking only the first row of the eigenvector matrix (all that
/// Golub–Welsch needs for the weights).
///
/// `diag` is replaced by the eigenvalues, `off[i]` is the element (i, i+1)
/// (the last entry is ignored), `first` must hold the first row of the
/// identity on entry and holds the first components of the normalised
/// eigenvectors on exit.
fn symmetric_tridiagonal_eigen(diag: &mut [f64], off: &mut [f64], first: &mut [f64]) {
    let n = diag.len();
    off[n - 1] = 0.0;
    for l in 0..n {
        for _ in 0..64 {
            let mut m = l;
            while m + 1 < n {
                let dd = diag[m].abs() + diag[m + 1].abs();
                if off[m].abs() <= f64::EPSILON * dd {
                    break;
                }
                m += 1;
            }
            if m == l {
                break;
            }
            let mut g = (diag[l + 1] - diag[l]) / (2.0 * off[l]);
            let mut r = g.hypot(1.0);
            g = diag[m] - diag[l] + off[l] / (g + r.copysign(g));
            let (mut s, mut c, mut p) = (1.0, 1.0, 0.0);
            let mut i = m;
            let mut deflated = false;
            while i > l {
                i -= 1;
                let f = s * off[i];
                let b = c * off[i];
                r = f.hypot(g);
                off[i + 1] = r;
                if r == 0.0 {
                    diag[i + 1] -= p;
                    off[m] = 0.0;
                    deflated = true;
                    break;
                }
                s = f / r;
                c = g / r;
                g = diag[i + 1] - p;
                r = (diag[i] - g) * s + 2.0 * c * b;
                p = s * r;
                diag[i + 1] = g + p;
                g = c * r - b;
                let fz = first[i + 1];
                first[i + 1] = s * first[i] + c * fz;
                first[i] = c * first[i] - s * fz;
            }
            if deflated {
                continue;
            }
            diag[l] -= p;
            off[l] = g;
            off[m] = 0.0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A Gauss rule with `n` nodes integrates `t^b · t^k` exactly for `k < 2n`.
    #[test]
    fn jacobi_rules_integrate_polynomials_exactly() {
        for b in [-0.702, -0.5, 0.0, 0.093, 0.298, 0.5, 0.982, 1.5, 2.7, 7.3, 25.0, 63.9] {
            let rule = Rule::jacobi(b);
            for k in 0..2 * NODES as i32 {
                let q: f64 = rule.t.iter().zip(&rule.w).map(|(t, w)| w * t.powi(k)).sum();
                let exact = 1.0 / (b + k as f64 + 1.0);
                assert!(((q - exact) / exact).abs() < 1e-13, "b = {b}, k = {k}: {q} vs {exact}");
            }
        }
    }

    #[test]
    fn legendre_nodes_are_symmetric_and_inside() {
        let rule = Rule::legendre();
        for i in 0..NODES {
            assert!(rule.t[i] > 0.0 && rule.t[i] < 1.0);
            assert!((rule.t[i] + rule.t[NODES - 1 - i] - 1.0).abs() < 1e-15);
            assert!((rule.w[i] - rule.w[NODES - 1 - i]).abs() < 1e-15);
        }
    }
}
