# tests/bench/bench.mk — benchmark tools and targets (included by the Makefile).
#   make bench             every tests/bench/*.cpp program, then one summary table
#                          (build/bench/summary.csv); not part of `make test`
#   make bench-callgrind   instruction counts per variant (--quick runs under valgrind)
#   make docs-charts       build/bench/*.pgm -> documentation/charts/*.png (the library's PNG writer)
#   make docs-tables       the tables in documentation/benchmarks.md from build/bench/*.csv
BENCH_TOOL_SRCS := $(sort $(wildcard tests/bench/tools/*.cpp))
BENCH_TOOLS     := $(BENCH_TOOL_SRCS:tests/bench/tools/%.cpp=$(BUILD)/bench/tools/%)
BENCH_CALLGRIND ?= $(BENCH_BINS)

$(BUILD)/bench/tools/%: $(BUILD)/obj/tests/bench/tools/%.o $(BENCH_LIB) $(LIB)
	@mkdir -p $(@D)
	$(CXX) $(STD) $(OPT) $< $(BENCH_LIB) $(LIB) -o $@ $(LDLIBS)

.PHONY: bench-callgrind docs-charts docs-tables
bench-callgrind: $(BENCH_BINS)
	bash tests/bench/callgrind.sh $(BUILD)/bench-callgrind $(BENCH_CALLGRIND)

docs-charts: $(BUILD)/bench/tools/pgm2png
	@mkdir -p documentation/charts
	@set -e; ls $(BUILD)/bench/*.pgm >/dev/null 2>&1 || { echo "no charts: run make bench first"; exit 1; }; \
	for f in $(BUILD)/bench/*.pgm; do \
	  $(BUILD)/bench/tools/pgm2png $$f documentation/charts/$$(basename $$f .pgm).png; done

docs-tables: $(BUILD)/bench/tools/summary
	$(BUILD)/bench/tools/summary $(BUILD)/bench --markdown documentation/benchmarks.md
