# Two commands need nothing but Python 3.11+: `make demo` and `make test`.
PYTHON ?= python3

# Bytecode is written once and read by every process a run starts (the tests start hundreds: the command line,
# kernels of lessons and grading platforms), where an environment that sets PYTHONDONTWRITEBYTECODE would have
# each of them compile graphkin again (about 0.7 s of CPU a process that imports its exercises and drawings).
unexport PYTHONDONTWRITEBYTECODE
VENV   := .venv
BIN    := $(VENV)/bin

.PHONY: demo test check check-lowest lint docs e2e bench figures clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

$(VENV)/.installed: pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $@

# The demo needs the core only: what `pip install graphkin` gives.
$(VENV)/.core: pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e .
	touch $@

demo: $(VENV)/.core
	$(BIN)/graphkin solve double_slider -o build/double_slider.png
	@echo "graphkin is installed in $(VENV), not on your PATH: run $(BIN)/graphkin list, or 'source $(BIN)/activate' once and then graphkin list"

# Every test, the lessons and the docstring examples, on every core (a module's tests stay on one worker, so an
# expensive module fixture, such as a grading platform's run, is made once).
PYTEST := $(BIN)/python -m pytest -q -n auto --dist loadfile

test: $(VENV)/.installed
	$(PYTEST) --nbmake --nbmake-timeout=300 --doctest-modules graphkin tests lessons

# All but the slow tests (real grading platforms, fuzzers, concurrency, figure overlaps, PDF measurements), and the linters: a quick check while working.
check: $(VENV)/.installed lint
	$(PYTEST) -m "not slow" --doctest-modules graphkin tests

# `make check`'s tests on the oldest versions pyproject.toml allows: each dependency graphkin names at its floor
# (uv's lowest-direct resolution; what those need, at its newest), in a venv of its own, on 2 workers. A floor
# that fails here is not true: raise it (docs/install.md).
LOWEST := .venv-lowest

$(LOWEST)/.installed: pyproject.toml
	rm -rf $(LOWEST)
	$(PYTHON) -m venv $(LOWEST)
	$(LOWEST)/bin/python -m pip install --quiet uv
	$(LOWEST)/bin/uv pip install --quiet --python $(LOWEST)/bin/python --resolution lowest-direct -e '.[test]'
	touch $@

check-lowest: $(LOWEST)/.installed
	$(LOWEST)/bin/python -m pip list 2>/dev/null | grep -iE '^(numpy|shapely|pint|matplotlib|tqdm|typst|latex2mathml|orjson) '
	$(LOWEST)/bin/python -m pytest -q -n 2 --dist loadfile -m "not slow" --doctest-modules graphkin tests

lint: $(VENV)/.installed
	$(BIN)/ruff check graphkin tests benchmarks figures
	$(BIN)/lint-imports

# The documentation site: the guide (docs/), the lessons run as it is built, the API from the docstrings.
# Warnings are errors, so a broken link between pages or a lesson that fails stops the build. A lesson runs again
# only when it, graphkin or an installed package changed (its outputs are kept in build/.docs-cache), and the
# lessons that must run do so on every core before the pages are read (docs/lesson_cache.py). The site must be
# whole offline, its widgets drawn: tests/docs/ checks every page of it.
$(VENV)/.docs: $(VENV)/.installed
	$(BIN)/python -m pip install --quiet -e '.[test,docs]'
	touch $@

docs: $(VENV)/.docs
	$(BIN)/python -m sphinx -W --keep-going -j auto -q -b html -c docs . build/docs
	GRAPHKIN_DOCS_SITE=build/docs $(BIN)/python -m pytest -q -p no:cacheprovider tests/docs
	@echo "the site is in build/docs (open build/docs/index.html)"

# The lessons (cell by cell in JupyterLab, and in Voilà) and `graphkin explore` in a real browser:
# Debian's chromium driven by Playwright's Python package. Root installs chromium where it is missing;
# `playwright install` is never run (it downloads a browser build). Screenshots and timings: build/e2e/.
CHROMIUM ?= /usr/bin/chromium

$(VENV)/.e2e: $(VENV)/.installed
	$(BIN)/python -m pip install --quiet -e '.[test,e2e]'
	touch $@

e2e: $(VENV)/.e2e
	@if [ ! -x "$(CHROMIUM)" ]; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    echo "installing chromium (apt-get)"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null; \
	  else \
	    echo "make e2e needs Chromium at $(CHROMIUM): apt-get install chromium, or make e2e CHROMIUM=/path/to/it"; \
	    exit 1; \
	  fi; \
	fi
	GRAPHKIN_CHROMIUM=$(CHROMIUM) $(BIN)/python -m pytest -q -s tests/e2e

figures: $(VENV)/.installed
	$(BIN)/python figures/build.py

bench: $(VENV)/.installed
	$(BIN)/python -m pip install --quiet -e '.[test,bench]'
	$(BIN)/python benchmarks/bench_fourbar.py
	$(BIN)/python benchmarks/bench_graphical.py
	$(BIN)/python benchmarks/bench_polygons.py
	$(BIN)/python benchmarks/bench_cycle.py
	$(BIN)/python benchmarks/bench_explorer.py
	$(BIN)/python benchmarks/bench_exercises.py
	$(BIN)/python benchmarks/fuzz_grader.py
	$(BIN)/python benchmarks/bench_export.py
	$(BIN)/python benchmarks/bench_handout.py
	$(BIN)/python benchmarks/bench_cli.py
	$(BIN)/python benchmarks/bench_animate.py
	$(BIN)/python benchmarks/bench_figure.py
	$(BIN)/python benchmarks/bench_study.py
	$(BIN)/python benchmarks/bench_scene.py

clean:
	rm -rf $(VENV) $(LOWEST) build *.egg-info
