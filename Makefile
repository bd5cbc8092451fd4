# The two quick-start commands: `make demo` and `make test`. Both set up what they need.
PYTHON  ?= python3
VENV    := .venv
PY      := $(VENV)/bin/python
# What runs before `make package` installs it (the demo, the references, the release) imports
# the package lgf_fmus of this tree, as the build's steps do (CMakeLists.txt: LGF_PYTHON).
TREE_PY := PYTHONPATH=$(CURDIR)/python $(PY)
BUILD   := build
RESULTS := results
JOBS    ?= 2
FUZZ_SECONDS ?= 3600
FUZZ_SMOKE_SECONDS ?= 120

.PHONY: all venv build demo test lint format pytest package package-test check-c fuzz-smoke fuzz bench bench-package descriptions references dist originals clean

# No "Entering directory" lines from the makes that CMake's build runs (MAKEFLAGS is exported).
MAKEFLAGS += --no-print-directory

all: build

# A local virtual environment with the pinned Python tools (FMPy also supplies the FMI headers).
$(VENV)/.installed: requirements.txt
	@$(PYTHON) -c 'import sys; sys.exit(sys.version_info < (3, 11))' || \
	  { echo "Python >= 3.11 is needed (numpy 2.4 of requirements.txt)"; exit 1; }
	@$(PYTHON) -m venv $(VENV) || \
	  { echo "Could not create a virtual environment: on Debian install python3-venv"; exit 1; }
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -r requirements.txt
	@touch $@

venv: $(VENV)/.installed

# The FMUs: first the cross builds, each in its own folder with its toolchain file and only when
# its compiler works with its C library (installed here when root): the win64 DLLs (mingw-w64)
# and the aarch64-linux libraries of the FMI 3.0 FMUs (FMI 2.0 has no platform name for aarch64
# Linux); then the native build, which packs them beside binaries/linux64 (x86_64-linux) and
# removes any fmus/*.fmu and fmus/fmi3/*.fmu that no block makes (cmake/prune-fmus.cmake).
# CMake's configure step shows only warnings and errors; the toolchain file is given to the
# first configure of a cross build only (CMake reads it once, and warns about it as unused after).
MINGW_CC := x86_64-w64-mingw32-gcc
AARCH64_CC := aarch64-linux-gnu-gcc
BUILD_WIN64 := $(BUILD)-win64
BUILD_AARCH64 := $(BUILD)-aarch64
NO_WIN64 := the FMUs get no binaries/win64
NO_AARCH64 := the FMI 3.0 FMUs get no binaries/aarch64-linux

# $(call cross,<shell variable>,<compiler>,<build folder>,<toolchain file>,<what is lost>):
# shell text that builds the libraries in <build folder> and sets <shell variable> to its path,
# or says what the FMUs lack without the compiler.
define cross
if printf '#include <math.h>\n' | $(2) -E -x c - >/dev/null 2>&1; then \
  $(1)=$(abspath $(3)); \
  toolchain=-DCMAKE_TOOLCHAIN_FILE=$(4); \
  [ ! -f $(3)/CMakeCache.txt ] || toolchain=; \
  ( set -x; cmake -S . -B $(3) $$toolchain --log-level=WARNING \
          -DPython3_EXECUTABLE=$(abspath $(PY)) -DLGF_DOCUMENTATION=OFF >/dev/null; \
    cmake --build $(3) --parallel $(JOBS) ); \
else \
  echo "NOTE: $(2) (with its C library) not found: $(5)"; \
fi;
endef

build: venv
	@tools/ensure-packages.sh $(MINGW_CC):gcc-mingw-w64-x86-64 \
	  $(AARCH64_CC):gcc-aarch64-linux-gnu libc6-dev-arm64-cross:libc6-dev-arm64-cross
	@set -e; win64=; aarch64=; \
	$(call cross,win64,$(MINGW_CC),$(BUILD_WIN64),cmake/mingw-w64.cmake,$(NO_WIN64)) \
	$(call cross,aarch64,$(AARCH64_CC),$(BUILD_AARCH64),cmake/aarch64-linux.cmake,$(NO_AARCH64)) \
	set -x; \
	cmake -S . -B $(BUILD) --log-level=WARNING -DPython3_EXECUTABLE=$(abspath $(PY)) \
	  -DWIN64_BINARIES_DIR=$$win64 -DAARCH64_BINARIES_DIR=$$aarch64 -DLGF_DOCUMENTATION=ON \
	  >/dev/null; \
	cmake --build $(BUILD) --parallel $(JOBS)

demo: build
	$(TREE_PY) -m demo.run_demo --fmus fmus --out $(RESULTS)

# The whole suite: the FMPy/pytest tests, the C harness (plain, sanitizers, valgrind) and a
# bounded fuzz run per block. tools/run-parts.sh runs every part even when an earlier one
# failed, then prints a table of the parts' results and durations; the exit status is non-zero
# if any failed. The build is its own part first, so that the parts' durations are their own
# (pytest and check-c still depend on it, as when they are made alone).
test:
	@tools/run-parts.sh \
	  lint       '$(MAKE) --no-print-directory lint' \
	  build      '$(MAKE) --no-print-directory build' \
	  pytest     '$(MAKE) --no-print-directory pytest' \
	  package    '$(MAKE) --no-print-directory package-test' \
	  check-c    '$(MAKE) --no-print-directory check-c' \
	  fuzz-smoke '$(MAKE) --no-print-directory fuzz-smoke'

# Style (docs/developing.md, Style): ruff checks and formats the Python (pyproject.toml's
# [tool.ruff]), clang-format the C (.clang-format); both are pinned in requirements.txt. `make lint`
# fails on any difference, `make format` applies both to the whole tree.
C_FILES = git ls-files '*.c' '*.h'

lint: venv
	$(VENV)/bin/ruff check .
	$(VENV)/bin/ruff format --check .
	$(C_FILES) | xargs $(VENV)/bin/clang-format --dry-run --Werror

format: venv
	$(VENV)/bin/ruff check --fix .
	$(VENV)/bin/ruff format .
	$(C_FILES) | xargs $(VENV)/bin/clang-format -i

# clang: tests/test_sources_build.py rebuilds every FMU from its sources/ with clang as well as
# gcc (installed here when root, else those tests are skipped with a note saying why). JOBS
# pytest workers (pytest-xdist), each taking whole files, so that a file's module fixtures (the
# rebuilt FMUs) are made once. The package is installed first: tests/scl compiles SCL with its
# lgf_fmus.scl, and tests/test_ids.py collects every test, those too.
pytest: package
	@tools/ensure-packages.sh clang:clang
	$(PY) -m pytest tests -n $(JOBS) --dist loadfile

check-c: build
	tests/c/check.sh

# The Python package lgf-fmus (pyproject.toml, python/), installed into .venv as `pip install .`
# would, but light: it bundles the FMUs `make build` made (LGF_PACKAGE_FMUS) instead of building
# them again, builds only its runner, in the persistent $(BUILD)-python, and is reinstalled only
# when its sources or the FMUs changed (the sub-make sees the FMUs the build just wrote).
PACKAGE_STAMP := $(VENV)/.lgf-fmus-installed
PACKAGE_SOURCES = pyproject.toml VERSION CMakeLists.txt python/CMakeLists.txt python/README.md \
                  $(wildcard python/runner/*.c python/lgf_fmus/*.py fmus/*.fmu fmus/*/*.fmu) \
                  $(wildcard python/lgf_fmus/scl/*.py python/lgf_fmus/scl/*.lark python/lgf_fmus/scl/*.txt \
                             python/lgf_fmus/scl/runtime/scl/*.h src/describe.c \
                             src/core/* src/iec/* src/fmi2/* src/fmi3/*)

package: build
	@$(MAKE) --no-print-directory $(PACKAGE_STAMP)

$(PACKAGE_STAMP): $(PACKAGE_SOURCES)
	$(PY) -m pip install --quiet --no-build-isolation -C build-dir=$(BUILD)-python \
	  -C cmake.define.LGF_PACKAGE_FMUS=$(abspath fmus) -C cmake.define.LGF_DOCUMENTATION=OFF .
	@touch $@

# The package's own tests, against the installed package (python/tests).
package-test: package
	$(PY) -m pytest python/tests

# FUZZ_SMOKE_SECONDS of fuzzing in all, shared by the blocks (at least 4 s and FUZZ_MIN_RUNS
# executions, 2000 for the smoke, each; two blocks at a time: see tests/fuzz/run.sh), so that
# the smoke's time does not grow with the catalogue.
BLOCK_COUNT = $(words $(wildcard src/blocks/*/interface.toml))
SMOKE_PER_BLOCK = $(shell n=$$(( $(FUZZ_SMOKE_SECONDS) / $(BLOCK_COUNT) )); echo $$(( n < 4 ? 4 : n )))

fuzz-smoke: venv
	FUZZ_MIN_RUNS=$${FUZZ_MIN_RUNS:-2000} tests/fuzz/run.sh $(SMOKE_PER_BLOCK)

# Long fuzzing, FUZZ_SECONDS per block.
fuzz: venv
	tests/fuzz/run.sh $(FUZZ_SECONDS)

# Cost of each FMU, printed (not asserted), measured in C by benchmarks/bench.c through dlopen:
# ns per PLC call, per one-call doStep, per get and per set, against plain C loops of the rules,
# and per get, set, serialize and deserialize of an FMU state; then the package benchmark.
# CALLGRIND=1 also counts instructions under valgrind (load-independent, slower);
# REFERENCE_FMU=<FMI 2.0 Feedthrough.fmu of the Modelica Reference FMUs> adds its get/set;
# BLOCKS="LGF_SinusCI ..." measures only those blocks. Then the SCL twins of the blocks with a
# scenario, compiled by lgf-fmus compile (hence the package), against the hand-written FMUs.
bench: package
	@$(if $(CALLGRIND),tools/ensure-packages.sh valgrind:valgrind)
	cmake -S . -B $(BUILD) -DLGF_BENCH=ON >/dev/null
	cmake --build $(BUILD) --target lgf_bench
	$(PY) -m benchmarks.bench --bench $(BUILD)/benchmarks/bench $(if $(CALLGRIND),--callgrind) \
		$(if $(BLOCKS),--blocks $(BLOCKS))
	@$(MAKE) --no-print-directory bench-package

# The package against a naive FMPy loop: the reference sweep with 1 and 2 Dask workers, and 1 h of
# 1 ms cycles through simulate (benchmarks/package_bench.py; printed, never asserted).
bench-package: package
	$(PY) -m benchmarks.package_bench

# The three-way check of the blocks against their original SCL (tests/originals/check.py): each
# original of the folder SCL (the LGF's TIA Portal exports, third-party code that stays outside
# the repository) compiled by lgf-fmus compile, against the hand-written FMU and the block's
# model on EXAMPLES random scenarios a block; a line per block. Not part of make test.
EXAMPLES ?= 200
originals: package
	@test -n "$(SCL)" || { echo "usage: make originals SCL=<folder of the LGF exports>"; exit 2; }
	$(PY) -m tests.originals.check --scl "$(SCL)" --examples $(EXAMPLES)

# Rewrites modelDescription/<Block>.xml and the interface table of each block's page
# (src/blocks/<Block>/README.md) from each block's interface table, and python/README.md from
# docs/python.md (tools/pages.py); review the diff.
descriptions: venv
	cmake -S . -B $(BUILD) -DPython3_EXECUTABLE=$(abspath $(PY)) >/dev/null
	cmake --build $(BUILD) --target descriptions
	$(PY) -m tools.pages --build $(BUILD)

# Regenerates the committed regression results from the current FMUs; review the diff.
references: build
	$(TREE_PY) -m demo.run_demo --fmus fmus --references

# The release zip dist/lgf-fmus-<version>.zip (version: VERSION): fmi2/ (and fmi3/ when built)
# with every FMU and its compatibility information, SHA256SUMS, LICENSE, CHANGELOG.md, and a
# README listing each folder's binaries (fmi2/: linux64, win64; fmi3/: x86_64-linux,
# x86_64-windows, aarch64-linux); stops if an FMU fails validation or its replayed reference
# result, or holds binaries its folder does not carry (release/dist.py).
dist: build
	$(TREE_PY) -m release.dist --fmus fmus --out dist

clean:
	rm -rf $(BUILD) $(BUILD)-* fmus $(RESULTS) dist
