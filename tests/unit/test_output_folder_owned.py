"""An output folder written again holds one run: the command's earlier files it did not write again are removed."""

from auxbearing.cli.verify_cmd import VERIFY_OUTPUTS
from auxbearing.common.io import atomic_output_dir


def test_an_earlier_runs_files_the_new_run_does_not_write_are_removed_and_the_users_are_kept(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    for name in ("drop_0.nc", "drop_6.nc", "coastdown.nc", "verify.json", "notes.txt"):
        (out / name).write_text("old")
    (out / "campaign_candidate_2.zarr").mkdir()
    with atomic_output_dir(out, owned=VERIFY_OUTPUTS) as scratch:
        for name in ("drop_0.nc", "verify.json", "report.html"):
            (scratch / name).write_text("new")
    assert sorted(p.name for p in out.iterdir()) == ["drop_0.nc", "notes.txt", "report.html", "verify.json"]
    assert (out / "drop_0.nc").read_text() == "new" and (out / "notes.txt").read_text() == "old"


def test_a_failed_run_removes_nothing(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "drop_6.nc").write_text("old")
    try:
        with atomic_output_dir(out, owned=VERIFY_OUTPUTS):
            raise RuntimeError("stopped")
    except RuntimeError:
        pass
    assert (out / "drop_6.nc").read_text() == "old"
