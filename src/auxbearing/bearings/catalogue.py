"""The bearing catalogue as one lookup: names as makers write them, hybrids and duplex sets.

Two sources, the first winning on a name both hold:

* ``catalog/bearings.toml``: bearings with named sources of their own (the source paper's QJ202,
  7202 and 7202-40, Harris & Kotzalas' 209 and 218, the examples' illustrative QJ208);
* the series of :mod:`auxbearing.bearings.series` (60, 62, 63, 72 B, 73 B, QJ2, QJ3; bore 15-100 mm).

A name is read as ``[QJ]<type><series><bore code>[maker suffix][/HC5 | hybrid][DB | DF | DT [preload]]``:
"6205", "6305-2RS", "7208", "7208 BECBP", "QJ 208 N2MA", "QJ208 hybrid", "7208 DB", "7208 BECBP/DB",
"7208 DF medium", "7208 DT". Maker suffixes are ignored except that an angular-contact bearing must
be the 40 deg B design (suffix starting with B, or none); "7202" is the source paper's 35 deg
bearing, "7202 B..." its 40 deg variant "7202-40". A suffix that would change the physics if it were read is
refused rather than ignored: a ball material ("QJ208hybrid", "6208 ceramic") or an internal clearance group
other than normal (C2-C5).
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from auxbearing.bearings.geometry import BearingGeometry, bearing_from_mapping, read_toml
from auxbearing.catalog import bearing_table
from auxbearing.common.errors import InputError

#: Words that make a name a hybrid (silicon-nitride balls): "hybrid", or SKF's /HC5 suffix.
HYBRID_WORDS = ("hybrid", "hc5")
PRELOAD_WORDS = ("light", "medium", "heavy", "none")
#: A bore code is two digits: a digit right after it is no maker suffix but a longer number ('QJ2088', '62080'), a
#: typo that must not read as QJ208 or 6208 (a suffix that starts with a digit is written apart: '6208-2RS1').
_DESIGNATION = re.compile(r"^(?:(QJ)\s*|([67]))([023])(\d\d)(?!\d)\s*[-/]?\s*([A-Z0-9/ -]*)$")
#: The start of a series designation followed by more digits than a bore code has, for the message.
_LONG_CODE = re.compile(r"^((?:QJ\s*|[67])[023]\d\d)(\d+)")
_SERIES_OF = {("6", "0"): "60", ("6", "2"): "62", ("6", "3"): "63", ("7", "2"): "72", ("7", "3"): "73",
              ("QJ", "2"): "QJ2", ("QJ", "3"): "QJ3"}


@dataclass(frozen=True)
class NameParts:
    """A catalogue name taken apart."""

    base: str
    hybrid: bool = False
    arrangement: str | None = None
    preload: str | None = None


def split_name(name: str, field: str = "bearing") -> NameParts:
    """Take a name apart into base designation, hybrid flag, arrangement and preload class (``field``: for errors).

    Examples
    --------
    >>> split_name("7208 BECBP/DB medium")
    NameParts(base='7208 BECBP', hybrid=False, arrangement='DB', preload='medium')
    >>> split_name("QJ208 hybrid")
    NameParts(base='QJ208', hybrid=True, arrangement=None, preload=None)
    >>> split_name("7208 DB 8 um")
    NameParts(base='7208', hybrid=False, arrangement='DB', preload='8 um')
    """
    text = " ".join(str(name).replace("/", " /").split())
    tokens = text.split(" ")
    hybrid, arrangement, preload = False, None, None
    kept: list[str] = []
    for i, token in enumerate(tokens):
        bare = token.lstrip("/").lower()
        if bare in HYBRID_WORDS:
            hybrid = True
        elif bare.upper() in ("DB", "DF", "DT"):
            if arrangement is not None:  # the last one used to win without a word
                raise InputError.for_field(field, name, f"two arrangements ({arrangement}, {bare.upper()}): "
                                           "give one")
            arrangement = bare.upper()
        elif bare in PRELOAD_WORDS and arrangement is not None:
            if preload is not None:
                raise InputError.for_field(field, name, f"two preloads ({preload}, {bare}): give one")
            preload = bare
        elif arrangement is not None and preload is None:
            # everything after the arrangement is its preload ("8 um", "500 N"), checked where the set is made
            preload = " ".join(tokens[i:])
            break
        elif preload is not None:  # "7208 DB light 500 N": a class and a force
            raise InputError.for_field(field, name, f"two preloads ({preload}, {' '.join(tokens[i:])}): "
                                       "give one")
        else:
            kept.append(token)
    base = " ".join(kept).replace(" /", "/").strip().rstrip("/")
    return NameParts(base, hybrid, arrangement, preload)


@cache
def _toml_entries() -> dict[str, str]:
    from auxbearing.catalog import bearing_table

    return {key.lower(): key for key in bearing_table()}


def _series_name(base: str) -> tuple[str | None, str]:
    """The series designation of a maker's name ('7208 BECBP' -> '7208') and its suffix."""
    match = _DESIGNATION.match(base.upper().strip())
    if match is None:
        return None, ""
    qj, kind, series, code, suffix = match.groups()
    suffix = suffix.replace(" ", "")
    key = _SERIES_OF.get(("QJ" if qj else kind, series))
    if key is None:
        return None, suffix
    prefix = "QJ" + series if qj else kind + series
    return f"{prefix}{code}", suffix


#: Suffix words that say what the balls are made of: ignored as maker codes, they would leave the balls steel.
_MATERIAL_WORDS = ("hybrid", "ceramic", "si3n4", "nitride", "zirconia", "zro2")
#: ISO 5753-1 internal clearance groups other than normal (CN): the catalogue's geometry has the normal one.
#: Makers write it apart ('6208 C3', '6208/C3') or glued to a seal, shield or cage code ('6208-2ZC3', NSK's
#: '6208ZZC3', NTN's '6208LLUC3', '6208 MC3'); no ball-bearing suffix code has a C followed by 2-5 otherwise.
_CLEARANCE_GROUP = re.compile(r"C([2-5])(?![0-9])")


#: A maker's pair suffix inside a designation's suffix: DB, DF or DT, maybe after a 2 (two bearings), maybe with the
#: preload class letter (SKF's DBA, DBB, DBC), at the end of a word ('BECBPDB', '/DBC', '/2DB').
_PAIR_SUFFIX = re.compile(r"(?:^|[a-z])2?d[bft][abc]?$")


def _check_suffix(base: str, designation: str, suffix: str, field: str) -> None:
    """Refuse a maker suffix that would change the physics if it were read, since suffixes are otherwise ignored.

    A ball material written into the suffix ('QJ208hybrid', 'QJ208 ceramic', '6208 hybird') would silently
    give an all-steel bearing; an internal clearance group (C2-C5) would silently give the normal clearance.

    Examples
    --------
    >>> _check_suffix("7208 BECBP", "7208", "BECBP", "bearing")
    >>> _check_suffix("6208 C3", "6208", "C3", "bearing")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: bearing = '6208 C3': ...
    """
    import difflib

    words = [w for w in re.split(r"[^a-z0-9]+", suffix.lower()) if w]
    for word in words:
        letters = re.sub(r"[0-9]", "", word)
        near = difflib.get_close_matches(word, _MATERIAL_WORDS, n=1, cutoff=0.75)
        # SKF writes silicon-nitride balls as HC in its super-precision suffixes ('7014 CD/HCP4A')
        hc = word.startswith("hc")
        if hc or near or any(m in word for m in _MATERIAL_WORDS) or (letters and letters in ("ceramic", "hybrid")):
            raise InputError.for_field(field, base, "a ball material is not read from a maker's suffix (the balls "
                                       "would be steel); write the word 'hybrid' apart for silicon-nitride balls, "
                                       f"e.g. '{designation} hybrid'")
    paired = [w for w in words if _PAIR_SUFFIX.search(w)]
    if paired:  # read as one row, a pair's second row and preload would be lost
        raise InputError.for_field(field, base, f"a matched pair ('{paired[0].upper()}') is not read from a maker's "
                                   "suffix (it would be one bearing); write the arrangement and the preload apart, "
                                   f"e.g. '{designation} DB light'")
    group = _CLEARANCE_GROUP.search(suffix.upper())
    if group:
        c = group.group(1)
        raise InputError.for_field(field, base, f"internal clearance group C{c} is not in the catalogue's geometry "
                                   "(it has the normal group, CN); give the bearing without it, or a bearing file "
                                   "with its own diametral_clearance")


def resolve_single(base: str, field: str = "bearing"):
    """The single bearing a base designation names (toml entries first, then the series).

    Examples
    --------
    >>> resolve_single("7208 BECBP").name, resolve_single("7202 BEP").name, resolve_single("qj202").name
    ('7208', '7202-40', 'QJ202')
    """
    from auxbearing.bearings.series import series_entries

    toml = _toml_entries()
    if base.lower() in toml:
        return get_catalogue_entry(toml[base.lower()])
    designation, suffix = _series_name(base)
    if designation is None:
        longer = _LONG_CODE.match(base.upper().strip())
        reason = "" if longer is None else (f"a bore code has two digits, and {longer.group(1)} is followed by "
                                            f"'{longer.group(2)}'; a maker's suffix that starts with a digit is "
                                            "written apart, as in '6208-2RS1'")
        raise InputError.for_field(field, base, _unknown_text(reason))
    _check_suffix(base, designation, suffix, field)
    if designation[0] == "7" and suffix and not suffix.startswith("B"):
        raise InputError.for_field(field, base, "only the 40 deg B design of angular-contact bearings is in the "
                                   "catalogue (suffix B..., or none)")
    if designation[0] == "7" and suffix.startswith("B") and f"{designation}-40".lower() in toml:
        return get_catalogue_entry(toml[f"{designation}-40".lower()])
    if designation.lower() in toml:
        return get_catalogue_entry(toml[designation.lower()])
    entry = series_entries().get(designation)
    if entry is None:
        raise InputError.for_field(field, base, "bore code outside the catalogue's 02-20 (15 to 100 mm); "
                                   + _unknown_text())
    return entry.bearing


def _unknown_text(reason: str = "") -> str:
    from auxbearing.catalog import bearing_names

    return ("unknown" + (f" ({reason})" if reason else "") + "; catalogue names are " + ", ".join(bearing_names())
            + " and the series 60xx, 62xx, 63xx, 72xx B, 73xx B, QJ2xx, QJ3xx with bore codes 02-20 "
            "('auxbearing bearings' lists them)")


def lookup(name: str, field: str = "bearing"):
    """A catalogue bearing, hybrid or duplex set by name (see the module notes).

    Examples
    --------
    >>> lookup("6305").ball_count, lookup("7208 DB").arrangement, lookup("QJ208 hybrid").ball_material.name
    (7, 'DB', 'Si3N4')
    """
    if not isinstance(name, str) or not name.strip():
        raise InputError.for_field(field, name, _unknown_text())
    parts = split_name(name, field)
    if not parts.base:
        raise InputError.for_field(field, name, "names no bearing; " + _unknown_text())
    bearing = resolve_single(parts.base, field)
    if parts.hybrid:
        from auxbearing.bearings.hybrid import hybrid

        bearing = hybrid(bearing)
    if parts.arrangement is None:
        return bearing
    from auxbearing.bearings.duplex import duplex_set

    if bearing.type != "angular_contact":
        raise InputError.for_field(field, name, f"a duplex set ({parts.arrangement}) needs an angular-contact row; "
                                   f"{bearing.name} is {bearing.label}")
    preload = parts.preload
    label = f"{bearing.name} {parts.arrangement}" + (f" {parts.preload}" if parts.preload else "")
    try:
        return duplex_set(bearing, parts.arrangement, preload=preload, name=label)
    except InputError as err:  # named as the user wrote it: the preload is part of the name
        # the rule alone, quoted with the preload as the name gives it ("-3 um", not the offset in metres)
        rule = str(err).split(": ", 1)[-1]
        raise InputError.for_field(field, name, f"its preload '{preload}': {rule}") from None


#: Bearing types the listing filters on, with the words a person may type for them.
TYPE_WORDS = {"deep_groove": ("deep_groove", "deep-groove", "deep groove", "dg", "6"),
              "angular_contact": ("angular_contact", "angular-contact", "angular contact", "angular", "ac", "7"),
              "four_point": ("four_point", "four-point", "four point", "qj", "4pt")}


def parse_type(text: str) -> str:
    """A bearing type from the words people use ('deep groove', 'angular', 'QJ', ...).

    Examples
    --------
    >>> parse_type("Angular"), parse_type("qj")
    ('angular_contact', 'four_point')
    """
    wanted = str(text).strip().lower()
    for kind, words in TYPE_WORDS.items():
        if wanted in words:
            return kind
    raise InputError.for_field("--type", text, "must be one of deep_groove, angular_contact, four_point")


def entries(types=None, bore_range=None) -> list[dict]:
    """The catalogue as rows: name, family, geometry, computed and published C and C0, provenance.

    Parameters
    ----------
    types : iterable of str, optional
        Bearing types to keep (``deep_groove``, ``angular_contact``, ``four_point``).
    bore_range : (float, float), optional
        Bore limits [m], inclusive.

    Examples
    --------
    >>> rows = entries(types=["four_point"], bore_range=(0.04, 0.04))
    >>> [r["name"] for r in rows]
    ['QJ208', 'QJ308']
    """
    from auxbearing.bearings import ratings
    from auxbearing.bearings.series import series_data, series_entries
    from auxbearing.catalog import bearing_table

    table = bearing_table()
    rows: list[dict] = []
    for key, raw in table.items():
        b = get_catalogue_entry(key)
        rows.append(_row(b, "named source", {}, tuple(raw.get("estimated", ())), "", ratings))
    shadowed = {k.lower() for k in table}
    sources = series_data()["sources"]
    for name, entry in series_entries().items():
        if name.lower() in shadowed:
            continue
        published = {k: {"value": v, "source": sources.get(s, s)} for k, (v, s) in entry.published.items()}
        rows.append(_row(entry.bearing, entry.series, published, entry.estimated, entry.rule, ratings))
    keep = set(types) if types else None
    out = []
    for r in rows:
        if keep is not None and r["type"] not in keep:
            continue
        if bore_range is not None:
            if r["bore_mm"] is None or not bore_range[0] * 1e3 - 1e-9 <= r["bore_mm"] <= bore_range[1] * 1e3 + 1e-9:
                continue
        out.append(r)
    return out


def _row(b, series, published, estimated, rule, ratings) -> dict:
    row = b.describe()
    row.update(series=series, C_N=ratings.dynamic_load_rating(b), C0_N=ratings.static_load_rating(b),
               C_published_N=published.get("C", {}).get("value"),
               C0_published_N=published.get("C0", {}).get("value"),
               published=sorted(published), estimated=list(estimated), rule=rule,
               bore_mm=None if b.bore is None else b.bore * 1e3,
               ball_mass_g=b.ball_mass * 1e3 if b.ball_material.density else None)
    if published:
        row["published_sources"] = sorted({p["source"] for p in published.values()})
    return row


def _catalogue() -> dict[str, dict]:
    return bearing_table()


def get_bearing(name: str, field: str = "bearing"):
    """A catalogue bearing, hybrid or duplex set by name as makers write it (case-insensitive).

    ``field`` names the input in an error. Single bearings are :class:`BearingGeometry`; a name with
    DB, DF or DT gives a :class:`~auxbearing.bearings.duplex.DuplexSet`; "hybrid" (or SKF's /HC5)
    puts silicon-nitride balls in (:mod:`auxbearing.bearings.catalogue` reads the names).

    Examples
    --------
    >>> get_bearing("qj202").type, get_bearing("6205").ball_count, get_bearing("7208 DB").arrangement
    ('four_point', 9, 'DB')
    """
    return lookup(name, field)


def get_catalogue_entry(key: str) -> BearingGeometry:
    """The ``catalog/bearings.toml`` entry named exactly ``key``."""
    found = _catalogue_bearing(key.strip().lower())
    if found is None:
        raise InputError.for_field("bearing", key, "not in catalog/bearings.toml")
    return found


@functools.cache
def _catalogue_bearing(lowered: str) -> BearingGeometry | None:
    # A catalogue bearing is read through the unit library once per process (a frozen dataclass, so
    # sharing it is safe): a campaign builds a machine per sample and spent most of that time here.
    for key, entry in _catalogue().items():
        if key.lower() == lowered:
            return bearing_from_mapping(entry, name=key, prefix=f"catalogue {key}.")
    return None


def load_bearing(spec: str | Path | BearingGeometry, field: str = "bearing", sets: bool = False):
    """A bearing from a catalogue name, a TOML path with a ``[bearing]`` table, or as given.

    ``field`` names the input in an error (``--bearing`` on the command line). A duplex set
    ("7208 DB") is returned only with ``sets=True``; the single-bearing analyses refuse it by name.
    """
    if isinstance(spec, BearingGeometry):
        return spec
    if sets and type(spec).__name__ == "DuplexSet":
        return spec
    text = str(spec)
    if not text.strip():
        raise InputError.for_field(field, text, "is empty; give a catalogue name (" + ", ".join(_catalogue())
                                   + ") or a TOML file")
    if text.lower().endswith(".toml") or Path(text).exists():
        data = read_toml(text, field)
        if "bearing" not in data:
            raise InputError.for_field(field, text, "has no [bearing] table")
        return bearing_from_mapping(data["bearing"], name=Path(text).stem)
    found = get_bearing(text, field)
    if not sets and not isinstance(found, BearingGeometry):
        raise InputError.for_field(field, text, f"is a matched set ({found.label}); this analysis takes one "
                                   "bearing (give its row, e.g. " + repr(found.row.name) + ")")
    return found
