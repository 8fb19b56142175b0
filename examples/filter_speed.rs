//! Times the ISO 16610 Gaussian filters on a 4096 × 4096 map (one core):
//! the S-filter at λs = 25·dx followed by the surface statistics, and the
//! L-filter at λc = scan/5; each also with the convolution forced direct
//! and FFT (`Convolution::Auto` picks by an estimate of their costs).
//!
//! `cargo run --release --features topography --example filter_speed [N]`

use ke_friction::topography::{gaussian_lowpass_using, l_filter, s_filter, Convolution, StatsOptions, Topography};
use std::time::Instant;

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .map_or(4096, |a| a.parse().expect("N: points along x and y"));
    let (dx, dy) = (1e-7, 1.2e-7);
    // A deterministic rough-looking surface (sums of incommensurate waves
    // plus a hash noise), 1 mm offset.
    let heights: Vec<f64> = (0..n * n)
        .map(|k| {
            let (i, j) = ((k % n) as f64, (k / n) as f64);
            let h = (k as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 11;
            1e-3 + 1e-7 * ((0.021 * i + 0.013 * j).sin() + 0.6 * (0.0047 * i - 0.009 * j).cos())
                + 3e-8 * (h as f64 * 2f64.powi(-53) - 0.5)
        })
        .collect();
    let t = Topography::map(heights, n, n, dx, dy).expect("a valid map");
    let scan = (n as f64 * dx).min(n as f64 * dy);
    let time = |label: &str, f: &dyn Fn() -> Topography| {
        let (start, cpu) = (Instant::now(), cpu_seconds());
        let out = f();
        let s = start.elapsed().as_secs_f64();
        println!(
            "{label:<40} {s:6.3} s wall {}  (z[0] = {:.6e})",
            cpu_since(cpu),
            out.heights()[0]
        );
        out
    };
    let lambda_s = 25.0 * dx;
    let (start, cpu) = (Instant::now(), cpu_seconds());
    let s = time("S-filter, lambda = 25 dx (auto)", &|| s_filter(&t, lambda_s).unwrap());
    let st = s.stats(&StatsOptions::default()).expect("statistics");
    println!(
        "{:<40} {:6.3} s wall {}  (sigma = {:.4e} m)",
        "S-filter + stats",
        start.elapsed().as_secs_f64(),
        cpu_since(cpu),
        st.sigma
    );
    for (label, m) in [("direct", Convolution::Direct), ("FFT", Convolution::Fft)] {
        time(&format!("S-filter, lambda = 25 dx ({label})"), &|| {
            gaussian_lowpass_using(&t, lambda_s, m).unwrap()
        });
    }
    let lambda_c = scan / 5.0;
    time("L-filter, lambda = scan/5 (auto)", &|| l_filter(&t, lambda_c).unwrap());
    for (label, m) in [("FFT", Convolution::Fft), ("direct", Convolution::Direct)] {
        time(&format!("low-pass, lambda = scan/5 ({label})"), &|| {
            gaussian_lowpass_using(&t, lambda_c, m).unwrap()
        });
    }
}

/// This thread's CPU time (Linux: /proc/thread-self/schedstat), which a
/// busy machine does not inflate as it does the wall time.
fn cpu_seconds() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    Some(text.split_whitespace().next()?.parse::<f64>().ok()? * 1e-9)
}

fn cpu_since(start: Option<f64>) -> String {
    match (start, cpu_seconds()) {
        (Some(a), Some(b)) => format!("{:6.3} s cpu", b - a),
        _ => "     - s cpu".to_string(),
    }
}
