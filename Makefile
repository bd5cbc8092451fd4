# The two quick-start commands: `make demo` and `make test`. Both set up what they need.
PYTHON  ?= python3
VENV    := .venv
PY      := $(VENV)/bin/python
BUILD   := build
RESULTS := results
JOBS    ?= 2
FUZZ_SECONDS ?= 3600

.PHONY: all venv build demo test pytest check-c fuzz-smoke fuzz bench references clean

all: build

# A local virtual environment with the pinned Python tools (FMPy also supplies the FMI headers).
$(VENV)/.installed: requirements.txt
	@$(PYTHON) -c 'import sys; sys.exit(sys.version_info < (3, 10))' || \
	  { echo "Python >= 3.10 is needed (FMPy 0.3.32)"; exit 1; }
	@$(PYTHON) -m venv $(VENV) || \
	  { echo "Could not create a virtual environment: on Debian install python3-venv"; exit 1; }
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -r requirements.txt
	@touch $@

venv: $(VENV)/.installed

build: venv
	cmake -S . -B $(BUILD) -DPython3_EXECUTABLE=$(abspath $(PY))
	cmake --build $(BUILD) --parallel $(JOBS)

demo: build
	$(PY) demo/run_demo.py --fmus fmus --out $(RESULTS)

# The whole suite: the FMPy/pytest tests, the C harness (plain, sanitizers, valgrind) and a
# bounded fuzz run per block.
test: pytest check-c fuzz-smoke

pytest: build
	$(PY) -m pytest tests

check-c: build
	tests/c/check.sh

fuzz-smoke: venv
	tests/fuzz/run.sh 60

# Long fuzzing, FUZZ_SECONDS per block.
fuzz: venv
	tests/fuzz/run.sh $(FUZZ_SECONDS)

# Speed of each FMU, printed (not asserted): ns per PLC call, µs per doStep, × real time.
bench: build
	$(PY) benchmarks/bench.py

# Regenerates the committed regression results from the current FMUs; review the diff.
references: build
	$(PY) demo/run_demo.py --fmus fmus --references tests/references

clean:
	rm -rf $(BUILD) $(BUILD)-* fmus $(RESULTS)
