# rtamp — the two commands of the README and a few more.
#   make demo    install missing Debian packages, build, run the built-in scenario
#   make test    install missing Debian packages, build, run every test (ctest -j2);
#                NOT_IN=TREE: only the tests that sanitizer tree TREE does not run (.ci/run)
#   make test-asan   build with clang under ASan+UBSan into build-asan/ and run the fast tests
#   make fuzz    build the libFuzzer targets in that same tree (build-asan/), run each for FUZZ_SECONDS, JOBS at a time
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
	ctest --test-dir $(BUILD) -j$(JOBS) --output-on-failure $(if $(NOT_IN),-R "$$(scripts/tests-only-in $(BUILD) $(NOT_IN) slow)")

# One clang tree serves the sanitizer tests and the fuzzers: the libraries are built once
# with ASan + UBSan and libFuzzer's coverage instrumentation (-fsanitize=fuzzer-no-link),
# the tests and the CLI link them with ASan + UBSan, the fuzz targets with libFuzzer
# (CI used to build the libraries three times: gcc Release, gcc ASan, clang fuzz).
SAN_BUILD ?= build-asan
SAN_CONFIGURE = CXX=clang++ CC=clang cmake -S . -B $(SAN_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Debug \
  -DRTAMP_SANITIZE=ON -DRTAMP_FUZZ=ON -DRTAMP_BENCH=OFF $(CMAKE_FLAGS)

test-asan: deps
	$(SAN_CONFIGURE)
	cmake --build $(SAN_BUILD) -j$(JOBS)
	ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --test-dir $(SAN_BUILD) -j$(JOBS) --output-on-failure -LE slow

fuzz: deps
	$(SAN_CONFIGURE)
	cmake --build $(SAN_BUILD) -j$(JOBS) --target fuzzers
	scripts/run-fuzzers $(SAN_BUILD) $(FUZZ_SECONDS) $(JOBS)

bench: build
	scripts/run-benchmarks $(BUILD)

clean:
	rm -rf $(BUILD) $(SAN_BUILD) build-fuzz
