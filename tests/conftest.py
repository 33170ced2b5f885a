import os

os.environ.setdefault("MPLBACKEND", "Agg")

from hypothesis import settings

# The property tests draw the same examples on every run, so CI's outcome never depends on the draw; set
# HYPOTHESIS_PROFILE=explore to search fresh examples while working on a property.
settings.register_profile("repeatable", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repeatable"))
