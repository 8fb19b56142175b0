"""The instruments' own formats, part b (Zygo MetroPro .dat, Bruker
Nanoscope, Nanosurf .nid) against SurfaceTopography, an independent reader
of the same files.

For each real file of ``../shared/topographies/`` (the folder
``KEF_TOPOGRAPHIES`` names, else ``shared/topographies`` beside the
repository): ``Surface.read`` gives the same grid, physical sizes and
heights (and missing points) as SurfaceTopography's
``read_topography(path).to_unit('m')`` to 1e-12 relative, and the
plane-detrended statistics of ``kefric surface FILE --json`` (sigma, Sk, K,
m2, m4, beta) agree with tools/surface_reference.py (NumPy) on
SurfaceTopography's heights to 1e-9. Skipped, with the reason, where
SurfaceTopography, the files or the CLI are absent.
"""

import numpy as np
import pytest

import ke_friction as kf
from conftest import instrument_file, kefric, surface_reference

#: The files of this part, and the channel each reads by default.
FILES = {
    "metropro-1.dat": None,
    "di-1.di": "Height",
    "di-3.di": "ZSensor",
    "nid-1.nid": "Scan forward (Z-Axis)",
}

#: Heights, sizes: the same numbers in another order of operations.
READ_REL = 1e-12
#: The statistics: two implementations' sums in other orders.
STATS_REL = 1e-9


def _surface_topography(path):
    """SurfaceTopography's reading in metres: heights as a (ny, nx) array
    (rows = y, NaN = masked) and the intervals."""
    st = pytest.importorskip("SurfaceTopography", reason="SurfaceTopography is not installed")
    t = st.read_topography(str(path)).to_unit("m")
    h = t.heights()
    z = np.ma.filled(np.ma.masked_invalid(np.ma.asarray(h, dtype=float)), np.nan).T
    (nx, ny), (sx, sy) = t.nb_grid_pts, t.physical_sizes
    return z, (nx, ny), (sx, sy)


@pytest.mark.parametrize("name", sorted(FILES))
def test_heights_match_surface_topography(name):
    path = instrument_file(name)
    z, (nx, ny), (sx, sy) = _surface_topography(path)
    s = kf.Surface.read(path)
    [(h, gx, gy, dx, dy)] = s._core.topographies()
    assert (gx, gy) == (nx, ny)
    np.testing.assert_allclose([gx * dx, gy * dy], [sx, sy], rtol=READ_REL, atol=0)
    ours = np.asarray(h, dtype=float).reshape(gy, gx)
    np.testing.assert_array_equal(np.isnan(ours), np.isnan(z))
    valid = ~np.isnan(z)
    scale = np.abs(z[valid]).max()
    np.testing.assert_allclose(ours[valid], z[valid], rtol=READ_REL, atol=READ_REL * scale)
    [meta] = s.metadata
    assert meta.get("channel") == FILES[name]
    assert meta["format"] in ("metropro", "nanoscope", "nid")


@pytest.mark.parametrize("name", sorted(FILES))
def test_statistics_match_numpy_on_surface_topography_heights(name):
    path = instrument_file(name)
    z, (nx, ny), (sx, sy) = _surface_topography(path)
    want = surface_reference().stats(z, sx / nx, sy / ny, detrend="plane", derivative="fd")
    [record] = kefric("surface", str(path))
    got = record["surface"]
    assert (got["nx"], got["ny"], got["missing"]) == (want["nx"], want["ny"], want["missing"])
    for key in ("sigma", "skewness", "kurtosis", "m2", "m4", "beta"):
        assert got[key] == pytest.approx(want[key], rel=STATS_REL, abs=0), key
    assert record["metadata"][0]["format"] in ("metropro", "nanoscope", "nid")
