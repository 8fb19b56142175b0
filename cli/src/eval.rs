//! `kefric eval`: direct integration at h* or F*, one row per point.

use crate::args::describe;
use crate::load_args::{points, LoadArgs, Spacing};
use crate::model_args::{ModelArgs, SurfaceSource};
use crate::output::sig;
use crate::output::{warn, Failure};
use crate::surface::{sensitivity_line, SensitivityArg};
use ke_friction::topography::Sensitivity;
use ke_friction::{bounds, Contact, Friction, Shortest, Warnings, H_LIMIT};

/// Evaluate the model by direct integration at given h* or F*.
///
/// A point is one number, or a range START:STOP:COUNT (linear for h*,
/// logarithmic for F*, the force and the pressure). A load in SI units
/// (--force with --area, or --pressure) needs the SI inputs or --surface
/// with the materials (for the hardness).
#[derive(Debug, clap::Args)]
#[command(group(clap::ArgGroup::new("at").required(true).args(["h_star", "f_star", "force", "pressure"])))]
pub struct Args {
    #[command(flatten)]
    pub model: ModelArgs,
    /// Separation h* = h/σ, within ±[`H_LIMIT`] (or START:STOP:COUNT, linear; COUNT [`bounds::LOAD_COUNT`]).
    #[arg(long, value_name = "H|START:STOP:COUNT", allow_hyphen_values = true, help = format!("Separation h* = h/σ, within ±{} (or START:STOP:COUNT, linear; COUNT {}).", Shortest(H_LIMIT), bounds::LOAD_COUNT.range()))]
    pub h_star: Option<String>,
    /// External force F* = F/(A_n·H) ([`bounds::F_STAR`]; or START:STOP:COUNT, logarithmic; COUNT [`bounds::LOAD_COUNT`]).
    #[arg(long, value_name = "F|START:STOP:COUNT", allow_hyphen_values = true, help = format!("External force F* = F/(A_n·H) {} (or START:STOP:COUNT, logarithmic; COUNT {}).", bounds::F_STAR.range(), bounds::LOAD_COUNT.range()))]
    pub f_star: Option<String>,
    #[command(flatten)]
    pub load: LoadArgs,
    #[command(flatten)]
    pub sensitivity: SensitivityArg,
    /// Print one JSON object per point, one per line (numbers in shortest round-trip form).
    #[arg(long)]
    pub json: bool,
}

impl Args {
    /// The sensitivity of μ at each F* of `f_star` on the surface, where
    /// one gave the model and it is asked for.
    fn sensitivity(&self, source: Option<&SurfaceSource>, f_star: impl Iterator<Item = f64>) -> Vec<Sensitivity> {
        match source {
            Some(source) if self.sensitivity.on() => source.sensitivity(f_star),
            _ => Vec::new(),
        }
    }
}

/// The sensitivity lines under a table: one a row, named by its F*.
fn print_sensitivity(f_star: impl Iterator<Item = f64>, sensitivity: &[Sensitivity]) -> Result<(), Failure> {
    for (f, s) in f_star.zip(sensitivity) {
        if let Some(line) = sensitivity_line(s) {
            outln!("# mu sensitivity at F* = {}: {line}", sig(f))?;
        }
    }
    Ok(())
}

/// Runs `kefric eval`.
pub fn run(args: Args) -> Result<(), Failure> {
    let (model, source) = args.model.model_and_source()?;
    if args.load.any() {
        return run_loads(&args, &model, source.as_ref());
    }
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
    let mut warnings = Warnings::new();
    // The sensitivity at F* (at h*, the other choices give another F*).
    let sensitivity = if args.h_star.is_some() {
        Vec::new()
    } else {
        args.sensitivity(source.as_ref(), contacts.iter().map(|c| c.f_star))
    };
    if args.json {
        // One record a line: the parameters and the contact, flat.
        for (k, c) in contacts.iter().enumerate() {
            let row = Row {
                params: p,
                result: c,
                source: source.as_ref(),
                sensitivity: sensitivity.get(k),
            };
            outln!("{}", serde_json::to_string(&row).expect("a contact serialises"))?;
            warnings.note_contact(c);
        }
    } else {
        outln!("# {}", describe(p))?;
        if let Some(source) = &source {
            outln!("# {source}")?;
        }
        outln!(
            "{:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}",
            "h*",
            "d*",
            "P*",
            "Fs*",
            "Q*",
            "F*",
            "mu"
        )?;
        for c in &contacts {
            let mu = c.mu.map_or("undefined".to_string(), |m| sig(m).to_string());
            outln!(
                "{:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}",
                sig(c.h_star).to_string(),
                sig(c.d_star).to_string(),
                sig(c.p_star).to_string(),
                sig(c.fs_star).to_string(),
                sig(c.q_star).to_string(),
                sig(c.f_star).to_string(),
                mu
            )?;
            warnings.note_contact(c);
        }
        print_sensitivity(contacts.iter().map(|c| c.f_star), &sensitivity)?;
    }
    warn(&warnings);
    Ok(())
}

/// `kefric eval` at loads in SI units (--force on --area, or --pressure):
/// F* = pressure/hardness, then the model there, one row a load.
fn run_loads(args: &Args, model: &ke_friction::Model, source: Option<&SurfaceSource>) -> Result<(), Failure> {
    let flag = args.load.flag();
    let Some(physical) = args.model.physical(source)? else {
        return Err(Failure::input(format!(
            "{flag}: a load in SI units needs the hardness: give the SI inputs or --surface with the materials (or --f-star)"
        )));
    };
    let loads = args.load.loads()?.unwrap_or_default();
    let mut warnings = Warnings::new();
    let mut rows: Vec<Friction> = Vec::with_capacity(loads.len());
    for load in &loads {
        let f = load.friction(model, &physical).map_err(|e| Failure::of(flag, e))?;
        warnings.note(f.warnings(model, &physical));
        rows.push(f);
    }
    let p = model.params();
    let sensitivity = args.sensitivity(source, rows.iter().map(|f| f.contact.f_star));
    if args.json {
        for (k, f) in rows.iter().enumerate() {
            let row = Row {
                params: p,
                result: f,
                source,
                sensitivity: sensitivity.get(k),
            };
            outln!("{}", serde_json::to_string(&row).expect("a friction record serialises"))?;
        }
    } else {
        outln!("# {}", describe(p))?;
        if let Some(source) = source {
            outln!("# {source}")?;
        }
        if let Some(area) = args.load.area {
            outln!(
                "# loads on A_n = {} m², hardness H = {} Pa",
                sig(area),
                sig(physical.hardness)
            )?;
        } else {
            outln!("# hardness H = {} Pa", sig(physical.hardness))?;
        }
        let load = if args.load.force.is_some() { "F (N)" } else { "p (Pa)" };
        outln!(
            "{load:>12} {:>12} {:>12} {:>12} {:>12} {:>12}",
            "F*",
            "h*",
            "d*",
            "mu",
            if args.load.force.is_some() {
                "Q (N)"
            } else {
                "mu p (Pa)"
            }
        )?;
        for f in &rows {
            let (l, q) = f.as_given();
            outln!(
                "{:>12} {:>12} {:>12} {:>12} {:>12} {:>12}",
                sig(l).to_string(),
                sig(f.contact.f_star).to_string(),
                sig(f.contact.h_star).to_string(),
                sig(f.contact.d_star).to_string(),
                sig(f.mu).to_string(),
                sig(q).to_string()
            )?;
        }
        print_sensitivity(rows.iter().map(|f| f.contact.f_star), &sensitivity)?;
    }
    warn(&warnings);
    Ok(())
}

/// One `--json` line of `eval`: the parameters, a result (a contact, or a
/// load's friction) and the surface it came from, flat.
#[derive(serde::Serialize)]
struct Row<'a, T> {
    #[serde(flatten)]
    params: &'a ke_friction::Params,
    #[serde(flatten)]
    result: &'a T,
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    source: Option<&'a crate::model_args::SurfaceSource>,
    /// μ under the other height models and at the band's ends (--surface).
    #[serde(skip_serializing_if = "Option::is_none")]
    sensitivity: Option<&'a Sensitivity>,
}
