//! A fixed workload for instruction counts of direct integration with
//! non-Gaussian heights: 40 loads F* from 1e-4 up (13 per decade) at
//! ψ = 1, θ = 0.001, for the Gaussian (no argument), Pearson type VII
//! (`vii`: Sk = 0, K = 8), type IV (`iv`: Sk = 0.3, K = 3.2), the gamma
//! line (`iii`: Sk = −0.5, K = 3.375), Weibull (`weibull`: Sk = 0), or
//! the Pearson density of two numbers `SK K`.
//!
//! `cargo build --release --example profile_distributions`, then
//! `valgrind --tool=callgrind target/release/examples/profile_distributions vii`
//! (docs/PERFORMANCE.md has the figures).

use ke_friction::{Constants, HeightDistribution, Model};
fn main() {
    let which = std::env::args().nth(1).unwrap_or_default();
    let d = match which.as_str() {
        "vii" => HeightDistribution::pearson(0.0, 8.0).unwrap(),
        "iv" => HeightDistribution::pearson(0.3, 3.2).unwrap(),
        "iii" => HeightDistribution::pearson(-0.5, 3.375).unwrap(),
        "weibull" => HeightDistribution::weibull(0.0).unwrap(),
        "" => HeightDistribution::GAUSSIAN,
        sk => {
            let k = std::env::args().nth(2).expect("SK K").parse().unwrap();
            HeightDistribution::pearson(sk.parse().unwrap(), k).unwrap()
        }
    };
    let m = Model::new(Constants::default().distribution(d).at(1.0, 0.001).unwrap()).unwrap();
    let mut s = 0.0;
    for k in 0..40 {
        let f = 1e-4 * 10f64.powf(k as f64 / 13.0);
        s += m.at_f_star(f).unwrap().mu.unwrap();
    }
    println!("{s}");
}
