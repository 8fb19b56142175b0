"""Issue 46's numerics through Python: scans of unbounded ranges, the
Weibull density at Sk = 2, an empty filter band, +inf pressures and masked pressures of a FrictionLaw."""

import numpy as np
import pytest

import ke_friction as kf


def _surface(n=64, **kw):
    x, y = np.meshgrid(np.arange(n), np.arange(n))
    h = 1e-7 * (np.sin(0.7 * x) + np.cos(0.9 * y) + np.sin(0.31 * x + 0.27 * y) + np.cos(0.13 * x - 0.41 * y))
    return kf.Surface.from_heights(h, 1e-6, 1e-6, **kw)


@pytest.mark.parametrize("lo, hi", [(1e-300, 1e300), (4.9e-324, 1e-5)])
def test_a_scan_of_unbounded_range_is_a_value_error(lo, hi):
    s = _surface()
    with pytest.raises(ValueError, match="decades"):
        s.scan(from_=lo, to=hi)


def test_weibull_at_skewness_two_has_numbers():
    # tools/nongaussian_reference.py (mpmath): Model(1, 10, weibull 2).evaluate(5.77)
    m = kf.Model(1.0, 10.0, distribution="weibull", skewness=2.0)
    r = m.at_h_star(5.77)
    assert abs(r.f_star / -0.019703042447467716 - 1) < 1e-9
    assert abs(r.fs_star / 0.019805671103146591 - 1) < 1e-9


def test_an_empty_band_is_a_value_error():
    with pytest.raises(ValueError, match="lambda_c"):
        _surface(lambda_s=1e-5, lambda_c=5e-6)


def test_plus_infinity_is_clamped_to_p_max():
    law = kf.FrictionLaw(1.0, 0.001, hardness=1e9)
    lo, hi = law.range
    law.reset_clamped()
    assert law.mu(float("inf")) == law.mu(hi) == law.mu(1e300)
    mu, dmu = law.mu_and_derivative(np.array([np.inf, 1e6]))
    assert mu[0] == law.mu(hi) and dmu[0] == 0.0
    assert law.clamped == 3


def test_masked_pressures_stay_masked():
    law = kf.FrictionLaw(1.0, 0.001, hardness=1e9)
    p = np.ma.masked_array([[1e6, -5.0], [np.nan, 1e7]], mask=[[False, True], [True, False]])
    law.reset_clamped()
    mu = law.mu(p)
    assert isinstance(mu, np.ma.MaskedArray)
    assert (np.ma.getmaskarray(mu) == np.ma.getmaskarray(p)).all()
    assert mu[0, 0] == law.mu(1e6) and mu[1, 1] == law.mu(1e7)
    mu, dmu = law.mu_and_derivative(p)
    assert (np.ma.getmaskarray(mu) == p.mask).all() and (np.ma.getmaskarray(dmu) == p.mask).all()
    assert dmu[1, 1] == law.mu_and_derivative(1e7)[1]
    assert law.clamped == 0
    # An unmasked bad pressure still raises, naming its index.
    with pytest.raises(ValueError, match="pressure"):
        law.mu(np.ma.masked_array([1e6, -5.0], mask=[False, False]))
