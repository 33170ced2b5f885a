"""Campaign statistics against identities and closed forms.

* Wilson interval: its ends are the two roots of the score equation (k - n p)^2 = z^2 n p (1 - p)
  (Wilson 1927); mirror symmetry k -> n - k; its exact binomial coverage lies near the nominal level
  (Newcombe 1998 reports a mean coverage of the score interval close to 0.95).
* Bootstrap quantile intervals: drawn through order statistics of uniforms, they equal those of
  resampling every value (to Monte Carlo error); they agree with the distribution-free order-statistic interval of a
  quantile (binomial ranks, e.g. Conover, Practical Nonparametric Statistics, 3rd ed., 1999, Sec. 3.2)
  to a few ranks, and cover the true quantile of a known distribution.
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
from auxbearing.campaign.statistics import bootstrap_quantiles, campaign_statistics, wilson_interval
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


def test_bootstrap_interval_matches_order_statistics_and_covers_the_truth():
    rng = np.random.default_rng(3)
    x = np.sort(rng.exponential(1.0, 4000))
    n = x.size
    for prob in (0.5, 0.95):
        estimate, low, high = bootstrap_quantiles(x, (prob,), seed=4)[prob]
        assert estimate == pytest.approx(np.quantile(x, prob))
        # ranks j < k with P(X_(j) <= x_p <= X_(k)) ~ 95 %: binomial(n, p) quantiles
        j = int(stats.binom.ppf(0.025, n, prob))
        k = int(stats.binom.ppf(0.975, n, prob)) + 1
        assert x[j - 4] <= low <= x[j + 4]
        assert x[k - 5] <= high <= x[k + 4]
        assert low <= -math.log(1 - prob) <= high  # the true quantile of Exp(1)


def test_bootstrap_by_order_statistics_equals_resampling_every_value():
    rng = np.random.default_rng(11)
    x = rng.lognormal(0.0, 0.5, 300)
    probs = (0.5, 0.95, 0.99)
    fast = bootstrap_quantiles(x, probs, resamples=40_000, seed=2)
    draws = np.quantile(x[rng.integers(0, x.size, (40_000, x.size))], probs, axis=1)
    for p, row in zip(probs, draws, strict=True):
        low, high = np.quantile(row, [0.025, 0.975])
        sd = row.std()  # both are Monte Carlo estimates of the same bootstrap quantiles
        assert fast[p][1] == pytest.approx(low, abs=0.05 * sd)
        assert fast[p][2] == pytest.approx(high, abs=0.05 * sd)


def test_bootstrap_is_reproducible_and_ignores_non_finite():
    x = np.r_[np.linspace(0.0, 1.0, 101), np.nan, np.inf]
    a = bootstrap_quantiles(x, seed=1)
    assert a == bootstrap_quantiles(x, seed=1)
    assert a[0.5][0] == pytest.approx(0.5)
    assert all(math.isnan(v) for v in bootstrap_quantiles([], (0.5,))[0.5])


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
    assert stats_["p_out_of_range"]["value"] == pytest.approx(1 / c.runs)
