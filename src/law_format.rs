//! A [`LawTable`] in a solver's own input syntax: the one place that
//! writes `kefric law --format` and Python's `FrictionLaw.table(format=…)`.
//!
//! | [`LawFormat`] | what it is | how the solver reads it |
//! |---|---|---|
//! | `csv` | `pressure_<unit>,mu,dmu_dp_per_<unit>` and the rows, nothing else | NumPy `genfromtxt(names=True, delimiter=',')`, pandas `read_csv()` |
//! | `abaqus` | a `*FRICTION` block, data lines μ, slip rate (0), contact pressure | under `*SURFACE INTERACTION` (Standard and Explicit) |
//! | `ls-dyna` | `*DEFINE_TABLE` (relative velocities 0 and 1, the same curve) and two `*DEFINE_CURVE`s μ against pressure | `*CONTACT_…` with FS = −2, FD = the table's id |
//! | `moose` | a `[Functions]` block: `PiecewiseLinear` with `axis = x` | `ComputeFrictionalForceLMMechanicalContact`'s `function_friction` |
//! | `comsol` | a spreadsheet text file: p and μ per row, `%` comments | an Interpolation function, data source File, format Spreadsheet |
//!
//! Every format but CSV carries the notes ([`law_notes`]: the inputs, the
//! units, the measured interpolation error) in its own comment form (`**`,
//! `$`, `#`, `%`); CSV carries none, so that NumPy and pandas read it with
//! their defaults (a `#` line holding commas is what `genfromtxt(names=True)`
//! takes for the names), and the front end shows them elsewhere (`kefric`:
//! on stderr).
//!
//! Pressures are in the [`StressUnit`] asked for and dμ/dp in its inverse,
//! scaled together: a solver reads the pressure in the model's own stress
//! unit (MPa in an N-mm model), and μ is unchanged.
//!
//! ```
//! use ke_friction::{FrictionLaw, LawFormat, LawTable, OutOfRange, Params, StressUnit};
//! let law = FrictionLaw::new(Params::new(1.0, 0.001), 1e9, Some((1e4, 1e8)), OutOfRange::Error)?;
//! let table = LawTable::with_rows(&law, 1e4, 1e8, 5)?;
//! let moose = table.to_format(LawFormat::Moose, StressUnit::MPa, &[]);
//! assert!(moose.contains("axis = x") && moose.contains("x = '0.01 "));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::{FrictionLaw, LawRow, LawTable, Shortest, INTERIOR_POINTS};
use std::fmt::Write;

/// A solver input syntax `kefric law --format` writes (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LawFormat {
    /// Comma-separated values with one names line: loads with NumPy's and
    /// pandas' defaults.
    Csv,
    /// An Abaqus `*FRICTION` block with pressure-dependent data lines.
    Abaqus,
    /// LS-DYNA `*DEFINE_TABLE` and `*DEFINE_CURVE` for `*CONTACT` FS = −2.
    LsDyna,
    /// A MOOSE `PiecewiseLinear` function of the contact pressure.
    Moose,
    /// A COMSOL interpolation-function text file (spreadsheet format).
    Comsol,
}

crate::named!(
    LawFormat,
    "format",
    [Csv = "csv", Abaqus = "abaqus", LsDyna = "ls-dyna", Moose = "moose", Comsol = "comsol"]
);

/// The stress unit a table's pressures are written in (dμ/dp in its
/// inverse): the solver model's own.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StressUnit {
    /// Pascal (N/m²): SI models.
    Pa,
    /// Megapascal (N/mm²): N-mm-s models.
    MPa,
    /// Pound-force per square inch: lbf-in models.
    Psi,
}

crate::named!(StressUnit, "stress unit", [Pa = "Pa", MPa = "MPa", Psi = "psi"]);

impl StressUnit {
    /// Pascals per unit (psi: 1 lbf/in² = 4.4482216152605 N / 0.0254² m²,
    /// both exact by definition).
    pub fn pascals(self) -> f64 {
        match self {
            StressUnit::Pa => 1.0,
            StressUnit::MPa => 1e6,
            StressUnit::Psi => 4.4482216152605 / (0.0254 * 0.0254),
        }
    }

    /// A row in this unit: the pressure divided by [`Self::pascals`],
    /// dμ/dp multiplied by it, μ as is.
    pub fn row(self, r: &LawRow) -> LawRow {
        let k = self.pascals();
        LawRow {
            pressure: r.pressure / k,
            mu: r.mu,
            dmu_dp: r.dmu_dp * k,
        }
    }
}

/// The id of the LS-DYNA `*DEFINE_TABLE`; its curves are the next two
/// ids (renumber all three if they clash with the model's).
pub const LS_DYNA_TABLE_ID: u32 = 9100;

/// The relative velocities of the LS-DYNA table's two (identical) curves:
/// μ does not depend on velocity, and two equal curves give the same μ
/// however the solver interpolates or extrapolates between them.
pub const LS_DYNA_VELOCITIES: [f64; 2] = [0.0, 1.0];

/// The width of an LS-DYNA curve point's fields (format E20.0).
pub const LS_DYNA_FIELD: usize = 20;

/// The name of the MOOSE function the `moose` format defines.
pub const MOOSE_FUNCTION: &str = "kef_mu";

/// `x` in at most [`LS_DYNA_FIELD`] characters: its shortest round-trip
/// form when that fits, else the most significant digits that do (16 or
/// 15: a positive value with a two-digit exponent, as a table's are).
pub fn ls_dyna_number(x: f64) -> String {
    let s = Shortest(x).to_string();
    if s.len() <= LS_DYNA_FIELD {
        return s;
    }
    (0..=16usize)
        .rev()
        .map(|digits| format!("{x:.digits$E}"))
        .find(|s| s.len() <= LS_DYNA_FIELD)
        .unwrap_or(s)
}

/// The notes every format carries in its comment form (CSV: none; the
/// front end shows them): what wrote the table, `extra` (the model's
/// inputs as the front end names them), the hardness and the pressure
/// range in `unit`, the units, and the measured interpolation error (with
/// the tolerance the rows were chosen for, if they were).
pub fn law_notes(
    law: &FrictionLaw,
    table: &LawTable,
    unit: StressUnit,
    tolerance: Option<f64>,
    extra: &[String],
) -> Vec<String> {
    let u = unit.name();
    let k = unit.pascals();
    let (lo, hi) = match (table.rows.first(), table.rows.last()) {
        (Some(a), Some(b)) => (a.pressure, b.pressure),
        _ => (f64::NAN, f64::NAN),
    };
    let mut notes = vec![format!(
        "ke-friction {}: the Kogut-Etsion static friction coefficient mu of the contact pressure p, at F* = p/H",
        env!("CARGO_PKG_VERSION")
    )];
    notes.extend(extra.iter().cloned());
    notes.push(format!(
        "hardness H = {} {u}; pressure from {} to {} {u}, {} rows, log-spaced",
        Shortest(law.hardness() / k),
        Shortest(lo / k),
        Shortest(hi / k),
        table.rows.len()
    ));
    notes.push(format!(
        "units: pressure {u} (the solver model's stress unit), mu 1, dmu_dp 1/{u}"
    ));
    notes.push(format!(
        "worst relative error of linear interpolation in p between rows: {} (measured at {} points inside every interval, the midpoint among them{}); the law is within {} of the model",
        Shortest::rounded(table.interpolation_error),
        INTERIOR_POINTS,
        match tolerance {
            Some(t) => format!("; rows chosen for a tolerance of {}", Shortest(t)),
            None => String::new(),
        },
        Shortest::rounded(law.max_error())
    ));
    notes
}

impl LawTable {
    /// The table in `format`, pressures in `unit`, with `notes` (e.g.
    /// [`law_notes`]) as the format's comments (CSV leaves them out: see
    /// the module docs). Every number is in its shortest round-trip form
    /// (LS-DYNA: [`ls_dyna_number`]), so a reader recovers the rows.
    pub fn to_format(&self, format: LawFormat, unit: StressUnit, notes: &[String]) -> String {
        let rows: Vec<LawRow> = self.rows.iter().map(|r| unit.row(r)).collect();
        let u = unit.name();
        let mut s = String::new();
        let comments = |s: &mut String, mark: &str| {
            for n in notes {
                // A note never ends a comment early: one line each.
                let _ = writeln!(s, "{mark} {}", n.replace(['\n', '\r'], " "));
            }
        };
        // `write!` to a String cannot fail.
        match format {
            LawFormat::Csv => {
                let _ = writeln!(s, "pressure_{u},mu,dmu_dp_per_{u}");
                for r in &rows {
                    let _ = writeln!(s, "{},{},{}", Shortest(r.pressure), Shortest(r.mu), Shortest(r.dmu_dp));
                }
            }
            LawFormat::Abaqus => {
                comments(&mut s, "**");
                let _ = writeln!(
                    s,
                    "** Place under *SURFACE INTERACTION; the contact pressure is in {u}: it must be the model's stress unit"
                );
                let _ = writeln!(s, "*FRICTION");
                let _ = writeln!(s, "** mu, slip rate, contact pressure ({u})");
                for r in &rows {
                    let _ = writeln!(s, "{}, 0., {}", Shortest(r.mu), Shortest(r.pressure));
                }
            }
            LawFormat::LsDyna => {
                comments(&mut s, "$");
                let table = LS_DYNA_TABLE_ID;
                let _ = writeln!(
                    s,
                    "$ For *CONTACT_... with FS = -2 and FD = {table}: mu against the contact pressure ({u}: the model's stress unit), the same curve at relative velocities {} and {}",
                    Shortest(LS_DYNA_VELOCITIES[0]),
                    Shortest(LS_DYNA_VELOCITIES[1])
                );
                let _ = writeln!(s, "*DEFINE_TABLE");
                let _ = writeln!(s, "$     TBID       SFA      OFFA");
                let _ = writeln!(s, "{table:>10}{:>10}{:>10}", "1.0", "0.0");
                let _ = writeln!(s, "$              VALUE");
                for v in LS_DYNA_VELOCITIES {
                    let _ = writeln!(s, "{:>20}", ls_dyna_number(v));
                }
                for (i, _) in LS_DYNA_VELOCITIES.iter().enumerate() {
                    let _ = writeln!(s, "*DEFINE_CURVE");
                    let _ = writeln!(s, "$     LCID      SIDR       SFA       SFO");
                    let _ = writeln!(s, "{:>10}{:>10}{:>10}{:>10}", table + 1 + i as u32, 0, "1.0", "1.0");
                    let _ = writeln!(s, "$          pressure (A1)             mu (O1)");
                    for r in &rows {
                        let _ = writeln!(s, "{:>20}{:>20}", ls_dyna_number(r.pressure), ls_dyna_number(r.mu));
                    }
                }
            }
            LawFormat::Moose => {
                comments(&mut s, "#");
                let _ = writeln!(
                    s,
                    "# mu of the contact pressure x ({u}: the model's stress unit); use it in [Constraints] with"
                );
                let _ = writeln!(s, "#   type = ComputeFrictionalForceLMMechanicalContact");
                let _ = writeln!(s, "#   function_friction = {MOOSE_FUNCTION}");
                let join = |f: &dyn Fn(&LawRow) -> f64| {
                    rows.iter()
                        .map(|r| Shortest(f(r)).to_string())
                        .collect::<Vec<_>>()
                        .join(" ")
                };
                let _ = writeln!(s, "[Functions]");
                let _ = writeln!(s, "  [{MOOSE_FUNCTION}]");
                let _ = writeln!(s, "    type = PiecewiseLinear");
                let _ = writeln!(s, "    axis = x");
                let _ = writeln!(s, "    x = '{}'", join(&|r| r.pressure));
                let _ = writeln!(s, "    y = '{}'", join(&|r| r.mu));
                let _ = writeln!(s, "  []");
                let _ = writeln!(s, "[]");
            }
            LawFormat::Comsol => {
                comments(&mut s, "%");
                let _ = writeln!(
                    s,
                    "% Interpolation function, data source File, data format Spreadsheet: argument p ({u}), function mu (1)"
                );
                let _ = writeln!(s, "% p mu");
                for r in &rows {
                    let _ = writeln!(s, "{} {}", Shortest(r.pressure), Shortest(r.mu));
                }
            }
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Named;

    #[test]
    fn names_parse_and_refuse() {
        assert_eq!(LawFormat::parse("ls-dyna").unwrap(), LawFormat::LsDyna);
        assert_eq!(
            LawFormat::parse("ansys").unwrap_err().to_string(),
            "format 'ansys' is unknown: must be one of csv, abaqus, ls-dyna, moose, comsol"
        );
        assert_eq!(StressUnit::parse("MPa").unwrap().pascals(), 1e6);
        assert!(StressUnit::parse("mpa").is_err());
        // 1 psi = 6894.757293168361 Pa (NIST SP 811).
        assert!((StressUnit::Psi.pascals() / 6894.757293168361 - 1.0).abs() < 1e-15);
    }

    #[test]
    fn ls_dyna_numbers_fit_their_field() {
        for x in [1e4, 0.5252108573913574, 1.2345678901234567e-4, 31622.776601683792, 9.87654321987654e-11] {
            let s = ls_dyna_number(x);
            assert!(s.len() <= LS_DYNA_FIELD, "{s}");
            let back: f64 = s.parse().unwrap();
            assert!((back / x - 1.0).abs() <= 5e-15, "{x} {s}");
        }
        assert_eq!(ls_dyna_number(0.5252108573913574), "0.5252108573913574");
    }
}
