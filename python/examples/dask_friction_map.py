#!/usr/bin/env python3
"""mu over a large (psi, F*) grid, and mu(F*) curves of many surfaces, on a
Dask cluster (local processes here; a Slurm allocation with one change).

Usage: python3 python/examples/dask_friction_map.py [--size N] [--chunk C]
       [--surfaces S] [--workers W] [--out RESULT.npz]

Requires, besides ke_friction and NumPy: ``pip install "dask[array,distributed]"``
(``dask.array`` for the map, ``dask.distributed`` for the cluster and
``client.map``); on Slurm also ``dask-jobqueue`` (below).

Two kinds of work:

* a friction map: mu(psi, theta, F*) from the default table on an N x N
  grid (log-spaced psi and F*, one theta), as a chunked ``dask.array``
  computed by ``map_blocks``: each C x C block is one task, one vectorised
  :meth:`ke_friction.Table.mu` call;
* surface curves: for S surfaces (their model parameters, here random),
  ``client.map`` builds each one's :class:`ke_friction.Curve` by direct
  integration (:meth:`Curve.from_model`, ~30 ms each: the costly part, and
  the reason to spread it) and evaluates it at the loads asked for, on the
  workers; only the mu arrays come back.

Both give, to the bit, what one process computes (the lookups do not
depend on how the work is cut; ``tests/test_dask.py`` checks it).

What travels: tasks and their arguments are pickled. The default table
pickles as its name (~50 bytes: each worker uses its own copy, built into
the library); a table from :meth:`Table.load` pickles as its file's bytes
(0.45 MB for a table like the default one; once in the pickled graph
here, 460 kB against 10 kB for 16 blocks, but it is decoded again by
every task that gets its own copy): for a large table and many tasks,
pass its path and load it once per worker process (``functools.lru_cache(maxsize=None)(ke_friction.Table.load)`` in
the task's module). A curve pickles as how it was made (its table and
(psi, theta), or its model and range) and is rebuilt where it lands: keep
curves built from models on the workers (as futures, as here) rather than
gathering them.

Scaling: a table lookup costs ~8 ns, so a 1000 x 1000 block is ~8 ms of
work against ~1 ms of scheduling per task: keep blocks at 10^5-10^6
points or more (``--chunk 1000``; a 20,000 x 20,000 map is then 400
tasks). Memory per worker, with one thread each: a block's psi, F* and mu
(24 bytes a point: 24 MB for 1000 x 1000) plus the results it holds until
they are gathered; the default table once per process, and for a loaded
one about 2.3 MB per copy alive (measured for a copy of the default
table: its decoded coefficients and the file's bytes it keeps for
pickling); a curve at most 16,384 cells of 40 bytes (~0.6 MB), some tens
of kB in practice. Curves scale with the number of surfaces: one
task each, ~30 ms, so W workers build about 30 W curves a second. Give
each worker one thread (``threads_per_worker=1``) and leave ``threads=1``
in the lookups: the cluster's processes are the parallelism, and more
threads per process only compete for the same cores.

On a Slurm cluster (``pip install dask-jobqueue``), replace the one line
that makes the cluster, in :func:`make_cluster`::

    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True)

with::

    cluster = dask_jobqueue.SLURMCluster(cores=8, processes=8, memory="16GB", walltime="01:00:00"); cluster.scale(jobs=4)

(4 Slurm jobs of 8 single-threaded worker processes each; add
``queue=``/``account=`` as your site needs). The rest is unchanged.
"""

import argparse
import sys

import numpy as np

import ke_friction as kf

#: The F* range of the default table (and of the curves here).
F_RANGE = (1e-5, 0.1)
#: The psi range of the map (within the default table's [0.5, 8]).
PSI_RANGE = (0.5, 8.0)


def make_cluster(workers):
    """The cluster: ``workers`` local processes of one thread each (the one
    line to change for Slurm, see the module's docstring)."""
    from dask.distributed import LocalCluster

    return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)


def grid_axes(size):
    """The map's psi and F* axes: ``size`` log-spaced points each."""
    return np.geomspace(*PSI_RANGE, size), np.geomspace(*F_RANGE, size)


def mu_block(psi, f_star, table, theta):
    """One task of the map: mu of a block of the grid (psi and F* blocks
    of the same shape)."""
    return table.mu(psi, theta, f_star)


def friction_map(table, theta, size, chunk):
    """mu(psi, theta, F*) on the size x size grid (psi along axis 0, F*
    along axis 1) as a lazy dask array of chunk x chunk blocks."""
    import dask.array as da

    psi, f_star = grid_axes(size)
    p, f = da.meshgrid(da.from_array(psi, chunks=chunk), da.from_array(f_star, chunks=chunk), indexing="ij")
    return da.map_blocks(mu_block, p, f, table=table, theta=theta, dtype=np.float64)


def surfaces(n, seed=0):
    """n surfaces' model parameters (``Model(**p)``): random psi in
    [0.5, 8] and theta in [0, 0.01], the default constants but for beta."""
    rng = np.random.default_rng(seed)
    return [dict(psi=float(np.exp(rng.uniform(np.log(0.5), np.log(8.0)))), theta=float(rng.uniform(0.0, 0.01)),
                 beta=float(rng.choice([0.02, 0.04, 0.1]))) for _ in range(n)]


def surface_curve(params):
    """One task: the surface's curve over F_RANGE, by direct integration."""
    return kf.Curve.from_model(kf.Model(**params), *F_RANGE)


def curve_mu(curve, f_star):
    """One task: a curve's mu at the loads f_star."""
    return curve.mu(f_star)


def surface_mu(client, params, f_star):
    """mu at the loads f_star for each surface of ``params``: the curves
    built and evaluated on the cluster; a list of arrays, in order."""
    curves = client.map(surface_curve, params)
    # The curves stay on the workers; only the mu arrays come back.
    return client.gather(client.map(curve_mu, curves, f_star=f_star))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--size", type=int, default=2000, help="grid points per axis (default %(default)s)")
    parser.add_argument("--chunk", type=int, default=500, help="block edge (default %(default)s)")
    parser.add_argument("--theta", type=float, default=0.003, help="theta of the map (default %(default)s)")
    parser.add_argument("--surfaces", type=int, default=16, help="surfaces (default %(default)s)")
    parser.add_argument("--workers", type=int, default=2, help="worker processes (default %(default)s)")
    parser.add_argument("--out", help="write the map and the curves' mu to this .npz")
    args = parser.parse_args(argv)

    from dask.distributed import Client

    table = kf.Table.default()
    loads = np.geomspace(*F_RANGE, 1000)
    with make_cluster(args.workers) as cluster, Client(cluster) as client:
        mu_map = friction_map(table, args.theta, args.size, args.chunk).compute()
        params = surfaces(args.surfaces)
        mu_curves = np.array(surface_mu(client, params, loads))
    print(f"map: {mu_map.shape}, mu in [{mu_map.min():.4f}, {mu_map.max():.4f}]; "
          f"{len(params)} surface curves at {loads.size} loads, mu in [{mu_curves.min():.4f}, {mu_curves.max():.4f}]")
    if args.out:
        psi, f_star = grid_axes(args.size)
        np.savez(args.out, psi=psi, f_star=f_star, theta=args.theta, mu=mu_map, loads=loads, curves_mu=mu_curves,
                 surfaces=np.array([[p["psi"], p["theta"], p["beta"]] for p in params]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
