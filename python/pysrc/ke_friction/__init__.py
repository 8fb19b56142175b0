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
  SurfaceTopography object), or two pressed together: its statistics
  (in a band of the ISO 16610 S- and L-filters, ``lambda_s``,
  ``lambda_c``), and with the materials its :class:`Model` and friction;
  against the scale (:meth:`Surface.scan`), its power spectral density
  (:meth:`Surface.psd`), scale-dependent slope and curvature and a
  scanning probe's reliability cut-off;
* :class:`Container` -- several measurements of one surface (a
  contact.engineering container): their combined power spectrum and mu
  from the whole band the instruments resolve together;
* :class:`FrictionLaw` -- mu(p) and dmu/dp of the contact pressure p in
  pascals (F* = p/H), for a simulator's contact nodes, with a stated
  policy outside its pressure range, and solver-ready tables;
* :func:`params_from_physical` -- psi, theta, beta, nu, eps_star from SI inputs.

Lookups take Python floats (and return a float) or array-likes, which
broadcast by NumPy's rules (and return float64 arrays). Arguments outside
the table's or curve's range, or NaN, raise ValueError naming the argument,
its value, its index and the range; ``out_of_domain="nan"`` gives NaN there
instead (the library's own batch policy). Errors map to exceptions by the
library's error kinds: ValueError for bad arguments, values out of range
(F* > 1, a pressure above the hardness, included) and an undefined mu; OSError for a file that cannot be read;
:class:`TableError` (a ValueError) for a damaged table file; RuntimeError
for a bug. A result that is returned but implausible (a load outside
the paper's range, h* < 0, mu > 1 where adhesion dominates, few
asperities in contact, a surface the relations fit poorly) warns with
:class:`ModelWarning` (a UserWarning), once per kind and call, and is
in the records' ``warnings``. Records use the library's names: :attr:`Table.info` is what
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

# The package is split by content: _args (argument checks, broadcasting),
# _errors (TableError, located errors), _table, _curve, _distribution,
# _model, _surface; this module re-exports their names, public and private,
# and makes the public ones (and the picklers) ke_friction's own.
#
# The modules and typing names this module imported when it held the whole
# package, kept so that ``from ke_friction import np`` (and the like) still
# works; dir() leaves them out.
import dataclasses
import math
import numbers
import os
import types
from typing import Any, Dict, Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import _core
from ._args import (_F64, _MODES, ArrayLike, FloatArray, OutOfDomain, _arrays, _check_real, _is_scalar, _mode,
                    _threads)
from ._container import Container
from ._curve import CURVE_ACCURACY, Curve, _curve_of
from ._distribution import HeightDistribution, _distribution_of, _heights_array, _heights_of, _resolve
from ._errors import WARNING_KINDS, ModelWarning, TableError, _located, _warn
from ._law import LAW_F_STAR_RANGE, FrictionLaw, _law_of
from ._model import DEFAULTS, Contact, Model, params_from_physical
from ._surface import (_DERIVATIVES, _DETRENDS, _FAMILIES, _LENGTH_UNITS, _MATERIALS, Surface, _choice, _interval,
                       _materials, _surface_of)
from ._table import _TABLE_ARGS, Table, _table_of

__all__ = ["Table", "Curve", "Model", "Contact", "HeightDistribution", "Surface", "Container", "FrictionLaw",
           "TableError",
           "ModelWarning", "params_from_physical", "CURVE_ACCURACY", "DEFAULTS", "WARNING_KINDS", "LAW_F_STAR_RANGE"]

#: The package's version: the library's (the Rust crate's).
__version__: str = _core.__version__


def __dir__() -> "list[str]":
    """The public API alone (not the modules and typing names this module
    imports)."""
    return sorted([*__all__, "__version__"])


def _rehome(*objects: Any) -> None:
    """Give ``objects`` (and a class's functions, static methods and
    properties) the module ``ke_friction``, where they are public: pickles
    name them ``ke_friction.Model``, ``ke_friction._table_of``, ... as they
    did before the package was split into modules (so old pickles load and
    new ones load in old versions), and doctest and help find them here."""
    for obj in objects:
        obj.__module__ = __name__
        if not isinstance(obj, type):
            continue
        for value in vars(obj).values():
            if isinstance(value, (staticmethod, classmethod)):
                value = value.__func__
            elif isinstance(value, property):
                value = value.fget
            if isinstance(value, types.FunctionType) and value.__module__.startswith(__name__ + "._"):
                value.__module__ = __name__


_rehome(Table, Curve, Model, Contact, HeightDistribution, Surface, Container, FrictionLaw, ModelWarning,
        params_from_physical,
        _table_of, _curve_of, _distribution_of, _surface_of, _law_of)
