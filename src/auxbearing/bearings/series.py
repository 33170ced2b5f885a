"""Catalogue series: the sizes touchdown designers fit, with internal geometry from published ratings.

Seven series from bore 15 to 100 mm (bore codes 02 to 20): deep groove 60, 62, 63; single-row
angular contact 72 B and 73 B (40 deg); four-point contact QJ2 and QJ3 (35 deg). Boundary
dimensions d x D x B come from ISO 15 and ratings from the maker, both in ``catalog/series.toml``.
Makers do not publish ball sets, so every entry's internal geometry is estimated by one rule:

1. Pitch diameter D_pw = (d + D)/2 (the mid-section of the ring envelope).
2. Where the maker's C and C0 are both held (every 60/62/63 size, 7208, 7308): the ball count Z
   (whole) and ball diameter D_w are chosen together so that ISO 281's C times the maker's rating
   factor and ISO 76's C0 (:mod:`auxbearing.bearings.ratings`) meet the published pair with equal and
   opposite log errors, the smallest over Z. Two published numbers, two unknowns: C and C0 then
   match to a few tenths of a per cent (the rounding of Z), which checks the calibration, not the
   model. The rule does recover the ball sets that are published: CWRU's measured SKF 6203
   (8 x 6.746 mm) and 6205 (9 x 7.94 mm) and eng-tools.dev's 6206 (9 x 9.525 mm) come back with the
   right Z and D_w within 0.3 % (tests/validation/test_skf_2018_ratings.py).
   Along a series the sizes are fitted together (:func:`fit_series`): the ball may not shrink from one
   size to the next by more than the fit resolves (:data:`BALL_SHRINK`), and within that the sum of the
   errors is smallest. A pair alone does not always tell the ball count: from 6314 on, 7 and 8 balls
   meet SKF's C and C0 within about 1 % of each other, the best of each size alone alternated between
   them (6314 7 x 27.6 mm, 6315 8 x 26.9 mm, 6316 7 x 31.0 mm), and the four-point and angular sizes
   that take those balls (rules 3, 4) were rated lower for a larger size (QJ314 189 kN, QJ315 183 kN).
   Fitted together, 6310-6319 take 8 balls and 6320 9, each within 1.1 % of SKF's C.
3. 72 B / 73 B sizes without ratings: the ball of the deep-groove bearing of the same boundary plan
   (62xx, 63xx), and as many balls as fit at the ball spacing of the calibrated 7208 and 7308
   (pitch chord over ball diameter :data:`ANGULAR_SPACING`; a one-shoulder ring takes more balls).
4. QJ2 / QJ3: the ball of the 72 B / 73 B bearing of the same boundary plan at 35 deg (as the
   source paper gives its QJ202 the ball of its 7202), as many as fit at the wider ball spacing
   :data:`FOUR_POINT_SPACING` (a machined cage between the balls), calibrated on the one four-point
   rating held, SKF's QJ 202 N2MA (C = 12.7 kN). With the 72 B ball count instead, the QJ 202 would be
   rated 15.2 kN, 19.5 % above SKF.
5. Groove radii 0.52 D_w inner and 0.53 D_w outer (the conformity ISO 76 assumes); diametral clearance
   zero for angular-contact and four-point bearings (as the catalogue's paper bearings), the middle
   of ISO 5753-1's Normal group for deep groove bearings (:data:`NORMAL_CLEARANCE_UM`).

The maker's rating factor: SKF states that its Explorer ratings follow ISO 281 "with adjusted
factors" (skf.com, Load ratings). :data:`SKF_RATING_FACTOR` is the geometric mean of SKF's C over
ISO 281's C for the three SKF sizes whose ball sets are published (6203, 6205, 6206).
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from functools import cache
from importlib import resources

from auxbearing.bearings import ratings
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.bearings.materials import get_material
from auxbearing.core import fatigue as cf

#: SKF Explorer over plain ISO 281: SKF C / ISO 281 C of the SKF 6203 (CWRU, 8 x 6.746 mm on 28.50 mm:
#: 1.0422), 6205 (CWRU, 9 x 7.940 mm on 39.04 mm: 1.0554) and 6206 (eng-tools.dev, 9 x 9.525 mm on 46 mm:
#: 1.0442), geometric mean; SKF C from SKF Rolling bearings 2018 (tests/validation).
SKF_RATING_FACTOR = 1.0473
#: Groove radius over ball diameter, inner and outer (ISO 76's assumption for radial ball bearings).
INNER_GROOVE_RATIO, OUTER_GROOVE_RATIO = 0.52, 0.53
#: Pitch chord over ball diameter, D_pw sin(pi/Z)/D_w, of the 7208 B and 7308 B ball sets fitted to
#: their published ratings (1.0607 and 1.0733), mean: the ball spacing of rule 3.
ANGULAR_SPACING = 1.067
#: Pitch chord over ball diameter of the four-point series (rule 4): SKF's QJ 202 N2MA (C = 12.7 kN) needs 9
#: balls of the 7202 B's 6.0 mm on D_pw 25 mm, i.e. a spacing in (1.288, 1.425]; the middle of that range.
FOUR_POINT_SPACING = 1.356
#: The most a series' estimated ball may shrink from one size to the next (rule 2 along a series): what the fit
#: cannot resolve. The calibration sizes' SKF factors lie up to 0.8 % from their mean (SKF_RATING_FACTOR), and in
#: the 60 and 62 series neighbours whose best fits share a ball (6009/6010, 6212/6213) come out 0.2-0.4 % apart.
BALL_SHRINK = 0.01
#: ISO 5753-1:2009 Table 1, radial internal clearance of deep groove ball bearings, Normal group
#: [um]: (bore over, bore up to and including, min, max).
NORMAL_CLEARANCE_UM = ((10, 18, 3, 18), (18, 24, 5, 20), (24, 30, 5, 20), (30, 40, 6, 20), (40, 50, 6, 23),
                       (50, 65, 8, 28), (65, 80, 10, 30), (80, 100, 12, 36), (100, 120, 15, 41))


@dataclass(frozen=True)
class Series:
    """One catalogue series: its type, angle, ISO 15 diameter series and designation prefix."""

    key: str
    type: str
    family: str
    contact_angle_deg: float
    diameter_series: str
    prefix: str
    partner: str | None = None
    label: str = ""


SERIES: dict[str, Series] = {s.key: s for s in (
    Series("60", "deep_groove", "deep groove", 0.0, "0", "60", label="deep groove, diameter series 0"),
    Series("62", "deep_groove", "deep groove", 0.0, "2", "62", label="deep groove, diameter series 2"),
    Series("63", "deep_groove", "deep groove", 0.0, "3", "63", label="deep groove, diameter series 3"),
    Series("72", "angular_contact", "angular contact", 40.0, "2", "72", "62", "angular contact 72 B, 40 deg"),
    Series("73", "angular_contact", "angular contact", 40.0, "3", "73", "63", "angular contact 73 B, 40 deg"),
    Series("QJ2", "four_point", "four-point", 35.0, "2", "QJ2", "72", "four-point QJ2, 35 deg"),
    Series("QJ3", "four_point", "four-point", 35.0, "3", "QJ3", "73", "four-point QJ3, 35 deg"),
)}


@dataclass(frozen=True)
class CatalogueEntry:
    """A catalogue bearing with what is published about it and what is estimated.

    ``published`` maps a quantity to (value in SI, source key of ``catalog/series.toml``);
    ``estimated`` names the geometry the rule supplied; ``rule`` says which rule.
    """

    name: str
    series: str
    bearing: BearingGeometry
    published: dict = field(default_factory=dict)
    estimated: tuple[str, ...] = ()
    rule: str = ""

    @property
    def bore(self) -> float:
        """Bore d [m]."""
        return self.bearing.bore


@cache
def _steel():
    return get_material("GCr15")


@cache
def series_data() -> dict:
    """``catalog/series.toml`` as read (dimensions, ratings and their sources)."""
    text = resources.files("auxbearing.catalog").joinpath("series.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)


def published_ratings(designation: str) -> tuple[float | None, float | None, str | None]:
    """The maker's (C, C0) [N] of a designation and the source key, None where not held.

    Examples
    --------
    >>> published_ratings("6205")
    (14800.0, 7800.0, 'skf2018')
    """
    for source, table in series_data()["ratings"].items():
        if designation in table:
            c, c0 = table[designation]
            return (c * 1e3 if c else None), (c0 * 1e3 if c0 else None), source
    return None, None, None


def normal_clearance(bore: float) -> float:
    """Middle of ISO 5753-1's Normal radial clearance group for a deep groove bearing [m].

    Examples
    --------
    >>> round(normal_clearance(40e-3) * 1e6, 1)
    13.0
    """
    d = bore * 1e3
    for low, high, cmin, cmax in NORMAL_CLEARANCE_UM:
        if low < d <= high:
            return 0.5 * (cmin + cmax) * 1e-6
    raise ValueError(f"bore {d:g} mm: outside the Normal clearance table (10 to 120 mm)")


def _ratings(dw, dm, z, alpha, rows, factor):
    return (factor * cf.dynamic_load_rating(dw, dm, z, alpha, rows),
            ratings.static_load_rating_si(dw, dm, z, alpha, rows))


def ball_set_candidates(bore: float, outside: float, contact_angle: float, rating: float, static_rating: float,
                        rows: int = 1, factor: float = SKF_RATING_FACTOR) -> list[tuple[int, float, float]]:
    """Each ball count with the diameter at which ISO 281 C (times ``factor``) and ISO 76 C0 meet a maker's pair.

    For each Z the diameter balances the two log errors (rule 2 of the module notes; D_pw = (d + D)/2).

    Returns
    -------
    list of (z, ball_diameter, error)
        Every Z that can meet the pair, fewest balls first: D_w [m] and the common |log| error of C and C0 [-].
    """
    dm = 0.5 * (bore + outside)
    cos_a = math.cos(contact_angle)
    lo_dw = 0.011 * dm / cos_a  # ISO 281 Table 2 starts at gamma = 0.01
    found = []
    guess = 0.6 * 0.5 * (outside - bore)
    z_guess = static_rating / (14.0 * rows * (guess * 1e3) ** 2 * cos_a)
    for z in range(max(3, int(z_guess) - 4), int(z_guess) + 6):
        hi_dw = min(0.999 * dm * math.sin(math.pi / z), 0.39 * dm / cos_a, 0.5 * (outside - bore))
        if hi_dw <= lo_dw:
            continue

        def balance(dw, z=z):
            c, c0 = _ratings(dw, dm, z, contact_angle, rows, factor)
            return math.log(c / rating) + math.log(c0 / static_rating)

        f_lo, f_hi = balance(lo_dw), balance(hi_dw)
        if f_lo > 0.0 or f_hi < 0.0:
            continue
        a, b = lo_dw, hi_dw
        for _ in range(60):  # bisection on a smooth monotone function
            mid = 0.5 * (a + b)
            if balance(mid) < 0.0:
                a = mid
            else:
                b = mid
            if b - a < 1e-10 * b:
                break
        dw = 0.5 * (a + b)
        c, _ = _ratings(dw, dm, z, contact_angle, rows, factor)
        found.append((z, dw, abs(math.log(c / rating))))
    if not found:
        raise ValueError(f"no ball set fits {bore * 1e3:g} x {outside * 1e3:g} mm with C = {rating:g} N, "
                         f"C0 = {static_rating:g} N")
    return found


def fit_ball_set(bore: float, outside: float, contact_angle: float, rating: float, static_rating: float,
                 rows: int = 1, factor: float = SKF_RATING_FACTOR) -> tuple[int, float, float]:
    """The ball count and diameter of :func:`ball_set_candidates` that meet a maker's pair best (one size alone).

    Examples
    --------
    >>> z, dw, err = fit_ball_set(25e-3, 52e-3, 0.0, 14.8e3, 7.8e3)   # SKF 6205
    >>> z, round(dw * 1e3, 2), err < 0.01
    (9, 7.95, True)
    """
    return min(ball_set_candidates(bore, outside, contact_angle, rating, static_rating, rows, factor),
               key=lambda found: found[2])


def fit_series(candidates: list[list[tuple[int, float, float]]]) -> list[tuple[int, float, float]]:
    """One ball set per size of a series, its balls growing with the size (rule 2 along a series).

    ``candidates``: for each size in order of bore, its :func:`ball_set_candidates`. The choice minimises the sum
    of the sizes' errors on condition that no size's ball is smaller than the one before it by more than
    :data:`BALL_SHRINK` (dynamic programming over the sizes); where no choice meets that, each size takes its best.
    """
    # cost[i][j]: least error sum of sizes 0..i with size i on its candidate j; back[i][j]: the candidate before it
    cost = [[c[2] for c in candidates[0]]]
    back: list[list[int]] = [[-1] * len(candidates[0])]
    for i in range(1, len(candidates)):
        row, links = [], []
        for _, dw, err in candidates[i]:
            allowed = [(cost[-1][j], j) for j, before in enumerate(candidates[i - 1])
                       if dw >= (1.0 - BALL_SHRINK) * before[1] and math.isfinite(cost[-1][j])]
            best = min(allowed, default=(math.inf, -1))
            row.append(best[0] + err)
            links.append(best[1])
        cost.append(row)
        back.append(links)
    end = min(range(len(cost[-1])), key=cost[-1].__getitem__)
    if not math.isfinite(cost[-1][end]):
        return [min(c, key=lambda found: found[2]) for c in candidates]
    chosen = [end]
    for i in range(len(candidates) - 1, 0, -1):
        chosen.append(back[i][chosen[-1]])
    return [candidates[i][j] for i, j in enumerate(reversed(chosen))]

def most_balls(pitch_diameter: float, ball_diameter: float, spacing: float) -> int:
    """Largest Z with D_pw sin(pi/Z) >= spacing * D_w (rule 3).

    Examples
    --------
    >>> most_balls(60e-3, 12.36e-3, ANGULAR_SPACING)
    14
    """
    return int(math.pi / math.asin(min(1.0, spacing * ball_diameter / pitch_diameter)) + 1e-9)


def _dimensions(series: Series) -> dict[str, tuple[float, float, float]]:
    rows = series_data()["dimensions"][series.diameter_series]
    return {code: (d * 1e-3, big_d * 1e-3, b * 1e-3) for code, d, big_d, b in rows}


def designation(series: Series, code: str) -> str:
    """Maker-style name: '6205', '7208', 'QJ208'."""
    return f"{series.prefix}{code}"


def _series_fits(series: Series) -> dict[str, tuple[int, float, float]]:
    """The ball sets of a series' sizes that have the maker's C and C0, fitted along the series (:func:`fit_series`)."""
    rows = 2 if series.type == "four_point" else 1
    alpha = math.radians(series.contact_angle_deg)
    codes, candidates = [], []
    for code, (d, big_d, _) in _dimensions(series).items():
        c, c0, _ = published_ratings(designation(series, code))
        if c is not None and c0 is not None:
            codes.append(code)
            candidates.append(ball_set_candidates(d, big_d, alpha, c, c0, rows))
    return dict(zip(codes, fit_series(candidates), strict=True)) if codes else {}


def _build(series: Series, code: str, entries: dict, fits: dict) -> CatalogueEntry:
    d, big_d, width = _dimensions(series)[code]
    name = designation(series, code)
    alpha = math.radians(series.contact_angle_deg)
    dm = 0.5 * (d + big_d)
    c, c0, source = published_ratings(name)
    published = {"bore": (d, "iso15"), "outside_diameter": (big_d, "iso15"), "width": (width, "iso15")}
    if c is not None and c0 is not None:
        z, dw, _ = fits[code]
        published.update(C=(c, source), C0=(c0, source))
        rule = "rule 2: Z and D_w fitted to the maker's C and C0 (ISO 281 x SKF factor, ISO 76)"
    elif series.type == "angular_contact":
        partner = entries[designation(SERIES[series.partner], code)].bearing
        dw = partner.ball_diameter
        z = most_balls(dm, dw, ANGULAR_SPACING)
        rule = (f"rule 3: ball of the {partner.name}, as many as fit at pitch chord {ANGULAR_SPACING:g} D_w "
                "(the spacing of the calibrated 7208 and 7308)")
    else:
        partner = entries[designation(SERIES[series.partner], code)].bearing
        dw = partner.ball_diameter
        z = most_balls(dm, dw, FOUR_POINT_SPACING)
        rule = (f"rule 4: ball of the {partner.name} at 35 deg, as many as fit at pitch chord "
                f"{FOUR_POINT_SPACING:g} D_w (calibrated on SKF's QJ 202)")
    if c is not None and "C" not in published:
        published["C"] = (c, source)
    clearance = normal_clearance(d) if series.type == "deep_groove" else 0.0
    steel = _steel()
    sources = series_data()["sources"]
    text = (f"{name} ({series.label}): {d * 1e3:g} x {big_d * 1e3:g} x {width * 1e3:g} mm from ISO 15"
            + (f"; C = {c / 1e3:g} kN, C0 = {c0 / 1e3:g} kN from {sources[source].split(',')[0].split(': ')[0]}"
               if c is not None and c0 is not None else "")
            + f". Estimated (auxbearing.bearings.series {rule.split(':')[0]}): {z} balls of {dw * 1e3:.3f} mm on "
            f"D_pw {dm * 1e3:g} mm, groove radii {INNER_GROOVE_RATIO:g}/{OUTER_GROOVE_RATIO:g} D_w, "
            f"clearance {clearance * 1e6:g} um.")
    bearing = BearingGeometry(
        type=series.type, ball_diameter=dw, pitch_diameter=dm, ball_count=z,
        inner_groove_ratio=INNER_GROOVE_RATIO, outer_groove_ratio=OUTER_GROOVE_RATIO, contact_angle=alpha,
        diametral_clearance=clearance, ball_material=steel, ring_material=steel, name=name, bore=d,
        outside_diameter=big_d, width=width, source=text, rating_factor=SKF_RATING_FACTOR)
    estimated = ("ball_diameter", "ball_count", "pitch_diameter", "inner_groove_ratio", "outer_groove_ratio",
                 "diametral_clearance")
    return CatalogueEntry(name, series.key, bearing, published, estimated, rule)


@cache
def series_entries() -> dict[str, CatalogueEntry]:
    """Every series entry by designation, built in rule order (deep groove, angular, four-point).

    Examples
    --------
    >>> e = series_entries()["7208"]
    >>> e.bearing.ball_count, round(e.bearing.ball_diameter * 1e3, 2), sorted(e.published)[:2]
    (15, 11.76, ['C', 'C0'])
    """
    entries: dict[str, CatalogueEntry] = {}
    for series in SERIES.values():
        fits = _series_fits(series)
        for code in _dimensions(series):
            entry = _build(series, code, entries, fits)
            entries[entry.name] = entry
    return entries
