//! Structure-aware: an `arbitrary` table spec (axes' origin, step, length,
//! domain, precision, coefficients including extremes) encoded by the
//! independent encoder `tests/forge.rs` with a valid checksum, loaded, and
//! if it loads, queried at in-domain and edge points across all kernels.
//! Raw bytes almost never get past the checksum and the decoder; this
//! target reaches the loader's value checks and the kernels every run.
#![no_main]

#[path = "check.rs"]
mod check;
#[path = "../../tests/forge.rs"]
mod forge;

use arbitrary::Arbitrary;
use ke_friction::Table;
use libfuzzer_sys::fuzz_target;

/// A value as the fuzzer picks it: often ordinary, sometimes extreme.
#[derive(Debug, Clone, Copy, Arbitrary)]
enum Value {
    /// In [-8, 8] (ordinary ln μ and h*).
    Small(i16),
    /// Near the loader's bounds.
    Edge(u8),
    /// Any bits (NaN, infinities, subnormals, huge).
    Raw(f64),
}

impl Value {
    fn get(self) -> f64 {
        match self {
            Value::Small(k) => k as f64 / 4096.0,
            Value::Edge(k) => {
                const EDGES: [f64; 12] = [
                    86.0, -86.0, 86.01, 87.0, 700.0, -700.0, 700.5, 3e38, -1000.0, 1e-300, 64.7, 1e6,
                ];
                EDGES[k as usize % EDGES.len()]
            }
            Value::Raw(v) => v,
        }
    }
}

/// An axis: usually a sane one over a domain inside its nodes; sometimes
/// with a raw origin, step or domain.
#[derive(Debug, Clone, Copy, Arbitrary)]
struct AxisSpec {
    nodes: u8,
    lo: u16,
    width: u16,
    step_exponent: i8,
    raw_first: Option<f64>,
    raw_step: Option<f64>,
    raw_domain: Option<(f64, f64)>,
    /// Domain ends inside the outermost cells, in 1/256ths of a step.
    inset: (u8, u8),
}

impl AxisSpec {
    fn axis(&self, k: usize) -> forge::Axis {
        let scale = if k == 1 { forge::SQRT } else { forge::LOG };
        let nodes = 5 + (self.nodes % 28) as u32;
        // A step of 2^(e/8): from very fine to very coarse.
        let step = self.raw_step.unwrap_or(2f64.powf(self.step_exponent as f64 / 8.0));
        let first = self.raw_first.unwrap_or(if k == 1 {
            -step
        } else {
            (self.lo as f64 / 4096.0 - 8.0) - step
        });
        // The domain spans nodes 1 … nodes − 2 less the insets, or less.
        let span = (nodes - 3) as f64 * step;
        let c_lo = first + step * (1.0 + self.inset.0 as f64 / 256.0);
        let c_hi = (c_lo + span * (0.01 + self.width as f64 / 65535.0)).min(first + step * (nodes - 2) as f64);
        let inverse = |c: f64| if k == 1 { c.max(0.0).powi(2) } else { c.exp() };
        let (lo, hi) = self.raw_domain.unwrap_or((inverse(c_lo), inverse(c_hi)));
        forge::Axis {
            scale,
            first,
            step,
            nodes,
            lo,
            hi,
        }
    }
}

#[derive(Debug, Arbitrary)]
struct Input {
    f32: bool,
    axes: [AxisSpec; 3],
    /// Coefficient palettes, cycled through the arrays.
    ln_mu: Vec<Value>,
    h_star: Vec<Value>,
    /// A stride through the palette (varies neighbours).
    stride: u8,
    generator: String,
    /// Query points, as fractions of each range.
    queries: Vec<[u16; 3]>,
}

fuzz_target!(|input: Input| {
    let mut spec = forge::Spec::uniform(0.0, input.f32);
    spec.axes = [input.axes[0].axis(0), input.axes[1].axis(1), input.axes[2].axis(2)];
    let n = spec.coefficients();
    let fill = |palette: &[Value], default: f64| -> Vec<f64> {
        let stride = 1 + input.stride as usize;
        (0..n)
            .map(|i| {
                palette
                    .get((i * stride) % palette.len().max(1))
                    .map_or(default, |v| v.get())
            })
            .collect()
    };
    spec.ln_mu = fill(&input.ln_mu, -0.5);
    spec.h_star = fill(&input.h_star, 1.0);
    spec.generator = input.generator.chars().take(64).collect();
    let Ok(t) = Table::from_bytes(&spec.encode()) else {
        return;
    };
    let max_coef = spec.ln_mu.iter().fold(0.0f64, |m, c| m.max(spec.stored(*c).abs()));
    let fractions: Vec<[f64; 3]> = input
        .queries
        .iter()
        .take(64)
        .map(|q| q.map(|v| v as f64 / 65535.0))
        .chain([[0.5; 3], [1e-9, 0.999_999_9, 0.25]])
        .collect();
    check::check(&t, &check::queries(&t, &fractions), max_coef);
    // The generator comes back escaped: no control characters.
    assert!(!t.info().build.generator.chars().any(char::is_control));
});
