"""mu(p) and dmu/dp of the contact pressure in pascals, for a simulator:
:class:`FrictionLaw`, and how it pickles."""

from __future__ import annotations

from typing import Any, Dict, Literal, Optional, Tuple, Union, overload

import numpy as np

from . import _core
from ._args import (ArrayLike, FloatArray, OutOfDomain, _arrays, _check_real, _choice, _is_scalar, _mode, _scalar,
                    _threads)
from ._errors import _located
from ._model import Model

#: ``out_of_range``: what a law does at a positive pressure outside its
#: range (the core's names, ``OutOfRange``).
OutOfRange = Literal["clamp", "error"]
_POLICIES: Tuple[str, ...] = tuple(_core.OUT_OF_RANGE)
#: The F* range of a law made without ``pressure_range``: p from
#: 1e-5 H to 0.1 H.
LAW_F_STAR_RANGE: Tuple[float, float] = tuple(_core.LAW_F_STAR_RANGE)  # type: ignore[assignment]


def _law_of(model: Model, hardness: float, pressure_range: Tuple[float, float], out_of_range: str) -> "FrictionLaw":
    """A pickled law, rebuilt as it was made."""
    return FrictionLaw.from_model(model, hardness, pressure_range=pressure_range, out_of_range=out_of_range)


class FrictionLaw:
    """The static friction coefficient mu of the contact pressure p (Pa) and
    its derivative dmu/dp (1/Pa), for a simulator that knows p at each
    contact node: mu(p) = mu(F* = p/H), the model's own load (a nominal
    pressure over the hardness H of the softer material), from a
    :class:`Curve` over the pressure range (``pressure_range``, Pa; by
    default 1e-5 H to 0.1 H), within :attr:`max_error` (at most
    CURVE_ACCURACY, 1e-6 relative) of the model.

    Outside the range, a positive pressure (+infinity too) is clamped
    (``out_of_range="clamp"``: mu at the nearest end, dmu/dp = 0, each
    such evaluation counted in :attr:`clamped`) or refused (``"error"``:
    ValueError, or NaN with ``out_of_domain="nan"``). p <= 0 (an open
    contact, -infinity too) or NaN is never a number: ValueError, or NaN
    with ``out_of_domain="nan"``. A NumPy masked array gives a masked
    array with its mask.

    Lookups take a Python float (and return a float) or an array-like of
    any shape (and return float64 arrays of that shape). A law pickles as
    it was made (its model, hardness, range and policy; tens of
    milliseconds to rebuild, the same to the bit; the clamped count starts
    again at 0). Thread-safe: share one law across threads.

    >>> law = FrictionLaw(1.0, 0.001, hardness=1e9)          # ~30 ms
    >>> law.range
    (10000.0, 100000000.0)
    >>> round(law.mu(1e7), 6)                                # F* = 0.01
    0.525211
    >>> mu, dmu_dp = law.mu_and_derivative([1e6, 1e7])
    >>> bool(dmu_dp[1] < 0)
    True
    """

    __slots__ = ("_core", "_model")

    def __init__(self, psi: float, theta: float, *, hardness: float,
                 pressure_range: Optional[Tuple[float, float]] = None, out_of_range: OutOfRange = "clamp",
                 beta: Optional[float] = None, nu: Optional[float] = None, eps_star: Optional[float] = None,
                 fit: Optional[str] = None, model: Optional[str] = None,
                 distribution: Union[str, Any, None] = None, skewness: Optional[float] = None,
                 kurtosis: Optional[float] = None, heights: Optional[ArrayLike] = None) -> None:
        """The law of the model at (psi, theta) (the other keywords as in
        :class:`Model`) on a softer material of hardness ``hardness`` (Pa)."""
        m = Model(psi, theta, beta, nu, eps_star, fit, model, distribution, skewness, kurtosis, heights)
        self._init(m, hardness, pressure_range, out_of_range)

    def _init(self, model: Model, hardness: float, pressure_range: Optional[Tuple[float, float]],
              out_of_range: str) -> None:
        _check_real(hardness=hardness)
        if pressure_range is None:
            lo = hi = None
        else:
            try:
                lo, hi = pressure_range
            except (TypeError, ValueError):
                raise TypeError("pressure_range must be a pair (p_min, p_max) of pressures in Pa, or None") from None
            _check_real(p_min=lo, p_max=hi)
            lo, hi = float(lo), float(hi)
        _choice("out_of_range", out_of_range, _POLICIES)
        self._core = _core.FrictionLawCore(model._core, float(hardness), lo, hi, out_of_range)
        self._model = model

    @staticmethod
    def from_model(model: Model, hardness: float, *, pressure_range: Optional[Tuple[float, float]] = None,
                   out_of_range: OutOfRange = "clamp") -> "FrictionLaw":
        """The law of ``model`` (a :class:`Model`) on a softer material of
        hardness ``hardness`` (Pa)."""
        if not isinstance(model, Model):
            raise TypeError(f"model must be a Model, not {type(model).__name__}")
        law = FrictionLaw.__new__(FrictionLaw)
        law._init(model, hardness, pressure_range, out_of_range)
        return law

    @staticmethod
    def from_physical(*, e1: float, nu1: float, e2: float, nu2: float, hardness: float, sigma: float,
                      radius: float, density: float, delta_gamma: float, epsilon: float,
                      pressure_range: Optional[Tuple[float, float]] = None,
                      out_of_range: OutOfRange = "clamp") -> "FrictionLaw":
        """The law of SI inputs (as :func:`params_from_physical`; H is
        ``hardness``)."""
        from ._model import params_from_physical
        p = params_from_physical(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, sigma=sigma, radius=radius,
                                 density=density, delta_gamma=delta_gamma, epsilon=epsilon)
        model = Model(p["psi"], p["theta"], p["beta"], p["nu"], p["eps_star"])
        return FrictionLaw.from_model(model, hardness, pressure_range=pressure_range, out_of_range=out_of_range)

    @staticmethod
    def from_surface(surface: Any, *, e1: float, nu1: float, e2: float, nu2: float, hardness: float,
                     delta_gamma: float, epsilon: float, distribution: str = "pearson", fit: str = "consistent",
                     model: str = "ke", pressure_range: Optional[Tuple[float, float]] = None,
                     out_of_range: OutOfRange = "clamp") -> "FrictionLaw":
        """The law of a measured :class:`Surface` and the materials: its
        :meth:`Surface.model` (the same keywords; as ``kefric surface``)
        on hardness ``hardness``."""
        m = surface.model(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, delta_gamma=delta_gamma,
                          epsilon=epsilon, distribution=distribution, fit=fit, model=model)
        return FrictionLaw.from_model(m, hardness, pressure_range=pressure_range, out_of_range=out_of_range)

    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]:
        return _law_of, (self._model, self.hardness, self.range, self.out_of_range)

    @property
    def model(self) -> Model:
        """The :class:`Model` the law evaluates."""
        return self._model

    @property
    def params(self) -> Dict[str, Any]:
        """The model's parameters (:attr:`Model.params`)."""
        return self._model.params

    @property
    def hardness(self) -> float:
        """H of the softer material, Pa."""
        return self._core.hardness()

    @property
    def range(self) -> Tuple[float, float]:
        """The pressure range (p_min, p_max), Pa."""
        return self._core.range()

    @property
    def out_of_range(self) -> str:
        """The policy outside the range: ``"clamp"`` or ``"error"``."""
        return self._core.policy()

    @property
    def max_error(self) -> float:
        """The largest relative error of mu against the model, measured when
        the law was made (at most CURVE_ACCURACY)."""
        return self._core.max_error()

    @property
    def clamped(self) -> int:
        """How many evaluations were clamped to the range since the law was
        made (or :meth:`reset_clamped`)."""
        return self._core.clamped()

    def reset_clamped(self) -> int:
        """Sets :attr:`clamped` to 0; returns what it was."""
        return self._core.reset_clamped()

    @overload
    def mu(self, pressure: float, *, out_of_domain: OutOfDomain = ..., threads: Optional[int] = ...) -> float: ...
    @overload
    def mu(self, pressure: ArrayLike, *, out_of_domain: OutOfDomain = ...,
           threads: Optional[int] = ...) -> FloatArray: ...

    def mu(self, pressure: ArrayLike, *, out_of_domain: OutOfDomain = "raise", threads: Optional[int] = 1) -> Any:
        """mu at the contact pressure (Pa): a float for a Python number, a
        float64 array of the same shape for an array-like. p <= 0 or NaN
        (and, with ``out_of_range="error"``, a pressure outside the range,
        +infinity too): ValueError naming the pressure (and its index), or NaN with
        ``out_of_domain="nan"``. ``threads``: as :meth:`Table.mu`. A NumPy
        masked array gives a masked array with the same mask (the masked
        pressures are not evaluated: no error, no clamped count)."""
        if type(pressure) is float and out_of_domain == "raise":
            return self._core.mu_scalar(pressure)  # the fast path of a call in a loop
        masked = self._unmasked(pressure)
        if masked is not None:
            data, mask = masked
            return np.ma.masked_array(self.mu(data, out_of_domain=out_of_domain, threads=threads), mask=mask)
        nan = _mode(out_of_domain)
        if _is_scalar(pressure):
            return _scalar(self._core.mu_scalar, (float(pressure),), nan)
        workers = _threads(threads)
        shape, (p,) = _arrays(("pressure",), (pressure,))
        out = np.empty(p.size)
        try:
            self._core.mu_into(p, out, nan, workers)
        except Exception as e:
            raise _located(e, shape) from None
        return out.reshape(shape)[()]

    @overload
    def mu_and_derivative(self, pressure: float, *, out_of_domain: OutOfDomain = ...,
                          threads: Optional[int] = ...) -> Tuple[float, float]: ...
    @overload
    def mu_and_derivative(self, pressure: ArrayLike, *, out_of_domain: OutOfDomain = ...,
                          threads: Optional[int] = ...) -> Tuple[FloatArray, FloatArray]: ...

    def mu_and_derivative(self, pressure: ArrayLike, *, out_of_domain: OutOfDomain = "raise",
                          threads: Optional[int] = 1) -> Tuple[Any, Any]:
        """(mu, dmu/dp) at the contact pressure, dmu/dp in 1/Pa (0 where
        clamped); as :meth:`mu` (a masked array gives two, both with its
        mask)."""
        if type(pressure) is float and out_of_domain == "raise":
            return self._core.mu_and_derivative_scalar(pressure)
        masked = self._unmasked(pressure)
        if masked is not None:
            data, mask = masked
            mu, dmu = self.mu_and_derivative(data, out_of_domain=out_of_domain, threads=threads)
            return np.ma.masked_array(mu, mask=mask), np.ma.masked_array(dmu, mask=mask.copy())
        nan = _mode(out_of_domain)
        if _is_scalar(pressure):
            return _scalar(self._core.mu_and_derivative_scalar, (float(pressure),), nan, 2)
        workers = _threads(threads)
        shape, (p,) = _arrays(("pressure",), (pressure,))
        mu, dmu = np.empty(p.size), np.empty(p.size)
        try:
            self._core.mu_and_derivative_into(p, mu, dmu, nan, workers)
        except Exception as e:
            raise _located(e, shape) from None
        return mu.reshape(shape)[()], dmu.reshape(shape)[()]

    def _unmasked(self, pressure: Any) -> Optional[Tuple[Any, Any]]:
        """For a NumPy masked array of real numbers: its data as float64 with
        the masked pressures replaced by p_min (in range: neither an error
        nor a clamp), and its mask; None for anything else (a masked array
        of other values is refused as its data would be)."""
        if not isinstance(pressure, np.ma.MaskedArray):
            return None
        data = np.ma.getdata(pressure)
        if data.dtype.kind not in "iuf":
            return None
        mask = np.ma.getmaskarray(pressure)
        data = np.array(data, dtype=np.float64)
        data[mask] = self.range[0]
        return data, mask

    def table(self, pressure_min: Optional[float] = None, pressure_max: Optional[float] = None, *,
              rows: Optional[int] = None, tolerance: float = 1e-3, format: Optional[str] = None,
              stress_unit: str = "Pa") -> Any:
        """A solver-ready table (what ``kefric law`` writes): ``rows``
        log-spaced pressures from pressure_min to pressure_max (default: the
        law's range; within it), or the fewest whose linear interpolation in
        p is within ``tolerance`` (relative) of the law. Returns
        {"pressure", "mu", "dmu_dp": float64 arrays, "interpolation_error":
        the measured worst relative error of linear interpolation between
        rows}.

        With ``format`` ("csv", "abaqus", "ls-dyna", "moose", "comsol":
        what ``kefric law --format`` writes) the same rows as text in that
        solver's input syntax, the pressures in ``stress_unit`` ("Pa",
        "MPa", "psi": the solver model's stress unit; dmu_dp in its inverse).
        The CSV is a names line and the rows: ``numpy.genfromtxt(...,
        names=True, delimiter=",")`` and ``pandas.read_csv`` read it."""
        lo, hi = self.range
        lo = lo if pressure_min is None else pressure_min
        hi = hi if pressure_max is None else pressure_max
        _check_real(pressure_min=lo, pressure_max=hi, tolerance=tolerance)
        if rows is not None and (not isinstance(rows, (int, np.integer)) or isinstance(rows, (bool, np.bool_))):
            raise TypeError(f"rows must be an int or None, not {type(rows).__name__}")
        if format is not None or stress_unit != "Pa":
            if not isinstance(format, (str, type(None))) or not isinstance(stress_unit, str):
                raise TypeError("format and stress_unit must be str")
            return self._core.table_text(float(lo), float(hi), None if rows is None else int(rows), float(tolerance),
                                         "csv" if format is None else format, stress_unit)
        values, error = self._core.table(float(lo), float(hi), None if rows is None else int(rows), float(tolerance))
        cols = np.asarray(values).reshape(-1, 3)
        return {"pressure": np.ascontiguousarray(cols[:, 0]), "mu": np.ascontiguousarray(cols[:, 1]),
                "dmu_dp": np.ascontiguousarray(cols[:, 2]), "interpolation_error": error}

    def __repr__(self) -> str:
        lo, hi = self.range
        return (f"FrictionLaw(psi={self._model.psi!r}, theta={self._model.theta!r}, hardness={self.hardness!r}, "
                f"pressure_range=({lo!r}, {hi!r}), out_of_range={self.out_of_range!r})")
