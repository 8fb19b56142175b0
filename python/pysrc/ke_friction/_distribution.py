"""The asperity heights' distribution, :class:`HeightDistribution`; how
arrays of heights are read; and :class:`Model`'s distribution keywords."""

from __future__ import annotations

import numbers
from typing import Any, Optional, Tuple

import numpy as np

from . import _core
from ._args import ArrayLike, _arrays, _check_real, _is_scalar


def _distribution_of(family: str, skewness: Optional[float], kurtosis: Optional[float],
                     heights: Optional[np.ndarray], parts: Optional[Tuple[Any, ...]] = None) -> "HeightDistribution":
    """A pickled :class:`HeightDistribution`: its family and what made it
    (the values a table stores, the heights of an empirical density, or
    ``parts``: the two surfaces' detrended heights and standard deviations
    of an empirical density of a :meth:`Surface.pair`)."""
    if parts is not None:
        return HeightDistribution._empirical_sum(*parts)
    if heights is not None:
        return HeightDistribution.empirical(heights)
    # A pickle of before the stored values kept None for a kurtosis the
    # family ignores.
    return HeightDistribution(_core.DistributionCore.of_stored(
        family, float(skewness or 0.0), float("nan") if kurtosis is None else float(kurtosis)))


def _heights_of(name: str, heights: Any, copy: bool = True) -> np.ndarray:
    """``heights`` as a C-contiguous float64 array of its shape, the masked
    points of a NumPy masked array NaN (missing): how every array of
    heights the package takes is read. A new array (later changes to the
    caller's change nothing) unless ``copy`` is False and none is needed.
    TypeError, naming ``name``, for a scalar, None or non-numeric input;
    ValueError for an array whose every point is masked."""
    if isinstance(heights, (numbers.Number, str, bytes)) or heights is None:
        raise TypeError(f"{name} must be an array of measured heights, not {type(heights).__name__}")
    # The mask before np.asarray, which keeps a masked array's data alone
    # (the masked points' values too: spikes, fill values).
    mask = np.ma.getmaskarray(heights) if np.ma.isMaskedArray(heights) else None
    a = np.asarray(heights)
    if a.dtype.kind not in "iuf":
        raise TypeError(f"{name} must be an array of real numbers, not {type(heights).__name__}"
                        + (f" of {a.dtype}" if isinstance(heights, np.ndarray) else ""))
    if mask is None or not mask.any():
        return np.array(a, dtype=np.float64, order="C") if copy else np.asarray(a, dtype=np.float64, order="C")
    if mask.all():
        raise ValueError(f"{name}: every point of the masked array is masked (no heights)")
    out = np.array(a, dtype=np.float64, order="C")
    out[mask] = np.nan
    return out


def _heights_array(heights: Any, name: str = "heights") -> np.ndarray:
    """``heights`` as a new flat, read-only float64 array (a copy; masked
    points NaN, see :func:`_heights_of`)."""
    flat = _heights_of(name, heights).reshape(-1)
    flat.setflags(write=False)
    return flat


class HeightDistribution:
    """The distribution of the asperity heights (MODEL.md section 9): a
    standardised density g (mean 0, variance 1) that the model scales by
    the asperities' standard deviation.

    * :meth:`gaussian` -- the paper's Gaussian (the default);
    * :meth:`pearson` -- the Pearson system from skewness Sk and kurtosis K
      (not excess: 3 for a Gaussian), admissible where K > Sk**2 + 1,
      Sk {ranges[pearson_skewness]} and K {ranges[pearson_kurtosis]};
      Pearson(0, 3) is the Gaussian;
    * :meth:`weibull` -- a Weibull distribution of skewness Sk
      {ranges[weibull_skewness]} (its kurtosis follows from Sk);
    * :meth:`empirical` -- a kernel density of measured heights
      ({ranges[heights]}, any unit; NaN marks a missing point).

    Inadmissible values raise ValueError naming the argument and its bound.
    Pass one to :class:`Model` (``distribution=``). Immutable; it pickles
    as what made it (an empirical one with its heights, so it is rebuilt
    to the bit), and ``copy`` and ``deepcopy`` give it itself.

    >>> d = HeightDistribution.pearson(0.0, 8.0)
    >>> d.family, d.skewness, d.kurtosis, d.pearson_type
    ('pearson', 0.0, 8.0, 'VII')
    >>> round(d.pdf(0.0), 6) > HeightDistribution.gaussian().pdf(0.0)
    True
    """

    __slots__ = ("_core", "_heights", "_parts")

    def __init__(self, core: Any, heights: Optional[np.ndarray] = None,
                 parts: Optional[Tuple[np.ndarray, float, np.ndarray, float]] = None) -> None:
        self._core = core
        self._heights = heights
        self._parts = parts

    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]:
        family = self.family
        if self._parts is not None:
            return _distribution_of, (family, None, None, None, self._parts)
        stored = self._core.stored()
        if stored is None:
            return _distribution_of, (family, None, None, self._heights)
        return _distribution_of, (family, stored[0], stored[1], None)

    def __copy__(self) -> "HeightDistribution":
        return self

    def __deepcopy__(self, memo: Any) -> "HeightDistribution":
        return self

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, HeightDistribution):
            return NotImplemented
        return bool(self._core.same(other._core))

    def __hash__(self) -> int:
        # Equal distributions (Pearson(0, 3) and the Gaussian) hash alike.
        return hash((self.skewness, self.kurtosis))

    @staticmethod
    def gaussian() -> "HeightDistribution":
        """The paper's Gaussian (skewness 0, kurtosis 3): the default."""
        return HeightDistribution(_core.DistributionCore.gaussian())

    @staticmethod
    def pearson(skewness: float = 0.0, kurtosis: float = 3.0) -> "HeightDistribution":
        """The Pearson distribution of ``skewness`` Sk and ``kurtosis`` K
        (not excess: 3 for a Gaussian). ValueError outside K > Sk**2 + 1,
        Sk {ranges[pearson_skewness]}, K {ranges[pearson_kurtosis]} (or for
        NaN), naming the argument and the bound."""
        _check_real(skewness=skewness, kurtosis=kurtosis)
        return HeightDistribution(_core.DistributionCore.pearson(float(skewness), float(kurtosis)))

    @staticmethod
    def weibull(skewness: float = 0.0) -> "HeightDistribution":
        """The standardised Weibull distribution of ``skewness`` Sk
        {ranges[weibull_skewness]} (its kurtosis follows: 2.717 at Sk = 0);
        ValueError outside."""
        _check_real(skewness=skewness)
        return HeightDistribution(_core.DistributionCore.weibull(float(skewness)))

    @staticmethod
    def empirical(heights: ArrayLike) -> "HeightDistribution":
        """The empirical (kernel) density of measured ``heights``: an array
        of any shape (a height map is flattened), dtype convertible to
        float64, any unit; NaN entries, and the masked entries of a NumPy
        masked array, are skipped as missing points. ValueError for fewer
        than 100 finite heights (a fully masked array), constant ones or
        an infinite one; TypeError for non-numeric input. The heights are
        copied and kept (:attr:`heights`, pickling)."""
        flat = _heights_array(heights)
        return HeightDistribution(_core.DistributionCore.empirical(flat), flat)

    @staticmethod
    def _empirical_sum(heights: np.ndarray, sd: float, other: np.ndarray, other_sd: float) -> "HeightDistribution":
        """The empirical density of two rough surfaces pressed together
        (:meth:`Surface.pair`): of sd X + other_sd Y, X and Y of the
        empirical densities of ``heights`` and ``other`` (the library's
        ``Empirical::sum``, the convolution of the two). Kept with its
        parts, as which it pickles."""
        a, b = _heights_array(heights), _heights_array(other)
        core = _core.DistributionCore.empirical_sum(a, float(sd), b, float(other_sd))
        return HeightDistribution(core, None, (a, float(sd), b, float(other_sd)))

    @property
    def family(self) -> str:
        """The family: one of the core's ``ke_friction._core.FAMILIES``."""
        return self._core.family()

    @property
    def skewness(self) -> float:
        """The skewness Sk (for an empirical density, the heights')."""
        return self._core.skewness()

    @property
    def kurtosis(self) -> float:
        """The kurtosis K, not excess (3 for a Gaussian; for Weibull the one
        its skewness implies; for an empirical density, the heights')."""
        return self._core.kurtosis()

    @property
    def is_gaussian(self) -> bool:
        """Whether the model treats it as the paper's Gaussian (the Gaussian,
        or Pearson(0, 3) exactly)."""
        return self._core.is_gaussian()

    @property
    def heights(self) -> Optional[np.ndarray]:
        """The heights of an empirical density (a read-only float64 copy,
        flattened, NaN included), else None (and None for the density of
        a :meth:`Surface.pair`, the convolution of its two surfaces')."""
        return self._heights

    @property
    def bandwidth(self) -> Optional[float]:
        """The kernel width of an empirical density (standardised units), else None."""
        return self._core.bandwidth()

    @property
    def support(self) -> Tuple[float, float]:
        """The standardised density's support (lo, hi), infinite where unbounded."""
        return self._core.support()

    @property
    def mode(self) -> float:
        """Where the standardised density is largest (for a J-shaped one,
        the end where it is unbounded)."""
        return self._core.mode()

    @property
    def pearson_type(self) -> Optional[str]:
        """The Pearson type (``"0"`` for the normal, ``"I"`` ... ``"VII"``)
        of a Pearson density or the Gaussian; None for the other families."""
        return self._core.pearson_type()

    def moments(self) -> Tuple[float, float, float, float, float]:
        """(mass, mean, variance, skewness, kurtosis) of the standardised
        density by the model's quadrature: (1, 0, 1, Sk, K) to about 1e-12
        for light tails."""
        return self._core.moments()

    def _eval(self, x: ArrayLike, into: Any) -> Any:
        scalar = _is_scalar(x)
        shape, (flat,) = _arrays(("x",), (x,))
        out = np.empty(flat.size)
        into(flat, out)
        return float(out[0]) if scalar else out.reshape(shape)[()]

    def pdf(self, x: ArrayLike) -> Any:
        """The standardised density g(x) (0 outside the support): a float
        for a number, a float64 array of x's shape for an array-like."""
        return self._eval(x, self._core.pdf_into)

    def ln_pdf(self, x: ArrayLike) -> Any:
        """ln g(x) (-inf outside the support); as :meth:`pdf`."""
        return self._eval(x, self._core.ln_pdf_into)

    def __repr__(self) -> str:
        family = self.family
        if family == "pearson":
            return f"HeightDistribution.pearson({self.skewness!r}, {self.kurtosis!r})"
        if family == "weibull":
            return f"HeightDistribution.weibull({self.skewness!r})"
        if family == "empirical":
            return f"HeightDistribution.empirical(<{self._core.heights()} heights>)"
        if family == "gaussian":
            return "HeightDistribution.gaussian()"
        # A family of the core's registry without a constructor here.
        return f"<HeightDistribution {family}: skewness={self.skewness!r}, kurtosis={self.kurtosis!r}>"


# The ranges in the docstrings are the core's (`ke_friction::bounds`).
for _documented in (HeightDistribution, HeightDistribution.pearson, HeightDistribution.weibull):
    if _documented.__doc__:  # (None under python -OO)
        _documented.__doc__ = _documented.__doc__.format(ranges=_core.RANGES)


def _resolve(distribution: Any, skewness: Any, kurtosis: Any, heights: Any) -> Optional[HeightDistribution]:
    """The distribution of :class:`Model`'s arguments, by the core's rules
    (the CLI's; ``HeightDistribution::from_arguments``), or None when none
    is given (the Gaussian)."""
    given = (("skewness", skewness), ("kurtosis", kurtosis), ("heights", heights))
    if isinstance(distribution, HeightDistribution):
        for name, value in given:
            if value is not None:
                raise ValueError(f"{name}: not with a HeightDistribution as distribution (it has its own)")
        return distribution
    if distribution is not None and not isinstance(distribution, str):
        raise TypeError(f"distribution must be a str or a HeightDistribution, not {type(distribution).__name__}")
    if all(value is None for _, value in given) and distribution is None:
        return None
    _check_real(**{k: v for k, v in given[:2] if v is not None})
    flat = None if heights is None else _heights_array(heights)
    core = _core.DistributionCore.from_arguments(distribution, None if skewness is None else float(skewness),
                                                 None if kurtosis is None else float(kurtosis), flat)
    return HeightDistribution(core, flat if core.family() == "empirical" else None)
