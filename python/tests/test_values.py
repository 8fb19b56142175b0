"""Values: the model, the table and curves against the mpmath reference
points and the CLI (`kefric eval --json`, `kefric lookup --json`)."""

import json
import math
import subprocess

import numpy as np
import pytest
from conftest import KEFRIC, MODEL_REL, REFERENCE, SAME_REL, kefric

import ke_friction as kf

CONTACT_KEYS = ["h_star", "d_star", "p_star", "fs_star", "q_star", "f_star", "mu"]


@pytest.mark.parametrize("p", REFERENCE, ids=lambda p: f"{p['model']}-{p['fit']}-{p['mode']}-{p['psi']:.3g}")
def test_model_matches_the_mpmath_reference(p):
    m = kf.Model(p["psi"], p["theta"], beta=p["beta"], nu=p["nu"], eps_star=p["eps_star"],
                 fit=p["fit"] or "consistent", model=p["model"])
    c = m.at_h_star(p["h_star"]) if p["mode"] == "h" else m.at_f_star(p["f_star"])
    for key in ["h_star", "p_star", "fs_star", "q_star", "f_star"]:
        assert getattr(c, key) == pytest.approx(p[key], rel=MODEL_REL, abs=1e-300), key
    if p["mu"] is None or not p["f_star"] > 0:
        assert math.isnan(c.mu)
    else:
        assert c.mu == pytest.approx(p["mu"], rel=MODEL_REL)


@pytest.mark.parametrize("args", [
    ("--psi", "1", "--theta", "0.001", "--f-star", "0.01"),
    ("--psi", "0.5", "--theta", "0.003", "--h-star", "0:3:7"),
    ("--psi", "2", "--theta", "0.003", "--f-star", "1e-5:0.1:9"),
    ("--psi", "1", "--theta", "0.003", "--h-star", "-0.5:6:5", "--model", "ceb", "--fit", "as-printed"),
    ("--psi", "4", "--theta", "0.0001", "--f-star", "1e-4:0.05:4", "--beta", "0.1", "--nu", "0.25",
     "--eps-star", "0.01"),
])
def test_model_matches_kefric_eval(args):
    rows = kefric("eval", *args)
    r0 = rows[0]
    m = kf.Model(r0["psi"], r0["theta"], beta=r0["beta"], nu=r0["nu"], eps_star=r0["eps_star"], fit=r0["fit"],
                 model=r0["model"])
    at_f = "--f-star" in args
    x = np.array([r["f_star"] if at_f else r["h_star"] for r in rows])
    c = m.at_f_star(x) if at_f else m.at_h_star(x)
    for key in CONTACT_KEYS:
        want = np.array([math.nan if r[key] is None else r[key] for r in rows])
        got = getattr(c, key)
        # at F*, the CLI's h* was solved for the F* it asked; Python solves for
        # the F* that h* gives back, a rounding away: compare at solver precision.
        rel = 1e-9 if at_f else SAME_REL
        np.testing.assert_allclose(got, want, rtol=rel, atol=0, equal_nan=True, err_msg=key)


def test_model_md_reference_value():
    # MODEL.md section 7: mu = 0.52521087083 at psi = 1, theta = 0.001, F* = 0.01.
    c = kf.Model(1.0, 0.001).at_f_star(0.01)
    assert type(c.mu) is float
    assert c.mu == pytest.approx(0.52521087083, abs=1e-10)
    assert c.h_star == pytest.approx(1.4692414618, abs=1e-10)


def test_table_is_within_its_tolerance_of_the_reference_points(table):
    info = table.info
    inside = [p for p in REFERENCE
              if (p["model"], p["fit"]) == (info["model"], info["fit"])
              and (p["beta"], p["nu"], p["eps_star"]) == (info["beta"], info["nu"], info["eps_star"])
              and info["psi"][0] <= p["psi"] <= info["psi"][1] and info["theta"][0] <= p["theta"] <= info["theta"][1]
              and p["mu"] is not None and info["f_star"][0] <= p["f_star"] <= info["f_star"][1]]
    assert len(inside) >= 20
    mu = table.mu([p["psi"] for p in inside], [p["theta"] for p in inside], [p["f_star"] for p in inside])
    exact = np.array([p["mu"] for p in inside])
    assert np.max(np.abs(mu / exact - 1)) <= info["tolerance"]


def test_table_and_curves_against_kefric_eval(table):
    psi, theta = 2.0, 0.003
    rows = kefric("eval", "--psi", "2", "--theta", "0.003", "--f-star", "1e-5:0.1:13")
    # The CLI prints the F* its solution gives, a rounding off the range's ends.
    loads = np.clip([r["f_star"] for r in rows], *table.info["f_star"])
    exact = np.array([r["mu"] for r in rows])
    tol = table.info["tolerance"]
    assert np.max(np.abs(table.mu(psi, theta, loads) / exact - 1)) <= tol
    curve = table.curve(psi, theta)
    # A curve from the table: the table's error plus the curve's own.
    assert np.max(np.abs(curve.mu(loads) / exact - 1)) <= tol + curve.max_error
    from_model = kf.Curve.from_model(kf.Model(psi, theta), 1e-5, 0.1)
    assert np.max(np.abs(from_model.mu(loads) / exact - 1)) <= kf.CURVE_ACCURACY


def test_table_lookups_are_kefric_lookups(table, points):
    psi, theta, f = (a[:5] for a in points)
    for i in range(5):
        row = kefric("lookup", "--psi", repr(float(psi[i])), "--theta", repr(float(theta[i])), "--f-star", repr(float(f[i])))[0]
        mu, slope = table.mu_with_slope(psi[i], theta[i], f[i])
        assert mu == pytest.approx(row["mu"], rel=SAME_REL)
        assert slope == pytest.approx(row["dmu_df_star"], rel=SAME_REL)


def test_batches_are_bit_for_bit_the_scalar_lookups(table, points):
    psi, theta, f = points
    mu = table.mu(psi, theta, f)
    mu2, slope = table.mu_with_slope(psi, theta, f)
    scalar = [table.mu_with_slope(float(a), float(b), float(c)) for a, b, c in zip(psi, theta, f)]
    assert np.array_equal(mu, [s[0] for s in scalar])
    assert np.array_equal(mu2, mu)
    assert np.array_equal(slope, [s[1] for s in scalar])
    curve = table.curve(1.0, 0.003)
    cmu, cslope = curve.mu_with_slope(f)
    assert np.array_equal(curve.mu(f), cmu)
    assert np.array_equal(cmu, [curve.mu(float(x)) for x in f])
    assert np.array_equal(cslope, [curve.mu_with_slope(float(x))[1] for x in f])


def test_curve_from_model_is_within_its_accuracy(points):
    m = kf.Model(0.8, 0.002)
    c = kf.Curve.from_model(m, 1e-4, 0.05)
    assert c.range == (1e-4, 0.05)
    assert 0 < c.max_error <= kf.CURVE_ACCURACY
    loads = np.exp(np.random.default_rng(3).uniform(np.log(1e-4), np.log(0.05), 50))
    assert np.max(np.abs(c.mu(loads) / m.at_f_star(loads).mu - 1)) <= kf.CURVE_ACCURACY


def test_info_describes_the_default_table(table):
    info = table.info
    assert info["model"] == "ke" and info["fit"] == "consistent"
    assert info["psi"] == [0.5, 8.0] and info["theta"] == [0.0, 0.01] and info["f_star"] == [1e-5, 0.1]
    # Built with the library's default constants.
    assert {k: info[k] for k in kf.DEFAULTS} == dict(kf.DEFAULTS)
    accuracy = info["accuracy"]
    assert 0 < accuracy["p99_rel"] <= accuracy["max_rel"] <= info["tolerance"] == 1e-4
    assert accuracy["samples"] > 0 and len(accuracy["worst"]) == 3
    assert info["precision"] in ("f32", "f64") and isinstance(table.fast_kernel, bool)
    assert len(info["build"]["nodes"]) == 3 and info["build"]["generator"].startswith("ke-friction")
    assert info["bytes"] > 0 and isinstance(info["crc32"], int) and info["format_version"] >= 1
    info["psi"] = None  # a copy: the table is not changed
    info["accuracy"]["max_rel"] = None
    assert table.info["psi"] == [0.5, 8.0] and table.info["accuracy"]["max_rel"] > 0


def test_info_is_the_record_of_kefric_info_and_of_the_export(table, tmp_path):
    """One record of a table, one set of names: Table.info is what `kefric
    info --json` prints, and has the keys of a NumPy export's metadata."""
    cli = kefric("info")
    assert len(cli) == 1 and cli[0] == kf.Table.default().info == table.info
    npz = tmp_path / "default.npz"
    subprocess.run([KEFRIC, "export", "--quiet", "--npz", str(npz)], check=True, capture_output=True)
    with np.load(npz) as z:
        metadata = json.loads(z["metadata"].tobytes())
    assert set(metadata) == set(table.info)
    assert metadata == table.info


def test_model_defaults_and_params_are_the_librarys_records():
    assert set(kf.DEFAULTS) == {"beta", "nu", "eps_star", "fit", "model", "distribution", "skewness", "kurtosis"}
    assert (kf.DEFAULTS["distribution"], kf.DEFAULTS["skewness"], kf.DEFAULTS["kurtosis"]) == ("gaussian", 0.0, 3.0)
    with pytest.raises(TypeError):
        kf.DEFAULTS["beta"] = 1.0  # read-only
    p = kf.Model(1.0, 0.001).params
    assert list(p) == ["psi", "theta", "beta", "nu", "eps_star", "fit", "model", "distribution", "skewness",
                       "kurtosis"]
    assert p == {"psi": 1.0, "theta": 0.001, **kf.DEFAULTS}
    # A constant left out or None is the default; one given is kept.
    assert kf.Model(1.0, 0.001, beta=None, fit=None).params == p
    assert kf.Model(1.0, 0.001, nu=0.25, model="ceb").params == {**p, "nu": 0.25, "model": "ceb"}
    row = kefric("eval", "--psi", "1", "--theta", "0.001", "--f-star", "0.01")[0]
    assert {k: row[k] for k in p} == p


def test_params_from_physical_is_kefric_params():
    si = dict(e1=200e9, nu1=0.3, e2=200e9, nu2=0.3, hardness=2e9, sigma=100e-9, radius=10e-6, density=4e10,
              delta_gamma=0.3, epsilon=0.4e-9)
    p = kf.params_from_physical(**si)
    flags = [x for k, v in si.items() for x in ("--" + k.replace("_", "-"), repr(v))]
    row = kefric("params", *flags)[0]
    assert set(p) == set(row) == {"psi", "theta", "beta", "nu", "eps_star", "fit", "model", "distribution",
                                  "skewness", "kurtosis"}
    for key in ["psi", "theta", "beta", "nu", "eps_star"]:
        assert p[key] == pytest.approx(row[key], rel=SAME_REL), key
    assert (p["fit"], p["model"]) == (row["fit"], row["model"]) == (kf.DEFAULTS["fit"], kf.DEFAULTS["model"])
    assert kf.Model(**p).at_f_star(0.01).mu > 0


def test_a_lookup_for_a_model_refuses_constants_the_table_was_not_built_for():
    # Issue 38: psi, theta of a surface whose beta is 0.117 and whose
    # heights are Pearson are answered by Table.mu with the table's
    # constants (a wrong mu, silently); Table.mu_for checks them.
    t = kf.Table.default()
    assert t.mu_for(kf.Model(1.0, 0.001), 2e-4) == t.mu(1.0, 0.001, 2e-4)
    f = np.array([1e-4, 1e-3, 1e-2])
    assert np.array_equal(t.mu_for(kf.Model(2.0, 0.003), f), t.mu(2.0, 0.003, f))
    measured = kf.Model(1.0, 0.001, beta=0.117, distribution="pearson", skewness=0.3, kurtosis=3.5)
    with pytest.raises(ValueError, match=r"^beta = 0\.117, but the table holds beta = 0\.04"):
        t.mu_for(measured, 2e-4)
    with pytest.raises(ValueError, match=r"^distribution = pearson \(skewness 0\.3, kurtosis 3\.5\), but the table "
                                         r"holds distribution = gaussian"):
        t.mu_for(kf.Model(1.0, 0.001, distribution="pearson", skewness=0.3, kurtosis=3.5), 2e-4)
    with pytest.raises(ValueError, match=r"^fit = as-printed, but the table holds fit = consistent"):
        t.mu_for(kf.Model(1.0, 0.001, fit="as-printed"), 2e-4)
    # The same for a curve from the table.
    f = np.array([1e-4, 1e-3, 1e-2])
    assert np.array_equal(t.curve_for(kf.Model(1.0, 0.001)).mu(f), t.curve(1.0, 0.001).mu(f))
    with pytest.raises(ValueError, match=r"^beta = 0\.117, but the table holds beta = 0\.04"):
        t.curve_for(measured)
    with pytest.raises(TypeError, match="model must be a ke_friction.Model"):
        t.curve_for((1.0, 0.001))
    with pytest.raises(TypeError, match="model must be a ke_friction.Model"):
        t.mu_for((1.0, 0.001), 2e-4)
