# polarform — the two commands of the README, and the developer targets around them.
#   make        install what is missing, build Release, run the roller-cam example
#   make test   build and run the whole test suite through ctest
#   make studio       build (only) and launch the desktop app polarform-studio
#   make screenshots  build the app and regenerate the README's docs/studio-*.png under Xvfb
BUILD ?= build
JOBS  ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all run deps configure build test bench asan studio-build studio screenshots clean

all: run

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS) > $(BUILD).configure.log 2>&1 || (cat $(BUILD).configure.log; exit 1)

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

run: build
	@scripts/run-example.sh $(BUILD)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --timeout 900

bench: build
	@$(BUILD)/tests/polarform_bench --benchmark_counters_tabular=true

asan: deps
	@cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DPOLARFORM_SANITIZE=ON -DPOLARFORM_BUILD_BENCH=OFF -DPOLARFORM_BUILD_STUDIO=OFF
	@cmake --build build-asan -j $(JOBS)
	@cd build-asan && ctest --output-on-failure -j $(JOBS) --timeout 1800

studio-build: configure
	@cmake --build $(BUILD) -j $(JOBS) --target polarform-studio

studio: studio-build
	@$(BUILD)/ui/studio/polarform-studio

screenshots: studio-build
	@ui/studio/tools/screenshots.sh $(BUILD)

clean:
	@rm -rf $(BUILD) build-asan $(BUILD).configure.log
