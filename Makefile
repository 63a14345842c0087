# Thin wrapper over CMake. See README.md.
BUILD ?= build
JOBS ?= $(shell nproc)
SCENES := $(wildcard scenes/*.toml)
SWEEPS := $(wildcard sweeps/*.toml)

.PHONY: all deps configure build bookspin figures test check render bench bench-explorer update-goldens clean
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

# The sweeps first, so that the one gallery render-all writes at the end shows it too
# (GALLERY_EXTRA: scene files the gallery lists beside the rendered ones); then the explorer
# page (web/build.sh builds its program, bookspin explore writes the scenes into it;
# docs/explorer.md), so that the gallery links each clip to it.
figures: bookspin
	$(BUILD)/bookspin sweep sweeps/flip-time-vs-perturbation.toml \
	  --vary 'initial.angular_velocity[1]=1e-6:1e-2:20:log' \
	  --measure first_flip,flip_period,energy_drift,orientation_error -o out
	$(BUILD)/bookspin sweep sweeps/t-handle-flip-time-vs-perturbation.toml \
	  --vary 'initial.angular_velocity[0]=1e-6:1e-2:20:log' \
	  --measure first_flip,flip_period,energy_drift,orientation_error -o out
	for f in sweeps/when-to-normalize*.toml; do \
	  $(BUILD)/bookspin sweep $$f --vary 'time.dt=0.0020833333333333333:0.125:7:log' \
	    --vary 'model.normalize_every=1:10000:9:log' \
	    --measure orientation_error,diverged_at -o out || exit 1; \
	done
	$(BUILD)/bookspin sweep sweeps/tennis-racket-twist.toml \
	  --vary 'initial.angular_velocity[0]=1e-3:3:25:log' --measure twist,flip_period -o out
	$(BUILD)/bookspin accuracy sweeps/engines-energy-vs-dt.toml \
	  --methods engines,rigid-quaternion:rk4,rigid-quaternion:implicit-midpoint,rigid-quaternion:splitting4 \
	  --dt 0.03333333333333333 0.016666666666666666 0.008333333333333333 0.004 0.002 0.001 \
	  0.0005 0.00025 -o out
	@if command -v em++ >/dev/null && command -v npm >/dev/null; then \
	  bash web/build.sh $(BUILD) && $(BUILD)/bookspin explore $(SCENES) $(SWEEPS) -o out; \
	else echo "figures: no emscripten or npm: out/explorer.html not made (scripts/install-deps.sh)"; fi
	@GALLERY_EXTRA="$(SWEEPS)" bash scripts/render-all.sh $(BUILD)/bookspin out $(SCENES)

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

# Rewrites tests/golden/ from the current build (on llvmpipe, the reference) and prints, for
# each golden, whether it is new, unchanged or changed (PSNR, share of differing pixels).
update-goldens: configure
	cmake --build $(BUILD) -j $(JOBS) --target picture_tests
	BOOKSPIN_UPDATE_GOLDENS=1 $(BUILD)/tests/picture_tests --gtest_brief=1

clean:
	rm -rf $(BUILD) out/*/ out/*.mp4 out/.logs
