# The README's two commands: `make run` (install what is missing, build, render the demo show)
# and `make test` (build, then every test; the unit tests again under ASan and UBSan).
BUILD      ?= build
ASAN_BUILD ?= build-asan
JOBS       ?= $(shell nproc)
DEMO       := examples/demo/demo.haze.json
HAZE       := $(BUILD)/app/haze

.PHONY: all deps configure build build-haze run test test-fast test-asan node-tools fuzz soak farm-test gui-parallel clean

all: build

deps:
	@tools/install-deps.sh

$(BUILD)/build.ninja:
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo

configure: deps $(BUILD)/build.ninja

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The program alone (and the libraries it links), not the tests: the demo renders as early as
# possible; `make test` builds the rest of the same tree later.
build-haze: configure
	cmake --build $(BUILD) -j $(JOBS) --target haze

run: build-haze
	@mkdir -p out
	$(HAZE) render $(DEMO) --all-cues -o out/
	@ls -1 out/*.png
	@if [ -n "$${DISPLAY:-}$${WAYLAND_DISPLAY:-}" ]; then $(HAZE) open $(DEMO); fi

# Everything: the unit tests under sanitizers, then the unit, render, CLI and GUI tests.
test: build test-asan node-tools
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 900

# Tools the tests use that this project did not write (JSON Schema validation, DMX senders),
# pinned by tests/node/package-lock.json.
node-tools: deps
	@[ -d tests/node/node_modules ] || npm ci --prefix tests/node --no-audit --no-fund

test-fast: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L unit

# The second tree is configured without the GUI (HAZE_BUILD_GUI=OFF: no GLFW, no ImGui), so
# CI proves the libraries and the headless program build without them. Under the sanitizers it
# runs the unit suites (one per pure library, no GL) and the headless program on the demo.
UNIT_SUITES := unit_core unit_atmosphere unit_fixtures unit_gdtf unit_scene unit_reference unit_shows unit_dmx unit_edit unit_import \
               unit_frame unit_mesh unit_output unit_xchange unit_fuzz_replay

$(ASAN_BUILD)/build.ninja:
	cmake -S . -B $(ASAN_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Debug -DHAZE_SANITIZE=ON -DHAZE_BUILD_GUI=OFF

test-asan: deps $(ASAN_BUILD)/build.ninja
	cmake --build $(ASAN_BUILD) -j $(JOBS) --target $(UNIT_SUITES) haze
	cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j $(JOBS) --timeout 900 -L '^unit/'
	@tools/headless_smoke.sh $(ASAN_BUILD)/app/haze

# libFuzzer on every parser (tools/fuzz.sh): FUZZ_SECONDS each, in build-fuzz (clang, ASan, UBSan).
FUZZ_SECONDS ?= 60
fuzz:
	@tools/install-deps.sh --fuzz
	tools/fuzz.sh $(FUZZ_SECONDS)

# The long versions of what ctest runs briefly: every writer killed 200 times, the GUI's save
# killed 50 times, `haze live` under 44 Hz on 8 universes for 10 minutes, and twenty copies of
# each GUI test at once.
soak: build node-tools
	bash tests/cli/kill_writers.sh $(HAZE) . 200
	bash tests/gui/kill_save.sh $(HAZE) . 50
	bash tests/cli/live_soak.sh $(HAZE) . 600
	$(MAKE) gui-parallel

# The video of the demo on a real one-node Slurm cluster on this machine (tests/farm/slurm_farm.sh):
# installs Slurm and munge, starts their daemons, renders in chunks, compares with one machine's
# video, kills a task and resubmits; stops every daemon it started. Root only; minutes.
farm-test: build-haze
	bash tests/farm/slurm_farm.sh $(HAZE) .

GUI_COPIES ?= 20
GUI_TESTS  ?=
gui-parallel: build
	tools/gui_parallel.sh $(HAZE) $(GUI_COPIES) $(GUI_TESTS)

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) build-fuzz out
