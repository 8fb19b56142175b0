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
    [
        Csv = "csv",
        Abaqus = "abaqus",
        LsDyna = "ls-dyna",
        Moose = "moose",
        Comsol = "comsol"
    ]
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

/// `text` in lines of at most `width` characters, broken at spaces (a
/// longer word stays whole on its own line).
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = vec![];
    for word in text.split(' ').filter(|w| !w.is_empty()) {
        match lines.last_mut() {
            Some(line) if line.chars().count() + 1 + word.chars().count() <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
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
                // A note never ends a comment early: one line each
                // (LS-DYNA: lines of at most 80 columns, its card width).
                let n = n.replace(['\n', '\r'], " ");
                if mark == "$" {
                    for line in wrap(&n, 80 - 2) {
                        let _ = writeln!(s, "$ {line}");
                    }
                } else {
                    let _ = writeln!(s, "{mark} {n}");
                }
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
                let usage = format!(
                    "For *CONTACT_... with FS = -2 and FD = {table}: mu against the contact pressure ({u}: the model's stress unit), the same curve at relative velocities {} and {}",
                    Shortest(LS_DYNA_VELOCITIES[0]),
                    Shortest(LS_DYNA_VELOCITIES[1])
                );
                for line in wrap(&usage, 80 - 2) {
                    let _ = writeln!(s, "$ {line}");
                }
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
        for x in [
            1e4,
            0.5252108573913574,
            1.2345678901234567e-4,
            31622.776601683792,
            9.87654321987654e-11,
        ] {
            let s = ls_dyna_number(x);
            assert!(s.len() <= LS_DYNA_FIELD, "{s}");
            let back: f64 = s.parse().unwrap();
            assert!((back / x - 1.0).abs() <= 5e-15, "{x} {s}");
        }
        assert_eq!(ls_dyna_number(0.5252108573913574), "0.5252108573913574");
    }
    // Readers written from each solver's documented grammar (not from the
    // emitter): they take what the solver takes and nothing else.

    fn table() -> (FrictionLaw, LawTable) {
        let law = FrictionLaw::new(
            crate::Params::new(1.0, 0.001),
            1e9,
            Some((1e4, 1e8)),
            crate::OutOfRange::Error,
        )
        .unwrap();
        let t = LawTable::for_tolerance(&law, 1e4, 1e8, 1e-3).unwrap();
        (law, t)
    }

    fn notes(law: &FrictionLaw, t: &LawTable, unit: StressUnit) -> Vec<String> {
        law_notes(law, t, unit, Some(1e-3), &["psi = 1, theta = 0.001".into()])
    }

    /// Abaqus input: `**` starts a comment line, `*` a keyword line
    /// (`*NAME, PARAM=VALUE, …`, case-insensitive), any other line is a
    /// data line of comma-separated values (an empty field is 0). The
    /// `*FRICTION` data lines for isotropic friction: μ, slip rate,
    /// contact pressure, temperature, field variables.
    fn read_abaqus(text: &str) -> Vec<(f64, f64, f64)> {
        let mut in_friction = false;
        let mut rows = vec![];
        for line in text.lines() {
            if line.starts_with("**") {
                continue;
            }
            if let Some(keyword) = line.strip_prefix('*') {
                let name = keyword.split(',').next().unwrap().trim().to_ascii_uppercase();
                assert!(!in_friction || name != "FRICTION", "a second *FRICTION");
                in_friction = name == "FRICTION";
                assert!(!keyword.contains(','), "*FRICTION takes no parameter here: {line}");
                continue;
            }
            assert!(in_friction, "a data line outside *FRICTION: {line}");
            assert!(line.len() <= 256, "Abaqus reads 256 characters a line");
            let f: Vec<f64> = line
                .split(',')
                .map(|v| {
                    if v.trim().is_empty() {
                        0.0
                    } else {
                        v.trim().parse().unwrap()
                    }
                })
                .collect();
            assert!(f.len() >= 3, "{line}");
            rows.push((f[0], f[1], f[2]));
        }
        rows
    }

    /// An LS-DYNA curve: its id and its points (abscissa, ordinate).
    type Curve = (u32, Vec<(f64, f64)>);

    /// LS-DYNA keyword input: `$` starts a comment, `*` a keyword; cards
    /// are fixed fields. `*DEFINE_TABLE`: card 1 TBID, SFA, OFFA (I10,
    /// 2E10.0); then one VALUE a card (E20.0) until the next keyword, the
    /// curves following in the values' order. `*DEFINE_CURVE`: card 1
    /// LCID, SIDR, SFA, SFO, … (I10, I10, E10.0, E10.0, …); then points
    /// A, O (2E20.0).
    fn read_ls_dyna(text: &str) -> (u32, Vec<f64>, Vec<Curve>) {
        let field = |line: &str, at: usize, width: usize| -> String {
            assert!(line.len() <= 80, "a card is 80 columns: {line}");
            line.get(at..(at + width).min(line.len()))
                .unwrap_or("")
                .trim()
                .to_string()
        };
        let (mut table, mut values, mut curves) = (0u32, vec![], vec![]);
        let mut keyword = String::new();
        let mut first = false;
        for line in text.lines() {
            assert!(line.chars().count() <= 80, "LS-DYNA reads 80 columns: {line}");
            if line.starts_with('$') {
                continue;
            }
            if let Some(k) = line.strip_prefix('*') {
                keyword = k.trim().to_string();
                first = true;
                continue;
            }
            match (keyword.as_str(), first) {
                ("DEFINE_TABLE", true) => {
                    table = field(line, 0, 10).parse().unwrap();
                    assert_eq!(field(line, 10, 10).parse::<f64>().unwrap(), 1.0);
                    assert_eq!(field(line, 20, 10).parse::<f64>().unwrap(), 0.0);
                }
                ("DEFINE_TABLE", false) => values.push(field(line, 0, 20).parse().unwrap()),
                ("DEFINE_CURVE", true) => {
                    let id = field(line, 0, 10).parse().unwrap();
                    assert_eq!(field(line, 20, 10).parse::<f64>().unwrap(), 1.0, "SFA");
                    assert_eq!(field(line, 30, 10).parse::<f64>().unwrap(), 1.0, "SFO");
                    curves.push((id, vec![]));
                }
                ("DEFINE_CURVE", false) => {
                    let (a, o) = (field(line, 0, 20), field(line, 20, 20));
                    curves
                        .last_mut()
                        .unwrap()
                        .1
                        .push((a.parse().unwrap(), o.parse().unwrap()));
                }
                (k, _) => panic!("unexpected keyword {k}"),
            }
            first = false;
        }
        (table, values, curves)
    }

    /// MOOSE input (HIT): `#` starts a comment; `[name]` opens a block,
    /// `[]` closes it; `key = value`, a value with spaces in single
    /// quotes. Returns the `[Functions]` sub-blocks' parameters.
    fn read_moose(text: &str) -> Vec<(String, Vec<(String, String)>)> {
        let mut path: Vec<String> = vec![];
        let mut functions = vec![];
        for line in text.lines() {
            let line = line.split('#').next().unwrap().trim();
            if line.is_empty() {
                continue;
            }
            if line == "[]" {
                path.pop().expect("a [] closes no block");
            } else if let Some(name) = line.strip_prefix('[').and_then(|l| l.strip_suffix(']')) {
                path.push(name.to_string());
                if path.len() == 2 && path[0] == "Functions" {
                    functions.push((name.to_string(), vec![]));
                }
            } else {
                let (k, v) = line.split_once('=').expect("key = value");
                let v = v.trim();
                let v = v.strip_prefix('\'').and_then(|v| v.strip_suffix('\'')).unwrap_or(v);
                assert!(path.len() == 2, "a parameter outside a function block");
                functions
                    .last_mut()
                    .unwrap()
                    .1
                    .push((k.trim().to_string(), v.to_string()));
            }
        }
        assert!(path.is_empty(), "an unclosed block");
        functions
    }

    /// COMSOL spreadsheet data: a `%` line is a comment; each other row
    /// is the arguments then the function values, separated by spaces or
    /// tabs.
    fn read_comsol(text: &str) -> Vec<Vec<f64>> {
        text.lines()
            .filter(|l| !l.trim_start().starts_with('%') && !l.trim().is_empty())
            .map(|l| l.split_whitespace().map(|v| v.parse().unwrap()).collect())
            .collect()
    }

    /// CSV (RFC 4180 without quotes): a names line, then rows of numbers.
    fn read_csv(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
        let mut lines = text.lines();
        let names = lines.next().unwrap().split(',').map(String::from).collect();
        let rows = lines
            .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
            .collect();
        (names, rows)
    }

    #[test]
    fn every_format_reads_back_to_the_rows() {
        let (law, t) = table();
        for unit in StressUnit::ALL {
            let want: Vec<LawRow> = t.rows.iter().map(|r| unit.row(r)).collect();
            let notes = notes(&law, &t, unit);
            let u = unit.name();

            let (names, rows) = read_csv(&t.to_format(LawFormat::Csv, unit, &notes));
            assert_eq!(names, [format!("pressure_{u}"), "mu".into(), format!("dmu_dp_per_{u}")]);
            let got: Vec<LawRow> = rows
                .iter()
                .map(|r| LawRow {
                    pressure: r[0],
                    mu: r[1],
                    dmu_dp: r[2],
                })
                .collect();
            assert_eq!(got, want, "csv {u}");

            let text = t.to_format(LawFormat::Abaqus, unit, &notes);
            assert!(text.contains(&format!("** units: pressure {u}")), "{text}");
            let rows = read_abaqus(&text);
            assert_eq!(
                rows,
                want.iter().map(|r| (r.mu, 0.0, r.pressure)).collect::<Vec<_>>(),
                "abaqus {u}"
            );

            let text = t.to_format(LawFormat::LsDyna, unit, &notes);
            let (id, values, curves) = read_ls_dyna(&text);
            assert_eq!((id, values), (LS_DYNA_TABLE_ID, LS_DYNA_VELOCITIES.to_vec()));
            assert_eq!(curves.len(), 2);
            for (i, (lcid, points)) in curves.iter().enumerate() {
                assert_eq!(*lcid, LS_DYNA_TABLE_ID + 1 + i as u32);
                assert_eq!(points.len(), want.len());
                for (&(p, mu), r) in points.iter().zip(&want) {
                    // Exact where the shortest form fits E20.0, else to
                    // the 15 or 16 digits that do.
                    assert_eq!(p, ls_dyna_number(r.pressure).parse::<f64>().unwrap());
                    assert_eq!(mu, ls_dyna_number(r.mu).parse::<f64>().unwrap());
                    assert!((p / r.pressure - 1.0).abs() <= 5e-15 && (mu / r.mu - 1.0).abs() <= 5e-15);
                }
            }

            let text = t.to_format(LawFormat::Moose, unit, &notes);
            assert!(
                text.contains(&format!("function_friction = {MOOSE_FUNCTION}")),
                "{text}"
            );
            let functions = read_moose(&text);
            assert_eq!(functions.len(), 1);
            let (name, params) = &functions[0];
            assert_eq!(name, MOOSE_FUNCTION);
            let get = |k: &str| params.iter().find(|(n, _)| n == k).map(|(_, v)| v.clone()).unwrap();
            assert_eq!((get("type"), get("axis")), ("PiecewiseLinear".into(), "x".into()));
            let nums = |v: String| v.split_whitespace().map(|x| x.parse().unwrap()).collect::<Vec<f64>>();
            assert_eq!(
                nums(get("x")),
                want.iter().map(|r| r.pressure).collect::<Vec<_>>(),
                "moose {u}"
            );
            assert_eq!(nums(get("y")), want.iter().map(|r| r.mu).collect::<Vec<_>>());

            let rows = read_comsol(&t.to_format(LawFormat::Comsol, unit, &notes));
            assert_eq!(
                rows,
                want.iter().map(|r| vec![r.pressure, r.mu]).collect::<Vec<_>>(),
                "comsol {u}"
            );
        }
    }

    #[test]
    fn a_stress_unit_scales_pressure_and_slope_together() {
        let (law, t) = table();
        let pa = t.rows[3];
        let mpa = StressUnit::MPa.row(&pa);
        assert_eq!(
            (mpa.pressure, mpa.mu, mpa.dmu_dp),
            (pa.pressure / 1e6, pa.mu, pa.dmu_dp * 1e6)
        );
        // μ(p) over a step is the same in any unit: dμ = dμ/dp · dp.
        let psi = StressUnit::Psi.row(&pa);
        assert!((psi.dmu_dp * psi.pressure / (pa.dmu_dp * pa.pressure) - 1.0).abs() < 1e-15);
        let notes = notes(&law, &t, StressUnit::MPa).join("\n");
        assert!(
            notes.contains("hardness H = 1000 MPa; pressure from 0.01 to 100 MPa"),
            "{notes}"
        );
        assert!(notes.contains("dmu_dp 1/MPa"), "{notes}");
    }

    #[test]
    fn a_note_stays_one_comment_line() {
        let (_, t) = table();
        let text = t.to_format(LawFormat::Abaqus, StressUnit::Pa, &["two\n*lines".into()]);
        assert!(text.starts_with("** two *lines\n"), "{text}");
        assert_eq!(read_abaqus(&text).len(), t.rows.len());
    }
}
