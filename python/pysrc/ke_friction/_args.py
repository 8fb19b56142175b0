"""The arguments of the lookups: the typing aliases, the checks of
numbers, ``out_of_domain`` and ``threads``, and the broadcasting of
array-likes into the flat float64 arrays the native layer takes."""

from __future__ import annotations

import numbers
from typing import Any, Literal, Optional, Tuple

import numpy as np
import numpy.typing as npt

#: What lookups take: a number or anything :func:`numpy.asarray` turns into
#: an array of real numbers.
ArrayLike = npt.ArrayLike
#: What lookups give for array input: float64 arrays of the broadcast shape.
FloatArray = npt.NDArray[np.float64]
#: ``out_of_domain``: raise ValueError, or give NaN at those elements.
OutOfDomain = Literal["raise", "nan"]
_MODES = ("raise", "nan")
_F64 = np.dtype(np.float64)


def _is_scalar(x: Any) -> bool:
    """A real number that is not an array (bool excluded, as NumPy's
    ``isreal`` would let it through silently)."""
    if type(x) is float:  # the common cases first: isinstance on an ABC is slow
        return True
    if type(x) is np.ndarray:
        return False
    return isinstance(x, numbers.Real) and not isinstance(x, (bool, np.bool_))


def _choice(name: str, value: Any, allowed: Tuple[str, ...]) -> str:
    """``value`` if it is one of the strings ``allowed``; else TypeError
    (not a str) or ValueError naming argument ``name``, worded as the
    core's unknown name (``ke_friction::NameError``)."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a str, not {type(value).__name__}")
    if value not in allowed:
        raise ValueError(f"{name} '{value[:40]}' is unknown: must be one of " + ", ".join(allowed))
    return value


def _scalar(call: Any, args: Tuple[float, ...], nan: bool, width: int = 1) -> Any:
    """``call(*args)`` of scalars (the core's ``*_scalar``); where the core
    refuses them (ValueError), NaN (``width`` of them) with ``nan``, else
    the error."""
    try:
        return call(*args)
    except ValueError:
        if nan:
            return float("nan") if width == 1 else (float("nan"),) * width
        raise


def _mode(out_of_domain: str) -> bool:
    if out_of_domain not in _MODES:
        _choice("out_of_domain", out_of_domain, _MODES)
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


def _check_real(**named: Any) -> None:
    for name, value in named.items():
        if not _is_scalar(value):
            raise TypeError(f"{name} must be a real number, not {type(value).__name__}")
