//! `ln` and `exp` for the portable lookup kernel: branch-free, inlinable,
//! plain multiplies and adds (the same result on every machine) and
//! accurate to about 1e-14 — far below the tables' 1e-4…1e-7
//! interpolation error. The C library's versions are out-of-line calls
//! that cost a third of a lookup.

/// ln 2 split into a head with trailing zero bits and a tail (fdlibm's).
pub const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
/// The tail of ln 2.
pub const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);
/// Subtracted from the bits of x so that the mantissa lands in [√½, √2).
pub const LN_OFFSET: u64 = 0x3fe6_a09e_667f_3bcd;
/// 2·atanh(s) = 2s(1 + z/3 + z²/5 + …), z = s² ≤ 0.0295: the coefficients
/// of z·(…), from z^6 down; the first omitted term, 2|s|z^8/17, is below 2e-14.
pub const LN_SERIES: [f64; 7] = [
    1.0 / 15.0,
    1.0 / 13.0,
    1.0 / 11.0,
    1.0 / 9.0,
    1.0 / 7.0,
    1.0 / 5.0,
    1.0 / 3.0,
];
/// Adding and removing 1.5·2^52 rounds to the nearest integer without a
/// call to a software `round` (no SSE4.1 on baseline x86-64).
pub const EXP_SHIFT: f64 = 6_755_399_441_055_744.0;
/// e^r = Σ r^k/k! for |r| ≤ ½ln 2, from r^11 down; the first omitted term,
/// r^12/12!, is below 1e-14.
pub const EXP_SERIES: [f64; 12] = [
    1.0 / 39_916_800.0,
    1.0 / 3_628_800.0,
    1.0 / 362_880.0,
    1.0 / 40_320.0,
    1.0 / 5_040.0,
    1.0 / 720.0,
    1.0 / 120.0,
    1.0 / 24.0,
    1.0 / 6.0,
    0.5,
    1.0,
    1.0,
];

/// Σ LN_SERIES[6−k]·z^k by Estrin's scheme (short dependency chains).
#[inline(always)]
fn ln_poly(z: f64) -> f64 {
    let c = |i: usize| LN_SERIES[6 - i];
    let z2 = z * z;
    let p01 = c(1) * z + c(0);
    let p23 = c(3) * z + c(2);
    let p45 = c(5) * z + c(4);
    let p0123 = p23 * z2 + p01;
    let p456 = c(6) * z2 + p45;
    p456 * (z2 * z2) + p0123
}

/// Σ EXP_SERIES[11−k]·r^k by Estrin's scheme.
#[inline(always)]
fn exp_poly(r: f64) -> f64 {
    let c = |i: usize| EXP_SERIES[11 - i];
    let r2 = r * r;
    let r4 = r2 * r2;
    let q0 = c(1) * r + c(0);
    let q1 = c(3) * r + c(2);
    let q2 = c(5) * r + c(4);
    let q3 = c(7) * r + c(6);
    let q4 = c(9) * r + c(8);
    let q5 = c(11) * r + c(10);
    let s0 = q1 * r2 + q0;
    let s1 = q3 * r2 + q2;
    let s2 = q5 * r2 + q4;
    let t0 = s1 * r4 + s0;
    s2 * (r4 * r4) + t0
}

/// Natural logarithm of a positive, finite, normal `x`.
#[inline(always)]
pub fn ln(x: f64) -> f64 {
    // x = 2^e · m with m in [√½, √2): ln x = e·ln 2 + 2·atanh(s), s = (m−1)/(m+1).
    let bits = x.to_bits();
    let tmp = bits.wrapping_sub(LN_OFFSET);
    let e = (tmp as i64 >> 52) as f64;
    let m = f64::from_bits(bits.wrapping_sub(tmp & 0xfff0_0000_0000_0000));
    let s = (m - 1.0) / (m + 1.0);
    let z = s * s;
    let p = ln_poly(z) * z;
    let two_s = s + s;
    e * LN2_HI + (two_s + (two_s * p + e * LN2_LO))
}

/// e^x for |x| < 700.
#[inline(always)]
pub fn exp(x: f64) -> f64 {
    // x = k·ln 2 + r, |r| ≤ ½ln 2.
    let shifted = x * core::f64::consts::LOG2_E + EXP_SHIFT;
    let k = shifted - EXP_SHIFT;
    // k, an integer, sits in the low mantissa bits of `shifted`.
    let k_int = shifted.to_bits().wrapping_sub(EXP_SHIFT.to_bits());
    let r = -k * LN2_LO + (-k * LN2_HI + x);
    exp_poly(r) * f64::from_bits(k_int.wrapping_add(1023) << 52)
}

#[cfg(test)]
mod tests {
    #[test]
    fn ln_and_exp_agree_with_std_to_1e_13() {
        let mut x = 1e-300f64;
        while x < 1e300 {
            for y in [x, x * 1.234_567, x * 1.42, x * 0.71] {
                let (a, b) = (super::ln(y), y.ln());
                assert!((a - b).abs() <= 1e-13 * b.abs().max(1.0), "ln({y}) = {a} vs {b}");
            }
            x *= 3.7;
        }
        let mut x = -700.0;
        while x < 700.0 {
            let (a, b) = (super::exp(x), x.exp());
            assert!(((a - b) / b).abs() <= 1e-13, "exp({x}) = {a} vs {b}");
            x += 0.0137;
        }
    }
}
