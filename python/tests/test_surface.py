"""Measured surfaces (`kf.Surface`): the statistics, model, curve and
friction against the CLI (`kefric surface --json`, the same .npy files),
the statistics against NumPy and SurfaceTopography, sampling intervals
dx != dy, missing points, pairs, errors and pickling."""

import copy
import math
import pickle

import numpy as np
import pytest
from conftest import SAME_REL, kefric

import ke_friction as kf

MATERIALS = dict(e1=70e9, nu1=0.33, e2=200e9, nu2=0.31, hardness=1e9, delta_gamma=0.5, epsilon=0.4e-9)
FLAGS = ["--e1", "70e9", "--nu1", "0.33", "--e2", "200e9", "--nu2", "0.31", "--hardness", "1e9",
         "--delta-gamma", "0.5", "--epsilon", "0.4e-9"]
DX, DY = 0.5e-6, 0.8e-6
PROTOCOLS = range(pickle.HIGHEST_PROTOCOL + 1)


def rough(ny, nx, seed, missing=0.0):
    """A random rough map (rows = y) of band-limited heights, ~0.1 um rms,
    with a tilt, and a fraction ``missing`` of its points NaN."""
    rng = np.random.default_rng(seed)
    spectrum = rng.normal(size=(ny, nx)) + 1j * rng.normal(size=(ny, nx))
    fy, fx = np.meshgrid(np.fft.fftfreq(ny), np.fft.fftfreq(nx), indexing="ij")
    spectrum *= np.exp(-((fx / 0.12) ** 2 + (fy / 0.1) ** 2))
    z = np.fft.ifft2(spectrum).real
    z = 1e-7 * z / z.std() + 1e-9 * np.arange(nx) + 2e-9 * np.arange(ny)[:, None]
    if missing:
        z[rng.random(z.shape) < missing] = np.nan
    return z


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    """Two maps and a profile as .npy files (the first map with 2 %
    missing points), and the arrays."""
    d = tmp_path_factory.mktemp("surfaces")
    arrays = {"a": rough(64, 96, 1, missing=0.02), "b": rough(64, 96, 2), "p": rough(1, 2000, 3)[0]}
    paths = {}
    for name, z in arrays.items():
        paths[name] = str(d / f"{name}.npy")
        np.save(paths[name], z)
    return paths, arrays


def cli(*args):
    (record,) = kefric("surface", *args)
    return record


def assert_same(python, reference, rel=SAME_REL, messages=True):
    """Two records equal: the same names, numbers within ``rel`` (and the
    warnings' messages, which print numbers, the same unless not
    ``messages``)."""
    if isinstance(reference, dict):
        assert isinstance(python, dict) and python.keys() == reference.keys(), (python, reference)
        for k in reference:
            if messages or k != "message":
                assert_same(python[k], reference[k], rel, messages)
    elif isinstance(reference, list):
        assert isinstance(python, list) and len(python) == len(reference)
        for x, y in zip(python, reference):
            assert_same(x, y, rel, messages)
    elif isinstance(reference, float) and not isinstance(python, (bool, str)):
        assert python == pytest.approx(reference, rel=rel, abs=0), (python, reference)
    else:
        assert python == reference


# ---- statistics ----------------------------------------------------------

@pytest.mark.parametrize("detrend, derivative", [("plane", "fd"), ("line", "fd"), ("mean", "fd")])
def test_stats_equal_the_cli_record_for_a_map_with_missing_points(files, detrend, derivative):
    paths, arrays = files
    ref = cli(paths["a"], "--dx", str(DX), "--dy", str(DY), "--detrend", detrend, "--derivative", derivative)
    for s in (kf.Surface.read(paths["a"], dx=DX, dy=DY, detrend=detrend, derivative=derivative),
              kf.Surface.from_heights(arrays["a"], DX, DY, detrend=detrend, derivative=derivative)):
        assert_same(s.stats, ref["surface"])
        assert s.stats["dx"] == DX and s.stats["dy"] == DY and s.stats["missing"] > 0
        assert s.detrend == detrend and s.derivative == derivative and not s.is_pair
        assert s.parts == [s.stats]


def test_stats_equal_the_cli_record_for_a_profile_and_spectral_moments(files):
    paths, arrays = files
    ref = cli(paths["p"], "--dx", "1e-6")
    s = kf.Surface.read(paths["p"], dx=1e-6)
    assert_same(s.stats, ref["surface"])
    assert s.stats["dy"] is None and s.stats["m02"] is None and s.stats["ny"] == 1
    assert kf.Surface.from_heights(arrays["p"], 1e-6).stats == s.stats
    ref = cli(paths["b"], "--dx", str(DX), "--dy", str(DY), "--detrend", "mean", "--derivative", "spectral")
    assert_same(kf.Surface.from_heights(arrays["b"], DX, DY, detrend="mean", derivative="spectral").stats,
                ref["surface"])


def test_stats_of_a_map_with_dx_ne_dy_and_missing_points_equal_numpy():
    """An independent path: the least-squares plane over the valid points,
    then the moments over valid points, pairs and triples, with dx along
    the columns and dy along the rows."""
    z = rough(48, 80, 7, missing=0.05)
    s = kf.Surface.from_heights(z, DX, DY).stats
    valid = ~np.isnan(z)
    y, x = np.mgrid[0:z.shape[0], 0:z.shape[1]]
    a = np.column_stack([np.ones(valid.sum()), x[valid], y[valid]])
    coef, *_ = np.linalg.lstsq(a, z[valid], rcond=None)
    d = z - (coef[0] + coef[1] * x + coef[2] * y)
    r = d[valid]
    sigma = np.sqrt(np.mean(r ** 2))
    assert s["points"] == valid.sum() and s["missing"] == (~valid).sum()
    assert (s["nx"], s["ny"]) == (80, 48)
    assert s["sigma"] == pytest.approx(sigma, rel=1e-11)
    assert s["skewness"] == pytest.approx(np.mean(r ** 3) / sigma ** 3, rel=1e-9)
    assert s["kurtosis"] == pytest.approx(np.mean(r ** 4) / sigma ** 4, rel=1e-11)

    def nanmean(v):
        return np.mean(v[~np.isnan(v)])

    # slopes of the detrended heights; the plane leaves curvatures unchanged
    assert s["m20"] == pytest.approx(nanmean((np.diff(d, axis=1) / DX) ** 2), rel=1e-11)
    assert s["m02"] == pytest.approx(nanmean((np.diff(d, axis=0) / DY) ** 2), rel=1e-11)
    assert s["m40"] == pytest.approx(nanmean((np.diff(z, 2, axis=1) / DX ** 2) ** 2), rel=1e-11)
    assert s["m04"] == pytest.approx(nanmean((np.diff(z, 2, axis=0) / DY ** 2) ** 2), rel=1e-11)
    assert s["m2"] == pytest.approx((s["m20"] + s["m02"]) / 2, rel=1e-15)


def test_any_float_dtype_order_and_alignment(files):
    _, arrays = files
    z = arrays["b"]
    ref = kf.Surface.from_heights(z, DX, DY).stats
    buf = bytearray(z.nbytes + 1)
    unaligned = np.frombuffer(buf, dtype=np.float64, offset=1, count=z.size).reshape(z.shape)
    unaligned[...] = z
    assert not unaligned.flags.aligned
    for variant in (z.astype(">f8"), np.asfortranarray(z), unaligned, z.tolist(), z[::-1, :][::-1, :],
                    np.pad(z, 1)[1:-1, 1:-1]):
        assert kf.Surface.from_heights(variant, DX, DY).stats == ref
    z32 = z.astype(np.float32)
    assert kf.Surface.from_heights(z32, DX, DY).stats == kf.Surface.from_heights(z32.astype(np.float64), DX, DY).stats
    # dy defaults to dx for a map
    assert kf.Surface.from_heights(z, DX).stats == kf.Surface.from_heights(z, DX, DX).stats


def test_read_text_and_units(tmp_path, files):
    _, arrays = files
    z = arrays["b"]
    path = tmp_path / "map.txt"
    np.savetxt(path, z * 1e6)  # micrometres
    s = kf.Surface.read(path, dx=DX, dy=DY, z_unit=1e-6)
    ref = kf.Surface.from_heights(np.loadtxt(path) * 1e-6, DX, DY)
    assert s.stats == ref.stats
    # x y z triples in micrometres: the intervals come from the grid
    ny, nx = z.shape
    y, x = np.mgrid[0:ny, 0:nx]
    path = tmp_path / "map.xyz"
    np.savetxt(path, np.column_stack([x.ravel() * 0.5, y.ravel() * 0.8, z.ravel() * 1e6]))
    s = kf.Surface.read(path, z_unit=1e-6, xy_unit=1e-6)
    assert s.stats["dx"] == pytest.approx(DX, rel=1e-12) and s.stats["dy"] == pytest.approx(DY, rel=1e-12)
    assert s.stats["sigma"] == pytest.approx(ref.stats["sigma"], rel=1e-12)


def test_units_by_name_as_the_cli_takes_them(tmp_path, files):
    """z_unit and xy_unit take the CLI's --z-unit names (the core's list,
    ``_core.LENGTH_UNITS``) and symbols as well as numbers, with the same
    result; the record equals ``kefric surface --z-unit um``'s."""
    paths, arrays = files
    path = tmp_path / "um.txt"
    np.savetxt(path, arrays["b"] * 1e6)
    by_number = kf.Surface.read(path, dx=DX, dy=DY, z_unit=1e-6)
    for name in ["um", "\u00b5m", "\u03bcm"]:
        assert kf.Surface.read(path, dx=DX, dy=DY, z_unit=name).stats == by_number.stats, name
    assert_same(by_number.stats, cli(str(path), "--dx", str(DX), "--dy", str(DY), "--z-unit", "um")["surface"])
    # Every name the CLI lists is accepted, at its number of metres.
    metres = {"km": 1e3, "m": 1.0, "cm": 1e-2, "mm": 1e-3, "um": 1e-6, "nm": 1e-9, "pm": 1e-12, "angstrom": 1e-10}
    cli_names = [n for n in kf._core.LENGTH_UNITS if n.isascii() and n not in ("A", "~m")]
    assert cli_names == list(metres)
    nm = tmp_path / "nm.txt"
    np.savetxt(nm, arrays["b"] * 1e9)
    ref = kf.Surface.read(nm, dx=DX, dy=DY, z_unit=1e-9).stats
    for name, m in metres.items():
        assert kf._core.length_unit(name) == m, name
    assert kf.Surface.read(nm, dx=DX, dy=DY, z_unit="nm").stats == ref
    # x y z triples in micrometres, the columns' unit by name
    ny, nx = arrays["b"].shape
    y, x = np.mgrid[0:ny, 0:nx]
    xyz = tmp_path / "map.xyz"
    np.savetxt(xyz, np.column_stack([x.ravel() * 0.5, y.ravel() * 0.8, arrays["b"].ravel() * 1e6]))
    assert (kf.Surface.read(xyz, z_unit="um", xy_unit="um").stats
            == kf.Surface.read(xyz, z_unit=1e-6, xy_unit=1e-6).stats)
    with pytest.raises(ValueError, match=r"z_unit: length unit 'inch' is unknown: must be one of km, m, cm, mm, um"):
        kf.Surface.read(path, dx=DX, dy=DY, z_unit="inch")
    with pytest.raises(TypeError, match="xy_unit"):
        kf.Surface.read(path, dx=DX, dy=DY, xy_unit=[1e-6])
    # from_topography's unit is a name only: its message offers no number.
    from ke_friction._surface import _unit
    assert _unit("unit", "\u00c5", number=False) == 1e-10
    with pytest.raises(ValueError, match=r"^unit: length unit 'furlong' is unknown: must be one of [^(]*$"):
        _unit("unit", "furlong", number=False)


def test_stats_is_both_an_attribute_and_a_call(files):
    """``s.stats`` (the record, as before) and ``s.stats()`` (as model(),
    curve(), friction() are called) give the same dict; it pickles as a
    plain dict."""
    _, arrays = files
    s = kf.Surface.from_heights(arrays["b"], DX, DY)
    assert s.stats() == s.stats and isinstance(s.stats(), dict)
    assert s.stats()["sigma"] == s.stats["sigma"] > 0
    assert type(pickle.loads(pickle.dumps(s.stats))) is dict
    assert pickle.loads(pickle.dumps(s.stats)) == s.stats


def test_curve_covers_the_light_loads_friction_answers(files):
    """``curve()`` defaults to the library's SURFACE_F_STAR, [1e-7, 0.1]
    (``kefric plot surface``'s range): a 2 kPa load on a 1 GPa hardness,
    F* = 2e-6, which friction() and ``kefric surface --pressure`` answer,
    is on it, with the same mu (within the curve's accuracy)."""
    _, arrays = files
    s = kf.Surface.from_heights(arrays["b"], DX, DY)
    assert kf._core.SURFACE_F_STAR == (1e-7, 0.1)
    c = s.curve(**MATERIALS, distribution="gaussian")
    f = s.friction(pressure=2e3, **MATERIALS, distribution="gaussian")
    assert f["f_star"] == pytest.approx(2e-6, rel=1e-12)
    assert c.mu(f["f_star"]) == pytest.approx(f["mu"], rel=10 * kf.CURVE_ACCURACY)
    assert c.mu(1e-7) > 0 and c.mu(0.1) > 0
    with pytest.raises(ValueError):
        c.mu(0.2)



# ---- pairs ----------------------------------------------------------------

def test_a_pair_equals_the_cli_record(files):
    paths, arrays = files
    ref = cli(paths["a"], paths["b"], "--dx", str(DX), "--dy", str(DY))
    a, b = kf.Surface.read(paths["a"], dx=DX, dy=DY), kf.Surface.from_heights(arrays["b"], DX, DY)
    s = kf.Surface.pair(a, b)
    assert s.is_pair
    assert_same(s.stats, ref["surface"])
    assert_same(s.parts, ref["parts"])
    assert s.parts == [a.stats, b.stats]
    # the sum of two: sigma^2 adds
    assert s.stats["sigma"] == pytest.approx(math.hypot(a.stats["sigma"], b.stats["sigma"]), rel=1e-12)


def test_pair_options_and_errors(files):
    _, arrays = files
    a = kf.Surface.from_heights(arrays["a"], DX, DY)
    m = kf.Surface.from_heights(arrays["b"], DX, DY, detrend="mean")
    with pytest.raises(ValueError, match="detrend"):
        kf.Surface.pair(a, m)
    s = kf.Surface.pair(a, m, detrend="mean")
    assert s.detrend == "mean" and s.parts[1] == m.stats
    with pytest.raises(ValueError, match="pair already"):
        kf.Surface.pair(s, a)
    with pytest.raises(ValueError):  # a profile with a map
        kf.Surface.pair(a, kf.Surface.from_heights(arrays["p"], 1e-6))
    with pytest.raises(TypeError, match="Surface"):
        kf.Surface.pair(a, arrays["b"])
    # intervals differing by more than 1 %: a warning in the record
    w = kf.Surface.pair(a, kf.Surface.from_heights(arrays["b"], DX * 1.1, DY)).stats["warnings"]
    assert "interval_mismatch" in [x["kind"] for x in w]


# ---- model, curve, friction ----------------------------------------------

CASES = [
    (["a"], "pearson", ["--force", "10", "--area", "1e-5"], dict(force=10.0, area=1e-5)),
    (["a"], "gaussian", ["--pressure", "3e5"], dict(pressure=3e5)),
    (["a"], "empirical", ["--force", "2", "--area", "1e-5"], dict(force=2.0, area=1e-5)),
    (["a", "b"], "pearson", ["--pressure", "1e6"], dict(pressure=1e6)),
    (["a", "b"], "empirical", ["--force", "10", "--area", "1e-5"], dict(force=10.0, area=1e-5)),
    (["p"], "weibull", ["--pressure", "1e6"], dict(pressure=1e6)),
]


def surface_of(paths, names):
    dx = ["--dx", "1e-6"] if names == ["p"] else ["--dx", str(DX), "--dy", str(DY)]
    read = [kf.Surface.read(paths[n], dx=1e-6) if n == "p" else kf.Surface.read(paths[n], dx=DX, dy=DY)
            for n in names]
    return (read[0] if len(read) == 1 else kf.Surface.pair(*read)), [paths[n] for n in names] + dx


@pytest.mark.parametrize("names, family, load_flags, load", CASES)
def test_model_curve_and_friction_equal_the_cli(files, names, family, load_flags, load):
    paths, _ = files
    s, args = surface_of(paths, names)
    ref = cli(*args, *FLAGS, "--distribution", family, *load_flags)
    m = s.model(**MATERIALS, distribution=family)
    assert m.distribution == family
    assert_same(m.params, ref["model"])
    f = s.friction(**load, **MATERIALS, distribution=family)
    assert_same(f, ref["friction"])
    c = m.at_f_star(ref["friction"]["f_star"])
    assert c.mu == pytest.approx(ref["friction"]["mu"], rel=SAME_REL)
    assert c.h_star == pytest.approx(ref["friction"]["h_star"], rel=SAME_REL)
    # the curve: the one of the CLI's model, to the bit
    p = ref["model"]
    cli_model = kf.Model(p["psi"], p["theta"], p["beta"], p["nu"], p["eps_star"], p["fit"], p["model"],
                         distribution=m.height_distribution)
    curve = s.curve(**MATERIALS, distribution=family, f_star_min=1e-4, f_star_max=1e-2)
    f_star = np.geomspace(1e-4, 1e-2, 50)
    assert curve.range == (1e-4, 1e-2)
    assert np.array_equal(curve.mu(f_star), kf.Curve.from_model(cli_model, 1e-4, 1e-2).mu(f_star))
    assert np.allclose(curve.mu(f_star), cli_model.at_f_star(f_star).mu, rtol=kf.CURVE_ACCURACY, atol=0)


def test_fit_and_model_kind_as_the_cli(files):
    paths, _ = files
    s, args = surface_of(paths, ["b"])
    ref = cli(*args, *FLAGS, "--fit", "as-printed", "--model", "ceb", "--pressure", "1e6")
    assert_same(s.model(**MATERIALS, fit="as-printed", model="ceb").params, ref["model"])
    assert_same(s.friction(pressure=1e6, **MATERIALS, fit="as-printed", model="ceb"), ref["friction"])


def test_height_distributions(files):
    _, arrays = files
    s = kf.Surface.from_heights(arrays["b"], DX, DY)
    st = s.stats
    p = s.height_distribution()
    assert p == kf.HeightDistribution.pearson(st["skewness"], st["kurtosis"])
    assert s.height_distribution("gaussian") == kf.HeightDistribution.gaussian()
    e = s.height_distribution("empirical")
    assert e.family == "empirical" and e.heights.size == arrays["b"].size
    assert abs(np.nanmean(e.heights)) < 1e-12 * np.nanmax(np.abs(arrays["b"]))  # the detrended heights
    assert e.skewness == pytest.approx(st["skewness"], rel=1e-9)


# ---- errors ----------------------------------------------------------------

@pytest.mark.parametrize("dx", [0.0, -1e-6, float("nan"), float("inf")])
def test_bad_intervals(files, dx):
    _, arrays = files
    with pytest.raises(ValueError, match="^dx = "):
        kf.Surface.from_heights(arrays["b"], dx)
    with pytest.raises(ValueError, match="^dy = "):
        kf.Surface.from_heights(arrays["b"], 1e-6, dx)
    with pytest.raises(ValueError, match="^dx = "):
        kf.Surface.read("whatever.npy", dx=dx)


def test_bad_arrays(files):
    _, arrays = files
    with pytest.raises(ValueError, match="3-D"):
        kf.Surface.from_heights(np.zeros((20, 20, 2)), 1e-6)
    with pytest.raises(ValueError, match="0-D|1-D"):
        kf.Surface.from_heights(np.zeros(()), 1e-6)
    with pytest.raises(TypeError):
        kf.Surface.from_heights("heights", 1e-6)
    with pytest.raises(TypeError):
        kf.Surface.from_heights(np.array(["a"] * 200), 1e-6)
    with pytest.raises(TypeError):
        kf.Surface.from_heights(arrays["b"], "1e-6")
    with pytest.raises(ValueError, match="nx = 10"):  # too few points along x
        kf.Surface.from_heights(arrays["b"][:, :10], DX, DY)
    with pytest.raises(ValueError, match="ny = 8"):
        kf.Surface.from_heights(arrays["b"][:8], DX, DY)
    with pytest.raises(ValueError, match="90 valid points"):  # too few valid points
        z = np.full(arrays["b"].shape, np.nan)
        keep = np.arange(90) * (z.size // 90)
        z.flat[keep] = arrays["b"].flat[keep]
        kf.Surface.from_heights(z, DX, DY)
    with pytest.raises(ValueError, match="infinite"):
        z = arrays["b"].copy()
        z[3, 4] = np.inf
        kf.Surface.from_heights(z, DX, DY)
    with pytest.raises(ValueError):  # constant heights
        kf.Surface.from_heights(np.ones((32, 32)), 1e-6)
    with pytest.raises(ValueError, match="dy"):
        kf.Surface.from_heights(arrays["p"], 1e-6, 1e-6)
    with pytest.raises(ValueError, match="detrend"):
        kf.Surface.from_heights(arrays["b"], DX, detrend="quadratic")
    with pytest.raises(ValueError, match="derivative"):
        kf.Surface.from_heights(arrays["b"], DX, derivative="spline")
    with pytest.raises(ValueError, match="missing"):  # spectral moments refuse missing points
        kf.Surface.from_heights(arrays["a"], DX, DY, derivative="spectral")


def test_bad_files(tmp_path, files):
    paths, _ = files
    bad = tmp_path / "bad.npy"
    bad.write_bytes(b"\x93NUMPY this is not an array")
    with pytest.raises(ValueError, match="bad.npy"):
        kf.Surface.read(bad, dx=1e-6)
    junk = tmp_path / "junk.x3p"
    junk.write_bytes(b"not a zip")
    with pytest.raises(ValueError, match="junk.x3p"):
        kf.Surface.read(junk)
    text = tmp_path / "words.txt"
    text.write_text("1 2 3\n4 five 6\n")
    with pytest.raises(ValueError, match="words.txt"):
        kf.Surface.read(text, dx=1e-6)
    with pytest.raises(OSError, match="nowhere.npy"):
        kf.Surface.read(tmp_path / "nowhere.npy", dx=1e-6)
    with pytest.raises(ValueError, match="dx"):  # .npy gives no interval
        kf.Surface.read(paths["b"])
    small = tmp_path / "small.npy"
    np.save(small, np.random.default_rng(0).normal(size=(8, 40)))
    with pytest.raises(ValueError, match="small.npy.*ny = 8"):
        kf.Surface.read(small, dx=1e-6)
    with pytest.raises(ValueError, match="z_unit"):
        kf.Surface.read(paths["b"], dx=1e-6, z_unit=0.0)
    with pytest.raises(ValueError, match="xy_unit"):
        kf.Surface.read(paths["b"], dx=1e-6, xy_unit=-1.0)
    with pytest.raises(ValueError, match="z_unit"):
        kf.Surface.read(paths["b"], dx=1e-6, z_unit=-1e-6)
    with pytest.raises(TypeError):
        kf.Surface.read(3, dx=1e-6)


def test_masked_points_are_missing_everywhere_heights_are_taken():
    """A masked array's mask marks missing points (NaN) in every entry that
    takes heights; the masked points' values (1 mm spikes here) are never
    used."""
    z = rough(64, 96, 21)
    mask = np.zeros(z.shape, bool)
    mask[np.random.default_rng(5).random(z.shape) < 0.01] = True
    mask[10, 20:24] = True
    spiky = z.copy()
    spiky[mask] = 1e-3  # 1 mm spikes on a ~0.1 um surface
    masked = np.ma.masked_array(spiky, mask=mask)
    nan = z.copy()
    nan[mask] = np.nan
    s = kf.Surface.from_heights(masked, DX, DY)
    ref = kf.Surface.from_heights(nan, DX, DY)
    assert s.stats["missing"] == mask.sum()
    assert_same(s.stats, ref.stats, rel=0)
    # Near the truth of the map without its spikes, nowhere near 1e-4 m.
    truth = kf.Surface.from_heights(z, DX, DY).stats["sigma"]
    assert s.stats["sigma"] == pytest.approx(truth, rel=0.05)
    assert s.stats["sigma"] < 2e-7
    # The caller's array is left as it was.
    assert np.array_equal(masked.data, spiky) and np.array_equal(masked.mask, mask)
    # A profile, and an integer dtype (masked points of no float value).
    p = rough(1, 600, 22)[0]
    pmask = np.zeros(p.shape, bool)
    pmask[::37] = True
    pnan = p.copy()
    pnan[pmask] = np.nan
    assert_same(kf.Surface.from_heights(np.ma.masked_array(np.where(pmask, 1e-3, p), mask=pmask), DX).stats,
                kf.Surface.from_heights(pnan, DX).stats, rel=0)
    ints = np.ma.masked_array((z * 1e9).astype(np.int64), mask=mask)
    ints.data[mask] = 10**6
    ref_nm = np.where(mask, np.nan, (z * 1e9).astype(np.int64).astype(np.float64))
    assert_same(kf.Surface.from_heights(ints, 1.0).stats, kf.Surface.from_heights(ref_nm, 1.0).stats, rel=0)
    # The empirical densities: HeightDistribution.empirical and Model's heights.
    d, dref = kf.HeightDistribution.empirical(masked), kf.HeightDistribution.empirical(nan)
    assert d == dref and np.array_equal(d.heights, dref.heights, equal_nan=True)
    assert d.moments() == dref.moments() and d.support == dref.support
    m = kf.Model(1.0, 0.001, heights=masked)
    assert m.height_distribution == dref
    # A mask of no points changes nothing.
    none = np.ma.masked_array(z, mask=np.zeros(z.shape, bool))
    assert_same(kf.Surface.from_heights(none, DX, DY).stats, kf.Surface.from_heights(z, DX, DY).stats, rel=0)
    assert_same(kf.Surface.from_heights(np.ma.masked_array(z), DX, DY).stats,
                kf.Surface.from_heights(z, DX, DY).stats, rel=0)


def test_a_fully_masked_array_is_a_clear_value_error():
    full = np.ma.masked_all((32, 40))
    with pytest.raises(ValueError, match="z: every point of the masked array is masked"):
        kf.Surface.from_heights(full, DX)
    with pytest.raises(ValueError, match="heights: every point of the masked array is masked"):
        kf.HeightDistribution.empirical(full)
    with pytest.raises(ValueError, match="heights: every point of the masked array is masked"):
        kf.Model(1.0, 0.001, heights=np.ma.masked_array(np.ones(200), mask=True))


@pytest.mark.parametrize("name", ["z_unit", "xy_unit"])
@pytest.mark.parametrize("value", [0.0, -1e-6, -1.0, math.inf, -math.inf, math.nan])
def test_read_refuses_units_not_finite_and_positive(files, name, value):
    paths, _ = files
    with pytest.raises(ValueError, match=rf"{name} = .* out of range: must be finite and > 0"):
        kf.Surface.read(paths["b"], dx=DX, dy=DY, **{name: value})


def test_read_max_points(tmp_path, files):
    paths, arrays = files
    points = arrays["b"].size  # 64 x 96
    s = kf.Surface.read(paths["b"], dx=DX, dy=DY, max_points=points)
    assert_same(s.stats, kf.Surface.read(paths["b"], dx=DX, dy=DY).stats, rel=0)
    assert kf.Surface.read(paths["b"], dx=DX, dy=DY, max_points=np.uint64(2**64 - 1)).stats["nx"] == 96
    with pytest.raises(ValueError, match=rf"b\.npy: .*{points} points, over the limit of {points - 1}.*max_points"):
        kf.Surface.read(paths["b"], dx=DX, dy=DY, max_points=points - 1)
    with pytest.raises(ValueError, match="over the limit of 100"):
        kf.Surface.read(paths["p"], dx=DX, max_points=100)
    text = tmp_path / "heights.txt"
    np.savetxt(text, arrays["b"][:20, :30] * 1e6)
    assert kf.Surface.read(text, dx=DX, dy=DY, z_unit=1e-6, max_points=600).stats["ny"] == 20
    with pytest.raises(ValueError, match="heights.txt.*over the limit of 599"):
        kf.Surface.read(text, dx=DX, dy=DY, z_unit=1e-6, max_points=599)
    for bad in [0, -5, 2**64]:
        with pytest.raises(ValueError, match="max_points"):
            kf.Surface.read(paths["b"], dx=DX, dy=DY, max_points=bad)
    for bad in [1e6, "1000", True]:
        with pytest.raises(TypeError, match="max_points"):
            kf.Surface.read(paths["b"], dx=DX, dy=DY, max_points=bad)


def test_model_and_friction_errors_name_the_keyword(files):
    _, arrays = files
    s = kf.Surface.from_heights(arrays["b"], DX, DY)
    for name, value in [("e1", -1.0), ("nu1", 0.7), ("hardness", 0.0), ("epsilon", float("nan")),
                        ("delta_gamma", -0.1)]:
        with pytest.raises(ValueError, match=f"^{name} = "):
            s.model(**{**MATERIALS, name: value})
    with pytest.raises(TypeError, match="e2"):
        s.model(**{**MATERIALS, "e2": "steel"})
    with pytest.raises(TypeError):
        s.model(**{k: v for k, v in MATERIALS.items() if k != "nu2"})
    with pytest.raises(ValueError, match="distribution"):
        s.model(**MATERIALS, distribution="lognormal")
    with pytest.raises(ValueError, match="fit"):
        s.model(**MATERIALS, fit="best")
    with pytest.raises(ValueError, match="^area: "):
        s.friction(force=1.0, **MATERIALS)
    with pytest.raises(ValueError, match="^force: "):
        s.friction(**MATERIALS)
    with pytest.raises(ValueError, match="^pressure: "):
        s.friction(force=1.0, area=1e-5, pressure=1e5, **MATERIALS)
    with pytest.raises(ValueError, match="^pressure = "):
        s.friction(pressure=-1.0, **MATERIALS)
    with pytest.raises(ValueError, match="^area = "):
        s.friction(force=1.0, area=0.0, **MATERIALS)
    with pytest.raises(ValueError, match="psi"):  # psi of these materials out of range
        s.model(**{**MATERIALS, "hardness": 1e3})


def test_a_measured_skewness_out_of_a_familys_range_names_it():
    # heights with a long upper tail: skewness beyond Weibull's 2
    rng = np.random.default_rng(4)
    z = rng.exponential(size=(64, 64)) ** 3 * 1e-8
    s = kf.Surface.from_heights(z, 1e-6, detrend="mean")
    assert s.stats["skewness"] > 2.5
    with pytest.raises(ValueError, match="^distribution: the surface's skewness.*empirical"):
        s.height_distribution("weibull")


# ---- pickling ---------------------------------------------------------------

def round_trips(x):
    return [pickle.loads(pickle.dumps(x, protocol=p)) for p in PROTOCOLS] + [copy.copy(x), copy.deepcopy(x)]


def test_surfaces_pickle_to_the_bit(files):
    paths, arrays = files
    surfaces = [kf.Surface.read(paths["a"], dx=DX, dy=DY, detrend="line"),
                kf.Surface.from_heights(arrays["p"], 1e-6, detrend="mean"),
                kf.Surface.from_heights(arrays["b"], DX, DY, detrend="mean", derivative="spectral")]
    surfaces.append(kf.Surface.pair(surfaces[0], kf.Surface.from_heights(arrays["b"], DX, DY, detrend="line")))
    for s in surfaces:
        for t in round_trips(s):
            assert t.stats == s.stats and t.parts == s.parts
            assert (t.detrend, t.derivative, t.is_pair) == (s.detrend, s.derivative, s.is_pair)
            for (h, *rest), (g, *more) in zip(s._core.topographies(), t._core.topographies()):
                assert h.tobytes() == g.tobytes() and rest == more
            assert repr(t) == repr(s)


@pytest.mark.parametrize("names", [["a"], ["a", "b"]])
def test_a_model_of_an_empirical_surface_distribution_pickles(files, names):
    paths, _ = files
    s, _ = surface_of(paths, names)
    m = s.model(**MATERIALS, distribution="empirical")
    d = m.height_distribution
    assert (d.heights is None) == (len(names) == 2)
    f_star = np.geomspace(1e-4, 1e-2, 20)
    mu = m.at_f_star(f_star).mu
    for n in round_trips(m):
        assert n.params == m.params and n.height_distribution == d
        assert np.array_equal(n.at_f_star(f_star).mu, mu)
    for e in round_trips(d):
        assert e == d and np.array_equal(e.pdf(np.linspace(-4, 4, 101)), d.pdf(np.linspace(-4, 4, 101)))
    # the model's empirical density is the surface's own, rebuilt the same
    assert pickle.loads(pickle.dumps(d)) == s.height_distribution("empirical")


# ---- SurfaceTopography -------------------------------------------------------

# (SurfaceTopography's rms_* functions warn of their own deprecation.)
@pytest.mark.filterwarnings("ignore::DeprecationWarning")
def test_from_topography_against_surfacetopography():
    st = pytest.importorskip("SurfaceTopography")
    z = rough(96, 128, 9)  # rows = y
    dx, dy = 0.5, 0.8  # micrometres
    t = st.Topography(z.T * 1e6, physical_sizes=(128 * dx, 96 * dy), unit="µm", periodic=False)
    s = kf.Surface.from_topography(t, detrend="mean")
    stats = s.stats
    assert (stats["nx"], stats["ny"]) == (128, 96)
    assert stats["dx"] == pytest.approx(dx * 1e-6, rel=1e-15) and stats["dy"] == pytest.approx(dy * 1e-6, rel=1e-15)
    assert stats["sigma"] == pytest.approx(t.rms_height_from_area() * 1e-6, rel=1e-12)
    plane = kf.Surface.from_topography(t).stats
    assert plane["sigma"] == pytest.approx(t.detrend("height").rms_height_from_area() * 1e-6, rel=1e-12)
    # SurfaceTopography's non-periodic gradient is taken on the (nx-1) x
    # (ny-1) points where both differences exist: a few 1/n apart
    assert math.sqrt(stats["m20"] + stats["m02"]) == pytest.approx(t.rms_gradient(), rel=0.02)
    gx, gy = t.derivative(1)
    assert stats["m20"] == pytest.approx(np.mean(gx ** 2), rel=0.03)
    assert stats["m02"] == pytest.approx(np.mean(gy ** 2), rel=0.03)
    assert stats["m02"] / stats["m20"] < 0.8  # an anisotropic surface: x and y not swapped
    # the same heights given in metres
    assert_same(s.stats, kf.Surface.from_heights(z, dx * 1e-6, dy * 1e-6, detrend="mean").stats, rel=1e-12,
                messages=False)
    # profiles: Rq, Rdq and Rddq exactly
    line = st.UniformLineScan(rough(1, 3000, 10)[0] * 1e9, physical_sizes=3000 * 2.0, unit="nm")
    p = kf.Surface.from_topography(line, detrend="mean").stats
    assert p["dx"] == pytest.approx(2e-9, rel=1e-15) and p["dy"] is None
    assert p["sigma"] == pytest.approx(line.rms_height_from_profile() * 1e-9, rel=1e-12)
    assert math.sqrt(p["m20"]) == pytest.approx(line.rms_slope_from_profile(), rel=1e-12)
    assert math.sqrt(p["m40"]) == pytest.approx(line.rms_curvature_from_profile() * 1e9, rel=1e-12)


def test_from_topography_keeps_masked_points_missing_and_units():
    st = pytest.importorskip("SurfaceTopography")
    z = rough(64, 80, 11)
    h = np.ma.masked_array(z.T * 1e3, mask=np.zeros(z.T.shape, bool))  # millimetres
    h.mask[5:9, 10:12] = True
    h.mask[40, 3] = True
    t = st.Topography(h, physical_sizes=(80 * 1e-3, 64 * 2e-3), unit="mm")
    s = kf.Surface.from_topography(t)
    assert s.stats["missing"] == 9
    ref = z.copy()
    ref[10:12, 5:9] = np.nan
    ref[3, 40] = np.nan
    assert_same(s.stats, kf.Surface.from_heights(ref, 1e-6, 2e-6).stats, rel=1e-12, messages=False)
    nounit = st.Topography(z.T, physical_sizes=(80.0, 64.0))
    with pytest.raises(ValueError, match="unit"):
        kf.Surface.from_topography(nounit)
    assert kf.Surface.from_topography(nounit, unit="um").stats["dx"] == pytest.approx(1e-6, rel=1e-15)
    with pytest.raises(ValueError, match="unit"):
        kf.Surface.from_topography(nounit, unit="furlong")
    with pytest.raises(TypeError):
        kf.Surface.from_topography(z)


def test_everything_public_is_documented():
    assert "Surface" in kf.__all__ and "Surface" in dir(kf)
    for attr, value in vars(kf.Surface).items():
        if not attr.startswith("_"):
            doc = getattr(value, "__doc__", None) or getattr(getattr(value, "__func__", None), "__doc__", None)
            assert doc and len(doc) > 40, attr


@pytest.mark.parametrize("z_type", ["INT16", "INT32", "FLOAT32", "FLOAT64"])
@pytest.mark.parametrize("storage", ["BINARY", "XML"])
@pytest.mark.parametrize("revision", ["ISO5436_2000", "ISO25178_72_2017_DAM1"])
def test_x3p_files_of_another_writer(tmp_path, z_type, storage, revision):
    """X3P files written by an independent implementation (x3pio, PyPI):
    every z type, binary or XML point data, both revisions of the
    standard, dx != dy, a missing point. Surface.read gives the statistics
    of the heights x3pio itself reads back (as stored: quantised for the
    integer types), bit for bit."""
    x3pio = pytest.importorskip("x3pio")
    rng = np.random.default_rng(7)
    ny, nx = 40, 56
    y, x = np.mgrid[0:ny, 0:nx]
    z = 1e-7 * (np.sin(0.3 * x) + np.cos(0.21 * y) + 0.5 * np.sin(0.17 * x - 0.4 * y)) + 2e-8 * rng.normal(size=(ny, nx))
    z[5, 7] = np.nan
    path = tmp_path / f"{z_type}-{storage}-{revision}.x3p"
    x3pio.write(path, z, x_scale=2e-6, y_scale=3e-6, z_type=x3pio.DataType[z_type],
                storage=x3pio.DataStorage[storage], revision=x3pio.Revision[revision])
    stored = np.asarray(x3pio.read(path).layers[0].z, dtype=np.float64)
    assert stored.shape == (ny, nx) and np.isnan(stored[5, 7])
    got = kf.Surface.read(path)
    want = kf.Surface.from_heights(stored, 2e-6, 3e-6)
    assert got.stats == want.stats
    assert (got.stats["nx"], got.stats["ny"], got.stats["missing"]) == (nx, ny, 1)


def test_sensitivity_values_are_the_single_runs(files):
    """Each mu of Surface.friction's "sensitivity" is the single run with
    that option: each height model, each end of the band (filtered at
    that lambda_s); sensitivity=False leaves it out."""
    paths, _ = files
    s = kf.Surface.read(paths["b"], dx=DX, dy=DY)
    f = s.friction(pressure=1e6, **MATERIALS)
    sens = f["sensitivity"]
    assert sorted(sens["distribution"]) == ["empirical", "gaussian", "pearson"]
    for family, outcome in sens["distribution"].items():
        single = s.friction(pressure=1e6, **MATERIALS, distribution=family, sensitivity=False)
        assert "sensitivity" not in single
        assert outcome["mu"] == pytest.approx(single["mu"], rel=1e-12, abs=0), family
    assert len(sens["lambda_s"]) == 2
    assert sens["lambda_s"][0]["lambda_s"] == pytest.approx(2 * max(DX, DY), rel=1e-15)
    for end in sens["lambda_s"]:
        single = s.filtered(lambda_s=end["lambda_s"]).friction(pressure=1e6, **MATERIALS, sensitivity=False)
        assert end["mu"] == pytest.approx(single["mu"], rel=1e-12, abs=0), end
