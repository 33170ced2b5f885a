"""``auxbearing campaign`` and ``auxbearing campaign-report``: drop campaigns on Dask, stored in Zarr.

Heavy libraries (numpy, xarray, dask, zarr, matplotlib) are imported inside the commands, so
``--help`` answers at once. Every check of the campaign file and of ``--out`` happens before a
cluster starts or anything is written.
"""

from __future__ import annotations

from pathlib import Path

import click

from auxbearing.cli.common import ProgressReporter, checked_out_dir, echo_json, json_option, warn
from auxbearing.common.errors import InputError

#: Exit status after Ctrl-C / SIGTERM (128 + SIGINT), as shells report it.
EXIT_INTERRUPTED = 130


def _workers(text: str | None, scheduler: str | None) -> int | None:
    if text is None:
        return None
    if scheduler is not None:
        raise InputError.for_field("--workers", text, "sizes the local cluster; a --scheduler brings its own workers")
    try:
        n = int(text)
    except ValueError:
        raise InputError.for_field("--workers", text, "must be a whole number from 1 to 1024") from None
    if not 1 <= n <= 1024:
        raise InputError.for_field("--workers", text, "must be a whole number from 1 to 1024")
    return n


def _status(p) -> tuple[float, str]:
    # the time left is the progress line's own estimate: a second one from the drop rate alone (no start-up)
    # contradicted it
    return p.done / p.runs, f"{p.done}/{p.runs} samples, {p.rate:.2f} drops/s"


@click.command("campaign")
@click.option("--config", "config", type=click.Path(dir_okay=False, path_type=Path), required=True,
              help="Campaign file: a machine (tables, or machine = NAME in [campaign]) and a [campaign] table.")
@click.option("--out", "store", type=click.Path(path_type=Path), required=True,
              callback=checked_out_dir, help="Zarr store of the results; the same command again resumes it.")
@click.option("--scheduler", default=None, metavar="ADDRESS",
              help="Address of a running Dask scheduler (tcp://host:8786); default a local cluster.")
@click.option("--workers", "workers_text", default=None, metavar="N",
              help="Worker processes of the local cluster [default: one per core].")
@json_option()
@click.option("--quiet", is_flag=True, help="No progress bar.")
def campaign_command(config, store, scheduler, workers_text, as_json, quiet):
    """Monte Carlo campaign of machine drops over uncertain inputs, on Dask, resumable.

    Runs every sample of the campaign's design (sobol, lhs, random or saltelli) on a local cluster
    started and stopped here, or on --scheduler. Each sample is a record with its verdict: a run
    that leaves the model's range or fails is a result, never the end of the campaign. Results go to
    the Zarr store --out as batches finish; after Ctrl-C or a kill, the same command goes on where
    it stopped and gives the store an uninterrupted run would.
    """
    import signal

    from auxbearing.campaign.config import read_campaign
    from auxbearing.campaign.run import CampaignInterrupted, run_campaign
    from auxbearing.campaign.sampling import balance_note
    from auxbearing.campaign.statistics import campaign_statistics, headline
    from auxbearing.campaign.store import load_results
    from auxbearing.common import interrupt

    workers = _workers(workers_text, scheduler)
    campaign = read_campaign(config)
    warn(*campaign.notes, balance_note(campaign))

    # SIGTERM ends like Ctrl-C: the cluster is shut down, the store kept
    previous = signal.signal(signal.SIGTERM, interrupt.handler)
    try:
        with ProgressReporter(f"campaign {campaign.name}", quiet) as reporter:
            result = run_campaign(campaign, store, scheduler, workers,
                                  progress=lambda p: reporter(*_status(p)))
    except Exception as err:  # an interrupt the cluster's client turned into an error of its own is still one
        if not interrupt.requested() or isinstance(err, InputError):
            raise
        _interrupted(_stored(store), campaign.runs, store)
    except KeyboardInterrupt as stop:  # in the batches, or while the cluster starts or winds down
        done, runs = (stop.done, stop.runs) if isinstance(stop, CampaignInterrupted) else (
            _stored(store), campaign.runs)
        _interrupted(done, runs, store)
    finally:
        signal.signal(signal.SIGTERM, previous)
    if result["lost"]:
        warn(f"{result['lost']} samples did not come back ({result['lost_reason']}); run the same command to "
             "retry them")
    stats = campaign_statistics(load_results(store))
    out = {**headline(stats), "wall_time_s": result["wall_time_s"], "drops_per_second": result["drops_per_second"],
           "new": result["new"], "lost": result["lost"], "workers": result["workers"],
           "startup_s": result["startup_s"], "warm_up_s": result["warm_up_s"], "run_s": result["run_s"],
           "store": str(store), "campaign": campaign.name, "runs": campaign.runs, "base_samples": campaign.samples,
           "sampler": campaign.sampler, "seed": campaign.seed}
    if as_json:
        echo_json(out)
        return
    _print(out, stats)


def _interrupted(done: int, runs: int, store) -> None:
    click.echo(f"interrupted: {done} of {runs} samples are in {store}; run the same command to resume", err=True)
    raise SystemExit(EXIT_INTERRUPTED) from None


def _stored(store) -> int:
    """Samples complete in the store (0 when it was not made yet or cannot be read)."""
    from auxbearing.campaign.store import completed

    try:
        return int(completed(store).sum())
    except Exception:
        return 0


def _print(out: dict, stats: dict) -> None:
    from rich.console import Console
    from rich.table import Table

    design = (f"saltelli on {out['base_samples']} base samples" if out["sampler"] == "saltelli"
              else out["sampler"])
    what = "runs" if out["sampler"] == "saltelli" else "samples"  # a Saltelli design runs N (D + 2) of them
    table = Table(title=f"Campaign {out['campaign']}: {out['completed']} of {out['samples']} {what} "
                        f"({design}, seed {out['seed']})")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    table.add_column("95 % interval", justify="right")
    table.add_row("runs ok / out of range / failed", f"{out['ok']} / {out['out_of_range']} / {out['failed']}", "")
    for key, label in (("p_backward_whirl", "P(backward whirl)"), ("p_out_of_range", "P(out of model range)"),
                       ("p_s0_below_required", f"P(s0 < {stats['required_s0']:g})")):
        p = stats[key]
        table.add_row(label, _shown(p["value"], "{:.3f}"), _interval(p["low"], p["high"], "{:.3f}"))
    stress = stats["quantiles"]["peak_ball_stress_MPa"]
    for tag in ("p50", "p95", "p99"):
        low, high = stress["interval"][tag]
        table.add_row(f"peak ball stress {tag} [MPa]", _shown(stress[tag], "{:.0f}"), _interval(low, high, "{:.0f}"))
    Console().print(table)
    for note in stats.get("notes", []):
        click.echo(f"note: {note}")
    if not out["ok"]:
        click.echo("No run ended ok, so there is nothing to estimate: the store's records say why each ended "
                   "(invalid_input: its reason)")
    rate = out["drops_per_second"]
    click.echo(f"{out['new']} new samples in {out['wall_time_s']:.1f} s"
               + (f" ({rate:.2f} drops/s on {out['workers']} workers)" if rate else "") + f"; store {out['store']}")


@click.command("campaign-report")
@click.argument("store", type=click.Path(path_type=Path))
@click.option("--out", "out_dir", type=click.Path(path_type=Path), required=True,
              callback=checked_out_dir, help="Folder for statistics (JSON, CSV) and figures.")
@click.option("--whirl-map", "whirl_map", nargs=2, default=None, metavar="KEY1 KEY2",
              help="The two inputs of the whirl map [default: the campaign's whirl_map, else its first two].")
@json_option()
def campaign_report_command(store, out_dir, whirl_map, as_json):
    """Statistics, sensitivity and figures of a campaign store (complete or not).

    Writes statistics.json, probabilities.csv (Wilson intervals), quantiles.csv (distribution-free
    intervals from the order statistics, an end left empty where too few runs bound it),
    sensitivity.csv (Sobol' indices for a complete saltelli design whose runs all ended ok, Spearman
    rank correlations otherwise), samples.csv and the figures histograms, scatter_matrix and whirl_map.
    """
    from auxbearing.campaign.statistics import headline
    from auxbearing.campaign.store import load_results
    from auxbearing.common.io import atomic_output_dir
    from auxbearing.report.campaign import whirl_map_keys, write_report

    ds = load_results(store)
    whirl_map_keys(ds, tuple(whirl_map) if whirl_map else None)  # a wrong key fails before anything is written
    with atomic_output_dir(out_dir) as tmp:
        stats = write_report(ds, tmp, tuple(whirl_map) if whirl_map else None)
    if as_json:
        echo_json({**headline(stats), "sensitivity": stats["sensitivity"], "out": str(out_dir)})
        return
    for note in stats.get("notes", []):
        click.echo(f"note: {note}")
    click.echo(f"{stats['completed']} of {stats['samples']} samples: P(backward whirl) = "
               f"{_shown(stats['p_backward_whirl']['value'], '{:.3f}')}; wrote statistics and figures in {out_dir}/")


def _shown(value, fmt: str) -> str:
    """A statistic as the table prints it: "-" where no run gave it (NaN or None), never "nan"."""
    import math

    return "-" if value is None or not math.isfinite(value) else fmt.format(value)


def _interval(low, high, fmt: str) -> str:
    """An interval as printed; an end too few runs can bound reads as one-sided ("≥ low"), both as "-"."""
    low_text, high_text = _shown(low, fmt), _shown(high, fmt)
    if "-" in (low_text, high_text):
        return {(True, False): f"≥ {low_text}", (False, True): f"≤ {high_text}"}.get(
            (low_text != "-", high_text != "-"), "-")
    return f"{low_text} - {high_text}"


COMMANDS = [campaign_command, campaign_report_command]
