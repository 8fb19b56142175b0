//! `kefric law`: solver-ready tables `pressure_Pa,mu,dmu_dp_per_Pa` whose rows
//! interpolate within their stated error, checked against direct
//! integration of the model (independent of the curve the law is built on).
use crate::support::{assert_bad_input, assert_stderr_has, kefric, stderr};
use ke_friction::{Model, Params, CURVE_ACCURACY};

/// A table's header lines, its stated interpolation error and its rows.
struct Csv {
    header: Vec<String>,
    stated: f64,
    rows: Vec<[f64; 3]>,
}

fn parse(o: &std::process::Output) -> Csv {
    assert!(o.status.success(), "{}", stderr(o));
    let text = String::from_utf8(o.stdout.clone()).unwrap();
    // The notes are on stderr: the CSV is the names and the rows only.
    let header: Vec<String> = stderr(o)
        .lines()
        .take_while(|l| l.starts_with('#'))
        .map(String::from)
        .collect();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("pressure_Pa,mu,dmu_dp_per_Pa"), "{text}");
    let rows: Vec<[f64; 3]> = lines
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect();
    let line = header
        .iter()
        .find(|l| l.contains("worst relative error of linear interpolation"))
        .unwrap_or_else(|| panic!("no stated error in {text}"));
    let at = line.find(": ").unwrap() + 2;
    let stated: f64 = line[at..].split_whitespace().next().unwrap().parse().unwrap();
    Csv { header, stated, rows }
}

/// `kefric law` of ψ = 1, θ = 0.001 on H = 1 GPa (the pressures to add).
const LAW: &[&str] = &["law", "--psi", "1", "--theta", "0.001", "--hardness", "1e9"];

/// μ of the model by direct integration at pressure `p` on hardness `h`.
fn exact(model: &Model, p: f64, h: f64) -> f64 {
    model.at_f_star(p / h).unwrap().mu.unwrap()
}

#[test]
fn law_rows_interpolate_within_their_stated_error() {
    let h = 1e9;
    let o = kefric(&[LAW, &["--pressure", "1e4:1e8"]].concat());
    let csv = parse(&o);
    let head = csv.header.join("\n");
    for needle in [
        "psi = 1, theta = 0.001",
        "hardness H = 1e9 Pa",
        "units: pressure Pa (the solver model's stress unit), mu 1, dmu_dp 1/Pa",
    ] {
        assert!(head.contains(needle), "{needle} missing in {head}");
    }
    assert!(head.contains(env!("CARGO_PKG_VERSION")), "{head}");
    // The default tolerance, met.
    assert!(csv.stated > 0.0 && csv.stated <= 1e-3, "{head}");
    let n = csv.rows.len();
    assert!(head.contains(&format!("{n} rows")), "{head}");
    let (first, last) = (csv.rows[0][0], csv.rows[n - 1][0]);
    assert_eq!((first, last), (1e4, 1e8));
    let model = Model::new(Params::new(1.0, 0.001)).unwrap();
    // The rows: log-spaced, μ within the curve's accuracy of direct
    // integration, dμ/dp within 1e-4 of a central difference of it.
    let ratio = (last / first).powf(1.0 / (n - 1) as f64);
    let mut worst_mid = 0.0f64;
    for (i, w) in csv.rows.windows(2).enumerate() {
        let ([p0, mu0, d0], [p1, mu1, _]) = (w[0], w[1]);
        assert!((p1 / p0 / ratio - 1.0).abs() < 1e-12, "row {i}: not log-spaced");
        let mu = exact(&model, p0, h);
        assert!(
            (mu0 / mu - 1.0).abs() <= 2.0 * CURVE_ACCURACY,
            "row {i}: mu {mu0} against {mu}"
        );
        let dp = p0 * 1e-4;
        let fd = (exact(&model, p0 + dp, h) - exact(&model, p0 - dp, h)) / (2.0 * dp);
        assert!((d0 / fd - 1.0).abs() < 1e-4, "row {i}: dmu_dp {d0} against {fd}");
        // Between rows: linear interpolation in p within the stated error
        // (+ the law's own error against the model) at the midpoint, and
        // within 2 % more at the quarter points (the error's peak need not
        // be at the midpoint; the stated error samples eighths).
        for (t, slack) in [(0.5, 1.0), (0.25, 1.02), (0.75, 1.02)] {
            let p = p0 + (p1 - p0) * t;
            let linear = mu0 + (mu1 - mu0) * t;
            let e = (linear / exact(&model, p, h) - 1.0).abs();
            assert!(
                e <= slack * csv.stated + 2.0 * CURVE_ACCURACY,
                "interval {i} at {t}: {e} > {}",
                csv.stated
            );
            if t == 0.5 {
                worst_mid = worst_mid.max(e);
            }
        }
    }
    // The stated error is the error, not a loose bound.
    assert!(
        worst_mid >= 0.9 * csv.stated,
        "midpoints' worst {worst_mid}, stated {}",
        csv.stated
    );
}

#[test]
fn law_takes_the_fewest_rows_that_meet_the_tolerance() {
    let base = [
        "law",
        "--psi",
        "2",
        "--theta",
        "0.003",
        "--hardness",
        "2e9",
        "--pressure",
        "2e4:2e8",
    ];
    let run = |extra: &[&str]| parse(&kefric(&[&base[..], extra].concat()));
    let coarse = run(&["--tolerance", "1e-3"]);
    let fine = run(&["--tolerance", "1e-4"]);
    assert!(fine.stated <= 1e-4 && coarse.stated <= 1e-3);
    assert!(
        fine.rows.len() > 2 * coarse.rows.len(),
        "{} vs {}",
        fine.rows.len(),
        coarse.rows.len()
    );
    // One row fewer misses it (the count is the fewest): a warning, exit 0.
    let fewer = (fine.rows.len() - 1).to_string();
    let o = kefric(&[&base[..], &["--tolerance", "1e-4", "--rows", &fewer]].concat());
    let less = parse(&o);
    assert_eq!(less.rows.len(), fine.rows.len() - 1);
    assert!(less.stated > 1e-4, "{}", less.stated);
    assert_stderr_has(&o, "\nwarning: ");
    assert_stderr_has(&o, "more than 0.0001");
}

#[test]
fn law_count_in_the_pressure_range_gives_that_many_rows() {
    let o = kefric(&[LAW, &["--pressure", "1e4:1e8:9"]].concat());
    let csv = parse(&o);
    assert_eq!(csv.rows.len(), 9);
    assert_eq!(csv.rows[4][0], 1e6);
    // Nine rows over four decades miss 1e-3, and say so.
    assert!(csv.stated > 1e-3 && stderr(&o).contains("warning"), "{}", csv.stated);
}

#[test]
fn law_takes_the_si_inputs() {
    let o = kefric(&[&["law"][..], &crate::cli_tools::SI, &["--pressure", "1e5:1e7"]].concat());
    let csv = parse(&o);
    assert!(csv.header.join("\n").contains("hardness H = 2e9 Pa"));
    assert!(csv.stated <= 1e-3 && csv.rows.len() >= 2);
}

#[test]
fn law_refuses_bad_input_naming_the_flag() {
    let law = ["law", "--psi", "1", "--theta", "0.001"];
    for (extra, needle) in [
        (&["--pressure", "1e4:1e8"][..], "--hardness"),
        (&["--hardness", "1e9", "--pressure", "0:1e8"], "--pressure"),
        (&["--hardness", "1e9", "--pressure", "1e8:1e4"], "--pressure"),
        (&["--hardness", "1e9", "--pressure", "1e4"], "--pressure"),
        (&["--hardness", "1e9", "--pressure", "1e4:x"], "--pressure"),
        (&["--hardness", "-1", "--pressure", "1e4:1e8"], "--hardness"),
        (&["--hardness", "1e9", "--pressure", "1e4:1e8", "--rows", "1"], "--rows"),
        (
            &["--hardness", "1e9", "--pressure", "1e4:1e8:5", "--rows", "6"],
            "--rows",
        ),
        (
            &["--hardness", "1e9", "--pressure", "1e4:1e8", "--tolerance", "0"],
            "--tolerance",
        ),
        (
            &["--hardness", "1e9", "--pressure", "1e4:1e8", "--tolerance", "nan"],
            "--tolerance",
        ),
        (
            &["--hardness", "1e9", "--pressure", "1e4:1e8", "--format", "ansys"],
            "--format",
        ),
        (
            &["--hardness", "1e9", "--pressure", "1e4:1e8", "--stress-unit", "kPa"],
            "--stress-unit",
        ),
        // F* = p/H up to 1e3: beyond the model's reach.
        (&["--hardness", "1e9", "--pressure", "1e4:1e12"], "--pressure"),
    ] {
        let o = kefric(&[&law[..], extra].concat());
        assert_bad_input(&o, needle);
    }
    let o = kefric(&["law", "--theta", "0.001", "--hardness", "1e9", "--pressure", "1e4:1e8"]);
    assert_bad_input(&o, "--psi");
}

#[test]
fn law_writes_each_solvers_syntax_in_its_stress_unit() {
    let base = [LAW, &["--pressure", "1e4:1e8:5"]].concat();
    let csv = parse(&kefric(&base));
    let run = |extra: &[&str]| {
        let o = kefric(&[&base[..], extra].concat());
        assert!(o.status.success(), "{}", stderr(&o));
        String::from_utf8(o.stdout).unwrap()
    };
    // The rows of every format are the CSV's (each format's reader is in
    // the library's tests); here: the syntax's mark, its comments, the
    // unit.
    for (format, mark, comment) in [
        ("abaqus", "*FRICTION", "** "),
        ("ls-dyna", "*DEFINE_TABLE", "$ "),
        ("moose", "axis = x", "# "),
        ("comsol", "% p mu", "% "),
    ] {
        let text = run(&["--format", format, "--stress-unit", "MPa"]);
        assert!(text.contains(mark), "{format}: {text}");
        assert!(
            text.contains(&format!("{comment}units: pressure MPa")),
            "{format}: {text}"
        );
        assert!(text.contains(&format!("{comment}psi = 1, theta = 0.001")), "{text}");
        // The middle row, 1e6 Pa = 1 MPa.
        let mu = csv.rows[2][1].to_string();
        assert!(text.contains(&mu), "{format}: {mu} missing in {text}");
    }
    let abaqus = run(&["--format", "abaqus", "--stress-unit", "MPa"]);
    assert!(abaqus.contains(&format!("{}, 0., 1\n", csv.rows[2][1])), "{abaqus}");
    let mpa = run(&["--stress-unit", "MPa"]);
    let mut lines = mpa.lines();
    assert_eq!(lines.next(), Some("pressure_MPa,mu,dmu_dp_per_MPa"));
    let middle: Vec<f64> = lines.nth(2).unwrap().split(',').map(|x| x.parse().unwrap()).collect();
    assert_eq!(middle, [1.0, csv.rows[2][1], csv.rows[2][2] * 1e6]);
}
