"""What the command line checks around a drop: the step and ball-contact budgets and the wall-time guard.

Before the run: the fewest steps the run can take against its step budget (:func:`check_budget`) and the
ball contact pairs against their budget; while it runs, a wall-time guard for interactive use
(:func:`budgeted`). The physics checks of the inputs and results are :mod:`auxbearing.analysis.plausibility`.
"""

from __future__ import annotations

from auxbearing.cli.common import BudgetExceeded
from auxbearing.common.errors import InputError

#: Default budget of ball contact pairs (balls x pairs) per touchdown plane of a drop. Every integration step
#: evaluates each pair; the paper's QJ202 has 22 and a 0.15 s drop takes ~0.5 s, while 12 000 pairs (6000 balls)
#: took ~3 ms a step, ~20 min a drop. 400 pairs (a 200-ball four-point bearing) keep a drop near a minute.
MAX_BALL_CONTACTS = 400


def check_ball_contacts(machine, budget: int, blame: str) -> None:
    """Refuse a plane whose ball set has more contact pairs than the budget (checked before any step)."""
    for plane in machine.planes:
        b = plane.bearing
        pairs = b.ball_count * b.pairs_per_ball * plane.rows  # a matched pair's rows each carry their balls
        if pairs > budget:
            rows = f" x {plane.rows} rows" if plane.rows > 1 else ""
            raise InputError(f"{blame}: {plane.name} has {b.ball_count} balls x {b.pairs_per_ball} contact pairs"
                             f"{rows} = {pairs} contacts, each evaluated at every step: beyond the budget "
                             f"--max-ball-contacts {budget}; raise --max-ball-contacts to run it anyway")


def check_budget(machine, duration: float, blame: str, raise_with: str) -> None:
    """Refuse a run whose fewest possible steps (duration / max_step) already exceed its step budget.

    ``blame`` names what the user set (``--duration = '20'``); ``raise_with`` says how the budget is raised.
    """
    sim = machine.simulation
    fewest = duration / sim.max_step
    if fewest > sim.max_steps:
        raise InputError(f"{blame}: the run needs at least {fewest:.3g} steps (duration {duration:g} s / max_step "
                         f"{sim.max_step:g} s), beyond the step budget drop.max_steps = {sim.max_steps:.3g}; shorten "
                         f"the run, lengthen the largest step, or {raise_with}")


def stiffness_warnings(machine, duration: float, prefix: str = "", names: dict | None = None) -> list[str]:
    """Warnings for a stiff run, said before it starts; a refusal when it cannot fit its step budget.

    :func:`auxbearing.machine.check.stiffness_notes` with each sentence prefixed (``"--machine = 'm.toml': "``).
    """
    from auxbearing.machine.check import stiffness_notes

    try:
        return [prefix + note for note in stiffness_notes(machine, duration, names)]
    except InputError as err:
        raise InputError(prefix + str(err)) from None


def paper_stiffness_names(params: dict) -> dict:
    """How the paper drop's options name its race in a stiffness warning: the options typed, else the default."""
    typed = [f"--{key.replace('_', '-')} = {params[('drop', key)]!r}"
             for key in ("race_mass", "ball_damping", "line_damping", "line_stiffness") if ("drop", key) in params]
    return {"touchdown.0.race_mass": ", ".join(typed) or "--race-mass (default)"}




def machine_input_names(spec: str) -> dict:
    """How :func:`plausibility` names the inputs of a machine file or example given as ``spec``."""
    return {"unbalance": f"{spec}: rotor.unbalance", "clearance": f"{spec}: radial_clearance",
            "line_stiffness": f"{spec}: line_stiffness", "polar_inertia": f"{spec}: rotor.polar_inertia"}










def budgeted(progress, seconds: float):
    """A progress callback that ends the run once it has used ``seconds`` of wall time (--max-wall-time)."""
    import time

    start = time.monotonic()

    def report(fraction: float, status: str = "") -> None:
        progress(fraction, status)
        spent = time.monotonic() - start
        if spent > seconds:
            raise BudgetExceeded(f"--max-wall-time = {seconds:g} s: the drop used up its wall-time budget after "
                                 f"{spent:.1f} s at {fraction:.1%} of the simulated time; the inputs make the model "
                                 "stiff or long (look at masses, stiffnesses and --max-step), or raise "
                                 "--max-wall-time to go on")

    return report


def decimation_note(written: float, asked: float, max_points: float) -> str:
    """The sentence that says a long run's output was written on a coarser grid than asked, and why."""
    return (f"the time series is written every {written * 1e6:.4g} us, not the {asked * 1e6:.4g} us asked: the run at "
            f"that step would exceed the output budget drop.max_output_points = {max_points:.3g} (memory); peaks, "
            "impacts and whirl come from the run itself, not from the written grid")




