"""The asperity heights' distribution (MODEL.md section 9) from Python:
HeightDistribution, Model's distribution arguments (the CLI's rules),
the library's reference values, errors, pickling and the densities."""

import copy
import pickle

import numpy as np
import pytest

import ke_friction as kf

#: The library's reference values of mu at psi = 1, theta = 0.001, F* = 1e-4.
REFERENCE = [
    ({}, 0.7567111956),
    (dict(skewness=0.0, kurtosis=8.0), 0.2529016383),
    (dict(skewness=-0.5, kurtosis=3.375), 1.004869931),
]

PROTOCOLS = range(pickle.HIGHEST_PROTOCOL + 1)


def round_trips(x):
    """x after each pickle protocol, and after copy and deepcopy."""
    return [pickle.loads(pickle.dumps(x, protocol=p)) for p in PROTOCOLS] + [copy.copy(x), copy.deepcopy(x)]


def mu(model):
    return model.at_f_star(1e-4).mu


@pytest.fixture(scope="module")
def heights():
    """A skewed height map (2-D, as measured), with missing points."""
    h = np.random.default_rng(11).gamma(2.0, 1e-7, size=(60, 50))
    h[3, 4] = np.nan
    return h


@pytest.mark.parametrize("kwargs, want", REFERENCE)
def test_the_reference_values(kwargs, want):
    m = kf.Model(1.0, 0.001, **kwargs)
    assert mu(m) == pytest.approx(want, abs=1e-9)
    # The same by a HeightDistribution object and by the family's name.
    if kwargs:
        d = kf.HeightDistribution.pearson(**kwargs)
        assert mu(kf.Model(1.0, 0.001, distribution=d)) == mu(m)
        assert mu(kf.Model(1.0, 0.001, distribution="pearson", **kwargs)) == mu(m)


def test_pearson_0_3_is_the_gaussian_exactly():
    gauss = kf.Model(1.0, 0.001)
    pearson = kf.Model(1.0, 0.001, skewness=0.0, kurtosis=3.0)
    assert pearson.distribution == "pearson" and gauss.distribution == "gaussian"
    assert kf.HeightDistribution.pearson(0.0, 3.0).is_gaussian
    loads = np.geomspace(1e-5, 0.1, 50)
    for name in ("h_star", "p_star", "fs_star", "q_star", "mu"):
        assert np.array_equal(getattr(pearson.at_f_star(loads), name), getattr(gauss.at_f_star(loads), name)), name
    assert mu(pearson) == mu(gauss)


def test_model_attributes_and_records():
    m = kf.Model(1.0, 0.001, kurtosis=8.0)
    assert (m.distribution, m.skewness, m.kurtosis) == ("pearson", 0.0, 8.0)
    p = m.params
    assert (p["distribution"], p["skewness"], p["kurtosis"]) == ("pearson", 0.0, 8.0)
    assert {k: getattr(m, k) for k in p} == p
    assert m.height_distribution == kf.HeightDistribution.pearson(0.0, 8.0)
    assert kf.Model(**p).params == p
    assert kf.Model(1.0, 0.001).height_distribution == kf.HeightDistribution.gaussian()
    # Weibull: the record's kurtosis (the one its skewness implies) rebuilds it.
    w = kf.Model(1.0, 0.001, distribution="weibull", skewness=0.5)
    assert w.distribution == "weibull" and w.skewness == 0.5 and 2.5 < w.kurtosis < 3.5
    assert kf.Model(**w.params).params == w.params
    assert "kurtosis=8.0" in repr(m)


def test_heights_give_an_empirical_density(heights):
    m = kf.Model(1.0, 0.001, heights=heights)
    d = m.height_distribution
    assert m.distribution == d.family == "empirical"
    assert m.params["heights"] == np.isfinite(heights).sum()
    finite = heights[np.isfinite(heights)]
    z = (finite - finite.mean()) / finite.std()
    assert m.skewness == pytest.approx(np.mean(z ** 3), rel=1e-9)
    assert m.kurtosis == pytest.approx(np.mean(z ** 4), rel=1e-9)
    assert 0 < mu(m) < 2
    # Any dtype, order, byte order and container: the same density.
    want = mu(m)
    for other in (np.asfortranarray(heights), heights.astype(">f8"), heights.T.copy().T, heights.tolist(),
                  kf.HeightDistribution.empirical(heights)):
        kw = dict(distribution=other) if isinstance(other, kf.HeightDistribution) else dict(heights=other)
        assert mu(kf.Model(1.0, 0.001, **kw)) == want
    assert mu(kf.Model(1.0, 0.001, heights=heights.astype(np.float32))) > 0
    assert mu(kf.Model(1.0, 0.001, distribution="empirical", heights=np.arange(200))) > 0
    # The heights are copied and kept, read-only.
    copied = heights.copy()
    d2 = kf.HeightDistribution.empirical(copied)
    copied[:] = 0.0
    assert d2 == d and d2.heights.shape == (heights.size,) and not d2.heights.flags.writeable
    assert np.array_equal(d2.heights, heights.reshape(-1), equal_nan=True)


@pytest.mark.parametrize("kwargs, name", [
    (dict(skewness=0.5, kurtosis=1.2), "kurtosis"),            # K <= Sk^2 + 1
    (dict(skewness=0.0, kurtosis=1.0), "kurtosis"),
    (dict(skewness=6.0, kurtosis=50.0), "skewness"),            # |Sk| <= 5
    (dict(kurtosis=101.0), "kurtosis"),                         # K <= 100
    (dict(skewness=float("nan")), "skewness"),
    (dict(kurtosis=float("nan")), "kurtosis"),
    (dict(distribution="weibull", skewness=2.5), "skewness"),
    (dict(distribution="weibull", kurtosis=3.0), "kurtosis"),   # weibull takes skewness alone
    (dict(distribution="weibull", skewness=0.0, kurtosis=3.0), "kurtosis"),
    (dict(distribution="gaussian", kurtosis=8.0), "kurtosis"),
    (dict(distribution="gaussian", skewness=0.3), "skewness"),
    (dict(distribution="lognormal"), "distribution"),
    (dict(distribution="empirical"), "heights"),
    (dict(distribution="pearson", heights=np.arange(200.0)), "heights"),
    (dict(heights=np.arange(200.0), skewness=0.1), "skewness"),
    (dict(heights=np.arange(99.0)), "heights"),                 # too few
    (dict(heights=np.r_[np.arange(99.0), np.full(50, np.nan)]), "heights"),  # too few finite
    (dict(heights=np.full(500, 2.0)), "heights"),               # constant
    (dict(heights=np.r_[np.arange(200.0), np.inf]), "heights"),
    (dict(distribution=kf.HeightDistribution.pearson(0.0, 8.0), kurtosis=8.0), "kurtosis"),
])
def test_bad_distributions_raise_value_error_naming_the_argument(kwargs, name):
    with pytest.raises(ValueError, match=name):
        kf.Model(1.0, 0.001, **kwargs)


def test_the_core_messages_name_the_bound():
    with pytest.raises(ValueError, match=r"kurtosis = 1\.2 is out of range: must be > skewness² \+ 1"):
        kf.HeightDistribution.pearson(0.5, 1.2)
    with pytest.raises(ValueError, match=r"skewness = 2\.5 is out of range: must be in \(-1\.1395, 2\]"):
        kf.HeightDistribution.weibull(2.5)
    with pytest.raises(ValueError, match="heights = 99 is out of range: must be at least 100 finite values"):
        kf.HeightDistribution.empirical(np.arange(99.0))


def test_wrong_types_raise_type_error():
    for kwargs in (dict(distribution=3), dict(skewness="0.5"), dict(kurtosis=True), dict(heights=5.0),
                   dict(heights=["a"] * 200), dict(heights=np.zeros(200, dtype=complex))):
        with pytest.raises(TypeError):
            kf.Model(1.0, 0.001, **kwargs)


#: (distribution, whether to build a curve of it too). Curve.from_model
#: is left out for the U-shaped type I density: mu(F*) is not smooth where
#: the contact plane passes its ends, and the curve misses its 1e-6.
PICKLED = [
    (lambda h: kf.HeightDistribution.gaussian(), True),
    (lambda h: kf.HeightDistribution.pearson(0.0, 8.0), True),
    (lambda h: kf.HeightDistribution.pearson(-0.5, 3.375), True),
    (lambda h: kf.HeightDistribution.pearson(1.0, 2.5), False),   # type I, U-shaped, bounded
    (lambda h: kf.HeightDistribution.weibull(0.7), True),
    (lambda h: kf.HeightDistribution.empirical(h), True),
]


@pytest.mark.parametrize("make, with_curve", PICKLED)
def test_models_curves_and_distributions_pickle_to_the_bit(make, with_curve, heights):
    d = make(heights)
    for e in round_trips(d):
        assert e == d and e.family == d.family and e.skewness == d.skewness and e.kurtosis == d.kurtosis
        assert e.support == d.support and e.mode == d.mode
        assert np.array_equal(e.pdf(np.linspace(-3, 3, 101)), d.pdf(np.linspace(-3, 3, 101)))
    m = kf.Model(1.0, 0.001, distribution=d)
    # (Up to 1e-2: the bounded type I density reaches F* = 0.026 at h* = 1.)
    loads = np.geomspace(1e-5, 1e-2, 20)
    want = m.at_f_star(loads)
    assert np.allclose(want.f_star, loads, rtol=1e-9, atol=0)
    for n in round_trips(m):
        assert n.params == m.params and repr(n) == repr(m)
        assert n.height_distribution == d
        got = n.at_f_star(loads)
        for name in ("h_star", "p_star", "fs_star", "q_star", "mu"):
            assert np.array_equal(getattr(got, name), getattr(want, name)), name
    if not with_curve:
        return
    c = kf.Curve.from_model(m, 1e-5, 1e-2)
    inside = np.geomspace(1e-5, 1e-2, 77)
    assert np.max(np.abs(c.mu(inside) / m.at_f_star(inside).mu - 1)) <= kf.CURVE_ACCURACY
    for e in round_trips(c):
        assert e.range == c.range and e.max_error == c.max_error
        assert np.array_equal(e.mu(inside), c.mu(inside))


@pytest.mark.parametrize("make", [
    lambda h: kf.HeightDistribution.gaussian(),
    lambda h: kf.HeightDistribution.pearson(0.0, 8.0),
    lambda h: kf.HeightDistribution.pearson(-0.5, 3.375),
    lambda h: kf.HeightDistribution.pearson(0.5, 2.8),          # type I: bounded
    lambda h: kf.HeightDistribution.pearson(1.5, 8.0),
    lambda h: kf.HeightDistribution.weibull(0.0),
    lambda h: kf.HeightDistribution.weibull(1.5),
    lambda h: kf.HeightDistribution.empirical(h),
])
def test_the_density_integrates_to_one_with_its_moments(make, heights):
    d = make(heights)
    lo, hi = d.support
    x = np.linspace(max(lo, -40.0), min(hi, 40.0), 400_001)
    g = d.pdf(x)
    assert g.shape == x.shape and np.all(g >= 0) and np.all(np.isfinite(g[1:-1]))
    g = np.where(np.isfinite(g), g, 0.0)  # a J-shaped end
    trapezoid = getattr(np, "trapezoid", None) or np.trapz
    assert trapezoid(g, x) == pytest.approx(1.0, abs=2e-3)
    mass, mean, var, sk, k = d.moments()
    assert mass == pytest.approx(1.0, abs=1e-9) and mean == pytest.approx(0.0, abs=1e-9)
    assert var == pytest.approx(1.0, abs=1e-9)
    if d.family != "empirical":
        assert sk == pytest.approx(d.skewness, abs=1e-8) and k == pytest.approx(d.kurtosis, abs=1e-6)
    # Broadcasting: scalars give floats, arrays their shape; ln_pdf agrees.
    assert isinstance(d.pdf(0.1), float) and d.pdf(0.1) == d.pdf(np.array([0.1]))[0]
    assert d.pdf(np.zeros((3, 4))).shape == (3, 4)
    inside = np.linspace(max(lo, -3) + 0.01, min(hi, 3) - 0.01, 50)
    assert np.allclose(np.exp(d.ln_pdf(inside)), d.pdf(inside), rtol=1e-12)
    if np.isfinite(lo):
        assert d.pdf(lo - 1.0) == 0.0 and d.ln_pdf(lo - 1.0) == -np.inf


def test_distribution_attributes():
    g = kf.HeightDistribution.gaussian()
    assert (g.family, g.skewness, g.kurtosis, g.pearson_type, g.support, g.mode) == (
        "gaussian", 0.0, 3.0, "0", (-np.inf, np.inf), 0.0)
    assert g.pdf(0.0) == pytest.approx(1 / np.sqrt(2 * np.pi), rel=1e-14)
    assert kf.HeightDistribution.pearson(0.0, 8.0).pearson_type == "VII"
    assert kf.HeightDistribution.pearson(1.0, 2.5).pearson_type == "I"
    beta = kf.HeightDistribution.pearson(1.0, 2.5)
    assert np.isfinite(beta.support[0]) and np.isfinite(beta.support[1])
    w = kf.HeightDistribution.weibull(0.0)
    assert w.pearson_type is None and w.kurtosis == pytest.approx(2.717, abs=1e-3) and np.isfinite(w.support[0])
    assert g.heights is None and g.bandwidth is None
    assert repr(kf.HeightDistribution.pearson(0.0, 8.0)) == "HeightDistribution.pearson(0.0, 8.0)"
    assert kf.HeightDistribution.pearson(0.0, 8.0) != kf.HeightDistribution.pearson(0.0, 8.5)
    assert len({kf.HeightDistribution.pearson(0.0, 8.0), kf.HeightDistribution.pearson(0.0, 8.0)}) == 1
    assert "HeightDistribution" in kf.__all__


def test_a_non_gaussian_table_from_kefric_build(tmp_path):
    """A Pearson table (format version 2) built by the CLI: Python reads
    its distribution in the record, looks up within the table's tolerance
    of the Model with the same distribution, and pickles it bit-identically."""
    import subprocess

    from conftest import KEFRIC

    if not __import__("os").path.exists(KEFRIC):
        pytest.skip(f"{KEFRIC} is not built")
    path = tmp_path / "skewed.kft"
    subprocess.run(
        [KEFRIC, "build", "--skewness", "-0.5", "--kurtosis", "3.375", "--nodes", "9,9,13", "--psi", "0.8:2",
         "--theta", "0:0.002", "--f-star", "1e-4:0.05", "--tolerance", "0.05", "--precision", "f64",
         "--samples", "200", "--quiet", "--out", str(path)],
        check=True,
    )
    table = kf.Table.load(path)
    info = table.info
    assert (info["distribution"], info["skewness"], info["kurtosis"]) == ("pearson", -0.5, 3.375)
    model = kf.Model(1.0, 0.001, skewness=-0.5, kurtosis=3.375)
    for f in (1e-4, 1e-3, 1e-2):
        exact = model.at_f_star(f).mu
        assert abs(float(table.mu(1.0, 0.001, f)) / exact - 1) <= info["tolerance"], f
    # A Gaussian model is not this table's: its mu differs by far more.
    gauss = kf.Model(1.0, 0.001).at_f_star(1e-4).mu
    assert abs(float(table.mu(1.0, 0.001, 1e-4)) / gauss - 1) > 0.1
    for back in round_trips(table):
        assert back.info == info
        assert float(back.mu(1.0, 0.001, 1e-3)) == float(table.mu(1.0, 0.001, 1e-3))


def test_pickles_of_every_family_go_through_the_stored_values():
    """A distribution pickles as its family with the values a table
    stores (one path for every family but the empirical, which keeps its
    heights); pickles made before, with None for a kurtosis the family
    ignores, still load."""
    from ke_friction import _distribution_of
    for d in (kf.HeightDistribution.gaussian(), kf.HeightDistribution.pearson(0.5, 4.0),
              kf.HeightDistribution.weibull(-0.3)):
        assert d.__reduce__()[1][3] is None
        assert all(r == d for r in round_trips(d))
    assert _distribution_of("weibull", -0.3, None, None) == kf.HeightDistribution.weibull(-0.3)
    assert _distribution_of("gaussian", 0.0, None, None) == kf.HeightDistribution.gaussian()
    with pytest.raises(ValueError, match="measured heights"):
        _distribution_of("empirical", 0.0, 3.0, None)
    with pytest.raises(ValueError, match="must be one of"):
        _distribution_of("lognormal", 0.0, 3.0, None)
