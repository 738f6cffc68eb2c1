# Two commands on a fresh machine:  make report   and   make test
# Everything runs from .venv, installed from the pinned requirements.lock.

PYTHON    ?= python3
VENV      := .venv
BIN       := $(VENV)/bin
STAMP     := $(VENV)/.installed
CORES     ?= all
# Debian packages: pango and fonts for WeasyPrint (PDF); chromium and poppler for the tests.
DEBS_REPORT := libpango-1.0-0 libpangoft2-1.0-0 fonts-dejavu-core
DEBS_TEST   := $(DEBS_REPORT) chromium poppler-utils

.PHONY: report test venv lock bench dist clean system-report system-test

report: venv system-report
	$(BIN)/snakemake --cores $(CORES)
	@echo
	@echo "HTML: $(CURDIR)/results/report.html"
	@echo "PDF:  $(CURDIR)/results/report.pdf"

test: venv system-test
	$(BIN)/python -m pytest

venv: $(STAMP)

$(STAMP): requirements.lock pyproject.toml
	test -d $(VENV) || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade "pip>=24"
	$(BIN)/python -m pip install --quiet --require-virtualenv -r requirements.lock
	$(BIN)/python -m pip install --quiet --require-virtualenv --no-deps --no-build-isolation -e .
	touch $@

# Installs missing Debian packages when run as root; otherwise says what to install.
system-report system-test: system-%:
	@missing=""; for p in $(DEBS_$(shell echo $* | tr a-z A-Z)); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then echo "apt-get install$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	  else echo "Missing Debian packages:$$missing  (sudo apt-get install$$missing)"; exit 1; fi; fi

bench: venv
	$(BIN)/python benchmarks/solver_speed.py
	$(BIN)/python benchmarks/chandler_wobble.py
	$(BIN)/python benchmarks/precession_cycle.py
	$(BIN)/python benchmarks/sine_cosine_integrals.py
	$(BIN)/python benchmarks/pipeline_build.py
	$(BIN)/python benchmarks/pipeline_scaling.py
	$(BIN)/python benchmarks/bad_input.py

dist: venv
	$(BIN)/snakemake --cores 1 dist

# Re-pin after changing dependencies in pyproject.toml.
lock: venv
	{ echo "# Every Python package the project installs, pinned (pip freeze of a working .venv, Python 3.11)."; \
	  echo "# Regenerate: make lock"; $(BIN)/python -m pip freeze --all --exclude-editable | grep -v "^pip=="; } > requirements.lock

clean:
	rm -rf results .snakemake
