# ballscrew: the two set-up commands are `make demo` and `make test`.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
DEMO   := results/demo

.PHONY: demo test docs bench lint format clean

CHROMIUM := /usr/bin/chromium

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e ".[test]"
	touch $(STAMP)

## demo: create .venv, install, run the flagship example and write its report
demo: $(STAMP)
	$(VENV)/bin/ballscrew contact examples/gao2019_tcr.toml --out $(DEMO)/contact
	$(VENV)/bin/ballscrew tcr examples/gao2019_tcr.toml --out $(DEMO)/tcr
	$(VENV)/bin/ballscrew sweep examples/sweeps/fig13_tcr_vs_axial_load.toml --out $(DEMO)/fig13
	$(VENV)/bin/ballscrew thermal examples/gao2019_tcr.toml --out $(DEMO)/thermal
	$(VENV)/bin/ballscrew operating-point examples/gao2019_tcr.toml --speed "1500 rpm" \
		--axial-load "2 kN" --out $(DEMO)/operating-point
	$(VENV)/bin/ballscrew duty examples/gao2019_tcr.toml --out $(DEMO)/duty
	$(VENV)/bin/ballscrew check examples/gao2019_tcr.toml --out $(DEMO)/check
	$(VENV)/bin/ballscrew kinematics examples/wear_step_stress.toml --out $(DEMO)/kinematics
	$(VENV)/bin/ballscrew wear examples/wear_step_stress.toml --out $(DEMO)/wear
	$(VENV)/bin/ballscrew surface examples/profiles/synthetic_wm_D1.59_G9e-10.sdf --out $(DEMO)/surface
	$(VENV)/bin/ballscrew index $(DEMO) --title "ballscrew demo: the reference screws"
	@echo "report: $(DEMO)/index.html (links each analysis's own report.html)"

# Debian's chromium for the browser test of the reports (tests/results/test_browser.py)
$(CHROMIUM):
	@if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
		apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium; \
	else echo "chromium missing and not installable here: the browser test will be skipped"; fi

## test: create .venv, install, run the test suite
test: $(STAMP) $(CHROMIUM)
	$(VENV)/bin/ruff check src tests benchmarks
	$(VENV)/bin/lint-imports
	$(PY) -m pytest -q

DOCS_STAMP := $(VENV)/.docs-installed

$(DOCS_STAMP): $(STAMP)
	$(PY) -m pip install --quiet -e ".[docs]"
	touch $(DOCS_STAMP)

## docs: build the documentation site into site/ (warnings are errors; runs the tutorials)
docs: $(DOCS_STAMP)
	$(VENV)/bin/mkdocs build --strict
	@echo "site: site/index.html"

# The contact benchmark's peer, Tamaas 2.9.0 (AGPL: only timed, never imported by the package),
# lives in its own environment beside ballscrew; without it the recorded times are printed.
PEERS       := .venv-peers
PEERS_STAMP := $(PEERS)/.installed

$(PEERS_STAMP): pyproject.toml
	$(PYTHON) -m venv $(PEERS)
	$(PEERS)/bin/python -m pip install --quiet -e .
	$(PEERS)/bin/python -m pip install --quiet "tamaas==2.9.0" \
		|| echo "Tamaas not installable here: bench_contact prints its recorded times (*)"
	touch $(PEERS_STAMP)

## bench: run the benchmarks (prints tables; not part of the tests)
bench: $(STAMP) $(PEERS_STAMP)
	$(PEERS)/bin/python benchmarks/bench_contact.py
	$(PY) benchmarks/bench_tcr.py
	$(PY) benchmarks/bench_sweep.py
	$(PY) benchmarks/bench_thermal.py
	$(PY) benchmarks/bench_wear.py
	$(PY) benchmarks/bench_operating_point.py
	$(PY) benchmarks/bench_design.py
	$(PY) benchmarks/bench_design_check.py
	$(PY) benchmarks/bench_duty.py
	$(PY) benchmarks/bench_batch.py
	$(PY) benchmarks/bench_ball_batch.py

lint: $(STAMP)
	$(VENV)/bin/ruff check src tests benchmarks
	$(VENV)/bin/lint-imports
	$(VENV)/bin/ruff format --check src tests benchmarks

format: $(STAMP)
	$(VENV)/bin/ruff format src tests benchmarks
	$(VENV)/bin/ruff check --fix src tests benchmarks

clean:
	rm -rf $(VENV) results site .cache .pytest_cache .ruff_cache
