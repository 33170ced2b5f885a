"""The figures of a verification report, built from the result of :func:`auxbearing.verify.run.verify`."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure


def build_figures(result: dict) -> dict[str, list[tuple[Figure, str]]]:
    """Section key -> [(figure, caption)] for :func:`auxbearing.report.verify_html.render`."""
    from auxbearing.analysis.coastdown_life import cycles_of_worst_contact
    from auxbearing.bearings.ratings import ISO76_BALL_STRESS
    from auxbearing.machine.scenario import SCENARIO_CASE
    from auxbearing.plots import coastdown as pc
    from auxbearing.plots import drop as pd
    from auxbearing.plots.machine import plot_machine

    cases = result["design"]["cases"]
    out: dict[str, list] = {"machine": [(plot_machine(cases.machine), "Rotor, touchdown planes, bearings, "
                                         "clearances (radially enlarged), mounts and collars.")]}
    out["modes"] = _modes(cases.machine)
    out["criteria"] = [(_criteria_margins(result["design"]["criteria"]),
                        "Every criterion's margin against its limit (the line at zero): green holds, red fails; "
                        "a yes/no criterion is drawn at +-100 %, one not checked is named with no bar.")]
    min_s0 = result.get("inputs", {}).get("criteria", {}).get("min_s0")
    # ISO 76: s0 = (4200 MPa / sigma)^3 for a ball contact, so s0 >= min_s0 holds below 4200 / min_s0^(1/3) MPa
    stress_limit = None if not min_s0 else ISO76_BALL_STRESS / 1e6 / float(min_s0) ** (1.0 / 3.0)
    drops = []
    for case, run in cases.drops.items():
        ds, summary = run.dataset, run.summary
        if case == "drop at the maximum speed":
            for k in range(ds.sizes["plane"]):
                drops.append((pd.plot_orbit(ds, k), f"{case}: orbit of the journal at {ds.plane.values[k]}"))
            drops.append((pd.plot_ball_stress(ds, limit_MPa=stress_limit), f"{case}: largest ball contact stress"
                          + ("" if stress_limit is None else f"; dashed: the stress at which s0 falls to "
                             f"criteria.min_s0 = {float(min_s0):g} (ISO 76)")))
            drops.append((pd.plot_tilt(ds), f"{case}: tilt and axial position of the rotor"))
            if pd.orbit_positions(cases.machine):
                drops.append((pd.plot_axis_orbits(cases.machine, ds), f"{case}: orbits of the rotor axis at the "
                              "stations and at mid-span (dashed: the nearest touchdown plane's clearance)"))
        drops.append((pd.plot_contact_force(ds), f"{case}: journal/race collision force ({summary['verdict']})"))
        drops.append((pd.plot_whirl_timeline(summary), f"{case}: whirl, window by window"))
    out["drops"] = drops
    out["scenarios"] = [(pd.plot_magnetic_bearings(run.dataset, run.summary), f"{case}: the magnetic bearings' "
                         f"currents and forces beside the collision forces ({run.summary['scenario']['outcome']})")
                        for case, run in cases.drops.items()
                        if case.startswith(SCENARIO_CASE) and "amb" in run.dataset and "outcome" in run.summary.get(
                            "scenario", {})]
    coast = cases.coastdown
    if coast is not None:
        figs = [(pc.plot_speeds(coast.history), "Spin-down of rotor and races. Grey bands: stretches the reduced "
                 "model carries (the races rolling or whirling steadily; spin speeds under the losses the last "
                 "full-dynamics windows measured). A race speed that steps where a band ends is full dynamics "
                 "taking over again from the averaged state.")]
        limit = result.get("inputs", {}).get("criteria", {}).get("max_temperature")
        limit_C = None if limit is None else limit - 273.15
        for k in range(len(cases.machine.planes)):
            figs.append((pc.plot_temperatures(coast.history, k, limit_C=limit_C),
                         f"{cases.machine.planes[k].name}: temperatures of the plane's thermal network"
                         + ("" if limit_C is None else f"; dashed: the limit the verdict judges against "
                            f"(criteria.max_temperature = {limit_C:.0f} °C)")))
        figs.append((pc.plot_clearances(coast.history), "Clearances with thermal growth"))
        for k, life in enumerate(coast.life):
            if life is None:  # the drop left the model's range: its stress history is not a life's
                continue
            figs.append((pc.plot_stress_cycles(cycles_of_worst_contact(life)),
                         f"{cases.machine.planes[k].name}: stress cycles of the drop's most damaged contact"))
        out["coastdown"] = figs
    if cases.campaign_store:
        from auxbearing.campaign.store import load_results
        from auxbearing.plots.campaign import plot_histograms, plot_whirl_map

        ds = load_results(cases.campaign_store)
        if cases.campaign and cases.campaign.get("stopped_decided"):  # the drops the statistics rest on
            ds = ds.isel(sample=slice(0, cases.campaign["samples"]))
        keys = [str(k) for k in ds["input"].values]
        whirled = "backward_whirl" in ds and bool(np.nansum(ds["backward_whirl"].values) > 0)
        note = "" if whirled or len(keys) < 2 else (" No drop of the campaign whirled backward, so there is no whirl "
                                                     "map to draw.")
        figs = [(plot_histograms(ds), "Distributions of the campaign's outcomes." + note)]
        if len(keys) >= 2 and whirled:
            figs.append((plot_whirl_map(ds, keys[0], keys[1]), f"Whirl class over {keys[0]} and {keys[1]}"))
        out["campaign"] = figs
    if result.get("candidates"):
        out["candidates"] = [(_candidate_bars(result), "Worst margin of every candidate (negative: fails)")]
    rec = result.get("recommendation")
    if rec:
        out["recommendation"] = [(_recommendation_map(rec), "Worst drop margin of every design tried")]
    return out


def _modes(machine) -> list[tuple[Figure, str]]:
    """The Campbell diagram, free (levitated) and in contact, and an elastic rotor's mode shapes."""
    from auxbearing.analysis.modes import STATES, campbell
    from auxbearing.plots.modes import plot_campbell, plot_mode_shapes

    speeds = np.linspace(0.0, 1.2 * abs(machine.rotor.speed), 25)
    diagrams = [campbell(machine, speeds, state) for state in STATES]
    crossings = []
    for d in diagrams:
        crit = ", ".join(f"{c['speed_rpm']:.0f} rpm" for c in d.critical_speeds()) or "none up to 1.2x the speed"
        crossings.append(f"{'levitated' if d.state == 'free' else 'in contact at rest'}: {crit}")
    out = [(plot_campbell(diagrams, machine.rotor.speed), "Damped natural frequencies against speed (forward and "
            "backward whirl), levitated on the magnetic bearings and linear supports and in contact with the touchdown "
            "bearings at rest; critical speeds (the synchronous line on a forward mode): " + "; ".join(crossings)
            + ". The magnetic bearings enter as their ideal spring and damper (sensor and amplifier lags left out).")]
    modal = machine.modal()
    if modal is not None and modal.n_modes:
        kept = f"the drop keeps {modal.natural} of them"
        if modal.residual:
            kept += (f" and {modal.residual} static correction vectors, which carry the flexibility of the modes "
                     "left out at the stations")
        out.append((plot_mode_shapes(modal), f"The rotor's free-free elastic mode shapes ({kept})"))
    return out


#: Margins beyond +-200 % are drawn cut at the axis' end with their value written on the bar.
CLIP = 2.0


def _criteria_margins(criteria: list) -> Figure:
    """One bar per criterion: its margin in per cent, the limit at zero; yes/no at +-100 %, unchecked named only."""
    fig = Figure(figsize=(8, 0.45 * len(criteria) + 1.2), layout="constrained")
    ax = fig.add_subplot()
    labels, values, colours = [], [], []
    for c in criteria:
        if c.passed is None:
            value, colour = 0.0, "0.6"
        elif c.margin is None:
            value, colour = (100.0 if c.passed else -100.0), ("tab:green" if c.passed else "tab:red")
        else:
            value, colour = 100.0 * max(min(c.margin, CLIP), -CLIP), ("tab:green" if c.passed else "tab:red")
        labels.append(c.name if len(c.name) <= 48 else c.name[:46] + "...")
        values.append(value)
        colours.append(colour)
    ax.barh(labels, values, color=colours)
    for i, c in enumerate(criteria):
        if c.passed is None:
            ax.text(0.0, i, "  not checked", va="center", fontsize=8, color="0.35")
        elif c.margin is not None and abs(c.margin) > CLIP:  # a bar cut at the axis' end says its value
            ax.text(values[i], i, f" {100.0 * c.margin:+.0f} % ", va="center", fontsize=8,
                    ha="right" if c.margin > 0 else "left", color="white")
    ax.axvline(0.0, color="black", lw=1.0)
    ax.set_xlabel("Margin [%] (0: at the limit)")
    ax.invert_yaxis()
    ax.grid(axis="x", alpha=0.3)
    return fig


def _candidate_bars(result: dict) -> Figure:
    fig = Figure(figsize=(7, 3), layout="constrained")
    ax = fig.add_subplot()
    labels = [row[1] for row in result["candidate_rows"]]
    values = [float(row[3].rstrip(" %")) if row[3] != "-" else np.nan for row in result["candidate_rows"]]
    ax.barh(labels, values, color=["tab:green" if v >= 0 else "tab:red" for v in values])
    ax.axvline(0.0, color="black", lw=0.8)
    ax.set_xlabel("Worst margin [%]")
    ax.invert_yaxis()
    return fig


def _recommendation_map(rec: dict) -> Figure:
    fig = Figure(figsize=(7, 4), layout="constrained")
    ax = fig.add_subplot()
    points = rec["points"]
    x = [p["contact_angle_deg"] for p in points]
    y = [p["inner_groove_ratio"] for p in points]
    c = [100 * p["worst_margin"] for p in points]
    sc = ax.scatter(x, y, c=c, s=[30 + 60 * p["clearance_factor"] for p in points], cmap="RdYlGn")
    fig.colorbar(sc, ax=ax, label="worst margin [%]")
    ax.plot(rec["contact_angle_deg"], rec["inner_groove_ratio"], "k*", ms=14, label="recommended")
    ax.set_xlabel("Contact angle [deg]")
    ax.set_ylabel("Inner groove ratio [-]")
    ax.legend(fontsize=8)
    ax.set_title("marker size: radial clearance factor", loc="left", fontsize=9)
    return fig
