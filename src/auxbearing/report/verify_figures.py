"""The figures of a verification report, built from the result of :func:`auxbearing.verify.run.verify`."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from auxbearing.machine.scenario import SCENARIO_CASE

#: Sections whose figures come from the design's own runs: a verification on a cluster draws them there, side by
#: side, once its runs are in (:func:`design_figure_tasks`).
DESIGN_SECTIONS = ("machine", "modes", "criteria", "drops", "scenarios", "coastdown", "campaign")


def build_figures(result: dict) -> dict[str, list[tuple[str, str]]]:
    """Section key -> [(PNG as base64 text, caption)] for :func:`auxbearing.report.verify_html.render`.

    Sections the verification already rendered (``result["figures"]``, see :func:`design_figure_tasks`) are
    taken as they are; the rest are drawn here.
    """
    done = result.get("figures") or {}
    out: dict[str, list] = {}
    design = result["design"]
    for key, task, args in design_figure_tasks(design["cases"], design["criteria"], result.get("inputs", {})):
        if key not in done:
            out.setdefault(key, []).extend(task(*args))
    out.update(done)
    if result.get("candidates"):
        out["candidates"] = rendered([(_candidate_bars(result), "Worst margin of every candidate (negative: fails)")])
    rec = result.get("recommendation")
    if rec:
        out["recommendation"] = rendered([(_recommendation_map(rec), "Worst drop margin of every design tried")])
    return {key: figures for key, figures in out.items() if figures}


def rendered(figures: list[tuple[Figure, str]]) -> list[tuple[str, str]]:
    """[(figure, caption)] as [(PNG as base64 text, caption)]."""
    from auxbearing.report.html import figure_png_base64

    return [(figure_png_base64(fig), caption) for fig, caption in figures]


def design_figure_tasks(cases, criteria: list, inputs: dict, runs: dict | None = None) -> list[tuple]:
    """The design's figures as (section, function, arguments), each call returning [(PNG base64, caption)].

    One task per section, the drops and scenarios one per case, so that a cluster draws them side by side.
    ``runs`` may give, per drop case and for ``"coast-down"``, a Dask future of the run in place of the run
    itself: the task then reads it where it was computed, and nothing large crosses to this process and back.
    """
    runs = runs or {}
    min_s0 = inputs.get("criteria", {}).get("min_s0")
    limit = inputs.get("criteria", {}).get("max_temperature")
    tasks = [("machine", _machine_figures, (cases.machine,)),
             ("modes", _mode_figures, (cases.machine,)),
             ("criteria", _criteria_figures, (criteria,))]
    for case, run in cases.drops.items():
        source = runs.get(case, run)
        tasks.append(("drops", _drop_figures, (cases.machine, case, source, min_s0)))
        if case.startswith(SCENARIO_CASE):
            tasks.append(("scenarios", _scenario_figures, (case, source)))
    if cases.coastdown is not None:
        coast = runs.get("coast-down", cases.coastdown)
        tasks.append(("coastdown", _coastdown_figures, (tuple(p.name for p in cases.machine.planes), coast, limit)))
    if cases.campaign_store:
        tasks.append(("campaign", _campaign_figures, (cases.campaign_store, cases.campaign)))
    return tasks


def _machine_figures(machine) -> list[tuple[str, str]]:
    from auxbearing.plots.machine import plot_machine

    return rendered([(plot_machine(machine), "Rotor, touchdown planes, bearings, clearances (radially enlarged), "
                      "mounts and collars.")])


def _mode_figures(machine) -> list[tuple[str, str]]:
    return rendered(_modes(machine))


def _criteria_figures(criteria: list) -> list[tuple[str, str]]:
    return rendered([(_criteria_margins(criteria),
                      "Every criterion's margin against its limit (the line at zero): green holds, red fails; "
                      "a yes/no criterion is drawn at +-100 %, one not checked is named with no bar.")])


def _drop_figures(machine, case: str, source, min_s0) -> list[tuple[str, str]]:
    """The figures of one drop case (the drop at the maximum speed has its orbits, stresses and tilt too)."""
    from auxbearing.analysis.coastdown import drop_of
    from auxbearing.bearings.ratings import ISO76_BALL_STRESS
    from auxbearing.plots import drop as pd

    run = drop_of(source)
    ds, summary = run.dataset, run.summary
    # ISO 76: s0 = (4200 MPa / sigma)^3 for a ball contact, so s0 >= min_s0 holds below 4200 / min_s0^(1/3) MPa
    stress_limit = None if not min_s0 else ISO76_BALL_STRESS / 1e6 / float(min_s0) ** (1.0 / 3.0)
    figs = []
    if case == "drop at the maximum speed":
        for k in range(ds.sizes["plane"]):
            figs.append((pd.plot_orbit(ds, k), f"{case}: orbit of the journal at {ds.plane.values[k]}"))
        figs.append((pd.plot_ball_stress(ds, limit_MPa=stress_limit), f"{case}: largest ball contact stress"
                     + ("" if stress_limit is None else f"; dashed: the stress at which s0 falls to "
                        f"criteria.min_s0 = {float(min_s0):g} (ISO 76)")))
        figs.append((pd.plot_tilt(ds), f"{case}: tilt and axial position of the rotor"))
        if pd.orbit_positions(machine):
            figs.append((pd.plot_axis_orbits(machine, ds), f"{case}: orbits of the rotor axis at the "
                         "stations and at mid-span (dashed: the nearest touchdown plane's clearance)"))
    figs.append((pd.plot_contact_force(ds), f"{case}: journal/race collision force ({summary['verdict']})"))
    figs.append((pd.plot_whirl_timeline(summary), f"{case}: whirl, window by window"))
    return rendered(figs)


def _scenario_figures(case: str, source) -> list[tuple[str, str]]:
    from auxbearing.analysis.coastdown import drop_of
    from auxbearing.plots import drop as pd

    run = drop_of(source)
    if "amb" not in run.dataset or "outcome" not in run.summary.get("scenario", {}):
        return []
    return rendered([(pd.plot_magnetic_bearings(run.dataset, run.summary), f"{case}: the magnetic bearings' "
                      f"currents and forces beside the collision forces ({run.summary['scenario']['outcome']})")])


def _coastdown_figures(plane_names: tuple, coast, limit) -> list[tuple[str, str]]:
    from auxbearing.analysis.coastdown_life import cycles_of_worst_contact
    from auxbearing.plots import coastdown as pc

    figs = [(pc.plot_speeds(coast.history), "Spin-down of rotor and races. Grey bands: stretches the reduced "
             "model carries (the races rolling or whirling steadily; spin speeds under the losses the last "
             "full-dynamics windows measured). A race speed that steps where a band ends is full dynamics "
             "taking over again from the averaged state.")]
    limit_C = None if limit is None else limit - 273.15
    for k, name in enumerate(plane_names):
        figs.append((pc.plot_temperatures(coast.history, k, limit_C=limit_C),
                     f"{name}: temperatures of the plane's thermal network"
                     + ("" if limit_C is None else f"; dashed: the limit the verdict judges against "
                        f"(criteria.max_temperature = {limit_C:.0f} °C)")))
    figs.append((pc.plot_clearances(coast.history), "Clearances with thermal growth"))
    for k, life in enumerate(coast.life):
        if life is None:  # the drop left the model's range: its stress history is not a life's
            continue
        figs.append((pc.plot_stress_cycles(cycles_of_worst_contact(life)),
                     f"{plane_names[k]}: stress cycles of the drop's most damaged contact"))
    return rendered(figs)


def _campaign_figures(store: str, campaign: dict | None) -> list[tuple[str, str]]:
    from auxbearing.campaign.store import load_results
    from auxbearing.plots.campaign import plot_histograms, plot_whirl_map

    ds = load_results(store)
    if campaign and campaign.get("stopped_decided"):  # the drops the statistics rest on
        ds = ds.isel(sample=slice(0, campaign["samples"]))
    keys = [str(k) for k in ds["input"].values]
    whirled = "backward_whirl" in ds and bool(np.nansum(ds["backward_whirl"].values) > 0)
    note = "" if whirled or len(keys) < 2 else (" No drop of the campaign whirled backward, so there is no whirl "
                                                 "map to draw.")
    figs = [(plot_histograms(ds), "Distributions of the campaign's outcomes." + note)]
    if len(keys) >= 2 and whirled:
        figs.append((plot_whirl_map(ds, keys[0], keys[1]), f"Whirl class over {keys[0]} and {keys[1]}"))
    return rendered(figs)


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
    out = [(plot_campbell(diagrams, machine.rotor.speed), "Damped natural frequencies against speed (forward, "
            "backward and planar whirl), levitated on the magnetic bearings and linear supports and in contact with "
            "the touchdown bearings at rest (across the weight a journal swings on the arc of its clearance); critical "
            "speeds (the synchronous line on a forward or planar mode): " + "; ".join(crossings)
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
    ax.plot(rec["contact_angle_deg"], rec["inner_groove_ratio"], "k*", ms=14,
            label="recommended" if rec["passes"] else "best found, not recommended")
    ax.set_xlabel("Contact angle [deg]")
    ax.set_ylabel("Inner groove ratio [-]")
    ax.legend(fontsize=8)
    ax.set_title("marker size: radial clearance factor", loc="left", fontsize=9)
    return fig
