"""A table of load cases (a duty cycle, a load spectrum) through the batched static solver.

The CSV has one load case per row and its units in the header, read by
:func:`auxbearing.common.unit_csv.read_unit_csv` (the same rules as a measured drop)::

    # duty cycle of the touchdown bearing
    axial [N], radial [kN], moment [N*m]
    0,   0.5, 0
    200, 1.0, 2

Columns are either the paper's planar loads ``axial`` (Fa), ``radial`` (Fr), ``moment`` (M)
or the 5-DOF loads ``axial``, ``force_x``, ``force_y``, ``moment_x``, ``moment_y`` (short
names ``Fa``, ``Fr``, ``M``, ``Fx``, ``Fy``, ``Mx``, ``My``); a missing column is zero. Every case
is solved in one batched Newton call (:func:`auxbearing.analysis.statics.solve_loads`).

Results keep their sign: the radial displacement and the tilt are the components in the plane of each
case's load (:func:`auxbearing.analysis.statics.planar_components`), the same numbers in the table, the CSV,
the JSON and the NetCDF. A case that loads no contact has no stress and so no s0: the JSON holds null, the
NetCDF NaN, the CSV an empty cell and the table "-".
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import xarray as xr

from auxbearing.analysis.statics import load_distribution, planar_components, solve_loads, validity_warnings_all
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.common.errors import InputError
from auxbearing.common.unit_csv import Column, read_unit_csv

PLANAR = ("axial", "radial", "moment")
FIVE_DOF = ("axial", "force_x", "force_y", "moment_x", "moment_y")
LOAD_COLUMNS = {
    "axial": Column("force", False, "N"),
    "radial": Column("force", False, "N"),
    "moment": Column("moment", False, "N*m"),
    "force_x": Column("force", False, "N"),
    "force_y": Column("force", False, "N"),
    "moment_x": Column("moment", False, "N*m"),
    "moment_y": Column("moment", False, "N*m"),
}
ALIASES = {"fa": "axial", "fr": "radial", "m": "moment", "fx": "force_x", "fy": "force_y",
           "mx": "moment_x", "my": "moment_y"}
#: Columns of the results table: key, CSV header with unit, format, short console header.
RESULT_COLUMNS = (
    ("line", "line", "{:d}", "line"),
    ("axial_displacement_um", "axial_displacement [um]", "{:.4f}", "δa [µm]"),
    ("radial_displacement_um", "radial_displacement [um]", "{:.4f}", "δr [µm]"),
    ("tilt_mrad", "tilt [mrad]", "{:.5f}", "θ [mrad]"),
    ("max_contact_load_N", "max_contact_load [N]", "{:.2f}", "Q max [N]"),
    ("max_stress_MPa", "max_stress [MPa]", "{:.1f}", "σ max [MPa]"),
    ("safety_factor_s0", "safety_factor_s0 [1]", "{:.4g}", "s0"),
    ("residual_N", "residual [N]", "{:.1e}", "resid. [N]"),
)


def read_load_cases(path: str | Path, field: str = "loads file", max_cases: int | None = None
                    ) -> tuple[dict[str, np.ndarray], list[int]]:
    """Load columns [N, N m] by name and the file line of each case.

    ``field`` names the file in an error (``--loads`` on the command line); ``max_cases`` is a budget of
    rows, checked before any value is converted.

    Raises
    ------
    InputError
        As :func:`auxbearing.common.unit_csv.read_unit_csv` (an unknown column is an error here, so a
        misspelt load is never dropped silently), plus: no load column, planar and 5-DOF
        columns mixed, no rows, more rows than ``max_cases``.
    """
    table = read_unit_csv(path, LOAD_COLUMNS, file_field=field, aliases=ALIASES, unknown="error",
                          max_rows=max_cases, budget_name="--max-cases" if field.startswith("--") else "max_cases")
    name = Path(path).name
    if not table.data:
        raise InputError(f"{name}: no load column in the header (line {table.header_line}); write e.g. "
                         "'axial [N], radial [N], moment [N*m]'")
    planar = {"radial", "moment"} & set(table.data)
    spatial = set(FIVE_DOF[1:]) & set(table.data)
    if planar and spatial:
        raise InputError(f"{name}: columns {', '.join(sorted(planar))} (planar) and {', '.join(sorted(spatial))} "
                         "(5-DOF) mixed; use axial, radial, moment or axial, force_x, force_y, moment_x, moment_y")
    if not table.lines:
        raise InputError(f"{name}: no load cases below the header (line {table.header_line})")
    return table.data, table.lines


def load_cases(bearing: BearingGeometry | str, path: str | Path, table: tuple | None = None,
               **options) -> xr.Dataset:
    """Solve every load case of a CSV file on one bearing.

    Parameters
    ----------
    bearing : BearingGeometry or str
    path : path
        The CSV (format in the module docstring).
    table : tuple, optional
        What :func:`read_load_cases` returned for ``path``, when the caller has read it already.
    **options
        ``axial_condition``, ``tilt``, ``ball_constant``, ``tol`` of
        :func:`auxbearing.analysis.statics.solve_loads`; errors name the file line of the case.

    Returns
    -------
    xarray.Dataset
        That of :func:`~auxbearing.analysis.statics.load_distribution` (planar columns) or
        :func:`~auxbearing.analysis.statics.solve_loads` (5-DOF columns), plus ``line``, the file
        line of each case, and ``source_file`` in attrs.
    """
    data, lines = read_load_cases(path) if table is None else table
    n = len(lines)
    options.setdefault("case_names", [f"{Path(path).name}: line {line}" for line in lines])
    column = {k: data.get(k, np.zeros(n)) for k in LOAD_COLUMNS}
    if set(data) <= set(PLANAR):
        ds = load_distribution(bearing, axial=column["axial"], radial=column["radial"], moment=column["moment"],
                               **options)
    else:
        ds = solve_loads(bearing, np.column_stack([column[k] for k in FIVE_DOF]), **options)
    if "radial_displacement" not in ds:  # 5-DOF columns: the signed numbers the results table shows
        radial, tilt = (v + 0.0 for v in planar_components(ds))  # + 0.0: no -0 stored
        ds["radial_displacement"] = ("case", radial, {"units": "m", "long_name": "Radial displacement in the plane "
                                                                               "of the load (planar_components)"})
        ds["tilt"] = ("case", tilt, {"units": "rad", "long_name": "Tilt in the plane of the load (planar_components)"})
    ds["line"] = ("case", np.asarray(lines), {"units": "1", "long_name": "Line of the case in the loads file"})
    ds.attrs["source_file"] = str(path)
    return ds


def case_rows(ds: xr.Dataset) -> list[dict]:
    """One mapping per case in display units (the results table), with its validity warnings.

    Built column by column (10^5 cases take well under a second; one case at a time took ~1 ms each).
    Displacement and tilt are signed (:func:`~auxbearing.analysis.statics.planar_components`), as
    ``auxbearing static`` shows them; s0 is None for a case that loads no contact.
    """
    radial, tilt = planar_components(ds)
    s0 = ds["safety_factor_s0"].values
    # + 0.0 turns a negative zero into zero
    columns = {
        "line": ds["line"].values.astype(int),
        "axial_displacement_um": ds["axial_displacement"].values * 1e6 + 0.0,
        "radial_displacement_um": radial * 1e6 + 0.0,
        "tilt_mrad": tilt * 1e3 + 0.0,
        "max_contact_load_N": ds["max_contact_load"].values,
        "max_stress_MPa": ds["max_stress"].values / 1e6,
        "safety_factor_s0": np.where(np.isfinite(s0), s0, None),
        "residual_N": ds["residual"].values,
    }
    lists = {key: np.asarray(values).tolist() for key, values in columns.items()}
    warnings = validity_warnings_all(ds)
    keys = list(lists)
    return [{**dict(zip(keys, values, strict=True)), "warnings": w}
            for *values, w in zip(*(lists[k] for k in keys), warnings, strict=True)]


def worst_case(rows: list[dict]) -> dict:
    """The row with the highest max stress (lowest s0)."""
    return max(rows, key=lambda r: r["max_stress_MPa"])


def format_cell(row: dict, key: str, fmt: str, missing: str = "-") -> str:
    """One value of a results row as the table and the CSV show it: ``missing`` for no value, no "-0.0000".

    >>> format_cell({"tilt_mrad": -1e-12}, "tilt_mrad", "{:.5f}"), format_cell({"s0": None}, "s0", "{:.4g}")
    ('0.00000', '-')
    """
    value = row[key]
    if value is None:
        return missing
    text = fmt.format(value)
    # a value that rounds to zero shows no sign (a round-off -1e-16 um is no displacement)
    if text.startswith("-") and not any(c in "123456789" for c in text.split("e")[0]):
        text = text[1:]
    return text


def write_rows_csv(rows: list[dict], path: str | Path, comment: str = "") -> Path:
    """The results table as CSV with units in the header (the input's own format).

    Warnings go to a last column (quoted by :mod:`csv` where needed) so that a spreadsheet
    shows them beside the case. A value a case does not have (s0 of a case that loads no contact)
    is an empty cell.
    """
    path = Path(path)
    with path.open("w", encoding="utf-8", newline="") as handle:
        if comment:
            handle.write(f"# {comment}\n")
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow([*(label for _, label, _, _ in RESULT_COLUMNS), "warnings"])
        for row in rows:
            writer.writerow([*(format_cell(row, key, fmt, missing="") for key, _, fmt, _ in RESULT_COLUMNS),
                             "; ".join(row["warnings"])])
    return path
