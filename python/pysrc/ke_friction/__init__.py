"""The Kogut-Etsion (2004) static friction model of rough surfaces.

The static friction coefficient mu of two rough surfaces as a function of
the load F* = F/(A_n H), the plasticity index psi, the adhesion parameter
theta = dgamma/(sigma H) and the roughness (beta, nu, eps_star):

* :class:`Table` -- mu(psi, theta, F*) from a precomputed table
  (nanoseconds per point; the default table is built in);
* :class:`Curve` -- mu(F*) of one surface pair (fixed psi and theta);
* :class:`Model` -- the model by direct integration (microseconds);
* :class:`HeightDistribution` -- the asperity heights' distribution a
  :class:`Model` takes: Gaussian (the paper's), Pearson (skewness and
  kurtosis), Weibull, or the empirical density of measured heights;
* :class:`Surface` -- a measured surface (X3P, .npy, text, an array or a
  SurfaceTopography object), or two pressed together: its statistics,
  and with the materials its :class:`Model` and friction;
* :func:`params_from_physical` -- psi, theta, beta, nu, eps_star from SI inputs.

Lookups take Python floats (and return a float) or array-likes, which
broadcast by NumPy's rules (and return float64 arrays). Arguments outside
the table's or curve's range, or NaN, raise ValueError naming the argument,
its value, its index and the range; ``out_of_domain="nan"`` gives NaN there
instead (the library's own batch policy). Errors map to exceptions by the
library's error kinds: ValueError for bad arguments, values out of range
and an undefined mu; OSError for a file that cannot be read;
:class:`TableError` (a ValueError) for a damaged table file; RuntimeError
for a bug. Records use the library's names: :attr:`Table.info` is what
``kefric info --json`` prints, :attr:`Model.params` and
:func:`params_from_physical` what ``kefric params --json`` prints, and
:data:`DEFAULTS` the model constants a :class:`Model` takes by default.
Array work runs with the GIL released and, if asked
(``threads=None`` for one per core, or a number), on several threads.
Tables, curves and models pickle (for multiprocessing and Dask): the
default table as its name, a loaded table with its file's bytes, a curve
and a model as they were made; float64 input of any alignment or byte
order is accepted (copied where it has to be).

>>> import ke_friction as kf
>>> t = kf.Table.default()
>>> round(t.mu(1.0, 0.001, 0.01), 4)
0.5252
"""

from __future__ import annotations

import dataclasses
import math
import numbers
import os
import types
from typing import Any, Dict, Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import _core

__all__ = ["Table", "Curve", "Model", "Contact", "HeightDistribution", "Surface", "TableError",
           "params_from_physical", "CURVE_ACCURACY", "DEFAULTS"]

#: The package's version: the library's (the Rust crate's).
__version__: str = _core.__version__


def __dir__() -> "list[str]":
    """The public API alone (not the modules and typing names this module
    imports)."""
    return sorted([*__all__, "__version__"])

#: Raised for a table file that is damaged, not a table, or inconsistent
#: (a subclass of ValueError).
TableError = _core.TableError

#: The relative accuracy of :meth:`Curve.from_model` against the model.
CURVE_ACCURACY: float = _core.CURVE_ACCURACY

#: The model constants a :class:`Model` takes unless told otherwise, from
#: the library (read-only): ``beta``, ``nu``, ``eps_star``, ``fit``,
#: ``model``, ``distribution``, ``skewness`` and ``kurtosis``, by the names
#: of its records.
DEFAULTS: "types.MappingProxyType[str, Any]" = types.MappingProxyType(_core.DEFAULTS)

#: What lookups take: a number or anything :func:`numpy.asarray` turns into
#: an array of real numbers.
ArrayLike = npt.ArrayLike
#: What lookups give for array input: float64 arrays of the broadcast shape.
FloatArray = npt.NDArray[np.float64]
#: ``out_of_domain``: raise ValueError, or give NaN at those elements.
OutOfDomain = Literal["raise", "nan"]
_MODES = ("raise", "nan")
_F64 = np.dtype(np.float64)
_TABLE_ARGS = ("psi", "theta", "f_star")


def _is_scalar(x: Any) -> bool:
    """A real number that is not an array (bool excluded, as NumPy's
    ``isreal`` would let it through silently)."""
    if type(x) is float:  # the common cases first: isinstance on an ABC is slow
        return True
    if type(x) is np.ndarray:
        return False
    return isinstance(x, numbers.Real) and not isinstance(x, (bool, np.bool_))


def _mode(out_of_domain: str) -> bool:
    if out_of_domain not in _MODES:
        raise ValueError(f'out_of_domain = {out_of_domain!r}: must be "raise" or "nan"')
    return out_of_domain == "nan"


def _threads(threads: Optional[int]) -> int:
    """``threads`` for the native layer: 0 for None (one per core)."""
    if threads is None:
        return 0
    if type(threads) is int and threads >= 1:  # before isinstance on an ABC, which is slow
        return threads
    if not isinstance(threads, numbers.Integral) or isinstance(threads, (bool, np.bool_)):
        raise TypeError(f"threads must be an int or None, not {type(threads).__name__}")
    if threads < 1:
        raise ValueError(f"threads = {threads}: must be at least 1 (or None for one per core)")
    return int(threads)


def _arrays(names: Tuple[str, ...], values: Tuple[Any, ...], scalars: bool = False) -> Tuple[Tuple[int, ...], list]:
    """Broadcast the inputs ``values`` (called ``names``): their shape, and
    each as a flat contiguous float64 array of that shape's size (a view,
    not a copy, of an array that already is one) or, with ``scalars``, of
    size 1 where it is one value (the native layer repeats it)."""
    # The common case first, in few steps (they count: with keyword
    # arguments and a generator this took 1.35 us, now 0.91, against 1.4 us
    # for the native call on 100 elements; and after other work has swept
    # the caches each step costs microseconds): float64 arrays of one
    # shape, flattened (a view where C-contiguous, else a contiguous copy).
    first = values[0]
    if type(first) is np.ndarray and first.dtype == _F64:
        for a in values:
            if type(a) is not np.ndarray or a.dtype != _F64 or a.shape != first.shape:
                break
        else:
            return first.shape, [a.ravel() for a in values]
    arrays = []
    for name, value in zip(names, values):
        a = np.asarray(value)
        if a.dtype.kind not in "iuf":
            raise TypeError(f"{name} must be a real number or an array of real numbers, not {type(value).__name__}"
                            + (f" of {a.dtype}" if isinstance(value, np.ndarray) else ""))
        arrays.append(a)
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays))
    except ValueError:
        shapes = ", ".join(f"{n} {a.shape}" for n, a in zip(names, arrays))
        raise ValueError(f"the shapes do not broadcast: {shapes}") from None
    flat = []
    for a in arrays:
        if a.shape == shape and a.dtype == _F64 and a.flags.c_contiguous:
            flat.append(a.reshape(-1))  # a view: no copy
        elif scalars and a.size == 1:
            flat.append(np.ascontiguousarray(a, dtype=np.float64).reshape(1))
        else:
            flat.append(np.ascontiguousarray(np.broadcast_to(a, shape), dtype=np.float64).reshape(-1))
    return shape, flat


def _located(e: BaseException, shape: Tuple[int, ...]) -> BaseException:
    """An exception of the native layer for an array of ``shape``: the same
    class, its message ending in the bad element's index in that shape if
    it has one (its ``index`` attribute: the flat index); else ``e``."""
    index = getattr(e, "index", None)
    if index is None or not shape:
        return e
    where = tuple(int(i) for i in np.unravel_index(index, shape))
    return type(e)(f"{e} (at index {where})")


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
        """The static friction coefficient mu(psi, theta, F*), interpolated.

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
            try:
                return self._core.mu_scalar(float(psi), float(theta), float(f_star))
            except ValueError:
                if nan:
                    return float("nan")
                raise
        workers = _threads(threads)
        shape, (p, t, f) = _arrays(_TABLE_ARGS, (psi, theta, f_star), scalars=True)
        out = np.empty(math.prod(shape))
        try:
            self._core.mu_into(p, t, f, out, nan, workers)
        except Exception as e:
            raise _located(e, shape) from None
        return out.reshape(shape)[()]

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
            try:
                return self._core.mu_with_slope_scalar(float(psi), float(theta), float(f_star))
            except ValueError:
                if nan:
                    return (float("nan"), float("nan"))
                raise
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
        a :class:`Curve`, several times faster than :meth:`mu` per point."""
        _check_real(psi=psi, theta=theta)
        psi, theta = float(psi), float(theta)
        return Curve(self._core.curve(psi, theta), ("table", self, psi, theta))

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


def _curve_of(how: str, source: Any, a: float, b: float) -> "Curve":
    """A pickled curve: of ``"table"`` ``source`` at (psi, theta) = (a, b),
    or of ``"model"`` ``source`` over F* in [a, b]."""
    return source.curve(a, b) if how == "table" else Curve.from_model(source, a, b)


def _check_real(**named: Any) -> None:
    for name, value in named.items():
        if not _is_scalar(value):
            raise TypeError(f"{name} must be a real number, not {type(value).__name__}")


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
            try:
                return self._core.mu_scalar(float(f_star))
            except ValueError:
                if nan:
                    return float("nan")
                raise
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
            try:
                return self._core.mu_with_slope_scalar(float(f_star))
            except ValueError:
                if nan:
                    return (float("nan"), float("nan"))
                raise
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


def _distribution_of(family: str, skewness: Optional[float], kurtosis: Optional[float],
                     heights: Optional[np.ndarray], parts: Optional[Tuple[Any, ...]] = None) -> "HeightDistribution":
    """A pickled :class:`HeightDistribution`: its family and what made it
    (``parts``: the two surfaces' detrended heights and standard
    deviations of an empirical density of a :meth:`Surface.pair`)."""
    if parts is not None:
        return HeightDistribution._empirical_sum(*parts)
    if family == "gaussian":
        return HeightDistribution.gaussian()
    if family == "pearson":
        return HeightDistribution.pearson(skewness, kurtosis)
    if family == "weibull":
        return HeightDistribution.weibull(skewness)
    return HeightDistribution.empirical(heights)


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
      |Sk| <= 5 and K <= 100; Pearson(0, 3) is the Gaussian;
    * :meth:`weibull` -- a Weibull distribution of skewness Sk in
      (-1.1395, 2] (its kurtosis follows from Sk);
    * :meth:`empirical` -- a kernel density of measured heights (at least
      100 finite values, any unit; NaN marks a missing point).

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
        if family == "empirical":
            return _distribution_of, (family, None, None, self._heights)
        return _distribution_of, (family, self.skewness, self.kurtosis if family == "pearson" else None, None)

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
        |Sk| <= 5, K <= 100 (or for NaN), naming the argument and the bound."""
        _check_real(skewness=skewness, kurtosis=kurtosis)
        return HeightDistribution(_core.DistributionCore.pearson(float(skewness), float(kurtosis)))

    @staticmethod
    def weibull(skewness: float = 0.0) -> "HeightDistribution":
        """The standardised Weibull distribution of ``skewness`` Sk in
        (-1.1395, 2] (its kurtosis follows: 2.717 at Sk = 0); ValueError
        outside."""
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
        """The family: ``"gaussian"``, ``"pearson"``, ``"weibull"`` or ``"empirical"``."""
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
        return "HeightDistribution.gaussian()"


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


@dataclasses.dataclass(frozen=True)
class Contact:
    """The model at one separation or force (floats) or many (arrays):
    separation h* = h/sigma, d* = d/sigma, the contact load P*, the adhesion
    force Fs*, the tangential capacity Q*, the external force F* = P* - Fs*,
    and mu = Q*/F* (NaN where F* <= 0)."""

    h_star: Any
    d_star: Any
    p_star: Any
    fs_star: Any
    q_star: Any
    f_star: Any
    mu: Any


class Model:
    """The Kogut-Etsion model by direct integration (microseconds a point).

    psi: plasticity index, in [1e-3, 1e3]; theta: adhesion parameter, in
    [0, 1e3]; beta: roughness parameter eta*R*sigma, in (0.01928, 100];
    nu: Poisson's ratio of the softer material, in [0, 0.5); eps_star:
    intermolecular distance eps/sigma, in [1e-9, 100]; fit: "consistent"
    (MODEL.md section 4) or "as-printed" (the literal printed Eq. 18);
    model: "ke" (Kogut-Etsion) or "ceb" (the CEB-type comparison model).
    A constant left out (or None) is the library's default,
    :data:`DEFAULTS`: beta = {beta!r}, nu = {nu!r}, eps_star = {eps_star!r},
    fit = {fit!r}, model = {model!r}.

    The asperity heights' distribution (MODEL.md section 9, see
    :class:`HeightDistribution`), as the CLI's flags: Gaussian by default;
    Pearson when ``skewness`` or ``kurtosis`` (not excess: 3 for a
    Gaussian) is given; empirical when ``heights`` (measured heights, an
    array of any shape and real dtype) is given; or
    ``distribution="gaussian"``, ``"pearson"``, ``"weibull"`` (skewness
    alone) or ``"empirical"`` (heights alone), or a
    :class:`HeightDistribution` (then none of the three). A conflicting
    combination raises ValueError naming the argument; an inadmissible
    value (kurtosis <= skewness**2 + 1, too few heights, ...) raises the
    library's ValueError naming it and its bound.
    Invalid values raise ValueError naming the parameter and its range.
    Wrong types raise TypeError. Array work runs with the GIL released,
    and with ``threads=None`` (or a number) on several threads from 8
    points (as :meth:`Table.mu`): near 2x on two cores. The parameters
    are attributes too (``Model(1.0, 0.001).beta``, ``.distribution``,
    ``.skewness``, ``.kurtosis``); a model pickles as its parameters (with
    its :class:`HeightDistribution`, an empirical one with its heights),
    and ``copy`` and ``deepcopy`` give the model itself.

    >>> c = Model(1.0, 0.001).at_f_star(0.01)      # solve F*(h*) = 0.01
    >>> round(c.h_star, 6), round(c.mu, 6)
    (1.469241, 0.525211)
    >>> Model(1.0, 0.001).at_h_star([0.0, 1.0, 2.0]).mu.shape
    (3,)
    >>> round(Model(1.0, 0.001, kurtosis=8.0).at_f_star(1e-4).mu, 6)   # peaked heights
    0.252902
    """

    __slots__ = ("_core", "_params", "_distribution")

    def __init__(self, psi: float, theta: float, beta: Optional[float] = None, nu: Optional[float] = None,
                 eps_star: Optional[float] = None, fit: Optional[str] = None, model: Optional[str] = None,
                 distribution: Union[str, "HeightDistribution", None] = None, skewness: Optional[float] = None,
                 kurtosis: Optional[float] = None, heights: Optional[ArrayLike] = None) -> None:
        _check_real(psi=psi, theta=theta)
        _check_real(**{k: v for k, v in (("beta", beta), ("nu", nu), ("eps_star", eps_star)) if v is not None})
        for name, value in (("fit", fit), ("model", model)):
            if value is not None and not isinstance(value, str):
                raise TypeError(f"{name} must be a str, not {type(value).__name__}")
        dist = _resolve(distribution, skewness, kurtosis, heights)
        self._core = _core.ModelCore(float(psi), float(theta), None if beta is None else float(beta),
                                     None if nu is None else float(nu),
                                     None if eps_star is None else float(eps_star), fit, model,
                                     None if dist is None else dist._core)
        self._distribution = dist
        self._params: Dict[str, Any] = self._core.params()

    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]:
        p = self._params
        return Model, (p["psi"], p["theta"], p["beta"], p["nu"], p["eps_star"], p["fit"], p["model"],
                       self._distribution)

    def __copy__(self) -> "Model":
        return self

    def __deepcopy__(self, memo: Any) -> "Model":
        return self

    @property
    def params(self) -> Dict[str, Any]:
        """The model's parameters, a new dict each time, by the library's
        record names (what ``kefric params --json`` prints): psi, theta,
        beta, nu, eps_star, fit, model, distribution, skewness, kurtosis
        (and heights, their number, for an empirical density). ``Model(**p)``
        rebuilds the model but for an empirical density (whose heights are
        not in the record: use :attr:`height_distribution`)."""
        return dict(self._params)

    psi = property(lambda self: self._params["psi"], doc="The plasticity index psi (a float).")
    theta = property(lambda self: self._params["theta"], doc="The adhesion parameter theta (a float).")
    beta = property(lambda self: self._params["beta"], doc="The roughness parameter beta = eta R sigma (a float).")
    nu = property(lambda self: self._params["nu"], doc="Poisson's ratio of the softer material (a float).")
    eps_star = property(lambda self: self._params["eps_star"],
                        doc="The intermolecular distance eps/sigma (a float).")
    fit = property(lambda self: self._params["fit"], doc='The fit: "consistent" or "as-printed".')
    model = property(lambda self: self._params["model"], doc='The model: "ke" (Kogut-Etsion) or "ceb" (CEB-type).')
    distribution = property(lambda self: self._params["distribution"],
                            doc='The heights\' distribution family: "gaussian", "pearson", "weibull" or "empirical".')
    skewness = property(lambda self: self._params["skewness"], doc="The skewness of the heights' distribution.")
    kurtosis = property(lambda self: self._params["kurtosis"],
                        doc="The kurtosis (not excess) of the heights' distribution.")

    @property
    def height_distribution(self) -> HeightDistribution:
        """The heights' distribution, a :class:`HeightDistribution`."""
        if self._distribution is None:
            return HeightDistribution.gaussian()
        return self._distribution

    def _at(self, x: ArrayLike, at_f_star: bool, name: str, out_of_domain: OutOfDomain,
            threads: Optional[int]) -> Contact:
        nan = _mode(out_of_domain)
        workers = _threads(threads)
        scalar = _is_scalar(x)
        shape, (flat,) = _arrays((name,), (x,))
        out = np.empty((flat.size, 7))
        try:
            self._core.contacts_into(flat, at_f_star, out.reshape(-1), nan, workers)
        except Exception as e:
            raise _located(e, shape) from None
        cols = [np.ascontiguousarray(out[:, k]).reshape(shape)[()] for k in range(7)]
        return Contact(*(float(c) for c in cols)) if scalar else Contact(*cols)

    def at_f_star(self, f_star: ArrayLike, *, out_of_domain: OutOfDomain = "raise",
                  threads: Optional[int] = 1) -> Contact:
        """The model at external force F* > 0 (solving F*(h*) = F*): a
        :class:`Contact` of floats for a number, of arrays for an array-like.
        F* <= 0, NaN or beyond the model's reach raises ValueError (or gives
        NaN with ``out_of_domain="nan"``); a solver that fails to converge
        (a bug) raises RuntimeError either way. ``threads``: as :meth:`Table.mu`,
        from 8 points."""
        return self._at(f_star, True, "f_star", out_of_domain, threads)

    def at_h_star(self, h_star: ArrayLike, *, out_of_domain: OutOfDomain = "raise",
                  threads: Optional[int] = 1) -> Contact:
        """The model at separation h* (|h*| <= 1e6): a :class:`Contact`; mu is
        NaN where F* <= 0. ``out_of_domain`` and ``threads`` as :meth:`at_f_star`."""
        return self._at(h_star, False, "h_star", out_of_domain, threads)

    def __repr__(self) -> str:
        p = self.params
        return "Model(" + ", ".join(f"{k}={v!r}" for k, v in p.items()) + ")"


if Model.__doc__:  # (None under python -OO)
    Model.__doc__ = Model.__doc__.format(**DEFAULTS)


def params_from_physical(*, e1: float, nu1: float, e2: float, nu2: float, hardness: float, sigma: float,
                         radius: float, density: float, delta_gamma: float, epsilon: float) -> Dict[str, Any]:
    """The model's dimensionless parameters of SI inputs.

    e1, e2: Young's moduli (Pa) of the softer material and the other;
    nu1, nu2: their Poisson's ratios; hardness: H of the softer material
    (Pa); sigma: standard deviation of the surface heights, Sq (m);
    radius: mean summit radius R (m); density: areal density eta of
    summits (1/m^2) (a measured surface gives all three:
    :class:`Surface`);
    delta_gamma: energy of adhesion (J/m^2); epsilon: intermolecular
    distance (m). Returns the model's parameters by the library's record
    names, as ``kefric params --json`` prints them: {"psi", "theta",
    "beta", "nu", "eps_star", "fit", "model", "distribution", "skewness",
    "kurtosis"} (the last five the defaults: Gaussian heights), ready for
    ``Model(**p)``. Unphysical input raises ValueError naming it.

    >>> p = params_from_physical(e1=200e9, nu1=0.3, e2=200e9, nu2=0.3, hardness=2e9, sigma=100e-9,
    ...                          radius=10e-6, density=4e10, delta_gamma=0.3, epsilon=0.4e-9)
    >>> round(p["psi"], 4), p["theta"], round(p["beta"], 12)
    (5.6745, 0.0015, 0.04)
    """
    values = dict(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, sigma=sigma, radius=radius,
                  density=density, delta_gamma=delta_gamma, epsilon=epsilon)
    _check_real(**values)
    return _core.params_from_physical(**{k: float(v) for k, v in values.items()})


#: Metres per length unit, by the names SurfaceTopography gives its
#: topographies' ``unit`` (µ as the micro sign or the Greek letter, or u).
_LENGTH_UNITS = {"km": 1e3, "m": 1.0, "cm": 1e-2, "mm": 1e-3, "\u00b5m": 1e-6, "\u03bcm": 1e-6, "um": 1e-6,
                 "nm": 1e-9, "\u00c5": 1e-10, "A": 1e-10, "pm": 1e-12}
_DETRENDS = ("plane", "line", "mean")
_DERIVATIVES = ("fd", "spectral")
_FAMILIES = ("gaussian", "pearson", "weibull", "empirical")
_MATERIALS = ("e1", "nu1", "e2", "nu2", "hardness", "delta_gamma", "epsilon")


def _choice(name: str, value: Any, allowed: Tuple[str, ...]) -> str:
    """``value`` if it is one of the strings ``allowed``; else TypeError
    (not a str) or ValueError naming argument ``name``."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a str, not {type(value).__name__}")
    if value not in allowed:
        raise ValueError(f"{name} = {value!r}: must be " + " or ".join(repr(a) for a in allowed))
    return value


def _interval(name: str, value: Any) -> float:
    """A sampling interval (metres), finite and > 0."""
    _check_real(**{name: value})
    v = float(value)
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"{name} = {v!r} is out of range: must be > 0 and finite (metres)")
    return v


def _materials(values: Dict[str, Any]) -> Tuple[float, ...]:
    """The seven materials keywords of :meth:`Surface.model`, as floats in
    the native layer's order (their ranges are the library's to check)."""
    _check_real(**values)
    return tuple(float(values[k]) for k in _MATERIALS)


def _surface_of(parts: Any, detrend: str, derivative: str) -> "Surface":
    """A pickled :class:`Surface`: its topographies (``(heights, nx, ny,
    dx, dy)`` each, heights flat and row-major) and its options."""
    return Surface(_core.SurfaceCore.new([(np.ascontiguousarray(h, dtype=np.float64), int(nx), int(ny),
                                           float(dx), None if dy is None else float(dy))
                                          for h, nx, ny, dx, dy in parts], detrend, derivative))


class Surface:
    """A measured rough surface as the model sees it (MODEL.md section 10):
    a height map or profile against a flat, or the equivalent surface of
    two rough surfaces pressed together (:meth:`pair`); its statistics
    (:attr:`stats`: sigma (Sq), skewness, kurtosis, the spectral moments,
    the summit density eta, radius R and beta), and with the materials the
    model's inputs (:meth:`model`, :meth:`curve`) and the friction of a
    load (:meth:`friction`), as ``kefric surface`` computes them.

    Make one with :meth:`from_heights` (an array in metres),
    :meth:`read` (an X3P, ``.npy`` or text file) or
    :meth:`from_topography` (a SurfaceTopography object). All lengths are
    in metres. Missing points (NaN, masked) stay missing: left out of
    every sum, never filled. The statistics are taken once, with
    ``detrend`` (``"plane"``: the least-squares plane, a line for a
    profile, the default; ``"line"``: a line along x; ``"mean"``: the mean
    only) and ``derivative`` (``"fd"``: non-periodic finite differences,
    the default; ``"spectral"``: periodic spectral moments, for periodic
    data without missing points). beta and psi depend on the sampling
    intervals and compare only at the same band.

    Immutable; a surface pickles as its heights, intervals and options
    (rebuilt to the bit), and ``copy`` and ``deepcopy`` give it itself.
    Errors: ValueError naming the argument (a bad interval, too few
    points, constant heights, a file that is not a readable surface,
    naming the file), OSError for a file that cannot be read, TypeError
    for arguments of the wrong type.

    >>> x = np.arange(128) * 1e-6
    >>> z = 2e-7 * (np.sin(0.7e6 * x) + np.cos(0.9e6 * x[:, None]) + np.sin(0.31e6 * x + 0.27e6 * x[:, None]))
    >>> s = Surface.from_heights(z, 1e-6)
    >>> s.stats["nx"], s.stats["ny"], round(s.stats["sigma"] * 1e9, 1)
    (128, 128, 244.8)
    >>> m = s.model(e1=70e9, nu1=0.33, e2=200e9, nu2=0.31, hardness=1e9, delta_gamma=0.5, epsilon=0.4e-9)
    >>> m.distribution
    'pearson'
    >>> f = s.friction(force=10.0, area=1e-5, e1=70e9, nu1=0.33, e2=200e9, nu2=0.31, hardness=1e9,
    ...                delta_gamma=0.5, epsilon=0.4e-9)
    >>> f["friction_force"] == 10.0 * f["mu"]
    True
    """

    __slots__ = ("_core",)

    def __init__(self, core: Any) -> None:
        self._core = core

    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]:
        parts = tuple((h, nx, ny, dx, dy) for h, nx, ny, dx, dy in self._core.topographies())
        return _surface_of, (parts, *self._core.options())

    def __copy__(self) -> "Surface":
        return self

    def __deepcopy__(self, memo: Any) -> "Surface":
        return self

    @staticmethod
    def _options(detrend: Any, derivative: Any) -> Tuple[str, str]:
        return _choice("detrend", detrend, _DETRENDS), _choice("derivative", derivative, _DERIVATIVES)

    @staticmethod
    def from_heights(z: ArrayLike, dx: float, dy: Optional[float] = None, *, detrend: str = "plane",
                     derivative: str = "fd") -> "Surface":
        """The surface of measured heights ``z`` (metres; NaN, or a masked
        entry of a NumPy masked array, marks a missing point): a 1-D array
        is a profile sampled every ``dx`` metres (no ``dy``), a 2-D array a
        map whose rows are y (``z[j, i]`` at x = i dx, y = j dy; ``dy``
        defaults to ``dx``). Any real dtype,
        byte order and memory layout (copied as needed; the surface keeps
        its own copy). ``detrend`` and ``derivative`` as in
        :class:`Surface`.

        ValueError: ``dx`` or ``dy`` not finite and > 0, an array of
        another dimension, an infinite height, fewer than 16 points along a
        direction or 100 valid ones (a fully masked array), constant
        heights; TypeError for non-numeric input."""
        a = _heights_of("z", z, copy=False)  # SurfaceCore.new copies
        if a.ndim not in (1, 2):
            raise ValueError(f"z must be 1-D (a profile) or 2-D (a map, rows = y), not {a.ndim}-D (shape {a.shape})")
        options = Surface._options(detrend, derivative)
        dx = _interval("dx", dx)
        if a.ndim == 1:
            if dy is not None:
                raise ValueError("dy: not for a profile (a 1-D z has no y)")
            ny, nx, dy = 1, a.shape[0], None
        else:
            (ny, nx), dy = a.shape, dx if dy is None else _interval("dy", dy)
        return Surface(_core.SurfaceCore.new([(a.reshape(-1), nx, ny, dx, dy)], *options))

    @staticmethod
    def read(path: Union[str, "os.PathLike[str]"], *, dx: Optional[float] = None, dy: Optional[float] = None,
             z_unit: float = 1.0, xy_unit: float = 1.0, detrend: str = "plane", derivative: str = "fd",
             max_points: Optional[int] = None) -> "Surface":
        """The surface in the file ``path``, by the library's reader (as
        ``kefric surface`` reads it): ISO 25178-72 X3P (``.x3p``), NumPy
        ``.npy`` (1-D a profile, 2-D a map, rows = y; f4 or f8) or, any
        other extension, text (one column a profile, ``x z`` pairs,
        ``x y z`` triples on a regular grid, or a matrix of heights).

        ``dx``, ``dy``: the sampling intervals in metres, for files that
        give none (``.npy``, a text matrix or column); ``dy`` defaults to
        ``dx``; an interval that contradicts the file's own is an error.
        ``z_unit``: metres per unit of the heights of ``.npy`` and text
        files (1e-6 for micrometres; X3P stores metres). ``xy_unit``:
        metres per unit of the x, y columns of ``x z`` and ``x y z`` text.
        Both finite and > 0 (ValueError naming the argument otherwise).
        ``detrend``, ``derivative`` as in :class:`Surface`.
        ``max_points``: the most points (heights) the surface may have,
        an integer >= 1; None (the default) is the library's limit,
        ``MAX_POINTS`` = 2**28. A file whose declared size is over it is
        refused before its heights are allocated.

        OSError if the file cannot be read; ValueError, naming the file,
        for one that is not a readable surface (damaged, unsupported, no
        interval given, more points than ``max_points``, the message
        giving the limit) or whose statistics cannot be taken;
        MemoryError if its heights cannot be allocated."""
        if not isinstance(path, (str, os.PathLike)):
            raise TypeError(f"path must be a str or os.PathLike, not {type(path).__name__}")
        options = Surface._options(detrend, derivative)
        dx = None if dx is None else _interval("dx", dx)
        dy = dx if dy is None else _interval("dy", dy)
        _check_real(z_unit=z_unit, xy_unit=xy_unit)
        z_unit, xy_unit = float(z_unit), float(xy_unit)
        for name, unit in (("z_unit", z_unit), ("xy_unit", xy_unit)):
            if not (math.isfinite(unit) and unit > 0):
                raise ValueError(f"{name} = {unit!r} is out of range: must be finite and > 0 (metres per unit)")
        if max_points is not None:
            if isinstance(max_points, bool) or not isinstance(max_points, numbers.Integral):
                raise TypeError(f"max_points must be an int or None, not {type(max_points).__name__}")
            max_points = int(max_points)
            if not 1 <= max_points < 2**64:
                raise ValueError(f"max_points = {max_points} is out of range: must be an integer in [1, 2**64 - 1] "
                                 "(points), or None for the library's limit")
        return Surface(_core.SurfaceCore.read(os.fspath(path), dx, dy, z_unit, xy_unit, *options, max_points))

    @staticmethod
    def from_topography(topography: Any, *, unit: Optional[str] = None, detrend: str = "plane",
                        derivative: str = "fd") -> "Surface":
        """The surface of a SurfaceTopography object on a regular grid (a
        ``Topography`` map or a ``UniformLineScan`` profile, detrended or
        not): its heights, pixel size and ``unit`` (``"m"``, ``"mm"``,
        ``"µm"`` or ``"um"``, ``"nm"``, ``"Å"``, ``"pm"``, ...), converted to
        metres. ``unit`` here names the topography's unit where it has none
        (or overrides it). Undefined (masked) and NaN heights stay missing.
        The heights are copied; ``detrend``, ``derivative`` as in
        :class:`Surface`.

        Needs the SurfaceTopography package (ImportError without it).
        TypeError for anything else (a nonuniform line scan);
        ValueError for an unknown or missing unit."""
        try:
            from SurfaceTopography.HeightContainer import UniformTopographyInterface
        except ImportError as e:
            raise ImportError("Surface.from_topography needs the SurfaceTopography package "
                              "(pip install SurfaceTopography)") from e
        if not isinstance(topography, UniformTopographyInterface):
            raise TypeError("topography must be a SurfaceTopography Topography or UniformLineScan (a regular "
                            f"grid), not {type(topography).__name__}")
        name = topography.unit if unit is None else unit
        if name is None:
            raise ValueError("unit: the topography has none: give its unit (unit=\"um\", ...)")
        if not isinstance(name, str):
            raise TypeError(f"unit must be a str, not {type(name).__name__}")
        if name not in _LENGTH_UNITS:
            raise ValueError(f"unit = {name!r}: must be one of " + ", ".join(repr(u) for u in _LENGTH_UNITS))
        metres = _LENGTH_UNITS[name]
        h = _heights_of("the topography's heights", topography.heights())
        pixel = [float(p) * metres for p in np.atleast_1d(topography.pixel_size)]
        # SurfaceTopography indexes heights [x, y]; a map here has rows = y.
        z = h * metres if topography.dim == 1 else h.T * metres
        return Surface.from_heights(z, *pixel, detrend=detrend, derivative=derivative)

    @staticmethod
    def pair(a: "Surface", b: "Surface", *, detrend: Optional[str] = None,
             derivative: Optional[str] = None) -> "Surface":
        """Two rough surfaces pressed together: the equivalent surface of
        their summed heights against a flat (MODEL.md section 10; the
        library's ``Surface::pair``). Both are profiles or both maps,
        ideally sampled alike (a warning in :attr:`stats` says when their
        intervals differ by more than 1 %). Its statistics are taken with
        ``detrend`` and ``derivative`` (by default the two surfaces',
        which must then agree); its Pearson distribution is of the added
        cumulants, its empirical one the convolution of the two.
        ValueError for a profile with a map, or a surface that is a pair
        already."""
        for name, s in (("a", a), ("b", b)):
            if not isinstance(s, Surface):
                raise TypeError(f"{name} must be a Surface, not {type(s).__name__}")
            if s._core.is_pair():
                raise ValueError(f"{name} is a pair already: give two single surfaces")
        (da, va), (db, vb) = a._core.options(), b._core.options()
        if detrend is None:
            if da != db:
                raise ValueError(f"detrend: the surfaces have {da!r} and {db!r}: give detrend=")
            detrend = da
        if derivative is None:
            if va != vb:
                raise ValueError(f"derivative: the surfaces have {va!r} and {vb!r}: give derivative=")
            derivative = va
        return Surface(_core.SurfaceCore.pair(a._core, b._core, *Surface._options(detrend, derivative)))

    @property
    def stats(self) -> Dict[str, Any]:
        """The surface's statistics (of the equivalent surface, for a pair),
        a new dict each time, by the library's record names (what ``kefric
        surface --json`` prints as ``"surface"``), in SI units: ``points``,
        ``missing``, ``nx``, ``ny``, ``dx``, ``dy`` (None for a profile),
        ``sigma`` (Sq), ``skewness``, ``kurtosis`` (not excess), the moments
        ``m20``, ``m02``, ``m40``, ``m04``, ``m2``, ``m4``, the bandwidth
        ``alpha``, the summit density ``eta``, radius ``radius``, ``beta``,
        ``sigma_s``, ``y_s``, the anisotropy ratios, and ``warnings`` (a
        list of ``{"kind", "message", ...}``)."""
        return self._core.stats()

    @property
    def parts(self) -> "list[Dict[str, Any]]":
        """The statistics of each measured surface, as :attr:`stats`: two
        for a :meth:`pair` (``kefric surface --json``'s ``"parts"``), one
        (the same as :attr:`stats`) for a single surface."""
        return self._core.parts()

    @property
    def is_pair(self) -> bool:
        """Whether this is the equivalent surface of two (:meth:`pair`)."""
        return self._core.is_pair()

    @property
    def detrend(self) -> str:
        """How the heights were detrended: ``"plane"``, ``"line"`` or ``"mean"``."""
        return self._core.options()[0]

    @property
    def derivative(self) -> str:
        """How the slope and curvature moments were estimated: ``"fd"`` or ``"spectral"``."""
        return self._core.options()[1]

    def height_distribution(self, distribution: str = "pearson") -> HeightDistribution:
        """The surface's height distribution of a family: ``"pearson"`` (of
        the measured skewness and kurtosis, the default), ``"gaussian"``
        (the paper's), ``"weibull"`` (of the measured skewness) or
        ``"empirical"`` (the kernel density of the detrended heights; a
        pair's is the convolution of the two, and it pickles with them).
        A measured skewness or kurtosis outside the family's range raises
        ValueError naming it."""
        family = _choice("distribution", distribution, _FAMILIES)
        try:
            core = self._core.distribution(family)
        except ValueError as e:
            hint = "" if family == "empirical" else ' (try distribution="empirical")'
            raise ValueError(f"distribution: the surface's {e}{hint}") from None
        if family != "empirical":
            return HeightDistribution(core)
        parts = self._core.empirical_parts()
        if len(parts) == 1:
            return HeightDistribution(core, _heights_array(parts[0][0]))
        (a, sa), (b, sb) = parts
        return HeightDistribution(core, None, (_heights_array(a), sa, _heights_array(b), sb))

    def model(self, *, e1: float, nu1: float, e2: float, nu2: float, hardness: float, delta_gamma: float,
              epsilon: float, distribution: str = "pearson", fit: str = "consistent", model: str = "ke") -> Model:
        """The :class:`Model` of this surface and the materials (as ``kefric
        surface`` with the material flags; its ``"model"`` record is the
        result's :attr:`Model.params`): psi, theta, beta, nu and eps_star
        from sigma, R and eta of :attr:`stats` (the library's
        ``Params::from_physical``) and the surface's
        :meth:`height_distribution` of family ``distribution``.

        e1, e2: Young's moduli (Pa) of the softer material and the other;
        nu1, nu2: their Poisson's ratios; hardness: H of the softer
        material (Pa); delta_gamma: energy of adhesion (J/m^2); epsilon:
        intermolecular distance (m). ``fit`` and ``model`` as in
        :class:`Model`. A value out of range raises ValueError naming the
        keyword (or, for psi, theta, ..., the parameter it gives)."""
        mats = _materials(dict(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, delta_gamma=delta_gamma,
                               epsilon=epsilon))
        for name, value in (("fit", fit), ("model", model)):
            if not isinstance(value, str):
                raise TypeError(f"{name} must be a str, not {type(value).__name__}")
        dist = self.height_distribution(distribution)
        p = self._core.params(mats, dist._core)
        try:
            return Model(p["psi"], p["theta"], p["beta"], p["nu"], p["eps_star"], fit, model, distribution=dist)
        except ValueError as e:
            if str(e).startswith(("fit", "model")):
                raise
            raise ValueError(f"the surface with these materials: {e}") from None

    def curve(self, *, e1: float, nu1: float, e2: float, nu2: float, hardness: float, delta_gamma: float,
              epsilon: float, distribution: str = "pearson", fit: str = "consistent", model: str = "ke",
              f_star_min: float = 1e-5, f_star_max: float = 0.1) -> Curve:
        """The :class:`Curve` mu(F*) of :meth:`model` (the same keywords)
        for F* in [f_star_min, f_star_max] (by default the default table's
        range), as :meth:`Curve.from_model` makes it (tens of
        milliseconds)."""
        m = self.model(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, delta_gamma=delta_gamma,
                       epsilon=epsilon, distribution=distribution, fit=fit, model=model)
        return Curve.from_model(m, f_star_min, f_star_max)

    def friction(self, *, force: Optional[float] = None, area: Optional[float] = None,
                 pressure: Optional[float] = None, e1: float, nu1: float, e2: float, nu2: float, hardness: float,
                 delta_gamma: float, epsilon: float, distribution: str = "pearson", fit: str = "consistent",
                 model: str = "ke") -> Dict[str, Any]:
        """The static friction of a load on :meth:`model` (the same
        keywords): a ``force`` (N) on a nominal ``area`` (m^2), or a
        nominal ``pressure`` (Pa). A dict by the library's record names
        (``kefric surface --json``'s ``"friction"``), in SI units:
        ``force`` and ``area`` (for a force), ``pressure``, ``mu``,
        ``friction_force`` = mu F (for a force), ``friction_stress``,
        ``separation`` h = h* sigma (m), and the dimensionless contact at
        F* = pressure/hardness: ``h_star``, ``d_star``, ``p_star``,
        ``fs_star``, ``q_star``, ``f_star``.

        ValueError naming the keyword for a load out of range (or given
        otherwise than a force with an area, or a pressure alone), and
        when the model has no mu at that F*."""
        if force is not None and area is not None and pressure is None:
            _check_real(force=force, area=area)
            load = (float(force), float(area), None)
        elif force is None and area is None and pressure is not None:
            _check_real(pressure=pressure)
            load = (None, None, float(pressure))
        else:
            name = "pressure" if pressure is not None else "area" if force is not None else "force"
            raise ValueError(f"{name}: give force with area, or pressure alone")
        mats = _materials(dict(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, delta_gamma=delta_gamma,
                               epsilon=epsilon))
        m = self.model(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, delta_gamma=delta_gamma,
                       epsilon=epsilon, distribution=distribution, fit=fit, model=model)
        return self._core.friction(m._core, mats, *load)

    def __repr__(self) -> str:
        s = self.stats
        shape = f"map {s['nx']} x {s['ny']}, dx={s['dx']!r}, dy={s['dy']!r}" if s["dy"] is not None \
            else f"profile of {s['nx']}, dx={s['dx']!r}"
        pair = "pair, " if self.is_pair else ""
        return f"Surface({pair}{shape}, sigma={s['sigma']!r}, detrend={self.detrend!r}, derivative={self.derivative!r})"
