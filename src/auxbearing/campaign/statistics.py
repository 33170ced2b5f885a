"""Statistics of a campaign: probabilities, quantiles and global sensitivity.

Probabilities carry Wilson score intervals, quantiles percentile-bootstrap intervals; sensitivity is
given as Sobol' indices through SALib on a Saltelli design, Spearman rank correlations otherwise.

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
#: Bootstrap resamples of a quantile interval (Efron & Tibshirani 1993, Sec. 13.3, suggest >= 1000
#: for percentile intervals).
RESAMPLES = 1000
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


def bootstrap_quantiles(values, probabilities=QUANTILES, confidence: float = CONFIDENCE,
                        resamples: int = RESAMPLES, seed: int = 0) -> dict[float, tuple[float, float, float]]:
    """Sample quantiles with percentile-bootstrap intervals.

    The interval is Efron & Tibshirani's percentile interval (An Introduction to the Bootstrap, 1993,
    Sec. 13.3); quantiles are numpy's default (linear interpolation between the order statistics of
    ranks r and r + 1, Hyndman & Fan 1996 definition 7). A resample is drawn from the empirical
    distribution, so its order statistics are the empirical quantile function at the order statistics
    of n uniforms: U_(r) ~ Beta(r, n - r + 1) and, given U_(r) = u, U_(r+1) = u + (1 - u) V with
    V ~ Beta(1, n - r) (David & Nagaraja, Order Statistics, 3rd ed., 2003, Sec. 2.2 and 2.5). Drawing
    those two per resample gives the same bootstrap distribution as resampling all n values, at a cost
    independent of n.

    Returns
    -------
    dict
        probability -> (quantile, low, high), NaN when there are no values.

    Examples
    --------
    >>> q = bootstrap_quantiles(np.arange(1001.0), (0.5,), seed=1)[0.5]
    >>> q[0], q[1] < 500.0 < q[2]
    (500.0, True)
    """
    x = np.asarray(values, dtype=float)
    x = np.sort(x[np.isfinite(x)])
    n = x.size
    if n == 0:
        return {float(p): (math.nan, math.nan, math.nan) for p in probabilities}
    rng = np.random.default_rng(seed)
    alpha = 0.5 * (1.0 - confidence)
    out = {}
    for p in probabilities:
        h = (n - 1) * float(p)
        r = math.floor(h) + 1  # 1-based rank of the lower order statistic
        frac = h - (r - 1)
        u = rng.beta(r, n - r + 1, resamples)
        lower = x[np.minimum(np.ceil(n * u).astype(int), n) - 1]
        if r < n:
            v = u + (1.0 - u) * rng.beta(1, n - r, resamples)
            upper = x[np.minimum(np.ceil(n * v).astype(int), n) - 1]
        else:
            upper = lower
        boot = lower + frac * (upper - lower)
        low, high = np.quantile(boot, [alpha, 1.0 - alpha])
        out[float(p)] = (float(np.quantile(x, p)), float(low), float(high))
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


def _quantile_entry(values, unit: str, seed: int) -> dict:
    x = np.asarray(values, dtype=float)
    x = x[np.isfinite(x)]
    q = bootstrap_quantiles(x, seed=seed)
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


def _sensitivity(ds, masks: dict, outputs: dict) -> dict:
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
        return result
    if saltelli:
        result["note"] = (f"Sobol' indices need every run of the Saltelli design to end ok; "
                          f"{int((~masks['ok']).sum())} did not, so rank correlations over the ok runs instead")
    ok = masks["ok"]
    for key in keys:
        y = outputs[key][0][ok]
        keep = np.isfinite(y)
        result["outputs"][key] = rank_correlations(ds["value"].values[ok][keep], y[keep], names)
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


def campaign_statistics(ds, required_s0: float | None = None, seed: int = 0) -> dict:
    """Counts, probabilities, quantiles, per-plane figures and sensitivity of a loaded campaign store."""
    masks = verdict_masks(ds)
    required = float(ds.attrs.get("required_s0", 1.0)) if required_s0 is None else float(required_s0)
    outputs = sample_outputs(ds)
    ok, done, oor = masks["ok"], masks["completed"], masks["out_of_range"]
    whirl = outputs["backward_whirl"][0]
    s0 = outputs["s0_min"][0]
    counts = {v: int((masks["names"][done] == v).sum()) for v in ds.attrs["verdicts"][1:]}
    stats = {
        "samples": int(ds.sizes["sample"]), "completed": int(done.sum()), "ok": int(ok.sum()),
        "failed": int(masks["failed"].sum()), "out_of_range": int(oor.sum()),
        "verdicts": {k: v for k, v in counts.items() if v},
        "p_backward_whirl": _probability(int((whirl[ok] > 0.5).sum()), int(ok.sum()), "runs that ended ok"),
        "p_backward_whirl_at_end": _probability(int(_backward_at_end(ds)[ok].sum()), int(ok.sum()),
                                                "runs that ended ok"),
        "p_out_of_range": _probability(int(oor.sum()), int(done.sum()), "completed samples"),
        "coastdown_limit": int(masks["coastdown_limit"].sum()),
        "p_s0_below_required": _probability(int((s0[ok] < required).sum()), int(ok.sum()), "runs that ended ok"),
        "p_s0_below_required_or_out_of_range": _probability(int((s0[ok] < required).sum() + oor.sum()),
                                                            int(ok.sum() + oor.sum()),
                                                            "runs that ended ok or left the model's range"),
        "required_s0": required,
        "required_s0_source": _required_source(required, required_s0 is not None),
        "smallest_s0": float(np.nanmin(s0[ok])) if ok.any() and np.isfinite(s0[ok]).any() else None,
        "largest_excursion_mm": _largest(outputs.get("max_excursion_mm", (None,))[0], ok),
        "quantiles": {},
        "planes": {},
    }
    for key, (values, unit) in outputs.items():
        if key != "backward_whirl":
            stats["quantiles"][key] = _quantile_entry(values[ok], unit, seed)
    codes = list(ds.attrs["whirl_classes"])
    for k, plane in enumerate(ds["plane"].values):
        sel = ds.isel(plane=k)
        flags = sel["backward_whirl"].values[ok]
        classes = np.array(codes, dtype=object)[sel["whirl"].values[ok].astype(int)]
        stats["planes"][str(plane)] = {
            "p_backward_whirl": _probability(int((flags > 0.5).sum()), int(ok.sum()), "runs that ended ok"),
            "whirl_at_end": {c: int((classes == c).sum()) for c in codes[1:] if (classes == c).any()},
            "peak_ball_stress_MPa": _quantile_entry(sel["peak_ball_stress"].values[ok] / 1e6, "MPa", seed),
        }
    stats["sensitivity"] = _sensitivity(ds, masks, outputs) if ok.sum() >= 3 else {
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
            "required_s0": stats["required_s0"]}
