"""The scale a surface is looked at: the S- and L-filters (``lambda_s``,
``lambda_c``, ``"auto"``, the reliability cut-off and its warning),
:meth:`Surface.filtered`, :meth:`Surface.psd`, :meth:`Surface.scan`,
:meth:`Surface.scale_dependent` and :meth:`Surface.reliability_cutoff`,
against the CLI (``kefric surface --json``, ``--psd``, ``--scan`` on the
same .npy files and options) and SurfaceTopography."""

import math
import pickle
import re

import numpy as np
import pytest
from conftest import SAME_REL, kefric

import ke_friction as kf

MATERIALS = dict(e1=70e9, nu1=0.33, e2=200e9, nu2=0.31, hardness=1e9, delta_gamma=0.5, epsilon=0.4e-9)
FLAGS = ["--e1", "70e9", "--nu1", "0.33", "--e2", "200e9", "--nu2", "0.31", "--hardness", "1e9",
         "--delta-gamma", "0.5", "--epsilon", "0.4e-9"]
DX, DY = 0.5e-6, 0.8e-6
#: SurfaceTopography against the library's PSD (tools/psd_check.py): REL
#: point by point, or FLOOR of the largest C (two different FFTs' rounding).
PSD_REL, PSD_FLOOR = 1e-10, 1e-14


def rough(shape, seed, hurst=0.8):
    """Self-affine-looking random heights (metres, ~0.1 um rms) with a tilt:
    a profile for a 1-tuple shape, else a map (rows = y)."""
    rng = np.random.default_rng(seed)
    spectrum = np.fft.fftn(rng.normal(size=shape))
    q = np.sqrt(sum(np.meshgrid(*[np.fft.fftfreq(n) ** 2 for n in shape], indexing="ij")))
    q[(0,) * len(shape)] = 1.0
    z = np.fft.ifftn(spectrum * q ** (-1 - hurst)).real
    z = 1e-7 * z / z.std() + 1e-9 * np.arange(shape[-1])
    return z


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    """A map (dx != dy) and a profile as .npy files, with their arrays."""
    d = tmp_path_factory.mktemp("scale")
    arrays = {"map": rough((96, 128), 11), "profile": rough((1500,), 12)}
    paths = {}
    for name, z in arrays.items():
        paths[name] = str(d / f"{name}.npy")
        np.save(paths[name], z)
    return paths, arrays


def grid(name):
    """The CLI's interval flags and the Python keywords of file ``name``."""
    if name == "map":
        return ["--dx", repr(DX), "--dy", repr(DY)], dict(dx=DX, dy=DY)
    return ["--dx", repr(DX)], dict(dx=DX)


def cli(*args):
    (record,) = kefric("surface", *args)
    return record


def assert_same(python, reference, rel=SAME_REL):
    """Two records equal: the same names, numbers within ``rel``."""
    if isinstance(reference, dict):
        assert isinstance(python, dict) and python.keys() == reference.keys(), (python, reference)
        for k in reference:
            assert_same(python[k], reference[k], rel)
    elif isinstance(reference, list):
        assert isinstance(python, list) and len(python) == len(reference)
        for x, y in zip(python, reference):
            assert_same(x, y, rel)
    elif isinstance(reference, float) and not isinstance(python, (bool, str)):
        assert python == pytest.approx(reference, rel=rel, abs=0), (python, reference)
    else:
        assert python == reference


# ---- the filters ---------------------------------------------------------

@pytest.mark.parametrize("name", ["map", "profile"])
@pytest.mark.parametrize("lambda_s, lambda_c", [(2e-6, None), (None, 20e-6), (1.7e-6, 25e-6)])
def test_filtered_stats_equal_the_cli(files, name, lambda_s, lambda_c):
    paths, arrays = files
    flags, kw = grid(name)
    extra = (["--lambda-s", repr(lambda_s)] if lambda_s else []) + (["--lambda-c", repr(lambda_c)] if lambda_c else [])
    ref = cli(paths[name], *flags, *extra, *FLAGS, "--pressure", "1e6")
    read = kf.Surface.read(paths[name], **kw, lambda_s=lambda_s, lambda_c=lambda_c)
    heights = kf.Surface.from_heights(arrays[name], **kw, lambda_s=lambda_s, lambda_c=lambda_c)
    later = kf.Surface.read(paths[name], **kw).filtered(lambda_s=lambda_s, lambda_c=lambda_c)
    for s in (read, heights, later):
        stats = s.stats
        assert_same(stats, ref["surface"])
        assert (stats["lambda_s"], stats["lambda_c"]) == (lambda_s, lambda_c) == (s.lambda_s, s.lambda_c)
        assert stats["size_x"] == pytest.approx(arrays[name].shape[-1] * DX)
        assert (stats["size_y"] is None) == (name == "profile")
        assert_same(s.friction(pressure=1e6, **MATERIALS), ref["friction"])
        assert s.detrend == "plane" and s.derivative == "fd"
    # Unfiltered again: the plain surface.
    assert_same(later.filtered().stats, kf.Surface.read(paths[name], **kw).stats)


def test_filtered_keeps_detrend_and_derivative(files):
    paths, arrays = files
    s = kf.Surface.from_heights(arrays["map"], DX, DY, detrend="line", derivative="spectral")
    f = s.filtered(lambda_s=3e-6)
    assert (f.detrend, f.derivative) == ("line", "spectral") and repr(f).endswith("lambda_s=3e-06)")
    assert_same(f.stats, kf.Surface.from_heights(arrays["map"], DX, DY, detrend="line", derivative="spectral",
                                                 lambda_s=3e-6).stats)
    # Its heights are the same: unfiltered again, the same statistics.
    assert f.filtered().stats == s.stats


@pytest.mark.parametrize("name", ["map", "profile"])
@pytest.mark.parametrize("instrument", [("--resolution", 2.2e-6), ("--tip-radius", 2e-6), ("--tip-radius", 1e-5),
                                        ("--tip-radius", 1e-4)])
def test_auto_is_the_reliability_cutoff_as_the_cli(files, name, instrument):
    paths, arrays = files
    flags, kw = grid(name)
    flag, value = instrument
    key = flag[2:].replace("-", "_")
    ref = cli(paths[name], *flags, "--lambda-s", "auto", flag, repr(value))
    s = kf.Surface.read(paths[name], **kw, lambda_s="auto", **{key: value})
    assert_same(s.stats, ref["surface"])
    expected = value if key == "resolution" else s.reliability_cutoff(value)
    assert s.lambda_s == expected == s.cutoff
    assert_same(kf.Surface.from_heights(arrays[name], **kw, lambda_s="auto", **{key: value}).stats,
                ref["surface"])
    # The warning without the filter: the cut-off known, the scale below it.
    plain_ref = cli(paths[name], *flags, flag, repr(value))
    plain = kf.Surface.read(paths[name], **kw, **{key: value})
    assert_same(plain.stats, plain_ref["surface"])
    kinds = [w["kind"] for w in plain.stats["warnings"]]
    assert ("unreliable_scale" in kinds) == (expected is not None and expected > 2 * max(kw.values()))
    # filtered("auto") uses the surface's cut-off.
    assert_same(plain.filtered(lambda_s="auto").stats, ref["surface"])


def test_auto_beyond_the_scan_size_is_refused(files):
    paths, _ = files
    # A 1 mm tip distorts the map up to 7.04e-5 m, more than its 6.4e-5 m side.
    cut = kf.Surface.read(paths["map"], dx=DX, dy=DY).reliability_cutoff(1e-3)
    assert cut > 128 * DX
    with pytest.raises(ValueError, match="lambda_s") as e:
        kf.Surface.read(paths["map"], dx=DX, dy=DY, lambda_s="auto", tip_radius=1e-3)
    assert any(math.isclose(x, cut, rel_tol=1e-12) for x in numbers_in(str(e.value)))


def test_the_unreliable_warning_names_the_scale_and_the_cutoff(files):
    paths, arrays = files
    s = kf.Surface.from_heights(arrays["map"], DX, DY, resolution=5e-6)
    (w,) = [w for w in s.stats["warnings"] if w["kind"] == "unreliable_scale"]
    assert w["cutoff"] == 5e-6 and w["scale"] == 2 * DY
    # Filtered at the cut-off: no warning.
    assert all(w["kind"] != "unreliable_scale" for w in s.filtered(lambda_s=5e-6).stats["warnings"])
    assert all(w["kind"] != "unreliable_scale" for w in s.filtered(lambda_s="auto").stats["warnings"])


def numbers_in(message):
    return [float(x) for x in re.findall(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)", message)]


@pytest.mark.parametrize("name", ["map", "profile"])
def test_bad_lambda_s_names_both_numbers(files, name):
    paths, arrays = files
    _, kw = grid(name)
    shortest = 2 * max(kw.values())
    size = arrays[name].shape[-1] * DX if name == "profile" else min(128 * DX, 96 * DY)
    for bad, limit in ((0.75 * shortest, shortest), (1.5 * size, size)):
        for make in (lambda: kf.Surface.read(paths[name], **kw, lambda_s=bad),
                     lambda: kf.Surface.from_heights(arrays[name], **kw, lambda_s=bad),
                     lambda: kf.Surface.from_heights(arrays[name], **kw).filtered(lambda_s=bad)):
            with pytest.raises(ValueError, match="lambda_s") as e:
                make()
            got = numbers_in(str(e.value))
            assert any(math.isclose(x, bad, rel_tol=1e-12) for x in got), (str(e.value), bad)
            assert any(math.isclose(x, limit, rel_tol=1e-12) for x in got), (str(e.value), limit)
    with pytest.raises(ValueError, match="lambda_c"):
        kf.Surface.from_heights(arrays[name], **kw, lambda_c=2 * size)
    with pytest.raises(ValueError, match="auto"):
        kf.Surface.from_heights(arrays[name], **kw, lambda_s="auto")
    with pytest.raises(ValueError, match="lambda_s"):
        kf.Surface.from_heights(arrays[name], **kw, lambda_s="fine")
    with pytest.raises(TypeError):
        kf.Surface.from_heights(arrays[name], **kw, lambda_c="1e-6")
    with pytest.raises(ValueError, match="resolution"):
        kf.Surface.from_heights(arrays[name], **kw, resolution=-1.0)


def test_filtered_surfaces_pickle_to_the_bit(files):
    paths, arrays = files
    for s in (kf.Surface.read(paths["map"], dx=DX, dy=DY, lambda_s=2e-6, lambda_c=30e-6, resolution=3e-6),
              kf.Surface.read(paths["profile"], dx=DX, lambda_s="auto", tip_radius=1e-3),
              kf.Surface.read(paths["profile"], dx=DX, tip_radius=2e-6)):
        for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
            t = pickle.loads(pickle.dumps(s, protocol))
            assert t.stats == s.stats and (t.lambda_s, t.lambda_c, t.cutoff) == (s.lambda_s, s.lambda_c, s.cutoff)
            assert t.filtered(lambda_s="auto").stats == s.filtered(lambda_s="auto").stats


def test_a_pair_of_filtered_surfaces(files):
    _, arrays = files
    a = kf.Surface.from_heights(arrays["map"], DX, DY, lambda_s=2e-6)
    b = kf.Surface.from_heights(arrays["map"][::-1], DX, DY, lambda_s=2e-6)
    p = kf.Surface.pair(a, b)
    assert p.lambda_s == 2e-6 and p.stats["lambda_s"] == 2e-6
    assert p.filtered(lambda_s=4e-6).stats == kf.Surface.pair(a.filtered(lambda_s=4e-6),
                                                               b.filtered(lambda_s=4e-6)).stats
    with pytest.raises(ValueError, match="filtered differently"):
        kf.Surface.pair(a, b.filtered())


# ---- the power spectral density ------------------------------------------

@pytest.mark.parametrize("name", ["map", "profile"])
@pytest.mark.parametrize("window", ["none", "hann"])
def test_psd_equals_the_cli(files, name, window):
    paths, _ = files
    flags, kw = grid(name)
    ref = cli(paths[name], *flags, "--psd", *(["--hann"] if window == "hann" else []))
    # The filters change nothing: the PSD is of the detrended, unfiltered heights.
    got = kf.Surface.read(paths[name], **kw, lambda_s=2e-6).psd(window)
    assert set(got) == ({"x"} if name == "profile" else {"x", "y", "area"})
    for k, (q, c) in got.items():
        assert isinstance(q, np.ndarray) and q.dtype == np.float64 and q.shape == c.shape
        np.testing.assert_allclose(q, ref[k]["q"], rtol=SAME_REL, atol=0)
        np.testing.assert_allclose(c, ref[k]["c"], rtol=SAME_REL, atol=0)


def close_psd(got, want):
    got, want = np.asarray(got, float), np.asarray(want, float)
    assert got.shape == want.shape
    diff = np.abs(got - want)
    assert np.all((diff <= PSD_REL * np.abs(want)) | (diff <= PSD_FLOOR * np.abs(want).max())), \
        np.max(diff / np.abs(want))


@pytest.mark.parametrize("name", ["map", "profile"])
@pytest.mark.parametrize("window", ["none", "hann"])
def test_psd_against_surfacetopography(files, name, window):
    st = pytest.importorskip("SurfaceTopography")
    paths, _ = files
    _, kw = grid(name)
    s = kf.Surface.read(paths[name], **kw)
    (h, _), = s._core.empirical_parts()  # the library's detrended heights
    got = s.psd(window)
    win = "hann" if window == "hann" else "None"
    if name == "profile":
        t = st.UniformLineScan(h, h.size * DX, periodic=False)
        want = {"x": t.power_spectrum_from_profile(window=win, reliable=False, resampling_method=None)}
    else:
        h = h.reshape(96, 128)
        t = st.Topography(h.T.copy(), (128 * DX, 96 * DY), periodic=False)
        ty = st.Topography(h.copy(), (96 * DY, 128 * DX), periodic=False)
        q, c = t.power_spectrum_from_area(window=win, reliable=False)
        want = {"x": t.power_spectrum_from_profile(window=win, reliable=False, resampling_method=None),
                "y": ty.power_spectrum_from_profile(window=win, reliable=False, resampling_method=None),
                "area": (np.ma.compressed(q), np.ma.compressed(c))}
    for k, (q, c) in want.items():
        close_psd(got[k][0], q)
        close_psd(got[k][1], c)


def test_psd_of_missing_points_is_of_the_largest_complete_rectangle(tmp_path):
    # Issue 49: psd() refused any file with missing points; now the largest
    # complete rectangle, said so, as kefric --psd.
    z = rough((96, 128), 13)
    z[:10, :] = np.nan          # rows 0-9 missing
    z[50, 100] = np.nan         # one point: the rectangle is rows 10-95, columns 0-99
    path = tmp_path / "holes.npy"
    np.save(path, z)
    s = kf.Surface.read(str(path), dx=DX, dy=DY)
    with pytest.warns(UserWarning, match=r"1281 missing points: .* largest complete rectangle, 100 × 86 points"):
        got = s.psd()
    want = kf.Surface.from_heights(z[10:, :100], DX, DY).psd()
    for k in ("x", "y", "area"):
        np.testing.assert_array_equal(got[k][0], want[k][0])
        np.testing.assert_array_equal(got[k][1], want[k][1])
    ref = cli(str(path), "--dx", repr(DX), "--dy", repr(DY), "--psd")
    for k in ("x", "y", "area"):
        np.testing.assert_allclose(got[k][1], ref[k]["c"], rtol=SAME_REL, atol=0)


def test_psd_refuses_a_pair_and_a_bad_window(files):
    _, arrays = files
    s = kf.Surface.from_heights(arrays["map"], DX, DY)
    with pytest.raises(ValueError, match="window"):
        s.psd("hamming")
    with pytest.raises(ValueError, match="pair"):
        kf.Surface.pair(s, s).psd()


# ---- the scan --------------------------------------------------------------

SCAN_STATS = ("sigma", "skewness", "kurtosis", "m2", "m4", "alpha", "eta", "radius", "beta")


def column(rows, group, name):
    return np.array([np.nan if r.get(group, {}).get(name) is None else r[group][name] for r in rows])


@pytest.mark.parametrize("name", ["map", "profile"])
def test_scan_equals_the_cli(files, name):
    paths, _ = files
    flags, kw = grid(name)
    ref = cli(paths[name], *flags, "--scan", "--per-decade", "4", "--lambda-c", "40e-6", "--resolution", "3e-6",
              *FLAGS, "--force", "10", "--area", "1e-5")
    s = kf.Surface.read(paths[name], **kw, lambda_c=40e-6)
    got = s.scan(per_decade=4, resolution=3e-6, force=10, area=1e-5, **MATERIALS)
    rows = ref["rows"]
    assert got["cutoff"] == ref["cutoff"] == 3e-6
    np.testing.assert_allclose(got["lambda_s"], [r["lambda_s"] for r in rows], rtol=SAME_REL, atol=0)
    assert got["reliable"].dtype == bool
    assert list(got["reliable"]) == [r["reliable"] for r in rows]
    assert not got["reliable"].all() and got["reliable"].any()
    failed = [i for i, r in enumerate(rows) if "error" in r]
    assert [i for i, _, _ in got["errors"]] == failed
    ok = [i for i in range(len(rows)) if i not in failed]
    assert ok
    for c in SCAN_STATS:
        np.testing.assert_allclose(got[c][ok], column(rows, "surface", c)[ok], rtol=SAME_REL, atol=0)
    for c in ("psi", "theta"):
        np.testing.assert_allclose(got[c][ok], column(rows, "model", c)[ok], rtol=SAME_REL, atol=0)
    for c in ("pressure", "mu", "friction_force", "separation"):
        np.testing.assert_allclose(got[c][ok], column(rows, "friction", c)[ok], rtol=SAME_REL, atol=0)
    for c in [k for k, v in got.items() if isinstance(v, np.ndarray) and v.dtype != bool]:
        assert np.isnan(got[c][failed]).all() if c != "lambda_s" else True


def test_scan_rows_equal_the_single_surface(files):
    paths, _ = files
    s = kf.Surface.read(paths["map"], dx=DX, dy=DY, tip_radius=5e-6)
    got = s.scan(from_=1.7e-6, to=9e-6, per_decade=3, pressure=1e6, **MATERIALS)
    assert got["lambda_s"][0] == 1.7e-6 and got["lambda_s"][-1] == 9e-6 and len(got["lambda_s"]) == 4
    assert got["cutoff"] == s.cutoff
    assert not got["errors"]
    for i, lambda_s in enumerate(got["lambda_s"]):
        one = kf.Surface.read(paths["map"], dx=DX, dy=DY, tip_radius=5e-6, lambda_s=float(lambda_s))
        for c in SCAN_STATS:
            assert got[c][i] == one.stats[c]
        f = one.friction(pressure=1e6, **MATERIALS)
        assert got["mu"][i] == f["mu"] and np.isnan(got["friction_force"][i])
        assert got["psi"][i] == one.model(**MATERIALS).params["psi"]
        assert got["reliable"][i] == (s.cutoff is None or lambda_s >= s.cutoff * (1 - 1e-12))


def test_scan_without_materials_and_its_errors(files):
    paths, _ = files
    s = kf.Surface.read(paths["profile"], dx=DX)
    got = s.scan(per_decade=2)
    assert set(got) == {"lambda_s", "reliable", *SCAN_STATS, "cutoff", "errors"}
    assert got["cutoff"] is None and got["reliable"].all()
    assert got["lambda_s"][0] == pytest.approx(2 * DX) and got["lambda_s"][-1] == pytest.approx(1500 * DX / 10)
    # Below the shortest sampled wavelength: rows with no result.
    low = s.scan(from_=0.5 * DX, to=4 * DX, per_decade=10)
    assert low["errors"] and all("lambda_s" in m or "lambda" in m for _, _, m in low["errors"])
    assert np.isnan(low["sigma"][[i for i, _, _ in low["errors"]]]).all()
    with pytest.raises(ValueError, match="out of range"):
        s.scan(from_=1e-5, to=1e-6)
    with pytest.raises(ValueError, match="per_decade"):
        s.scan(per_decade=0)
    with pytest.raises(ValueError, match="materials"):
        s.scan(pressure=1e6)
    with pytest.raises(ValueError, match="hardness"):
        s.scan(**{k: v for k, v in MATERIALS.items() if k != "hardness"})


# ---- scale-dependent slope and curvature -------------------------------------

def test_scale_dependent_of_a_line_and_a_parabola():
    x = np.arange(400) * 1e-6
    # A slope of 0.1 under roughness enough for the statistics (a bare line
    # has no summits); detrend="mean" keeps the slope (the default, a line
    # fit, removes it).
    h = 0.1 * x + 1e-8 * np.random.default_rng(1).standard_normal(400)
    line = kf.Surface.from_heights(h, 1e-6, detrend="mean")
    got = line.scale_dependent([1e-6, 3e-6, 2.5e-6, 10e-6])
    assert set(got) == {"distance", "x"}
    centred = h - h.mean()
    want = [np.sqrt(np.mean(((centred[k:] - centred[:-k]) / (k * 1e-6)) ** 2)) for k in (1, 3)]
    np.testing.assert_allclose(got["x"][:2], want, rtol=1e-12)
    np.testing.assert_allclose(got["x"], 0.1, rtol=0.05)
    bowl = kf.Surface.from_heights(rough((96, 128), 21), DX, DY)
    d = bowl.scale_dependent(order=2)["distance"]
    assert d[0] == pytest.approx(2 * DY) and d[-1] == pytest.approx(128 * DX / 2) and np.all(np.diff(d) > 0)
    with pytest.raises(ValueError, match="order"):
        bowl.scale_dependent(order=3)
    with pytest.raises(ValueError, match="distance"):
        bowl.scale_dependent([-1e-6])


def test_scale_dependent_is_of_the_detrended_heights():
    # Issue 49: at one interval the rms slope is sqrt(m20) of the statistics
    # (the heights detrended as they are), not of the tilted heights.
    x = np.arange(500) * DX
    h = 3.0 * x + rough((500,), 5)
    s = kf.Surface.from_heights(h, DX)
    one = s.scale_dependent([DX])["x"][0]
    assert one == pytest.approx(math.sqrt(s.stats["m20"]), rel=1e-10)
    # The tilted heights' own slope at one interval (what was measured before).
    assert np.sqrt(np.mean((np.diff(h) / DX) ** 2)) > 1.2 * one
    z = rough((96, 128), 9) + 0.2 * (np.arange(128) * DX)[None, :]
    m = kf.Surface.from_heights(z, DX, DY)
    got = m.scale_dependent([DX])["x"][0]
    # A map's stencils also drop its last row.
    assert got == pytest.approx(math.sqrt(m.stats["m20"]), rel=2e-2)


def test_auto_without_a_cutoff_warns(files):
    _, arrays = files
    with pytest.warns(UserWarning, match="tip_radius 1e-8 m distorts no scale"):
        s = kf.Surface.from_heights(arrays["map"], DX, DY, lambda_s="auto", tip_radius=1e-8)
    assert s.lambda_s is None


def test_filtered_auto_without_a_cutoff_warns_as_the_cli(files):
    # Surface.filtered(lambda_s="auto") of a surface whose tip distorts no
    # scale warns the core's note, as the CLI and from_heights do (issue 49).
    _, arrays = files
    s = kf.Surface.from_heights(arrays["map"], DX, DY, tip_radius=1e-8)
    with pytest.warns(UserWarning, match=r"the surface: lambda_s auto: tip_radius 1e-8 m distorts no scale "
                                         r"of these data \(reliability cut-off: none\): no S-filter applied"):
        f = s.filtered(lambda_s="auto")
    assert f.lambda_s is None
    # Its filtered surface keeps the tip: asked again, it warns again.
    with pytest.warns(UserWarning, match="distorts no scale"):
        f.filtered(lambda_s="auto")
    # A length, or a surface made without a tip, warns nothing of it.
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        s.filtered(lambda_s=4 * DX)
        with pytest.raises(ValueError):
            kf.Surface.from_heights(arrays["map"], DX, DY).filtered(lambda_s="auto")


@pytest.mark.parametrize("order", [1, 2])
def test_scale_dependent_against_surfacetopography(files, order):
    st = pytest.importorskip("SurfaceTopography")
    _, arrays = files
    z = arrays["map"]
    t = st.Topography(z.T.copy(), (128 * DX, 96 * DY), periodic=False)  # ST: first axis = x
    distances = np.array([DX, 2 * DY, 2.5e-6, 7.3e-6, 20e-6]) * order
    _, want = t.scale_dependent_statistical_property(lambda x, y: np.array([np.mean(x * x), np.mean(y * y)]),
                                                     n=order, distance=distances, reliable=False)
    got = kf.Surface.from_heights(z, DX, DY, detrend="mean").scale_dependent(distances, order=order)
    np.testing.assert_allclose(got["x"], np.sqrt(np.asarray(want)[:, 0]), rtol=1e-10)
    np.testing.assert_allclose(got["y"], np.sqrt(np.asarray(want)[:, 1]), rtol=1e-10)
    cut = kf.Surface.from_heights(z, DX, DY).reliability_cutoff(1e-4)
    assert cut == pytest.approx(t.scanning_probe_reliability_cutoff(1e-4, 0.5), rel=1e-6)


def test_reliability_cutoff(files):
    _, arrays = files
    s = kf.Surface.from_heights(arrays["profile"], DX)
    small, large = s.reliability_cutoff(1e-9), s.reliability_cutoff(1e-2)
    assert small is None or small < large
    assert 2 * DX <= large
    assert s.reliability_cutoff(1e-2, 0.5) == large
    with pytest.raises(ValueError, match="tip radius"):
        s.reliability_cutoff(-1.0)
    missing = arrays["profile"].copy()
    missing[7] = np.nan
    with pytest.raises(ValueError, match="missing"):
        kf.Surface.from_heights(missing, DX).reliability_cutoff(1e-6)


def test_from_topography_takes_the_filters(files):
    st = pytest.importorskip("SurfaceTopography")
    _, arrays = files
    z = arrays["map"]
    t = st.Topography(z.T.copy(), (128 * DX, 96 * DY), periodic=False, unit="m")
    s = kf.Surface.from_topography(t, lambda_s="auto", lambda_c=30e-6, tip_radius=1e-4)
    ref = kf.Surface.from_heights(z, DX, DY, lambda_s="auto", lambda_c=30e-6, tip_radius=1e-4)
    assert s.stats == ref.stats and s.lambda_s == ref.cutoff
