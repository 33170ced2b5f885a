"""A campaign's report folder: statistics as JSON and CSV (units in the headers) and the figures.

Files: ``statistics.json`` (everything of :func:`~auxbearing.campaign.statistics.campaign_statistics`),
``probabilities.csv``, ``quantiles.csv``, ``sensitivity.csv``, ``samples.csv`` (one row per completed
sample: inputs in display units, verdict, outputs of the worst plane) and the figures
``histograms.png``, ``scatter_matrix.png``, ``whirl_map.png``.
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from auxbearing.campaign.statistics import QUANTILES, campaign_statistics, sample_outputs, verdict_masks
from auxbearing.common.errors import InputError

PROBABILITIES = ("p_backward_whirl", "p_backward_whirl_at_end", "p_out_of_range", "p_s0_below_required",
                 "p_s0_below_required_or_out_of_range")


def _write_csv(path: Path, header: list[str], rows: list[list]) -> None:
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        writer.writerows(rows)


def _csv_number(value) -> object:
    if value is None:
        return ""
    if isinstance(value, float):
        return "" if not np.isfinite(value) else f"{value:.6g}"
    return value


def whirl_map_keys(ds, keys: tuple[str, str] | None) -> tuple[str, str] | None:
    """The two inputs of the whirl map: those given, the campaign's ``whirl_map``, or its first two inputs."""
    inputs = [str(k) for k in ds["input"].values]
    chosen = keys or tuple(ds.attrs.get("whirl_map") or ()) or tuple(inputs[:2])
    if len(chosen) != 2:
        return None
    for key in chosen:
        if key not in inputs:
            raise InputError.for_field("--whirl-map", key, "not an input of this campaign; inputs: "
                                       + ", ".join(inputs))
    return chosen[0], chosen[1]


def write_report(ds, folder: Path, whirl_map: tuple[str, str] | None = None) -> dict:
    """Write the statistics and figures of a loaded campaign store into ``folder``; returns the statistics."""
    from auxbearing.common.io import save_figure, write_json
    from auxbearing.plots.campaign import plot_histograms, plot_scatter_matrix, plot_whirl_map

    keys = whirl_map_keys(ds, whirl_map)
    stats = campaign_statistics(ds)
    inputs = {"campaign": ds.attrs.get("campaign"), "store_created": ds.attrs.get("created")}
    write_json(stats, folder / "statistics.json", inputs)
    rows = [[name, *(_csv_number(stats[name][k]) for k in ("value", "low", "high")), stats[name]["successes"],
             stats[name]["trials"], stats[name]["among"]] for name in PROBABILITIES]
    for plane, entry in stats["planes"].items():
        p = entry["p_backward_whirl"]
        rows.append([f"p_backward_whirl [{plane}]", *(_csv_number(p[k]) for k in ("value", "low", "high")),
                     p["successes"], p["trials"], p["among"]])
    _write_csv(folder / "probabilities.csv", ["probability", "value [-]", "low 95% [-]", "high 95% [-]",
                                              "successes [-]", "trials [-]", "among"], rows)
    quantiles = stats["quantiles"]
    header = ["quantile [-]"]
    for name, entry in quantiles.items():
        base = name.removesuffix("_" + entry["unit"]) if entry["unit"] != "-" else name
        header += [f"{base} [{entry['unit']}]", f"{base} low 95% [{entry['unit']}]",
                   f"{base} high 95% [{entry['unit']}]"]
    rows = []
    for p in QUANTILES:
        tag = f"p{round(100 * p)}"
        row = [p]
        for entry in quantiles.values():
            row += [_csv_number(entry[tag]), *(_csv_number(v) for v in entry["interval"][tag])]
        rows.append(row)
    _write_csv(folder / "quantiles.csv", header, rows)
    sens = stats["sensitivity"]
    fields = ("S1", "S1_conf", "ST", "ST_conf") if sens["method"] == "sobol" else ("rho", "p_value")
    names = [str(k) for k in ds["input"].values]
    header = ["input"] + [f"{field} {output} [-]" for output in sens["outputs"] for field in fields]
    rows = [[name] + [_csv_number(sens["outputs"][output].get(name, {}).get(field)) for output in sens["outputs"]
                      for field in fields] for name in names]
    _write_csv(folder / "sensitivity.csv", header, rows)
    _samples_csv(ds, folder / "samples.csv")
    save_figure(plot_histograms(ds), folder / "histograms")
    save_figure(plot_scatter_matrix(ds), folder / "scatter_matrix")
    if keys is not None:
        save_figure(plot_whirl_map(ds, *keys), folder / "whirl_map")
    return stats


def _samples_csv(ds, path: Path) -> None:
    masks = verdict_masks(ds)
    done = np.nonzero(masks["completed"])[0]
    outputs = sample_outputs(ds)
    header = ["sample"]
    columns = []
    for j, key in enumerate(ds["input"].values):
        unit = str(ds["input_display_unit"].values[j]) or "-"
        header.append(f"{key} [{unit}]")
        columns.append(ds["value"].values[:, j] * float(ds["input_display_scale"].values[j]))
    header += ["verdict"] + [f"{name} [{unit}]" for name, (_, unit) in outputs.items()] + ["sample_time [s]"]
    times = ds["sample_time"].values
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        for i in done:
            writer.writerow([int(i), *(_csv_number(float(c[i])) for c in columns), masks["names"][i],
                             *(_csv_number(float(v[i])) for v, _ in outputs.values()), _csv_number(float(times[i]))])
