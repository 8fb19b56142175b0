"""Tests of the Python package ke_friction: values, shapes, errors, threads."""

import json
import math
import os
import pathlib
import shutil
import subprocess
import threading

import numpy as np
import pytest

import ke_friction as kf

ROOT = pathlib.Path(__file__).resolve().parents[2]
REFERENCE = [p for p in json.loads((ROOT / "tests" / "data" / "reference_points.json").read_text())["points"] if "mode" in p]
KEFRIC = os.environ.get("KEFRIC", str(ROOT / "target" / "release" / "kefric"))


def kefric(*args):
    if not os.path.exists(KEFRIC):
        pytest.skip(f"{KEFRIC} is not built")
    out = subprocess.run([KEFRIC, *args], check=True, capture_output=True, text=True).stdout
    return [json.loads(line) for line in out.splitlines()]


@pytest.fixture(scope="module")
def table():
    return kf.Table.default()


# -- values ---------------------------------------------------------------


@pytest.mark.parametrize("p", REFERENCE, ids=lambda p: f"{p['model']}-{p['fit']}-{p['mode']}-{p['psi']:.3g}")
def test_model_matches_the_mpmath_reference(p):
    m = kf.Model(p["psi"], p["theta"], beta=p["beta"], nu=p["nu"], eps_star=p["eps_star"], fit=p["fit"] or "consistent",
                 model=p["model"])
    c = m.at_h_star(p["h_star"]) if p["mode"] == "h" else m.at_f_star(p["f_star"])
    for key in ["h_star", "p_star", "fs_star", "q_star", "f_star"]:
        assert getattr(c, key) == pytest.approx(p[key], rel=1e-9, abs=1e-300), key
    if p["mu"] is None or not p["f_star"] > 0:
        assert math.isnan(c.mu)
    else:
        assert c.mu == pytest.approx(p["mu"], rel=1e-9)


def test_model_md_reference_value():
    # MODEL.md section 7: mu = 0.52521087083 at psi = 1, theta = 0.001, F* = 0.01.
    c = kf.Model(1.0, 0.001).at_f_star(0.01)
    assert isinstance(c.mu, float)
    assert c.mu == pytest.approx(0.52521087083, abs=1e-10)
    assert c.h_star == pytest.approx(1.4692414618, abs=1e-10)


def test_table_and_curves_against_kefric_eval(table):
    psi, theta = 2.0, 0.003
    loads = [1e-4, 1e-3, 1e-2, 5e-2]
    exact = np.array([kefric("eval", "--json", "--psi", str(psi), "--theta", str(theta), "--f-star", repr(f))[0]["mu"]
                      for f in loads])
    tol = table.info["tolerance"]
    assert np.all(np.abs(table.mu(psi, theta, loads) / exact - 1) <= tol)
    assert np.all(np.abs(table.curve(psi, theta).mu(loads) / exact - 1) <= tol)
    c = kf.Curve.from_model(kf.Model(psi, theta), 1e-4, 5e-2)
    assert np.all(np.abs(c.mu(loads) / exact - 1) <= kf.CURVE_ACCURACY)
    # The table's lookups are exactly kefric lookup's.
    row = kefric("lookup", "--json", "--psi", "2", "--theta", "0.003", "--f-star", "0.01")[0]
    assert table.mu_with_slope(2.0, 0.003, 0.01) == (row["mu"], row["dmu_df_star"])


def test_info_describes_the_default_table(table):
    info = table.info
    assert info["model"] == "ke" and info["fit"] == "consistent"
    assert info["psi"] == (0.5, 8.0) and info["theta"] == (0.0, 0.01) and info["f_star"] == (1e-5, 0.1)
    assert (info["beta"], info["nu"], info["eps_star"]) == (0.04, 0.3, 0.004)
    assert 0 < info["max_rel_error"] <= info["tolerance"] == 1e-4


def test_params_from_physical_feeds_the_model():
    p = kf.params_from_physical(e1=200e9, nu1=0.3, e2=200e9, nu2=0.3, hardness=2e9, sigma=100e-9,
                                radius=10e-6, density=4e10, delta_gamma=0.3, epsilon=0.4e-9)
    assert p["theta"] == pytest.approx(0.0015) and p["beta"] == pytest.approx(0.04)
    assert p["psi"] == pytest.approx(5.6745, abs=1e-4)
    assert kf.Model(**p).at_f_star(0.01).mu > 0
    with pytest.raises(ValueError, match="hardness = -1 is out of range"):
        kf.params_from_physical(e1=200e9, nu1=0.3, e2=200e9, nu2=0.3, hardness=-1.0, sigma=100e-9,
                                radius=10e-6, density=4e10, delta_gamma=0.3, epsilon=0.4e-9)


# -- shapes ---------------------------------------------------------------


def test_scalars_give_floats_and_arrays_broadcast(table):
    assert type(table.mu(1.0, 0.001, 0.01)) is float
    assert type(table.mu(1, 0, 1e-3)) is float
    zero_d = table.mu(np.array(1.0), 0.001, 0.01)
    assert isinstance(zero_d, np.ndarray) and zero_d.shape == ()
    psi = np.array([0.5, 1.0, 2.0])
    f = np.array([[1e-4], [1e-3]])
    out = table.mu(psi, 0.003, f)
    assert out.shape == (2, 3) and out.dtype == np.float64
    for i in range(2):
        for j in range(3):
            assert out[i, j] == table.mu(float(psi[j]), 0.003, float(f[i, 0]))
    mu, slope = table.mu_with_slope(psi, [0.003], f)
    assert mu.shape == slope.shape == (2, 3)
    assert np.array_equal(mu, out) and np.all(slope < 0)
    # Other dtypes and strides are converted; lists work.
    ints = table.mu(np.array([1, 2], dtype=np.int32), 0.0, [0.01, 0.02])
    assert np.array_equal(ints, table.mu([1.0, 2.0], 0.0, [0.01, 0.02]))
    strided = np.linspace(0.5, 8, 20)[::3]
    assert np.array_equal(table.mu(strided, 0.001, 0.01), table.mu(strided.copy(), 0.001, 0.01))
    # The model and curves broadcast the same way.
    c = kf.Model(1.0, 0.001).at_h_star(np.array([[0.0, 1.0], [2.0, 3.0]]))
    assert c.mu.shape == (2, 2)
    curve = table.curve(1.0, 0.001)
    assert curve.mu(np.full((3, 4), 0.01)).shape == (3, 4)
    assert type(curve.mu(0.01)) is float


def test_empty_input(table):
    assert table.mu(np.array([]), 0.001, 0.01).shape == (0,)


# -- errors ---------------------------------------------------------------


def test_out_of_domain_names_argument_value_index_and_range(table):
    with pytest.raises(ValueError, match=r"^psi = 9 is outside the range \[0.5, 8\]$"):
        table.mu(9.0, 0.001, 0.01)
    with pytest.raises(ValueError, match=r"f_star = 0.2 is outside the range \[1e-5, 0.1\] \(at index \(1, 0\)\)"):
        table.mu(1.0, 0.001, [[0.01], [0.2]])
    with pytest.raises(ValueError, match=r"theta = NaN .*\(at index \(2,\)\)"):
        table.mu(1.0, [0.0, 0.001, np.nan], 0.01)
    out = table.mu([1.0, 9.0, 2.0], 0.001, 0.01, out_of_domain="nan")
    assert math.isnan(out[1]) and out[0] == table.mu(1.0, 0.001, 0.01) and out[2] > 0
    assert math.isnan(table.mu(9.0, 0.001, 0.01, out_of_domain="nan"))
    mu, slope = table.mu_with_slope([1.0, 9.0], 0.001, 0.01, out_of_domain="nan")
    assert math.isnan(mu[1]) and math.isnan(slope[1]) and mu[0] > 0
    curve = table.curve(1.0, 0.001)
    with pytest.raises(ValueError, match=r"f_star = 1 is outside the range \[1e-5, 0.1\] \(at index \(1,\)\)"):
        curve.mu([0.01, 1.0])
    assert math.isnan(curve.mu([0.01, 1.0], out_of_domain="nan")[1])
    with pytest.raises(ValueError, match="out_of_domain"):
        table.mu(1.0, 0.001, 0.01, out_of_domain="clip")
    with pytest.raises(ValueError, match="do not broadcast"):
        table.mu([1.0, 2.0], [0.0, 0.001, 0.002], 0.01)
    with pytest.raises(ValueError, match=r"f_star = -1 is out of range"):
        kf.Model(1.0, 0.001).at_f_star(-1.0)
    assert math.isnan(kf.Model(1.0, 0.001).at_f_star([0.01, -1.0], out_of_domain="nan").mu[1])


def test_bad_parameters_and_types():
    with pytest.raises(ValueError, match=r"psi = -1 is out of range"):
        kf.Model(-1.0, 0.001)
    with pytest.raises(ValueError, match="fit"):
        kf.Model(1.0, 0.001, fit="printed")
    with pytest.raises(ValueError, match="f_star_min < f_star_max"):
        kf.Curve.from_model(kf.Model(1.0, 0.001), 1e-2, 1e-4)
    t = kf.Table.default()
    for bad in ["1.0", None, [1.0, "x"], {"a": 1}]:
        with pytest.raises(TypeError):
            t.mu(bad, 0.001, 0.01)
    with pytest.raises(TypeError):
        t.mu(True, 0.001, 0.01)
    with pytest.raises(TypeError):
        kf.Model("1", 0.001)
    with pytest.raises(TypeError):
        kf.Curve.from_model("model", 1e-4, 1e-2)
    with pytest.raises(TypeError):
        kf.Table.load(3)


def test_loading_tables(tmp_path):
    good = tmp_path / "good.kft"
    shutil.copy(ROOT / "tables" / "default.kft", good)
    t = kf.Table.load(good)
    assert t.mu(1.0, 0.001, 0.01) == kf.Table.default().mu(1.0, 0.001, 0.01)
    with pytest.raises(OSError):
        kf.Table.load(tmp_path / "missing.kft")
    data = bytearray(good.read_bytes())
    data[len(data) // 2] ^= 0x10
    bad = tmp_path / "bad.kft"
    bad.write_bytes(bytes(data))
    with pytest.raises(ValueError, match="checksum"):
        kf.Table.load(bad)


# -- threads and docs -----------------------------------------------------


def test_many_threads_share_one_table_and_one_curve(table):
    curve = table.curve(1.0, 0.003)
    rng = np.random.default_rng(1)
    psi = rng.uniform(0.5, 8, 20000)
    f = np.exp(rng.uniform(np.log(1e-5), np.log(0.1), 20000))
    want_t, want_c = table.mu(psi, 0.003, f), curve.mu(f)
    errors = []

    def work():
        try:
            for _ in range(20):
                assert np.array_equal(table.mu(psi, 0.003, f), want_t)
                assert np.array_equal(curve.mu(f), want_c)
        except Exception as e:  # noqa: BLE001 (reported below)
            errors.append(e)

    threads = [threading.Thread(target=work) for _ in range(4)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert not errors, errors


def test_everything_public_is_documented():
    for name in kf.__all__:
        obj = getattr(kf, name)
        if callable(obj):
            assert obj.__doc__ and len(obj.__doc__) > 40, name
    for cls in [kf.Table, kf.Curve, kf.Model]:
        for attr, value in vars(cls).items():
            if not attr.startswith("_"):
                doc = getattr(value, "__doc__", None) or getattr(getattr(value, "__func__", None), "__doc__", None)
                assert doc, f"{cls.__name__}.{attr}"
    assert "psi" in kf.Table.mu.__doc__ and "out_of_domain" in kf.Table.mu.__doc__
    pkg = pathlib.Path(kf.__file__).parent
    assert (pkg / "py.typed").exists() and (pkg / "_core.pyi").exists()
