"""Array work split over several threads (``threads=``): the same results,
the same first bad element and NaN placement as on one thread, checked
arguments, and the threads really started."""

import os
import threading

import numpy as np
import pytest

import ke_friction as kf

#: Table lookups split from 32,768 elements, curve lookups from 262,144,
#: the model from 8 points; the sizes below are above those.
N_TABLE = 100_003
N_CURVE = 600_001
THREADS = (2, 3, 8, None)


@pytest.fixture(scope="module")
def many(points):
    """N_TABLE random points of the domain (the 4,000 of `points`, shuffled)."""
    rng = np.random.default_rng(61)
    pick = rng.integers(0, points[0].size, N_TABLE)
    return tuple(np.ascontiguousarray(a[pick]) for a in points)


@pytest.fixture(scope="module")
def loads(table):
    lo, hi = table.info["f_star"]
    return np.exp(np.random.default_rng(62).uniform(np.log(lo), np.log(hi), N_CURVE)).clip(lo, hi)


@pytest.mark.parametrize("threads", THREADS)
def test_table_results_do_not_depend_on_threads(table, many, threads):
    psi, theta, f = many
    assert np.array_equal(table.mu(psi, theta, f, threads=threads), table.mu(psi, theta, f, threads=1))
    for got, want in zip(table.mu_with_slope(psi, theta, f, threads=threads),
                         table.mu_with_slope(psi, theta, f, threads=1)):
        assert np.array_equal(got, want)
    # One value for all of an argument (repeated natively, a chunk at a
    # time) and a 2-D shape.
    grid = f[:100_000].reshape(400, 250)
    assert np.array_equal(table.mu(2.0, theta[:250], grid, threads=threads),
                          table.mu(2.0, theta[:250], grid, threads=1))
    assert np.array_equal(table.mu_with_slope(psi[:250], 0.004, grid, threads=threads)[1],
                          table.mu_with_slope(psi[:250], 0.004, grid, threads=1)[1])


@pytest.mark.parametrize("threads", THREADS)
def test_curve_and_model_results_do_not_depend_on_threads(table, loads, threads):
    curve = table.curve(1.5, 0.002)
    assert np.array_equal(curve.mu(loads, threads=threads), curve.mu(loads, threads=1))
    for got, want in zip(curve.mu_with_slope(loads, threads=threads), curve.mu_with_slope(loads, threads=1)):
        assert np.array_equal(got, want)
    model, few = kf.Model(1.5, 0.002), loads[:19]
    got, want = model.at_f_star(few, threads=threads), model.at_f_star(few, threads=1)
    for name in ("h_star", "d_star", "p_star", "fs_star", "q_star", "f_star", "mu"):
        assert np.array_equal(getattr(got, name), getattr(want, name)), name


@pytest.mark.parametrize("threads", THREADS)
def test_the_first_bad_element_is_reported_whichever_thread_meets_it(table, many, loads, threads):
    psi, theta, f = (a.copy() for a in many)
    f[90_000] = 0.5
    with pytest.raises(ValueError, match=r"f_star = 0.5 .*\(at index \(90000,\)\)"):
        table.mu(psi, theta, f, threads=threads)
    psi[70_000] = 9.0
    with pytest.raises(ValueError, match=r"psi = 9 .*\(at index \(70000,\)\)"):
        table.mu_with_slope(psi, theta, f, threads=threads)
    theta[30_000] = -1.0
    with pytest.raises(ValueError, match=r"theta = -1 .*\(at index \(30000,\)\)"):
        table.mu(psi, theta, f, threads=threads)
    bad = loads.copy()
    bad[[400_000, 500_000]] = np.nan
    with pytest.raises(ValueError, match=r"\(at index \(400000,\)\)"):
        table.curve(1.0, 0.001).mu(bad, threads=threads)
    with pytest.raises(ValueError, match=r"\(at index \(5,\)\)"):
        kf.Model(1.0, 0.001).at_f_star([1e-3] * 5 + [-1.0] + [1e-3] * 6 + [-2.0] + [1e-3] * 3, threads=threads)


@pytest.mark.parametrize("threads", THREADS)
def test_nan_mode_gives_nan_exactly_at_the_bad_elements_on_every_thread(table, many, loads, threads):
    psi, theta, f = (a.copy() for a in many)
    bad = [10, 49_999, 50_001, 75_000, N_TABLE - 1]
    f[bad] = 1.0
    want = table.mu(psi, theta, f, out_of_domain="nan", threads=1)
    got = table.mu(psi, theta, f, out_of_domain="nan", threads=threads)
    assert np.flatnonzero(np.isnan(got)).tolist() == bad
    assert np.array_equal(got, want, equal_nan=True)
    mu, slope = table.mu_with_slope(psi, theta, f, out_of_domain="nan", threads=threads)
    assert np.flatnonzero(np.isnan(mu)).tolist() == bad == np.flatnonzero(np.isnan(slope)).tolist()
    far = loads.copy()
    far[[0, 300_000, N_CURVE - 1]] = 10.0
    got = table.curve(1.0, 0.001).mu(far, out_of_domain="nan", threads=threads)
    assert np.flatnonzero(np.isnan(got)).tolist() == [0, 300_000, N_CURVE - 1]


@pytest.mark.parametrize("threads, error, message", [
    (0, ValueError, "threads = 0: must be at least 1"),
    (-2, ValueError, "threads = -2: must be at least 1"),
    (1.5, TypeError, "threads must be an int or None, not float"),
    ("2", TypeError, "threads must be an int or None, not str"),
    (True, TypeError, "threads must be an int or None, not bool"),
])
def test_the_threads_argument_is_checked(table, threads, error, message):
    curve, model = table.curve(1.0, 0.001), kf.Model(1.0, 0.001)
    calls = [lambda: table.mu([1.0], 0.001, 0.01, threads=threads),
             lambda: table.mu_with_slope([1.0], 0.001, 0.01, threads=threads),
             lambda: curve.mu([0.01], threads=threads),
             lambda: curve.mu_with_slope([0.01], threads=threads),
             lambda: model.at_f_star(0.01, threads=threads),
             lambda: model.at_h_star(1.0, threads=threads)]
    for call in calls:
        with pytest.raises(error, match=message):
            call()


def test_numpy_integers_are_accepted_as_threads(table, many):
    psi, theta, f = many
    assert np.array_equal(table.mu(psi, theta, f, threads=np.int64(2)), table.mu(psi, theta, f, threads=1))


def threads_seen_during(call):
    """The most threads this process had while `call` ran in another one."""
    done, most = threading.Event(), [0]

    def target():
        call()
        done.set()

    th = threading.Thread(target=target)
    th.start()
    while not done.is_set():
        most[0] = max(most[0], len(os.listdir("/proc/self/task")))
    th.join()
    return most[0]


@pytest.mark.skipif(not os.path.isdir("/proc/self/task"), reason="needs Linux's /proc")
def test_the_work_runs_on_the_threads_asked_for():
    # 2,000 loads of the model take some 40 ms on one thread: long enough
    # to see the threads it starts.
    model, loads = kf.Model(1.0, 0.003), np.geomspace(1e-5, 0.1, 2000)
    before = len(os.listdir("/proc/self/task"))
    # The calling Python thread, and with threads=k, k - 1 more.
    assert threads_seen_during(lambda: model.at_f_star(loads, threads=1)) == before + 1
    assert threads_seen_during(lambda: model.at_f_star(loads, threads=3)) == before + 3
