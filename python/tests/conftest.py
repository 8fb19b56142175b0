"""Shared fixtures and tolerances of the ke_friction tests.

The tests import the installed package (``pip install ./python``); run
them from outside ``python/`` so that ``pysrc`` is not imported instead:
``cd /tmp && python3 -m pytest -q /path/to/ke-friction/python/tests``.
"""

import json
import os
import pathlib
import subprocess

import pytest

import ke_friction as kf

ROOT = pathlib.Path(__file__).resolve().parents[2]

#: The CLI, for reference values (`kefric eval --json`, `kefric lookup --json`):
#: $KEFRIC, else the workspace's release build.
KEFRIC = os.environ.get("KEFRIC", str(ROOT / "target" / "release" / "kefric"))

#: tests/data/reference_points.json: the model at h* or F*, computed with
#: mpmath at 50 digits by tools/reference.py (the points with a "mode").
REFERENCE = [p for p in json.loads((ROOT / "tests" / "data" / "reference_points.json").read_text())["points"]
             if "mode" in p]

#: Direct integration against the mpmath reference: the library's own
#: integration tests hold it to 1e-9 relative (its quadrature reaches ~1e-13).
MODEL_REL = 1e-9

#: The same computation through Python and through the CLI's JSON: equal
#: to the last digit printed. The CLI prints shortest round-trip numbers
#: (exactly equal); 1e-12 leaves room for a shorter format without letting
#: through any real difference (the f32 and f64 table kernels differ by ~1e-6).
SAME_REL = 1e-12


#: The instruments' example files: $KEF_TOPOGRAPHIES, else
#: ``shared/topographies`` beside the repository.
TOPOGRAPHIES = pathlib.Path(os.environ.get("KEF_TOPOGRAPHIES", str(ROOT.parent / "shared" / "topographies")))


def instrument_file(name):
    """The instruments' example file ``name`` (:data:`TOPOGRAPHIES`); the
    test is skipped where it is absent."""
    path = TOPOGRAPHIES / name
    if not path.is_file():
        pytest.skip(f"{path} is absent (set KEF_TOPOGRAPHIES to the folder of the instruments' example files)")
    return path


def surface_reference():
    """tools/surface_reference.py (NumPy statistics), imported by its path
    (tools/ is not a package)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location("surface_reference", ROOT / "tools" / "surface_reference.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def kefric(*args):
    """The objects `kefric ARGS --json` prints (one per point), parsed as JSON:
    a JSON array, one object, or one object per line."""
    if not os.path.exists(KEFRIC):
        pytest.skip(f"{KEFRIC} is not built (cargo build --release -p kefric, or set KEFRIC)")
    out = subprocess.run([KEFRIC, *args, "--json"], check=True, capture_output=True, text=True).stdout
    try:
        whole = json.loads(out)
    except json.JSONDecodeError:
        return [json.loads(line) for line in out.splitlines() if line.strip()]
    return whole if isinstance(whole, list) else [whole]


@pytest.fixture(scope="session")
def table():
    return kf.Table.default()


@pytest.fixture(scope="session")
def points():
    """4,000 random points of the default table's domain (log-uniform in psi
    and F*, uniform in sqrt theta), fixed seed."""
    import numpy as np

    info = kf.Table.default().info
    rng = np.random.default_rng(16)
    n = 4000
    psi = np.exp(rng.uniform(*np.log(info["psi"]), n)).clip(*info["psi"])
    theta = (rng.uniform(*np.sqrt(info["theta"]), n) ** 2).clip(*info["theta"])
    f = np.exp(rng.uniform(*np.log(info["f_star"]), n)).clip(*info["f_star"])
    return psi, theta, f
