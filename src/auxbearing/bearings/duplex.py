"""Matched pairs of single-row angular-contact bearings: back-to-back (DB), face-to-face (DF), tandem (DT).

A :class:`DuplexSet` is two identical rows on one shaft and in one housing, their centres
``row_spacing`` = B + spacer apart. Each row is the one ball-set model of
:mod:`auxbearing.core.ballset` (:func:`~auxbearing.core.ballset.accumulate`, the one contact-pair
kernel); this module only places the rows:

* row k sits at z_k = -/+ row_spacing / 2 on the pair's axis and faces s_k = +1 (carries an axial
  load on the inner ring along +z, as a single row of the catalogue does) or s_k = -1 (the row
  turned end for end: a rotation by pi about x, which maps (delta_a, dx, dy, theta_x, theta_y) to
  (-delta_a, dx, -dy, theta_x, -theta_y)). Back-to-back puts the load lines' apexes outside the pair
  (row at +z faces -1), face-to-face inside (row at +z faces +1), tandem faces both rows +1
  (Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., 2007, Essential Concepts Ch. 1, Fig. 1.10-1.12);
* the shaft's displacement u at the pair's centre moves row k's inner ring by
  M_k u = R_k (delta_a, dx + z_k theta_y, dy - z_k theta_x, theta_x, theta_y) (rigid shaft, small
  tilts), and the row's reaction returns as M_k^T f_k, so forces and displacements stay conjugate;
* preload: the rows are clamped so that each inner ring sits ``preload_offset``/2 further into its
  balls than at first contact (zero clearance rows; the offset is the axial interference that the
  clamping closes, e.g. the stand-out ground off the faces). The preload force that follows is the
  row's own axial load at that displacement, Harris & Kotzalas (2007) Ch. 7 (Eq. 7.31-7.33 in
  their numbering of the 5th edition: F_a = Z K_n(alpha) (B D)^1.5 sin(alpha)
  (cos(alpha0)/cos(alpha) - 1)^1.5 with delta_a = B D sin(alpha - alpha0)/cos(alpha));
  tests/consistency checks the kernel against that closed form.

Preload classes: no maker's preload table could be retrieved while this was written, so the
classes are this project's convention, named as such wherever they appear: light, medium and heavy
are 1 %, 2 % and 4 % of the row's basic static load rating C0 (the doubling steps makers use
between classes); give a force or an axial offset to use a maker's value instead.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.common.errors import InputError

#: Arrangements and their rows' facing (row at -z, row at +z); see the module notes.
ARRANGEMENTS: dict[str, tuple[str, tuple[float, float]]] = {
    "DB": ("back-to-back", (1.0, -1.0)),
    "DF": ("face-to-face", (-1.0, 1.0)),
    "DT": ("tandem", (1.0, 1.0)),
}
#: Preload classes as fractions of the row's C0: this project's convention (module notes), not a maker's table.
PRELOAD_CLASSES: dict[str, float] = {"light": 0.01, "medium": 0.02, "heavy": 0.04}
PRELOAD_SOURCE = ("auxbearing convention: light/medium/heavy = 1/2/4 % of the row's C0 (no maker's preload "
                  "table was retrieved; give a force or an axial offset for a maker's value)")
#: Rotation by pi about x in the (delta_a, dx, dy, theta_x, theta_y) coordinates.
_FLIP = np.array([-1.0, 1.0, -1.0, 1.0, -1.0])


@dataclass(frozen=True)
class DuplexSet:
    """Two identical single-row angular-contact bearings as one unit (SI).

    Parameters
    ----------
    row : BearingGeometry
        One row (angular contact).
    arrangement : str
        "DB", "DF" or "DT".
    preload_offset : float
        Axial interference of the clamped pair [m], >= 0; each row is pushed half of it into its balls.
        Zero for a tandem set (its rows share the load in one direction).
    spacer : float
        Length of the (equal) inner and outer ring spacers between the rows [m], >= 0.
    preload : str
        How the preload was given ("light", "500 N", "8 um", "none"), for reports.
    name : str

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> pair = get_bearing("7208 DB")
    >>> pair.arrangement, pair.preload, round(pair.preload_force)
    ('DB', 'light', 241)
    """

    row: BearingGeometry
    arrangement: str
    preload_offset: float = 0.0
    spacer: float = 0.0
    preload: str = "none"
    name: str = ""

    def __post_init__(self) -> None:
        if not isinstance(self.row, BearingGeometry) or self.row.type != "angular_contact":
            raise InputError.for_field("row", getattr(self.row, "name", self.row),
                                       "a duplex set needs a single-row angular-contact bearing")
        if self.arrangement not in ARRANGEMENTS:
            raise InputError.for_field("arrangement", self.arrangement, "must be one of " + ", ".join(ARRANGEMENTS))
        for key in ("preload_offset", "spacer"):
            value = getattr(self, key)
            if not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0.0:
                raise InputError.for_field(key, value, "must be a finite length >= 0 m")
        if self.arrangement == "DT" and self.preload_offset > 0.0:
            raise InputError.for_field("preload", self.preload, "a tandem (DT) set cannot be preloaded against "
                                       "itself; its rows carry one axial direction together")
        if self.preload_offset >= 0.5 * self.row.curvature_centre_distance:
            raise InputError.for_field("preload_offset", self.preload_offset,
                                       "must be below half the curvature-centre distance A of the row")
        if self.preload_offset > 0.0:
            _check_preload_statics(self)
        if not self.name:
            object.__setattr__(self, "name", f"{self.row.name} {self.arrangement}")

    # -- geometry of the set ---------------------------------------------------------------
    @property
    def label(self) -> str:
        """Human-readable arrangement."""
        return f"duplex {ARRANGEMENTS[self.arrangement][0]} ({self.arrangement})"

    @property
    def type(self) -> str:
        """``duplex_<arrangement>``, the set's kind beside a single bearing's ``type``."""
        return f"duplex_{self.arrangement}"

    @property
    def row_count(self) -> int:
        """Rows in the set (2)."""
        return 2

    @property
    def row_spacing(self) -> float:
        """Distance of the two rows' ball planes [m]: the row width plus the spacer."""
        width = self.row.width if self.row.width is not None else 0.0
        return width + self.spacer

    @property
    def row_positions(self) -> tuple[float, float]:
        """Axial positions z_k of the rows' ball planes from the set's centre [m]."""
        half = 0.5 * self.row_spacing
        return (-half, half)

    @property
    def row_facings(self) -> tuple[float, float]:
        """s_k of each row: +1 carries an axial load on the shaft along +z, -1 along -z."""
        return ARRANGEMENTS[self.arrangement][1]

    @property
    def row_preload_displacement(self) -> float:
        """Axial displacement of each row into its balls in the clamped, unloaded set [m]."""
        return 0.5 * self.preload_offset

    @property
    def preload_force(self) -> float:
        """Axial force each row carries in the clamped, unloaded set [N] (the preload)."""
        return row_axial_force(self.row, self.row_preload_displacement)

    @property
    def width(self) -> float | None:
        """Overall width of the set [m]."""
        return None if self.row.width is None else 2.0 * self.row.width + self.spacer

    @property
    def bore(self) -> float | None:
        """Bore [m], the row's."""
        return self.row.bore

    @property
    def outside_diameter(self) -> float | None:
        """Outside diameter [m], the row's."""
        return self.row.outside_diameter

    @property
    def source(self) -> str:
        """Where the set's data come from."""
        how = PRELOAD_SOURCE if self.preload in PRELOAD_CLASSES else "preload as given"
        return f"{self.label} of {self.row.name}; preload {self.preload} ({how}). Row: {self.row.source}"

    def row_map(self, k: int) -> np.ndarray:
        """M_k (5x5): the shaft's displacement at the set's centre to row k's own coordinates."""
        z = self.row_positions[k]
        shift = np.eye(5)
        shift[1, 4] = z  # dx_k = dx + z theta_y
        shift[2, 3] = -z  # dy_k = dy - z theta_x
        flip = np.ones(5) if self.row_facings[k] > 0.0 else _FLIP
        return flip[:, None] * shift

    def with_changes(self, **changes) -> DuplexSet:
        """A copy with some fields changed, validated again."""
        return replace(self, **changes)

    def describe(self) -> dict[str, object]:
        """Inputs with units, for files and reports."""
        return {"name": self.name, "type": self.type, "arrangement": self.arrangement, "row": self.row.name,
                "preload": self.preload, "preload_force_N": self.preload_force,
                "preload_offset_um": self.preload_offset * 1e6, "spacer_mm": self.spacer * 1e3,
                "row_spacing_mm": self.row_spacing * 1e3, "source": self.source}


#: ISO 76:2006 Table 3, single-row angular-contact ball bearings: the static axial factor Y0 by contact angle [deg]
#: (P0 = 0.5 Fr + Y0 Fa, at least Fr), as SKF's and NSK's catalogues reprint it.
STATIC_AXIAL_FACTORS = {15: 0.46, 20: 0.42, 25: 0.38, 30: 0.33, 35: 0.29, 40: 0.26, 45: 0.22}


def _check_preload_statics(pair: DuplexSet) -> None:
    """Refuse a preload that alone loads a row past its static rating (s0 = C0 / P0 < 1, ISO 76:2006 Eq. 2).

    Clamped and unloaded, each row carries the preload as a pure axial load Fa, so P0 = Y0 Fa. An offset typed in
    place of a force reaches that quickly: 0.29 mm on a 7208 pair is 124 kN a row, five times its C0.
    """
    from auxbearing.bearings.ratings import nearest_angle, static_load_rating

    force = pair.preload_force
    angle = nearest_angle(STATIC_AXIAL_FACTORS, pair.row.contact_angle)
    c0 = static_load_rating(pair.row)
    s0 = c0 / (STATIC_AXIAL_FACTORS[angle] * force)
    if s0 < 1.0:
        raise InputError.for_field(
            "preload", pair.preload,
            f"loads each row with {force / 1e3:.3g} kN, past its static rating on its own (ISO 76: s0 = C0 / (Y0 Fa) "
            f"= {c0 / 1e3:.3g} kN / ({STATIC_AXIAL_FACTORS[angle]:g} x {force / 1e3:.3g} kN) = {s0:.2f} < 1)")


def row_axial_force(row: BearingGeometry, displacement: float) -> float:
    """Axial load [N] a row carries when its inner ring is pushed ``displacement`` [m] into its balls.

    Evaluated by the ball-set kernel (:func:`auxbearing.core.ballset.accumulate`) at
    u = (displacement, 0, 0, 0, 0).

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> round(row_axial_force(get_bearing("7208"), 5e-6))
    593
    """
    from auxbearing.bearings.ballset import ballset_params
    from auxbearing.core.ballset import accumulate

    force = np.zeros(5)
    accumulate(np.array([displacement, 0.0, 0.0, 0.0, 0.0]), ballset_params(row), row.diametral_clearance,
               force, np.zeros((5, 5)), False, False)
    return -float(force[0])


def offset_for_preload(row: BearingGeometry, force: float) -> float:
    """Axial interference of a pair [m] whose rows each carry ``force`` [N] when clamped (inverse of the above).

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> row = get_bearing("7208")
    >>> round(row_axial_force(row, 0.5 * offset_for_preload(row, 500.0)), 6)
    500.0
    """
    if not math.isfinite(force) or force < 0.0:
        raise InputError.for_field("preload", f"{force:g} N", "must be a finite force >= 0 N")
    if force == 0.0:
        return 0.0
    lo, hi = 0.0, 1e-7 * row.ball_diameter
    while row_axial_force(row, hi) < force:
        lo, hi = hi, 2.0 * hi
        if hi > 0.5 * row.curvature_centre_distance:
            raise InputError.for_field("preload", f"{force:g} N", "is more than the row can carry")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if row_axial_force(row, mid) < force:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 1e-15 * hi:
            break
    return lo + hi  # twice the row's displacement


def duplex_set(row: BearingGeometry, arrangement: str, preload: object = None, spacer: object = 0.0,
               name: str | None = None) -> DuplexSet:
    """A matched pair of ``row`` with its preload given as a class, a force or an axial offset.

    Parameters
    ----------
    row : BearingGeometry
    arrangement : {"DB", "DF", "DT"}
    preload : str or float, optional
        "light" (the default for DB and DF), "medium", "heavy" (project convention, see the module
        notes), "none" (the default for DT), a force
        ("500 N"), or an axial offset ("10 um", the interference of the clamped pair). A plain
        number is a force in N. A tandem set takes no preload.
    spacer : str or float
        Spacer length between the rows ("10 mm"; a plain number in m).
    name : str, optional

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> pair = duplex_set(get_bearing("7208"), "DF", preload="1 kN", spacer="5 mm")
    >>> round(pair.preload_force), round(pair.row_spacing * 1e3, 1)
    (1000, 23.0)
    """
    from auxbearing.bearings.ratings import compliance_ratio, static_load_rating
    from auxbearing.common.units import ureg

    arrangement = str(arrangement).upper()
    if arrangement not in ARRANGEMENTS:
        raise InputError.for_field("arrangement", arrangement, "must be one of " + ", ".join(ARRANGEMENTS))
    spacer_m = _length("spacer", spacer)
    if preload is None:
        preload = "none" if arrangement == "DT" else "light"
    text = str(preload).strip().lower() if isinstance(preload, str) else preload
    if arrangement == "DT" and text in PRELOAD_CLASSES:
        raise InputError.for_field("preload", preload, "a tandem (DT) set cannot be preloaded against itself; its "
                                   "rows carry one axial direction together")
    if text in (None, "none", "zero", 0, 0.0):
        offset, label = 0.0, "none"
    elif text in PRELOAD_CLASSES:
        # a share of the steel row's C0: the class is a force the makers give whatever the balls are made of,
        # while a hybrid's C0 is lowered for its stiffer balls (auxbearing.bearings.ratings)
        force = PRELOAD_CLASSES[text] * static_load_rating(row) / compliance_ratio(row) ** 2
        offset, label = offset_for_preload(row, force), text
    elif isinstance(text, (int, float)):
        offset, label = offset_for_preload(row, float(text)), f"{float(text):g} N"
    else:
        quantity = _quantity("preload", preload, ureg)
        if quantity.check("[length]"):
            offset = float(quantity.to("m").magnitude)
            label = f"{offset * 1e6:g} um offset"
        elif quantity.check("[force]"):
            offset = offset_for_preload(row, float(quantity.to("N").magnitude))
            label = f"{float(quantity.to('N').magnitude):g} N"
        else:
            raise InputError.for_field("preload", preload, "must be light, medium, heavy, none, a force "
                                       "('500 N') or an axial offset ('10 um')")
    return DuplexSet(row, arrangement, offset, spacer_m, label, name or "")


def _quantity(field: str, value: object, ureg):
    from auxbearing.common.units import ambiguous

    if ambiguous(str(value)):  # '500 N 2' is 1000 N to pint, '±5 um' +5 um
        raise InputError.for_field(field, value, "one number and its unit, such as '500 N' or '10 um' (no second "
                                   "number, no commas, no ±)")
    try:
        return ureg.Quantity(str(value))
    except Exception:  # pint raises several kinds for text it cannot read
        raise InputError.for_field(field, value, "cannot read it; e.g. 'light', '500 N' or '10 um'") from None


def _length(field: str, value: object) -> float:
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        out = float(value)
    else:
        from auxbearing.common.units import to_si

        out = to_si(field, value, "length")
    if not math.isfinite(out) or out < 0.0:
        raise InputError.for_field(field, value, "must be a length >= 0")
    return out
