"""Property: a table written with any units, delimiter and comments reads back as the same SI values."""

import tempfile
from pathlib import Path

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from auxbearing.common.unit_csv import Column, read_unit_csv

# unit -> SI value of one unit (independent of pint: the definitions of the units)
FORCE = {"N": 1.0, "kN": 1e3, "mN": 1e-3, "lbf": 4.4482216152605}
MOMENT = {"N*m": 1.0, "N*mm": 1e-3, "kN*m": 1e3}
COLUMNS = {"fa": Column("force", False, "N"), "fr": Column("force", False, "N"), "m": Column("moment", False, "N*m")}


@st.composite
def tables(draw):
    names = draw(st.lists(st.sampled_from(sorted(COLUMNS)), min_size=1, max_size=3, unique=True))
    units = {n: draw(st.sampled_from(sorted(MOMENT if n == "m" else FORCE))) for n in names}
    rows = draw(st.integers(1, 12))
    finite = st.floats(-1e6, 1e6, allow_nan=False, allow_subnormal=False)
    values = {n: draw(st.lists(finite, min_size=rows, max_size=rows)) for n in names}
    delimiter = draw(st.sampled_from([",", ";", " "]))
    comments = draw(st.booleans())
    return names, units, values, delimiter, comments


@settings(max_examples=60, deadline=None)
@given(tables())
def test_round_trip_in_si(table):
    names, units, values, delimiter, comments = table
    sep = delimiter if delimiter == " " else delimiter + " "
    lines = ["# written by the property test", "# rig = none"] if comments else []
    # "name [unit]" with a space, whatever the delimiter (a whitespace-separated header included)
    lines.append(sep.join(f"{n} [{units[n]}]" for n in names))
    for k in range(len(values[names[0]])):
        lines.append(sep.join(repr(values[n][k]) for n in names))
        if comments:
            lines.append("")
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "t.csv"
        path.write_text("\n".join(lines) + "\n")
        got = read_unit_csv(path, COLUMNS, unknown="error")
    assert set(got.data) == set(names)
    for n in names:
        scale = (MOMENT if n == "m" else FORCE)[units[n]]
        np.testing.assert_allclose(got.data[n], np.array(values[n]) * scale, rtol=1e-12, atol=1e-300)
    assert len(got.lines) == len(values[names[0]])
    assert got.meta == ({"rig": "none"} if comments else {})
