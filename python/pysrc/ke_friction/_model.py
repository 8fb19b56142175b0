"""The model by direct integration, :class:`Model` and its
:class:`Contact`; the library's default constants; and
:func:`params_from_physical`."""

from __future__ import annotations

import dataclasses
import types
from typing import Any, Dict, Optional, Tuple, Union

import numpy as np

from . import _core
from ._args import ArrayLike, OutOfDomain, _arrays, _check_real, _is_scalar, _mode, _threads
from ._distribution import HeightDistribution, _resolve
from ._errors import _located, _warn

#: The model constants a :class:`Model` takes unless told otherwise, from
#: the library (read-only): ``beta``, ``nu``, ``eps_star``, ``fit``,
#: ``model``, ``distribution``, ``skewness`` and ``kurtosis``, by the names
#: of its records.
DEFAULTS: "types.MappingProxyType[str, Any]" = types.MappingProxyType(_core.DEFAULTS)


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

    psi: plasticity index, {ranges[psi]}; theta: adhesion parameter,
    {ranges[theta_non_negative]} and {ranges[theta_at_most]}; beta: roughness
    parameter eta*R*sigma, {ranges[beta]}; nu: Poisson's ratio of the softer
    material, {ranges[nu]}; eps_star: intermolecular distance eps/sigma,
    {ranges[eps_star]}; fit: "consistent"
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
    fit = property(lambda self: self._params["fit"], doc=f"The fit: one of {', '.join(map(repr, _core.FITS))}.")
    model = property(lambda self: self._params["model"],
                     doc=f"The model: one of {', '.join(map(repr, _core.MODELS))} (MODEL.md).")
    distribution = property(lambda self: self._params["distribution"],
                            doc=f"The heights' distribution family: one of {', '.join(map(repr, _core.FAMILIES))}.")
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
        _warn(_core.contact_warnings(out.reshape(-1)), stacklevel=4)
        cols = [np.ascontiguousarray(out[:, k]).reshape(shape)[()] for k in range(7)]
        return Contact(*(float(c) for c in cols)) if scalar else Contact(*cols)

    def at_f_star(self, f_star: ArrayLike, *, out_of_domain: OutOfDomain = "raise",
                  threads: Optional[int] = 1) -> Contact:
        """The model at external force F* > 0 (solving F*(h*) = F*): a
        :class:`Contact` of floats for a number, of arrays for an array-like.
        F* <= 0, NaN, F* > 1 (a pressure above the hardness, where the model
        has no meaning) or beyond the model's reach raises ValueError (or
        gives NaN with ``out_of_domain="nan"``). Implausible results warn
        (:class:`ModelWarning`, one per kind: F* outside the paper's
        1e-5..0.1, h* < 0, mu > 1 where adhesion dominates). A solver that fails to converge
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
    Model.__doc__ = Model.__doc__.format(ranges=_core.RANGES, **DEFAULTS)


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
    return _core.params_from_physical([float(values[k]) for k in _core.MATERIALS], float(sigma), float(radius),
                                      float(density))
