"""Dask: examples/dask_friction_map.py on a local cluster of two worker
processes gives, to the bit, what one process computes. Skipped only if
dask or distributed cannot be imported, and not even then with
KEF_REQUIRE_DASK set (.ci/python.sh installs them and sets it)."""

import importlib
import os
import sys
import time

import numpy as np
import pytest
from conftest import ROOT

import ke_friction as kf

try:
    import dask.array as da  # noqa: F401
    import dask.distributed as distributed
except ImportError as e:
    if os.environ.get("KEF_REQUIRE_DASK"):
        raise ImportError(f"KEF_REQUIRE_DASK is set but dask cannot be imported: {e}") from e
    pytest.skip(f"dask or distributed cannot be imported: {e}", allow_module_level=True)


@pytest.fixture(scope="module")
def example():
    """The example, imported as a module here and (by its name, as dask
    pickles functions of modules) in the worker processes: its folder on
    PYTHONPATH, which the workers inherit."""
    folder = str(ROOT / "python" / "examples")
    saved = os.environ.get("PYTHONPATH")
    os.environ["PYTHONPATH"] = os.pathsep.join([folder, *([saved] if saved else [])])
    sys.path.insert(0, folder)
    try:
        yield importlib.import_module("dask_friction_map")
    finally:
        sys.path.remove(folder)
        sys.modules.pop("dask_friction_map", None)
        if saved is None:
            del os.environ["PYTHONPATH"]
        else:
            os.environ["PYTHONPATH"] = saved


@pytest.fixture(scope="module")
def client(example):
    # The example's own cluster: 2 processes of 1 thread each.
    with example.make_cluster(2) as cluster, distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        yield client


def test_the_map_over_two_worker_processes_is_bit_identical(example, client):
    table, theta, size, chunk = kf.Table.default(), 0.003, 600, 150
    t0 = time.perf_counter()
    lazy = example.friction_map(table, theta, size, chunk)
    assert lazy.numblocks == (4, 4)
    got = lazy.compute()
    # The work went to both worker processes.
    seen = client.run(lambda dask_worker: len(dask_worker.data) + dask_worker.state.executed_count)
    assert len(seen) == 2 and all(v > 0 for v in seen.values()), seen
    psi, f_star = example.grid_axes(size)
    want = table.mu(psi[:, None], theta, f_star[None, :])
    assert got.shape == (size, size) and np.array_equal(got, want)
    # And with a loaded table (pickled as its bytes): the same.
    loaded = kf.Table.from_bytes(table.to_bytes())
    assert np.array_equal(example.friction_map(loaded, theta, size, 300).compute(), want)
    assert time.perf_counter() - t0 < 20


def test_curves_of_many_surfaces_by_client_map_are_bit_identical(example, client):
    params = example.surfaces(8, seed=3)
    loads = np.geomspace(*example.F_RANGE, 2001)
    got = example.surface_mu(client, params, loads)
    assert len(got) == len(params)
    for p, mu in zip(params, got):
        assert np.array_equal(mu, kf.Curve.from_model(kf.Model(**p), *example.F_RANGE).mu(loads)), p
    # Curves themselves come back rebuilt to the bit (as they were made).
    curves = client.gather(client.map(example.surface_curve, params[:2]))
    for p, c in zip(params[:2], curves):
        assert np.array_equal(c.mu(loads), example.surface_curve(p).mu(loads))
