"""The errors of the package: :class:`TableError` and the located
exceptions of array work (the native layer's errors given the bad
element's index in the array's shape)."""

from __future__ import annotations

import warnings
from typing import Any, Dict, List, Tuple

import numpy as np

from . import _core

#: Raised for a table file that is damaged, not a table, or inconsistent
#: (a subclass of ValueError).
TableError = _core.TableError


class ModelWarning(UserWarning):
    """A result that is returned but implausible, or to be read with care:
    the library's warnings (a load outside the paper's range, h* < 0, mu > 1
    where adhesion dominates, few asperities in contact, spectral
    derivatives of a non-periodic surface, anisotropy, ...), one per kind.
    ``kind`` is its name (one of :data:`WARNING_KINDS`), ``record`` its
    record (``kind``, ``message``, its values, ``count`` and ``of``: the
    results that gave it, of how many)."""

    def __init__(self, message: str, record: "Dict[str, Any] | None" = None) -> None:
        super().__init__(message)
        self.record: Dict[str, Any] = dict(record or {})
        self.kind: str = self.record.get("kind", "")


#: The names of the warnings' kinds, from the library (its one list).
WARNING_KINDS: Tuple[str, ...] = tuple(_core.WARNING_KINDS)


def _warn(summaries: List[Dict[str, Any]], stacklevel: int = 3) -> None:
    """Warn each of the library's warning summaries (one a kind) as a
    :class:`ModelWarning` with its ``summary`` (the line the CLI prints)."""
    for s in summaries:
        warnings.warn(ModelWarning(s["summary"], s), stacklevel=stacklevel)


def _located(e: BaseException, shape: Tuple[int, ...]) -> BaseException:
    """An exception of the native layer for an array of ``shape``: the same
    class, its message ending in the bad element's index in that shape if
    it has one (its ``index`` attribute: the flat index); else ``e``."""
    index = getattr(e, "index", None)
    if index is None or not shape:
        return e
    where = tuple(int(i) for i in np.unravel_index(index, shape))
    return type(e)(f"{e} (at index {where})")
