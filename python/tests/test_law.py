"""FrictionLaw: mu(p) and dmu/dp in SI against direct integration (the
model at F* = p/H) and a finite difference, NumPy shapes, the out-of-range
policies and open contacts, pickling, threads, solver-ready tables."""

import copy
import os
import pickle
import threading

import numpy as np
import pytest

import ke_friction as kf

#: The law's curve against direct integration: CURVE_ACCURACY (1e-6), with
#: the model's own error (1e-9) on top.
LAW_REL = kf.CURVE_ACCURACY + 1e-9
#: dmu/dp of the curve's cubic against a central difference of the model
#: (step 1e-4 p: truncation ~1e-8, the cubic's slope error ~1e-5).
SLOPE_REL = 1e-4


@pytest.fixture(scope="module")
def law():
    return kf.FrictionLaw(1.0, 0.001, hardness=1e9)


@pytest.fixture(scope="module")
def model():
    return kf.Model(1.0, 0.001)


def test_mu_is_the_model_at_p_over_h(law, model):
    # MODEL.md §7: psi = 1, theta = 0.001, F* = 0.01: mu = 0.52521087083.
    assert abs(law.mu(1e7) / 0.52521087083 - 1) < LAW_REL
    p = np.geomspace(1.1e4, 0.99e8, 37)
    exact = model.at_f_star(p / 1e9).mu
    assert np.max(np.abs(law.mu(p) / exact - 1)) < LAW_REL
    assert law.max_error <= kf.CURVE_ACCURACY
    assert law.range == (1e4, 1e8) and law.hardness == 1e9 and law.out_of_range == "clamp"
    assert law.params == model.params


def test_dmu_dp_matches_a_finite_difference_of_the_model(law, model):
    p = np.geomspace(2e4, 5e7, 11)
    mu, dmu = law.mu_and_derivative(p)
    h = 1e-4 * p
    fd = (model.at_f_star((p + h) / 1e9).mu - model.at_f_star((p - h) / 1e9).mu) / (2 * h)
    assert np.max(np.abs(dmu / fd - 1)) < SLOPE_REL
    assert np.all(dmu < 0)  # mu falls with the load (MODEL.md §7)
    assert np.array_equal(mu, law.mu(p))


def test_arrays_keep_their_shape_and_floats_stay_floats(law):
    p = np.geomspace(1e5, 1e7, 12).reshape(3, 1, 4)
    mu = law.mu(p)
    assert mu.shape == (3, 1, 4) and mu.dtype == np.float64
    assert mu[1, 0, 2] == law.mu(float(p[1, 0, 2]))
    m, d = law.mu_and_derivative(p.tolist())
    assert m.shape == d.shape == (3, 1, 4)
    assert type(law.mu(1e6)) is float and type(law.mu(np.float32(1e6))) is float
    assert isinstance(law.mu_and_derivative(10 ** 6), tuple)
    # A Fortran-ordered, non-contiguous view.
    q = np.asfortranarray(np.geomspace(1e5, 1e7, 20).reshape(4, 5))[:, ::2]
    assert np.array_equal(law.mu(q), np.array([[law.mu(float(x)) for x in row] for row in q]))
    assert law.mu(np.empty((0, 3))).shape == (0, 3)
    with pytest.raises(TypeError, match="pressure"):
        law.mu(np.array(["1e6"]))


def test_clamp_gives_the_ends_and_counts_them():
    law = kf.FrictionLaw(1.0, 0.001, hardness=1e9, pressure_range=(1e5, 1e7))
    assert law.clamped == 0
    lo, hi = law.mu(1e5), law.mu(1e7)
    mu, dmu = law.mu_and_derivative(np.array([1e3, 5e4, 1e6, 2e7, 1e9]))
    assert mu[0] == mu[1] == lo and mu[3] == mu[4] == hi
    assert dmu[0] == dmu[1] == dmu[3] == dmu[4] == 0.0 and dmu[2] < 0
    assert law.clamped == 4
    assert law.mu(1e9) == hi and law.clamped == 5
    assert law.reset_clamped() == 5 and law.clamped == 0


def test_error_policy_names_the_pressure_and_the_range():
    law = kf.FrictionLaw(1.0, 0.001, hardness=1e9, pressure_range=(1e5, 1e7), out_of_range="error")
    with pytest.raises(ValueError, match=r"pressure = 2e7 Pa .*\[100000, 1e7\] Pa"):
        law.mu(2e7)
    with pytest.raises(ValueError, match=r"at index \(1, 0\)"):
        law.mu([[1e6], [2e7]])
    mu = law.mu([1e6, 2e7, 1e4], out_of_domain="nan")
    assert np.isfinite(mu[0]) and np.isnan(mu[1:]).all()
    assert law.clamped == 0


@pytest.mark.parametrize("p", [0.0, -1e6, float("nan"), float("-inf")])
def test_an_open_contact_is_never_a_number(law, p):
    with pytest.raises(ValueError, match="pressure"):
        law.mu(p)
    with pytest.raises(ValueError, match="pressure"):
        law.mu_and_derivative(np.array([1e6, p]))
    assert np.isnan(law.mu(p, out_of_domain="nan"))
    mu, dmu = law.mu_and_derivative(np.array([p, 1e6]), out_of_domain="nan")
    assert np.isnan(mu[0]) and np.isnan(dmu[0]) and np.isfinite(mu[1])


def test_bad_construction_names_the_input():
    with pytest.raises(ValueError, match="hardness"):
        kf.FrictionLaw(1.0, 0.001, hardness=-1.0)
    with pytest.raises(ValueError, match="pressure range"):
        kf.FrictionLaw(1.0, 0.001, hardness=1e9, pressure_range=(1e7, 1e5))
    with pytest.raises(ValueError, match="out_of_range"):
        kf.FrictionLaw(1.0, 0.001, hardness=1e9, out_of_range="wrap")
    with pytest.raises(ValueError, match="psi"):
        kf.FrictionLaw(-1.0, 0.001, hardness=1e9)
    with pytest.raises(TypeError, match="pressure_range"):
        kf.FrictionLaw(1.0, 0.001, hardness=1e9, pressure_range=1e5)
    with pytest.raises(TypeError, match="hardness"):
        kf.FrictionLaw(1.0, 0.001, hardness="1e9")
    with pytest.raises(TypeError, match="model"):
        kf.FrictionLaw.from_model("ke", 1e9)


def test_the_other_constructors_agree_with_the_model_they_make():
    si = dict(e1=200e9, nu1=0.3, e2=200e9, nu2=0.3, hardness=2e9, sigma=1e-7, radius=1e-5, density=4e10,
              delta_gamma=0.5, epsilon=4e-10)
    law = kf.FrictionLaw.from_physical(**si)
    p = kf.params_from_physical(**si)
    model = kf.Model(p["psi"], p["theta"], p["beta"], p["nu"], p["eps_star"])
    assert law.hardness == 2e9 and law.params == model.params
    assert abs(law.mu(2e6) / model.at_f_star(1e-3).mu - 1) < LAW_REL
    m = kf.Model(2.0, 0.003, beta=0.1, distribution="pearson", skewness=0.3, kurtosis=3.5)
    law = kf.FrictionLaw.from_model(m, 5e8, pressure_range=(1e3, 1e7), out_of_range="error")
    assert abs(law.mu(1e5) / m.at_f_star(2e-4).mu - 1) < LAW_REL
    assert law.params["skewness"] == 0.3


def test_a_law_pickles_as_it_was_made(law):
    m = kf.Model(2.0, 0.003, distribution="pearson", skewness=0.3, kurtosis=3.5)
    other = kf.FrictionLaw.from_model(m, 5e8, pressure_range=(1e3, 1e7), out_of_range="error")
    p = np.geomspace(1.5e4, 9e6, 50)
    for original in (law, other):
        for copied in [pickle.loads(pickle.dumps(original, protocol=k)) for k in range(pickle.HIGHEST_PROTOCOL + 1)] + [
                copy.copy(original), copy.deepcopy(original)]:
            assert copied.range == original.range and copied.hardness == original.hardness
            assert copied.out_of_range == original.out_of_range and copied.params == original.params
            for a, b in zip(copied.mu_and_derivative(p), original.mu_and_derivative(p)):
                assert np.array_equal(a, b)
    assert "FrictionLaw" in repr(law) and "ke_friction" in pickle.dumps(law).decode("latin-1")


def test_threads_give_the_same_answers_and_count_every_clamp():
    law = kf.FrictionLaw(1.0, 0.001, hardness=1e9, pressure_range=(1e5, 1e7))
    rng = np.random.default_rng(38)
    p = 10 ** rng.uniform(4, 8, 600_000)
    outside = int(np.sum((p < 1e5) | (p > 1e7)))
    one = law.mu(p)
    law.reset_clamped()
    assert np.array_equal(law.mu(p, threads=None), one)
    assert law.clamped == outside
    law.reset_clamped()
    results = [None] * 4

    def work(i):
        results[i] = law.mu_and_derivative(p[i::4])

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for i, (mu, _) in enumerate(results):
        assert np.array_equal(mu, one[i::4])
    assert law.clamped == outside


def test_a_table_interpolates_within_its_stated_error(law, model):
    t = law.table(1e4, 1e8)
    p, mu, dmu = t["pressure"], t["mu"], t["dmu_dp"]
    assert p[0] == 1e4 and p[-1] == 1e8 and 0 < t["interpolation_error"] <= 1e-3
    assert np.array_equal(mu, law.mu(p)) and np.array_equal(dmu, law.mu_and_derivative(p)[1])
    mid = (p[1:] + p[:-1]) / 2
    exact = model.at_f_star(mid / 1e9).mu
    assert np.max(np.abs(np.interp(mid, p, mu) / exact - 1)) <= t["interpolation_error"] + 2 * LAW_REL
    nine = law.table(1e4, 1e8, rows=9)
    assert len(nine["pressure"]) == 9 and nine["interpolation_error"] > 1e-3
    fine = law.table(tolerance=1e-4)
    assert len(fine["pressure"]) > len(p) and fine["interpolation_error"] <= 1e-4
    with pytest.raises(ValueError, match="pressure range"):
        law.table(1e3, 1e8)
    with pytest.raises(ValueError, match="rows"):
        law.table(rows=1)
    with pytest.raises(ValueError, match="rows"):
        law.table(rows=-3)
    with pytest.raises(ValueError, match="tolerance"):
        law.table(tolerance=0.0)


def test_from_surface_is_the_surfaces_model_at_p_over_h():
    # A smooth synthetic map (the CLI's surface tests' shape), dx = 2 um.
    n = 64
    y, x = np.mgrid[0:n, 0:n].astype(float)
    w = np.sin(0.31 * x + 0.7) + np.cos(0.23 * y) + 0.7 * np.sin(0.17 * x - 0.29 * y + 0.7) \
        + 0.5 * np.cos(0.41 * x + 0.37 * y)
    s = kf.Surface.from_heights(0.2e-6 * (w + 0.15 * w * w), 2e-6)
    materials = dict(e1=70e9, nu1=0.33, e2=200e9, nu2=0.31, hardness=1e9, delta_gamma=0.5, epsilon=0.4e-9)
    law = kf.FrictionLaw.from_surface(s, **materials, pressure_range=(1e5, 1e7))
    model = s.model(**materials)
    assert law.params == model.params and law.hardness == 1e9
    p = np.array([1e5, 1e6, 1e7])
    assert np.max(np.abs(law.mu(p) / model.at_f_star(p / 1e9).mu - 1)) < LAW_REL


def test_a_table_in_a_solvers_syntax_and_a_csv_numpy_and_pandas_read():
    import io
    law = kf.FrictionLaw(1.0, 0.001, hardness=1e9, pressure_range=(1e4, 1e8))
    t = law.table(1e4, 1e8)
    csv = law.table(1e4, 1e8, format="csv")
    # NumPy's genfromtxt with names, and pandas' defaults, read it (no
    # comment line that holds commas).
    a = np.genfromtxt(io.StringIO(csv), names=True, delimiter=",")
    assert a.dtype.names == ("pressure_Pa", "mu", "dmu_dp_per_Pa")
    assert np.array_equal(a["pressure_Pa"], t["pressure"]) and np.array_equal(a["mu"], t["mu"])
    assert np.array_equal(a["dmu_dp_per_Pa"], t["dmu_dp"])
    try:
        import pandas as pd
    except ImportError:
        # CI installs pandas and sets KEF_REQUIRE_PANDAS: there it must run.
        assert not os.environ.get("KEF_REQUIRE_PANDAS"), "pandas is missing"
        pd = None
    if pd is not None:
        f = pd.read_csv(io.StringIO(csv))
        assert list(f.columns) == ["pressure_Pa", "mu", "dmu_dp_per_Pa"]
        assert np.array_equal(f["mu"].to_numpy(), t["mu"])
    mpa = np.genfromtxt(io.StringIO(law.table(1e4, 1e8, format="csv", stress_unit="MPa")), names=True, delimiter=",")
    assert np.array_equal(mpa["pressure_MPa"], t["pressure"] / 1e6)
    assert np.array_equal(mpa["dmu_dp_per_MPa"], t["dmu_dp"] * 1e6)
    moose = law.table(1e4, 1e8, format="moose", stress_unit="MPa")
    assert "axis = x" in moose and "function_friction = kef_mu" in moose and "# units: pressure MPa" in moose
    abaqus = law.table(1e4, 1e8, format="abaqus")
    assert "*FRICTION" in abaqus and "psi = 1, theta = 0.001" in abaqus
    with pytest.raises(ValueError, match="format 'ansys' is unknown: must be one of csv, abaqus"):
        law.table(format="ansys")
    with pytest.raises(ValueError, match="stress unit 'kPa' is unknown"):
        law.table(format="csv", stress_unit="kPa")
    with pytest.raises(TypeError):
        law.table(format=3)
