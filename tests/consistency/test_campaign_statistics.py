"""Campaign statistics against identities and closed forms.

* Wilson interval: its ends are the two roots of the score equation (k - n p)^2 = z^2 n p (1 - p)
  (Wilson 1927); mirror symmetry k -> n - k; its exact binomial coverage lies near the nominal level
  (Newcombe 1998 reports a mean coverage of the score interval close to 0.95).
* Quantile intervals: the distribution-free order-statistic interval (binomial ranks, Conover, Practical
  Nonparametric Statistics, 3rd ed., 1999, Sec. 3.2); they cover the true quantile of a known distribution at
  least as often as their level says, and leave an end open where too few values bound it.
* Sobol' indices of the Ishigami function (Ishigami & Homma 1990), whose variances are closed forms
  (Sobol' & Levitan 1999): S1 = 0.3139, 0.4424, 0; ST = 0.5576, 0.4424, 0.2437 for a = 7, b = 0.1,
  computed here from the formulas. The function goes through the whole campaign path: campaign
  file, Saltelli design, distributions, store, statistics. Tolerance 0.03: the Monte Carlo error of
  N = 4096 base points.
"""

import math

import numpy as np
import pytest
from scipy import optimize, stats

from auxbearing.campaign.config import campaign_from_mapping
from auxbearing.campaign.evaluate import VERDICTS, WHIRL_CODES, output_variables
from auxbearing.campaign.sampling import design
from auxbearing.campaign.statistics import campaign_statistics, quantile_intervals, wilson_interval
from auxbearing.campaign.store import load_results, prepare_store, write_batch


@pytest.mark.parametrize(("k", "n"), [(0, 10), (3, 10), (81, 263), (500, 1000), (999, 1000), (7, 7)])
def test_wilson_ends_are_roots_of_the_score_equation(k, n):
    z = stats.norm.ppf(0.975)
    p, low, high = wilson_interval(k, n)
    assert p == k / n and low <= p <= high

    def score(q):
        return (k - n * q) ** 2 - z * z * n * q * (1 - q)

    if k > 0:
        assert low == pytest.approx(optimize.brentq(score, 1e-15, min(k / n, 1 - 1e-12)), abs=1e-12)
    else:
        assert low == 0.0
    if k < n:
        assert high == pytest.approx(optimize.brentq(score, max(k / n, 1e-12), 1 - 1e-15), abs=1e-12)
    else:
        assert high == 1.0
    mirror = wilson_interval(n - k, n)
    assert mirror[1] == pytest.approx(1 - high, abs=1e-12) and mirror[2] == pytest.approx(1 - low, abs=1e-12)


@pytest.mark.slow
def test_wilson_exact_coverage_is_near_nominal():
    n = 60
    coverages = []
    for p in np.linspace(0.05, 0.95, 19):
        pmf = stats.binom.pmf(np.arange(n + 1), n, p)
        covered = [wilson_interval(k, n)[1] <= p <= wilson_interval(k, n)[2] for k in range(n + 1)]
        coverages.append(float(pmf[covered].sum()))
    assert 0.935 <= np.mean(coverages) <= 0.965
    assert min(coverages) > 0.85


def test_wilson_without_trials_is_the_whole_interval():
    p, low, high = wilson_interval(0, 0)
    assert math.isnan(p) and (low, high) == (0.0, 1.0)


def test_quantile_interval_is_the_binomial_order_statistic_interval():
    rng = np.random.default_rng(3)
    x = np.sort(rng.exponential(1.0, 4000))
    n = x.size
    for prob in (0.5, 0.95):
        estimate, low, high = quantile_intervals(x, (prob,))[prob]
        assert estimate == pytest.approx(np.quantile(x, prob))
        # ranks whose binomial(n, p) tails hold 2.5 % each (Conover 1999, Sec. 3.2), one rank either way
        j = int(stats.binom.ppf(0.025, n, prob))
        k = int(stats.binom.ppf(0.975, n, prob)) + 1
        assert x[j - 2] <= low <= x[j + 1]
        assert x[k - 2] <= high <= x[k + 1]
        assert low <= -math.log(1 - prob) <= high  # the true quantile of Exp(1)


@pytest.mark.slow
@pytest.mark.parametrize(("n", "prob"), [(16, 0.5), (32, 0.95), (128, 0.95), (128, 0.99), (600, 0.99)])
def test_quantile_interval_covers_at_least_its_level(n, prob):
    """Distribution-free: over 2000 normal samples the truth lies inside at least 95 % of the time, less 1.2 % of
    Monte Carlo error (2.5 standard errors); an end too few values bound is NaN and counts as open."""
    rng = np.random.default_rng(n)
    truth = stats.norm.ppf(prob)
    hits = 0
    for _ in range(2000):
        _, low, high = quantile_intervals(rng.standard_normal(n), (prob,))[prob]
        hits += (math.isnan(low) or low <= truth) and (math.isnan(high) or truth <= high)
    assert hits / 2000 >= 0.95 - 0.012


def test_quantile_interval_leaves_open_what_few_values_cannot_bound():
    one = quantile_intervals([1733.0])
    assert all(math.isnan(one[p][1]) or p == 0.99 for p in one)  # one value bounds no median
    assert all(math.isnan(one[p][2]) for p in one)
    sixteen = quantile_intervals(np.arange(16.0), (0.95, 0.99))
    assert math.isnan(sixteen[0.95][2]) and math.isnan(sixteen[0.99][2])  # nothing above the largest value


def test_quantile_intervals_ignore_non_finite():
    x = np.r_[np.linspace(0.0, 1.0, 101), np.nan, np.inf]
    a = quantile_intervals(x)
    assert a == quantile_intervals(x)
    assert a[0.5][0] == pytest.approx(0.5)
    assert all(math.isnan(v) for v in quantile_intervals([], (0.5,))[0.5])


def ishigami_indices(a=7.0, b=0.1):
    v1 = 0.5 * (1 + b * math.pi**4 / 5) ** 2
    v2 = a * a / 8
    v13 = b * b * math.pi**8 * (1 / 18 - 1 / 50)
    v = v1 + v2 + v13
    return np.array([v1, v2, 0.0]) / v, np.array([v1 + v13, v2, v13]) / v


def _store_with_outputs(tmp_path, campaign, y, ok=None):
    """A campaign store whose peak_ball_stress holds y [MPa], written through the store's own path."""
    points = design(campaign)
    path = tmp_path / "s.zarr"
    prepare_store(path, campaign, points)
    runs = campaign.runs
    sample_vars, plane_vars = output_variables(campaign.analysis)
    arrays = {name: np.zeros(runs, dtype) for name, (dtype, *_) in sample_vars.items()}
    arrays.update({name: np.zeros((runs, 1), dtype) for name, (dtype, *_) in plane_vars.items()})
    arrays["verdict"][:] = np.where(ok if ok is not None else np.ones(runs, bool), VERDICTS.index("ok"),
                                    VERDICTS.index("journal_contact_overstress"))
    arrays["peak_ball_stress"][:, 0] = np.asarray(y) * 1e6
    arrays["peak_contact_force"][:, 0] = y
    arrays["s0"][:] = 2.0
    arrays["whirl"][:] = WHIRL_CODES.index("none")
    arrays["sample_time"][:] = 0.1
    write_batch(path, 0, arrays)
    return load_results(path), points


def _ishigami_campaign(sampler, samples):
    uniform = {"distribution": "uniform", "low": f"{-math.pi!r} rad", "high": f"{math.pi!r} rad"}
    return campaign_from_mapping({"campaign": {
        "machine": "paper_rig", "sampler": sampler, "samples": samples, "seed": 7, "batch_size": 100_000,
        "input": [{"key": "rotor.unbalance_phase", **uniform}, {"key": "rotor.couple_unbalance_phase", **uniform},
                  {"key": "touchdown.0.misalignment_x", "distribution": "uniform", "low": f"{-math.pi!r} m",
                   "high": f"{math.pi!r} m"}]}})


@pytest.mark.slow
def test_sobol_indices_of_ishigami_through_the_campaign_path(tmp_path):
    c = _ishigami_campaign("saltelli", 4096)
    points = design(c)
    x = points.values
    y = np.sin(x[:, 0]) + 7.0 * np.sin(x[:, 1]) ** 2 + 0.1 * x[:, 2] ** 4 * np.sin(x[:, 0])
    ds, _ = _store_with_outputs(tmp_path, c, y)
    sens = campaign_statistics(ds)["sensitivity"]
    assert sens["method"] == "sobol"
    got = sens["outputs"]["peak_ball_stress_MPa"]
    s1, st = ishigami_indices()
    for j, key in enumerate(c.keys):
        assert got[key]["S1"] == pytest.approx(s1[j], abs=0.03)
        assert got[key]["ST"] == pytest.approx(st[j], abs=0.03)


def test_saltelli_with_a_failed_run_falls_back_to_rank_correlations(tmp_path):
    c = _ishigami_campaign("saltelli", 64)
    x = design(c).values
    y = x[:, 0] + 0.1 * x[:, 1]
    ok = np.ones(c.runs, bool)
    ok[5] = False
    ds, _ = _store_with_outputs(tmp_path, c, y, ok)
    stats_ = campaign_statistics(ds)
    sens = stats_["sensitivity"]
    assert sens["method"] == "spearman" and "1 did not" in sens["note"]
    rho = sens["outputs"]["peak_ball_stress_MPa"]
    assert rho["rotor.unbalance_phase"]["rho"] > 0.9 > abs(rho["touchdown.0.misalignment_x"]["rho"])
    assert stats_["out_of_range"] == 1 and stats_["ok"] == c.runs - 1
    # row 5 opens the second block of D + 2 = 5 rows: an A row, one of the 2 N = 128 independent draws
    assert stats_["independent_runs"] == 128
    assert stats_["p_out_of_range"]["value"] == pytest.approx(1 / 128)


@pytest.mark.slow
def test_saltelli_probabilities_count_only_the_a_and_b_rows(tmp_path):
    """A drop condition of an A row comes back in D of its block's rows; counted there it would weigh D + 1 times."""
    from auxbearing.campaign.statistics import independent_rows

    c = _ishigami_campaign("saltelli", 8)
    ds, _ = _store_with_outputs(tmp_path, c, np.ones(c.runs))
    block = len(c.inputs) + 2
    rows = independent_rows(ds)
    assert rows.sum() == 16 and all(rows[i] == (i % block in (0, block - 1)) for i in range(c.runs))
    whirl = np.zeros(c.runs)
    whirl[[block * i + j for i in range(8) for j in range(1, block - 1)]] = 1.0  # every mixed row whirls
    ds["backward_whirl"][:, 0] = whirl
    stats_ = campaign_statistics(ds)
    assert stats_["p_backward_whirl"]["trials"] == 16 and stats_["p_backward_whirl"]["successes"] == 0
    assert "independent runs" in stats_["notes"][0]


@pytest.mark.slow
def test_a_drop_that_closed_no_whirl_window_is_not_counted_as_without_whirl(tmp_path):
    c = _ishigami_campaign("sobol", 8)
    ds, _ = _store_with_outputs(tmp_path, c, np.ones(8))
    whirl = np.zeros(8)
    whirl[:5] = np.nan  # five drops too short to be classified
    whirl[5] = 1.0
    ds["backward_whirl"][:, 0] = whirl
    stats_ = campaign_statistics(ds)
    p = stats_["p_backward_whirl"]
    assert (p["successes"], p["trials"]) == (1, 3) and stats_["whirl_unclassified"] == 5
    assert "whirl classified" in p["among"] and "closed no whirl window" in stats_["notes"][0]
