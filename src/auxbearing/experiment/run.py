"""The whole experiment pipeline in one call: measured drop in; Datasets, a summary and figures out.

Steps (see :mod:`auxbearing.experiment.orbit` and :mod:`auxbearing.experiment.fit`):
read and check the file, pre-process, fit the uncertain parameters, estimate force and stress
from the measured orbit, simulate the same case (as configured, and as fitted), and lay the
peaks side by side. The simulations are also put through the measurement pipeline (sampled,
filtered, force from the orbit) so that "measured" and "simulated" are compared like with like.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path
from typing import NamedTuple

import numpy as np
import xarray as xr

from auxbearing.analysis.statics import stress_warning
from auxbearing.bearings.ballset import ballset_params
from auxbearing.bearings.catalogue import load_bearing
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.bearings.ratings import ISO76_BALL_STRESS
from auxbearing.common.errors import InputError
from auxbearing.common.params import convert
from auxbearing.experiment.fit import FitOptions, fit_parameters, simulate_like_measurement
from auxbearing.experiment.io import read_measured
from auxbearing.experiment.orbit import (
    Preprocessing,
    contact_from_orbit,
    elastic_limit_excursion,
    orbit_features,
    preprocess,
)
from auxbearing.planar.params import DropCase, Rotor
from auxbearing.planar.rig import planar_machine

#: Peak quantities compared in the table: (summary key, label, format).
PEAK_ROWS = (
    ("peak_contact_force_N", "Peak contact force [N]", "{:.0f}"),
    ("peak_ball_stress_MPa", "Peak ball stress [MPa]", "{:.0f}"),
    ("peak_ball_load_N", "Peak ball load [N]", "{:.0f}"),
    ("impacts", "Impacts", "{:d}"),
    ("first_impact_ms", "First impact [ms]", "{:.2f}"),
    ("whirl", "Whirl", "{}"),
    ("whirl_frequency_Hz", "Whirl frequency [Hz]", "{:.0f}"),
)


class ExperimentDrawing(NamedTuple):
    """What the experiment's figures are drawn from (:func:`auxbearing.plots.experiment.experiment_figures`)."""

    label: str  #: the figures' title stem: bearing, and whether the measurement is synthetic
    orbit: object  #: the measured orbit (:func:`auxbearing.experiment.orbit.orbit_from_probes`)
    simulated: dict  #: name -> simulated drop dataset
    clearance: float  #: the clearance the comparison used [m]
    clearances: dict  #: name of each simulation -> its clearance [m]
    measured: xr.Dataset  #: force and stress from the measured orbit
    fitted_orbit: tuple | None  #: (time, simulated xy, measured xy) of the fitted stretch, None without a fit


class ExperimentResult(NamedTuple):
    """What :func:`run_experiment` returns (unpacks as ``datasets, summary, drawing``); it draws nothing."""

    datasets: dict[str, xr.Dataset]
    summary: dict
    drawing: ExperimentDrawing


def _fmt(fmt: str, value: object) -> str:
    if value is None:
        return "-"
    try:
        return fmt.format(value)
    except (ValueError, TypeError):
        return str(value)


def peak_table(columns: dict[str, dict]) -> dict:
    """Rows of peak values per column, and the difference of each simulation from the measurement [%].

    The first column is the reference (the measurement); a column "sim X via orbit" is the
    simulation put through the measurement pipeline (sampled, filtered, force from the orbit).
    """
    names = list(columns)
    rows = []
    for key, label, fmt in PEAK_ROWS:
        row = [label, *(_fmt(fmt, columns[n].get(key)) for n in names)]
        ref = columns[names[0]].get(key)
        for n in names[1:]:
            other = columns[n].get(key)
            numeric = isinstance(ref, (int, float)) and isinstance(other, (int, float)) and ref
            row.append(f"{100.0 * (other / ref - 1.0):+.1f} %" if numeric else "-")
        rows.append(row)
    return {"columns": ["", *names, *(f"Δ {n.removeprefix('sim ')}" for n in names[1:])], "rows": rows}


def _truth(attrs: dict) -> dict:
    """True values written in a SYNTHETIC file's header (``true_*`` keys), as floats where they are numbers."""
    out = {}
    for key, value in attrs.items():
        if key.startswith("true_"):
            try:
                out[key[5:]] = float(value)
            except (TypeError, ValueError):
                out[key[5:]] = value
    return out


#: Standard gravity [m/s^2] (the free fall a record must at least span).
GRAVITY = 9.80665


def _long_enough(orbit: xr.Dataset, clearance: float, name) -> None:
    """Refuse a record that ends before the journal can have fallen its clearance: it shows no touchdown.

    A free fall across the radial clearance s takes sqrt(2 s / g); a record shorter than that after the drop has
    no impact in it, whatever the fit or the figures would make of it.
    """
    after = float(orbit.time.values[-1])
    fall = math.sqrt(2.0 * clearance / GRAVITY)
    if after < fall:
        raise InputError(f"{name or 'the measured file'}: the record ends {after * 1e3:.3g} ms after the drop, "
                         f"before a free fall across the {clearance * 1e3:g} mm clearance ({fall * 1e3:.3g} ms) "
                         "ends: it holds no touchdown (record longer after the drop)")


def run_experiment(
    measured: str | Path | xr.Dataset,
    bearing: str | BearingGeometry = "QJ202",
    rotor: Rotor | None = None,
    case: DropCase | None = None,
    preprocessing: Preprocessing | None = None,
    fit: bool = True,
    fit_options: FitOptions | None = None,
    clearance: float | None = None,
    progress: Callable[[float, str], None] | None = None,
) -> ExperimentResult:
    """Run the experiment pipeline on a measured drop (source paper Sec. III).

    Parameters
    ----------
    measured : path or xarray.Dataset
        CSV or NetCDF file (:mod:`auxbearing.experiment.io`) or what its readers return.
    bearing : str or BearingGeometry
        The auxiliary bearing of the test (catalogue name, TOML file or geometry).
    rotor, case : optional
        The simulated case (defaults: Table II). A measured speed channel replaces ``case.speed``
        by the speed at the drop; the start position comes from the levitated stretch.
    preprocessing : Preprocessing, optional
    fit : bool
        Fit friction, clearance and unbalance phase (and the drop moment) to the opening orbit.
    fit_options : FitOptions, optional
    clearance : float or str, optional
        Clearance s for the force estimate: a string with a unit ("180 um") or metres; default: the
        fitted one, else ``case.clearance``.
    progress : callable, optional
        Called with (fraction done, label of the next step).

    Returns
    -------
    ExperimentResult
        ``datasets``: ``measured`` (orbit, force, ball loads and stress over time since the
        drop) and ``simulated_<label>`` (:func:`auxbearing.planar.rig.run_drop` output);
        ``summary``: JSON-ready (``warnings``: sentences on results that mean little, such as an orbit that
        never reaches the clearance used or goes further beyond it than the contact can deflect within ISO 76's
        4200 MPa, and peak ball stresses above that limit); ``drawing``: what the figures are drawn from
        (orbits, force and stress, the fitted stretch: :func:`auxbearing.plots.experiment.experiment_figures`).
    """
    def step(fraction: float, label: str) -> None:
        if progress is not None:
            progress(fraction, label)

    if clearance is not None:
        typed_clearance = clearance
        clearance = convert("clearance", clearance, "length")
        if not clearance > 0.0:
            raise InputError.for_field("clearance", typed_clearance, "must be > 0")
    step(0.0, "reading")
    data = measured if isinstance(measured, xr.Dataset) else read_measured(measured)
    bearing = load_bearing(bearing)
    rotor = rotor or Rotor()
    case = case or DropCase()
    orbit, info = preprocess(data, preprocessing)
    _long_enough(orbit, clearance if clearance is not None else case.clearance, data.attrs.get("source_file"))
    if "speed" in orbit:
        near = np.abs(orbit.time.values) <= 1e-3
        case = replace(case, speed=float(np.median(orbit.speed.values[near])))
    case = replace(case, start_x=info["start_x_m"], start_y=info["start_y_m"])
    spin = case.speed
    fitted = None
    if fit:
        step(0.05, "fitting friction, clearance and unbalance phase")
        fitted = fit_parameters(orbit, info, bearing, rotor, case, fit_options)
        shift = fitted["drop_time_s"] - info["drop_time_s"]
        orbit = orbit.assign_coords(time=orbit.time - shift)
        orbit.time.attrs.update(units="s", long_name="Time since the (fitted) drop")
        info["drop_time_s"] = fitted["drop_time_s"]
    if clearance is not None:
        s_used, s_source = clearance, "given"
    elif fitted is not None:
        s_used, s_source = fitted["case"].clearance, "fitted"
    else:
        s_used, s_source = case.clearance, "configured"
    step(0.45, "force and stress from the measured orbit")
    plane = planar_machine(bearing, rotor, replace(case, clearance=s_used)).planes[0]
    ball_params = ballset_params(bearing, case.ball_constant)
    measured_ds, measured_summary = orbit_features(orbit, s_used, plane.line_stiffness, ball_params,
                                                   case.line_damping, info["noise_filtered_m"], spin)
    dt = float(np.median(np.diff(orbit.time.values)))
    after = orbit.time.values >= 0.0
    sensitivity = {}
    for ds_um in (-1.0, 1.0):
        c = contact_from_orbit(orbit.x.values[after], orbit.y.values[after], s_used + ds_um * 1e-6,
                               plane.line_stiffness, ball_params, case.line_damping, dt)
        sensitivity[f"{ds_um:+.0f}"] = (float(c["contact_force"].max()), float(c["max_ball_stress"].max() / 1e6))
    measured_summary["clearance_used_um"] = s_used * 1e6
    measured_summary["clearance_source"] = s_source
    warnings = _clearance_warnings(measured_ds, s_used, s_source, plane.line_stiffness, ball_params,
                                   measured_summary["impacts"])
    if fitted is not None:  # a converged fit can still be no result: say why before its figures are read
        warnings += [f"fit: {note}" for note in fitted["quality"]]
    measured_summary["peak_stress_if_clearance_minus_1um_MPa"] = sensitivity["-1"][1]
    measured_summary["peak_stress_if_clearance_plus_1um_MPa"] = sensitivity["+1"][1]
    measured_summary["peak_force_if_clearance_minus_1um_N"] = sensitivity["-1"][0]
    measured_summary["peak_force_if_clearance_plus_1um_N"] = sensitivity["+1"][0]
    cases = {"configured": case}
    if fitted is not None:
        cases["fitted"] = fitted["case"]
    datasets = {"measured": measured_ds}
    sims, columns = {}, {"measured": measured_summary}
    for k, (label, sim_case) in enumerate(cases.items()):
        step(0.55 + 0.2 * k, f"simulating the {label} case")
        sim_ds, sim_summary, seen = simulate_like_measurement(bearing, rotor, sim_case, orbit, info["cutoff_Hz"])
        sim_plane = planar_machine(bearing, rotor, sim_case).planes[0]
        _, seen_summary = orbit_features(seen, sim_case.clearance, sim_plane.line_stiffness, ball_params,
                                         sim_case.line_damping, info["noise_filtered_m"], spin)
        sims[f"simulated, {label}"] = sim_ds
        datasets[f"simulated_{label}"] = sim_ds
        columns[f"sim {label}"] = sim_summary
        if label == "fitted" or fitted is None:
            columns[f"sim {label} via orbit"] = seen_summary
    for name, column in columns.items():
        if not name.endswith("via orbit") and column.get("peak_ball_stress_MPa") is not None:
            sentence = stress_warning(column["peak_ball_stress_MPa"] * 1e6)
            if sentence:
                warnings.append(f"{'measured orbit' if name == 'measured' else name}: {sentence}")
    synthetic = str(data.attrs.get("synthetic", "")).lower() in ("true", "1", "yes")
    label = f"{bearing.name}: {'SYNTHETIC ' if synthetic else ''}measured drop"
    summary = {
        "bearing": bearing.name,
        "source_file": data.attrs.get("source_file"),
        "synthetic": synthetic,
        "preprocessing": {k: v for k, v in info.items() if k != "circle"} | {"circle": info.get("circle")},
        "speed_at_drop_rpm": spin * 30.0 / math.pi,
        "measured": measured_summary,
        "simulated": {k: v for k, v in columns.items() if k != "measured"},
        "peak_table": peak_table(columns),
        "warnings": warnings,
    }
    fitted_orbit = None
    if fitted is not None:
        fitted_orbit = fitted.pop("fitted_orbit")
        summary["fit"] = {k: v for k, v in fitted.items() if k != "case"}
    truth = _truth(data.attrs)
    if truth:
        summary["truth"] = truth
        if fitted is not None:
            summary["recovery"] = recovery_table(fitted, truth)
    measured_ds.attrs.update(
        title=label, synthetic=int(synthetic), bearing=bearing.describe(), source_file=str(data.attrs.get(
            "source_file", "")), clearance_m=s_used, clearance_source=s_source,
        offset_x_m=info["offset_x_m"], offset_y_m=info["offset_y_m"], drop_time_s=info["drop_time_s"],
        method="force and stress from the orbit: quasi-static series split of line contact (Eq. 19) and ball set "
               "(Eq. 10-16, 22); see auxbearing.experiment.orbit")
    step(1.0, "done")
    drawing = ExperimentDrawing(label, orbit, sims, s_used, {f"simulated, {k}": c.clearance for k, c in cases.items()},
                                measured_ds, fitted_orbit)
    return ExperimentResult(datasets, summary, drawing)


def _clearance_warnings(measured: xr.Dataset, s_used: float, s_source: str, line_stiffness: float,
                        ball_params: np.ndarray, impacts: int) -> list[str]:
    """Sentences on a clearance the measured orbit contradicts: never reached, or overshot by far."""
    after = measured.time.values >= 0.0
    radius = np.hypot(measured.x.values[after], measured.y.values[after])
    excursion = measured.excursion.values[after]
    reach_um, s_um = float(radius.max()) * 1e6, s_used * 1e6
    advice = {"given": "check the clearance given (--clearance) or let the fit find it",
              "configured": "give the clearance (--clearance) or let the fit find it",
              "fitted": "check the sensor offset (--offset) and the fit"}[s_source]
    if impacts == 0:
        return [f"the measured orbit never reaches the clearance circle used for the force ({s_um:.4g} um, "
                f"{s_source}): its largest radius after the drop is {reach_um:.4g} um, so the estimate sees no "
                f"impact; {advice}"]
    k = int(np.argmax(excursion))
    # "Far beyond" is deeper than the contact (line contact and ball set in series, the model of the force
    # estimate) deflects before its most loaded ball reaches ISO 76's 4200 MPa, the stress of the static rating.
    # Past it every such drop would dent the raceways; with the right clearance the shipped QJ202 drop peaks
    # at 11 of the 79 um, whereas a clearance set too small counts the free fall itself as deflection. A
    # multiple of that depth would miss such errors: in a small bearing it is already near the clearance.
    limit = elastic_limit_excursion(math.atan2(float(measured.y.values[after][k]), float(measured.x.values[after][k])),
                                    line_stiffness, ball_params)
    if not excursion[k] > limit:
        return []
    return [f"the measured orbit goes {excursion[k] * 1e6:.4g} um beyond the clearance circle used for the force "
            f"({s_um:.4g} um, {s_source}; largest radius {reach_um:.4g} um), further than the contact deflects "
            f"before its balls reach ISO 76's {ISO76_BALL_STRESS / 1e6:.0f} MPa ({limit * 1e6:.3g} um): the "
            f"clearance is likely too small, and the force and stress from the orbit are not to be trusted; {advice}"]


def recovery_table(fitted: dict, truth: dict) -> list[dict]:
    """Recovered against true values of a SYNTHETIC record (fitted parameters with a true value)."""
    rows = []
    pairs = (("sliding_friction", "sliding_friction", 1.0, "-"), ("clearance", "clearance_m", 1e6, "um"),
             ("unbalance_phase", "unbalance_phase_deg", None, "deg"))
    for name, key, factor, unit in pairs:
        if key not in truth:
            continue
        p = fitted["parameters"][name]
        true = truth[key] if factor is None else truth[key] * factor
        value = p["value_shown"]
        if factor is None:  # a phase: compare on the circle
            diff = (value - true + 180.0) % 360.0 - 180.0
        else:
            diff = value - true
        rows.append({"parameter": name, "unit": unit, "true": true, "recovered": value, "std": p["std_shown"],
                     "error": diff, "start": p["start"] * (factor or 180.0 / math.pi)})
    return rows
