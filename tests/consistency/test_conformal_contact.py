"""The journal-in-bore contact's closed forms (core.hertz Eq. C1, C2) against a direct numerical solution.

The direct solution does not use the closed forms' reduction to a Cauchy equation. It writes the radial
closing of a disc in a hole (one material, plane strain) from the pressure's Fourier modes, mode 0 of
compliance R/E* and mode n >= 2 of (2R/E*) n / (n^2 - 1) (Michell's solution; Barber, *Elasticity*, 3rd
ed., Ch. 12), summed in closed form into a kernel,

    sum_{n>=2} 2n/(n^2 - 1) cos(n x) = -2 cos(x) ln|2 sin(x/2)| - 1 - cos(x)/2,

and solves u(theta) = delta cos(theta) - dR on the contact arc by collocation, with the pressure as
sqrt(1 - t^2) times Chebyshev polynomials U_2k(t), t = theta/eps; the logarithmic part of the kernel is
integrated exactly (Mason & Handscomb, *Chebyshev Polynomials*, 2003, Sec. 9.5) and the rest by
Gauss-Chebyshev quadrature. Units: R = E* = dR = 1. At small angles both must be Hertz's line contact
(Johnson 1985, Eq. 4.43): the published comparison is tests/validation/test_johnson_1985_line_contact.py.
"""

import math

import numpy as np
import pytest
from scipy.special import eval_chebyt, eval_chebyu

from auxbearing.core.hertz import (
    conformal_half_angle,
    conformal_load,
    conformal_peak_pressure,
    journal_contact,
    journal_force_at_pressure,
)


def _log_moment(m: int, s: np.ndarray) -> np.ndarray:
    """Integral of sqrt(1 - t^2) U_m(t) ln|s - t| over (-1, 1), for |s| < 1."""
    n = m + 1
    if n == 1:
        return 0.5 * math.pi * (0.5 * eval_chebyt(2, s) - math.log(2.0))
    return 0.5 * math.pi * (eval_chebyt(n + 1, s) / (n + 1) - eval_chebyt(n - 1, s) / (n - 1))


def _smooth_kernel(x: np.ndarray) -> np.ndarray:
    """The kernel -2 cos x ln|2 sin(x/2)| - 1 - cos(x)/2 less its -2 ln|x| part."""
    safe = np.where(x == 0.0, 1.0, x)
    ratio = np.where(x == 0.0, 1.0, 2.0 * np.sin(safe / 2.0) / safe)
    return (-2.0 * np.cos(x) * np.log(np.abs(ratio)) - 2.0 * (np.cos(x) - 1.0) * np.log(np.abs(safe))
            - 1.0 - 0.5 * np.cos(x))


def direct_solution(eps: float, terms: int = 20, quadrature: int = 1500) -> tuple[float, float]:
    """(P / (E* dR), p_max R / (E* dR)) at contact half-angle eps by collocation (module docstring)."""
    j = np.arange(1, quadrature + 1)
    t = np.cos(j * np.pi / (quadrature + 1))
    w = np.pi / (quadrature + 1) * np.sin(j * np.pi / (quadrature + 1)) ** 2  # weight sqrt(1 - t^2)
    s = np.cos((2.0 * np.arange(1, 3 * terms + 1) - 1.0) * np.pi / (12.0 * terms))  # points in (0, 1)
    a = np.zeros((s.size, terms + 1))
    for k in range(terms):
        u = eval_chebyu(2 * k, t)
        mean = 0.5 * math.pi if k == 0 else 0.0  # integral of sqrt(1 - t^2) U_2k
        for i, si in enumerate(s):
            smooth = np.sum(w * u * _smooth_kernel(eps * (si - t)))
            kernel = -2.0 * (math.log(eps) * mean + _log_moment(2 * k, si)) + smooth
            a[i, k] = eps / math.pi * kernel + eps / (2.0 * math.pi) * mean
    a[:, terms] = -np.cos(eps * s)  # the approach delta
    coef, *_ = np.linalg.lstsq(a, -np.ones(s.size), rcond=None)
    pressure = sum(c * eval_chebyu(2 * k, t) for k, c in enumerate(coef[:terms]))
    load = eps * np.sum(w * pressure * np.cos(eps * t))
    peak = sum(c * eval_chebyu(2 * k, 0.0) for k, c in enumerate(coef[:terms]))
    return float(load), float(peak)


@pytest.mark.parametrize("degrees", [2.0, 10.0, 30.0, 50.0, 70.0, 80.0])
def test_closed_forms_agree_with_the_direct_solution(degrees):
    eps = math.radians(degrees)
    load, peak = direct_solution(eps)
    assert conformal_load(eps) == pytest.approx(load, rel=1e-4)
    assert conformal_peak_pressure(eps) == pytest.approx(peak, rel=1e-4)


def test_the_load_is_inverted_and_the_pressure_limit_found():
    for degrees in (1.0, 20.0, 60.0, 84.0):
        eps = math.radians(degrees)
        assert conformal_half_angle(conformal_load(eps)) == pytest.approx(eps, rel=1e-9)
    compliance, s, r, length = 2 * (1 - 0.3**2) / 207e9, 0.15e-3, 20e-3, 18e-3
    for pressure in (50e6, 500e6, 4000e6):
        force = journal_force_at_pressure(pressure, length, compliance, s, r)
        assert journal_contact(force, length, compliance, s, r)[1] == pytest.approx(pressure, rel=1e-9)


def test_the_contact_never_passes_its_limiting_angle_and_the_pressure_becomes_linear_in_load():
    angles = [conformal_half_angle(x) for x in (1e2, 1e4, 1e6)]
    assert all(a < math.radians(84.83) for a in angles) and angles == sorted(angles)
    # p_max R / P tends to 0.5996 as the contact saturates (derived in the closed form's limit)
    eps = conformal_half_angle(1e6)
    assert conformal_peak_pressure(eps) / 1e6 == pytest.approx(0.5996, abs=2e-3)
