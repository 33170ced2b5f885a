"""Statistics of a campaign: probabilities, quantiles and global sensitivity.

Probabilities carry Wilson score intervals, quantiles distribution-free intervals from their order statistics;
sensitivity is given as Sobol' indices through SALib on a Saltelli design, Spearman rank correlations otherwise.

A Saltelli design's rows are not independent draws: of each block of D + 2 rows (2 D + 2 with second order) only
the first (A) and the last (B) are; the D rows between repeat all of A's inputs but one. Probabilities, quantiles
and rank correlations are taken over the A and B rows alone (:func:`independent_rows`), 2 N draws; counted over
every row, one drop condition weighed up to D + 1 times and a "95 %" Wilson interval held the truth 59 % of the
time.

Backward whirl counts when a plane whirls backward at the end or had sustained backward whirl at some
time (:mod:`auxbearing.analysis.whirl`); ``p_backward_whirl_at_end`` counts the first kind only.

Which runs count: a probability of a drop outcome (backward whirl, s0 below the required value) is
taken over the runs that ended ``ok``, since a run stopped outside the model's range has no valid
peaks; how often runs leave the range is its own probability over every completed sample; a
combined "s0 below required or out of range" is given too, since a run stopped for overload
would have failed the s0 check.
"""

from __future__ import annotations

import math

import numpy as np

#: Confidence level of every interval unless told otherwise.
CONFIDENCE = 0.95
#: Bootstrap resamples of the Sobol' index bounds (SALib's default).
SOBOL_RESAMPLES = 100
QUANTILES = (0.5, 0.95, 0.99)


def wilson_interval(successes: int, trials: int, confidence: float = CONFIDENCE) -> tuple[float, float, float]:
    """Proportion and its Wilson score interval, through ``scipy.stats.binomtest``.

    Wilson, JASA 22 (1927) 209-212; Newcombe, Stat. Med. 17 (1998) 857-872, method 3: the p whose
    score test does not reject at that level. With no trials the interval is the whole [0, 1].

    Parameters
    ----------
    successes : int
        Count k [-].
    trials : int
        Count n [-].
    confidence : float
        Two-sided confidence level [-].

    Returns
    -------
    tuple of float
        (k/n, low, high) [-].

    Examples
    --------
    >>> [round(v, 4) for v in wilson_interval(81, 263)]
    [0.308, 0.2553, 0.3662]
    >>> [round(v, 4) for v in wilson_interval(0, 20)]
    [0.0, 0.0, 0.1611]
    """
    from scipy.stats import binomtest

    if trials <= 0:
        return math.nan, 0.0, 1.0
    interval = binomtest(int(successes), int(trials)).proportion_ci(confidence, method="wilson")
    return successes / trials, float(interval.low), float(interval.high)


def quantile_intervals(values, probabilities=QUANTILES,
                       confidence: float = CONFIDENCE) -> dict[float, tuple[float, float, float]]:
    """Sample quantiles with distribution-free confidence intervals from the order statistics.

    The count of values below the true p-quantile is binomial(n, p), so the interval between the order statistics
    of ranks l and u covers it with probability P(l <= B < u) whatever the distribution (Conover, Practical
    Nonparametric Statistics, 3rd ed., 1999, Sec. 3.2; Hahn & Meeker, Statistical Intervals, 1991, Sec. 5.2);
    the ranks come from ``scipy.stats.quantile_test``, each end at the two-sided level's half. Too few values to
    reach the level on a side leave that end NaN, not the sample's extreme: 16 values bound the 95th percentile
    from below only, and one value bounds nothing. (A percentile bootstrap, used before, gave the 99th percentile
    of 16 values an interval that held the truth 14 % of the time.) The quantile itself is numpy's default
    (Hyndman & Fan 1996, definition 7).

    Returns
    -------
    dict
        probability -> (quantile, low, high), NaN when there are no values.

    Examples
    --------
    >>> q = quantile_intervals(np.arange(1001.0), (0.5,))[0.5]
    >>> q[0], q[1] < 500.0 < q[2]
    (500.0, True)
    >>> quantile_intervals([1.0, 2.0], (0.99,))[0.99][2]
    nan
    """
    from scipy.stats import quantile_test

    x = np.asarray(values, dtype=float)
    x = np.sort(x[np.isfinite(x)])
    out = {}
    for p in probabilities:
        if x.size == 0:
            out[float(p)] = (math.nan, math.nan, math.nan)
            continue
        interval = quantile_test(x, q=float(np.quantile(x, p)), p=float(p)).confidence_interval(confidence)
        out[float(p)] = (float(np.quantile(x, p)), float(interval.low), float(interval.high))
    return out


def sobol_indices(y, names, second_order: bool = False, confidence: float = CONFIDENCE,
                  seed: int = 0) -> dict[str, dict[str, float]]:
    """First-order and total Sobol' indices from the outputs of a Saltelli design, through SALib.

    SALib's estimators are those of Saltelli et al., Comput. Phys. Commun. 181 (2010) 259-270 (Table 2:
    S1 by (b), ST by Jansen's (f)); confidence bounds by bootstrap. The indices depend only on the
    outputs and the order of the design rows (A, A_B^(i), ..., B), not on the input values, so the
    design may be on the unit hypercube.

    Returns
    -------
    dict
        input name -> {"S1", "S1_conf", "ST", "ST_conf"} [-] (conf: half-width of the interval).
    """
    from SALib.analyze import sobol

    problem = {"num_vars": len(names), "names": list(names), "bounds": [[0.0, 1.0]] * len(names)}
    result = sobol.analyze(problem, np.asarray(y, dtype=float), calc_second_order=second_order,
                           conf_level=confidence, num_resamples=SOBOL_RESAMPLES, seed=seed)
    return {name: {key: float(result[key][j]) for key in ("S1", "S1_conf", "ST", "ST_conf")}
            for j, name in enumerate(names)}


def rank_correlations(inputs, y, names) -> dict[str, dict[str, float]]:
    """Spearman's rank correlation of the output with each input, and its p-value (scipy.stats.spearmanr).

    Returns NaN for an input or output that does not vary.
    """
    from scipy.stats import spearmanr

    x = np.asarray(inputs, dtype=float)
    y = np.asarray(y, dtype=float)
    out = {}
    for j, name in enumerate(names):
        if x.shape[0] < 3 or np.ptp(x[:, j]) == 0.0 or np.ptp(y) == 0.0:
            out[name] = {"rho": math.nan, "p_value": math.nan}
            continue
        rho, p = spearmanr(x[:, j], y)
        out[name] = {"rho": float(rho), "p_value": float(p)}
    return out


def _probability(successes: int, trials: int, among: str) -> dict:
    value, low, high = wilson_interval(successes, trials)
    return {"value": value, "low": low, "high": high, "successes": int(successes), "trials": int(trials),
            "among": among, "confidence": CONFIDENCE}


def _quantile_entry(values, unit: str) -> dict:
    x = np.asarray(values, dtype=float)
    x = x[np.isfinite(x)]
    q = quantile_intervals(x)
    entry = {"unit": unit, "n": int(x.size), "mean": float(x.mean()) if x.size else math.nan,
             "max": float(x.max()) if x.size else math.nan}
    for p, (value, _, _) in q.items():
        entry[f"p{round(100 * p)}"] = value
    entry["interval"] = {f"p{round(100 * p)}": [low, high] for p, (_, low, high) in q.items()}
    return entry


def sample_outputs(ds) -> dict[str, tuple[np.ndarray, str]]:
    """Per-sample outputs over all planes (worst plane): name -> (values, unit)."""
    planes = {"peak_ball_stress_MPa": (ds["peak_ball_stress"].max("plane", skipna=False).values / 1e6, "MPa"),
              "peak_contact_force_N": (ds["peak_contact_force"].max("plane", skipna=False).values, "N"),
              "s0_min": (ds["s0"].min("plane", skipna=False).values, "-"),
              "backward_whirl": (ds["backward_whirl"].max("plane", skipna=False).values, "-")}
    if "max_excursion" in ds:  # stores made before it was recorded lack it
        planes["max_excursion_mm"] = (ds["max_excursion"].max("plane", skipna=False).values * 1e3, "mm")
    if "max_bearing_excursion" in ds and np.isfinite(ds["max_bearing_excursion"].values).any():  # machines with AMBs
        planes["max_bearing_excursion_mm"] = (ds["max_bearing_excursion"].values * 1e3, "mm")
    if "max_temperature" in ds:
        planes["max_temperature_C"] = (ds["max_temperature"].max("plane", skipna=False).values, "degC")
        planes["damage_per_drop"] = (ds["damage_per_drop"].max("plane", skipna=False).values, "-")
        planes["allowed_drops_min"] = (ds["allowed_drops"].min("plane", skipna=False).values, "-")
        planes["coastdown_time_s"] = (ds["coastdown_time"].values, "s")
    return planes


def _largest(values, ok: np.ndarray) -> float | None:
    """The largest of ``values`` over the runs that ended ok, or None (no such runs, no values, no array)."""
    if values is None or not ok.any() or not np.isfinite(values[ok]).any():
        return None
    return float(np.nanmax(values[ok]))


def verdict_masks(ds) -> dict[str, np.ndarray]:
    """Boolean per sample: completed, ok, out_of_range, coastdown_limit, failed (and the verdict names)."""
    verdicts = list(ds.attrs["verdicts"])
    names = np.array(verdicts, dtype=object)[ds["verdict"].values.astype(int)]
    done = ds["completed"].values.astype(bool)
    ok = done & (names == "ok")
    out_of_range = done & np.isin(names, ds.attrs["out_of_range_verdicts"])
    limit = done & np.isin(names, ds.attrs.get("coastdown_limit_verdicts", []))
    return {"completed": done, "ok": ok, "out_of_range": out_of_range, "coastdown_limit": limit,
            "failed": done & ~ok & ~out_of_range & ~limit, "names": names}


def _sensitivity(ds, masks: dict, outputs: dict, independent: np.ndarray) -> dict:
    names = [str(k) for k in ds["input"].values]
    saltelli = ds.attrs.get("sampler") == "saltelli"
    result: dict = {"method": "spearman", "outputs": {}, "note": None}
    keys = list(outputs)
    if saltelli and masks["ok"].all():
        result["method"] = "sobol"
        for key in keys:
            y = outputs[key][0]
            if np.all(np.isfinite(y)) and np.ptp(y) > 0.0:
                result["outputs"][key] = sobol_indices(y, names, bool(ds.attrs.get("second_order", 0)))
        result["note"] = _sobol_note(result["outputs"], int(ds.attrs.get("samples", 0)))
        return result
    if saltelli:
        result["note"] = (f"Sobol' indices need every run of the Saltelli design to end ok; "
                          f"{int((masks['completed'] & ~masks['ok']).sum())} did not and "
                          f"{int((~masks['completed']).sum())} have not run, so rank correlations over the "
                          "independent runs that ended ok instead")
    use = masks["ok"] & independent
    for key in keys:
        y = outputs[key][0][use]
        keep = np.isfinite(y)
        result["outputs"][key] = rank_correlations(ds["value"].values[use][keep], y[keep], names)
    return result


def _backward_at_end(ds) -> np.ndarray:
    """Per sample: some plane's whirl class at the end is a backward one."""
    from auxbearing.campaign.evaluate import BACKWARD_CLASSES

    names = np.array(ds.attrs["whirl_classes"], dtype=object)[ds["whirl"].values.astype(int)]
    return np.isin(names, BACKWARD_CLASSES).any(axis=1)


def _required_source(required: float, given: bool) -> str:
    from auxbearing.campaign.config import DEFAULT_REQUIRED_S0

    if given:
        return "given to the report"
    if required == DEFAULT_REQUIRED_S0:
        return ("default: s0 = 1 is where the peak ball stress reaches ISO 76's 4200 MPa reference "
                "(a permanent set of 1e-4 of the ball diameter)")
    return "campaign.required_s0"


def independent_rows(ds) -> np.ndarray:
    """Per run, whether it is an independent draw of the inputs: every run, or a Saltelli design's A and B rows.

    SALib lays a Saltelli design out in blocks of D + 2 rows (2 D + 2 with second order), A first and B last
    (Saltelli et al. 2010, Sec. 3; SALib.sample.sobol); the rows between take A's inputs with one (or, second
    order, all but one) from B, so they draw nothing new.
    """
    runs = int(ds.sizes["sample"])
    if ds.attrs.get("sampler") != "saltelli":
        return np.ones(runs, dtype=bool)
    d = int(ds.sizes["input"])
    block = (2 * d + 2) if int(ds.attrs.get("second_order", 0)) else (d + 2)
    where = np.arange(runs) % block
    return (where == 0) | (where == block - 1)


#: Sobol' indices are shares of a variance, so an estimate outside [0, 1] by more than this, or one whose 95 %
#: half-width exceeds it, tells of too few base samples (:func:`_sobol_note`).
SOBOL_SCATTER = 0.1


def _sobol_note(indices: dict[str, dict], base: int) -> str | None:
    """A note on the outputs whose Sobol' estimates are too scattered to read (None: all are usable)."""
    loose = []
    for output, values in indices.items():
        if any(v[key] < -SOBOL_SCATTER or v[key] > 1.0 + SOBOL_SCATTER or v[key + "_conf"] > SOBOL_SCATTER
               for v in values.values() for key in ("S1", "ST")):
            loose.append(output)
    if not loose:
        return None
    return (f"with N = {base} base samples the Sobol' indices of {', '.join(loose)} are too scattered to read "
            f"(an estimate outside [0, 1] or a 95 % half-width above {SOBOL_SCATTER:g}): take them as indications "
            "only, or run more base samples (512 or more is usual)")


def campaign_statistics(ds, required_s0: float | None = None, seed: int = 0) -> dict:
    """Counts, probabilities, quantiles, per-plane figures and sensitivity of a loaded campaign store.

    Counts are over every run; probabilities, quantiles and rank correlations over the independent ones
    (:func:`independent_rows`). Whirl is counted over the runs whose whirl was classified: a drop shorter than one
    whirl window closed none, and whether it whirled is unknown.
    """
    masks = verdict_masks(ds)
    required = float(ds.attrs.get("required_s0", 1.0)) if required_s0 is None else float(required_s0)
    outputs = sample_outputs(ds)
    independent = independent_rows(ds)
    ok, done, oor = masks["ok"], masks["completed"], masks["out_of_range"]
    use, done_use, oor_use = ok & independent, done & independent, oor & independent
    whirl = outputs["backward_whirl"][0]
    classified = use & np.isfinite(whirl)
    among = "runs that ended ok" + ("" if classified.sum() == use.sum() else " with their whirl classified")
    s0 = outputs["s0_min"][0]
    counts = {v: int((masks["names"][done] == v).sum()) for v in ds.attrs["verdicts"][1:]}
    stats = {
        "samples": int(ds.sizes["sample"]), "completed": int(done.sum()), "ok": int(ok.sum()),
        "failed": int(masks["failed"].sum()), "out_of_range": int(oor.sum()),
        "verdicts": {k: v for k, v in counts.items() if v},
        "independent_runs": int(done_use.sum()),
        "whirl_unclassified": int((use & ~np.isfinite(whirl)).sum()),
        "p_backward_whirl": _probability(int((whirl[classified] > 0.5).sum()), int(classified.sum()), among),
        "p_backward_whirl_at_end": _probability(int(_backward_at_end(ds)[classified].sum()), int(classified.sum()),
                                                among),
        "p_out_of_range": _probability(int(oor_use.sum()), int(done_use.sum()), "completed samples"),
        "coastdown_limit": int(masks["coastdown_limit"].sum()),
        "p_s0_below_required": _probability(int((s0[use] < required).sum()), int(use.sum()), "runs that ended ok"),
        "p_s0_below_required_or_out_of_range": _probability(int((s0[use] < required).sum() + oor_use.sum()),
                                                            int(use.sum() + oor_use.sum()),
                                                            "runs that ended ok or left the model's range"),
        "required_s0": required,
        "required_s0_source": _required_source(required, required_s0 is not None),
        "smallest_s0": float(np.nanmin(s0[ok])) if ok.any() and np.isfinite(s0[ok]).any() else None,
        "largest_excursion_mm": _largest(outputs.get("max_excursion_mm", (None,))[0], ok),
        "largest_bearing_excursion_mm": _largest(outputs.get("max_bearing_excursion_mm", (None,))[0], ok),
        "quantiles": {},
        "planes": {},
        "notes": [],
    }
    if not independent.all():
        stats["notes"].append(
            f"probabilities and quantiles over the Saltelli design's {int(done_use.sum())} independent runs (its A "
            f"and B rows) of {int(done.sum())}: the rows between repeat A's inputs but one")
    if stats["whirl_unclassified"]:
        stats["notes"].append(
            f"{stats['whirl_unclassified']} runs closed no whirl window (a drop shorter than drop.whirl_window): "
            "whether they whirled is unknown, so the whirl probabilities leave them out")
    for key, (values, unit) in outputs.items():
        if key != "backward_whirl":
            stats["quantiles"][key] = _quantile_entry(values[use], unit)
    codes = list(ds.attrs["whirl_classes"])
    for k, plane in enumerate(ds["plane"].values):
        sel = ds.isel(plane=k)
        flags = sel["backward_whirl"].values
        known = use & np.isfinite(flags)
        classes = np.array(codes, dtype=object)[sel["whirl"].values[use].astype(int)]
        stats["planes"][str(plane)] = {
            "p_backward_whirl": _probability(int((flags[known] > 0.5).sum()), int(known.sum()), among),
            "whirl_at_end": {c: int((classes == c).sum()) for c in codes[1:] if (classes == c).any()},
            "peak_ball_stress_MPa": _quantile_entry(sel["peak_ball_stress"].values[use] / 1e6, "MPa"),
        }
    stats["sensitivity"] = _sensitivity(ds, masks, outputs, independent) if use.sum() >= 3 else {
        "method": None, "outputs": {}, "note": "fewer than 3 runs ended ok"}
    times = ds["sample_time"].values[done]
    integrated = ds["integration_time"].values[done]
    integrated = integrated[np.isfinite(integrated)]  # a sample refused as invalid input integrated nothing
    stats["timing"] = {"mean_sample_time_s": float(times.mean()) if times.size else math.nan,
                       "total_sample_time_s": float(times.sum()),
                       "mean_integration_time_s": float(integrated.mean()) if integrated.size else math.nan}
    return stats


def headline(stats: dict) -> dict:
    """The keys ``auxbearing campaign --json`` prints (see the issue): counts, P(backward whirl), stress."""
    stress = stats["quantiles"]["peak_ball_stress_MPa"]
    whirl = stats["p_backward_whirl"]
    return {"samples": stats["samples"], "completed": stats["completed"], "ok": stats["ok"],
            "failed": stats["failed"], "out_of_range": stats["out_of_range"],
            "p_backward_whirl": {k: whirl[k] for k in ("value", "low", "high", "trials")},
            "p_backward_whirl_at_end": {k: stats["p_backward_whirl_at_end"][k] for k in ("value", "low", "high")},
            "peak_ball_stress_MPa": {k: stress[k] for k in ("p50", "p95", "p99", "interval")},
            "p_s0_below_required": {k: stats["p_s0_below_required"][k] for k in ("value", "low", "high")},
            "required_s0": stats["required_s0"], "notes": stats.get("notes", [])}
