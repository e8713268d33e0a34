# Top-level entry points. `make demo` and `make test` do all the set-up on a fresh Debian
# machine: install dependencies (scripts/setup.sh), configure, build, then run.
JOBS ?= $(shell nproc)
PRESET ?= release
BUILD := build/$(PRESET)
SSFX := $(BUILD)/ssfx
FUZZ_SECONDS ?= 60

.PHONY: all setup configure build demo test asan fuzz fuzz-smoke bench install-check format clean

all: build

setup:
	@bash scripts/setup.sh

configure: setup
	@cmake --preset $(PRESET) -DSSFX_WERROR=$(if $(CI),ON,OFF) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# The main job: the whole evaluation (test images, quality, temporal stability, speed,
# kernel experiment) as an HTML report in out/report/.
demo: build
	@bash scripts/demo.sh $(SSFX) out/report

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory fuzz-smoke

asan:
	@$(MAKE) --no-print-directory PRESET=asan build
	@cd build/asan && LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp ctest --output-on-failure -j $(JOBS)

# libFuzzer: a short run per target (make test), or longer: make fuzz FUZZ_SECONDS=3600
fuzz-smoke: setup
	@bash scripts/fuzz.sh $(FUZZ_SECONDS)

fuzz: fuzz-smoke

bench: build
	@$(BUILD)/bench/bench_aa --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
	@$(BUILD)/bench/bench_ao --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
	@$(BUILD)/bench/bench_render --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
	@$(SSFX) bench

# Applies .clang-format (clang-format 14) to every C++ source and header; ctest format.check checks it.
format:
	@find src include apps tests bench fuzz python -name node_modules -prune -o \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print | xargs clang-format-14 -i

clean:
	rm -rf build out
