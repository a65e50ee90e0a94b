# rtamp — the two commands of the README and a few more.
#   make demo    install missing Debian packages, build, run the built-in scenario
#   make test    install missing Debian packages, build, run every test (ctest -j2)
#   make test-asan   build under ASan+UBSan into build-asan/ and run the fast tests
#   make fuzz    build the libFuzzer targets with clang into build-fuzz/, run each for FUZZ_SECONDS
#   make bench   build and run the Google Benchmark suites
BUILD ?= build
JOBS ?= 2
FUZZ_SECONDS ?= 30
CMAKE_FLAGS ?=
ifeq ($(CI),true)
  CMAKE_FLAGS += -DRTAMP_WERROR=ON
endif

.PHONY: all deps build demo test test-asan fuzz bench clean

all: build

deps:
	@scripts/install-deps

$(BUILD)/build.ninja:
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: deps $(BUILD)/build.ninja
	cmake --build $(BUILD) -j$(JOBS)

demo: build
	@scripts/demo $(BUILD)/bin/rtamp

test: build
	ctest --test-dir $(BUILD) -j$(JOBS) --output-on-failure

test-asan: deps
	cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DRTAMP_SANITIZE=ON -DRTAMP_BENCH=OFF $(CMAKE_FLAGS)
	cmake --build build-asan -j$(JOBS)
	ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --test-dir build-asan -j$(JOBS) --output-on-failure -LE slow

fuzz: deps
	CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRTAMP_FUZZ=ON $(CMAKE_FLAGS)
	cmake --build build-fuzz -j$(JOBS) --target fuzzers
	scripts/run-fuzzers build-fuzz $(FUZZ_SECONDS)

bench: build
	scripts/run-benchmarks $(BUILD)

clean:
	rm -rf $(BUILD) build-asan build-fuzz
