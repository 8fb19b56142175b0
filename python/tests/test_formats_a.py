"""The instruments' own formats, part a: Digital Surf .sur, Sensofar .plu,
Bruker/Veeco .opd and Alicona .al3d, read by the library's readers and by
SurfaceTopography's (the oracle) from the real files of its test suite.

The files: $KEF_TOPOGRAPHIES, else ``../shared/topographies`` beside the
repository (sur-2.sur, plu-1.plu, opd-1.opd, al3d-1.al3d). The library's
raw reading (grid, heights, missing points) comes from the example
``read_dump`` (``cargo build --release --features topography --example
read_dump``; $KEF_READ_DUMP, else beside $KEFRIC); the statistics from
``ke_friction.Surface.read`` and ``kefric surface FILE --json``, against
the independent NumPy statistics of tools/surface_reference.py on
SurfaceTopography's heights. Each test skips, saying why, when
SurfaceTopography, the files or the programs are absent.
"""

import json
import os
import pathlib
import subprocess
import warnings

import numpy as np
import pytest

import ke_friction as kf

from conftest import KEFRIC, instrument_file, surface_reference

#: Heights and intervals against SurfaceTopography's reading: the same
#: numbers from the same bytes, up to the order of the unit conversions.
READ_REL = 1e-12

#: The plane-detrended statistics against the NumPy reference on
#: SurfaceTopography's heights (sums in another order over ~3e5 points).
STATS_REL = 1e-9

READ_DUMP = os.environ.get("KEF_READ_DUMP", str(pathlib.Path(KEFRIC).parent / "examples" / "read_dump"))

#: file, format name, (nx, ny), missing points.
FILES = [
    ("sur-2.sur", "sur", (563, 484), 117),
    ("plu-1.plu", "plu", (768, 576), 0),
    ("opd-1.opd", "opd", (640, 480), 116),
    ("al3d-1.al3d", "al3d", (200, 296), 0),
]

STATS = ["sigma", "skewness", "kurtosis", "m2", "m4", "beta"]


def _oracle(path):
    """SurfaceTopography's reading in metres: (nx, ny), sizes, heights
    indexed [x, y] as a masked array."""
    st = pytest.importorskip("SurfaceTopography")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        t = st.read_topography(str(path)).to_unit("m")
        h = np.ma.masked_invalid(t.heights())
    return tuple(t.nb_grid_pts), tuple(t.physical_sizes), h


def _dump(path, tmp_path):
    """The library's reading: (record, heights of shape (ny, nx), NaN missing)."""
    if not os.path.exists(READ_DUMP):
        pytest.skip(f"{READ_DUMP} is not built (cargo build --release --features topography --example read_dump, "
                    "or set KEF_READ_DUMP)")
    out = tmp_path / "heights.npy"
    run = subprocess.run([READ_DUMP, str(path), str(out)], check=True, capture_output=True, text=True)
    return json.loads(run.stdout), np.load(out)


def _close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b))


@pytest.mark.parametrize("name, fmt, grid, missing", FILES)
def test_the_reader_agrees_with_surface_topography(name, fmt, grid, missing, tmp_path):
    path = instrument_file(name)
    (nx, ny), sizes, h = _oracle(path)
    record, ours = _dump(path, tmp_path)
    assert (record["nx"], record["ny"]) == (nx, ny) == grid
    assert record["metadata"]["format"] == fmt
    for ours_d, n, size in [(record["dx"], nx, sizes[0]), (record["dy"], ny, sizes[1])]:
        assert _close(ours_d * n, size, READ_REL), (name, ours_d * n, size)
    # Ours are rows = y; SurfaceTopography's [x, y].
    assert ours.shape == (ny, nx)
    theirs = h.T
    mask = np.ma.getmaskarray(theirs)
    assert np.array_equal(np.isnan(ours), mask), (name, np.isnan(ours).sum(), mask.sum())
    assert mask.sum() == missing
    valid = ~mask
    a, b = ours[valid], np.asarray(theirs)[valid]
    scale = np.abs(b).max()
    worst = np.max(np.abs(a - b) / np.maximum(np.abs(b), 1e-300))
    assert np.all(np.abs(a - b) <= READ_REL * np.abs(b) + 1e-300), (name, worst, scale)


@pytest.mark.parametrize("name, fmt, grid, missing", FILES)
def test_statistics_agree_with_numpy_on_surface_topography_heights(name, fmt, grid, missing):
    path = instrument_file(name)
    (nx, ny), sizes, h = _oracle(path)
    z = np.ma.filled(h.T.astype(float), np.nan)
    expected = surface_reference().stats(z, sizes[0] / nx, sizes[1] / ny, detrend="plane")
    from_python = kf.Surface.read(path).stats
    if not os.path.exists(KEFRIC):
        pytest.skip(f"{KEFRIC} is not built (cargo build --release -p kefric, or set KEFRIC)")
    run = subprocess.run([KEFRIC, "surface", str(path), "--json"], check=True, capture_output=True, text=True)
    from_cli = json.loads(run.stdout)["surface"]
    assert (from_cli["nx"], from_cli["ny"], from_cli["missing"]) == (nx, ny, missing)
    for key in STATS:
        for source, got in [("python", from_python[key]), ("kefric", from_cli[key])]:
            assert _close(got, expected[key], STATS_REL), (name, source, key, got, expected[key])


@pytest.mark.parametrize("name, fmt, grid, missing", FILES)
def test_metadata_says_the_format_and_unit(name, fmt, grid, missing):
    (metadata,) = kf.Surface.read(instrument_file(name)).metadata
    assert metadata["format"] == fmt
    assert metadata["height_unit"]


def test_a_channel_is_chosen_by_name_or_index_and_a_wrong_one_lists_them():
    path = instrument_file("opd-1.opd")
    by_name = kf.Surface.read(path, channel="raw").stats
    by_index = kf.Surface.read(path, channel=0).stats
    assert by_name["sigma"] == by_index["sigma"] == kf.Surface.read(path).stats["sigma"]
    with pytest.raises(ValueError, match="0 Raw"):
        kf.Surface.read(path, channel="Intensity")
    with pytest.raises(ValueError, match="only one"):
        kf.Surface.read(instrument_file("al3d-1.al3d"), channel=0)


def test_a_truncated_file_is_a_value_error_naming_it(tmp_path):
    for name, *_ in FILES:
        data = instrument_file(name).read_bytes()
        cut = tmp_path / name
        cut.write_bytes(data[: len(data) // 2])
        with pytest.raises(ValueError, match=name):
            kf.Surface.read(cut)
