"""ke_friction.Container: a contact.engineering container read as
SurfaceTopography reads it (the oracle: its ``Container.IO.read_container``),
and its combined spectrum, mu over the whole band and scan equal to
``kefric surface CONTAINER --psd/--scan --json``'s; hostile containers give
ValueError naming what is wrong.

The container: ``$KEF_CONTAINERS/container-2.zip`` (default
``../shared/containers`` beside the checkout); the tests skip, saying so,
without it."""

import io
import math
import os
import pathlib
import warnings
import zipfile

import numpy as np
import pytest

import ke_friction as kf
from conftest import ROOT, SAME_REL, kefric

CONTAINERS = pathlib.Path(os.environ.get("KEF_CONTAINERS", ROOT.parent / "shared" / "containers"))
#: The README's aluminium pin on a nickel-coated disk.
MATERIALS = dict(e1=70e9, nu1=0.33, e2=200e9, nu2=0.31, hardness=1e9, delta_gamma=0.5, epsilon=0.4e-9)
#: Metres per unit of the units container-2.zip's meta.yml uses.
UNITS = {"nm": 1e-9, "um": 1e-6, "µm": 1e-6, "mm": 1e-3, "m": 1.0}


def flags(**values):
    return [a for k, v in values.items() for a in ("--" + k.replace("_", "-"), str(v))]


@pytest.fixture(scope="module")
def path():
    p = CONTAINERS / "container-2.zip"
    if not p.is_file():
        pytest.skip(f"{p} is absent (set KEF_CONTAINERS)")
    return p


@pytest.fixture(scope="module")
def container(path):
    return kf.Container.read(path)


def close(a, b, where, rel=SAME_REL):
    """Equal structure and strings, numbers within ``rel``."""
    if isinstance(b, dict):
        assert isinstance(a, dict) and a.keys() == b.keys(), f"{where}: keys {sorted(a)} != {sorted(b)}"
        for k in b:
            close(a[k], b[k], f"{where}.{k}", rel)
    elif isinstance(b, list):
        assert isinstance(a, (list, tuple)) and len(a) == len(b), f"{where}: {a} != {b}"
        for i, (x, y) in enumerate(zip(a, b)):
            close(x, y, f"{where}[{i}]", rel)
    elif isinstance(b, float) or (isinstance(b, int) and not isinstance(b, bool)):
        assert math.isclose(a, b, rel_tol=rel, abs_tol=0.0), f"{where}: {a!r} != {b!r}"
    else:
        assert a == b, f"{where}: {a!r} != {b!r}"


def test_measurements_sizes_and_units_equal_surface_topography(path, container):
    st = pytest.importorskip("SurfaceTopography.Container.IO")
    (theirs,) = st.read_container(str(path))
    ours = container.measurements
    assert len(ours) == len(theirs) == 3
    for m, t in zip(ours, theirs):
        assert m["file"] == t.info["datafile"]["original"]
        assert m["unit"] == t.unit
        grid = tuple(t.nb_grid_pts)
        assert (m["nx"], m["ny"]) == (grid + (1,))[:2], (m["name"], grid)
        metres = UNITS[t.unit]
        sizes = [s * metres for s in t.physical_sizes]
        assert math.isclose(m["size"][0], sizes[0], rel_tol=1e-12), (m["name"], m["size"], sizes)
        if t.dim == 2:
            assert math.isclose(m["size"][1], sizes[1], rel_tol=1e-12)
        else:
            assert m["size"][1] is None and m["ny"] == 1
        assert m["reliable"]["lambda_min"] < m["reliable"]["lambda_max"]
    # The AFM map names its instrument (the Nanoscope file's), as
    # SurfaceTopography's info does.
    assert "Dimension V" in ours[1]["instrument"] and theirs[1].info["instrument"]["name"] == "Dimension V"


def test_bytes_read_as_the_file(path, container):
    c = kf.Container.read(path.read_bytes(), name="c2.zip")
    assert c.name == "c2.zip" and c.surfaces == container.surfaces
    assert c.measurements == container.measurements
    assert repr(c).startswith("Container('c2.zip', 3 measurements: 80_Scale10.472_FIXEDv2p1.asc")


def test_psd_equals_the_cli(path, container):
    (doc,) = kefric("surface", str(path), "--psd")
    psd = container.psd()
    q, c = psd["combined"]
    close(q.tolist(), doc["combined"]["q"], "combined.q")
    close(c.tolist(), doc["combined"]["c"], "combined.c")
    assert psd["contributors"] == doc["combined"]["contributors"]
    assert len(q) > 50 and np.all(np.diff(q) > 0)
    for (own_q, own_c), m in zip(psd["measurements"], doc["measurements"]):
        close(own_q.tolist(), m["psd"]["q"], f"{m['name']}.q")
        close(own_c.tolist(), m["psd"]["c"], f"{m['name']}.c")
    # Another grid: more bins over the same decades.
    q20, _ = container.psd(nb_points_per_decade=20)["combined"]
    assert 1.8 * len(q) < len(q20) < 2.2 * len(q)


def test_friction_equals_the_cli(path, container):
    (doc,) = kefric("surface", str(path), *flags(**MATERIALS, force=10, area=1e-5))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        record = container.friction(force=10.0, area=1e-5, **MATERIALS)
    doc.pop("files")
    close(record, doc, "record")
    mu = record["friction"][0]["mu"]
    assert 0 < mu < 1, mu
    # The warnings reach Python as the single surface's do: one
    # ModelWarning a kind, with its record.
    kinds = {w.message.kind for w in caught if issubclass(w.category, kf.ModelWarning)}
    assert kinds == {w["kind"] for w in doc["warnings"]}, kinds
    # Two pressures at once, and a band of its own: the CLI's too.
    (doc,) = kefric("surface", str(path), *flags(**MATERIALS, lambda_s=1e-8), "--pressure", "1e6:3e6:2")
    pressures = [f["pressure"] for f in doc["friction"]]
    assert len(pressures) == 2
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        record = container.friction(pressure=np.array(pressures), lambda_s=1e-8, **MATERIALS)
    doc.pop("files")
    close(record, doc, "record")
    assert record["combined"]["band"]["lambda_s"] == 1e-8


def test_scan_equals_the_cli(path, container):
    (doc,) = kefric("surface", str(path), *flags(**MATERIALS, force=10, area=1e-5), "--scan")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scan = container.scan(force=10.0, area=1e-5, **MATERIALS)
    close(scan["rows"], doc["rows"], "rows")
    n = len(doc["rows"])
    assert n > 10 and len(scan["mu"]) == n
    assert scan["lambda_s"][0] == min(m["reliable"]["lambda_min"] for m in container.measurements)
    # Rows resting on two or more measurements carry the spread of mu.
    spread = [i for i, r in enumerate(doc["rows"]) if r.get("spread")]
    assert spread, "no row rests on two measurements"
    for i in spread:
        lo, hi = scan["mu_min"][i], scan["mu_max"][i]
        assert lo <= hi and len(doc["rows"][i]["measurements"]) >= 2
    assert all(r["measurements"] for r in scan["rows"])


def test_bad_keywords_are_value_errors_naming_them(container):
    with pytest.raises(ValueError, match=r"^nu1: nu1 = 0\.7 is out of range"):
        container.friction(pressure=1e6, **{**MATERIALS, "nu1": 0.7})
    with pytest.raises(ValueError, match=r"^lambda_c: -1 is out of range: must be > 0 and finite"):
        container.friction(pressure=1e6, lambda_c=-1.0, **MATERIALS)
    with pytest.raises(ValueError, match=r"^lambda_s: band: "):
        container.friction(pressure=1e6, lambda_s=1.0, **MATERIALS)
    with pytest.raises(ValueError, match=r"^epsilon: mu from a container needs the materials"):
        container.friction(pressure=1e6, **{**MATERIALS, "epsilon": None})
    with pytest.raises(ValueError, match=r"^pressure: "):
        container.friction(pressure=-3.0, **MATERIALS)
    with pytest.raises(ValueError, match=r"^area: give force with area"):
        container.friction(force=10.0, **MATERIALS)
    with pytest.raises(ValueError, match=r"^distribution 'cubic' is unknown: must be one of"):
        container.friction(pressure=1e6, distribution="cubic", **MATERIALS)
    with pytest.raises(ValueError, match=r"^force: one load for a scan"):
        container.scan(force=[1.0, 2.0], area=1e-5, **MATERIALS)
    with pytest.raises(ValueError, match=r"^nb_points_per_decade = 0 is out of range"):
        container.psd(nb_points_per_decade=0)
    with pytest.raises(TypeError):
        container.psd(nb_points_per_decade=2.5)


def test_read_keywords(path):
    with pytest.raises(ValueError, match=r"^surface = 1 is out of range: the container .* has 1 surface \(0 to 0\)"):
        kf.Container.read(path, surface=1)
    with pytest.raises(ValueError, match=r"^tip_radius = -1\.0 is out of range"):
        kf.Container.read(path, tip_radius=-1.0)
    with pytest.raises(ValueError, match=r"points"):
        kf.Container.read(path, max_points=1000)
    # A tip radius for the measurements whose meta.yml gives none: their
    # reliable range is cut at its cut-off.
    c = kf.Container.read(path, resolution=5e-9)
    ms = c.measurements
    assert all(m["resolution"] == 5e-9 and m["cutoff"] == 5e-9 for m in ms)
    assert ms[1]["reliable"]["lambda_min"] >= 5e-9


def members(path, leave_out=()):
    with zipfile.ZipFile(path) as z:
        return {n: z.read(n) for n in z.namelist() if n not in leave_out}


def zipped(files):
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w") as z:
        for name, data in files.items():
            z.writestr(name, data)
    return out.getvalue()


def test_hostile_containers_are_value_errors(path, tmp_path):
    stylus = "uncd_stylus_300um_5mar_3_k0HpKJt.txt"
    missing = tmp_path / "missing.zip"
    missing.write_bytes(zipped(members(path, leave_out=(stylus,))))
    with pytest.raises(ValueError, match=f"its data file {stylus} is not in the archive"):
        kf.Container.read(missing)
    not_zip = tmp_path / "not-a-zip.zip"
    not_zip.write_bytes(b"surfaces:\n  - topographies: []\n")
    with pytest.raises(ValueError, match="not a readable zip archive"):
        kf.Container.read(not_zip)
    with pytest.raises(ValueError, match="not a readable zip archive"):
        kf.Container.read(b"PK\x03\x04 not really an archive")
    without_meta = members(path, leave_out=("meta.yml",))
    with pytest.raises(ValueError, match="neither meta.yml nor index.json"):
        kf.Container.read(zipped(without_meta))
    files = members(path)
    files["meta.yml"] = files["meta.yml"].replace(b"unit: nm", b"unit: parsec", 1)
    with pytest.raises(ValueError, match=r"unit = \"parsec\" is not a length unit"):
        kf.Container.read(zipped(files))
    with pytest.raises(OSError):
        kf.Container.read(tmp_path / "absent.zip")
    with pytest.raises(TypeError):
        kf.Container.read(3.0)
