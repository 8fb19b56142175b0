"""Errors: ValueError naming the argument, value, index and range; NaN mode;
TypeError for wrong types; nothing panics."""

import math
import pathlib

import numpy as np
import pytest

import ke_friction as kf


def test_out_of_domain_names_argument_value_index_and_range(table):
    with pytest.raises(ValueError, match=r"^psi = 9 is outside the range \[0.5, 8\]$"):
        table.mu(9.0, 0.001, 0.01)
    with pytest.raises(ValueError, match=r"^f_star = 0.2 is outside the range \[1e-5, 0.1\] \(at index \(1, 0\)\)$"):
        table.mu(1.0, 0.001, [[0.01], [0.2]])
    with pytest.raises(ValueError, match=r"^theta = NaN is outside the range \[0, 0.01\] \(at index \(2,\)\)$"):
        table.mu(1.0, [0.0, 0.001, np.nan], 0.01)
    with pytest.raises(ValueError, match=r"psi = -1 .*\(at index \(1, 2\)\)"):
        table.mu_with_slope([[1.0, 1.0, 1.0], [1.0, 1.0, -1.0]], 0.001, 0.01)
    # The index is in the broadcast shape, not in the argument's own.
    with pytest.raises(ValueError, match=r"f_star = 1 .*\(at index \(3, 0\)\)"):
        table.mu([[1.0, 2.0]], 0.001, [[0.01], [0.01], [0.01], [1.0]])
    curve = table.curve(1.0, 0.001)
    with pytest.raises(ValueError, match=r"^f_star = 1 is outside the range \[1e-5, 0.1\] \(at index \(1,\)\)$"):
        curve.mu([0.01, 1.0])
    with pytest.raises(ValueError, match=r"^f_star = 0 is outside the range"):
        curve.mu_with_slope(0.0)


def test_the_first_bad_element_is_reported(table):
    f = np.full(1000, 0.01)
    f[[517, 700]] = [5.0, np.nan]
    with pytest.raises(ValueError, match=r"f_star = 5 .*\(at index \(517,\)\)"):
        table.mu(2.0, 0.001, f)
    with pytest.raises(ValueError, match=r"f_star = 5 .*\(at index \(517,\)\)"):
        table.mu_with_slope(2.0, 0.001, f)


def test_nan_mode_gives_nan_exactly_at_the_bad_elements(table, points):
    psi, theta, f = (a.copy() for a in points)
    rng = np.random.default_rng(5)
    bad = np.zeros(psi.size, bool)
    bad[rng.choice(psi.size, 300, replace=False)] = True
    bad[[0, 7, 8, 255, 256, 257, psi.size - 1]] = True  # ends, SIMD blocks and chunks
    which = rng.integers(0, 3, psi.size)
    psi[bad & (which == 0)] = 9.0
    theta[bad & (which == 1)] = np.nan
    f[bad & (which == 2)] = -1e-3
    good = table.mu(psi[~bad], theta[~bad], f[~bad])
    mu = table.mu(psi, theta, f, out_of_domain="nan")
    mu2, slope = table.mu_with_slope(psi, theta, f, out_of_domain="nan")
    assert np.array_equal(np.isnan(mu), bad) and np.array_equal(mu[~bad], good)
    assert np.array_equal(np.isnan(mu2), bad) and np.array_equal(np.isnan(slope), bad)
    assert np.array_equal(mu2[~bad], good)
    assert np.array_equal(slope[~bad], table.mu_with_slope(psi[~bad], theta[~bad], f[~bad])[1])
    assert math.isnan(table.mu(9.0, 0.001, 0.01, out_of_domain="nan"))
    assert all(math.isnan(x) for x in table.mu_with_slope(1.0, -1.0, 0.01, out_of_domain="nan"))
    curve = table.curve(1.0, 0.001)
    loads = np.where(bad, np.where(which == 0, 1.0, np.nan), f)
    cmu = curve.mu(loads, out_of_domain="nan")
    cmu2, cslope = curve.mu_with_slope(loads, out_of_domain="nan")
    assert np.array_equal(np.isnan(cmu), bad) and np.array_equal(np.isnan(cslope), bad)
    assert np.array_equal(cmu[~bad], curve.mu(f[~bad])) and np.array_equal(cmu2[~bad], cmu[~bad])
    all_bad = table.mu(np.full(20, 20.0), 0.001, 0.01, out_of_domain="nan")
    assert np.isnan(all_bad).all()


def test_the_model_reports_and_skips_bad_loads():
    m = kf.Model(1.0, 0.001)
    with pytest.raises(ValueError, match=r"^f_star = -1 is out of range: must be > 0 and finite$"):
        m.at_f_star(-1.0)
    with pytest.raises(ValueError, match=r"f_star = 0 is out of range.*\(at index \(1,\)\)"):
        m.at_f_star([0.01, 0.0])
    with pytest.raises(ValueError, match=r"^h_star = inf is out of range"):
        m.at_h_star(math.inf)
    c = m.at_f_star([0.01, -1.0, math.nan], out_of_domain="nan")
    assert c.mu[0] > 0 and np.isnan(c.mu[1:]).all() and np.isnan(c.h_star[1:]).all()
    # mu is NaN where F* <= 0 (no error: the contact exists, mu does not).
    far = m.at_h_star(6.0)
    assert far.f_star < 0 and math.isnan(far.mu) and far.p_star > 0


def test_bad_parameters_name_themselves():
    with pytest.raises(ValueError, match=r"^psi = -1 is out of range"):
        kf.Model(-1.0, 0.001)
    with pytest.raises(ValueError, match=r"beta = 0.01 is out of range"):
        kf.Model(1.0, 0.001, beta=0.01)
    with pytest.raises(ValueError, match=r"^fit 'printed' is unknown: must be one of consistent, as-printed$"):
        kf.Model(1.0, 0.001, fit="printed")
    with pytest.raises(ValueError, match=r"^model 'CEB' is unknown: must be one of ke, ceb"):
        kf.Model(1.0, 0.001, model="CEB")
    with pytest.raises(ValueError, match="f_star_min < f_star_max"):
        kf.Curve.from_model(kf.Model(1.0, 0.001), 1e-2, 1e-4)
    with pytest.raises(ValueError, match=r"psi = 100 is outside the range \[0.5, 8\]"):
        kf.Table.default().curve(100.0, 0.001)
    with pytest.raises(ValueError, match="hardness = -1 is out of range"):
        kf.params_from_physical(e1=200e9, nu1=0.3, e2=200e9, nu2=0.3, hardness=-1.0, sigma=100e-9,
                                radius=10e-6, density=4e10, delta_gamma=0.3, epsilon=0.4e-9)
    with pytest.raises(ValueError, match="out_of_domain"):
        kf.Table.default().mu(1.0, 0.001, 0.01, out_of_domain="clip")
    with pytest.raises(ValueError, match=r"do not broadcast: psi \(2,\), theta \(3,\), f_star \(\)"):
        kf.Table.default().mu([1.0, 2.0], [0.0, 0.001, 0.002], 0.01)


@pytest.mark.parametrize("bad", ["1.0", None, [1.0, "x"], {"a": 1}, True, np.array([True]), 1j, [1j],
                                 object(), np.array(["a"]), [[1.0], [2.0, 3.0]]])
def test_wrong_types_raise_type_error(table, bad):
    with pytest.raises((TypeError, ValueError)) as e:
        table.mu(bad, 0.001, 0.01)
    ragged = isinstance(bad, list) and len(bad) == 2 and isinstance(bad[0], list)
    assert e.type is (ValueError if ragged else TypeError)  # NumPy calls a ragged list a ValueError
    if e.type is TypeError:
        assert "psi" in str(e.value)


def test_wrong_types_elsewhere_raise_type_error(table):
    with pytest.raises(TypeError, match="f_star"):
        table.curve(1.0, 0.001).mu("0.01")
    with pytest.raises(TypeError, match="psi"):
        kf.Model("1", 0.001)
    with pytest.raises(TypeError, match="fit"):
        kf.Model(1.0, 0.001, fit=3)  # (None is the default)
    with pytest.raises(TypeError, match="beta"):
        kf.Model(1.0, 0.001, beta="0.04")
    with pytest.raises(TypeError, match="h_star"):
        kf.Model(1.0, 0.001).at_h_star(None)
    with pytest.raises(TypeError, match="model"):
        kf.Curve.from_model("model", 1e-4, 1e-2)
    with pytest.raises(TypeError, match="psi"):
        table.curve([1.0], 0.001)
    with pytest.raises(TypeError, match="path"):
        kf.Table.load(3)
    with pytest.raises(TypeError, match="sigma"):
        kf.params_from_physical(e1=200e9, nu1=0.3, e2=200e9, nu2=0.3, hardness=2e9, sigma="100e-9",
                                radius=10e-6, density=4e10, delta_gamma=0.3, epsilon=0.4e-9)


def test_the_native_layer_rejects_mismatched_arrays_without_panicking(table):
    core = table._core
    a, b = np.ones(3), np.ones(4)
    with pytest.raises(ValueError, match="theta has 4 elements, not 3 or 1"):
        core.mu_into(a, b, a, np.empty(3), False, 0)
    with pytest.raises(ValueError, match="slope has 4 elements, not 3"):
        core.mu_with_slope_into(a, a, a, np.empty(3), np.empty(4), False, 0)
    with pytest.raises(ValueError, match="psi has 4 elements, not 3 or 1"):
        core.mu_with_slope_into(b, a, a, np.empty(3), np.empty(3), False, 0)
    with pytest.raises(ValueError, match="must be contiguous"):
        core.mu_into(np.ones(6)[::2], a, a, np.empty(3), False, 0)
    with pytest.raises(ValueError, match="out has 3 elements, not 14"):
        kf.Model(1.0, 0.001)._core.contacts_into(np.ones(2), False, np.empty(3), False, 0)
    with pytest.raises(TypeError):
        core.mu_into(a.astype(np.float32), a, a, np.empty(3), False, 0)


def test_the_native_layer_raises_by_error_kind_with_the_flat_index(table):
    """The native layer maps the library's error kinds to exceptions in one
    place and hands the bad element's flat index on as ``index``; in NaN
    mode it returns how many elements are NaN (the library's count)."""
    core = table._core
    f = np.full(600, 0.01)
    f[[5, 300, 599]] = [0.5, np.nan, -1.0]
    one = np.ones(1)
    with pytest.raises(ValueError, match=r"^f_star = 0.5 is outside the range \[1e-5, 0.1\]$") as e:
        core.mu_into(one, one * 0.001, f, np.empty(600), False, 1)
    assert e.value.index == 5
    with pytest.raises(ValueError, match=r"^f_star = NaN ") as e:
        core.mu_with_slope_into(one, one * 0.001, f[6:], np.empty(594), np.empty(594), False, 1)
    assert e.value.index == 294
    assert core.mu_into(one, one * 0.001, f, np.empty(600), True, 1) == 3
    assert core.mu_with_slope_into(one, one * 0.001, f, np.empty(600), np.empty(600), True, 2) == 3
    curve = table.curve(1.0, 0.001)._core
    assert curve.mu_into(f, np.empty(600), True, 1) == 3
    assert curve.mu_with_slope_into(f, np.empty(600), np.empty(600), True, 1) == 3
    model = kf.Model(1.0, 0.001)._core
    assert model.contacts_into(np.array([0.01, -1.0, np.nan]), True, np.empty(21), True, 1) == 2
    with pytest.raises(ValueError) as e:
        model.contacts_into(np.array([0.01, -1.0, np.nan]), True, np.empty(21), False, 1)
    assert e.value.index == 1
    # Scalar lookups and errors without an element raise without an index.
    with pytest.raises(ValueError) as e:
        core.mu_scalar(9.0, 0.001, 0.01)
    assert not hasattr(e.value, "index")
    with pytest.raises(kf.TableError):
        kf.Table.load(pathlib.Path(kf.__file__))  # not a table
    assert issubclass(kf.TableError, ValueError)


def test_loading_tables(tmp_path):
    from conftest import ROOT

    good = tmp_path / "good.kft"
    good.write_bytes((ROOT / "tables" / "default.kft").read_bytes())
    t = kf.Table.load(good)
    assert t.mu(1.0, 0.001, 0.01) == kf.Table.default().mu(1.0, 0.001, 0.01)
    assert kf.Table.load(str(good)).info == kf.Table.default().info
    with pytest.raises(OSError, match="missing.kft"):
        kf.Table.load(tmp_path / "missing.kft")
    data = bytearray(good.read_bytes())
    data[len(data) // 2] ^= 0x10
    bad = tmp_path / "bad.kft"
    bad.write_bytes(bytes(data))
    with pytest.raises(ValueError, match="checksum"):
        kf.Table.load(bad)
    empty = tmp_path / "empty.kft"
    empty.write_bytes(b"")
    with pytest.raises(ValueError, match="empty.kft"):
        kf.Table.load(empty)


def test_crafted_tables_raise_table_error_or_answer(tmp_path):
    """Issue 23's crafted files (valid checksums, hostile contents, written
    by examples/crafted_tables.rs from tests/forge.rs into KEF_CRAFTED_DIR,
    which .ci/python.sh sets): refused with TableError naming the field, or
    loaded and answering mu = e^c; never a PanicException."""
    import math
    import os
    import pathlib

    crafted = os.environ.get("KEF_CRAFTED_DIR")
    assert crafted, "KEF_CRAFTED_DIR is not set (.ci/python.sh writes the crafted tables there)"
    lines = (pathlib.Path(crafted) / "index.tsv").read_text().splitlines()
    assert len(lines) >= 20
    refused = 0
    for line in lines:
        file, field, query, expected, name = line.split("\t")
        path = pathlib.Path(crafted) / file
        if field != "ok":
            with pytest.raises(kf.TableError, match=field.replace("*", r"\*")) as err:
                kf.Table.load(path)
            assert isinstance(err.value, ValueError), name
            refused += 1
            continue
        t = kf.Table.load(path)
        psi, theta, f_star = map(float, query.split())
        mu = t.mu(psi, theta, f_star)
        batch = t.mu(np.full(3, psi), np.full(3, theta), np.full(3, f_star))
        assert mu > 0 and math.isfinite(mu), name
        assert abs(mu / float(expected) - 1) <= 2e-6 * (1 + abs(math.log(float(expected)))), (name, mu, expected)
        assert (batch == mu).all(), name
    assert refused >= 10
