# Two commands need nothing but Python 3.11+: `make demo` and `make test`.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin

.PHONY: demo test bench figures clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

$(VENV)/.installed: pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $@

demo: $(VENV)/.installed
	$(BIN)/graphkin solve double_slider --figure build/double_slider.png

test: $(VENV)/.installed
	$(BIN)/python -m pytest -q --nbmake --nbmake-timeout=300 --doctest-modules graphkin tests lessons

figures: $(VENV)/.installed
	$(BIN)/python figures/build.py

bench: $(VENV)/.installed
	$(BIN)/python -m pip install --quiet -e '.[test,bench]'
	$(BIN)/python benchmarks/bench_fourbar.py
	$(BIN)/python benchmarks/bench_graphical.py
	$(BIN)/python benchmarks/bench_cycle.py
	$(BIN)/python benchmarks/bench_explorer.py
	$(BIN)/python benchmarks/bench_exercises.py
	$(BIN)/python benchmarks/fuzz_grader.py
	$(BIN)/python benchmarks/bench_export.py

clean:
	rm -rf $(VENV) build *.egg-info
