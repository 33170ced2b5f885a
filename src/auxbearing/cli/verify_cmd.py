"""``auxbearing verify``: a machine file in, a report with criteria, margins, candidates and a recommendation out.

Heavy libraries are imported inside the command, so ``--help`` answers at once.
"""

from __future__ import annotations

from pathlib import Path

import click

from auxbearing.cli.common import ProgressReporter, checked_out_dir, echo_json, json_option
from auxbearing.common.errors import InputError
from auxbearing.machine.judging import MAX_CAMPAIGN_SAMPLES

#: What a verification writes into its --out folder (an earlier verification's are replaced as a whole).
VERIFY_OUTPUTS = ("report.html", "verify.json", "drop_*.nc", "coastdown.nc", "campaign*.zarr")
#: Exit status by verdict (2 is bad input, as for every command): a script can gate on it.
EXIT_STATUS = {"pass": 0, "fail": 1, "incomplete": 3}


#: Columns from which the verdict is a table; narrower consoles (a log is 80) get one line a criterion.
WIDE_TABLE = 110


@click.command("verify")
@click.option("--machine", "machine_spec", required=True, metavar="FILE|NAME",
              help="A machine TOML file or an example machine (`auxbearing machines`).")
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), required=True,
              callback=checked_out_dir, help="Folder for report.html, verify.json and the data behind them.")
@click.option("--candidates", default=None, metavar="LIST",
              help="Comma-separated catalogue bearings or bearing TOML files to try in the same seats "
                   "(default: the file's [[candidate]] tables; none: the design alone).")
@click.option("--quick", is_flag=True, help="A first look in well under a minute: short drops, the first seconds "
                                            "of the coast-down, 8 campaign drops, a coarse recommendation; what the "
                                            "cut runs pass is not checked (INCOMPLETE at best).")
@click.option("--campaign-samples", type=int, default=None, metavar="N",
              help="Drops of the campaign over the drop conditions (0: none); default verify.campaign_samples.")
@click.option("--workers", type=int, default=None, metavar="N", help="Campaign worker processes (default: cores).")
@click.option("--scheduler", default=None, metavar="ADDRESS", help="Use a running Dask scheduler for the campaigns.")
@click.option("--no-recommendation", is_flag=True, help="Skip the search for the best geometry.")
@json_option()
@click.option("--quiet", is_flag=True, help="No progress output.")
def verify_command(machine_spec, out_dir, candidates, quick, campaign_samples, workers, scheduler,
                   no_recommendation, as_json, quiet):
    """Verify the touchdown bearings of a machine against explicit criteria.

    Runs a drop at the maximum speed, one at low speed, the process thrust reversed (when there is one),
    the coast-down with heat and a small campaign; judges them against the [criteria] table (every default's
    origin is stated in the report); ranks candidate bearings in the same seats; recommends the contact
    angle, groove ratios and clearance of the design's bearing family that maximise the worst margin.
    Writes report.html (verdicts first) and verify.json. Exit status: 0 PASS, 1 FAIL, 3 INCOMPLETE (a criterion
    not checked: its input missing, a run cut short by --quick or a budget, a campaign too small to show it),
    2 bad input.
    """
    from rich.console import Console
    from rich.table import Table

    from auxbearing.common.io import atomic_output_dir
    from auxbearing.report.verify_html import verdict_rows
    from auxbearing.verify.run import verify

    if campaign_samples is not None and not 0 <= campaign_samples <= MAX_CAMPAIGN_SAMPLES:
        raise InputError.for_field("--campaign-samples", campaign_samples, f"must lie in [0, {MAX_CAMPAIGN_SAMPLES}]")
    if workers is not None and not 1 <= workers <= 256:
        raise InputError.for_field("--workers", workers, "must lie in [1, 256]")
    with atomic_output_dir(out_dir, owned=VERIFY_OUTPUTS) as tmp:
        # its fraction counts stages, whose work differs a hundredfold: a percentage or time left would mislead
        with ProgressReporter(f"verify {machine_spec}", quiet, time_left=False) as progress:
            steps = {"n": 0}

            def say(text: str) -> None:
                steps["n"] += 1
                progress(min(0.99, steps["n"] / 40.0), text)

            result = verify(machine_spec, tmp, candidates, quick=quick, samples=campaign_samples, workers=workers,
                            scheduler=scheduler, with_recommendation=not no_recommendation, progress=say,
                            candidates_option="--candidates")
        result.save(tmp)
    if as_json:
        shown = ("verdict", "reason", "machine", "criteria", "worst_margin", "candidates", "ranking",
                 "ranking_whirl_term", "recommendation", "recommendation_note", "wall_time_s", "margins", "campaign")
        echo_json({k: v for k, v in result.items() if k in shown} | {"out": str(out_dir)})
        click.get_current_context().exit(EXIT_STATUS[result["verdict"]])
    rows, _ = verdict_rows(result["design"]["criteria"])
    table = Table(title=f"Verification of {result['machine']}: {result['verdict'].upper()}")
    for col in ("criterion", "required", "found", "margin", "pass/fail"):
        table.add_column(col, justify="left" if col == "criterion" else "right")
    for row in rows:
        table.add_row(*[str(v) for v in row])
    console = Console()
    console.print(f"{result['verdict'].upper()}: {result['reason']}", highlight=False)
    if console.width >= WIDE_TABLE:
        console.print(table)
    else:  # a log or a narrow terminal: one line a criterion instead of a table wrapped over five
        console.print(f"Verification of {result['machine']}: {result['verdict'].upper()}", highlight=False)
        for name, required, found, margin, status in rows:
            console.print(f"  {status:>11}  {name}: {found} against {required}"
                          + (f" (margin {margin})" if margin != "-" else ""), highlight=False, soft_wrap=True)
    if result["verdict"] == "fail":  # an incomplete verdict's reason says already why each is not checked
        for c in result["design"]["criteria"]:
            if c.passed is None:
                console.print(f"Not checked: {c.name}: {c.evidence}", highlight=False, soft_wrap=True)
    if result["candidates"]:
        console.print("Candidates ranked (fewest criteria failed, then fewest not checked, then the larger worst "
                      "margin" + (f"; {result['ranking_whirl_term']}" if result.get("ranking_whirl_term") else "")
                      + ("; --quick: an order of figures not checked, which the full run may change"
                         if result["quick"] else "") + "): " + ", ".join(result["ranking"]), highlight=False)
    if result.get("recommendation_note"):
        console.print(f"No recommendation: {result['recommendation_note']}", highlight=False)
    if result["recommendation"]:
        rec = result["recommendation"]
        if not rec["passes"]:
            console.print(f"No recommendation: {rec['note']}", highlight=False)
        else:
            # the search judges drops only; a geometry whose own verification is not a pass says so here too,
            # not only in the report (a --quick run's never is)
            checked = rec.get("verification")
            own = (f"; its own verification: {checked['verdict'].upper()}, see the report"
                   if checked and checked["verdict"] != "pass" else "")
            console.print(f"Recommended {rec['family'].replace('_', ' ')} geometry: contact angle "
                          f"{rec['contact_angle_deg']:.1f} deg, groove ratios {rec['inner_groove_ratio']:.3f}/"
                          f"{rec['outer_groove_ratio']:.3f}, clearance x{rec['clearance_factor']:.2f}; binds: "
                          f"{rec['binding_criterion']}{own}", highlight=False)
    click.echo(f"Report: {out_dir / 'report.html'} ({result['wall_time_s']:.0f} s)")
    click.get_current_context().exit(EXIT_STATUS[result["verdict"]])


COMMANDS = [verify_command]
