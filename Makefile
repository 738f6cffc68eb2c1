# Two commands on a fresh machine:  make report   and   make test
# Everything runs from .venv, installed from the lock files (pinned, with hashes): requirements/pipeline.lock for
# the report, requirements/test.lock for what the tests add.

PYTHON    ?= python3
VENV      := .venv
BIN       := $(VENV)/bin
STAMP     := $(VENV)/.installed
TEST_STAMP := $(VENV)/.installed-test
SLURM_STAMP := $(VENV)/.installed-slurm
CORES     ?= all
# Debian packages: pango and fonts for WeasyPrint (PDF); chromium and poppler for the tests.
DEBS_REPORT := libpango-1.0-0 libpangoft2-1.0-0 fonts-dejavu-core
DEBS_TEST   := $(DEBS_REPORT) chromium poppler-utils

.PHONY: report test test-slurm coverage mutants lint format venv venv-test venv-slurm lock bench dist clean system-report system-test

report: venv system-report
	$(BIN)/snakemake --cores $(CORES)
	@echo
	@echo "HTML: $(CURDIR)/results/report.html"
	@echo "PDF:  $(CURDIR)/results/report.pdf"

test: venv-test system-test
	$(BIN)/python -m pytest

# The pipeline through a real Slurm cluster started on this machine (tools/local-slurm; as root, it installs it).
test-slurm: venv-test venv-slurm system-test
	tools/local-slurm up
	$(BIN)/python -m pytest -m slurm

# Branch coverage of src/ by the fast tests (everything but the pipeline builds), printed per package.
coverage: venv-test
	rm -f .coverage .coverage.*
	$(BIN)/python -m coverage run -m pytest -m "not pipeline and not slurm" -q
	$(BIN)/python tools/coverage_by_package.py

# Mutation testing of the studies' and models' Python code by the fast tests (mutmut): the score per package and
# the surviving mutants. A benchmark, not a gate: it runs long. All 59 000 mutants take days of CPU, so it checks
# MUTANTS_PER_PACKAGE of each package, drawn with a fixed seed (0: all), each score with its 95 % interval.
MUTANTS_PER_PACKAGE ?= 40
mutants: venv-test
	rm -rf mutants
	$(BIN)/python tools/mutants.py --sample $(MUTANTS_PER_PACKAGE)

# One format and one lint for the tree (ruff, configured in pyproject.toml): `make format` applies both's fixes.
lint: venv-test
	$(BIN)/ruff format --check .
	$(BIN)/ruff check .

format: venv-test
	$(BIN)/ruff format .
	$(BIN)/ruff check --fix .

venv: $(STAMP)
venv-test: $(TEST_STAMP)
# Snakemake's Slurm executor, only where a cluster is used (installed, every snakemake start asks Slurm for its state)
venv-slurm: $(SLURM_STAMP)

$(STAMP): requirements/pipeline.lock pyproject.toml
	test -d $(VENV) || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade "pip>=24"
	$(BIN)/python -m pip install --quiet --require-virtualenv --require-hashes -r requirements/pipeline.lock
	$(BIN)/python -m pip install --quiet --require-virtualenv --no-deps --no-build-isolation -e .
	touch $@

$(TEST_STAMP): $(STAMP) requirements/test.lock
	$(BIN)/python -m pip install --quiet --require-virtualenv --require-hashes -r requirements/test.lock
	touch $@

$(SLURM_STAMP): $(STAMP) requirements/slurm.lock
	$(BIN)/python -m pip install --quiet --require-virtualenv --require-hashes -r requirements/slurm.lock
	touch $@

# Installs missing Debian packages when run as root; otherwise says what to install.
system-report system-test: system-%:
	@missing=""; for p in $(DEBS_$(shell echo $* | tr a-z A-Z)); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then echo "apt-get install$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	  else echo "Missing Debian packages:$$missing  (sudo apt-get install$$missing)"; exit 1; fi; fi

bench: venv-test
	$(BIN)/python benchmarks/solver_speed.py
	$(BIN)/python benchmarks/chandler_wobble.py
	$(BIN)/python benchmarks/precession_cycle.py
	$(BIN)/python benchmarks/sine_cosine_integrals.py
	$(BIN)/python benchmarks/effect_cost.py
	$(BIN)/python benchmarks/pipeline_build.py
	$(BIN)/python benchmarks/pipeline_scaling.py
	$(BIN)/python benchmarks/bad_input.py
	$(BIN)/python benchmarks/pdf_render.py
	$(BIN)/python benchmarks/speed_goals.py

dist: venv
	$(BIN)/snakemake --cores 1 dist

# Re-pin after changing dependencies in pyproject.toml (pip-tools, in a venv of its own).
lock:
	test -d .venv-lock || $(PYTHON) -m venv .venv-lock
	.venv-lock/bin/python -m pip install --quiet pip-tools
	.venv-lock/bin/python tools/lock.py

clean:
	rm -rf results .snakemake
