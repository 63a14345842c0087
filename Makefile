# Thin wrapper over CMake. See README.md.
BUILD ?= build
JOBS ?= $(shell nproc)
SCENES := $(wildcard scenes/*.toml)
SWEEPS := $(wildcard sweeps/*.toml)

.PHONY: all deps configure build bookspin class wheel npm figures test check render bench bench-explorer bench-taps update-goldens clean
all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

# Everything: the program, the benchmark, the example and every test program.
build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The program alone: what figures and render run. The test programs and the benchmark are
# built by `make test` and `make bench`, so a first `make figures` does not wait for them.
bookspin: configure
	cmake --build $(BUILD) -j $(JOBS) --target bookspin

# The class server (docs/class.md, "The teacher's steps"): the program, the Python module the
# class's pooled fit runs in and the page the phones get (out/explorer.html, written where it is
# missing or older than the page's program), then the command that starts the class.
class: bookspin
	cmake --build $(BUILD) -j $(JOBS) --target bookspin_python
	bash web/build.sh $(BUILD)
	@if [ ! -f out/explorer.html ] || [ $(BUILD)/web/explorer-shell.html -nt out/explorer.html ]; then \
	  echo "$(BUILD)/bookspin explore scenes/*.toml -o out"; $(BUILD)/bookspin explore scenes/*.toml -o out; fi
	@echo "class: ready: $(BUILD)/bookspin-class starts the class (docs/class.md, \"The teacher's steps\")"

# The Python wheel (docs/python.md, "The wheel"): BUILD/dist/bookspin-VERSION-cp311-*.whl, the
# module with its stub and the flipcheck scenarios, packed offline; pip installs it anywhere.
wheel: configure
	cmake --build $(BUILD) -j $(JOBS) --target bookspin_wheel

# The npm package flipcheck (docs/flipcheck.md, "In your engine's tests"): BUILD/npm/flipcheck-VERSION.tgz,
# the judge and the exact motion compiled by emscripten (npm/build.sh).
npm: bookspin
	bash npm/build.sh $(BUILD)

# The sweeps, the engines' accuracy report, the explorer page (where emscripten and npm are
# installed), then every scene rendered and plotted and the gallery: scripts/figures.sh, which
# the figures test runs with --quick.
figures: bookspin
	bash scripts/figures.sh $(BUILD) out

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The format check (scripts/check-format.sh), then the unit tier alone (tests/README.md): no
# package step, no GL, no program runs; seconds once built.
check:
	bash scripts/check-format.sh
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j $(JOBS) --target unit_tests
	cd $(BUILD) && ctest -L unit --output-on-failure -j $(JOBS)

render: bookspin
	$(BUILD)/bookspin render $(SCENE) -o out

# Pipeline against the encoder alone, resolutions, physics against MuJoCo and MuJoCo's renderer,
# memory (docs/performance.md): a table on stdout and out/bench.csv. Quiet machine, a few
# minutes.
bench: configure
	cmake --build $(BUILD) -j $(JOBS) --target bookspin-bench
	$(BUILD)/bookspin-bench -o out

# The explorer page against the native build (bench/explorer_bench.py, docs/explorer.md): ns
# per step of each method in WebAssembly (headless Chromium) and natively, alternated in one
# run, and the page's frames per second at 1280×720; a table on stdout and
# bench/results/explorer-MACHINE.csv. EXPLORER=path/to/explorer.html times that page instead
# of building out/explorer.html.
EXPLORER ?=
PYTHON ?= /usr/bin/python3
bench-explorer: configure
	cmake --build $(BUILD) -j $(JOBS) --target bookspin-bench bookspin
	@if [ -z "$(EXPLORER)" ]; then \
	  bash web/build.sh $(BUILD) && $(BUILD)/bookspin explore $(SCENES) $(SWEEPS) -o out; fi
	$(PYTHON) bench/explorer_bench.py $(or $(EXPLORER),out/explorer.html) $(BUILD)/bookspin-bench

# Each tap's interaction duration in the explorer and its lab (bench/tap_bench.py,
# docs/performance.md "Taps"): headless Chromium at 390x844, unthrottled and the CPU slowed 4x.
bench-taps: configure
	cmake --build $(BUILD) -j $(JOBS) --target bookspin
	@if [ -z "$(EXPLORER)" ]; then \
	  bash web/build.sh $(BUILD) && $(BUILD)/bookspin explore scenes/exact-unstable-x.toml \
	    scenes/fig09-matrix-unstable-x.toml -o out/taps; fi
	$(PYTHON) bench/tap_bench.py $(or $(EXPLORER),out/taps/explorer.html)

# Rewrites tests/golden/ from the current build (on llvmpipe, the reference) and prints, for
# each golden, whether it is new, unchanged or changed (PSNR, share of differing pixels).
update-goldens: configure
	cmake --build $(BUILD) -j $(JOBS) --target picture_tests
	BOOKSPIN_UPDATE_GOLDENS=1 $(BUILD)/tests/picture_tests --gtest_brief=1

clean:
	rm -rf $(BUILD) out/*/ out/*.mp4 out/.logs
