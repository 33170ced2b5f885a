import os

import pytest

os.environ.setdefault("MPLBACKEND", "Agg")


def pytest_collection_modifyitems(items):
    """Under pytest-xdist (`make test` runs on every core), a module whose tests share a module-scoped
    fixture (a verification, a coast-down) keeps them on one worker, so that fixture is computed once."""
    for item in items:
        info = getattr(item, "_fixtureinfo", None)
        if info and any(d.scope == "module" for defs in info.name2fixturedefs.values() for d in defs):
            item.add_marker(pytest.mark.xdist_group(item.module.__name__))
