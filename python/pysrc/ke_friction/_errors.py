"""The errors of the package: :class:`TableError` and the located
exceptions of array work (the native layer's errors given the bad
element's index in the array's shape)."""

from __future__ import annotations

from typing import Tuple

import numpy as np

from . import _core

#: Raised for a table file that is damaged, not a table, or inconsistent
#: (a subclass of ValueError).
TableError = _core.TableError


def _located(e: BaseException, shape: Tuple[int, ...]) -> BaseException:
    """An exception of the native layer for an array of ``shape``: the same
    class, its message ending in the bad element's index in that shape if
    it has one (its ``index`` attribute: the flat index); else ``e``."""
    index = getattr(e, "index", None)
    if index is None or not shape:
        return e
    where = tuple(int(i) for i in np.unravel_index(index, shape))
    return type(e)(f"{e} (at index {where})")
