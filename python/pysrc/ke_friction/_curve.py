"""mu(F*) of one surface pair, :class:`Curve`, and how it pickles."""

from __future__ import annotations

from typing import Any, Optional, Tuple, overload

import numpy as np

from . import _core
from ._args import ArrayLike, FloatArray, OutOfDomain, _arrays, _check_real, _is_scalar, _mode, _scalar, _threads
from ._errors import _located
from ._model import Model

#: The relative accuracy of :meth:`Curve.from_model` against the model.
CURVE_ACCURACY: float = _core.CURVE_ACCURACY


def _curve_of(how: str, source: Any, a: float, b: float) -> "Curve":
    """A pickled curve: of ``"table"`` ``source`` at (psi, theta) = (a, b),
    or of ``"model"`` ``source`` over F* in [a, b]."""
    return source.curve(a, b) if how == "table" else Curve.from_model(source, a, b)


class Curve:
    """mu(F*) of one surface pair (fixed psi and theta): Hermite cubics in
    F* through mu and dmu/dF* on cells spaced by octaves of F*, C1-smooth. From :meth:`Table.curve` or
    :meth:`Curve.from_model`. Immutable; share it freely across threads.
    A lookup takes about a nanosecond per load in arrays: the fastest way to
    evaluate mu where psi and theta stay fixed (a simulation's inner loop).
    A curve pickles as it was made (its table and (psi, theta), or its
    model and range) and is rebuilt the same to the bit where it is
    unpickled (microseconds from a table, tens of milliseconds from a
    model); ``copy`` and ``deepcopy`` give the curve itself.

    >>> c = Curve.from_model(Model(1.0, 0.001), 1e-5, 0.1)   # ~30 ms
    >>> c.range
    (1e-05, 0.1)
    >>> abs(c.mu(0.01) / Model(1.0, 0.001).at_f_star(0.01).mu - 1) < CURVE_ACCURACY
    True
    """

    __slots__ = ("_core", "_made")

    def __init__(self, core: Any, made: Tuple[str, Any, float, float]) -> None:
        self._core = core
        self._made = made

    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]:
        return _curve_of, self._made

    def __copy__(self) -> "Curve":
        return self

    def __deepcopy__(self, memo: Any) -> "Curve":
        return self

    @staticmethod
    def from_model(model: "Model", f_star_min: float, f_star_max: float) -> "Curve":
        """A curve of ``model`` for F* in [f_star_min, f_star_max], within
        CURVE_ACCURACY (1e-6 relative) of direct integration."""
        if not isinstance(model, Model):
            raise TypeError(f"model must be a Model, not {type(model).__name__}")
        _check_real(f_star_min=f_star_min, f_star_max=f_star_max)
        lo, hi = float(f_star_min), float(f_star_max)
        return Curve(_core.CurveCore.from_model(model._core, lo, hi), ("model", model, lo, hi))

    @property
    def range(self) -> Tuple[float, float]:
        """The F* range (lo, hi)."""
        return self._core.range()

    @property
    def max_error(self) -> float:
        """The largest relative error of mu measured when the curve was built."""
        return self._core.max_error()

    @overload
    def mu(self, f_star: float, *, out_of_domain: OutOfDomain = ..., threads: Optional[int] = ...) -> float: ...
    @overload
    def mu(self, f_star: ArrayLike, *, out_of_domain: OutOfDomain = ...,
           threads: Optional[int] = ...) -> FloatArray: ...

    def mu(self, f_star: ArrayLike, *, out_of_domain: OutOfDomain = "raise", threads: Optional[int] = 1) -> Any:
        """mu at f_star: a float for a Python number, a float64 array for an
        array-like. Outside the range, or NaN: ValueError, or NaN with
        ``out_of_domain="nan"``. ``threads``: as :meth:`Table.mu`, but
        only arrays of at least 262,144 loads use more than one."""
        if type(f_star) is float and out_of_domain == "raise":
            return self._core.mu_scalar(f_star)  # the fast path of a call in a loop
        nan = _mode(out_of_domain)
        if _is_scalar(f_star):
            return _scalar(self._core.mu_scalar, (float(f_star),), nan)
        workers = _threads(threads)
        shape, (f,) = _arrays(("f_star",), (f_star,))
        out = np.empty(f.size)
        try:
            self._core.mu_into(f, out, nan, workers)
        except Exception as e:
            raise _located(e, shape) from None
        return out.reshape(shape)[()]

    @overload
    def mu_with_slope(self, f_star: float, *, out_of_domain: OutOfDomain = ...,
                      threads: Optional[int] = ...) -> Tuple[float, float]: ...
    @overload
    def mu_with_slope(self, f_star: ArrayLike, *, out_of_domain: OutOfDomain = ...,
                      threads: Optional[int] = ...) -> Tuple[FloatArray, FloatArray]: ...

    def mu_with_slope(self, f_star: ArrayLike, *, out_of_domain: OutOfDomain = "raise",
                      threads: Optional[int] = 1) -> Tuple[Any, Any]:
        """(mu, dmu/dF*) at f_star; as :meth:`mu`."""
        if type(f_star) is float and out_of_domain == "raise":
            return self._core.mu_with_slope_scalar(f_star)  # the fast path of a call in a loop
        nan = _mode(out_of_domain)
        if _is_scalar(f_star):
            return _scalar(self._core.mu_with_slope_scalar, (float(f_star),), nan, 2)
        workers = _threads(threads)
        shape, (f,) = _arrays(("f_star",), (f_star,))
        mu, slope = np.empty(f.size), np.empty(f.size)
        try:
            self._core.mu_with_slope_into(f, mu, slope, nan, workers)
        except Exception as e:
            raise _located(e, shape) from None
        return mu.reshape(shape)[()], slope.reshape(shape)[()]

    def __repr__(self) -> str:
        return f"Curve(range={self.range})"
