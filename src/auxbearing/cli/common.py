"""Options and parsing shared by the commands."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from pathlib import Path

import click

from auxbearing.catalog import bearing_names
from auxbearing.common.errors import InputError


class BudgetExceeded(RuntimeError):
    """A computation used up a budget the user can raise (the message says which and how)."""


@contextlib.contextmanager
def option_named(option: str, *fields: str, value: object = None) -> Iterator[None]:
    """Tell an InputError about ``field = ...`` again as ``option = ...`` (the name the user typed).

    Library functions name their inputs by their keys ("machine", "file"); on the command line the
    same input is an option ("--machine"). With ``value``, only an error about that value is renamed (a
    machine file names other files: a bearing file in it is not ``--machine``).
    """
    try:
        yield
    except InputError as err:
        text = str(err)
        for field in fields:
            head = f"{field} = " if value is None else f"{field} = {str(value)!r}"
            if text.startswith(head):
                raise InputError(option + text[len(field):]) from None
        raise


def bearing_option(default: str = "QJ202"):
    """``--bearing``: a catalogue name or a TOML file with a [bearing] table."""
    return click.option(
        "--bearing", "bearing_spec", default=default, show_default=True, metavar="NAME|FILE.toml",
        help="Catalogue bearing (" + ", ".join(bearing_names()) + ") or a TOML file with a [bearing] table.",
    )


def json_option():
    """``--json``: print one JSON object instead of a table."""
    return click.option("--json", "as_json", is_flag=True, help="Print one JSON object (for scripts).")


def checked_out_dir(ctx: click.Context, param: click.Parameter, value: Path | None) -> Path | None:
    """Click callback: refuse an output folder that cannot be made before the command does any work."""
    from auxbearing.common.io import check_output_dir

    # An InputError here reaches the group's one-line handler (click parses inside Group.invoke).
    return None if value is None else check_output_dir(value, max(param.opts, key=len))


def warn(*warnings: str | None, where: str = "") -> None:
    """Print each non-empty warning as one ``warning: ...`` line on stderr (stdout stays clean JSON)."""
    for text in warnings:
        if text:  # one line whatever a typed value holds (a carriage return, a newline)
            click.echo("warning: " + " ".join(f"{where}{text}".split()), err=True)


def out_option(default: str):
    """``--out``: output folder."""
    return click.option(
        "--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=default,
        show_default=True, callback=checked_out_dir, help="Output folder (created; files in it are replaced).",
    )


def quantity(field: str, text: str | None, dimension: str, default_unit: str | None = None) -> float | None:
    """A command-line value with an optional unit, in SI (None stays None)."""
    from auxbearing.common.units import to_si

    if text is None:
        return None
    return to_si(field, text, dimension, default_unit)


def resolve_bearing(spec: str, contact_angle: str | None = None, groove_ratio: str | None = None,
                    option: str = "--bearing"):
    """Load a bearing (a :class:`~auxbearing.bearings.geometry.BearingGeometry`) and apply the common overrides.

    Errors name the options as typed (``option``, ``--contact-angle``, ``--groove-ratio``) with the values as typed.
    """
    from auxbearing.analysis.contact import with_overrides
    from auxbearing.bearings.catalogue import load_bearing

    return with_overrides(load_bearing(spec, option), contact_angle, groove_ratio,
                          names=("--contact-angle", "--groove-ratio"), angle_unit="deg")


def echo_json(obj: object) -> None:
    """Print a JSON document."""
    from auxbearing.common.io import dumps

    click.echo(dumps(obj))


def _time_left(fraction: float, elapsed: float) -> str:
    """", about N s left": the time left at the mean pace so far, once a twentieth of the work is done.

    The fraction is of work whose size is known (the speed a coast-down still has to lose, the drops a campaign
    still has to run), so the pace is that of the work itself; a coast-down's slow end takes longer per share
    than its start, and the estimate says "about".
    """
    if not 0.05 <= fraction < 1.0 or elapsed <= 0.0:
        return ""
    left = elapsed * (1.0 - fraction) / fraction
    return f", about {left:.0f} s left" if left < 120.0 else f", about {left / 60.0:.0f} min left"


class ProgressReporter:
    """Progress on stderr: a bar on a terminal, otherwise a plain line at least every :attr:`every` seconds.

    Use as a context manager; call it with (fraction done, status text). Off a terminal (a log, a pipe) a
    line names what is being done at least every :attr:`every` seconds, with the time since the start, also
    while one long step (a campaign, a coast-down on the cluster) reports nothing new: a log never looks
    stuck.
    """

    every = 5.0

    def __init__(self, label: str, quiet: bool = False, time_left: bool = True) -> None:
        import sys
        import threading
        import time

        self.label = label
        self.quiet = quiet
        #: whether the fraction is a share of the work (its percentage and the time left follow from it) or only
        #: counts stages, whose work differs a hundredfold: then neither is shown (a verification sat at "99 %"
        #: for its last 100 s), only what is being done and the time since the start
        self.time_left = time_left
        self.tty = sys.stderr.isatty()
        self._clock = time.monotonic
        self._start = self._last = self._clock()
        self._bar = None
        self._state = (0.0, "")
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._beat = None

    def __enter__(self) -> ProgressReporter:
        if self.quiet:
            return self
        if self.tty:
            from rich.console import Console
            from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

            columns = ([TextColumn("{task.description}"), BarColumn()]
                       + ([TextColumn("{task.percentage:>3.0f}%")] if self.time_left else [])
                       + [TimeElapsedColumn()] + ([TimeRemainingColumn()] if self.time_left else []))
            self._bar = Progress(*columns, console=Console(stderr=True), transient=True)
            self._bar.__enter__()
            # a total of None makes the bar pulse: stages counted are not a share of the work
            self._task = self._bar.add_task(self.label, total=1.0 if self.time_left else None)
        else:
            import threading

            self._beat = threading.Thread(target=self._heartbeat, name="progress", daemon=True)
            self._beat.start()
        return self

    def __call__(self, fraction: float, status: str = "") -> None:
        """Report ``fraction`` (0-1) of the work done and a short status."""
        if self.quiet:
            return
        if self._bar is not None:
            if self.time_left:
                self._bar.update(self._task, completed=fraction)
            self._bar.update(self._task, description=f"{self.label} {status}".strip())
            return
        with self._lock:
            self._state = (fraction, status)
            if self._clock() - self._last >= self.every:
                self._line()

    def _line(self) -> None:
        fraction, status = self._state
        self._last = self._clock()
        elapsed = self._last - self._start
        done = f"{100.0 * fraction:.0f} % " if self.time_left else ""
        left = _time_left(fraction, elapsed) if self.time_left else ""
        click.echo(f"{self.label}: {done}{status} ({elapsed:.0f} s{left})".replace("  ", " "), err=True)

    def _heartbeat(self) -> None:
        while not self._stop.wait(self.every / 5.0):
            with self._lock:
                if self._clock() - self._last >= self.every and self._state[1]:
                    self._line()

    def __exit__(self, *exc) -> None:
        self._stop.set()
        if self._beat is not None:
            self._beat.join(timeout=1.0)
        if self._bar is not None:
            self._bar.__exit__(*exc)


def read_machine_file(spec):
    """A machine for a command: the file checked whole, its ``[campaign]`` table by the campaign's reader too.

    The machine room checks every table it owns (:func:`auxbearing.machine.check.check_machine_document`);
    a ``[campaign]`` table belongs to a room above it, so the command line, which sits above both, asks the
    campaign's reader: a file any command refuses, every command refuses.
    """
    from auxbearing.machine.check import check_machine_document
    from auxbearing.machine.files import machine_document

    data, name, base = machine_document(spec)
    machine = check_machine_document(data, name, base)
    if "campaign" in data:
        from auxbearing.campaign.config import campaign_from_mapping

        campaign_from_mapping(data, name, base, check_machine=False)
    return machine
