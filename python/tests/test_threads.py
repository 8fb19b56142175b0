"""One table, curve and model used from several Python threads at once:
the same results as from one thread, and the GIL released meanwhile."""

import threading
import time

import numpy as np

import ke_friction as kf

THREADS = 4


def run_threads(work):
    errors = []

    def guarded(k):
        try:
            work(k)
        except BaseException as e:  # noqa: BLE001 (reported below)
            errors.append(e)

    threads = [threading.Thread(target=guarded, args=(k,)) for k in range(THREADS)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert not errors, errors


def test_threads_share_one_table_one_curve_and_one_model(table, points):
    psi, theta, f = points
    curve = table.curve(1.0, 0.003)
    model = kf.Model(1.0, 0.003)
    loads = f[:40]
    want_mu = table.mu(psi, theta, f)
    want_slope = table.mu_with_slope(psi, theta, f)[1]
    want_curve = curve.mu(f)
    want_model = model.at_f_star(loads).mu
    # Each thread asks different points (its own slice and order) so that a
    # mix-up between threads would show.
    perms = [np.random.default_rng(k).permutation(psi.size) for k in range(THREADS)]

    def work(k):
        p = perms[k]
        for _ in range(10):
            assert np.array_equal(table.mu(psi[p], theta[p], f[p]), want_mu[p])
            assert np.array_equal(table.mu_with_slope(psi[p], theta[p], f[p])[1], want_slope[p])
            assert np.array_equal(curve.mu(f[p]), want_curve[p])
            assert table.mu(float(psi[p[0]]), float(theta[p[0]]), float(f[p[0]])) == want_mu[p[0]]
        assert np.array_equal(model.at_f_star(loads[::-1] if k % 2 else loads).mu,
                              want_model[::-1] if k % 2 else want_model)

    run_threads(work)


def longest_pause_of_this_thread_during(call):
    """Runs `call` in another thread while this one keeps taking timestamps;
    returns (the longest gap between them, the call's duration). With the
    GIL held through the call, the gap would be the whole call."""
    done = threading.Event()
    span = []

    def target():
        t0 = time.perf_counter()
        call()
        span.append(time.perf_counter() - t0)
        done.set()

    th = threading.Thread(target=target)
    last, gap = time.perf_counter(), 0.0
    th.start()
    while not done.is_set():
        now = time.perf_counter()
        gap, last = max(gap, now - last), now
    th.join()
    return gap, span[0]


def test_batch_work_releases_the_gil(table):
    n = 2_000_000
    rng = np.random.default_rng(9)
    psi, f = rng.uniform(0.5, 8, n), np.exp(rng.uniform(np.log(1e-5), np.log(0.1), n))
    theta, mu, slope = np.full(n, 0.003), np.empty(n), np.empty(n)
    curve, model = table.curve(1.0, 0.003), kf.Model(1.0, 0.003)
    # One native call each (what runs without the GIL: the Python layer's
    # conversions hold it), long enough to tell: 10-60 ms.
    calls = {
        "Table.mu_with_slope": lambda: table._core.mu_with_slope_into(psi, theta, f, mu, slope, False, 1),
        "Curve.mu_with_slope": lambda: curve._core.mu_with_slope_into(f, mu, slope, False, 1),
        "Model.at_f_star": lambda: model._core.contacts_into(f[:2000], True, np.empty(14000), False, 1),
    }
    for name, call in calls.items():
        # The best of three, so that a busy machine pausing this thread once
        # does not fail it; with the GIL held every try pauses it throughout.
        gap, span = min((longest_pause_of_this_thread_during(call) for _ in range(3)), key=lambda r: r[0] / r[1])
        assert span > 0.005, f"{name}: the call is too short ({span * 1e3:.1f} ms) to tell"
        assert gap < 0.5 * span, f"{name}: this thread stopped {gap * 1e3:.1f} ms of the call's {span * 1e3:.1f} ms"
