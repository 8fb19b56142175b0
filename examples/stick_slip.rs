//! A block on a rough surface under a vibrating normal load and a slowly
//! growing tangential load: when does it start to slide?
//!
//! The inner loop asks the table for μ(ψ, θ, F*) every time step (a few
//! nanoseconds each), as a contact-mechanics simulator would; the moment of
//! slip is then confirmed by direct integration.
//!
//! ```sh
//! cargo run --release --example stick_slip
//! ```
use ke_friction::{Model, Params, Table};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let table = Table::embedded();
    // An aluminium-like contact: ψ = 0.8, moderate adhesion θ = 0.002.
    let (psi, theta) = (0.8, 0.002);
    // Normal load (dimensionless, F* = F/(A_n·H)) with a 30 % vibration.
    let normal = |t: f64| 0.004 * (1.0 + 0.3 * (2.0 * std::f64::consts::PI * 50.0 * t).sin());
    // Tangential load ramps up at 0.001 (in units of A_n·H) per second.
    let tangential = |t: f64| 0.001 * t;
    let dt = 1e-5;
    let mut t = 0.0;
    let mut steps = 0u64;
    let started = std::time::Instant::now();
    let (slip_t, f, q, mu) = loop {
        let f = normal(t);
        let mu = table.mu(psi, theta, f)?;
        let q = tangential(t);
        if q > mu * f {
            break (t, f, q, mu);
        }
        t += dt;
        steps += 1;
        if t > 100.0 {
            return Err("no slip within 100 s".into());
        }
    };
    let per_step = started.elapsed().as_secs_f64() / steps.max(1) as f64;
    println!("static friction overcome at t = {slip_t:.5} s after {steps} time steps");
    println!("  normal load F* = {f:.6e}, tangential load Q* = {q:.6e}");
    println!("  table:  mu = {mu:.8}  (Q*/F* = {:.8})", q / f);
    let exact = Model::new(Params::new(psi, theta))?.at_f_star(f)?;
    let mu_exact = exact.mu.ok_or("mu undefined")?;
    println!(
        "  direct: mu = {mu_exact:.8} at h* = {:.6} (relative difference {:.1e})",
        exact.h_star,
        (mu - mu_exact).abs() / mu_exact
    );
    println!("  {:.1} ns per time step (lookup included)", per_step * 1e9);
    // The same question for 10,000 independent contacts at once (batch lookup).
    let n = 10_000;
    let psis: Vec<f64> = (0..n).map(|i| 0.5 + 7.5 * (i as f64 / n as f64)).collect();
    let thetas: Vec<f64> = (0..n).map(|i| 0.01 * ((i * 7919) % n) as f64 / n as f64).collect();
    let loads: Vec<f64> = (0..n)
        .map(|i| 1e-4 * (1.0 + ((i * 104_729) % n) as f64 / n as f64))
        .collect();
    let mut mus = vec![0.0; n];
    table.mu_batch(&psis, &thetas, &loads, &mut mus)?;
    let q_applied = 2e-5;
    let slipped = mus.iter().zip(&loads).filter(|(mu, f)| q_applied > *mu * *f).count();
    println!("{slipped} of {n} contacts slip under Q* = {q_applied:e} (the rest stick)");
    Ok(())
}
