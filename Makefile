# The two commands of the README: `make demo` and `make test`. Both do all set-up themselves.
BUILD ?= build
JOBS ?= $(shell nproc)
DEMO_INPUT ?= datasets/3dbag/3dbag_5910.city.json
DEMO_OUT ?= $(BUILD)/demo

FUZZ_SECONDS ?= 20
CMAKE_ARGS ?=

.PHONY: all deps configure build test demo bench clean test-sanitize fuzz

all: build

deps:
	@bash tools/setup-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

demo: build
	@mkdir -p $(DEMO_OUT)
	@# exit code 1 = some buildings partial/failed (each with its reason in the report): fine for a demo
	@$(BUILD)/tools/morphcut-city $(DEMO_INPUT) -o $(DEMO_OUT)/demo.morphcut.city.json \
	  --report $(DEMO_OUT)/demo.morphcut.report.json --summary $(DEMO_OUT)/demo.morphcut.csv; \
	  rc=$$?; [ $$rc -le 1 ] || exit $$rc
	@# every file checked: every part a valid Solid by val3dity's rules, each level tiling each building's cell
	@for f in $(DEMO_OUT)/demo.morphcut.city.json $(DEMO_OUT)/demo.morphcut.level-*.city.json; do \
	  $(BUILD)/tools/morphcut-city validate $$f > $$f.validate.txt; rc=$$?; tail -2 $$f.validate.txt | head -1; \
	  [ $$rc -le 1 ] || exit $$rc; done
	@echo "demo outputs in $(DEMO_OUT)/: demo.morphcut.city.json (the input annotated per building)," \
	  "demo.morphcut.level-<t>.city.json (one city per level: the parts are the BuildingParts)," \
	  "demo.morphcut.report.json, demo.morphcut.csv; validation in *.validate.txt"
	@# the run wrote the HTML page beside its report (morphcut-city --no-html turns it off)
	@echo "open the page (offline, self-contained): $(abspath $(DEMO_OUT))/demo.morphcut.html"

bench: build
	@$(BUILD)/tools/bench_cityjson_io
	@tools/bench-samples $(BUILD)
	@tools/bench-preprocess $(BUILD)
	@bash tools/bench_city.sh --bin $(BUILD)/tools/morphcut-city

test-sanitize: deps
	@cmake -S . -B $(BUILD)-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMC_SANITIZE=ON -DMC_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(BUILD)-asan -j $(JOBS)
	@# no free-memory quarantine: the streaming tests measure peak RSS, which it would inflate;
	@# suppressions only for findings inside oneTBB and libstdc++ (tools/sanitizers/*.supp say why)
	@cd $(BUILD)-asan && ASAN_OPTIONS=quarantine_size_mb=0 \
	  UBSAN_OPTIONS=print_stacktrace=1:suppressions=$(CURDIR)/tools/sanitizers/ubsan.supp \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tools/sanitizers/lsan.supp \
	  ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

# libFuzzer targets (clang, own build dir): each fuzzed FUZZ_SECONDS; see tools/fuzz.sh.
fuzz: deps
	@bash tools/fuzz.sh --build $(BUILD)-fuzz --seconds $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD)
