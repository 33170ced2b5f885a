# Two commands on a fresh machine: `make verify` (the main job: verify the example blower's touchdown
# bearings into verify/report.html) and `make test` (all tests). `make study` reproduces the source paper.
# `make quick` is the edit loop: ruff, then every test not marked slow (30 s or less once the kernels are cached).
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed-stamp
ROSS_STAMP := $(VENV)/.ross-stamp
KERNELS_STAMP := $(VENV)/.kernels-stamp
# The compiled core's cache folder is named after these files (auxbearing.core.source_fingerprint)
CORE_SOURCES := $(wildcard src/auxbearing/core/*.py)
OUT ?= study
VERIFY_OUT ?= verify
MACHINE ?= blower
# Tests keep their compiled bytecode (pytest's assertion rewrite included) even where the environment sets
# PYTHONDONTWRITEBYTECODE: recompiling ~220 modules on every run cost 5 s of the quick loop's collection.
TEST_ENV := PYTHONDONTWRITEBYTECODE=

.PHONY: verify study test quick lint bench clean kernels

$(STAMP): pyproject.toml
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[dev]'
	@touch $(STAMP)

# The tests also read rotors saved by ROSS: its optional extra (about 30 s more to install), for `make test` only.
$(ROSS_STAMP): $(STAMP)
	$(BIN)/python -m pip install --quiet -e '.[dev,ross]'
	@touch $(ROSS_STAMP)

verify: $(KERNELS_STAMP)
	@# exit 1 (FAIL) and 3 (INCOMPLETE) are verdicts, not errors of the job; 2 is bad input
	$(BIN)/auxbearing verify --machine $(MACHINE) --out $(VERIFY_OUT); s=$$?; test $$s -eq 0 -o $$s -eq 1 -o $$s -eq 3
	@echo "Verification: $(VERIFY_OUT)/report.html (open it in a browser); verdicts in $(VERIFY_OUT)/verify.json"

study: $(KERNELS_STAMP)
	$(BIN)/auxbearing study --out $(OUT)
	@echo "Study output: $(OUT)/report.html (open it in a browser); data, figures and results.json in $(OUT)/"

# Compile the kernels once after an install or a change to the core, before anything runs them: on a fresh
# machine every test worker compiled them at the same time (about 3 minutes of the CI's wall time), and the
# verification's two workers did the same before its first case. Two lines side by side on the two cores: the
# two-plane drop and coast-down (about 2 minutes from cold; the paper rig's 0.15 s drop and one coast-down window,
# which has its own integrator) then a levitated start (the right-hand side called
# from Python, which its steady orbit linearises), and the small kernels then the three-plane specialisation the
# open-machine tests use (which took a test worker 75 s). Runs in a scratch folder; the stamp follows the core's
# sources as the cache folder's name does, so `make verify` after that loads them in seconds.
kernels: $(KERNELS_STAMP)

$(KERNELS_STAMP): $(STAMP) $(CORE_SOURCES)
	@echo "Compiling the kernels: once after an install or a change to src/auxbearing/core, about two minutes"
	@d=$$(mktemp -d); A=$(CURDIR)/$(BIN)/auxbearing; cd $$d || exit 1; \
	  { $$A drop --duration '0.1 ms' --quiet >/dev/null && $$A coastdown --machine paper_rig --duration 0.17 --quiet \
	    >/dev/null && $$A drop --machine blower --scenario surge --duration '0.1 ms' --quiet >/dev/null; } & first=$$!; \
	  $$A static --radial 1000 >/dev/null && $$A contact >/dev/null && (cd $(CURDIR) && $(BIN)/python -c \
	    "from auxbearing.analysis.coastdown import run_coastdown; from tests.consistency.test_open_machine import \
	    FAR_PLANE, _blower; run_coastdown(_blower(FAR_PLANE, duration='0.1 ms'), until_stop=False, duration=0.01); \
	    from auxbearing.analysis.drop import run_machine; run_machine('paper_rig', duration='0.1 ms', lean=True)"); \
	  second=$$?; wait $$first; s=$$?; cd / && rm -rf $$d; test $$s -eq 0 -a $$second -eq 0
	@touch $(KERNELS_STAMP)

test: $(STAMP) $(ROSS_STAMP) $(KERNELS_STAMP)
	$(BIN)/ruff check src tests benchmarks
	$(TEST_ENV) $(BIN)/python -m pytest -n logical --dist loadfile --durations=15

quick: $(STAMP)
	$(BIN)/ruff check src tests benchmarks
	$(TEST_ENV) $(BIN)/python -m pytest -n logical --dist loadfile -m "not slow"

bench: $(STAMP)
	$(BIN)/python benchmarks/run.py

clean:
	rm -rf $(VENV) $(OUT) $(VERIFY_OUT) out .pytest_cache .ruff_cache
	find src -name "*.nbi" -o -name "*.nbc" | xargs rm -f  # numba caches do not see edits in imported modules
