"""Entry point ``auxbearing``: the command group, lazy command loading and the user-error boundary.

Commands live in the modules ``auxbearing.cli.*_cmd``. :data:`COMMANDS` names, for each command, its
module and its one-line help, so ``auxbearing --help`` lists them without importing any of them and
``auxbearing <command>`` imports only its own module (a test checks that the table and the modules
agree). Heavy libraries (numba, xarray, matplotlib) are imported inside the command functions.
"""

from __future__ import annotations

import importlib
import sys
import warnings

import click

from auxbearing.cli.common import BudgetExceeded
from auxbearing.common.errors import ConvergenceError, InputError

EXIT_USER_ERROR = 2

#: command name -> (module in auxbearing.cli, one-line help)
COMMANDS: dict[str, tuple[str, str]] = {
    "bearings": ("bearings_cmd", "The bearing catalogue, filtered by type and bore, and the materials, with sources."),
    "campaign": ("campaign_cmd", "Monte Carlo campaign of machine drops over uncertain inputs (Dask, Zarr)."),
    "campaign-report": ("campaign_cmd", "Statistics, sensitivity and figures of a campaign store."),
    "coastdown": ("coastdown_cmd", "A machine from the drop to standstill: heat, thermal growth, drops to failure."),
    "contact": ("contact_cmd", "Hertz contact of one ball on the inner and outer raceway (Eq. 1-8)."),
    "contact-sweep": ("contact_cmd", "Contact-angle and groove-ratio sweeps (the paper's Fig. 2-3)."),
    "drop": ("drop_cmd", "Drop of a rotor onto its touchdown bearings: a machine file, or the paper's rig."),
    "drop-compare": ("drop_cmd", "Four-point QJ202 versus angular-contact 7202 drop beside the paper."),
    "experiment": ("experiment_cmd", "A measured drop: preprocess, force and stress from the orbit, fit."),
    "machines": ("drop_cmd", "List the example machines shipped in the catalogue."),
    "modes": ("modes_cmd", "Natural frequencies against speed (Campbell diagram), free and in contact."),
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
        raw = [*ctx._protected_args, *ctx.args]  # click empties both once the command is found
        from auxbearing.common.interrupt import watching

        with warnings.catch_warnings(), watching():
            warnings.showwarning = _one_line_warning
            try:
                _refuse_empty_paths(self, ctx)
                _check_compile_switch(raw)
                _say_when_compiling(raw)
                return super().invoke(ctx)
            except InputError as err:
                _fail(ctx, _named_as_typed(str(err), raw), EXIT_USER_ERROR)
            except click.UsageError as err:
                # click's own parsing errors (a choice, a missing option, a typo in an option's name) as one line
                where = f"; see '{err.ctx.command_path} --help'" if err.ctx is not None else ""
                _fail(ctx, err.format_message().rstrip(".") + where, EXIT_USER_ERROR)
            except ConvergenceError as err:
                _fail(ctx, str(err), 1)
            except BudgetExceeded as err:
                _fail(ctx, str(err), 1)
            except UnicodeDecodeError as err:
                _fail(ctx, f"a file is not text in any encoding auxbearing can tell ({err.reason} at byte "
                           f"{err.start}); save it as UTF-8", EXIT_USER_ERROR)
            except OSError as err:
                # A full disk or a read-only folder is the machine's state, not a bug: one line.
                what = f"file '{err.filename}'" if err.filename else "a file could not be written or read"
                _fail(ctx, f"{what}: {err.strerror or err}", EXIT_USER_ERROR)
            except MemoryError:
                _fail(ctx, "out of memory; shorten the run or coarsen its output (drop.max_output_points)",
                      EXIT_USER_ERROR)


#: Commands that run the compiled kernels (the rest answer without them).
_KERNEL_COMMANDS = ("drop", "coastdown", "campaign", "verify", "study", "static", "static-cases", "contact",
                    "experiment")


def _check_compile_switch(args: list[str]) -> None:
    """A bad AUXBEARING_COMPILE_HELPER before any work (a verification's workers would meet it only in a case)."""
    import os

    # the name is auxbearing.analysis.first_compile.ENV_SWITCH, imported (numba with it) only when it is set
    if args and args[0] in _KERNEL_COMMANDS and "--help" not in args and "AUXBEARING_COMPILE_HELPER" in os.environ:
        from auxbearing.analysis.first_compile import helper_switched_on

        helper_switched_on()


def _say_when_compiling(args: list[str]) -> None:
    """Tell the user, once after an install or an upgrade, that the first run compiles the kernels first."""
    import os
    import sys

    # on a terminal only: a script or a test reading stderr for warnings gets no extra line
    if not args or args[0] not in _KERNEL_COMMANDS or "--help" in args or not sys.stderr.isatty():
        return
    from auxbearing.core import cache_folder

    folder = cache_folder()
    if not os.path.isdir(folder) or not any(os.scandir(folder)):
        # the 2-core machine from an empty cache: the first drop 52 s, a quick verification of the blower 133 s
        # where a warm one takes 33 s (README, "Compiled kernels")
        click.echo("compiling the kernels, once after an install or an upgrade (about a minute for a drop, two for "
                   "a verification; later runs load them from the cache in under a second)", err=True)


def _named_as_typed(message: str, args: list[str]) -> str:
    """A message about ``field = 'value'`` whose value the user gave to an option, told with that option's name.

    Library code names a file it cannot read by a key of its own ("file = 'c.toml'"); the user typed
    ``--config c.toml``. Only plain fields are renamed (not a file's ``table.key``), and only when exactly one
    option carries that value.
    """
    field, sep, rest = message.partition(" = ")
    if not sep or field.startswith("-") or "." in field or not rest.startswith(("'", '"')):
        return message
    quote = rest[0]
    value = rest[1:rest.find(quote, 1)]
    options = [args[k - 1] for k in range(1, len(args)) if args[k] == value and args[k - 1].startswith("--")]
    options += [a.partition("=")[0] for a in args if a.startswith("--") and a.partition("=")[2] == value]
    return f"{options[0]} = {rest}" if len(set(options)) == 1 else message


def _fail(ctx: click.Context, message: str, status: int) -> None:
    click.echo(f"error: {' '.join(message.split())}", err=True)
    ctx.exit(status)


def _one_line_warning(message, category, filename, lineno, file=None, line=None) -> None:
    """Every warning as one ``warning:`` line on stderr (a library's file and line mean nothing to a user)."""
    text = " ".join(str(message).split())
    if not issubclass(category, UserWarning) or category.__module__.split(".")[0] != "auxbearing":
        text = f"{category.__name__}: {text}"
    click.echo(f"warning: {text}", err=True)


def _refuse_empty_paths(group: click.Group, ctx: click.Context) -> None:
    """An empty file or folder option (``--out ''``) would mean the current folder: refuse it by its name.

    click turns '' into ``Path('.')`` before any callback sees it, so the raw arguments are read here.
    """
    args = [*ctx._protected_args, *ctx.args]
    if not args:
        return
    command = group.get_command(ctx, args[0])
    if command is None:
        return
    names = {opt for p in command.params if isinstance(p, click.Option) and isinstance(p.type, click.Path)
             for opt in p.opts}
    for k, arg in enumerate(args[1:], start=1):
        option, sep, value = arg.partition("=")
        if option in names and ((sep and not value.strip()) or (not sep and k + 1 < len(args)
                                                                 and not args[k + 1].strip())):
            raise InputError.for_field(option, value if sep else args[k + 1],
                                       "is empty; give a file or folder name ('.' for the current folder)")


@click.group(cls=_Group, context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100})
@click.version_option(package_name="auxbearing", prog_name="auxbearing")
def cli() -> None:
    """Auxiliary (touchdown) bearings for active magnetic bearings: contact, load, drop, machine verdicts."""


def main() -> None:
    """Run the command line (console script ``auxbearing``)."""
    cli.main(prog_name="auxbearing", standalone_mode=True)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
