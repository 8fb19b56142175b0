"""The precomputed table, :class:`Table`, and how it pickles."""

from __future__ import annotations

import math
import os
from typing import Any, Dict, Optional, Tuple, Union, overload

import numpy as np

from . import _core
from ._args import ArrayLike, FloatArray, OutOfDomain, _arrays, _check_real, _is_scalar, _mode, _scalar, _threads
from ._curve import Curve
from ._errors import _located
from ._model import Model

_TABLE_ARGS = ("psi", "theta", "f_star")


class Table:
    """A table of mu(psi, theta, F*): a cubic B-spline of ln(mu) over
    (ln psi, sqrt theta, ln F*), within its recorded tolerance of direct
    integration. Immutable; share it freely across threads.

    Use :meth:`Table.default` (the table built into the library: psi in
    [0.5, 8], theta in [0, 0.01], F* in [1e-5, 0.1], mu within 1e-4) or
    :meth:`Table.load` (a file from ``kefric build``). A table pickles
    (``pickle``, ``multiprocessing``, Dask) as the word ``"default"`` for
    the default table and as its file's bytes for a loaded one; ``copy``
    and ``deepcopy`` give the table itself (it is immutable).
    """

    __slots__ = ("_core",)

    def __init__(self, core: Any) -> None:
        self._core = core

    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]:
        return _table_of, ("default" if self._core.is_default() else self._core.to_bytes(),)

    def __copy__(self) -> "Table":
        return self

    def __deepcopy__(self, memo: Any) -> "Table":
        return self

    @staticmethod
    def default() -> "Table":
        """The table built into the library."""
        return Table(_core.TableCore.default())

    @staticmethod
    def load(path: Union[str, "os.PathLike[str]"]) -> "Table":
        """Load a table file written by ``kefric build``.

        Raises OSError if the file cannot be read and :class:`TableError`
        (a ValueError) if it is damaged, not a table, or inconsistent.
        The table keeps the file's bytes (for :meth:`to_bytes` and
        pickling): 0.45 MB for a table like the default one.
        """
        if not isinstance(path, (str, os.PathLike)):
            raise TypeError(f"path must be a str or os.PathLike, not {type(path).__name__}")
        return Table(_core.TableCore.load(os.fspath(path)))

    @staticmethod
    def from_bytes(data: Union[bytes, bytearray, memoryview]) -> "Table":
        """The table of a table file's contents (what :meth:`load` reads
        from the file, or :meth:`to_bytes` gives). Raises
        :class:`TableError` (a ValueError) if they are damaged, not a
        table, or inconsistent."""
        if not isinstance(data, (bytes, bytearray, memoryview)):
            raise TypeError(f"data must be bytes, not {type(data).__name__}")
        return Table(_core.TableCore.from_bytes(bytes(data)))

    def to_bytes(self) -> bytes:
        """The table file's contents: the bytes the table was read from
        (for the default table, the file built into the library), which
        :meth:`from_bytes` and :meth:`load` (once written to a file) read
        back to the same table."""
        return self._core.to_bytes()

    @overload
    def mu(self, psi: float, theta: float, f_star: float, *, out_of_domain: OutOfDomain = ...,
           threads: Optional[int] = ...) -> float: ...
    @overload
    def mu(self, psi: ArrayLike, theta: ArrayLike, f_star: ArrayLike, *,
           out_of_domain: OutOfDomain = ..., threads: Optional[int] = ...) -> FloatArray: ...

    def mu(self, psi: ArrayLike, theta: ArrayLike, f_star: ArrayLike, *, out_of_domain: OutOfDomain = "raise",
           threads: Optional[int] = 1) -> Any:
        """The static friction coefficient mu(psi, theta, F*), interpolated,
        with the table's constants (``info``: beta, nu, eps_star, fit,
        model, distribution): psi and theta of a surface pair with other
        constants give a wrong mu here, silently; :meth:`mu_for` takes the
        pair's :class:`Model` and checks them (the path for a measured
        surface).

        Parameters
        ----------
        psi : float or array_like
            Plasticity index, within ``info["psi"]`` ([0.5, 8] for the
            default table).
        theta : float or array_like
            Adhesion parameter dgamma/(sigma H), within ``info["theta"]``
            ([0, 0.01]).
        f_star : float or array_like
            External force F/(A_n H), within ``info["f_star"]`` ([1e-5, 0.1]).
        out_of_domain : {"raise", "nan"}
            What a value outside its range, or NaN, does: raise ValueError
            (the default), or give NaN at that element.
        threads : int or None
            The most threads an array lookup runs on: 1 (the default) the
            calling thread alone, as NumPy's own functions; k the calling
            one and up to k - 1 it starts; None one per core this process
            may use. Arrays of fewer than 32,768 elements run on the
            calling thread alone (about 16,000 lookups are worth a thread);
            the threads take the work 4,096 elements at a time, so one that
            starts late does less. Two threads gain 1.7-1.9x on 10^5-10^6
            random lookups, but where the cores are shared (a VM, other
            busy processes) a thread held up by the system holds up the
            call. The results, and which bad element an error names, do
            not depend on it.

        Returns
        -------
        float or numpy.ndarray
            A float if all three are Python (or NumPy scalar) numbers; else
            a float64 array of the arguments' broadcast shape (NumPy's
            rules; 0-d arrays give a NumPy float64 scalar, as ufuncs do).
            The table's error is within ``info["tolerance"]`` relative to
            direct integration.

        Raises
        ------
        ValueError
            An argument outside its range or NaN, naming it, its value, its
            index in the broadcast shape and the range, e.g. ``f_star = 0.2
            is outside the range [1e-5, 0.1] (at index (1, 0))``; or shapes
            that do not broadcast.
        TypeError
            An argument that is not a real number or array of them (str,
            None, bool, complex, object arrays); ``threads`` not an int.

        Array input runs in one call with the GIL released; contiguous
        float64 arrays of the broadcast shape are read in place, other
        dtypes, orders and shapes are converted first.

        Examples
        --------
        >>> t = Table.default()
        >>> round(t.mu(1.0, 0.001, 0.01), 6)
        0.525211
        >>> t.mu([0.5, 1.0, 2.0], 0.003, [[1e-4], [1e-2]]).shape
        (2, 3)
        """
        if type(psi) is float and type(theta) is float and type(f_star) is float and out_of_domain == "raise":
            return self._core.mu_scalar(psi, theta, f_star)  # the fast path of a call in a loop
        nan = _mode(out_of_domain)
        if _is_scalar(psi) and _is_scalar(theta) and _is_scalar(f_star):
            return _scalar(self._core.mu_scalar, (float(psi), float(theta), float(f_star)), nan)
        workers = _threads(threads)
        shape, (p, t, f) = _arrays(_TABLE_ARGS, (psi, theta, f_star), scalars=True)
        out = np.empty(math.prod(shape))
        try:
            self._core.mu_into(p, t, f, out, nan, workers)
        except Exception as e:
            raise _located(e, shape) from None
        return out.reshape(shape)[()]

    def mu_for(self, model: Model, f_star: ArrayLike, *, out_of_domain: OutOfDomain = "raise",
               threads: Optional[int] = 1) -> Any:
        """mu of ``model``'s surface pair (its psi and theta) at ``f_star``
        from this table, after checking that the model's constants (beta,
        nu, eps_star, fit, model, the heights' distribution) are the
        table's: the documented path for a measured surface
        (``Surface.model(...)``), whose constants are seldom the default
        table's. :meth:`mu` with psi and theta alone assumes them.

        Raises ValueError naming the first constant that differs and both
        values, e.g. ``beta = 0.117, but the table holds beta = 0.04: ...``;
        then as :meth:`mu` (``f_star`` broadcasts, ``out_of_domain`` and
        ``threads`` as there).

        >>> t = Table.default()
        >>> t.mu_for(Model(1.0, 0.001), 0.01) == t.mu(1.0, 0.001, 0.01)
        True
        """
        if not isinstance(model, Model):
            raise TypeError(f"model must be a ke_friction.Model, not {type(model).__name__}")
        self._core.check_constants(model._core)
        return self.mu(model.psi, model.theta, f_star, out_of_domain=out_of_domain, threads=threads)

    @overload
    def mu_with_slope(self, psi: float, theta: float, f_star: float, *,
                      out_of_domain: OutOfDomain = ..., threads: Optional[int] = ...) -> Tuple[float, float]: ...
    @overload
    def mu_with_slope(self, psi: ArrayLike, theta: ArrayLike, f_star: ArrayLike, *,
                      out_of_domain: OutOfDomain = ...,
                      threads: Optional[int] = ...) -> Tuple[FloatArray, FloatArray]: ...

    def mu_with_slope(self, psi: ArrayLike, theta: ArrayLike, f_star: ArrayLike, *,
                      out_of_domain: OutOfDomain = "raise", threads: Optional[int] = 1) -> Tuple[Any, Any]:
        """mu and its slope dmu/dF* at (psi, theta, F*), for Newton-type
        solvers: a pair of floats, or of float64 arrays of the broadcast
        shape. Arguments, ``out_of_domain``, ``threads`` and errors as :meth:`mu`
        (NaN in both at a bad element with ``out_of_domain="nan"``).

        >>> mu, slope = Table.default().mu_with_slope(2.0, 0.003, [1e-3, 1e-2])
        >>> bool((slope < 0).all())   # mu falls as the load rises
        True
        """
        if type(psi) is float and type(theta) is float and type(f_star) is float and out_of_domain == "raise":
            return self._core.mu_with_slope_scalar(psi, theta, f_star)  # the fast path of a call in a loop
        nan = _mode(out_of_domain)
        if _is_scalar(psi) and _is_scalar(theta) and _is_scalar(f_star):
            return _scalar(self._core.mu_with_slope_scalar, (float(psi), float(theta), float(f_star)), nan, 2)
        workers = _threads(threads)
        shape, (p, t, f) = _arrays(_TABLE_ARGS, (psi, theta, f_star), scalars=True)
        size = math.prod(shape)
        mu, slope = np.empty(size), np.empty(size)
        try:
            self._core.mu_with_slope_into(p, t, f, mu, slope, nan, workers)
        except Exception as e:
            raise _located(e, shape) from None
        return mu.reshape(shape)[()], slope.reshape(shape)[()]

    @property
    def info(self) -> Dict[str, Any]:
        """What the table file says about itself, a new dict each time: the
        library's table record, exactly what ``kefric info --json`` prints
        and a NumPy export (``kefric export``) stores as ``metadata``:

        * ``psi``, ``theta``, ``f_star``: the ranges [lo, hi] lookups accept;
        * ``beta``, ``nu``, ``eps_star``: the model constants it was built with;
          ``model``: ``"ke"`` (Kogut-Etsion) or ``"ceb"`` (CEB-type);
          ``fit``: ``"consistent"`` or ``"as-printed"`` (see :class:`Model`);
          ``distribution``, ``skewness``, ``kurtosis``: the asperity heights'
          distribution (``"gaussian"`` unless built with another; see
          :class:`HeightDistribution`), and ``heights``, their number, for
          an empirical one;
        * ``tolerance``: the largest relative error of mu it promises;
        * ``accuracy``: its error of mu against direct integration measured
          at build time, ``max_rel`` and ``p99_rel``, at ``samples`` random
          points, the largest at ``worst`` [psi, theta, F*];
        * ``build``: the build options, ``nodes`` [psi, theta, F*],
          ``ghosts``, ``h_star`` [from, to, points] of the integration grid,
          ``samples``, ``seed`` and ``generator`` (the program that built it);
        * ``precision`` (``"f32"``/``"f64"``), ``format_version``, and the
          file's ``bytes`` and ``crc32``.

        Ranges and other tuples are lists (as JSON has them).
        """
        return self._core.info()

    @property
    def fast_kernel(self) -> bool:
        """Whether lookups run the fast AVX2 kernel on this CPU (else the
        portable f64 one); the results agree within the table's tolerance."""
        return self._core.fast_kernel()

    def curve(self, psi: float, theta: float) -> "Curve":
        """mu(F*) of the surface pair (psi, theta) over the table's F* range:
        a :class:`Curve`, several times faster than :meth:`mu` per point.
        It assumes the table's constants, as :meth:`mu`; :meth:`curve_for`
        checks a model's."""
        _check_real(psi=psi, theta=theta)
        psi, theta = float(psi), float(theta)
        return Curve(self._core.curve(psi, theta), ("table", self, psi, theta))

    def curve_for(self, model: Model) -> "Curve":
        """:meth:`curve` of ``model``'s surface pair (its psi and theta),
        after checking that the model's constants are the table's: a
        ValueError naming the first that differs and both values, as
        :meth:`mu_for`.

        >>> t = Table.default()
        >>> t.curve_for(Model(1.0, 0.001)).mu(0.01) == t.curve(1.0, 0.001).mu(0.01)
        True
        """
        if not isinstance(model, Model):
            raise TypeError(f"model must be a ke_friction.Model, not {type(model).__name__}")
        self._core.check_constants(model._core)
        return self.curve(model.psi, model.theta)

    def __repr__(self) -> str:
        i = self.info
        shape = ""
        if i.get("distribution", "gaussian") != "gaussian":
            shape = f"distribution={i['distribution']!r}, skewness={i['skewness']!r}, kurtosis={i['kurtosis']!r}, "
        return (f"Table(model={i['model']!r}, fit={i['fit']!r}, {shape}psi={i['psi']}, theta={i['theta']}, "
                f"f_star={i['f_star']}, tolerance={i['tolerance']})")


def _table_of(source: Union[str, bytes]) -> Table:
    """A pickled table: ``"default"`` or a table file's bytes."""
    return Table.default() if source == "default" else Table.from_bytes(source)
