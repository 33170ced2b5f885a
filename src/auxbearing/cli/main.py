"""Entry point ``auxbearing``: the command group and the user-error boundary.

Commands live in the modules ``auxbearing.cli.*_cmd``, each listing its click commands in
``COMMANDS``; they are registered here by discovery, so adding an analysis adds a module,
not an edit to a central if/elif chain.
"""

from __future__ import annotations

import importlib
import pkgutil
import sys

import click

from auxbearing import __version__
from auxbearing.errors import ConvergenceError, InputError

EXIT_USER_ERROR = 2


class _Group(click.Group):
    """A group that turns user mistakes into one line on stderr and exit status 2."""

    def invoke(self, ctx: click.Context):
        try:
            return super().invoke(ctx)
        except InputError as err:
            click.echo(f"error: {err}", err=True)
            ctx.exit(EXIT_USER_ERROR)
        except ConvergenceError as err:
            click.echo(f"error: {err}", err=True)
            ctx.exit(1)
        except OSError as err:
            # A full disk or a read-only folder is the machine's state, not a bug: one line.
            where = f" '{err.filename}'" if err.filename else ""
            click.echo(f"error: file{where}: {err.strerror or err}", err=True)
            ctx.exit(EXIT_USER_ERROR)

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(self.commands)


@click.group(cls=_Group, context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100})
@click.version_option(__version__, prog_name="auxbearing")
def cli() -> None:
    """Auxiliary (touchdown) bearings for active magnetic bearings: contact, load, drop."""


def _register() -> None:
    package = importlib.import_module("auxbearing.cli")
    for info in sorted(pkgutil.iter_modules(package.__path__), key=lambda m: m.name):
        if info.name.endswith("_cmd"):
            module = importlib.import_module(f"auxbearing.cli.{info.name}")
            for command in getattr(module, "COMMANDS", ()):
                cli.add_command(command)


_register()


def main() -> None:
    """Run the command line (console script ``auxbearing``)."""
    cli.main(prog_name="auxbearing", standalone_mode=True)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
