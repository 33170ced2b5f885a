"""A campaign's report folder: statistics as JSON and CSV (units in the headers) and the figures.

Files: ``statistics.json`` (everything of :func:`~auxbearing.campaign.statistics.campaign_statistics`),
``probabilities.csv``, ``quantiles.csv``, ``sensitivity.csv``, ``samples.csv`` (one row per completed
sample: inputs in display units, verdict, outputs of the worst plane), the figures
``histograms.png``, ``scatter_matrix.png``, ``whirl_map.png``, and ``report.html``: the page to read, in
words (probabilities with their 95 % intervals, outcomes' quantiles, what drives them, the figures).
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from auxbearing.campaign.statistics import QUANTILES, campaign_statistics, sample_outputs, verdict_masks
from auxbearing.campaign.store import input_display
from auxbearing.common.errors import InputError

#: Parameters of a distribution that are differences of the input, shown without a unit's offset.
SPREADS = ("std",)

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
    if chosen[0] == chosen[1]:  # a map of one input against itself is a line, as the campaign file is told
        raise InputError.for_field("--whirl-map", " ".join(chosen), "give two different inputs")
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
    figures = [(plot_histograms(ds), "histograms", "Distributions of the outcomes over the runs that ended ok."),
               (plot_scatter_matrix(ds), "scatter_matrix", "Every sample's outcomes against its inputs.")]
    whirled = bool(np.nansum(ds["backward_whirl"].values) > 0)
    if keys is not None and whirled:
        figures.append((plot_whirl_map(ds, *keys), "whirl_map",
                        f"Probability of backward whirl over {_label(keys[0])} and {_label(keys[1])}, with every "
                        "sample's whirl class (ringed: sustained backward whirl at some time)."))
    elif keys is not None:
        save_figure(plot_whirl_map(ds, *keys), folder / "whirl_map")
    for fig, name, _ in figures:
        save_figure(fig, folder / name)
    note = None if whirled else "No drop of the campaign whirled backward, so the whirl map has nothing to show."
    (folder / "report.html").write_text(_page(ds, stats, figures, note), encoding="utf-8")
    return stats


#: Words for the statistics' keys (the page reads in an engineer's words, the files keep the keys).
_WORDS = {
    "p_backward_whirl": "Sustained backward whirl at some time", "p_backward_whirl_at_end": "Backward whirl at the end",
    "p_out_of_range": "Run left the model's range", "p_s0_below_required": "s0 below the required value",
    "p_s0_below_required_or_out_of_range": "s0 below required, or out of range",
    "peak_ball_stress_MPa": "Peak ball contact stress", "peak_contact_force_N": "Peak journal/race collision force",
    "s0_min": "Smallest static safety factor s0", "max_temperature_C": "Hottest bearing part",
    "damage_per_drop": "Fatigue damage per drop", "allowed_drops_min": "Drops allowed (fewest over the planes)",
    "coastdown_time_s": "Coast-down to standstill",
}


def _label(key: str) -> str:
    """An input's or outcome's name as a person reads it.

    ``touchdown.0.sliding_friction`` reads "sliding friction (touchdown 0)"; outcomes by :data:`_WORDS`.
    """
    if key in _WORDS:
        return _WORDS[key]
    parts = key.split(".")
    words = parts[-1].replace("_", " ")
    where = " ".join(parts[:-1])
    return f"{words} ({where})" if where else words


def _page(ds, stats: dict, figures: list, note: str | None) -> str:
    """The campaign's report page (self-contained HTML, figures embedded)."""
    from auxbearing.common.io import loads
    from auxbearing.report.html import _CSS, _e, _table, figure_png_base64

    try:  # the store writes an infinity "inf": json.loads would leave it a string, not the number
        described = loads(ds.attrs.get("campaign") or "{}")
    except (TypeError, ValueError):
        described = {}
    machine = ((described.get("tables") or {}).get("machine") or {}).get("name")
    name = f"{machine}: {described.get('name', 'campaign')}" if machine else described.get("name", "campaign")
    counts = (f"{stats['samples']} samples, {stats['completed']} completed: {stats['ok']} ended ok, "
              f"{stats['out_of_range']} left the model's range, {stats['failed']} failed otherwise.")
    parts = [f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>Campaign {_e(name)}</title>"
             f"<style>{_CSS}</style></head><body><h1>Campaign {_e(name)}</h1><p>{_e(counts)}</p>"]
    rows = []
    for j, spec in enumerate(described.get("inputs") or []):
        unit, scale, offset = input_display(ds, j) if "input_unit" in ds.coords else ("", 1.0, 0.0)
        numbers = {k: v for k, v in spec.items() if isinstance(v, (int, float)) and k not in ("key",)}
        # a spread (std) is a difference, with no offset: 5 K of spread is 5 degC of it
        shown = ", ".join(f"{k} {v * scale + (0.0 if k in SPREADS else offset):.4g}{' ' + unit if unit else ''}"
                          for k, v in numbers.items())
        rows.append([_label(spec.get("key", "?")), spec.get("distribution", "?"), shown])
    if rows:
        parts.append("<h2>Inputs varied</h2>" + _table(["input", "distribution", "parameters"], rows))
    rows = []
    for key in PROBABILITIES:
        p = stats[key]
        rows.append([_label(key), _percent(p["value"]), f"{_percent(p['low'])} to {_percent(p['high'])}",
                     f"{p['successes']} of {p['trials']} ({p['among']})"])
    for plane, entry in stats["planes"].items():
        p = entry["p_backward_whirl"]
        rows.append([f"Sustained backward whirl at {plane}", _percent(p["value"]),
                     f"{_percent(p['low'])} to {_percent(p['high'])}", f"{p['successes']} of {p['trials']}"])
    parts.append("<h2>Probabilities</h2>" + _table(["event", "estimate", "95 % interval (Wilson)", "counted"],
                                                    rows)
                 + "".join(f"<p>{_e(note)}</p>" for note in stats.get("notes", [])))
    rows = []
    for key, entry in stats["quantiles"].items():
        if entry["n"] == 0:
            continue
        unit = "" if entry["unit"] in ("-", "") else f" {entry['unit']}"
        rows.append([_label(key), *(f"{entry[t]:.4g}{unit}" for t in ("p50", "p95")),
                     f"{entry['max']:.4g}{unit}", entry["n"]])
    parts.append("<h2>Outcomes</h2>" + (_table(["outcome", "median", "95th percentile", "largest", "runs"], rows)
                                         if rows else "<p>No run ended ok: no outcome to summarise.</p>"))
    sens = stats["sensitivity"]
    if sens.get("method"):
        field = "ST" if sens["method"] == "sobol" else "rho"
        what = ("total Sobol' index" if field == "ST" else "Spearman rank correlation")
        outputs = [o for o in sens["outputs"] if any(v.get(field) is not None and np.isfinite(v.get(field))
                                                     for v in sens["outputs"][o].values())]
        inputs = [str(k) for k in ds["input"].values]
        rows = [[_label(i), *(_number(sens["outputs"][o].get(i, {}).get(field)) for o in outputs)] for i in inputs]
        parts.append(f"<h2>What drives the outcomes ({what})</h2>"
                     + (_table(["input", *(_label(o) for o in outputs)], rows) if outputs else
                        "<p>No outcome varied enough over the runs to rank its drivers.</p>")
                     + (f"<p>{_e(sens['note'])}</p>" if sens.get("note") else ""))
    else:
        parts.append(f"<h2>What drives the outcomes</h2><p>{_e(sens.get('note', 'not computed'))}</p>")
    parts.append("<h2>Figures</h2>")
    if note:
        parts.append(f"<p>{_e(note)}</p>")
    for fig, _, caption in figures:
        parts.append(f"<figure><img alt='{_e(caption)}' src='data:image/png;base64,{figure_png_base64(fig)}'>"
                     f"<figcaption>{_e(caption)}</figcaption></figure>")
    parts.append("<p class='small'>The numbers behind this page: statistics.json and the CSV files beside it "
                 "(units in their headers).</p></body></html>")
    return "".join(parts)


def _percent(value) -> str:
    return "-" if value is None or not np.isfinite(value) else f"{100.0 * value:.1f} %"


def _number(value) -> str:
    return "n/a" if value is None or not np.isfinite(value) else f"{value:+.2f}"


def _samples_csv(ds, path: Path) -> None:
    masks = verdict_masks(ds)
    done = np.nonzero(masks["completed"])[0]
    outputs = sample_outputs(ds)
    header = ["sample"]
    columns = []
    for j, key in enumerate(ds["input"].values):
        unit, scale, offset = input_display(ds, j)
        header.append(f"{key} [{unit or '-'}]")
        columns.append(ds["value"].values[:, j] * scale + offset)
    header += ["verdict"] + [f"{name} [{unit}]" for name, (_, unit) in outputs.items()] + ["sample_time [s]"]
    times = ds["sample_time"].values
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        for i in done:
            writer.writerow([int(i), *(_csv_number(float(c[i])) for c in columns), masks["names"][i],
                             *(_csv_number(float(v[i])) for v, _ in outputs.values()), _csv_number(float(times[i]))])
