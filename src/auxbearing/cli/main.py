"""Entry point ``auxbearing``: the command group, lazy command loading and the user-error boundary.

Commands live in the modules ``auxbearing.cli.*_cmd``. :data:`COMMANDS` names, for each command, its
module and its one-line help, so ``auxbearing --help`` lists them without importing any of them and
``auxbearing <command>`` imports only its own module (a test checks that the table and the modules
agree). Heavy libraries (numba, xarray, matplotlib) are imported inside the command functions.
"""

from __future__ import annotations

import importlib
import sys

import click

from auxbearing.errors import ConvergenceError, InputError

EXIT_USER_ERROR = 2

#: command name -> (module in auxbearing.cli, one-line help)
COMMANDS: dict[str, tuple[str, str]] = {
    "bearings": ("study_cmd", "List the bearing and material catalogues with their sources."),
    "campaign": ("campaign_cmd", "Monte Carlo campaign of machine drops over uncertain inputs (Dask, Zarr)."),
    "campaign-report": ("campaign_cmd", "Statistics, sensitivity and figures of a campaign store."),
    "coastdown": ("coastdown_cmd", "A machine from the drop to standstill: heat, thermal growth, drops to failure."),
    "contact": ("contact_cmd", "Hertz contact of one ball on the inner and outer raceway (Eq. 1-8)."),
    "contact-sweep": ("contact_cmd", "Contact-angle and groove-ratio sweeps (the paper's Fig. 2-3)."),
    "drop": ("drop_cmd", "Drop of a rotor onto its touchdown bearings: a machine file, or the paper's rig."),
    "drop-compare": ("drop_cmd", "Four-point QJ202 versus angular-contact 7202 drop beside the paper."),
    "experiment": ("experiment_cmd", "A measured drop: preprocess, force and stress from the orbit, fit."),
    "machines": ("drop_cmd", "List the example machines shipped in the catalogue."),
    "static": ("static_cmd", "Quasi-static load distribution of one load case (Eq. 9-16)."),
    "static-cases": ("static_cmd", "A CSV of load cases through the batched static solver."),
    "static-study": ("static_cmd", "The paper's static study (Fig. 6-8)."),
    "study": ("study_cmd", "Reproduce the source paper into a report with a claims check."),
    "verify": ("verify_cmd", "Verify a touchdown-bearing design: criteria, margins, candidates, a recommendation."),
}


def _available() -> dict[str, tuple[str, str]]:
    """The commands whose module is installed (a command appears once its module exists)."""
    from importlib.util import find_spec

    return {name: entry for name, entry in COMMANDS.items() if find_spec(f"auxbearing.cli.{entry[0]}") is not None}


class _Group(click.Group):
    """Loads a command's module when it is called; turns user mistakes into one line and exit status 2."""

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(_available())

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        entry = _available().get(name)
        if entry is None:
            return None
        module = importlib.import_module(f"auxbearing.cli.{entry[0]}")
        return next(c for c in module.COMMANDS if c.name == name)

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        rows = [(name, help_text) for name, (_, help_text) in sorted(_available().items())]
        with formatter.section("Commands"):
            formatter.write_dl(rows)

    def invoke(self, ctx: click.Context):
        try:
            return super().invoke(ctx)
        except InputError as err:
            click.echo(f"error: {err}", err=True)
            ctx.exit(EXIT_USER_ERROR)
        except ConvergenceError as err:
            click.echo(f"error: {err}", err=True)
            ctx.exit(1)
        except UnicodeDecodeError as err:
            click.echo(f"error: a file is not UTF-8 text ({err.reason} at byte {err.start}); save it as UTF-8",
                       err=True)
            ctx.exit(EXIT_USER_ERROR)
        except OSError as err:
            # A full disk or a read-only folder is the machine's state, not a bug: one line.
            where = f" '{err.filename}'" if err.filename else ""
            click.echo(f"error: file{where}: {err.strerror or err}", err=True)
            ctx.exit(EXIT_USER_ERROR)
        except MemoryError:
            click.echo("error: out of memory; shorten the run or coarsen its output (drop.max_output_points)",
                       err=True)
            ctx.exit(EXIT_USER_ERROR)


@click.group(cls=_Group, context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100})
@click.version_option(package_name="auxbearing", prog_name="auxbearing")
def cli() -> None:
    """Auxiliary (touchdown) bearings for active magnetic bearings: contact, load, drop, machine verdicts."""


def main() -> None:
    """Run the command line (console script ``auxbearing``)."""
    cli.main(prog_name="auxbearing", standalone_mode=True)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
