//! Tensor-product cubic B-splines on uniform grids: the interpolant behind
//! every table lookup.
//!
//! Cubic B-spline interpolation is C² and fourth-order accurate when its end
//! conditions are: each line is a clamped spline whose end slopes come from
//! fifth-order one-sided differences of the data (or are exactly zero, for
//! an axis on which the function is even about its first node). Fitting
//! happens once, in the builder; a lookup only blends 4×4×4 coefficients.

/// How a physical input maps to the uniform coordinate of an axis. Table
/// files store it by [`Scale::code`], an explicit number, so reordering
/// the variants cannot change the format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// Coordinate = ln(value); value > 0.
    Log,
    /// Coordinate = √value; value ≥ 0. The function must be smooth in the
    /// value itself, so it is even in the coordinate about 0 (slope 0 there).
    Sqrt,
}

impl Scale {
    /// The scale's code in table files (format version 1).
    pub const fn code(self) -> u8 {
        match self {
            Scale::Log => 0,
            Scale::Sqrt => 1,
        }
    }

    /// The scale with this code, if any.
    pub const fn from_code(code: u8) -> Option<Scale> {
        match code {
            0 => Some(Scale::Log),
            1 => Some(Scale::Sqrt),
            _ => None,
        }
    }

    /// The coordinate of `value`.
    #[inline(always)]
    pub fn forward(self, value: f64) -> f64 {
        match self {
            Scale::Log => value.ln(),
            Scale::Sqrt => value.sqrt(),
        }
    }

    /// The value at coordinate `c`.
    pub fn inverse(self, c: f64) -> f64 {
        match self {
            Scale::Log => c.exp(),
            Scale::Sqrt => c * c,
        }
    }
}

/// One axis: `nodes` points uniform in the coordinate, from `first` with
/// spacing `step`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axis {
    /// The coordinate map.
    pub scale: Scale,
    /// Coordinate of node 0.
    pub first: f64,
    /// Coordinate spacing, > 0.
    pub step: f64,
    /// Number of nodes, ≥ 5.
    pub nodes: usize,
}

impl Axis {
    /// Coordinate of node `k`.
    pub fn coord(&self, k: usize) -> f64 {
        self.first + self.step * k as f64
    }

    /// Physical value of node `k`.
    pub fn value(&self, k: usize) -> f64 {
        self.scale.inverse(self.coord(k))
    }
}

/// The uniform cubic B-spline basis as polynomials in the cell offset f:
/// weight j is `((A[j]·f + B[j])·f + C[j])·f + D[j]` with
/// `[A, B, C, D] = BASIS`. The portable and the AVX2 lookups both evaluate
/// it from here, by Horner's rule.
pub const BASIS: [[f64; 4]; 4] = [
    [-1.0 / 6.0, 0.5, -0.5, 1.0 / 6.0],
    [0.5, -1.0, 0.5, 0.0],
    [-0.5, 0.0, 0.5, 0.0],
    [1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0, 0.0],
];

/// Cubic B-spline basis weights at offset `f ∈ [0, 1]`.
#[inline(always)]
pub fn weights(f: f64) -> [f64; 4] {
    let [a, b, c, d] = BASIS;
    core::array::from_fn(|j| ((a[j] * f + b[j]) * f + c[j]) * f + d[j])
}

/// Derivatives of [`weights`] with respect to `f`: `(3A·f + 2B)·f + C`.
#[inline(always)]
pub fn weight_slopes(f: f64) -> [f64; 4] {
    let [a, b, c, _] = BASIS;
    core::array::from_fn(|j| ((3.0 * a[j]) * f + (b[j] + b[j])) * f + c[j])
}

/// End condition of one axis for [`fit_line`].
#[cfg(feature = "builder")]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Start {
    /// Estimate the slope at node 0 from the data.
    Estimated,
    /// The slope at node 0 is zero (the function is even there).
    Even,
}

/// Spline coefficients (`y.len() + 2` of them) interpolating `y` at the
/// nodes of a uniform axis, clamped to slopes estimated to fifth order (or
/// zero at the start, for [`Start::Even`]).
#[cfg(feature = "builder")]
pub fn fit_line(y: &[f64], start: Start, out: &mut [f64]) {
    let n = y.len();
    debug_assert!(n >= 5 && out.len() == n + 2);
    let d0 = match start {
        Start::Even => 0.0,
        Start::Estimated => (-25.0 * y[0] + 48.0 * y[1] - 36.0 * y[2] + 16.0 * y[3] - 3.0 * y[4]) / 12.0,
    };
    let d1 = (25.0 * y[n - 1] - 48.0 * y[n - 2] + 36.0 * y[n - 3] - 16.0 * y[n - 4] + 3.0 * y[n - 5]) / 12.0;
    // Rows: c[i-1] + 4c[i] + c[i+1] = 6y[i]; with c[-1] = c[1] − 2d0 and
    // c[n] = c[n-2] + 2d1 eliminated, a tridiagonal system for c[0..n).
    let c = &mut out[1..=n];
    let mut sup = vec![0.0; n];
    let mut rhs: Vec<f64> = y.iter().map(|v| 6.0 * v).collect();
    rhs[0] += 2.0 * d0;
    rhs[n - 1] -= 2.0 * d1;
    let (mut b, mut u) = (4.0, 2.0); // first row: 4c0 + 2c1
    sup[0] = u / b;
    rhs[0] /= b;
    for i in 1..n {
        let a = if i == n - 1 { 2.0 } else { 1.0 };
        u = 1.0;
        b = 4.0 - a * sup[i - 1];
        sup[i] = u / b;
        rhs[i] = (rhs[i] - a * rhs[i - 1]) / b;
    }
    c[n - 1] = rhs[n - 1];
    for i in (0..n - 1).rev() {
        c[i] = rhs[i] - sup[i] * c[i + 1];
    }
    out[0] = out[2] - 2.0 * d0;
    out[n + 1] = out[n - 1] + 2.0 * d1;
}

/// Fits a 3-D tensor spline to node values `y` of shape `dims` (last index
/// fastest); returns coefficients of shape `dims + 2` (last index fastest).
#[cfg(feature = "builder")]
pub fn fit_3d(y: &[f64], dims: [usize; 3], starts: [Start; 3]) -> Vec<f64> {
    debug_assert_eq!(y.len(), dims.iter().product::<usize>());
    // The tensor spline is separable: fit every line along axis 2, then
    // every line of those coefficients along axis 1, then along axis 0.
    let (mut data, mut dims) = (y.to_vec(), dims);
    for axis in (0..3).rev() {
        (data, dims) = fit_axis(&data, dims, axis, starts[axis]);
    }
    data
}

/// Fits every line of `data` (shape `dims`, last index fastest) along
/// `axis`; returns the coefficients and their shape (`dims[axis] + 2`).
#[cfg(feature = "builder")]
fn fit_axis(data: &[f64], dims: [usize; 3], axis: usize, start: Start) -> (Vec<f64>, [usize; 3]) {
    let mut out_dims = dims;
    out_dims[axis] += 2;
    let stride = |d: [usize; 3]| d[axis + 1..].iter().product::<usize>();
    let (s_in, s_out) = (stride(dims), stride(out_dims));
    let outer: usize = dims[..axis].iter().product();
    let mut out = vec![0.0; out_dims.iter().product()];
    let mut line = vec![0.0; dims[axis]];
    let mut coef = vec![0.0; out_dims[axis]];
    for o in 0..outer {
        for inner in 0..s_in {
            let base_in = o * dims[axis] * s_in + inner;
            for (j, v) in line.iter_mut().enumerate() {
                *v = data[base_in + j * s_in];
            }
            fit_line(&line, start, &mut coef);
            let base_out = o * out_dims[axis] * s_out + inner;
            for (j, c) in coef.iter().enumerate() {
                out[base_out + j * s_out] = *c;
            }
        }
    }
    (out, out_dims)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn eval_line(c: &[f64], s: f64) -> f64 {
        let i = (s.floor() as usize).min(c.len() - 4);
        let w = weights(s - i as f64);
        (0..4).map(|k| w[k] * c[i + k]).sum()
    }

    #[test]
    fn a_line_spline_interpolates_its_nodes_and_reproduces_cubics() {
        let cubic = |x: f64| 1.0 - 2.0 * x + 0.3 * x * x - 0.05 * x * x * x;
        let y: Vec<f64> = (0..9).map(|k| cubic(k as f64)).collect();
        let mut c = vec![0.0; 11];
        fit_line(&y, Start::Estimated, &mut c);
        for s in [0.0, 0.3, 1.0, 2.5, 4.0, 7.9, 8.0] {
            assert!((eval_line(&c, s) - cubic(s)).abs() < 1e-12, "s = {s}");
        }
    }

    #[test]
    fn the_error_falls_like_the_fourth_power_of_the_spacing() {
        let f = |x: f64| (1.3 * x).sin() + x * x;
        let err = |n: usize| {
            let h = 2.0 / (n - 1) as f64;
            let y: Vec<f64> = (0..n).map(|k| f(k as f64 * h)).collect();
            let mut c = vec![0.0; n + 2];
            fit_line(&y, Start::Estimated, &mut c);
            (0..1000)
                .map(|m| {
                    let x = 2.0 * m as f64 / 999.0;
                    (eval_line(&c, x / h) - f(x)).abs()
                })
                .fold(0.0, f64::max)
        };
        let ratio = err(11) / err(21);
        assert!(ratio > 12.0, "halving the spacing gained only {ratio}");
    }

    #[test]
    fn scale_codes_round_trip_and_are_the_format_s() {
        for (scale, code) in [(Scale::Log, 0), (Scale::Sqrt, 1)] {
            assert_eq!(scale.code(), code);
            assert_eq!(Scale::from_code(code), Some(scale));
        }
        assert_eq!(Scale::from_code(3), None);
    }

    #[test]
    fn weights_sum_to_one_and_slopes_to_zero() {
        for f in [0.0, 0.25, 0.5, 1.0] {
            assert!((weights(f).iter().sum::<f64>() - 1.0).abs() < 1e-15);
            assert!(weight_slopes(f).iter().sum::<f64>().abs() < 1e-15);
        }
    }
}
