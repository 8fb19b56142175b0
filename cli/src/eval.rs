//! `kefric eval`: direct integration at h* or F*, one row per point.

use crate::args::{describe, number, Failure, ModelArgs, PaperRange};
use ke_friction::Contact;

/// Evaluate the model by direct integration at given h* or F*.
///
/// A point is one number, or a range START:STOP:COUNT (linear for h*,
/// logarithmic for F*).
#[derive(Debug, clap::Args)]
#[command(group(clap::ArgGroup::new("at").required(true).args(["h_star", "f_star"])))]
pub struct Args {
    #[command(flatten)]
    pub model: ModelArgs,
    /// Separation h* = h/σ, within ±1e6 (or START:STOP:COUNT, linear; COUNT up to 1000000).
    #[arg(long, value_name = "H|START:STOP:COUNT", allow_hyphen_values = true)]
    pub h_star: Option<String>,
    /// External force F* = F/(A_n·H) > 0 (or START:STOP:COUNT, logarithmic; COUNT up to 1000000).
    #[arg(long, value_name = "F|START:STOP:COUNT", allow_hyphen_values = true)]
    pub f_star: Option<String>,
    /// Print one JSON object per point, one per line (numbers in shortest round-trip form).
    #[arg(long)]
    pub json: bool,
}

/// Spacing of the points of a range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spacing {
    /// Equal steps.
    Linear,
    /// Equal ratios (all points > 0).
    Log,
}

/// Parses `X` or `START:STOP:COUNT` into the points; `flag` names the input.
pub fn points(flag: &str, text: &str, spacing: Spacing) -> Result<Vec<f64>, Failure> {
    let bad = |why: String| Failure::input(format!("{flag}: {why}"));
    let parts: Vec<&str> = text.split(':').collect();
    let num = |s: &str| number(flag, s);
    let positive = |v: f64| {
        if spacing == Spacing::Log && v <= 0.0 {
            Err(bad(format!(
                "{} is out of range: must be > 0",
                ke_friction::Shortest(v)
            )))
        } else {
            Ok(v)
        }
    };
    match parts.as_slice() {
        [one] => Ok(vec![positive(num(one)?)?]),
        [a, b, n] => {
            let (a, b) = (positive(num(a)?)?, positive(num(b)?)?);
            let n: usize = n
                .trim()
                .parse()
                .ok()
                .filter(|&n| (1..=1_000_000).contains(&n))
                .ok_or_else(|| {
                    bad(format!(
                        "COUNT '{n}' is out of range: must be a whole number from 1 to 1000000"
                    ))
                })?;
            Ok((0..n)
                .map(|i| {
                    let t = if n == 1 { 0.0 } else { i as f64 / (n - 1) as f64 };
                    match spacing {
                        Spacing::Linear => a + (b - a) * t,
                        Spacing::Log => a * (b / a).powf(t),
                    }
                })
                .collect())
        }
        _ => Err(bad(format!("'{text}' is not a number or START:STOP:COUNT"))),
    }
}

/// Runs `kefric eval`.
pub fn run(args: Args) -> Result<(), Failure> {
    let (model, source) = args.model.model_and_source()?;
    let contacts: Vec<Result<Contact, ke_friction::EvalError>> = if let Some(h) = &args.h_star {
        points("--h-star", h, Spacing::Linear)?
            .into_iter()
            .map(|h| model.at_h_star(h))
            .collect()
    } else {
        let f = args.f_star.as_deref().unwrap_or_default();
        points("--f-star", f, Spacing::Log)?
            .into_iter()
            .map(|f| model.at_f_star(f))
            .collect()
    };
    let flag = if args.h_star.is_some() { "--h-star" } else { "--f-star" };
    let contacts = contacts
        .into_iter()
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| Failure::of(flag, e))?;
    let p = model.params();
    let mut paper = PaperRange::default();
    if args.json {
        // One record a line: the parameters and the contact, flat.
        #[derive(serde::Serialize)]
        struct Row<'a> {
            #[serde(flatten)]
            params: &'a ke_friction::Params,
            #[serde(flatten)]
            contact: &'a Contact,
            #[serde(flatten, skip_serializing_if = "Option::is_none")]
            source: Option<&'a crate::args::SurfaceSource>,
        }
        for c in &contacts {
            let row = Row {
                params: p,
                contact: c,
                source: source.as_ref(),
            };
            outln!("{}", serde_json::to_string(&row).expect("a contact serialises"))?;
            paper.note(c.f_star, c.h_star);
        }
    } else {
        outln!("# {}", describe(p))?;
        if let Some(source) = &source {
            outln!("# {source}")?;
        }
        outln!(
            "{:>10} {:>10} {:>12} {:>12} {:>12} {:>12} {:>12}",
            "h*",
            "d*",
            "P*",
            "Fs*",
            "Q*",
            "F*",
            "mu"
        )?;
        for c in &contacts {
            let mu = c.mu.map_or("undefined".to_string(), |m| format!("{m:.5e}"));
            outln!(
                "{:>10.6} {:>10.6} {:>12.5e} {:>12.5e} {:>12.5e} {:>12.5e} {:>12}",
                c.h_star,
                c.d_star,
                c.p_star,
                c.fs_star,
                c.q_star,
                c.f_star,
                mu
            )?;
            paper.note(c.f_star, c.h_star);
        }
    }
    paper.warn();
    Ok(())
}
