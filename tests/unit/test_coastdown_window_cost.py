"""The coast-down's full-dynamics windows do not refine peaks they never report.

The observer refines a peak of the contact force, ball stress and axial force inside a step with 86 calls of
its target (two golden-section searches). The drop reports those peaks; the coast-down's windows do not, and in
the blower's steady rolling below 1500 rpm their searches came on one step in four (204 us a step against 47 us
without them; the whole coast-down 58.7 s of CPU against 32.8 s, its summary identical). The
observer therefore tracks no peak in them (``Watch.track_peaks``), so it never starts a search there.
"""

from auxbearing.analysis.coastdown import run_coastdown
from auxbearing.core import drive
from auxbearing.machine.files import read_machine


def test_windows_make_no_peak_search_and_the_drop_still_refines(monkeypatch):
    calls = []

    def recording(advance):
        def recorded(m, w, y, t_end, settings, memory, grid):
            before = int(w.searches[0])
            status = advance(m, w, y, t_end, settings, memory, grid)
            calls.append((w.track_peaks[0] == 0.0, int(w.searches[0]) - before))
            return status
        return recorded

    monkeypatch.setattr(drive, "advance", recording(drive.advance))
    monkeypatch.setattr(drive, "advance_window", recording(drive.advance_window))
    run = run_coastdown(read_machine("paper_rig").for_batch(), until_stop=False, duration=0.3)
    windows = [searches for is_window, searches in calls if is_window]
    drop = [searches for is_window, searches in calls if not is_window]
    assert len(windows) >= 5 and windows == [0] * len(windows)
    assert sum(drop) > 0  # the drop's impacts are refined as before
    assert run.summary["verdict"] == "ok"
