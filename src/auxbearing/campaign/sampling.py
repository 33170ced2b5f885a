"""Designs on the unit hypercube and the samples they give: the same seed gives the same samples.

``sobol`` is a scrambled Sobol' sequence (Owen scrambling, seeded), ``lhs`` a Latin hypercube and
``random`` plain pseudo-random points, all from :mod:`scipy.stats.qmc` / numpy's default generator;
``saltelli`` is SALib's design for Sobol' indices (Saltelli et al., Comput. Phys. Commun. 181 (2010)
259-270, Table 2 estimators; Sobol' base points scrambled with the seed).
"""

from __future__ import annotations

import warnings
from typing import NamedTuple

import numpy as np

from auxbearing.campaign.config import Campaign


class Design(NamedTuple):
    """Points of a campaign: where each sample sits in the unit hypercube and its SI input values."""

    unit: np.ndarray  #: (runs, inputs) points in [0, 1)
    values: np.ndarray  #: (runs, inputs) SI values, column j = inputs[j].distribution.ppf(unit[:, j])


def unit_design(sampler: str, runs: int, dimensions: int, seed: int, second_order: bool = False) -> np.ndarray:
    """``runs`` points of the unit hypercube in ``dimensions`` dimensions; ``saltelli`` takes N = runs.

    Examples
    --------
    >>> a = unit_design("sobol", 8, 2, seed=1)
    >>> bool(np.array_equal(a, unit_design("sobol", 8, 2, seed=1))), a.shape
    (True, (8, 2))
    >>> unit_design("saltelli", 4, 3, seed=1).shape  # N (D + 2) rows
    (20, 3)
    """
    from scipy.stats import qmc

    if sampler == "saltelli":
        from SALib.sample import sobol as saltelli

        problem = {"num_vars": dimensions, "names": [f"x{j}" for j in range(dimensions)],
                   "bounds": [[0.0, 1.0]] * dimensions}
        with warnings.catch_warnings():
            # SALib warns when N is not a power of two (the balance of the Sobol' points is lost)
            warnings.simplefilter("ignore")
            return np.asarray(saltelli.sample(problem, runs, calc_second_order=second_order, scramble=True,
                                              seed=seed), dtype=float)
    if sampler == "sobol":
        engine = qmc.Sobol(dimensions, scramble=True, rng=np.random.default_rng(seed))
        with warnings.catch_warnings():
            # scipy warns when runs is not a power of two, for the same reason
            warnings.simplefilter("ignore")
            return engine.random(runs)
    if sampler == "lhs":
        return qmc.LatinHypercube(dimensions, rng=np.random.default_rng(seed)).random(runs)
    if sampler == "random":
        return np.random.default_rng(seed).random((runs, dimensions))
    raise ValueError(f"unknown sampler {sampler!r}")


def design(campaign: Campaign) -> Design:
    """The campaign's design points and SI input values (a pure function of the campaign)."""
    base = campaign.samples if campaign.sampler == "saltelli" else campaign.runs
    unit = unit_design(campaign.sampler, base, len(campaign.inputs), campaign.seed, campaign.second_order)
    values = np.empty_like(unit)
    for j, inp in enumerate(campaign.inputs):
        values[:, j] = inp.distribution.ppf(unit[:, j])
    return Design(unit, values)


def balance_note(campaign: Campaign) -> str | None:
    """A note when a Sobol' or Saltelli design is not of a power-of-two size (its balance is lost)."""
    if campaign.sampler in ("sobol", "saltelli") and campaign.samples & (campaign.samples - 1):
        return (f"campaign.samples = {campaign.samples} is not a power of two: the Sobol' points lose their "
                "balance (use 128, 256, 512, ...)")
    return None
