"""Synthetic surfaces the SurfaceTopography cross-checks share
(tools/psd_check.py, tools/scale_check.py)."""

import numpy as np


def rough(shape, rng, hurst=0.8):
    """A self-affine-looking random surface (or profile) in metres: white
    noise filtered to a power-law spectrum, plus an offset."""
    noise = rng.standard_normal(shape)
    f = np.fft.fftn(noise)
    q2 = sum(np.meshgrid(*[np.fft.fftfreq(n) ** 2 for n in shape], indexing="ij"))
    q2.flat[0] = np.inf
    f *= q2 ** (-(1 + hurst) / 2)
    h = np.real(np.fft.ifftn(f))
    return 1e-6 * h / h.std() + 3e-6
