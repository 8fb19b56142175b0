//! A wedged contact under a vibrating clamp load and a slowly growing
//! tangential load: when does it start to slide?
//!
//! The surfaces (aluminium on steel, given in SI units) are fixed for the
//! whole run, so the inner loop asks a [`Curve`] for μ(F*) — a few
//! nanoseconds per call — as a contact-mechanics simulator would. The
//! wedge makes the normal load grow with the tangential one, F* = F₀*(t) +
//! k·Q*, so the friction limit Q* = μ(F*)·F* is implicit: each step solves
//! it by Newton's method with the slope `mu_with_slope` gives. While the
//! clamp is being applied the load is below the curve's range: those steps
//! record an open contact and the simulation goes on. The moment of slip is then
//! confirmed by direct integration.
//!
//! ```sh
//! cargo run --release --example stick_slip
//! ```
use ke_friction::{Curve, LookupError, Model, Params, Physical};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // Aluminium (the softer material) on steel, in SI units.
    let (sigma, radius) = (100e-9, 300e-6);
    let surfaces = Physical {
        e1: 70e9,
        nu1: 0.33,
        e2: 210e9,
        nu2: 0.3,
        hardness: 1.0e9,
        sigma,
        radius,
        density: 0.04 / (radius * sigma),
        delta_gamma: 0.3,
        epsilon: 0.4e-9,
    };
    let params = Params::from_physical(&surfaces)?;
    let model = Model::new(params.clone())?;
    let started = std::time::Instant::now();
    let curve = Curve::from_model(&model, 1e-5, 0.1)?;
    println!(
        "surfaces: psi = {:.4}, theta = {:.4}, beta = {}, eps* = {}; curve over F* in [{:e}, {:e}] built in {:.1} ms, max relative error {:.1e}",
        params.psi,
        params.theta,
        params.constants.beta,
        params.constants.eps_star,
        curve.range().0,
        curve.range().1,
        started.elapsed().as_secs_f64() * 1e3,
        curve.max_error()
    );

    // Clamp load F₀* = F/(A_n·H): applied from zero over the first 10 ms
    // (so the contact starts open, below the curve's range), then held
    // with a 30 % vibration at 50 Hz. The wedge adds k·Q* to it.
    let settle = 0.01;
    let clamp = |t: f64| 0.004 * (t / settle).min(1.0) * (1.0 + 0.3 * (2.0 * std::f64::consts::PI * 50.0 * t).sin());
    let wedge = 0.5;
    // Once the clamp is on, the tangential load ramps up at 0.001 (in units
    // of A_n·H) per second.
    let tangential = |t: f64| 0.001 * (t - settle).max(0.0);
    let dt = 1e-5;
    let (mut t, mut steps, mut open_steps, mut newton_iterations) = (0.0, 0u64, 0u64, 0u64);
    let mut limit = 0.0; // the previous step's friction limit: Newton's start
    let started = std::time::Instant::now();
    let (slip_t, f_star, q_star, mu) = loop {
        t += dt;
        steps += 1;
        if t > 100.0 {
            return Err("no slip within 100 s".into());
        }
        // Solve Q = μ(F₀ + kQ)·(F₀ + kQ) for the friction limit Q.
        let f0 = clamp(t);
        let mut q = limit;
        let solved = loop {
            let f = f0 + wedge * q;
            let (mu, dmu) = match curve.mu_with_slope(f) {
                Ok(v) => v,
                // Unloaded below the curve's range (or pulled apart): the
                // contact is open this step, and carries no friction.
                Err(LookupError::OutOfDomain { value, lo, .. }) if value < lo => break None,
                Err(e) => return Err(e.into()),
            };
            let residual = q - mu * f;
            let step = residual / (1.0 - wedge * (dmu * f + mu));
            q -= step;
            newton_iterations += 1;
            if step.abs() <= 1e-14 * q.abs() {
                break Some((q, f, mu));
            }
        };
        let Some((q, f, mu)) = solved else {
            open_steps += 1;
            limit = 0.0;
            continue;
        };
        limit = q;
        if tangential(t) > q {
            break (t, f, q, mu);
        }
    };
    let per_step = started.elapsed().as_secs_f64() / steps as f64;
    println!(
        "static friction overcome at t = {slip_t:.5} s after {steps} time steps ({open_steps} with the contact open)"
    );
    println!("  normal load F* = {f_star:.6e}, friction limit Q* = {q_star:.6e}");
    println!(
        "  curve:  mu = {mu:.8} ({:.2} Newton iterations per closed step)",
        newton_iterations as f64 / (steps - open_steps) as f64
    );
    let exact = model.at_f_star(f_star)?;
    let mu_exact = exact.mu.ok_or("mu undefined")?;
    println!(
        "  direct: mu = {mu_exact:.8} at h* = {:.6} (relative difference {:.1e})",
        exact.h_star,
        (mu - mu_exact).abs() / mu_exact
    );
    println!(
        "  {:.1} ns per time step (Newton solve with its lookups included)",
        per_step * 1e9
    );

    // The same surfaces under 10,000 contacts' loads at once (batch lookup).
    let n = 10_000;
    let loads: Vec<f64> = (0..n)
        .map(|i| 1e-4 * (1.0 + ((i * 104_729) % n) as f64 / n as f64))
        .collect();
    let mut mus = vec![0.0; n];
    curve.mu_batch(&loads, &mut mus)?;
    let q_applied = 1.2e-4;
    let slipped = mus.iter().zip(&loads).filter(|(mu, f)| q_applied > *mu * *f).count();
    println!("{slipped} of {n} contacts slip under Q* = {q_applied:e} (the rest stick)");
    Ok(())
}
