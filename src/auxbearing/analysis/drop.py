"""Rotor drop onto the auxiliary bearing: run, summarise, detect whirl.

Source paper Sec. II.D (Eq. 17-26, Table II, Fig. 9-11) read as ../shared/paper/NOTES.md
("How to read the drop model", items 1-9, all applied; see :mod:`auxbearing.core.drop` for the
model and :mod:`auxbearing.analysis.drop_params` for every input with its unit, rule and
source). The support of the inner race is THE shared ball-set model
(:func:`auxbearing.core.ballset.radial_support`), so four-point and angular-contact bearings
differ only through their geometry (NOTES item 8).

Public API: :class:`Rotor`, :class:`DropCase`, :func:`read_config`, :func:`run_drop`,
:func:`detect_whirl`; the paper's QJ202 / 7202 comparison is
:func:`auxbearing.analysis.drop_paper.drop_compare`.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from typing import NamedTuple

import numpy as np
import xarray as xr

from auxbearing import __version__
from auxbearing.analysis.contact import ball_constant as contact_ball_constant
from auxbearing.analysis.drop_params import PARAMETERS, DropCase, Param, Rotor, convert, from_mapping, read_config
from auxbearing.analysis.static import safety_factor
from auxbearing.bearing import BearingGeometry, load_bearing
from auxbearing.core import drop as cd
from auxbearing.core.ballset import ballset_state, kernel_params
from auxbearing.core.hertz import line_contact_constant
from auxbearing.errors import ConvergenceError, InputError
from auxbearing.io import to_jsonable

__all__ = ["PARAMETERS", "DropCase", "DropModel", "Param", "Rotor", "build_model", "convert", "detect_whirl",
           "from_mapping", "read_config", "run_drop", "static_safety_factor"]


#: (1 - nu^2)/E of the journal: steel, E = 207 GPa, nu = 0.3 (not in the paper; Palmgren's steel).
ROTOR_STEEL_COMPLIANCE = (1.0 - 0.3**2) / 207e9


# ----------------------------------------------------------------------------- the model
class DropModel(NamedTuple):
    """Everything the compiled kernels need, and the derived values they were built from."""

    params: np.ndarray  #: model parameters, layout ``P_*`` of :mod:`auxbearing.core.drop`
    ballset: np.ndarray  #: :func:`auxbearing.core.ballset.kernel_params`
    y0: np.ndarray  #: initial state
    atol: np.ndarray  #: absolute tolerance per state [SI]
    rotor_radius: float  #: r [m]
    race_bore_radius: float  #: r + s [m]
    line_stiffness: float  #: K_l [N/m^(10/9)]
    ball_constant: float  #: K_b at the nominal contact angle [N/m^1.5] (Hertz or override)


def build_model(bearing: BearingGeometry, rotor: Rotor, case: DropCase) -> DropModel:
    """Check that rotor, clearance and bearing fit together and pack the kernel parameters.

    The journal radius r and the clearance s must add up to the race bore radius (NOTES item 6).

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> m = build_model(get_bearing("QJ202"), Rotor(), DropCase())
    >>> round(m.rotor_radius * 1e3, 3), f"{m.line_stiffness:.4g}"
    (7.3, '1.463e+09')
    >>> build_model(get_bearing("QJ202"), Rotor(radius=7.4e-3), DropCase())
    Traceback (most recent call last):
    ...
    auxbearing.errors.InputError: rotor.radius = '7.4 mm': rotor.radius + drop.clearance = 7.6 mm must equal ...
    """
    s = case.clearance
    if bearing.bore is not None:
        bore_radius = 0.5 * bearing.bore
        if s >= bore_radius:
            raise InputError.for_field("drop.clearance", f"{s * 1e3:g} mm",
                                       f"must be below the race bore radius {bore_radius * 1e3:g} mm")
        r = bore_radius - s if rotor.radius is None else rotor.radius
        if abs(r + s - bore_radius) > 1e-9:
            raise InputError.for_field(
                "rotor.radius", f"{r * 1e3:g} mm",
                f"rotor.radius + drop.clearance = {(r + s) * 1e3:g} mm must equal the race bore radius "
                f"{bore_radius * 1e3:g} mm (bore {bearing.bore * 1e3:g} mm); leave rotor.radius unset to derive it")
    elif rotor.radius is None:
        raise InputError.for_field("rotor.radius", None,
                                   f"bearing {bearing.name} has no bore: give the journal radius")
    else:
        r = rotor.radius
        bore_radius = r + s
    if case.line_stiffness is not None:
        k_l = case.line_stiffness
    elif bearing.width is not None:
        # journal steel assumed as Palmgren's (the paper names no rotor material); the ring's own
        # material enters through its compliance term
        k_l = float(line_contact_constant(bearing.width, bearing.ring_material.compliance
                                          + ROTOR_STEEL_COMPLIANCE))
    else:
        raise InputError.for_field("drop.line_stiffness", None,
                                   f"bearing {bearing.name} has no width for Palmgren's K_l: give line_stiffness")
    bp = kernel_params(bearing, case.ball_constant)
    k_b = case.ball_constant if case.ball_constant is not None else float(contact_ball_constant(bearing))
    p = np.zeros(cd.N_PARAMS)
    p[cd.P_MR], p[cd.P_JR], p[cd.P_E] = rotor.mass, rotor.polar_inertia, rotor.eccentricity
    p[cd.P_MB], p[cd.P_JB], p[cd.P_R], p[cd.P_S] = case.race_mass, case.race_inertia, r, s
    p[cd.P_KL], p[cd.P_CL], p[cd.P_CB] = k_l, case.line_damping, case.ball_damping
    p[cd.P_MU1], p[cd.P_MU2], p[cd.P_VEPS] = case.sliding_friction, case.rolling_friction, case.slip_velocity
    p[cd.P_G], p[cd.P_RI] = case.gravity, 0.5 * bearing.inner_raceway_diameter
    y0 = np.zeros(cd.N_STATE)
    y0[0], y0[1], y0[2], y0[8] = case.start_x, case.start_y, case.unbalance_phase, case.speed
    # velocity scale: impact speed of a fall through the clearance (or 1 mm/s without gravity)
    v = max(math.sqrt(2.0 * case.gravity * s), 1e-3)
    w = max(abs(case.speed), 1.0)
    scale = np.array([s, s, 1.0, s, s, 1.0, v, v, w, v, v, w])
    return DropModel(p, bp, y0, case.atol * scale, r, bore_radius, k_l, k_b)


_WARM = {"done": False}


def _warm_up(model: DropModel) -> float:
    """Compile (or load from the numba cache) the kernels once per process; seconds spent."""
    if _WARM["done"]:
        return 0.0
    start = time.perf_counter()
    grid = np.empty((2, cd.N_STATE))
    cd.integrate(model.y0.copy(), 0.0, 1e-5, model.params, model.ballset, 1e-6, model.atol, 1e-6, 1e-5, 1,
                 grid, cd.new_stats(1e-6))
    cd.grid_contact(grid, model.params, model.ballset)
    _WARM["done"] = True
    return time.perf_counter() - start


# ----------------------------------------------------------------------------- running
def run_drop(
    bearing: str | BearingGeometry = "QJ202",
    rotor: Rotor | None = None,
    case: DropCase | None = None,
    progress: Callable[[float], None] | None = None,
    chunks: int = 30,
) -> tuple[xr.Dataset, dict]:
    """Simulate the rotor drop (source paper Sec. II.D, corrected per NOTES.md).

    Parameters
    ----------
    bearing : str or BearingGeometry
        Catalogue name, TOML path or geometry; its ball set carries the race.
    rotor : Rotor, optional
        Default: Table II.
    case : DropCase, optional
        Default: Table II with the corrected units and the defaults of :data:`PARAMETERS`.
    progress : callable, optional
        Called with the completed fraction (0-1) after each of ``chunks`` pieces.
    chunks : int
        Pieces the integration is cut into for ``progress`` (the step control carries over).

    Returns
    -------
    dataset : xarray.Dataset
        Time series on the uniform output grid (units in attrs).
    summary : dict
        ``peak_contact_force_N`` and ``peak_ball_stress_MPa``: exact maxima (golden-section
        search on the dense output around each local maximum of the step sequence), with their
        times; ``s0`` = (4200 MPa / peak stress)^3 (ISO 76); ``first_impact_ms`` (bisection on the
        dense output); ``impacts``: contact onsets, counted at the accepted steps;
        ``largest_bounce_um``: widest gap between journal and race after the first impact;
        ``whirl``, ``whirl_frequency_Hz`` (:func:`detect_whirl` after the first impact);
        ``final_rotor_speed_rad_s``, ``final_race_speed_rad_s``; ``race_spin_up_ms``: first time
        the race surface reaches 95 % of the journal surface speed; ``contact_fraction``: share
        of the output instants after the first impact with penetration > 0; ``steps``,
        ``rejected_steps``, ``rhs_evaluations``; ``wall_time_s``: the integration alone
        (compile or cache load reported apart in ``compile_or_cache_load_s``).
    """
    bearing = load_bearing(bearing)
    rotor = rotor or Rotor()
    case = case or DropCase()
    model = build_model(bearing, rotor, case)
    compile_s = _warm_up(model)
    n_out = math.floor(case.duration / case.output_step + 1e-9) + 1
    grid = np.empty((n_out, cd.N_STATE))
    grid[0] = model.y0
    y = model.y0.copy()
    stats = cd.new_stats(min(1e-6, case.max_step))
    k_next = 1
    wall = 0.0
    edges = np.linspace(0.0, case.duration, max(1, chunks) + 1)
    for i in range(edges.size - 1):
        start = time.perf_counter()
        k_next = cd.integrate(y, edges[i], edges[i + 1], model.params, model.ballset, case.rtol, model.atol,
                              case.max_step, case.output_step, k_next, grid, stats)
        wall += time.perf_counter() - start
        if stats[cd.S_FAIL] >= 0.0:
            raise ConvergenceError(f"drop integration stalled at t = {stats[cd.S_FAIL] * 1e3:.6g} ms "
                                   "(step size underflow: non-finite forces or an unphysical input)",
                                   float("nan"), int(stats[cd.S_STEPS]))
        if progress is not None:
            progress((i + 1) / (edges.size - 1))
    if k_next < n_out:  # the last instant can fall a rounding error past the end
        grid[k_next:] = y
    contact = cd.grid_contact(grid, model.params, model.ballset)
    ds = _dataset(bearing, rotor, case, model, grid, contact)
    summary = _summary(bearing, case, model, ds, stats, wall, compile_s)
    ds.attrs["summary"] = json.dumps(to_jsonable(summary))
    return ds, summary


_SERIES = {  # name: (state column or contact field, unit, long name)
    "rotor_x": (0, "m", "Journal centre x"),
    "rotor_y": (1, "m", "Journal centre y"),
    "rotor_angle": (2, "rad", "Rotor spin angle"),
    "race_x": (3, "m", "Inner race centre x"),
    "race_y": (4, "m", "Inner race centre y"),
    "race_angle": (5, "rad", "Inner race spin angle"),
    "rotor_vx": (6, "m/s", "Journal centre velocity x"),
    "rotor_vy": (7, "m/s", "Journal centre velocity y"),
    "rotor_speed": (8, "rad/s", "Rotor spin speed"),
    "race_vx": (9, "m/s", "Inner race velocity x"),
    "race_vy": (10, "m/s", "Inner race velocity y"),
    "race_speed": (11, "rad/s", "Inner race spin speed"),
    "penetration": ("penetration", "m", "Rotor/race penetration delta (Eq. 17); negative: gap"),
    "normal_force": ("normal_force", "N", "Rotor/race collision (normal) force F_n1 (Eq. 19)"),
    "friction_force": ("friction_force", "N", "Friction on the rotor along the CCW tangent (Eq. 21 corrected)"),
    "slip_velocity": ("slip_velocity", "m/s", "Slip of the rotor surface over the race surface"),
    "ball_force_x": ("ball_force_x", "N", "Ball-set force on the race x (Eq. 22)"),
    "ball_force_y": ("ball_force_y", "N", "Ball-set force on the race y (Eq. 22)"),
    "max_ball_load": ("max_ball_load", "N", "Largest ball contact-pair load"),
    "max_ball_stress": ("max_ball_stress", "Pa", "Hertz max stress of the most loaded ball contact (NOTES item 9)"),
}


def _dataset(bearing, rotor, case, model, grid, contact) -> xr.Dataset:
    t = np.arange(grid.shape[0]) * case.output_step
    data = {}
    for name, (col, unit, long_name) in _SERIES.items():
        values = grid[:, col] if isinstance(col, int) else contact[:, cd.CONTACT_FIELDS.index(col)]
        data[name] = ("time", values, {"units": unit, "long_name": long_name})
    whirl_angle = np.unwrap(np.arctan2(grid[:, 1], grid[:, 0]))
    data["whirl_angle"] = ("time", whirl_angle, {"units": "rad", "long_name": "Orbit angle of the journal centre"})
    disp = np.zeros((grid.shape[0], 5))
    disp[:, 1:3] = grid[:, 3:5]
    loads = ballset_state(disp, model.ballset).load
    data["ball_load"] = (("time", "ball", "pair"), loads,
                         {"units": "N", "long_name": "Contact-pair load of each ball (shared ball-set model)"})
    ds = xr.Dataset(data, coords={
        "time": ("time", t, {"units": "s", "long_name": "Time since the drop"}),
        "ball": ("ball", np.arange(loads.shape[1])),
        "pair": ("pair", np.arange(loads.shape[2])),
    })
    ds.attrs.update(
        title=f"Rotor drop on {bearing.name} ({bearing.label})",
        source="source paper Sec. II.D, Eq. 17-26, Table II, corrected per NOTES.md",
        bearing=bearing.describe(), rotor=rotor.describe(), drop=case.describe(),
        rotor_radius_m=model.rotor_radius, race_bore_radius_m=model.race_bore_radius,
        line_stiffness_N_per_m10_9=model.line_stiffness, ball_constant_N_per_m1_5=model.ball_constant,
        auxbearing_version=__version__,
    )
    return ds


#: ISO 76:2006 static load rating of ball bearings: the load giving 4200 MPa at the most
#: loaded contact. Since sigma_max ~ Q^(1/3) (Eq. 8), s0 = C0/P0 = (4200 MPa / sigma_max)^3.


def static_safety_factor(max_stress: float) -> float | None:
    """s0 of :func:`auxbearing.analysis.static.safety_factor` for JSON: None without contact.

    Examples
    --------
    >>> round(static_safety_factor(2100e6), 3)
    8.0
    """
    return float(safety_factor(max_stress)) if max_stress > 0.0 else None


def detect_whirl(t: np.ndarray, x: np.ndarray, y: np.ndarray, clearance: float, spin: float = 1.0,
                 start: float = 0.0, min_amplitude: float = 0.05) -> dict:
    """Whirl direction and frequency from the complex spectrum of the orbit z = x + i y.

    Power at positive frequencies is counter-clockwise motion of the journal centre, at negative
    frequencies clockwise; forward whirl turns with the spin. The mean position (the rotor
    sitting in the bottom of the clearance) is removed and a Hann window applied. The whirl is
    ``forward`` or ``backward`` when at least 2/3 of the orbit's spectral power turns one way and
    the rms orbit exceeds ``min_amplitude`` x clearance; otherwise ``none`` (rest, bouncing, or
    rocking in the bottom, whose spectrum is symmetric).

    Parameters
    ----------
    t, x, y : arrays
        Uniform time [s] and journal centre [m].
    clearance : float
        s [m].
    spin : float
        Spin speed (its sign defines forward).
    start : float
        Analyse t >= start [s] (e.g. the first impact).
    min_amplitude : float
        Smallest rms orbit, as a fraction of the clearance, that counts as whirl.

    Examples
    --------
    >>> t = np.arange(0, 0.1, 1e-4)
    >>> w = detect_whirl(t, 2e-4 * np.cos(-2 * np.pi * 50 * t), 2e-4 * np.sin(-2 * np.pi * 50 * t), 2e-4)
    >>> w["whirl"], w["whirl_frequency_Hz"]
    ('backward', 50.0)
    """
    keep = t >= start
    z = x[keep] + 1j * y[keep]
    if spin < 0:  # mirror the orbit so that positive frequencies always mean "with the spin"
        z = np.conj(z)
    out = {"whirl": "none", "whirl_frequency_Hz": None, "whirl_rms_um": 0.0, "forward_power_fraction": None}
    if z.size < 16:
        return out
    z = z - z.mean()
    rms = float(np.sqrt(np.mean(np.abs(z) ** 2)))
    spectrum = np.fft.fft(z * np.hanning(z.size))
    freq = np.fft.fftfreq(z.size, t[1] - t[0])
    power = np.abs(spectrum) ** 2
    fwd, bwd = power[freq > 0].sum(), power[freq < 0].sum()
    frac = float(fwd / (fwd + bwd)) if fwd + bwd > 0 else 0.5
    out.update(whirl_rms_um=rms * 1e6, forward_power_fraction=frac)
    if rms < min_amplitude * clearance or 1.0 / 3.0 < frac < 2.0 / 3.0:
        return out
    side = freq > 0 if frac >= 2.0 / 3.0 else freq < 0
    peak = np.argmax(np.where(side, power, -1.0))
    out.update(whirl="forward" if frac >= 2.0 / 3.0 else "backward", whirl_frequency_Hz=float(abs(freq[peak])))
    return out


def _summary(bearing, case, model, ds, stats, wall, compile_s) -> dict:
    st = dict(zip(cd.STAT_FIELDS, stats.tolist(), strict=True))
    t = ds.time.values
    pen = ds.penetration.values
    first = st["t_first_contact"] if st["t_first_contact"] >= 0.0 else None
    after = t >= (first if first is not None else t[-1] + 1.0)
    rotor_surface = ds.rotor_speed.values * model.rotor_radius
    race_surface = ds.race_speed.values * model.race_bore_radius
    spun = np.nonzero((np.abs(rotor_surface) > 0) & (race_surface * np.sign(case.speed)
                                                       >= 0.95 * np.abs(rotor_surface)))[0]
    whirl = detect_whirl(t, ds.rotor_x.values, ds.rotor_y.values, case.clearance, case.speed,
                         first if first is not None else t[-1] + 1.0)
    peak_stress = st["peak_stress"]
    return {
        "bearing": bearing.name,
        "type": bearing.type,
        "peak_contact_force_N": st["peak_force"],
        "peak_ball_stress_MPa": peak_stress / 1e6,
        "s0": static_safety_factor(peak_stress),
        "first_impact_ms": None if first is None else first * 1e3,
        "impacts": int(st["onsets"]),
        "largest_bounce_um": float(max(0.0, -pen[after].min())) * 1e6 if after.any() else 0.0,
        "whirl": whirl["whirl"],
        "whirl_frequency_Hz": whirl["whirl_frequency_Hz"],
        "final_rotor_speed_rad_s": float(ds.rotor_speed.values[-1]),
        "final_race_speed_rad_s": float(ds.race_speed.values[-1]),
        "race_spin_up_ms": float(t[spun[0]] * 1e3) if spun.size else None,
        "contact_fraction": float(np.mean(pen[after] > 0.0)) if after.any() else 0.0,
        "steps": int(st["steps"]),
        "wall_time_s": wall,
        "peak_force_time_ms": st["t_peak_force"] * 1e3,
        "peak_stress_time_ms": st["t_peak_stress"] * 1e3,
        "peak_ball_load_N": float(ds.max_ball_load.values.max()),
        "whirl_rms_um": whirl["whirl_rms_um"],
        "forward_power_fraction": whirl["forward_power_fraction"],
        "rejected_steps": int(st["rejected"]),
        "rhs_evaluations": int(st["rhs_evals"]),
        "compile_or_cache_load_s": compile_s,
        "rotor_radius_mm": model.rotor_radius * 1e3,
        "clearance_mm": case.clearance * 1e3,
        "line_stiffness_N_per_m10_9": model.line_stiffness,
        "ball_constant_N_per_m1_5": model.ball_constant,
        "ball_constant_source": "override" if case.ball_constant is not None else "Hertz (Eq. 15)",
        "sliding_friction": case.sliding_friction,
        "rtol": case.rtol,
    }
