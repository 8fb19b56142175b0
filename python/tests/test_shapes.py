"""Shapes and types: NumPy broadcasting, floats for numbers, conversions."""

import numpy as np
import pytest

import ke_friction as kf
from ke_friction import _arrays


def test_numbers_give_python_floats(table):
    assert type(table.mu(1.0, 0.001, 0.01)) is float
    assert type(table.mu(1, 0, 1e-3)) is float  # ints
    assert type(table.mu(np.float32(1.0), np.int64(0), np.float64(1e-3))) is float  # NumPy scalars
    mu, slope = table.mu_with_slope(1.0, 0.001, 0.01)
    assert type(mu) is float and type(slope) is float
    curve = table.curve(1.0, 0.001)
    assert type(curve.mu(0.01)) is float
    assert all(type(x) is float for x in curve.mu_with_slope(0.01))
    c = kf.Model(1.0, 0.001).at_f_star(0.01)
    assert all(type(getattr(c, k)) is float for k in ["h_star", "d_star", "p_star", "fs_star", "q_star", "f_star", "mu"])


def test_zero_d_arrays_give_numpy_scalars_like_ufuncs(table):
    r = table.mu(np.array(1.0), 0.001, 0.01)
    assert isinstance(r, np.float64) and np.ndim(r) == 0  # what np.sin(np.array(1.0)) gives
    assert r == table.mu(1.0, 0.001, 0.01)
    mu, slope = table.mu_with_slope(np.array(1.0), np.array(0.001), np.array(0.01))
    assert isinstance(mu, np.float64) and isinstance(slope, np.float64)
    assert isinstance(table.curve(1.0, 0.001).mu(np.array(0.01)), np.float64)


@pytest.mark.parametrize("psi_shape,theta_shape,f_shape,want", [
    ((3,), (), (), (3,)),
    ((), (4,), (), (4,)),
    ((3,), (3,), (3,), (3,)),
    ((1, 3), (), (2, 1), (2, 3)),
    ((2, 1, 4), (3, 1), (1,), (2, 3, 4)),
    ((0,), (), (), (0,)),
    ((5, 0), (1,), (), (5, 0)),
])
def test_arrays_broadcast_by_numpys_rules(table, psi_shape, theta_shape, f_shape, want):
    rng = np.random.default_rng(7)
    psi = rng.uniform(0.5, 8, psi_shape)
    theta = rng.uniform(0, 0.01, theta_shape)
    f = np.exp(rng.uniform(np.log(1e-5), np.log(0.1), f_shape))
    out = table.mu(psi, theta, f)
    assert out.shape == want == np.broadcast_shapes(psi_shape, theta_shape, f_shape) and out.dtype == np.float64
    mu, slope = table.mu_with_slope(psi, theta, f)
    assert mu.shape == slope.shape == want and np.array_equal(mu, out)
    bp, bt, bf = np.broadcast_arrays(psi, theta, f)
    scalar = [table.mu(float(a), float(b), float(c)) for a, b, c in zip(bp.ravel(), bt.ravel(), bf.ravel())]
    assert np.array_equal(out.ravel(), np.array(scalar, dtype=float))


def test_curves_and_the_model_broadcast_too(table):
    c = kf.Model(1.0, 0.001).at_h_star(np.array([[0.0, 1.0], [2.0, 3.0]]))
    for key in ["h_star", "d_star", "p_star", "fs_star", "q_star", "f_star", "mu"]:
        assert getattr(c, key).shape == (2, 2) and getattr(c, key).flags.c_contiguous
    assert c.h_star[1, 0] == 2.0 and c.p_star[1, 0] == kf.Model(1.0, 0.001).at_h_star(2.0).p_star
    curve = table.curve(1.0, 0.001)
    assert curve.mu(np.full((3, 4), 0.01)).shape == (3, 4)
    mu, slope = curve.mu_with_slope([[0.01, 0.02]])
    assert mu.shape == slope.shape == (1, 2)


def test_other_dtypes_orders_and_strides_are_converted(table):
    ref = table.mu([1.0, 2.0], 0.0, [0.01, 0.02])
    assert np.array_equal(table.mu(np.array([1, 2], dtype=np.int32), 0, (0.01, 0.02)), ref)  # ints, tuples
    assert np.array_equal(table.mu(np.array([1, 2], dtype=np.float32), 0.0, [0.01, 0.02]), ref)
    strided = np.linspace(0.5, 8, 20)[::3]
    assert np.array_equal(table.mu(strided, 0.001, 0.01), table.mu(strided.copy(), 0.001, 0.01))
    grid = np.asfortranarray(np.linspace(0.5, 8, 12).reshape(3, 4))
    assert np.array_equal(table.mu(grid, 0.001, 0.01), table.mu(np.ascontiguousarray(grid), 0.001, 0.01))
    big_endian = np.array([1.0, 2.0], dtype=">f8")
    assert np.array_equal(table.mu(big_endian, 0.0, [0.01, 0.02]), ref)


def test_contiguous_float64_input_is_not_copied():
    a = np.linspace(0.5, 8, 6).reshape(2, 3)
    shape, (flat, other) = _arrays(("psi", "theta"), (a, 0.001))
    assert shape == (2, 3) and np.shares_memory(flat, a)
    assert not np.shares_memory(other, a) and other.shape == (6,)
    _, (copied,) = _arrays(("psi",), (a[:, ::2],))
    assert not np.shares_memory(copied, a) and copied.flags.c_contiguous
    # Lookups pass one value for a scalar argument; the native layer repeats it.
    shape, (flat, one, row) = _arrays(("psi", "theta", "f_star"), (a, [[0.001]], [0.01, 0.02, 0.03]), scalars=True)
    assert shape == (2, 3) and np.shares_memory(flat, a) and one.shape == (1,) and row.shape == (6,)


def test_float64_arrays_of_one_shape_take_the_short_path_in_c_order():
    a = np.linspace(0.5, 8, 6).reshape(2, 3)
    fortran, reversed_ = np.asfortranarray(a), a.reshape(-1)[::-1]
    shape, (same, f_order, back) = _arrays(("psi", "theta", "f_star"), (a.reshape(-1), fortran.reshape(-1), reversed_))
    assert shape == (6,) and np.shares_memory(same, a)
    assert np.array_equal(back, a.reshape(-1)[::-1]) and back.flags.c_contiguous
    shape, (c, f) = _arrays(("psi", "theta"), (a, fortran))
    assert shape == (2, 3) and np.array_equal(c, f) and not np.shares_memory(f, fortran)
    # Another byte order is not float64 here: converted on the general path.
    big = a.astype(">f8")
    _, (flat,) = _arrays(("psi",), (big,))
    assert flat.dtype == np.float64 and np.array_equal(flat, a.reshape(-1))


def test_scalar_arguments_repeated_natively_match_full_arrays(table, points):
    psi, theta, f = points
    for args in [(psi, 0.003, f), (2.0, theta, f), (2.0, 0.003, f), (psi, [0.003], [[0.01]])]:
        full = [np.ascontiguousarray(np.broadcast_to(np.asarray(x, float), np.broadcast_shapes(
            *(np.shape(y) for y in args)))) for x in args]
        assert np.array_equal(table.mu(*args), table.mu(*full))
        assert all(np.array_equal(x, y) for x, y in zip(table.mu_with_slope(*args), table.mu_with_slope(*full)))
    bad = f.copy()
    bad[[3, 300, 301]] = [1.0, np.nan, 0.0]
    with pytest.raises(ValueError, match=r"f_star = 1 .*\(at index \(3,\)\)"):
        table.mu(2.0, 0.003, bad)
    mu = table.mu(2.0, 0.003, bad, out_of_domain="nan")
    assert np.isnan(mu).sum() == 3 and np.isnan(mu[[3, 300, 301]]).all()
    with pytest.raises(ValueError, match=r"^psi = 9 .*\(at index \(0,\)\)"):
        table.mu(9.0, 0.003, f)


def test_outputs_are_new_writable_arrays(table):
    psi = np.linspace(0.5, 8, 5)
    out = table.mu(psi, 0.001, 0.01)
    assert not np.shares_memory(out, psi) and out.flags.writeable
    out[:] = 0  # does not touch the input
    assert psi[0] == 0.5
