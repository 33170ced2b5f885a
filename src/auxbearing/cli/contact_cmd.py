"""``auxbearing contact`` and ``auxbearing contact-sweep`` (source paper Sec. II.B, Fig. 2-4)."""

from __future__ import annotations

import math
from pathlib import Path

import click

from auxbearing.cli.common import (
    bearing_option,
    echo_json,
    json_option,
    out_option,
    resolve_bearing,
    warn,
)
from auxbearing.common.errors import InputError

#: Default budget of a contact sweep: grid points (contact angles x groove ratios). Each point holds 14
#: numbers and the figures draw every one, so 250 000 points are ~30 MB and a few seconds.
MAX_SWEEP_POINTS = 250_000


def _ball_load(text: str) -> float:
    from auxbearing.analysis.contact import ball_load_si

    return ball_load_si(text, "--ball-load")


_ROWS = (
    ("contact_load_N", "Contact load", "N", "{:.1f}"),
    ("semi_major_mm", "Semi-major axis a", "mm", "{:.4f}"),
    ("semi_minor_mm", "Semi-minor axis b", "mm", "{:.4f}"),
    ("ellipticity", "Ellipticity a/b", "-", "{:.3f}"),
    ("approach_um", "Elastic approach", "µm", "{:.3f}"),
    ("max_stress_MPa", "Max contact stress", "MPa", "{:.1f}"),
    ("stiffness_N_per_m1_5", "Load-deflection constant K", "N/m^1.5", "{:.4g}"),
)


@click.command("contact")
@bearing_option()
@click.option("--ball-load", default="1000", show_default=True, metavar="LOAD",
              help="Radial load on one ball: a number in N, or with a unit ('1 kN').")
@click.option("--contact-angle", default=None, metavar="ANGLE",
              help="Override the contact angle: a number in deg, or with a unit ('0.6 rad').")
@click.option("--groove-ratio", default=None, metavar="F", help="Override both groove radius coefficients (> 0.5).")
@click.option("--method", type=click.Choice(["exact", "hamrock_brewe"]), default="exact", show_default=True,
              help="Ellipticity from exact elliptic integrals, or the Hamrock-Brewe approximation.")
@json_option()
def contact_command(bearing_spec, ball_load, contact_angle, groove_ratio, method, as_json):
    """Hertz contact of one ball on the inner and outer race (source paper Eq. 1-8).

    The radial ball load is split over the ball's contacts: Q/(2 cos α) on each of the two
    contacts of a four-point bearing, Q/cos α on the one contact of an angular-contact bearing.
    """
    from rich.console import Console
    from rich.table import Table

    from auxbearing.analysis.contact import OutsideHertz, ball_contact, ellipse_checks
    from auxbearing.analysis.statics import stress_warning
    bearing = resolve_bearing(bearing_spec, contact_angle, groove_ratio)
    load = _ball_load(ball_load)
    # the option to blame for a contact outside Hertz theory: the override given, else the load
    load_given = click.get_current_context().get_parameter_source("ball_load") != click.core.ParameterSource.DEFAULT
    blame = next(((n, v) for n, v in (("--groove-ratio", groove_ratio), ("--contact-angle", contact_angle),
                                      ("--ball-load", ball_load if load_given else None), ("--bearing", bearing_spec))
                  if v is not None))
    try:
        result = ball_contact(bearing, load, method=method)
    except OutsideHertz as err:  # the API names its argument; here the option typed
        raise InputError.for_field(blame[0], blame[1], err.reason) from None
    notes = ellipse_checks(bearing, result)[0]
    warn(*notes, where=f"{blame[0]} {blame[1]}: ")
    warn(stress_warning(1e6 * max(result["inner"]["max_stress_MPa"], result["outer"]["max_stress_MPa"])))
    if as_json:
        echo_json(result)
        return
    table = Table(title=f"{bearing.name} ({bearing.label}), ball load {load:g} N, "
                        f"α = {result['contact_angle_deg']:g} deg, {bearing.pairs_per_ball} contact(s) per race")
    table.add_column("quantity")
    table.add_column("unit")
    table.add_column("inner race", justify="right")
    table.add_column("outer race", justify="right")
    for key, label, unit, fmt in _ROWS:
        table.add_row(label, unit, fmt.format(result["inner"][key]), fmt.format(result["outer"][key]))
    Console().print(table)
    click.echo(f"Ball constant K_b (Eq. 15): {result['ball_constant_N_per_m1_5']:.4g} N/m^1.5")


@click.command("contact-sweep")
@bearing_option()
@click.option("--ball-load", default="1000", show_default=True, metavar="LOAD", help="Radial load on one ball [N].")
@click.option("--angle-range", nargs=3, type=float, default=(10.0, 75.0, 1.0), show_default=True,
              metavar="START STOP STEP", help="Contact angles [deg] (Fig. 2: 10-75 deg).")
@click.option("--ratio-range", nargs=3, type=float, default=(0.505, 0.6, 0.0025), show_default=True,
              metavar="START STOP STEP", help="Groove radius coefficients [-] (Fig. 3: 0.505-0.6).")
@click.option("--max-points", default=MAX_SWEEP_POINTS, show_default=True, type=click.IntRange(min=1), metavar="N",
              help="Budget: most grid points (angles x ratios) a sweep may have.")
@out_option("out/contact")
@json_option()
def contact_sweep_command(bearing_spec, ball_load, angle_range, ratio_range, max_points, out_dir, as_json):
    """Sweep contact angle and groove ratio; write NetCDF data and Fig. 2-3 style figures.

    Writes contact_map.nc (dims race x contact_angle x groove_ratio, SI units in attrs),
    fig2_contact_angle.png, fig3_groove_ratio.png, contact_map.png and contact_summary.json
    (the Fig. 4 comparison of four-point and angular-contact beside the paper's numbers).
    """
    import numpy as np

    from auxbearing.analysis.contact import PAPER_CONTACT, contact_map, type_comparison
    from auxbearing.common.io import atomic_output_dir, save_dataset, save_figure, write_json
    from auxbearing.plots.contact import plot_contact_angle_sweep, plot_contact_map, plot_groove_ratio_sweep
    bearing = resolve_bearing(bearing_spec)
    load = _ball_load(ball_load)
    if load <= 0.0:  # an unloaded ball has no contact: every stress of the sweep would be 0, its comparison 0 / 0
        raise InputError.for_field("--ball-load", ball_load, "must be > 0 N for a sweep of contact stresses")
    angles = _grid("--angle-range", angle_range, lambda v: 0.0 <= v < 90.0, "contact angles must lie in [0, 90) deg",
                   max_points)
    ratios = _grid("--ratio-range", ratio_range, lambda v: v > 0.5, "groove ratios must exceed 0.5", max_points)
    points = len(angles) * len(ratios)
    if points > max_points:
        raise InputError(f"--angle-range x --ratio-range = {len(angles):.4g} x {len(ratios):.4g} = {points:.4g} grid "
                         f"points: beyond the budget --max-points {max_points}; take larger steps or raise "
                         "--max-points")
    ds = contact_map(bearing, load, angles, ratios)
    outside = _points_outside_hertz(bearing, ds)
    if outside:
        warn(f"{outside} of {points} grid points have a contact ellipse past the groove shoulder or as large as the "
             "ball: their values are outside Hertz theory (see `auxbearing contact` at one of them)")
    summary = {"bearing": bearing.describe(), "ball_load_N": load, "fig4_comparison": type_comparison(bearing, load)}
    inputs = {"bearing": bearing.describe(), "ball_load_N": load, "angle_range_deg": angle_range,
              "ratio_range": ratio_range}
    with atomic_output_dir(out_dir) as tmp:
        save_dataset(ds, tmp / "contact_map.nc", inputs)
        save_figure(plot_contact_angle_sweep(ds, bearing.inner_groove_ratio), tmp / "fig2_contact_angle")
        save_figure(plot_groove_ratio_sweep(ds, np.degrees(bearing.contact_angle)), tmp / "fig3_groove_ratio")
        save_figure(plot_contact_map(ds), tmp / "contact_map")
        write_json(summary, tmp / "contact_summary.json", inputs)
    if as_json:
        echo_json({**summary, "out": str(out_dir)})
        return
    comp = summary["fig4_comparison"]
    click.echo(f"Four-point max stress  {comp['four_point_max_stress_MPa']:.1f} MPa "
               f"(paper: theory {PAPER_CONTACT['theory_four_point_MPa']} MPa, "
               f"FE {PAPER_CONTACT['fe_four_point_MPa']} MPa)")
    click.echo(f"Angular-contact        {comp['angular_contact_max_stress_MPa']:.1f} MPa "
               f"(paper: FE {PAPER_CONTACT['fe_angular_contact_MPa']} MPa)")
    click.echo(f"Wrote {Path(out_dir) / 'contact_map.nc'} and the Fig. 2-3 figures in {out_dir}/")


def _grid(name: str, triple: tuple[float, float, float], valid, rule: str, budget: int):
    """START..STOP by STEP, checked, never past STOP; its length is known before anything is allocated."""
    import numpy as np

    from auxbearing.analysis.contact import sweep_grid

    start, stop, step = triple
    typed = " ".join(f"{v:g}" for v in triple)
    if not all(math.isfinite(v) for v in triple):
        raise InputError.for_field(name, typed, "START STOP STEP must be finite numbers")
    if step <= 0 or stop < start:
        raise InputError.for_field(name, typed, "needs START <= STOP and STEP > 0")
    if not (valid(start) and valid(stop)):
        raise InputError.for_field(name, typed, rule)
    count = math.floor((stop - start) / step + 1e-9) + 1
    if count > budget:  # refused here, before an array of that length is made
        raise InputError.for_field(name, typed, f"{count:.4g} values: beyond the budget --max-points {budget}; "
                                                "take a larger STEP or raise --max-points")
    return np.asarray(sweep_grid(start, stop, step))


def _points_outside_hertz(bearing, ds) -> int:
    """Grid points whose ellipse is as large as the ball or reaches past the shoulder (as in :func:`ellipse_checks`)."""
    import numpy as np

    from auxbearing.analysis.contact import outside_hertz

    alpha = np.radians(ds["contact_angle"].values)[None, :, None]
    too_large, over_shoulder = outside_hertz(bearing, ds["semi_major"].values, alpha,  # race x angle x ratio
                                             ds["groove_ratio"].values[None, None, :])
    return int(np.count_nonzero((too_large | over_shoulder).any(axis=0)))


COMMANDS = [contact_command, contact_sweep_command]
