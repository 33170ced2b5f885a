"""Figures of a drop campaign: output histograms, an input scatter matrix by whirl class, a whirl map.

Each function takes the store of a campaign read into memory
(:func:`auxbearing.campaign.store.load_results`). A one-panel function takes ``ax=None``, a
multi-panel one ``fig=None``; either returns a :class:`matplotlib.figure.Figure` and touches no
global state (no pyplot). Inputs are drawn in their display units (the store's
``input_display_unit``); outputs only from runs that ended ``ok``.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.figure import Figure

#: Colours of the whirl classes (as in the drop figures) and of runs without a valid result.
WHIRL_COLOURS = {"none": "0.6", "forward": "tab:green", "backward_rolling": "tab:orange", "dry_whip": "tab:red",
                 "backward": "tab:purple"}
NOT_OK_COLOUR = "black"
#: Order in which a sample's planes are summed up into one class: the most severe plane wins.
SEVERITY = ("none", "forward", "backward_rolling", "backward", "dry_whip")
#: ISO 76 reference stress for ball bearings [MPa] (s0 = 1); drawn on the stress histogram.
ISO76_BALL_STRESS_MPA = 4200.0
#: The ISO 76 line is drawn when the largest stress reaches this fraction of it.
NEAR_REFERENCE = 0.6
#: Runs per cell the whirl map aims at when it chooses its bins.
RUNS_PER_BIN = 10
#: Most inputs a scatter matrix shows (beyond this the panels become unreadable).
MAX_MATRIX_INPUTS = 6


def _axes(ax, size=(6, 4)):
    if ax is not None:
        return ax.figure, ax
    fig = Figure(figsize=size, layout="constrained")
    return fig, fig.add_subplot()


def sample_classes(ds) -> np.ndarray:
    """The whirl class of each sample: its most severe plane's final class ("" when it has no ok run)."""
    from auxbearing.campaign.statistics import verdict_masks

    codes = list(ds.attrs["whirl_classes"])
    names = np.array(codes, dtype=object)[ds["whirl"].values.astype(int)]  # (sample, plane)
    rank = np.vectorize(lambda c: SEVERITY.index(c) if c in SEVERITY else -1, otypes=[int])(names)
    worst = names[np.arange(names.shape[0]), rank.argmax(axis=1)]
    worst[~verdict_masks(ds)["ok"]] = ""
    return worst


def _input(ds, key: str) -> tuple[np.ndarray, str]:
    """Values of an input in its display unit, and an axis label."""
    from auxbearing.campaign.store import input_display

    j = [str(k) for k in ds["input"].values].index(key)
    unit, scale, offset = input_display(ds, j)
    return ds["value"].values[:, j] * scale + offset, f"{key} [{unit or '-'}]"


def plot_histograms(ds, fig=None) -> Figure:
    """Histograms of peak ball stress, peak collision force, smallest s0 (and coast-down outputs), verdicts."""
    from auxbearing.campaign.statistics import sample_outputs, verdict_masks

    masks = verdict_masks(ds)
    outputs = {k: v for k, v in sample_outputs(ds).items() if k != "backward_whirl"}
    panels = len(outputs) + 1
    cols = min(3, panels)
    rows = math.ceil(panels / cols)
    fig = fig or Figure(figsize=(4.2 * cols, 3.2 * rows), layout="constrained")
    axes = fig.subplots(rows, cols, squeeze=False).ravel()
    for ax, (name, (values, unit)) in zip(axes, outputs.items(), strict=False):
        x = values[masks["ok"]]
        x = x[np.isfinite(x)]
        if x.size:
            ax.hist(x, bins=min(40, max(5, int(math.sqrt(x.size)))), color="tab:blue", alpha=0.8)
        if name == "peak_ball_stress_MPa" and x.size:
            # the reference is drawn only when it is near the data, so it does not squash the histogram
            if x.max() >= NEAR_REFERENCE * ISO76_BALL_STRESS_MPA:
                ax.axvline(ISO76_BALL_STRESS_MPA, color="tab:red", ls="--", lw=1, label="ISO 76 (s0 = 1)")
                ax.legend(fontsize=7)
            else:
                ax.set_title(f"all below {NEAR_REFERENCE:g} x ISO 76's {ISO76_BALL_STRESS_MPA:.0f} MPa", fontsize=8)
        ax.set_xlabel(f"{name.removesuffix('_' + unit)} [{unit}]")
        ax.set_ylabel("runs")
    verdict_ax = axes[len(outputs)]
    names = masks["names"][masks["completed"]]
    labels, counts = np.unique(names.astype(str), return_counts=True) if names.size else ([], [])
    verdict_ax.barh(list(labels), list(counts), color=["tab:green" if v == "ok" else "tab:red" for v in labels])
    verdict_ax.set_xlabel("samples")
    verdict_ax.set_title("verdicts", fontsize=9)
    for ax in axes[panels:]:
        ax.set_visible(False)
    fig.suptitle(f"{ds.attrs.get('title', 'Campaign')}: {int(masks['ok'].sum())} ok of "
                 f"{int(masks['completed'].sum())} completed")
    return fig


def _scatter_classes(ax, x, y, classes, size=8) -> None:
    for name, colour in WHIRL_COLOURS.items():
        sel = classes == name
        if sel.any():
            ax.scatter(x[sel], y[sel], s=size, color=colour, label=name, linewidths=0)
    sel = classes == ""
    if sel.any():
        ax.scatter(x[sel], y[sel], s=size + 6, color=NOT_OK_COLOUR, marker="x", linewidths=0.8,
                   label="not ok (out of range or failed)")


def _strongest_inputs(ds) -> list[str]:
    from auxbearing.campaign.statistics import rank_correlations, verdict_masks

    names = [str(k) for k in ds["input"].values]
    ok = verdict_masks(ds)["ok"]
    if len(names) <= MAX_MATRIX_INPUTS or ok.sum() < 3:
        return names
    rho = rank_correlations(ds["value"].values[ok], ds["backward_whirl"].max("plane").values[ok], names)
    strength = {k: abs(v["rho"]) if np.isfinite(v["rho"]) else -1.0 for k, v in rho.items()}
    chosen = sorted(names, key=lambda k: -strength[k])[:MAX_MATRIX_INPUTS]
    return [k for k in names if k in chosen]


def plot_scatter_matrix(ds, keys=None, fig=None) -> Figure:
    """Pairs of inputs, each sample coloured by its whirl class; histograms of the inputs on the diagonal.

    Without ``keys``, a campaign of more than :data:`MAX_MATRIX_INPUTS` inputs shows those whose rank
    correlation with backward whirl is strongest.
    """
    done = ds["completed"].values.astype(bool)
    keys = list(keys or _strongest_inputs(ds))[:MAX_MATRIX_INPUTS]
    classes = sample_classes(ds)[done]
    columns = [_input(ds, k) for k in keys]
    n = len(keys)
    fig = fig or Figure(figsize=(2.4 * n + 1.5, 2.4 * n), layout="constrained")
    axes = fig.subplots(n, n, squeeze=False)
    for i in range(n):
        for j in range(n):
            ax = axes[i, j]
            yi, ylabel = columns[i]
            xj, xlabel = columns[j]
            if i == j:
                ax.hist(xj[done], bins=20, color="0.6")
            else:
                _scatter_classes(ax, xj[done], yi[done], classes, size=5)
            if i == n - 1:
                ax.set_xlabel(xlabel, fontsize=7)
            if j == 0:
                ax.set_ylabel(ylabel if i != j else "samples", fontsize=7)
            ax.tick_params(labelsize=6)
    handles, labels = [], []
    for ax in axes.ravel():
        for h, label in zip(*ax.get_legend_handles_labels(), strict=True):
            if label not in labels:
                handles.append(h)
                labels.append(label)
    if handles:
        fig.legend(handles, labels, loc="outside right center", fontsize=7, title="whirl at the end")
    fig.suptitle("Inputs coloured by whirl class (most severe plane)")
    return fig


def plot_whirl_map(ds, x_key: str, y_key: str, ax=None, bins: int | None = None) -> Figure:
    """Probability of backward whirl over two inputs (binned, ok runs) with every sample's whirl class.

    ``bins`` per axis default to about :data:`RUNS_PER_BIN` runs per cell. Samples that had sustained
    backward whirl at some time are ringed in black, whatever their class at the end.
    """
    fig, ax = _axes(ax, (6.5, 5))
    from auxbearing.campaign.statistics import verdict_masks

    keys = [str(k) for k in ds["input"].values]
    for key in (x_key, y_key):
        if key not in keys:
            from auxbearing.common.errors import InputError

            raise InputError.for_field("--whirl-map", key, "not an input of this campaign; inputs: " + ", ".join(keys))
    x, xlabel = _input(ds, x_key)
    y, ylabel = _input(ds, y_key)
    masks = verdict_masks(ds)
    ok, done = masks["ok"], masks["completed"]
    flag = ds["backward_whirl"].max("plane").values
    bins = bins or int(np.clip(round(math.sqrt(ok.sum() / RUNS_PER_BIN)), 2, 12))
    if ok.sum() >= 1 and np.ptp(x[ok]) > 0 and np.ptp(y[ok]) > 0:
        edges = (np.linspace(x[ok].min(), x[ok].max(), bins + 1), np.linspace(y[ok].min(), y[ok].max(), bins + 1))
        hits, *_ = np.histogram2d(x[ok], y[ok], bins=edges, weights=(flag[ok] > 0.5).astype(float))
        total, *_ = np.histogram2d(x[ok], y[ok], bins=edges)
        with np.errstate(invalid="ignore", divide="ignore"):
            share = np.where(total > 0, hits / total, np.nan)
        mesh = ax.pcolormesh(edges[0], edges[1], share.T, cmap="Purples", vmin=0.0, vmax=1.0, alpha=0.6)
        fig.colorbar(mesh, ax=ax, label="share of runs with backward whirl")
    ringed = ok & (flag > 0.5)
    if ringed.any():
        ax.scatter(x[ringed], y[ringed], s=40, facecolors="none", edgecolors="black", linewidths=0.7,
                   label="sustained backward whirl at some time")
    _scatter_classes(ax, x[done], y[done], sample_classes(ds)[done], size=10)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if ax.get_legend_handles_labels()[0]:  # no sample with a whirl class (none closed a window): no legend
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=3, title="whirl at the end",
                  title_fontsize=7)
    ax.set_title("Backward whirl over two inputs")
    return fig


__all__ = ["plot_histograms", "plot_scatter_matrix", "plot_whirl_map", "sample_classes"]
