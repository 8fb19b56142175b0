"""The library's plausibility warnings as ke_friction.ModelWarning (issue
37's cases 1-4 from Python): once per kind and call, with the record the
CLI prints; F* > 1 refused; Surface.friction broadcasting loads."""

import os
import subprocess
import warnings

import numpy as np
import pytest
from conftest import KEFRIC, instrument_file, kefric

import ke_friction as kf

MATERIALS = dict(e1=70e9, nu1=0.33, e2=200e9, nu2=0.31, hardness=1e9, delta_gamma=0.5, epsilon=0.4e-9)
FLAGS = ["--e1", "70e9", "--nu1", "0.33", "--e2", "200e9", "--nu2", "0.31", "--hardness", "1e9",
         "--delta-gamma", "0.5", "--epsilon", "0.4e-9"]
DX = 1e-6


def waves(n, periodic):
    """A map of a few waves: whole periods along x and y (periodic), or
    not (its edges jump)."""
    x, y = np.meshgrid(np.arange(n, dtype=float), np.arange(n, dtype=float))
    if periodic:
        t = 2 * np.pi / n
        w = np.sin(6 * x * t) + np.cos(5 * y * t) + 0.7 * np.sin(3 * x * t - 7 * y * t) + 0.5 * np.cos(9 * x * t + 8 * y * t)
    else:
        w = np.sin(0.31 * x) + np.cos(0.23 * y) + 0.7 * np.sin(0.17 * x - 0.29 * y) + 0.5 * np.cos(0.41 * x + 0.37 * y)
    return 0.2e-6 * w


def recorded(fn):
    """What ``fn()`` returns, and the ModelWarnings it warned."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = fn()
    return result, [w.message for w in caught if issubclass(w.category, kf.ModelWarning)]


def test_model_warning_is_a_user_warning_with_the_libraries_kinds():
    assert issubclass(kf.ModelWarning, UserWarning)
    assert kf.WARNING_KINDS[:4] == ("f_star_below_range", "f_star_above_range", "negative_separation",
                                    "adhesion_dominated")
    assert "non_periodic" in kf.WARNING_KINDS and "anisotropy" in kf.WARNING_KINDS


def test_a_load_above_the_hardness_is_refused():
    # Case 1: F* = 20 was mu = 0.0; now a ValueError naming the bound.
    with pytest.raises(ValueError, match=r"f_star = 20 is out of range: must be <= 1"):
        kf.Model(0.85, 0.0013).at_f_star(20)
    got = kf.Model(0.85, 0.0013).at_f_star([0.01, 20.0], out_of_domain="nan")
    assert not np.isnan(got.mu[0]) and np.isnan(got.mu[1])


def test_results_inside_the_papers_range_do_not_warn():
    _, caught = recorded(lambda: kf.Model(1.0, 0.001).at_f_star(np.geomspace(1e-5, 0.01, 7)))
    assert caught == []


def test_implausible_contacts_warn_once_per_kind_with_the_worst():
    # Case 1 and 2: a light load with adhesion (mu > 1) and a heavy one (h* < 0).
    c, caught = recorded(lambda: kf.Model(0.85, 0.0013).at_f_star([1e-9, 1e-7, 1e-3, 0.5]))
    kinds = [w.kind for w in caught]
    assert kinds == ["f_star_below_range", "adhesion_dominated", "f_star_above_range", "negative_separation"]
    below = caught[0]
    assert str(below).startswith("2 of 4 results; the worst: F* = 1e-9 is below the range the paper covers")
    assert below.record["count"] == 2 and below.record["of"] == 4
    assert below.record["f_star"] == pytest.approx(1e-9, rel=1e-9)
    assert c.mu[1] > 1
    # The same as the CLI's lines for the same points.
    if not os.path.exists(KEFRIC):
        pytest.skip(f"{KEFRIC} is not built")
    err = subprocess.run([KEFRIC, "eval", "--psi", "0.85", "--theta", "0.0013", "--f-star", "1e-9:0.5:4"],
                         check=True, capture_output=True, text=True).stderr
    _, caught = recorded(lambda: kf.Model(0.85, 0.0013).at_f_star(np.geomspace(1e-9, 0.5, 4)))
    assert err.splitlines() == [f"warning: {w}" for w in caught]


def test_surface_friction_warns_and_broadcasts_loads(tmp_path):
    s = kf.Surface.from_heights(waves(128, periodic=False), DX)
    # Case 2: friction at an absurd load records warnings (it recorded none).
    f, caught = recorded(lambda: s.friction(force=1e-6, area=1e-4, **MATERIALS))
    kinds = {w.kind for w in caught}
    assert {"f_star_below_range", "few_asperities"} <= kinds, kinds
    assert f["f_star"] == pytest.approx(1e-11, rel=1e-12)
    # The same kinds as `kefric surface --json` records for the same file.
    np.save(tmp_path / "s.npy", waves(128, periodic=False))
    (ref,) = kefric("surface", str(tmp_path / "s.npy"), "--dx", "1e-6", *FLAGS, "--force", "1e-6", "--area",
                    "1e-4")
    assert sorted(w["kind"] for w in ref["warnings"]) == sorted(w.kind for w in caught)
    assert [w["summary"] for w in ref["warnings"]] == [str(w) for w in caught]
    # Case 4: forces as an array broadcast against the area; each value the scalar call's.
    forces = np.geomspace(0.1, 100, 7)
    many, caught = recorded(lambda: s.friction(force=forces, area=1e-5, **MATERIALS))
    assert many["mu"].shape == (7,) and many["force"].shape == (7,)
    for i, force in enumerate(forces):
        one, _ = recorded(lambda: s.friction(force=float(force), area=1e-5, **MATERIALS))
        assert many["mu"][i] == one["mu"] and many["friction_force"][i] == one["friction_force"]
    grid, _ = recorded(lambda: s.friction(pressure=[[1e4], [1e5]], **MATERIALS))
    assert grid["mu"].shape == (2, 1) and grid["mu"][1, 0] < grid["mu"][0, 0]
    # 1e6 N on 1 cm^2 against 1 GPa: F* = 10, refused.
    with pytest.raises(ValueError, match="must be <= 1"):
        s.friction(force=1e6, area=1e-4, **MATERIALS)


def test_spectral_derivatives_of_a_non_periodic_map_warn():
    # Case 3: the periodic assumption violated at the edges.
    rough = kf.Surface.from_heights(waves(128, periodic=False), DX, derivative="spectral")
    _, caught = recorded(lambda: rough.model(**MATERIALS))
    assert "non_periodic" in [w.kind for w in caught]
    assert any(w["kind"] == "non_periodic" for w in rough.stats["warnings"])
    periodic = kf.Surface.from_heights(waves(128, periodic=True), DX, derivative="spectral")
    assert not any(w["kind"] == "non_periodic" for w in periodic.stats["warnings"])
    fd = kf.Surface.from_heights(waves(128, periodic=False), DX)
    assert rough.stats["m4"] / fd.stats["m4"] > 2


# Issue 48: the validity domain, spikes and tail warnings, and the default
# height model, on the README's synthetic map and the instruments' files.

STEEL = dict(e1=200e9, nu1=0.3, e2=200e9, nu2=0.3, hardness=2e9, delta_gamma=0.3, epsilon=0.4e-9)


def readme_map():
    """examples/rough_surface.rs's map (the README's example), in NumPy."""
    n, dx, hurst = 256, 1e-6, 0.8
    m64 = (1 << 64) - 1

    def uniform(k):
        z = ((k + 0x9E3779B97F4A7C15) * 0x9E3779B97F4A7C15) & m64
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & m64
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & m64
        return ((z ^ (z >> 31)) >> 11) * 2.0 ** -53

    k_lo, k_hi = 2 * np.pi / (256 * dx), 2 * np.pi / (8 * dx)
    x, y = np.meshgrid(np.arange(n) * dx, np.arange(n) * dx)
    z = np.zeros((n, n))
    for w in range(600):
        k = k_lo * (k_hi / k_lo) ** uniform(3 * w)
        angle, phase = 2 * np.pi * uniform(3 * w + 1), 2 * np.pi * uniform(3 * w + 2)
        z += k ** -hurst * np.cos(k * np.cos(angle) * x + k * np.sin(angle) * y + phase)
    z = (z - z.mean()) / z.std() * 0.5e-6
    return kf.Surface.from_heights(z, dx, dx)


def instrument(name):
    return kf.Surface.read(instrument_file(name))


def kinds(caught):
    return {w.kind for w in caught}


def test_the_new_kinds_are_the_libraries():
    for kind in ("psi_domain", "theta_domain", "beta_domain", "spikes", "tail"):
        assert kind in kf.WARNING_KINDS


def test_the_readme_example_warns_nothing_at_10_n():
    s = readme_map()
    assert s.height_distribution().family == "pearson"
    got, caught = recorded(lambda: s.friction(force=10.0, area=1e-5, **MATERIALS))
    assert caught == [], [str(w) for w in caught]
    assert 0.009 < got["mu"] < 0.0098


def test_di_1_is_outside_the_validity_domain():
    s = instrument("di-1.di")
    _, caught = recorded(lambda: s.friction(force=1.0, area=1e-5, **STEEL))
    assert {"psi_domain", "beta_domain"} <= kinds(caught)
    psi = next(w for w in caught if w.kind == "psi_domain")
    assert str(psi).startswith("psi = 209.") and psi.record["psi"] > 200


def test_sur_2_has_spikes_and_falls_back_to_the_empirical_density():
    s = instrument("sur-2.sur")
    assert s.height_distribution().family == "empirical"
    _, caught = recorded(lambda: s.friction(force=1.0, area=1e-5, **STEEL))
    spikes = next(w for w in caught if w.kind == "spikes")
    assert "clean the data" in str(spikes) and spikes.record["kurtosis"] > 800


def test_plu_1_pearson_at_a_light_load_warns_tail_and_the_default_does_not():
    s = instrument("plu-1.plu")
    _, caught = recorded(lambda: s.friction(force=0.01, area=1e-5, distribution="pearson", **STEEL))
    tail = next(w for w in caught if w.kind == "tail")
    assert tail.record["above"] == 0 and tail.record["h_star"] > 16 and tail.record["max_height"] < 4
    assert s.height_distribution().family == "empirical"
    _, caught = recorded(lambda: s.friction(force=0.01, area=1e-5, **STEEL))
    assert "tail" not in kinds(caught)
