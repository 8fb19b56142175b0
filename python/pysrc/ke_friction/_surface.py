"""A measured surface, :class:`Surface`: read, paired, its statistics,
and with the materials its model and friction."""

from __future__ import annotations

import math
import numbers
import os
import warnings
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np

from . import _core
from ._args import ArrayLike, _arrays, _check_real, _choice, _is_scalar
from ._curve import Curve
from ._distribution import HeightDistribution, _heights_array, _heights_of
from ._errors import ModelWarning, _warn
from ._model import Model

# The core's name lists (defined once, in Rust).
_DETRENDS = tuple(_core.DETRENDS)
_DERIVATIVES = tuple(_core.DERIVATIVES)
_FAMILIES = tuple(_core.FAMILIES)
_WINDOWS = tuple(_core.WINDOWS)
#: The length units' names (``kefric surface --z-unit``'s) and the other
#: symbols SurfaceTopography gives its topographies' ``unit`` ("µm", "Å").
_LENGTH_UNITS = tuple(_core.LENGTH_UNITS)
_MATERIALS = tuple(_core.MATERIALS)


class _Record(dict):  # type: ignore[type-arg]
    """A record (a dict) that may also be called, giving itself: the
    statistics are :attr:`Surface.stats` as they always were and
    ``Surface.stats()`` as :meth:`Surface.model`, :meth:`Surface.curve`
    and :meth:`Surface.friction` are spelled. It pickles, compares and
    serialises as the dict it is."""

    __slots__ = ()

    def __call__(self) -> "_Record":
        return self

    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]:
        # A plain dict in a pickle: no private class to import to load it.
        return dict, (dict(self),)


def _unit(name: str, value: Any, number: bool = True) -> float:
    """Metres per unit of argument ``name``: a unit's name or symbol (one
    of :data:`_LENGTH_UNITS`: ``"um"``, ``"nm"``, ``"µm"``, ... as
    ``kefric surface --z-unit`` takes them; the core's list) or, if
    ``number``, a number, finite and > 0."""
    if isinstance(value, str):
        try:
            return _core.length_unit(value)
        except ValueError as e:
            also = " (or a number of metres per unit)" if number else ""
            raise ValueError(f"{name}: {e}{also}") from None
    _check_real(**{name: value})
    v = float(value)
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"{name} = {v!r} is out of range: must be finite and > 0 (metres per unit), or a unit's "
                         "name (" + ", ".join(_LENGTH_UNITS) + ")")
    return v


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


def _load(force: Any, area: Any, pressure: Any) -> Tuple[Optional[float], Optional[float], Optional[float]]:
    """The load of :meth:`Surface.scan`'s keywords, ``(force, area,
    pressure)`` as the native layer takes it: a force with an area, or a
    pressure alone (ValueError naming the keyword otherwise)."""
    if force is not None and area is not None and pressure is None:
        _check_real(force=force, area=area)
        return float(force), float(area), None
    if force is None and area is None and pressure is not None:
        _check_real(pressure=pressure)
        return None, None, float(pressure)
    name = "pressure" if pressure is not None else "area" if force is not None else "force"
    raise ValueError(f"{name}: give force with area, or pressure alone")


def _loads(force: Any, area: Any, pressure: Any) -> Tuple[Tuple[int, ...], bool, Tuple[Any, ...]]:
    """The loads of :meth:`Surface.friction`'s keywords, broadcast: their
    shape, whether all were numbers, and ``(force, area, pressure)`` as
    lists of floats (None where not given) for the native layer."""
    if force is not None and area is not None and pressure is None:
        names, values = ("force", "area"), (force, area)
    elif force is None and area is None and pressure is not None:
        names, values = ("pressure",), (pressure,)
    else:
        name = "pressure" if pressure is not None else "area" if force is not None else "force"
        raise ValueError(f"{name}: give force with area, or pressure alone")
    scalar = all(_is_scalar(v) for v in values)
    shape, flats = _arrays(names, values)
    lists = dict(zip(names, (f.tolist() for f in flats)))
    return shape, scalar, (lists.get("force"), lists.get("area"), lists.get("pressure"))

def _length(name: str, value: Any) -> Optional[float]:
    """An optional length keyword (metres) as a float; its range is the
    library's to check (its message gives the limits)."""
    if value is None:
        return None
    _check_real(**{name: value})
    return float(value)


def _filters(lambda_s: Any, lambda_c: Any, tip_radius: Any = None, resolution: Any = None) -> Dict[str, Any]:
    """The native layer's filter keywords of the Python ones: ``lambda_s``
    metres or ``"auto"`` (the reliability cut-off), ``lambda_c`` metres,
    the instrument's ``tip_radius`` or ``resolution`` (metres, finite and
    > 0)."""
    auto = isinstance(lambda_s, str)
    if auto and lambda_s != "auto":
        raise ValueError(f"lambda_s = {lambda_s!r}: must be a length in metres, \"auto\" or None")
    out: Dict[str, Any] = dict(lambda_s=None if auto else _length("lambda_s", lambda_s),
                               lambda_c=_length("lambda_c", lambda_c), auto=auto)
    for name, value in (("tip_radius", tip_radius), ("resolution", resolution)):
        out[name] = None if value is None else _interval(name, value)
    return out


def _surface_of(parts: Any, detrend: str, derivative: str, lambda_s: Optional[float] = None,
                lambda_c: Optional[float] = None, known: bool = False,
                cutoff: Optional[float] = None) -> "Surface":
    """A pickled :class:`Surface`: its topographies (``(heights, nx, ny,
    dx, dy)`` each, heights flat and row-major), its options, filters and
    reliability cut-off (``known``: whether one is known; ``cutoff``: it,
    or None when known to be none)."""
    return Surface(_core.SurfaceCore.new([(np.ascontiguousarray(h, dtype=np.float64), int(nx), int(ny),
                                           float(dx), None if dy is None else float(dy))
                                          for h, nx, ny, dx, dy in parts], detrend, derivative,
                                         lambda_s=lambda_s, lambda_c=lambda_c, resolution=cutoff,
                                         no_cutoff=known and cutoff is None))


#: The columns of :meth:`Surface.scan` from the statistics, the model and
#: the friction record (``kefric surface --scan --csv``'s, by the same names).
_SCAN_STATS = ("sigma", "skewness", "kurtosis", "m2", "m4", "alpha", "eta", "radius", "beta")
_SCAN_MODEL = ("psi", "theta")
_SCAN_FRICTION = ("pressure", "mu", "friction_force", "friction_stress", "separation")


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

    The band: ``lambda_s`` (metres) applies the ISO 16610-61 Gaussian
    S-filter (wavelengths shorter than it removed; at least 2 max(dx, dy))
    before the detrending, ``lambda_c`` (metres) the L-filter after it
    (longer ones removed; at most the scan size), as ``kefric surface
    --lambda-s --lambda-c``. ``lambda_s="auto"`` is the instrument's
    reliability cut-off: ``resolution`` (metres, an optical instrument's
    lateral resolution) or, from a scanning probe's ``tip_radius``
    (metres), :meth:`reliability_cutoff` (no filter when the tip distorts
    no scale). With either given, the statistics warn
    (``"unreliable_scale"``) when the shortest scale analysed is below the
    cut-off. :meth:`filtered` changes the filters, :meth:`scan` runs
    lambda_s over a range, :meth:`psd` and :meth:`scale_dependent` give
    the spectrum and the scale-dependent slope and curvature.

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
        lambda_s, lambda_c = self._core.filters()
        known, cutoff = self._core.cutoff()
        if lambda_s is None and lambda_c is None and not known:
            return _surface_of, (parts, *self._core.options())
        return _surface_of, (parts, *self._core.options(), lambda_s, lambda_c, known, cutoff)

    def __copy__(self) -> "Surface":
        return self

    def __deepcopy__(self, memo: Any) -> "Surface":
        return self

    @staticmethod
    def _options(detrend: Any, derivative: Any) -> Tuple[str, str]:
        return _choice("detrend", detrend, _DETRENDS), _choice("derivative", derivative, _DERIVATIVES)

    @staticmethod
    def from_heights(z: ArrayLike, dx: float, dy: Optional[float] = None, *, detrend: str = "plane",
                     derivative: str = "fd", lambda_s: Union[float, str, None] = None,
                     lambda_c: Optional[float] = None, tip_radius: Optional[float] = None,
                     resolution: Optional[float] = None) -> "Surface":
        """The surface of measured heights ``z`` (metres; NaN, or a masked
        entry of a NumPy masked array, marks a missing point): a 1-D array
        is a profile sampled every ``dx`` metres (no ``dy``), a 2-D array a
        map whose rows are y (``z[j, i]`` at x = i dx, y = j dy; ``dy``
        defaults to ``dx``). Any real dtype,
        byte order and memory layout (copied as needed; the surface keeps
        its own copy). ``detrend``, ``derivative``, the filters
        ``lambda_s``, ``lambda_c`` and the instrument's ``tip_radius`` or
        ``resolution`` as in :class:`Surface`.

        ValueError: ``dx`` or ``dy`` not finite and > 0, an array of
        another dimension, an infinite height, fewer than 16 points along a
        direction or 100 valid ones (a fully masked array), constant
        heights; TypeError for non-numeric input."""
        a = _heights_of("z", z, copy=False)  # SurfaceCore.new copies
        if a.ndim not in (1, 2):
            raise ValueError(f"z must be 1-D (a profile) or 2-D (a map, rows = y), not {a.ndim}-D (shape {a.shape})")
        options = Surface._options(detrend, derivative)
        filters = _filters(lambda_s, lambda_c, tip_radius, resolution)
        dx = _interval("dx", dx)
        if a.ndim == 1:
            if dy is not None:
                raise ValueError("dy: not for a profile (a 1-D z has no y)")
            ny, nx, dy = 1, a.shape[0], None
        else:
            (ny, nx), dy = a.shape, dx if dy is None else _interval("dy", dy)
        return Surface(_core.SurfaceCore.new([(a.reshape(-1), nx, ny, dx, dy)], *options, **filters))

    @staticmethod
    def read(path: Union[str, "os.PathLike[str]"], *, dx: Optional[float] = None, dy: Optional[float] = None,
             z_unit: Union[float, str] = 1.0, xy_unit: Union[float, str] = 1.0, detrend: str = "plane",
             derivative: str = "fd",
             max_points: Optional[int] = None, lambda_s: Union[float, str, None] = None,
             lambda_c: Optional[float] = None, tip_radius: Optional[float] = None,
             resolution: Optional[float] = None, channel: Union[str, int, None] = None) -> "Surface":
        """The surface in the file ``path``, by the library's reader (as
        ``kefric surface`` reads it): ISO 25178-72 X3P (``.x3p``), NumPy
        ``.npy`` (1-D a profile, 2-D a map, rows = y; f4 or f8), an
        instrument's own file (Digital Surf ``.sur``, Sensofar ``.plu``
        (``.apx``), Bruker/Veeco ``.opd``, Alicona ``.al3d``, Zygo MetroPro
        ``.dat``, Bruker Nanoscope ``.di``/``.spm``/``.001``, Nanosurf
        ``.nid``: heights in metres by the file's scale factors and units,
        its intervals, invalid points missing; the list: ``kefric surface
        --help``) or, any other extension, text (one column a profile,
        ``x z`` pairs, ``x y z`` triples on a regular grid, or a matrix of
        heights).

        ``dx``, ``dy``: the sampling intervals in metres, for files that
        give none (``.npy``, a text matrix or column); ``dy`` defaults to
        ``dx``; an interval that contradicts the file's own is an error.
        ``z_unit``: the unit of the heights of ``.npy`` and text files
        (X3P and the instruments' files give their own), ``xy_unit``: of the x, y columns of ``x z``
        and ``x y z`` text (``dx`` and ``dy`` are in metres, unlike
        ``kefric surface --dx``, which is in ``--xy-unit``). Each a
        unit's name as ``kefric surface --z-unit`` takes it (``"km"``,
        ``"m"``, ``"cm"``, ``"mm"``, ``"um"``, ``"nm"``, ``"pm"``,
        ``"angstrom"``; or ``"µm"``, ``"Å"``) or a number of metres per
        unit (1e-6 for micrometres), finite and > 0 (ValueError naming
        the argument otherwise).
        ``detrend``, ``derivative``, the filters ``lambda_s``, ``lambda_c``
        and the instrument's ``tip_radius`` or ``resolution`` as in
        :class:`Surface` (``kefric surface --lambda-s``, ``--lambda-c``,
        ``--tip-radius``, ``--resolution``).
        ``max_points``: the most points (heights) the surface may have,
        an integer >= 1; None (the default) is the library's limit,
        ``MAX_POINTS`` = 2**28. A file whose declared size is over it is
        refused before its heights are allocated.
        ``channel``: for a file with several channels (AFM: height,
        amplitude, phase, ...), the one to read, by name (any case) or
        index from 0; None (the default) is the height channel. A wrong or
        ambiguous choice is a ValueError listing the file's channels.

        OSError if the file cannot be read; ValueError, naming the file,
        for one that is not a readable surface (damaged, unsupported, no
        interval given, more points than ``max_points``, the message
        giving the limit) or whose statistics cannot be taken;
        MemoryError if its heights cannot be allocated."""
        if not isinstance(path, (str, os.PathLike)):
            raise TypeError(f"path must be a str or os.PathLike, not {type(path).__name__}")
        options = Surface._options(detrend, derivative)
        filters = _filters(lambda_s, lambda_c, tip_radius, resolution)
        dx = None if dx is None else _interval("dx", dx)
        dy = dx if dy is None else _interval("dy", dy)
        z_unit, xy_unit = _unit("z_unit", z_unit), _unit("xy_unit", xy_unit)
        if max_points is not None:
            if isinstance(max_points, bool) or not isinstance(max_points, numbers.Integral):
                raise TypeError(f"max_points must be an int or None, not {type(max_points).__name__}")
            max_points = int(max_points)
            if not 1 <= max_points < 2**64:
                raise ValueError(f"max_points = {max_points} is out of range: must be an integer in [1, 2**64 - 1] "
                                 "(points), or None for the library's limit")
        if channel is not None:
            if isinstance(channel, bool) or not isinstance(channel, (str, numbers.Integral)):
                raise TypeError(f"channel must be a str, an int or None, not {type(channel).__name__}")
            if isinstance(channel, numbers.Integral) and channel < 0:
                raise ValueError(f"channel = {channel} is out of range: must be an index >= 0 or a name")
            channel = str(channel)
        return Surface(_core.SurfaceCore.read(os.fspath(path), dx, dy, z_unit, xy_unit, *options, max_points,
                                              channel=channel, **filters))

    @staticmethod
    def from_topography(topography: Any, *, unit: Optional[str] = None, detrend: str = "plane",
                        derivative: str = "fd", lambda_s: Union[float, str, None] = None,
                        lambda_c: Optional[float] = None, tip_radius: Optional[float] = None,
                        resolution: Optional[float] = None) -> "Surface":
        """The surface of a SurfaceTopography object on a regular grid (a
        ``Topography`` map or a ``UniformLineScan`` profile, detrended or
        not): its heights, pixel size and ``unit`` (``"m"``, ``"mm"``,
        ``"µm"`` or ``"um"``, ``"nm"``, ``"Å"``, ``"pm"``, ...), converted to
        metres. ``unit`` here names the topography's unit where it has none
        (or overrides it). Undefined (masked) and NaN heights stay missing.
        The heights are copied; ``detrend``, ``derivative``, ``lambda_s``,
        ``lambda_c``, ``tip_radius``, ``resolution`` as in :class:`Surface`.

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
        metres = _unit("unit", name, number=False)
        h = _heights_of("the topography's heights", topography.heights())
        pixel = [float(p) * metres for p in np.atleast_1d(topography.pixel_size)]
        # SurfaceTopography indexes heights [x, y]; a map here has rows = y.
        z = h * metres if topography.dim == 1 else h.T * metres
        return Surface.from_heights(z, *pixel, detrend=detrend, derivative=derivative, lambda_s=lambda_s,
                                    lambda_c=lambda_c, tip_radius=tip_radius, resolution=resolution)

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
    def metadata(self) -> List[Dict[str, Any]]:
        """What each part's file said about its measurement, one dict per
        part (one, or two for a pair), by the library's record names (what
        ``kefric surface --json`` prints as ``"metadata"``): ``format``,
        and where the file gives them ``instrument``, ``date``,
        ``channel``, ``channels``, ``height_unit``; empty for heights not
        read from a file."""
        return self._core.metadata()

    @property
    def stats(self) -> "_Record":
        """The surface's statistics (of the equivalent surface, for a pair),
        a new dict each time; both spellings work: ``s.stats["sigma"]``
        (an attribute, as before) and ``s.stats()["sigma"]`` (a call, as
        :meth:`model`, :meth:`curve` and :meth:`friction`: the dict is
        callable and returns itself). By the library's record names (what ``kefric
        surface --json`` prints as ``"surface"``), in SI units: ``points``,
        ``missing``, ``nx``, ``ny``, ``dx``, ``dy`` (None for a profile),
        ``sigma`` (Sq), ``skewness``, ``kurtosis`` (not excess), the moments
        ``m20``, ``m02``, ``m40``, ``m04``, ``m2``, ``m4``, the bandwidth
        ``alpha``, the summit density ``eta``, radius ``radius``, ``beta``,
        ``sigma_s``, ``y_s``, the anisotropy ratios, the scan size
        ``size_x``, ``size_y`` (None for a profile), the filters' nesting
        indices ``lambda_s``, ``lambda_c`` (None where not applied), and
        ``warnings`` (a list of ``{"kind", "message", ...}``, kinds of
        :data:`WARNING_KINDS`: ``"low_bandwidth"``, ``"anisotropy"``,
        ``"non_periodic"`` for spectral derivatives of a surface whose
        edges jump by more than its rms height, ``"unreliable_scale"`` when
        a reliability cut-off is known and the shortest scale analysed,
        lambda_s or 2 max(dx, dy), is below it; :meth:`model` and
        :meth:`friction` warn them as :class:`ModelWarning`)."""
        return _Record(self._core.stats())

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

    def height_distribution(self, distribution: Optional[str] = None) -> HeightDistribution:
        """The surface's height distribution of a family: ``"pearson"`` (of
        the measured skewness and kurtosis), ``"gaussian"``
        (the paper's), ``"weibull"`` (of the measured skewness) or
        ``"empirical"`` (the kernel density of the detrended heights; a
        pair's is the convolution of the two, and it pickles with them).
        A measured skewness or kurtosis outside the family's range raises
        ValueError naming it. ``None`` (the default) is the library's rule
        (docs/MODEL.md, "The default height model"): Pearson where its upper
        tail is supported by the measured heights, else empirical."""
        if distribution is None:
            family = self._core.default_family()
        else:
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
              epsilon: float, distribution: Optional[str] = None, fit: str = "consistent", model: str = "ke") -> Model:
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
        keyword (or, for psi, theta, ..., the parameter it gives). The
        surface's warnings (:attr:`stats`' ``warnings``) are warned as
        :class:`ModelWarning`."""
        mats = _materials(dict(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, delta_gamma=delta_gamma,
                               epsilon=epsilon))
        for name, value in (("fit", fit), ("model", model)):
            if not isinstance(value, str):
                raise TypeError(f"{name} must be a str, not {type(value).__name__}")
        dist = self.height_distribution(distribution)
        p = self._core.params(mats, dist._core)
        _warn(self._core.warnings())
        try:
            return Model(p["psi"], p["theta"], p["beta"], p["nu"], p["eps_star"], fit, model, distribution=dist)
        except ValueError as e:
            if str(e).startswith(("fit", "model")):
                raise
            raise ValueError(f"the surface with these materials: {e}") from None

    def curve(self, *, e1: float, nu1: float, e2: float, nu2: float, hardness: float, delta_gamma: float,
              epsilon: float, distribution: Optional[str] = None, fit: str = "consistent", model: str = "ke",
              f_star_min: Optional[float] = None, f_star_max: Optional[float] = None) -> Curve:
        """The :class:`Curve` mu(F*) of :meth:`model` (the same keywords)
        for F* in [f_star_min, f_star_max], by default the library's
        ``SURFACE_F_STAR``, [1e-7, 0.1] (``kefric plot surface``'s range:
        down to the light loads :meth:`friction` and ``kefric surface``
        answer, 100 Pa on a hardness of 1 GPa), as
        :meth:`Curve.from_model` makes it (tens of milliseconds; seconds
        for the ``"empirical"`` distribution)."""
        m = self.model(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, delta_gamma=delta_gamma,
                       epsilon=epsilon, distribution=distribution, fit=fit, model=model)
        lo, hi = _core.SURFACE_F_STAR
        return Curve.from_model(m, lo if f_star_min is None else f_star_min, hi if f_star_max is None else f_star_max)

    def friction(self, *, force: Optional[ArrayLike] = None, area: Optional[ArrayLike] = None,
                 pressure: Optional[ArrayLike] = None, e1: float, nu1: float, e2: float, nu2: float,
                 hardness: float, delta_gamma: float, epsilon: float, distribution: Optional[str] = None,
                 fit: str = "consistent", model: str = "ke", sensitivity: bool = True) -> Dict[str, Any]:
        """The static friction of a load on :meth:`model` (the same
        keywords): a ``force`` (N) on a nominal ``area`` (m^2), or a
        nominal ``pressure`` (Pa); numbers, or array-likes that broadcast
        (then every value is an array of their shape). A dict by the
        library's record names (``kefric surface --json``'s
        ``"friction"``), in SI units: ``force`` and ``area`` (for a force),
        ``pressure``, ``mu``, ``friction_force`` = mu F (for a force),
        ``friction_stress``, ``separation`` h = h* sigma (m), and the
        dimensionless contact at F* = pressure/hardness: ``h_star``,
        ``d_star``, ``p_star``, ``fs_star``, ``q_star``, ``f_star``.
        With ``sensitivity`` (the default), ``"sensitivity"``: mu under each
        height model (``{"distribution": {"gaussian": {"mu": ...},
        "pearson": {"mu": ...} or {"error": "..."}, "empirical": ...},
        "lambda_s": [{"lambda_s": ..., "mu": ...}, ...]}``: the band's two
        ends), as ``kefric surface --json`` gives it; for array loads, a
        list of such dicts in the loads' flat order.
        The warnings ``kefric surface --json`` records (``"warnings"``, one
        a kind) are warned as :class:`ModelWarning` warnings, each with its record:
        the surface's, and the loads' (F* outside the paper's 1e-5..0.1,
        h* < 0, mu > 1 where adhesion dominates, fewer than 10 asperities
        in contact on the area, ``tail``: fewer than 10 measured heights
        above the separation), and the model's inputs outside its validity
        domain (``psi_domain``, ``theta_domain``, ``beta_domain``;
        docs/MODEL.md, "Validity domain").

        ValueError naming the keyword for a load out of range (or given
        otherwise than a force with an area, or a pressure alone), for
        F* > 1 (a pressure above the hardness), and when the model has no
        mu at that F*."""
        shape, scalar, lists = _loads(force, area, pressure)
        materials = dict(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, delta_gamma=delta_gamma,
                         epsilon=epsilon)
        mats = _materials(materials)
        m = self._model(materials, distribution, fit, model)
        result = self._core.friction(m._core, mats, *lists)
        _warn(result["warnings"])
        records = result["records"]
        out: Dict[str, Any]
        if scalar:
            out = dict(records[0])
        else:
            out = {k: np.array([r[k] for r in records], dtype=np.float64).reshape(shape) for k in records[0]}
        if sensitivity:
            s = self._core.sensitivity(mats, distribution, fit, model, *lists)
            out["sensitivity"] = s[0] if scalar else s
        return out

    def _model(self, materials: Dict[str, Any], distribution: str, fit: str, model: str) -> Model:
        """:meth:`model` without warning the surface's warnings (the
        caller warns them with its own)."""
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ModelWarning)
            return self.model(**materials, distribution=distribution, fit=fit, model=model)

    def _evaluate(self, materials: Dict[str, Any], load: Optional[Tuple[Optional[float], ...]], distribution: str,
                  fit: str, model: str) -> Tuple[Model, Optional[Dict[str, Any]]]:
        """The :meth:`model` of ``materials`` (the seven keywords) and, with
        a ``load`` (:func:`_load`'s), its friction record (no warnings:
        :meth:`scan`'s rows)."""
        mats = _materials(materials)
        m = self._model(materials, distribution, fit, model)
        if load is None:
            return m, None
        lists = tuple(None if v is None else [v] for v in load)
        return m, self._core.friction(m._core, mats, *lists)["records"][0]

    def filtered(self, lambda_s: Union[float, str, None] = None, lambda_c: Optional[float] = None) -> "Surface":
        """A new surface of the same heights, detrending and derivative
        (and reliability cut-off) with the filters ``lambda_s`` (metres,
        or ``"auto"``: the reliability cut-off of the ``tip_radius`` or
        ``resolution`` this surface was made with) and ``lambda_c``
        (metres); None: no such filter. As ``kefric surface --lambda-s
        --lambda-c``. ValueError for a nesting index out of range (its
        message names the keyword and the limit)."""
        f = _filters(lambda_s, lambda_c)
        return Surface(self._core.filtered(f["lambda_s"], f["lambda_c"], f["auto"]))

    @property
    def lambda_s(self) -> Optional[float]:
        """The S-filter's nesting index (metres), None if not applied."""
        return self._core.filters()[0]

    @property
    def lambda_c(self) -> Optional[float]:
        """The L-filter's nesting index (metres), None if not applied."""
        return self._core.filters()[1]

    @property
    def cutoff(self) -> Optional[float]:
        """The instrument's reliability cut-off (metres) of the
        ``resolution`` or ``tip_radius`` the surface was made with; None
        if none was given or the tip distorts no scale."""
        return self._core.cutoff()[1]

    def psd(self, window: str = "none") -> Dict[str, Tuple[np.ndarray, np.ndarray]]:
        """The power spectral density of the detrended, unfiltered heights
        (as ``kefric surface --psd``), in SurfaceTopography's conventions:
        ``{"x": (q, c)}`` of a profile (q in rad/m, C in m^3, averaged over
        the lines along x), and for a map also ``"y"`` (along y) and
        ``"area"`` (the radially averaged 2-D PSD, C in m^4). ``window``:
        ``"none"`` or ``"hann"``. Of a single surface (ValueError for a
        pair) without missing points."""
        window = _choice("window", window, _WINDOWS)
        return {name: (q, c) for name, q, c in self._core.psd(window)}

    def scale_dependent(self, distances: Optional[ArrayLike] = None, order: int = 1) -> Dict[str, np.ndarray]:
        """The scale-dependent rms slope (``order=1``) or curvature
        (``order=2``, 1/m) of the heights detrended as the statistics are
        (``detrend``), unfiltered, at each stencil length
        in ``distances`` (metres; by default the library's
        ``default_distances``: log-spaced, 5 a decade, from ``order`` x
        max(dx, dy) to half the scan size; ``kefric surface
        --scale-dependent`` prints both orders at ``order=2``'s) (Sanner et al. 2022; the
        library's ``scale_dependent_slope``, ``scale_dependent_curvature``):
        ``{"distance", "x"}``, and ``"y"`` for a map; NaN where fewer than 4
        points have their stencil in the data. Of a single surface without
        missing points (ValueError otherwise)."""
        if isinstance(order, bool) or order not in (1, 2):
            raise ValueError(f"order = {order!r}: must be 1 (slope) or 2 (curvature)")
        if distances is None:
            d = self._core.default_distances(int(order))
        else:
            d = np.ascontiguousarray(np.atleast_1d(np.asarray(distances, dtype=np.float64)))
            if d.ndim != 1:
                raise ValueError(f"distances must be 1-D, not {d.ndim}-D")
        x, y = self._core.scale_dependent(d, int(order))
        out = {"distance": d.copy(), "x": x}
        if y is not None:
            out["y"] = y
        return out

    def reliability_cutoff(self, tip_radius: float, safety_factor: float = 0.5) -> Optional[float]:
        """The length (metres) below which a scanning-probe tip of radius
        ``tip_radius`` (metres) distorts these heights, or None if it
        distorts no scale (the library's ``tip_reliability_cutoff``,
        SurfaceTopography's ``scanning_probe_reliability_cutoff``; safety
        factor 1/2 as in the paper and ``kefric surface --tip-radius``).
        Of a single surface without missing points."""
        _check_real(tip_radius=tip_radius, safety_factor=safety_factor)
        return self._core.reliability_cutoff(float(tip_radius), float(safety_factor))

    def scan(self, *, from_: Optional[float] = None, to: Optional[float] = None, per_decade: int = 5,
             tip_radius: Optional[float] = None, resolution: Optional[float] = None,
             force: Optional[float] = None, area: Optional[float] = None, pressure: Optional[float] = None,
             e1: Optional[float] = None, nu1: Optional[float] = None, e2: Optional[float] = None,
             nu2: Optional[float] = None, hardness: Optional[float] = None, delta_gamma: Optional[float] = None,
             epsilon: Optional[float] = None, distribution: Optional[str] = None, fit: str = "consistent",
             model: str = "ke") -> Dict[str, Any]:
        """The surface against the scale it is looked at (``kefric surface
        --scan``): the statistics at S-filter nesting indices lambda_s
        log-spaced from ``from_`` (default 2 max(dx, dy)) to ``to`` (default
        a tenth of the scan size), ``per_decade`` a decade
        ({ranges[per_decade]}; at most {scan_rows_max} rows, ValueError
        beyond: {scan_decades}/per_decade decades), the other options (detrending, derivative, lambda_c) this surface's.
        Each row equals ``filtered(lambda_s=...)`` at its lambda_s. With the
        seven materials keywords (all or none) also psi and theta of
        :meth:`model`, and with a load (as :meth:`friction`) mu. The
        reliability cut-off: of ``resolution`` or ``tip_radius`` (metres),
        else the surface's own.

        A dict of NumPy arrays, one element a row: ``lambda_s``,
        ``reliable`` (bool: lambda_s at or above the cut-off; all True
        without one), ``sigma``, ``skewness``, ``kurtosis``, ``m2``,
        ``m4``, ``alpha``, ``eta``, ``radius``, ``beta``; with materials
        ``psi``, ``theta``; with a load ``pressure``, ``mu``,
        ``friction_force`` (NaN for a pressure), ``friction_stress``,
        ``separation``. Besides: ``cutoff`` (metres or None) and
        ``errors``, a list of ``(index, lambda_s, message)`` of the rows
        with no result (NaN in their columns: all of them where the
        statistics cannot be taken, the model's and the friction's where
        the model cannot be made).

        ValueError for a range out of order or out of range (its message
        gives both ends), or a load without materials."""
        materials = dict(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, delta_gamma=delta_gamma,
                         epsilon=epsilon)
        given = [k for k, v in materials.items() if v is not None]
        if given and len(given) < len(materials):
            missing = [k for k in _MATERIALS if materials[k] is None]
            raise ValueError(f"{missing[0]}: give all the materials ({', '.join(_MATERIALS)}) or none")
        load = None if force is None and area is None and pressure is None else _load(force, area, pressure)
        if load is not None and not given:
            raise ValueError(f"{'pressure' if pressure is not None else 'force'}: a load needs the materials")
        if given:
            _materials(materials)
            for name, value in (("fit", fit), ("model", model)):
                if not isinstance(value, str):
                    raise TypeError(f"{name} must be a str, not {type(value).__name__}")
            if distribution is not None:
                _choice("distribution", distribution, _FAMILIES)
        if isinstance(per_decade, bool) or not isinstance(per_decade, numbers.Integral):
            raise TypeError(f"per_decade must be an int, not {type(per_decade).__name__}")
        if not _core.in_range("per_decade", per_decade):
            raise ValueError(f"per_decade = {per_decade} is out of range: must be {_core.RANGES['per_decade']}")
        f = _filters(None, None, tip_radius, resolution)
        cutoff, rows = self._core.scan(_length("from_", from_), _length("to", to), int(per_decade),
                                       f["tip_radius"], f["resolution"])
        n = len(rows)
        columns = list(_SCAN_STATS) + (list(_SCAN_MODEL) if given else []) + \
            (list(_SCAN_FRICTION) if load is not None else [])
        out: Dict[str, Any] = {"lambda_s": np.array([r[0] for r in rows], dtype=np.float64),
                               "reliable": np.array([r[1] is not False for r in rows], dtype=bool)}
        for c in columns:
            out[c] = np.full(n, np.nan)
        errors = []
        for i, (lambda_s, _, core, message) in enumerate(rows):
            if core is None:
                errors.append((i, lambda_s, message))
                continue
            surface = Surface(core)
            stats = surface.stats
            for c in _SCAN_STATS:
                out[c][i] = stats[c]
            if not given:
                continue
            try:
                m, friction = surface._evaluate(materials, load, distribution, fit, model)
            except ValueError as e:
                errors.append((i, lambda_s, str(e)))
                continue
            for c in _SCAN_MODEL:
                out[c][i] = m.params[c]
            for c in _SCAN_FRICTION if friction is not None else ():
                v = friction.get(c)
                out[c][i] = np.nan if v is None else v
        out["cutoff"] = cutoff
        out["errors"] = errors
        return out

    def __repr__(self) -> str:
        s = self.stats
        shape = f"map {s['nx']} x {s['ny']}, dx={s['dx']!r}, dy={s['dy']!r}" if s["dy"] is not None \
            else f"profile of {s['nx']}, dx={s['dx']!r}"
        pair = "pair, " if self.is_pair else ""
        band = "".join(f", {k}={s[k]!r}" for k in ("lambda_s", "lambda_c") if s[k] is not None)
        return f"Surface({pair}{shape}, sigma={s['sigma']!r}, detrend={self.detrend!r}, " \
            f"derivative={self.derivative!r}{band})"


# The ranges in the docstring are the core's (`ke_friction::bounds`).
if Surface.scan.__doc__:  # (None under python -OO)
    Surface.scan.__doc__ = Surface.scan.__doc__.format(ranges=_core.RANGES, scan_rows_max=_core.SCAN_ROWS_MAX,
                                                       scan_decades=_core.SCAN_ROWS_MAX - 1)
