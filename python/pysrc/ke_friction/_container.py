"""Several measurements of one surface, :class:`Container`: a
contact.engineering container read, its combined power spectrum, and mu
from the whole band the instruments resolve together."""

from __future__ import annotations

import numbers
import os
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np

from . import _core
from ._args import _check_real, _is_scalar
from ._errors import _warn
from ._surface import _FAMILIES, _choice, _interval, _length, _materials

#: The columns of :meth:`Container.scan` from each row's roughness, model
#: and first load's friction (``kefric surface CONTAINER --scan --csv``'s).
_SCAN_ROUGHNESS = ("sigma", "alpha", "eta", "radius", "beta")
_SCAN_MODEL = ("psi", "theta")


def _container_loads(force: Any, area: Any, pressure: Any,
                     one: bool = False) -> Tuple[Optional[List[float]], Optional[float], Optional[List[float]]]:
    """The loads of :meth:`Container.friction`'s keywords as the native
    layer takes them: forces (a number or a 1-D array-like) on one
    ``area``, or pressures; none at all. ``one``: a single load (the
    scan's)."""
    if force is None and area is None and pressure is None:
        return None, None, None
    if pressure is not None and (force is not None or area is not None):
        raise ValueError(f"{'force' if force is not None else 'area'}: give force with area, or pressure alone")
    if pressure is None and (force is None or area is None):
        raise ValueError(f"{'area' if area is None else 'force'}: give force with area, or pressure alone")
    name, value = ("force", force) if pressure is None else ("pressure", pressure)
    values = np.atleast_1d(np.asarray(value, dtype=np.float64))
    if values.ndim != 1 or values.size == 0:
        raise ValueError(f"{name} must be a number or a 1-D array of them, not of shape {np.shape(value)}")
    if one and values.size != 1:
        raise ValueError(f"{name}: one load for a scan, not {values.size}")
    if area is not None:
        _check_real(area=area)
    loads = values.tolist()
    return (loads, float(area), None) if pressure is None else (None, None, loads)


def _model_keywords(materials: Dict[str, Any], distribution: Any, fit: Any, model: Any) -> Tuple[float, ...]:
    """The seven materials (all needed) as floats, the height model, fit
    and model checked for their type (their names are the library's)."""
    missing = [k for k, v in materials.items() if v is None]
    if missing:
        raise ValueError(f"{missing[0]}: mu from a container needs the materials ("
                         + ", ".join(materials) + ")")
    for name, value in (("fit", fit), ("model", model)):
        if not isinstance(value, str):
            raise TypeError(f"{name} must be a str, not {type(value).__name__}")
    if distribution is not None:
        _choice("distribution", distribution, _FAMILIES)
    return _materials(materials)


class Container:
    """A contact.engineering container ("digital surface twin"): several
    measurements of one surface (say a TEM profile, an AFM map and a
    stylus profile, each resolving its own band of scales) in a zip with
    their ``meta.yml``, read as SurfaceTopography's
    ``Container.IO.read_container`` reads them (each data file by the
    library's readers, the metadata's ``unit``, ``size``,
    ``height_scale`` and ``detrend_mode`` applied); as ``kefric surface
    CONTAINER`` analyses it (docs/MODEL.md, the multi-measurement
    section):

    * :attr:`measurements` -- each one's file, instrument, unit, grid
      (``ny`` = 1 for a profile), spacing, size and reliable range;
    * :meth:`psd` -- each one's reliable 1-D spectrum and the combined one
      (SurfaceTopography's container ``power_spectrum``);
    * :meth:`friction` -- mu from the spectral moments of the combined
      spectrum over the whole band (the height distribution from the
      measurement that resolves the longest scale);
    * :meth:`scan` -- mu against the short cut-off lambda_s, each row with
      the measurements it rests on and the spread of mu across them.

    All lengths in metres. Errors: OSError for a file that cannot be read;
    ValueError naming the keyword for a bad argument, or naming the
    container and the member or ``meta.yml`` field for a container that is
    not one or is damaged (a missing data file, a bad size, ...); TypeError
    for arguments of the wrong type. Warnings as :class:`ModelWarning`,
    as :class:`Surface` warns them.

    >>> c = Container.read("container-2.zip")  # doctest: +SKIP
    >>> [(m["name"], m["nx"], m["ny"]) for m in c.measurements]  # doctest: +SKIP
    [('80_Scale10.472_FIXEDv2p1.asc', 76, 1), ('gain_control_uncd_35.001', 512, 512), ...]
    >>> r = c.friction(force=10.0, area=1e-5, e1=70e9, nu1=0.33, e2=200e9, nu2=0.31, hardness=1e9,
    ...                delta_gamma=0.5, epsilon=0.4e-9)  # doctest: +SKIP
    >>> r["friction"][0]["mu"]  # doctest: +SKIP
    """

    __slots__ = ("_core",)

    def __init__(self, core: Any) -> None:
        self._core = core

    @staticmethod
    def read(source: Union[str, "os.PathLike[str]", bytes, bytearray, memoryview], *, surface: int = 0,
             name: Optional[str] = None, tip_radius: Optional[float] = None, resolution: Optional[float] = None,
             max_points: Optional[int] = None) -> "Container":
        """The container at the path ``source``, or of its bytes
        (``bytes``, ``bytearray`` or ``memoryview``; ``name`` names it in
        messages). ``surface``: which of the container's surfaces (from 0;
        :attr:`surfaces` lists them). ``tip_radius`` or ``resolution``
        (metres, finite and > 0; the resolution first): the instrument's,
        for the measurements whose ``meta.yml`` gives neither (their
        reliable range is cut there). ``max_points``: each measurement's
        most points (None: the library's ``MAX_POINTS``).

        OSError if the file cannot be read; ValueError for a file that is
        not a container (not a zip, no ``meta.yml``) or a damaged one, its
        message naming the member or field (a data file missing from the
        archive, a bad ``size`` or ``unit``, a member too large)."""
        if isinstance(surface, bool) or not isinstance(surface, numbers.Integral):
            raise TypeError(f"surface must be an int, not {type(surface).__name__}")
        if surface < 0:
            raise ValueError(f"surface = {surface} is out of range: must be >= 0")
        if max_points is not None:
            if isinstance(max_points, bool) or not isinstance(max_points, numbers.Integral):
                raise TypeError(f"max_points must be an int, not {type(max_points).__name__}")
            if max_points < 1:
                raise ValueError(f"max_points = {max_points} is out of range: must be >= 1")
        tip = None if tip_radius is None else _interval("tip_radius", tip_radius)
        res = None if resolution is None else _interval("resolution", resolution)
        options = dict(surface=int(surface), tip_radius=tip, resolution=res,
                       max_points=None if max_points is None else int(max_points))
        if isinstance(source, (bytes, bytearray, memoryview)):
            if name is not None and not isinstance(name, str):
                raise TypeError(f"name must be a str, not {type(name).__name__}")
            return Container(_core.ContainerCore.read(data=bytes(source), name=name, **options))
        if not isinstance(source, (str, os.PathLike)):
            raise TypeError(f"source must be a path or bytes, not {type(source).__name__}")
        if name is not None:
            raise ValueError("name: only with bytes (a file's name is its path)")
        return Container(_core.ContainerCore.read(path=os.fspath(source), **options))

    @property
    def name(self) -> str:
        """The container's name in messages (its path, or the ``name``
        given with its bytes)."""
        return self._core.name()

    @property
    def surfaces(self) -> List[Optional[str]]:
        """The names of the container's surfaces (None where unnamed)."""
        return self._core.surfaces()

    @property
    def measurements(self) -> List[Dict[str, Any]]:
        """Each measurement's record, as ``kefric surface CONTAINER
        --json`` lists them: ``file`` (its data file in the archive),
        ``name``, ``unit`` (of ``meta.yml``), ``instrument`` (as its data
        file names it, or None), ``nx``, ``ny`` (1 for a profile), ``dx``
        (the mean spacing, m), ``size`` (``[x, y]``, m; y None for a
        profile), ``tip_radius``, ``resolution``, ``cutoff`` (the
        reliability cut-off, m, or None), ``reliable`` (``q_min``,
        ``q_max`` in rad/m, ``lambda_min``, ``lambda_max`` in m; None
        without a reliable spectrum) and ``note`` (why there is none)."""
        return self._core.measurements()

    def psd(self, nb_points_per_decade: int = 10) -> Dict[str, Any]:
        """The power spectra (1-D along x; q in rad/m, C in m^3), as
        ``kefric surface CONTAINER --psd`` gives them: ``"combined"``, the
        measurements' reliable spectra resampled onto a log grid of
        ``nb_points_per_decade`` bins a decade aligned to whole decades and
        averaged where they overlap (SurfaceTopography's container
        ``power_spectrum(unit='m', nb_points_per_decade=...)``), a pair of
        NumPy arrays ``(q, c)`` or None if no measurement has a reliable
        spectrum; ``"contributors"``, the measurements (indices) of each
        bin; ``"measurements"``, each measurement's own reliable spectrum
        ``(q, c)`` (from q = 0, below its cut-off) or None, in
        :attr:`measurements`' order."""
        if isinstance(nb_points_per_decade, bool) or not isinstance(nb_points_per_decade, numbers.Integral):
            raise TypeError(f"nb_points_per_decade must be an int, not {type(nb_points_per_decade).__name__}")
        if not 1 <= nb_points_per_decade <= 1000:
            raise ValueError(f"nb_points_per_decade = {nb_points_per_decade} is out of range: 1 to 1000")
        combined, own = self._core.psd(int(nb_points_per_decade))
        return {
            "combined": None if combined is None else (combined[0], combined[1]),
            "contributors": None if combined is None else combined[2],
            "measurements": own,
        }

    def friction(self, *, force: Any = None, area: Optional[float] = None, pressure: Any = None,
                 e1: Optional[float] = None, nu1: Optional[float] = None, e2: Optional[float] = None,
                 nu2: Optional[float] = None, hardness: Optional[float] = None,
                 delta_gamma: Optional[float] = None, epsilon: Optional[float] = None,
                 distribution: Optional[str] = None, fit: str = "consistent", model: str = "ke",
                 lambda_s: Union[float, str, None] = None, lambda_c: Optional[float] = None) -> Dict[str, Any]:
        """mu from the whole band, as ``kefric surface CONTAINER --json``
        gives it (the record, ``files`` apart): the spectral moments m0,
        m2, m4 of the combined spectrum between 2 pi/lambda_c and 2
        pi/lambda_s (by default the whole band the measurements resolve
        together: lambda_s the smallest reliable scale of any,
        ``"auto"`` or None; lambda_c the largest), sigma, alpha, eta, R
        and beta from them, the height distribution (``distribution``,
        None: the library's default) of the measurement with the most
        points among those resolving lambda_c, then the model's inputs
        with the seven materials keywords (all needed, as for
        :meth:`Surface.friction`) and mu at each load (``force``, a
        number or a 1-D array, on ``area``; or ``pressure``; none: the
        model's inputs alone).

        A dict: ``name``, ``measurements`` (as :attr:`measurements`),
        ``combined`` (``band``, ``moments``, ``roughness``,
        ``heights_from``, ``rests_on``: the measurements overlapping the
        band), ``model`` (as :attr:`Model.params`), ``friction`` (one
        record a load, as :meth:`Surface.friction`'s) and ``warnings``
        (``kind``, ``message``), each warned as a :class:`ModelWarning`.

        ValueError naming the keyword for a value out of range (a
        material, a load, a band end), for a band holding fewer than two
        points of the spectrum, and where the model has no mu."""
        materials = dict(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, delta_gamma=delta_gamma,
                         epsilon=epsilon)
        mats = _model_keywords(materials, distribution, fit, model)
        if isinstance(lambda_s, str):
            if lambda_s != "auto":
                raise ValueError(f"lambda_s = {lambda_s!r}: must be a length in metres, \"auto\" or None")
            lambda_s = None
        force_l, area_v, pressure_l = _container_loads(force, area, pressure)
        result = self._core.friction(list(mats), distribution, fit, model, force_l, area_v, pressure_l,
                                     _length("lambda_s", lambda_s), _length("lambda_c", lambda_c))
        _warn(result["warnings"])
        return result["record"]

    def scan(self, *, lambda_c: Optional[float] = None, per_decade: int = 5, force: Optional[float] = None,
             area: Optional[float] = None, pressure: Optional[float] = None, e1: Optional[float] = None,
             nu1: Optional[float] = None, e2: Optional[float] = None, nu2: Optional[float] = None,
             hardness: Optional[float] = None, delta_gamma: Optional[float] = None,
             epsilon: Optional[float] = None, distribution: Optional[str] = None, fit: str = "consistent",
             model: str = "ke") -> Dict[str, Any]:
        """mu against the short cut-off lambda_s, as ``kefric surface
        CONTAINER --scan --json``: lambda_s log-spaced ``per_decade`` a
        decade (1 to 1000) from the smallest reliable scale of any
        measurement towards ``lambda_c`` (default: the largest scale any
        resolves), each row as :meth:`friction` over [lambda_s,
        lambda_c] with the materials keywords (all needed) and at most one
        load.

        A dict: ``rows``, the records (``lambda_s``, ``lambda_c``,
        ``measurements``: the names of those whose reliable range overlaps
        the row's band; ``spread``: each load's ``mu_min``, ``mu_max``
        over those measurements taken alone, or None; ``moments``,
        ``roughness``, ``model``, ``warnings``, ``friction``; or
        ``error``); and NumPy columns of them, one element a row:
        ``lambda_s``, ``lambda_c``, ``sigma``, ``alpha``, ``eta``,
        ``radius``, ``beta``, ``psi``, ``theta`` and, with a load, ``mu``,
        ``mu_min``, ``mu_max`` (NaN where a row has none); ``errors``: the
        ``(index, lambda_s, message)`` of the rows with no result. The
        rows' warnings are warned once a kind as :class:`ModelWarning`."""
        materials = dict(e1=e1, nu1=nu1, e2=e2, nu2=nu2, hardness=hardness, delta_gamma=delta_gamma,
                         epsilon=epsilon)
        mats = _model_keywords(materials, distribution, fit, model)
        if isinstance(per_decade, bool) or not isinstance(per_decade, numbers.Integral):
            raise TypeError(f"per_decade must be an int, not {type(per_decade).__name__}")
        if not _core.in_range("per_decade", per_decade):
            raise ValueError(f"per_decade = {per_decade} is out of range: must be {_core.RANGES['per_decade']}")
        for k, v in (("force", force), ("pressure", pressure)):
            if v is not None and not _is_scalar(v):
                raise ValueError(f"{k}: one load for a scan (a number), not {type(v).__name__}")
        force_l, area_v, pressure_l = _container_loads(force, area, pressure, one=True)
        result = self._core.scan(list(mats), distribution, fit, model, force_l, area_v, pressure_l,
                                 _length("lambda_c", lambda_c), int(per_decade))
        _warn(result["warnings"])
        rows = result["rows"]
        n = len(rows)
        out: Dict[str, Any] = {"rows": rows}
        for key in ("lambda_s", "lambda_c"):
            out[key] = np.array([r[key] for r in rows], dtype=np.float64)
        columns = list(_SCAN_ROUGHNESS) + list(_SCAN_MODEL)
        if force_l is not None or pressure_l is not None:
            columns += ["mu", "mu_min", "mu_max"]
        for c in columns:
            out[c] = np.full(n, np.nan)
        errors = []
        for i, r in enumerate(rows):
            if "error" in r:
                errors.append((i, r["lambda_s"], r["error"]))
                continue
            for c in _SCAN_ROUGHNESS:
                out[c][i] = r["roughness"][c]
            for c in _SCAN_MODEL:
                out[c][i] = r["model"][c]
            if "mu" in out:
                if r.get("friction"):
                    out["mu"][i] = r["friction"]["mu"]
                if r.get("spread"):
                    out["mu_min"][i] = r["spread"][0]["mu_min"]
                    out["mu_max"][i] = r["spread"][0]["mu_max"]
        out["errors"] = errors
        return out

    def __repr__(self) -> str:
        ms = self.measurements
        return f"Container({self.name!r}, {len(ms)} measurements: " + ", ".join(m["name"] for m in ms) + ")"
