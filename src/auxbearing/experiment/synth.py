"""SYNTHETIC measured drops: the drop simulation seen through imperfect sensors.

No measured drop of a QJ202 or 7202 is public (the paper's Fig. 13 is only a picture), so the
example data of ``auxbearing/catalog/experiments/`` are made here: the drop simulation of
:mod:`auxbearing.analysis.drop` with known parameters, then what a test rig adds on top -- a
levitated stretch before the drop, a sensor offset (sensor zero off the bearing centre), white
noise, the sensors' anti-alias low-pass (causal, so it also delays the signal), sampling and
rounding. The files say SYNTHETIC in their header and give the true parameters, so the
pipeline's recovery can be tested.

Regenerate the shipped files with::

    python -m auxbearing.experiment.synth   # writes src/auxbearing/catalog/experiments/
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from auxbearing.bearings.catalogue import load_bearing
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.planar.params import DropCase, Rotor
from auxbearing.planar.rig import run_drop

#: Folder of the shipped example data (inside the package, next to the catalogue).
EXAMPLE_DIR = Path(__file__).resolve().parents[1] / "catalog" / "experiments"


@dataclass(frozen=True)
class SensorModel:
    """What the rig adds to the true journal orbit (SI).

    Parameters
    ----------
    offset_x, offset_y : float
        Sensor reading at the bearing centre [m].
    noise : float
        Standard deviation of white noise added before the anti-alias filter [m].
    cutoff : float
        -3 dB frequency of the sensors' 4th-order Butterworth low-pass [Hz] (causal).
    sampling_rate : float
        Output sampling rate [Hz].
    pre_drop : float
        Levitated stretch recorded before the drop [s]; the journal sits at the drop position.
    resolution : float
        Rounding of the written displacement [m].
    speed_noise : float
        Standard deviation of the speed channel noise [rad/s].
    seed : int
        Random seed.
    """

    offset_x: float = 31.7e-6
    offset_y: float = -18.4e-6
    noise: float = 0.25e-6
    cutoff: float = 10e3
    sampling_rate: float = 50e3
    pre_drop: float = 5e-3
    resolution: float = 1e-8
    speed_noise: float = 0.2
    seed: int = 2026


#: True parameters of the shipped examples. The first three are what the pipeline should recover
#: (the fit starts from Table II's mu_1 = 0.2 and the 0.2 mm default clearance). The damping and
#: rolling-friction values are set off the defaults the fit keeps fixed, so the fit does not meet
#: its own model exactly (no "inverse crime"): the recovery tests then include a model error.
TRUE_CASE = {"sliding_friction": 0.15, "clearance": 0.18e-3, "unbalance_phase": math.radians(40.0),
             "line_damping": 800.0, "ball_damping": 600.0, "rolling_friction": 0.012}


def synthesize(bearing: str | BearingGeometry = "QJ202", rotor: Rotor | None = None, case: DropCase | None = None,
               sensor: SensorModel | None = None, duration: float = 0.1) -> tuple[dict, dict]:
    """Simulate a drop and make it look measured.

    Parameters
    ----------
    bearing, rotor, case :
        As :func:`auxbearing.planar.rig.run_drop`; default case: Table II with
        :data:`TRUE_CASE`.
    sensor : SensorModel, optional
    duration : float
        Length of the record after the drop [s].

    Returns
    -------
    channels : dict
        ``time`` [s] (0 at the start of the record), ``x``, ``y`` [m] in the sensor frame,
        ``speed`` [rad/s], as sampled.
    truth : dict
        The true parameters and the sensor model, for the file header and the tests.
    """
    bearing = load_bearing(bearing)
    sensor = sensor or SensorModel()
    case = case or DropCase(**TRUE_CASE)
    fine = 4.0 * sensor.sampling_rate  # simulate finer than the sampling, filter, then sample
    case = replace(case, duration=duration, output_step=1.0 / fine)
    ds, summary = run_drop(bearing, rotor, case)
    n_pre = round(sensor.pre_drop * fine)
    x = np.r_[np.full(n_pre, case.start_x), ds.rotor_x.values]
    y = np.r_[np.full(n_pre, case.start_y), ds.rotor_y.values]
    speed = np.r_[np.full(n_pre, case.speed), ds.rotor_speed.values]
    from scipy import signal  # here: 0.7 s to import, and most importers of this module want EXAMPLE_DIR only

    rng = np.random.default_rng(sensor.seed)
    sos = signal.butter(4, sensor.cutoff, fs=fine, output="sos")
    # start the filter in its steady state at the levitated position, as a rig that was running
    zi = signal.sosfilt_zi(sos)
    noisy_x = x + rng.normal(0.0, sensor.noise, x.size)
    noisy_y = y + rng.normal(0.0, sensor.noise, y.size)
    mx = signal.sosfilt(sos, noisy_x, zi=zi * noisy_x[0])[0]
    my = signal.sosfilt(sos, noisy_y, zi=zi * noisy_y[0])[0]
    step = 4
    mx = np.round((mx[::step] + sensor.offset_x) / sensor.resolution) * sensor.resolution
    my = np.round((my[::step] + sensor.offset_y) / sensor.resolution) * sensor.resolution
    sp = speed[::step] + rng.normal(0.0, sensor.speed_noise, mx.size)
    t = np.arange(mx.size) / sensor.sampling_rate
    truth = {
        "bearing": bearing.name,
        "sliding_friction": case.sliding_friction,
        "clearance_m": case.clearance,
        "unbalance_phase_deg": math.degrees(case.unbalance_phase),
        "line_damping_N_s_per_m": case.line_damping,
        "ball_damping_N_s_per_m": case.ball_damping,
        "rolling_friction": case.rolling_friction,
        "drop_time_s": n_pre / fine,
        "offset_x_m": sensor.offset_x,
        "offset_y_m": sensor.offset_y,
        "noise_m": sensor.noise,
        "sensor_cutoff_Hz": sensor.cutoff,
        "sampling_rate_Hz": sensor.sampling_rate,
        "simulated_peak_contact_force_N": summary["peak_contact_force_N"],
        "simulated_peak_ball_stress_MPa": summary["peak_ball_stress_MPa"],
        "simulated_impacts": summary["impacts"],
    }
    return {"time": t, "x": mx, "y": my, "speed": sp}, truth


def write_csv(path: str | Path, channels: dict, truth: dict) -> Path:
    """Write channels in the documented CSV format with a SYNTHETIC header carrying ``truth``."""
    path = Path(path)
    lines = [
        "# SYNTHETIC DATA - not a measurement. Made by auxbearing.experiment.synth:",
        "# the auxbearing drop simulation (source paper Sec. II.D, Table II, corrected per docs/paper_notes.md)",
        "# with a levitated stretch before the drop, a sensor offset, white noise, a causal 4th-order",
        "# Butterworth anti-alias low-pass, sampling and rounding on top. True values below (SI).",
        "# synthetic = true",
    ]
    lines += [f"# true_{key} = {value}" for key, value in truth.items()]
    lines.append("time [s], x [um], y [um], speed [rpm]")
    rpm = channels["speed"] * 30.0 / math.pi
    for t, x, y, s in zip(channels["time"], channels["x"] * 1e6, channels["y"] * 1e6, rpm, strict=True):
        lines.append(f"{t:.6f}, {x:.2f}, {y:.2f}, {s:.1f}")
    path.write_text("\n".join(lines) + "\n")
    return path


def main() -> None:  # pragma: no cover - regenerates the shipped files
    """Regenerate the shipped example files (QJ202 and 7202-40, same true parameters)."""
    EXAMPLE_DIR.mkdir(parents=True, exist_ok=True)
    for name, stem in (("QJ202", "qj202"), ("7202-40", "7202-40")):
        channels, truth = synthesize(name)
        path = write_csv(EXAMPLE_DIR / f"{stem}_drop_synthetic.csv", channels, truth)
        print(f"wrote {path} ({path.stat().st_size / 1e3:.0f} kB)")


if __name__ == "__main__":  # pragma: no cover
    main()
