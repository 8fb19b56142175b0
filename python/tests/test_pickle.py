"""Pickling and copying (tables, curves, models, contacts: the same
results to the bit after a round trip), a table sent to a process pool,
arrays of any alignment and byte order, the model's parameters as
attributes, the version and the module's public names."""

import copy
import multiprocessing
import pathlib
import pickle

import numpy as np
import pytest
from conftest import ROOT

import ke_friction as kf

#: Every pickle protocol this Python has (2 is the oldest that copyreg's
#: __reduce__ of classes with __slots__ needs; 0 and 1 work too).
PROTOCOLS = range(pickle.HIGHEST_PROTOCOL + 1)


def round_trips(x):
    """x after each pickle protocol, and after copy and deepcopy."""
    return [pickle.loads(pickle.dumps(x, protocol=p)) for p in PROTOCOLS] + [copy.copy(x), copy.deepcopy(x)]


@pytest.fixture(scope="module")
def loaded(tmp_path_factory):
    """The default table's file, loaded from a copy of it (not the default)."""
    path = tmp_path_factory.mktemp("tables") / "copy.kft"
    path.write_bytes((ROOT / "tables" / "default.kft").read_bytes())
    return kf.Table.load(path)


def assert_same_table(a, b, points):
    psi, theta, f = points
    assert np.array_equal(a.mu(psi, theta, f), b.mu(psi, theta, f))
    for x, y in zip(a.mu_with_slope(psi, theta, f), b.mu_with_slope(psi, theta, f)):
        assert np.array_equal(x, y)
    assert a.info == b.info and a.to_bytes() == b.to_bytes()


def test_the_default_table_pickles_as_its_name(table, points):
    data = pickle.dumps(table)
    assert len(data) < 100 and b"default" in data
    for t in round_trips(table):
        assert_same_table(t, table, points)
        assert pickle.dumps(t) == data


def test_a_loaded_table_pickles_as_its_files_bytes(loaded, table, points):
    raw = (ROOT / "tables" / "default.kft").read_bytes()
    assert loaded.to_bytes() == raw == table.to_bytes()
    data = pickle.dumps(loaded)
    assert raw in data and b"default" not in data
    for t in round_trips(loaded):
        assert_same_table(t, loaded, points)
        assert_same_table(t, table, points)


def test_tables_of_bytes(table, points):
    raw = table.to_bytes()
    for data in (raw, bytearray(raw), memoryview(raw)):
        assert_same_table(kf.Table.from_bytes(data), table, points)
    with pytest.raises(kf.TableError):
        kf.Table.from_bytes(raw[:-1])
    with pytest.raises(TypeError, match="data must be bytes"):
        kf.Table.from_bytes("default")


def test_crafted_tables_pickle_as_their_bytes():
    """The crafted valid tables of test_errors.py (other than the default)."""
    import os

    crafted = os.environ.get("KEF_CRAFTED_DIR")
    if not crafted:
        pytest.skip("KEF_CRAFTED_DIR is not set (.ci/python.sh sets it)")
    done = 0
    for line in (pathlib.Path(crafted) / "index.tsv").read_text().splitlines():
        file, field, query, _, _ = line.split("\t")
        if field != "ok":
            continue
        t = kf.Table.load(pathlib.Path(crafted) / file)
        psi, theta, f_star = map(float, query.split())
        for u in round_trips(t):
            assert u.to_bytes() == t.to_bytes() and u.info == t.info
            assert u.mu(psi, theta, f_star) == t.mu(psi, theta, f_star)
        done += 1
    assert done >= 1


def test_curves_pickle_as_they_were_made(table, loaded):
    loads = np.geomspace(1e-5, 0.1, 20_001)
    curves = [table.curve(1.5, 0.002), loaded.curve(0.7, 0.0), table.curve(np.float32(2.0), 0),
              kf.Curve.from_model(kf.Model(1.0, 0.001), 1e-5, 0.1),
              kf.Curve.from_model(kf.Model(3.0, 0.02, beta=0.1, nu=0.25, fit="as-printed", model="ceb"), 1e-4, 0.05)]
    for c in curves:
        lo, hi = c.range
        inside = loads[(loads >= lo) & (loads <= hi)]
        want, want_slope = c.mu(inside), c.mu_with_slope(inside)[1]
        for d in round_trips(c):
            assert d.range == c.range and d.max_error == c.max_error
            assert np.array_equal(d.mu(inside), want)
            assert np.array_equal(d.mu_with_slope(inside)[1], want_slope)
            assert d.mu(0.01) == c.mu(0.01)
    # A curve of the default table carries the table's name, not its bytes.
    assert len(pickle.dumps(curves[0])) < 200
    assert (ROOT / "tables" / "default.kft").read_bytes() in pickle.dumps(curves[1])


def test_models_and_contacts_pickle(points):
    loads = np.geomspace(1e-5, 0.1, 200)
    for m in [kf.Model(1.0, 0.001), kf.Model(0.3, 0.5, beta=0.2, nu=0.1, eps_star=0.01, fit="as-printed", model="ceb")]:
        want = m.at_f_star(loads)
        for n in round_trips(m):
            assert n.params == m.params and repr(n) == repr(m)
            got = n.at_f_star(loads)
            for name in ("h_star", "d_star", "p_star", "fs_star", "q_star", "f_star", "mu"):
                assert np.array_equal(getattr(got, name), getattr(want, name)), name
        for c in round_trips(want) + round_trips(m.at_h_star(1.0)):
            assert isinstance(c, kf.Contact)
    c = kf.Model(1.0, 0.001).at_h_star(np.linspace(0, 3, 7))
    assert all(np.array_equal(getattr(d, "mu"), c.mu) for d in round_trips(c))


def _table_mu(table, psi, theta, f_star):
    """In a worker process: the table's mu (the table arrives pickled)."""
    return table.mu(psi, theta, f_star)


def _curve_mu(curve, f_star):
    return curve.mu(f_star)


def test_a_table_goes_to_a_spawned_process_pool(table, loaded, points):
    psi, theta, f = (a[:1000] for a in points)
    ctx = multiprocessing.get_context("spawn")
    with ctx.Pool(2) as pool:
        got = pool.starmap(_table_mu, [(t, psi, theta, f) for t in (table, loaded)])
        curve = table.curve(2.0, 0.004)
        got_curve = pool.apply(_curve_mu, (curve, f))
        got_bound = pool.apply(table.mu, (psi, theta, f))  # a bound method carries its table
    want = table.mu(psi, theta, f)
    assert all(np.array_equal(g, want) for g in got) and np.array_equal(got_bound, want)
    assert np.array_equal(got_curve, curve.mu(f))


def unaligned(values):
    """``values`` as a float64 array one byte into a buffer: not aligned."""
    raw = np.ascontiguousarray(values, dtype=np.float64).tobytes()
    a = np.frombuffer(bytearray(b"\0" + raw), dtype=np.float64, offset=1).reshape(np.shape(values))
    assert not a.flags.aligned and a.flags.c_contiguous
    return a


def test_unaligned_and_byte_swapped_arrays_are_accepted(table, points):
    psi, theta, f = (a[:3001] for a in points)
    curve, model = table.curve(1.0, 0.001), kf.Model(1.0, 0.001)
    want = table.mu(psi, theta, f)
    want_slope = table.mu_with_slope(psi, theta, f)
    loads = f[:50]
    want_contact = model.at_f_star(loads)
    for convert in (unaligned, lambda a: np.asarray(a, dtype=">f8"),
                    # Big-endian and not aligned.
                    lambda a: np.frombuffer(b"\0" + np.asarray(a, ">f8").tobytes(), dtype=">f8", offset=1)):
        p, t, ff = convert(psi), convert(theta), convert(f)
        assert np.array_equal(table.mu(p, t, ff), want)
        assert np.array_equal(table.mu(p, 0.001, ff), table.mu(psi, 0.001, f))  # with one value for all
        for x, y in zip(table.mu_with_slope(p, t, ff), want_slope):
            assert np.array_equal(x, y)
        assert np.array_equal(curve.mu(ff), curve.mu(f))
        assert np.array_equal(curve.mu_with_slope(ff)[1], curve.mu_with_slope(f)[1])
        assert np.array_equal(model.at_f_star(convert(loads)).mu, want_contact.mu)
    # 2-D unaligned input keeps its shape.
    grid = unaligned(f[:3000].reshape(30, 100))
    assert np.array_equal(table.mu(2.0, 0.003, grid), table.mu(2.0, 0.003, f[:3000].reshape(30, 100)))


def test_the_native_layer_copies_unaligned_arrays_itself(table):
    """A direct call of the native module (no conversion in Python first)."""
    f = np.geomspace(1e-5, 0.1, 257)
    out, want = np.empty(257), table.mu(2.0, 0.003, f)
    table._core.mu_into(np.array([2.0]), np.array([0.003]), unaligned(f), out, False, 1)
    assert np.array_equal(out, want)
    with pytest.raises(ValueError, match="f_star must be contiguous"):
        table._core.mu_into(np.array([2.0]), np.array([0.003]), np.repeat(f, 2)[::2], out, False, 1)


def test_the_models_parameters_are_attributes():
    m = kf.Model(2.0, 0.003, beta=0.1, nu=0.25, eps_star=0.01, fit="as-printed", model="ceb")
    assert (m.psi, m.theta, m.beta, m.nu, m.eps_star, m.fit, m.model) == (2.0, 0.003, 0.1, 0.25, 0.01, "as-printed",
                                                                         "ceb")
    d = kf.Model(1.0, 0.001)
    assert {k: getattr(d, k) for k in d.params} == d.params
    assert {k: getattr(d, k) for k in kf.DEFAULTS} == dict(kf.DEFAULTS)
    with pytest.raises(AttributeError):
        d.psi = 3.0
    p = d.params
    p["psi"] = 5.0  # a copy
    assert d.psi == 1.0 and d.params["psi"] == 1.0


def test_the_version_and_the_public_names():
    import re

    assert re.fullmatch(r"\d+\.\d+\.\d+\S*", kf.__version__)
    cargo = (ROOT / "Cargo.toml").read_text()
    assert f'\nversion = "{kf.__version__}"' in cargo
    from importlib.metadata import version

    assert version("ke-friction") == kf.__version__
    names = dir(kf)
    assert names == sorted([*kf.__all__, "__version__"])
    for typing_name in ("Any", "Dict", "Optional", "Tuple", "Union", "np", "os", "math", "dataclasses"):
        assert typing_name not in names
    assert all(hasattr(kf, n) for n in names)
