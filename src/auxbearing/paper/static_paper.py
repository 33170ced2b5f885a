"""The paper's static study (source paper Sec. II.C, Fig. 6-8) plus the Stribeck check.

Built on :func:`auxbearing.analysis.statics.load_distribution`; the loads the paper does not
print are named constants below, each with the reason for its value.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from auxbearing import __version__
from auxbearing.analysis.statics import STRIBECK_CONSTANT, load_distribution, stribeck_comparison
from auxbearing.bearings.catalogue import load_bearing
from auxbearing.bearings.geometry import BearingGeometry

#: Fig. 6 loads. The paper prints only "(d) Radial force is 1000N"; the axial sweep is at that
#: radial load and the radial sweep at 500 N axial load (our choice: with zero axial load the
#: two pairs of a four-point ball are mirror images and the figure would show one curve).
FIG6_RADIAL_LOADS = (250.0, 500.0, 1000.0, 1500.0, 2000.0)
FIG6_FIXED_AXIAL = 500.0
FIG6_AXIAL_LOADS = (0.0, 250.0, 500.0, 750.0, 1000.0)
FIG6_FIXED_RADIAL = 1000.0
#: Fig. 7 grid of axial x radial load [N] (moment zero, ring free to tilt as in Eq. 14).
FIG7_LOADS = tuple(float(v) for v in np.arange(0.0, 2001.0, 100.0))
#: Fig. 8 radial loads [N]; the angular-contact ring is located axially and kept square.
FIG8_RADIAL_LOADS = tuple(float(v) for v in np.arange(0.0, 4001.0, 100.0))


def _fig7(bearing: BearingGeometry) -> xr.Dataset:
    fa, fr = np.meshgrid(FIG7_LOADS, FIG7_LOADS, indexing="ij")
    ds = load_distribution(bearing, axial=fa.ravel(), radial=fr.ravel())
    shape = fa.shape
    out = xr.Dataset(coords={"axial_load": ("axial_load", np.array(FIG7_LOADS), {"units": "N"}),
                             "radial_load": ("radial_load", np.array(FIG7_LOADS), {"units": "N"})})
    for name in ("axial_displacement", "radial_displacement", "tilt", "max_contact_load", "max_stress", "residual"):
        out[name] = (("axial_load", "radial_load"), ds[name].values.reshape(shape), ds[name].attrs)
    out.attrs.update(ds.attrs, title=f"Fig. 7: ring displacements over axial x radial load, {bearing.name}")
    return out


def _fig8(four_point: BearingGeometry, angular: BearingGeometry) -> xr.Dataset:
    r = np.array(FIG8_RADIAL_LOADS)
    runs = [load_distribution(four_point, radial=r),
            load_distribution(angular, radial=r, axial_condition="located", tilt="fixed")]
    out = xr.Dataset(coords={"bearing": [four_point.name, angular.name],
                             "radial_load": ("radial_load", r, {"units": "N"})})
    for name in ("max_stress", "max_contact_load", "safety_factor_s0", "radial_displacement", "axial_reaction"):
        out[name] = (("bearing", "radial_load"), np.stack([d[name].values for d in runs]), runs[0][name].attrs)
    out["type"] = ("bearing", [four_point.type, angular.type])
    out.attrs.update(
        title="Fig. 8: max contact stress under radial load, four-point versus angular contact",
        conditions=f"{four_point.name}: free ring, M = 0 (symmetric: no axial or tilt motion); "
                   f"{angular.name}: axially located and square (as the drop model), axial reaction reported",
        auxbearing_version=__version__,
    )
    return out


def static_study(out_dir=None, bearing_4pt: BearingGeometry | str = "QJ202",
                 bearing_ac: BearingGeometry | str = "7202", progress=None) -> dict:
    """The paper's static study (Sec. II.C, Fig. 6-8) plus the Stribeck check.

    Parameters
    ----------
    out_dir : path, optional
        Folder for NetCDF data, PNG figures and ``static_summary.json`` (written atomically).
    bearing_4pt, bearing_ac : BearingGeometry or str
        Four-point and angular-contact bearings compared in Fig. 8.
    progress : callable, optional
        Called with a short text before each step.

    Returns
    -------
    dict
        ``fig6_radial``, ``fig6_axial``, ``fig7``, ``fig8``, ``stribeck`` (Datasets),
        ``figures`` (matplotlib Figures by file stem) and ``summary`` (numbers for the report).
    """
    from auxbearing.plots.static import plot_contact_angles, plot_displacements, plot_max_stress

    def step(text: str) -> None:
        if progress is not None:
            progress(text)

    four = load_bearing(bearing_4pt)
    angular = load_bearing(bearing_ac)
    step("Fig. 6 contact angles")
    fig6_radial = load_distribution(four, axial=FIG6_FIXED_AXIAL, radial=np.array(FIG6_RADIAL_LOADS))
    fig6_axial = load_distribution(four, axial=np.array(FIG6_AXIAL_LOADS), radial=FIG6_FIXED_RADIAL)
    step("Fig. 7 displacements")
    fig7 = _fig7(four)
    step("Fig. 8 max stress")
    fig8 = _fig8(four, angular)
    stribeck = stribeck_comparison(four, (250.0, 1000.0, 4000.0))
    at = fig8.sel(radial_load=1000.0)
    excess = (fig8["max_stress"].isel(bearing=1) - fig8["max_stress"].isel(bearing=0)).values[1:]
    summary_out = {
        "four_point": four.name,
        "angular_contact": angular.name,
        "max_stress_at_1000N_MPa": {str(b): float(v) / 1e6 for b, v in zip(fig8.bearing.values, at["max_stress"].values,
                                                                           strict=True)},
        "angular_exceeds_four_point_everywhere": bool(np.all(excess > 0.0)),
        "excess_grows_with_load": bool(np.all(np.diff(excess) > 0.0)),
        "stribeck_k_loaded": [float(v) for v in stribeck["k_loaded"].values],
        "stribeck_constant": STRIBECK_CONSTANT,
        "max_relative_residual": float(max(d["relative_residual"].max() for d in (fig6_radial, fig6_axial))),
    }
    step("figures")
    figures = {
        "fig6_contact_angles": plot_contact_angles(fig6_radial, fig6_axial),
        "fig7_displacements": plot_displacements(fig7),
        "fig8_max_stress": plot_max_stress(fig8),
    }
    result = {"fig6_radial": fig6_radial, "fig6_axial": fig6_axial, "fig7": fig7, "fig8": fig8,
              "stribeck": stribeck, "figures": figures, "summary": summary_out}
    if out_dir is not None:
        step("writing files")
        _write_study(result, out_dir, four, angular)
    return result


def _write_study(result: dict, out_dir, four: BearingGeometry, angular: BearingGeometry) -> None:
    from auxbearing.common.io import atomic_output_dir, save_dataset, save_figure, write_json

    inputs = {"bearing_4pt": four.describe(), "bearing_ac": angular.describe(),
              "fig6_radial_loads_N": FIG6_RADIAL_LOADS, "fig6_fixed_axial_N": FIG6_FIXED_AXIAL,
              "fig6_axial_loads_N": FIG6_AXIAL_LOADS, "fig6_fixed_radial_N": FIG6_FIXED_RADIAL,
              "fig7_loads_N": FIG7_LOADS, "fig8_radial_loads_N": FIG8_RADIAL_LOADS}
    with atomic_output_dir(out_dir) as tmp:
        for key in ("fig6_radial", "fig6_axial", "fig7", "fig8", "stribeck"):
            save_dataset(result[key], tmp / f"{key}.nc", inputs)
        for stem, fig in result["figures"].items():
            save_figure(fig, tmp / stem)
        write_json(result["summary"], tmp / "static_summary.json", inputs)
