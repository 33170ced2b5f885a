import os

from xdist.scheduler import LoadFileScheduling

os.environ.setdefault("MPLBACKEND", "Agg")

from hypothesis import settings

# The property tests draw the same examples on every run, so CI's outcome never depends on the draw; set
# HYPOTHESIS_PROFILE=explore to search fresh examples while working on a property.
settings.register_profile("repeatable", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repeatable"))


#: Files of long, independent tests that `make test` hands to its workers one test at a time; every other file runs
#: whole on one worker, as pytest-xdist's --dist loadfile does, so a module fixture is computed once. The
#: reduced/full coast-down comparisons are ten tests of 25-60 s: run as one file, they kept one worker busy for
#: about 330 s of the suite's 560 s.
SPREAD = {"tests/consistency/test_coastdown_reduced.py", "tests/consistency/test_coastdown_tail.py",
          "tests/cli/test_campaign_cli.py", "tests/consistency/test_elastic_rotor.py"}


def _file_of(nodeid: str) -> str:
    return nodeid.split("::", 1)[0]


class _FileOrTestScheduling(LoadFileScheduling):
    """--dist loadfile, but a file in :data:`SPREAD` is split into its tests (pytest-xdist's scheduler hook;
    its own --dist loadgroup marks cannot do it under pytest 9.2, whose test ids no longer take xdist's suffix)."""

    def _split_scope(self, nodeid: str) -> str:
        path = _file_of(nodeid)
        return nodeid if path in SPREAD else path


def pytest_xdist_make_scheduler(config, log):
    if config.getvalue("dist") == "loadfile":
        return _FileOrTestScheduling(config, log)
    return None


def pytest_collection_modifyitems(config, items):
    """Files holding slow tests first, each in its own order (a stable sort). pytest-xdist sends the files with
    the most tests first and keeps this order among files of as many tests: the spread tests, units of one test
    each, come last, the long ones among them first. (Kept in this order throughout, --no-loadscope-reorder,
    the CI took 809 s; in xdist's order 743 s, and 807 s later the same evening: the machine's drift, not the
    order.)"""
    slow_files = {_file_of(item.nodeid) for item in items if item.get_closest_marker("slow")}
    items.sort(key=lambda item: _file_of(item.nodeid) not in slow_files)
