"""What a machine file says about judging it: its ``[criteria]``, ``[verify]`` and ``[[candidate]]`` tables.

The tables' rows and readers live with the machine description (a file is checked whole, by
:func:`auxbearing.machine.check.check_machine_document`, before any analysis runs); what the verdict does with
them is :mod:`auxbearing.verify`'s.
"""

from __future__ import annotations

import copy
from pathlib import Path

from auxbearing.common.errors import InputError
from auxbearing.common.params import Param, by_key, display_value, read_table

#: The ``[criteria]`` rows: what the verdict judges against.
CRITERIA: tuple[Param, ...] = (
    Param("criteria", "min_s0", "dimensionless", 1.0, "", "positive",
          "Smallest static safety factor s0 of any ball contact in any drop",
          "ISO 76:2006: s0 = C0/P0, and 1 loads a contact to 4200 MPa (a permanent set of 1e-4 D); makers ask 1.5-2 "
          "or more under shock, so raise it for your machine"),
    Param("criteria", "max_temperature", "temperature", 393.15, "degC", "service_temperature",
          "Hottest bearing part over the coast-down, -73 to 350 degC, between coastdown.ambient_temperature and "
          "coastdown.max_temperature",
          "ours: 120 degC, the heat-stabilisation limit makers state for standard through-hardened bearing steel; "
          "check your bearing's and its lubricant's"),
    Param("criteria", "max_preload_stress", "pressure", 4200e6, "MPa", "positive",
          "Ball stress at rest of the preload a closing internal clearance makes", "ISO 76:2006 (4200 MPa at rest)"),
    Param("criteria", "required_drops", "dimensionless", None, "", "optional_count",
          "Drops (each with its coast-down) the bearings must survive; default life.required_drops",
          "the machine file's life.required_drops (itself an assumption unless you set it)"),
    Param("criteria", "amb_air_gap", "length", None, "mm", "optional_positive",
          "Radial air gap of the magnetic bearings; without it the air-gap criterion is not checked", "user input"),
    Param("criteria", "air_gap_fraction", "dimensionless", 0.5, "", "fraction",
          "Largest touchdown clearance (at the top of its fit tolerance, with thermal growth) as a fraction of the "
          "magnetic air gap; the rotor's largest travel in the runs is judged against the whole gap",
          "ours: common practice of about half the air gap; not a clause we could read in ISO 14839-5"),
    Param("criteria", "seal_clearance", "length", None, "mm", "optional_positive",
          "Radial clearance of the tightest seal; the journal's largest excursion from the machine's axis (where the "
          "seals are centred; a compliant mount lets the bearing move with the journal) must stay inside it",
          "user input"),
    Param("criteria", "max_backward_whirl_probability", "dimensionless", 0.05, "", "fraction",
          "Largest probability of sustained backward whirl over the campaign's uncertain drop conditions", "ours"),
    Param("criteria", "max_amb_current_share", "dimensionless", 1.0, "", "fraction",
          "Largest control current per axis in any scenario, as a share of each magnetic bearing's own limit "
          "(reaching the limit itself fails: the controller has lost authority)", "ours: the amplifier's limit"),
    Param("criteria", "relevitation_time", "time", None, "ms", "optional_positive",
          "Every scenario that leaves the magnetic bearings powered must re-levitate within this time of its "
          "strike (a scenario's own relevitate_within takes precedence)", "user input; not asked unless given"),
)
CRITERIA_TABLE = by_key(CRITERIA, "criteria")


def read_criteria(data: dict | None) -> dict:
    """The ``[criteria]`` table in SI (unknown keys refused with the list), defaults filled in."""
    given = read_table(data, CRITERIA_TABLE, "criteria.")
    return {p.key: given.get(p.key, p.default) for p in CRITERIA} | {"given": sorted(given)}


#: Dry steel-on-steel sliding friction: 0.10-0.30 in Gieck & Gieck, *Engineering Formulas*, 7th ed. (1997),
#: as quoted with other handbooks' values (0.23-0.62) by LBL's engineering table of friction coefficients
#: (www-eng.lbl.gov/~ajdemell/coefficients_of_friction.html); Blau, Tribol. Int. 34 (2001) 585-591 on why a
#: friction coefficient is a system's, not a material pair's, property: hence a spread, not a value.
FRICTION_RANGE = (0.1, 0.3)
FRICTION_SOURCE = ("Gieck & Gieck, Engineering Formulas, 7th ed. (1997): steel on steel sliding 0.10-0.30; "
                   "a system property (Blau, Tribol. Int. 34, 2001), so a range")
#: Samples of the verification's campaign unless ``verify.campaign_samples`` says otherwise: a power of two
#: (Sobol' balance) whose whirl-free outcome shows P(backward whirl) within the default 5 % at one-sided 97.5 %
#: (Wilson's bound for no events, 1.96^2 / (n + 1.96^2), is 0.029 at 128 and 0.057 at 64).
CAMPAIGN_SAMPLES = 128
#: Largest campaign of a verification (the command line's --campaign-samples, the API's samples, the file's key).
MAX_CAMPAIGN_SAMPLES = 100000

VERIFY: tuple[Param, ...] = (
    Param("verify", "low_speed", "angular_speed", None, "rpm", "optional_positive",
          "Speed of the low-speed drop; default a quarter of rotor.speed", "ours"),
    Param("verify", "campaign_samples", "dimensionless", float(CAMPAIGN_SAMPLES), "", "nonnegative",
          "Samples of the verification's campaign (a whole number up to 100000; 0: no campaign)",
          "ours: 128 whirl-free drops show P(backward whirl) <= 0.05 at one-sided 97.5 % (Wilson)"),
    Param("verify", "friction_low", "dimensionless", FRICTION_RANGE[0], "", "unit_interval",
          "Lowest journal/race sliding friction of the campaign (uniform spread)", FRICTION_SOURCE),
    Param("verify", "friction_high", "dimensionless", FRICTION_RANGE[1], "", "unit_interval",
          "Highest journal/race sliding friction of the campaign (uniform spread)", FRICTION_SOURCE),
    Param("verify", "balance_grade", "velocity", 6.3e-3, "mm/s", "nonnegative",
          "Balance grade G of the rotor: the campaign's unbalance spreads from 0 to G / speed (and at least to "
          "rotor.unbalance)",
          "ISO 21940-11:2016, Table 1 (G 6.3: fans, blowers, pumps, electric motors); e_per = G / Omega"),
    Param("verify", "fit_grade", "dimensionless", 6.0, "", "positive",
          "ISO tolerance grade (IT) of the race bore and the journal; the campaign's radial clearance spreads by "
          "(IT_bore + IT_journal) / 4 either side, and the air-gap criterion takes its top",
          "ISO 286-1:2010, Table 1 (IT6: ground bore and journal)"),
    Param("verify", "clearance_tolerance", "length", None, "um", "optional_nonnegative",
          "Half-width of the radial clearance's spread (the campaign's, and the air-gap criterion's allowance), "
          "instead of the one from verify.fit_grade", "user input"),
    Param("verify", "mount_stiffness_spread", "dimensionless", 0.2, "", "unit_interval",
          "Half-width of the mount stiffness's spread, as a fraction of its value",
          "ours: elastomer and spring mounts are held to about +-20 % of their rated stiffness"),
    Param("verify", "mount_damping_spread", "dimensionless", 0.3, "", "unit_interval",
          "Half-width of the mount damping's spread, as a fraction of its value",
          "ours: damping scatters more than stiffness (temperature, frequency)"),
    Param("verify", "start_offset", "dimensionless", 0.3, "", "unit_interval",
          "Largest offset of the levitated rotor from the bearing centre when the magnetic bearings let go, as a "
          "fraction of the smallest radial clearance (square spread of that half-diagonal)",
          "ISO 14839-2:2004: zone A/B boundary of a levitated rotor's displacement at 0.3 of the minimum "
          "clearance"),
)
VERIFY_TABLE = by_key(VERIFY, "verify")


#: The ISO tolerance grades the clearance spread is tabulated for (``verify.fit_grade``).
FIT_GRADES = (6.0, 7.0)


def verify_settings(data: dict) -> dict:
    """The ``[verify]`` table in SI with defaults."""
    given = read_table(data.get("verify"), VERIFY_TABLE, "verify.")
    grade = given.get("fit_grade")
    if grade is not None and not FIT_GRADES[0] <= grade <= FIT_GRADES[1]:
        # the tolerance table holds IT6 and IT7 only (auxbearing.verify.cases.IT_TABLE): another grade was
        # quietly taken as the nearer of the two, understating a coarse fit's clearance spread tenfold at IT12
        raise InputError.for_field("verify.fit_grade", data["verify"]["fit_grade"],
                                   f"must be between {FIT_GRADES[0]:g} and {FIT_GRADES[1]:g} (ISO 286-1 IT6-IT7, "
                                   "ground bores and journals); for another fit give verify.clearance_tolerance")
    return {p.key: given.get(p.key, p.default) for p in VERIFY}


#: Touchdown keys that belong to the design's bearing: a candidate gets its own from its geometry (Hertz's K_b of
#: Eq. 15, the shoulder at a quarter of its ball diameter, its rings' mass and inertia, its line and face contacts).
CANDIDATE_DERIVED = ("race_mass", "race_inertia", "line_stiffness", "face_stiffness", "face_radius", "ball_constant",
                     "shoulder_height")


def typed_values(values: dict, table: dict[str, Param]) -> dict:
    """SI values of a table's keys as a user would type them, with their units (``120 degC``), for files and reports.

    >>> typed_values({"max_temperature": 393.15, "amb_air_gap": None, "given": []}, CRITERIA_TABLE)
    {'max_temperature': '120 degC', 'amb_air_gap': None}
    """
    return {k: None if v is None else display_value(table[k], v) for k, v in values.items() if k in table}


def candidate_tables(data: dict, specs: list) -> list[tuple[str, dict]]:
    """(label, machine tables) per candidate; a spec is a catalogue name, a bearing TOML path or a table."""
    out = []
    for i, spec in enumerate(specs):
        if isinstance(spec, dict):
            unknown = [k for k in spec if k not in ("name", "bearing", "preload")]
            if unknown:
                raise InputError.for_field(f"candidate.{i}.{unknown[0]}", spec[unknown[0]],
                                           "unknown key; allowed keys: name, bearing, preload")
            if "bearing" not in spec:
                raise InputError(f"candidate.{i}.bearing: missing; a [[candidate]] names its bearing")
            bearing, label = spec["bearing"], str(spec.get("name", spec["bearing"]))
            if not label.strip():  # a ranking and a report row without a name
                raise InputError.for_field(f"candidate.{i}.name", spec.get("name"), "must not be empty")
            preload = spec.get("preload")
        else:
            preload = None
            bearing, label = str(spec).strip(), str(spec).strip()
            if not bearing:
                raise InputError.for_field("--candidates", spec, "an empty name in the list")
            _check_bearing_name(bearing, "--candidates")
            if Path(bearing).is_file():  # a file named on the command line is where the user is, not the machine's
                bearing = str(Path(bearing).resolve())
        tables = copy.deepcopy(data)
        for plane in tables["touchdown"]:
            plane["bearing"] = bearing
            plane.pop("preload", None)  # the design's preload is not the candidate's
            if preload is not None:
                plane["preload"] = preload
            for derived in CANDIDATE_DERIVED:
                plane.pop(derived, None)  # follow the new bearing
        out.append((label, tables))
    return out


def _check_bearing_name(spec: str, field: str) -> None:
    """Refuse a candidate that is neither a catalogue bearing nor a bearing TOML file, naming ``field``."""
    from auxbearing.bearings.catalogue import get_bearing
    from auxbearing.bearings.geometry import bearing_names

    if Path(spec).is_file():
        return
    if spec.lower().endswith(".toml"):
        raise InputError.for_field(field, spec, f"no such bearing file (looked in {Path.cwd()})")
    try:
        get_bearing(spec, field)
    except (InputError, KeyError, ValueError) as err:
        from auxbearing.bearings.catalogue import resolve_single, split_name

        try:  # a catalogue bearing with a bad preload or suffix: its own rule, not "no such bearing"
            resolve_single(split_name(spec, field).base.split()[0], field)
        except (InputError, KeyError, ValueError, IndexError):
            raise InputError.for_field(field, spec, "neither a catalogue bearing (e.g. " + ", ".join(bearing_names())
                                       + "; `auxbearing bearings` lists them all) nor a bearing TOML file") from None
        raise (err if isinstance(err, InputError) else InputError.for_field(field, spec, str(err))) from None
