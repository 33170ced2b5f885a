"""``experiment``: defects found on the measured-drop surface, each pinned by the line a user now sees.

The record is the shipped SYNTHETIC QJ202 drop without its comment lines (a plain CSV as a rig writes it),
cut to its first 30 ms where a run is needed (the drop at 5 ms, its hardest impact at 7 ms), so that
each run simulates a short case. Errors are raised before any simulation.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from auxbearing.cli.main import cli
from auxbearing.common.errors import InputError
from auxbearing.experiment.fit import FitOptions
from auxbearing.experiment.io import read_measured
from auxbearing.experiment.orbit import Preprocessing, preprocess
from auxbearing.experiment.run import peak_table, run_experiment

SYNTHETIC = Path(__file__).parents[2] / "src" / "auxbearing" / "catalog" / "experiments" / "qj202_drop_synthetic.csv"


def _plain(folder: Path, rows: int | None = None, header: str | None = None) -> Path:
    """The synthetic record without its comments: the header and the first ``rows`` samples."""
    lines = [ln for ln in SYNTHETIC.read_text().splitlines() if not ln.startswith("#")]
    if header is not None:
        lines[0] = header
    path = folder / "plain.csv"
    path.write_text("\n".join(lines[: None if rows is None else rows + 1]) + "\n")
    return path


def _run(folder: Path, *args: str):
    return CliRunner().invoke(cli, ["experiment", *args], env={"COLUMNS": "80"})


def _refused(folder: Path, *args: str) -> str:
    """The one error line of a refused run, after checking it wrote nothing and printed no traceback."""
    result = _run(folder, *args, "--out", str(folder / "o"), "--quiet")
    assert result.exit_code == 2, result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), result.stderr
    assert result.stdout == "" and "Traceback" not in result.output and not (folder / "o").exists()
    return lines[0]


# ----------------------------------------------------------------------------- 1. the API takes units
def test_options_take_strings_with_units():
    assert Preprocessing(cutoff="8 kHz").cutoff == pytest.approx(8e3)
    assert Preprocessing(drop_time="5 ms").drop_time == pytest.approx(5e-3)
    assert Preprocessing(offset=("31.7 um", "-18.4 um")).offset == pytest.approx((31.7e-6, -18.4e-6))
    assert Preprocessing(cutoff="none").cutoff is None
    assert FitOptions(window="12 ms").window == pytest.approx(12e-3)
    assert FitOptions(max_evaluations=40.0, phase_grid="4") == FitOptions(max_evaluations=40, phase_grid=4)


@pytest.mark.parametrize(("make", "message"), [
    (lambda: FitOptions(phase_grid=0), "phase_grid = 0: must be a whole number >= 1"),
    (lambda: FitOptions(phase_grid=2.5), "phase_grid = 2.5: must be a whole number >= 1"),
    (lambda: FitOptions(max_evaluations=5.5), "max_evaluations = 5.5: must be a whole number >= 5"),
    (lambda: FitOptions(max_evaluations=True), "max_evaluations = True: must be a whole number >= 5"),
    (lambda: FitOptions(window="1 ms"), "window = '1 ms': must lie in [2, 200] ms"),
    (lambda: FitOptions(window="12 kg"), "window = '12 kg': unit kilogram is not a time"),
    (lambda: Preprocessing(cutoff="-8 kHz"), "cutoff = '-8 kHz': must be > 0 Hz"),
    (lambda: Preprocessing(cutoff="8 kg"), "cutoff = '8 kg': unit kilogram is not a frequency"),
    (lambda: Preprocessing(drop_time="5 um"), "drop_time = '5 um': unit micrometer is not a time"),
    (lambda: Preprocessing(clearance="0 um"), "clearance = '0 um': must be > 0 m"),
    (lambda: Preprocessing(offset=("1 um",)), "offset = ('1 um',): must be 'auto', 'fit', 'start' or two lengths"),
    (lambda: run_experiment("never-read.csv", clearance="-5 um"), "clearance = '-5 um': must be > 0"),
    (lambda: run_experiment("never-read.csv", clearance="5 kg"), "clearance = '5 kg': unit kilogram is not a length"),
])
def test_options_refuse_what_the_command_line_refuses(make, message):
    with pytest.raises(InputError) as err:
        make()
    assert str(err.value).startswith(message)


def test_a_later_check_quotes_the_value_as_given(tmp_path):
    data = read_measured(_plain(tmp_path))
    with pytest.raises(InputError, match=r"^drop_time = '105 ms': must lie in the record's time span \[0, 0.105\) s"):
        preprocess(data, Preprocessing(drop_time="105 ms"))
    with pytest.raises(InputError, match=r"^cutoff = '30 kHz': must be below 0.45 x the record's sampling rate"):
        preprocess(data, Preprocessing(cutoff="30 kHz"))


# ----------------------------------------------------------------------------- 2. a clearance far too small
def test_api_clearance_with_unit_and_an_orbit_far_beyond_it_is_warned(tmp_path):
    _, summary, _ = run_experiment(_plain(tmp_path, 1500), fit=False, clearance="100 um")
    assert summary["measured"]["clearance_used_um"] == pytest.approx(100.0)
    beyond, stress = summary["warnings"]
    assert beyond.startswith("the measured orbit goes 90.92 um beyond the clearance circle used for the force "
                             "(100 um, given; largest radius 190.9 um), further than the contact deflects before its "
                             "balls reach ISO 76's 4200 MPa (77.9 um): the clearance is likely too small")
    assert stress.startswith("measured orbit: max contact stress 4510 MPa exceeds the 4200 MPa of ISO 76")


@pytest.mark.slow  # the whole experiment command on the shipped record
def test_cli_orbit_far_beyond_the_clearance_is_warned(tmp_path):
    result = _run(tmp_path, "--measured", str(_plain(tmp_path, 1500)), "--no-fit", "--clearance", "100 um",
                  "--out", str(tmp_path / "o"), "--quiet")
    assert result.exit_code == 0, result.output
    warnings = [ln for ln in result.stderr.splitlines() if ln.startswith("warning: ")]
    assert len(warnings) == 2, result.stderr
    assert "goes 90.92 um beyond the clearance circle" in warnings[0] and "likely too small" in warnings[0]
    assert "4510 MPa exceeds the 4200 MPa of ISO 76" in warnings[1]


def test_the_right_clearance_is_not_warned(tmp_path):
    # the synthetic drop's true clearance: its 11 um peak excursion is far inside the 79 um the warning allows
    _, summary, _ = run_experiment(_plain(tmp_path, 1500), fit=False, clearance="180 um")
    assert summary["warnings"] == [] and summary["measured"]["peak_excursion_um"] < 15.0


# ----------------------------------------------------------------------------- 3. no contact at all
@pytest.mark.slow  # the whole experiment command on the shipped record
def test_no_contact_has_no_peak_times_and_says_so(tmp_path):
    out = tmp_path / "o"
    result = _run(tmp_path, "--measured", str(_plain(tmp_path, 1500)), "--no-fit", "--out", str(out), "--quiet")
    assert result.exit_code == 0, result.output
    m = json.loads((out / "experiment_summary.json").read_text())["measured"]
    assert m["peak_contact_force_N"] == 0.0
    assert m["peak_force_time_ms"] is None and m["peak_stress_time_ms"] is None and m["peak_excursion_um"] is None
    assert m["gap_to_clearance_um"] == pytest.approx(9.08, abs=0.01)
    text = " ".join(result.stdout.split())  # rich wraps the line at 80 columns
    assert ("Clearance used for the force: 200.00 µm (configured); the orbit stays 9.08 µm inside it: no contact, "
            "so no force or stress from the orbit") in text
    assert "0 / 0 MPa" not in text
    assert "never reaches the clearance circle" in result.stderr


# ----------------------------------------------------------------------------- 4. messages as typed
def test_auto_offset_that_fell_back_to_a_fit_is_named(tmp_path):
    line = _refused(tmp_path, "--measured", str(_plain(tmp_path)), "--no-fit", "--cutoff", "10 Hz")
    assert line.startswith("error: --offset = 'auto': 'auto' (the default) found no levitated stretch before the "
                           "drop (the unfiltered record has one: the low-pass cutoff of 10 Hz smears the drop back "
                           "over it), so it fell back to fitting the offset to the orbit, but the orbit touches the "
                           "clearance wall in fewer than 3 directions")


def test_fit_window_longer_than_the_record_names_the_option(tmp_path):
    line = _refused(tmp_path, "--measured", str(_plain(tmp_path, 660)))
    assert re.fullmatch(r"error: --fit-window = '12 ms': longer than the record after the drop \(8\.\d+ ms\)", line)


def test_a_record_that_ends_before_the_journal_can_land_is_refused(tmp_path):
    """1.24 ms after the drop, where a free fall across the 0.2 mm clearance takes sqrt(2 x 0.2e-3 / g) = 6.39 ms:
    with --no-fit it ran and told the user to give the clearance."""
    line = _refused(tmp_path, "--measured", str(_plain(tmp_path, 321)), "--no-fit")
    assert line == ("error: plain.csv: the record ends 1.24 ms after the drop, before a free fall across the 0.2 mm "
                    "clearance (6.39 ms) ends: it holds no touchdown (record longer after the drop)")


def test_cutoff_above_the_sampling_is_quoted_as_typed(tmp_path):
    line = _refused(tmp_path, "--measured", str(_plain(tmp_path)), "--no-fit", "--cutoff", "30 kHz")
    assert line == ("error: --cutoff = '30 kHz': must be below 0.45 x the record's sampling rate of 50000 Hz, "
                    "i.e. below 22500 Hz")


def test_drop_time_is_quoted_as_typed_with_the_interval_accepted(tmp_path):
    line = _refused(tmp_path, "--measured", str(_plain(tmp_path)), "--no-fit", "--drop-time", "105 ms")
    assert line == ("error: --drop-time = '105 ms': must lie in the record's time span [0, 0.105) s: at or after "
                    "its first sample and before its last")


def test_fit_window_out_of_range_names_the_option(tmp_path):
    line = _refused(tmp_path, "--measured", str(_plain(tmp_path)), "--fit-window", "1")
    assert line == "error: --fit-window = '1': must lie in [2, 200] ms"


def test_time_errors_quote_the_header_as_written(tmp_path):
    path = _plain(tmp_path, 100, header="time [ms], x [um], y [um], speed [rpm]")
    lines = path.read_text().splitlines()
    lines[5], lines[6] = lines[6], lines[5]
    path.write_text("\n".join(lines) + "\n")
    line = _refused(tmp_path, "--measured", str(path), "--no-fit")
    assert line.startswith("error: plain.csv: column 'time [ms]', line 7: time ")


# ----------------------------------------------------------------------------- 5. a record that ends before the drop
@pytest.mark.parametrize("rows", [64, 200])
def test_record_ending_before_the_drop_is_said_so(tmp_path, rows):
    line = _refused(tmp_path, "--measured", str(_plain(tmp_path, rows)), "--no-fit")
    assert line.startswith("error: plain.csv: columns 'x [um]', 'y [um]': the journal never leaves its levitated "
                           "position (it moves 0.295 um at most, within 10 times its jitter of 0.1 um): the record "
                           f"ends before the drop, or holds none ({rows} samples over ")
    assert "rather than" not in line


def test_a_drop_in_too_large_a_unit_still_gets_the_unit_hint(tmp_path):
    path = _plain(tmp_path, header="time [s], x [nm], y [nm], speed [rpm]")
    line = _refused(tmp_path, "--measured", str(path), "--no-fit")
    assert "are the columns in um rather than nm? (the orbit would span 0.2996 mm)" in line


# ----------------------------------------------------------------------------- 6. the peak table
def test_peak_table_keeps_its_units_and_fits_80_columns(tmp_path, monkeypatch, capsys):
    from auxbearing.cli.experiment_cmd import _print

    column = {"peak_contact_force_N": 13458.0, "peak_ball_stress_MPa": 4510.0, "peak_ball_load_N": 3070.0,
              "impacts": 17, "first_impact_ms": 6.84, "whirl": "none", "whirl_frequency_Hz": None}
    names = ("measured", "sim configured", "sim fitted", "sim fitted via orbit")
    measured = {**column, "clearance_used_um": 180.2, "clearance_source": "fitted",
                "peak_stress_if_clearance_plus_1um_MPa": 4400.0, "peak_stress_if_clearance_minus_1um_MPa": 4600.0}
    summary = {"synthetic": False, "bearing": "QJ202", "peak_table": peak_table({n: column for n in names}),
               "measured": measured, "speed_at_drop_rpm": 6000.0}
    monkeypatch.setenv("COLUMNS", "80")
    _print(summary, tmp_path)
    text = capsys.readouterr().out
    assert "First impact [ms]" in text
    assert "…" not in text and "configured" in text
    assert max(len(line) for line in text.splitlines()) <= 80
