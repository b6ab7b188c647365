# polarform — the two commands of the README, and the developer targets around them.
#   make        install what is missing, build Release, run the roller-cam example
#   make test   build and run the whole test suite through ctest
#   make studio       build (only) and launch the desktop app polarform-studio
#   make screenshots  build the app and regenerate the README's docs/studio-*.png under Xvfb
#   make fuzz   build the libFuzzer harnesses (clang, ASan, UBSan) in build-fuzz and run each for
#               FUZZ_SECONDS (default 60) or FUZZ_RUNS executions; FUZZ_HARNESSES="ply obj" picks some
BUILD ?= build
JOBS  ?= $(shell nproc)
CMAKE_FLAGS ?=
FUZZ_SECONDS ?= 60
FUZZ_HARNESSES ?=
FUZZ_RUNS ?=

.PHONY: all run deps configure build test bench asan fuzz studio-build studio screenshots clean

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

fuzz:
	@scripts/install-deps.sh --fuzz
	@cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DPOLARFORM_FUZZ=ON -DPOLARFORM_BUILD_BENCH=OFF > build-fuzz.configure.log 2>&1 \
	  || (cat build-fuzz.configure.log; exit 1)
	@cmake --build build-fuzz -j $(JOBS) --target polarform_fuzzers
	@FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_RUNS=$(FUZZ_RUNS) scripts/fuzz.sh build-fuzz $(FUZZ_HARNESSES)

studio-build: configure
	@cmake --build $(BUILD) -j $(JOBS) --target polarform-studio

studio: studio-build
	@$(BUILD)/ui/studio/polarform-studio

screenshots: studio-build
	@ui/studio/tools/screenshots.sh $(BUILD)

clean:
	@rm -rf $(BUILD) build-asan build-fuzz $(BUILD).configure.log build-fuzz.configure.log
