# libtiny3d — plain Makefile. See README.md.
#   make          build/libtiny3d.a
#   make demo     build and run every demo, frames under build/frames/<demo>/ (+ <demo>.gif)
#   make test     build and run every test, then again under ASan + UBSan
#   make test-portable  every test again with all SIMD paths off, under build/portable/
#   make bench    speed-vs-accuracy benchmarks, CSV + charts under build/bench/
#   make fuzz     the libFuzzer targets (clang); make mutation: the mutation check;
#   make tsan     the threaded render under ThreadSanitizer (none of the three is in make test)
#   make install  headers, libtiny3d.a and tiny3d.pc under PREFIX (default /usr/local), DESTDIR honoured
#   make clean
# BUILD=dir puts everything in another folder (several checkouts or people at once).

BUILD    ?= build
CXX      ?= g++
ifeq ($(origin CXX),default)
CXX      := g++
endif
STD      := -std=c++20
WARN     := -Wall -Wextra -Wpedantic -Werror
# SIMD_FLAGS=-DTINY3D_PORTABLE compiles every SIMD path out (src/simd_config.h).
SIMD_FLAGS ?=
CPPFLAGS := -Iinclude -MMD -MP $(SIMD_FLAGS)
OPT      ?= -O2
# float-cast-overflow is not part of GCC's "undefined" group: out-of-range float→int is UB too.
# -g1 (line tables only): reports still name file:line, and the sanitizer build — most of
# `make test`'s time — compiles faster than with full -g. -Og: the library compiles faster
# than at -O1 and the sanitized tests run as fast.
SANFLAGS := -Og -g1 -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer -fno-sanitize-recover=all
LDLIBS   := -pthread

LIB_SRCS   := $(sort $(shell find src -name '*.cpp'))
LIB_OBJS   := $(LIB_SRCS:%.cpp=$(BUILD)/obj/%.o)
LIB        := $(BUILD)/libtiny3d.a
SAN_OBJS   := $(LIB_SRCS:%.cpp=$(BUILD)/san/obj/%.o)
SAN_LIB    := $(BUILD)/san/libtiny3d.a

TEST_SRCS  := $(sort $(wildcard tests/*_test.cpp))
TEST_BINS  := $(TEST_SRCS:tests/%.cpp=$(BUILD)/tests/%)
SAN_TESTS  := $(TEST_SRCS:tests/%.cpp=$(BUILD)/san/tests/%)

DEMO_COMMON_SRCS := $(sort $(wildcard demo/common/*.cpp))
DEMO_COMMON_OBJS := $(DEMO_COMMON_SRCS:%.cpp=$(BUILD)/obj/%.o)
DEMO_SRCS  := $(sort $(wildcard demo/*.cpp))
DEMO_NAMES := $(DEMO_SRCS:demo/%.cpp=%)
DEMO_BINS  := $(DEMO_NAMES:%=$(BUILD)/demo/%)

# The benchmarks' own library (timing, CSV, charts, font): not part of libtiny3d.a.
BENCH_COMMON_SRCS := $(sort $(wildcard tests/bench/common/*.cpp))
BENCH_COMMON_OBJS := $(BENCH_COMMON_SRCS:%.cpp=$(BUILD)/obj/%.o)
BENCH_LIB         := $(BUILD)/bench/libtiny3d_bench.a
SAN_BENCH_LIB     := $(BUILD)/san/bench/libtiny3d_bench.a
BENCH_SRCS := $(sort $(wildcard tests/bench/*.cpp))
BENCH_BINS := $(BENCH_SRCS:tests/bench/%.cpp=$(BUILD)/bench/bin/%)

.PHONY: all lib demo demos test tests plain-tests test-portable bench clean
.SECONDARY:
all: lib
lib: $(LIB)

$(LIB): $(LIB_OBJS)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^

$(SAN_LIB): $(SAN_OBJS)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^

$(BENCH_LIB): $(BENCH_COMMON_OBJS)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^

$(SAN_BENCH_LIB): $(BENCH_COMMON_SRCS:%.cpp=$(BUILD)/san/obj/%.o)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/obj/%.o: %.cpp
	@mkdir -p $(@D)
	$(CXX) $(STD) $(OPT) $(WARN) $(CPPFLAGS) -c $< -o $@

$(BUILD)/san/obj/%.o: %.cpp
	@mkdir -p $(@D)
	$(CXX) $(STD) $(SANFLAGS) $(WARN) $(CPPFLAGS) -c $< -o $@

# The test programs' own code (tests/*_test.cpp; not the library they test, not the
# benchmarks) is compiled at -O0 with the precompiled prelude below, plain and under the
# sanitizers: compiling the tests is most of `make test`'s time, -O0 and the prelude
# compile them much faster than -O2 / -O1 without it, and the tests spend their run time
# in the library, which keeps $(OPT) and SANFLAGS' -Og. (-O1 is no choice for the plain
# build: GCC 12 then warns falsely of array bounds inside std::string.)
TEST_OPT       ?= -O0
SAN_TEST_FLAGS := $(subst -Og,-O0,$(SANFLAGS))
# tests/test_prelude.h (the standard and library headers most tests include) is compiled
# once per build into a precompiled header next to a copy of it, which each test is given
# with -include (-Winvalid-pch: an unusable one is an error, not a silent slow build).
TEST_PCH     := $(BUILD)/pch/test_prelude.h
SAN_TEST_PCH := $(BUILD)/san/pch/test_prelude.h
$(TEST_PCH).gch: tests/test_prelude.h
	@mkdir -p $(@D)
	cp $< $(TEST_PCH)
	$(CXX) $(STD) $(TEST_OPT) $(WARN) $(CPPFLAGS) -x c++-header $(@:.gch=) -o $@

$(SAN_TEST_PCH).gch: tests/test_prelude.h
	@mkdir -p $(@D)
	cp $< $(SAN_TEST_PCH)
	$(CXX) $(STD) $(SAN_TEST_FLAGS) $(WARN) $(CPPFLAGS) -x c++-header $(@:.gch=) -o $@

$(TEST_SRCS:%.cpp=$(BUILD)/obj/%.o): $(BUILD)/obj/%.o: %.cpp $(TEST_PCH).gch
	@mkdir -p $(@D)
	$(CXX) $(STD) $(TEST_OPT) $(WARN) -Winvalid-pch $(CPPFLAGS) -include $(TEST_PCH) -c $< -o $@

$(TEST_SRCS:%.cpp=$(BUILD)/san/obj/%.o): $(BUILD)/san/obj/%.o: %.cpp $(SAN_TEST_PCH).gch
	@mkdir -p $(@D)
	$(CXX) $(STD) $(SAN_TEST_FLAGS) $(WARN) -Winvalid-pch $(CPPFLAGS) -include $(SAN_TEST_PCH) -c $< -o $@

# ---- tests: one binary per tests/*_test.cpp, plain and sanitized ----
$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(LIB)
	@mkdir -p $(@D)
	$(CXX) $(STD) $(OPT) $< $(LIB) -o $@ $(LDLIBS)

$(BUILD)/san/tests/%: $(BUILD)/san/obj/tests/%.o $(SAN_LIB)
	@mkdir -p $(@D)
	$(CXX) $(STD) $(SANFLAGS) $< $(SAN_LIB) -o $@ $(LDLIBS)

# These test the benchmarks' library too (charts, font, CSV; the analytic-coverage prototype).
BENCH_LINKED_TESTS := chart_test analytic_coverage_test
$(BENCH_LINKED_TESTS:%=$(BUILD)/tests/%): $(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(BENCH_LIB) $(LIB)
	@mkdir -p $(@D)
	$(CXX) $(STD) $(OPT) $< $(BENCH_LIB) $(LIB) -o $@ $(LDLIBS)

$(BENCH_LINKED_TESTS:%=$(BUILD)/san/tests/%): $(BUILD)/san/tests/%: $(BUILD)/san/obj/tests/%.o $(SAN_BENCH_LIB) $(SAN_LIB)
	@mkdir -p $(@D)
	$(CXX) $(STD) $(SANFLAGS) $< $(SAN_BENCH_LIB) $(SAN_LIB) -o $@ $(LDLIBS)

tests: $(TEST_BINS) $(SAN_TESTS) $(DEMO_BINS)
# `make test` and `make demo` build with one job per core even when called without -j.
NPROC := $(shell nproc 2>/dev/null || echo 2)
PARALLEL := -j$(NPROC)
test:
	@$(MAKE) --no-print-directory $(PARALLEL) tests
	@BUILD=$(BUILD) bash tests/run_tests.sh $(TEST_BINS) -- $(SAN_TESTS)
include tests/compat/compat.mk

# `make test-portable`: the library, every test and the programs the tests run, built again
# with every SIMD path off (-DTINY3D_PORTABLE, src/simd_config.h) into $(BUILD)/portable/
# (plain -O2, no sanitizer build) and run, so the portable reference kernels that the SIMD
# kernels are tested against keep building and passing. First checks that every SIMD guard
# in the tree goes through src/simd_config.h (tests/check_simd_guards.sh) and that the
# modules include each other one way (tests/check_header_layers.sh).
PORTABLE_BUILD := $(BUILD)/portable
plain-tests: $(TEST_BINS) $(DEMO_BINS) $(COMPAT_BINS) $(COMPAT_C_BINS)
test-portable:
	@bash tests/check_simd_guards.sh
	@bash tests/check_header_layers.sh
	@$(MAKE) --no-print-directory $(PARALLEL) BUILD=$(PORTABLE_BUILD) SIMD_FLAGS=-DTINY3D_PORTABLE plain-tests
	@BUILD=$(PORTABLE_BUILD) bash tests/run_tests.sh $(TEST_SRCS:tests/%.cpp=$(PORTABLE_BUILD)/tests/%)

# ---- demos: one program per demo/*.cpp, linked with demo/common ----
$(BUILD)/demo/%: $(BUILD)/obj/demo/%.o $(DEMO_COMMON_OBJS) $(LIB)
	@mkdir -p $(@D)
	$(CXX) $(STD) $(OPT) $< $(DEMO_COMMON_OBJS) $(LIB) -o $@ $(LDLIBS)

demos: $(DEMO_BINS)
# How `make demo` runs each demo; a demo that needs more than --out sets DEMO_ARGS_<name>.
DEMO_ARGS_wireframe  = tests/data/cube_quads.obj
DEMO_ARGS_render     = tests/data/torus_binary.ply
DEMO_ARGS_ply_render = tests/data/torus_binary.ply 0 60 20 $(BUILD)/frames/ply_render/ply_render.pgm
DEMO_NO_OUT          = ply_render
# The animated demos also leave their sequence as one animated GIF, $(BUILD)/frames/<demo>.gif.
DEMO_GIF             = cube soccer wireframe shaded lighting render
define run-demo
	@echo "demo: $(1)"; mkdir -p $(BUILD)/frames/$(1); $(BUILD)/demo/$(1) $(DEMO_ARGS_$(1)) $(if $(filter $(1),$(DEMO_NO_OUT)),,--out $(BUILD)/frames/$(1)) $(if $(filter $(1),$(DEMO_GIF)),--gif $(BUILD)/frames/$(1).gif)

endef
demo:
	@$(MAKE) --no-print-directory $(PARALLEL) demos
	$(foreach d,$(DEMO_NAMES),$(call run-demo,$(d)))
	@echo "frames written under $(BUILD)/frames/"

# ---- benchmarks ----
$(BUILD)/bench/bin/%: $(BUILD)/obj/tests/bench/%.o $(BENCH_LIB) $(LIB)
	@mkdir -p $(@D)
	$(CXX) $(STD) $(OPT) $< $(BENCH_LIB) $(LIB) -o $@ $(LDLIBS)

bench: $(BENCH_BINS) $(BUILD)/bench/tools/summary
	@set -e; mkdir -p $(BUILD)/bench; for b in $(BENCH_BINS); do \
	  echo "== $$(basename $$b)"; $$b --out $(BUILD)/bench; done
	@$(BUILD)/bench/tools/summary $(BUILD)/bench

# summary tool, bench-callgrind, docs-charts, docs-tables
include tests/bench/bench.mk

# ---- fuzzing (clang + libFuzzer; not part of `make test`): make fuzz FUZZ_SECONDS=N ----
# The library is compiled again with clang and the sanitizers under $(BUILD)/fuzz/.
FUZZ_CXX     ?= clang++
FUZZ_SECONDS ?= 60
FUZZ_FLAGS   := $(STD) -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZ_OBJS    := $(LIB_SRCS:%.cpp=$(BUILD)/fuzz/obj/%.o)
FUZZ_BINS    := $(patsubst tests/fuzz/%.cpp,$(BUILD)/fuzz/%,$(sort $(wildcard tests/fuzz/fuzz_*.cpp)))

$(BUILD)/fuzz/obj/%.o: %.cpp
	@mkdir -p $(@D)
	$(FUZZ_CXX) $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link $(CPPFLAGS) -c $< -o $@

$(BUILD)/fuzz/libtiny3d.a: $(FUZZ_OBJS)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/fuzz/fuzz_%: tests/fuzz/fuzz_%.cpp $(BUILD)/fuzz/libtiny3d.a
	$(FUZZ_CXX) $(FUZZ_FLAGS) -fsanitize=fuzzer $(CPPFLAGS) $< $(BUILD)/fuzz/libtiny3d.a -o $@ $(LDLIBS)

.PHONY: fuzz
fuzz: $(FUZZ_BINS)
	bash tests/fuzz/run_fuzz.sh $(BUILD) $(FUZZ_SECONDS) $(FUZZ_BINS)

# ---- mutation check (not part of `make test`): make mutation [MUTANTS=id-regex] ----
# Each mutant of tests/mutation/mutants.txt applied to a copy of the tree under
# $(BUILD)/mutation/ (never to the working tree), the named plain tests run against it;
# table, closing line and $(BUILD)/mutation/report.txt. See tests/mutation/run_mutation.sh.
.PHONY: mutation
mutation:
	bash tests/mutation/run_mutation.sh $(BUILD) tests/mutation/mutants.txt '$(MUTANTS)'

# ---- ThreadSanitizer on the threaded render (not part of `make test`): make tsan ----
# The library and the tests that render on several threads, built with -fsanitize=thread
# under $(BUILD)/tsan/ and run; any report fails the run (halt_on_error).
TSAN_FLAGS := -O1 -g1 -fsanitize=thread -fno-omit-frame-pointer
TSAN_OBJS  := $(LIB_SRCS:%.cpp=$(BUILD)/tsan/obj/%.o)
TSAN_TESTS := $(BUILD)/tsan/tests/raster_threads_test $(BUILD)/tsan/tests/raster_context_test

$(BUILD)/tsan/obj/%.o: %.cpp
	@mkdir -p $(@D)
	$(CXX) $(STD) $(TSAN_FLAGS) $(WARN) $(CPPFLAGS) -c $< -o $@

$(BUILD)/tsan/libtiny3d.a: $(TSAN_OBJS)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/tsan/tests/%: tests/%.cpp $(BUILD)/tsan/libtiny3d.a
	@mkdir -p $(@D)
	$(CXX) $(STD) $(TSAN_FLAGS) $(WARN) $(CPPFLAGS) $< $(BUILD)/tsan/libtiny3d.a -o $@ $(LDLIBS)

.PHONY: tsan
tsan: $(TSAN_TESTS)
	@set -e; for t in $(TSAN_TESTS); do echo "tsan: $$t"; \
	  TSAN_OPTIONS="halt_on_error=1 exitcode=66" $$t; done; echo "tsan: no data race reported"

# ---- install: headers, libtiny3d.a and the pkg-config file tiny3d.pc ----
#   make install [PREFIX=/usr/local] [DESTDIR=staging-root]    (and make uninstall)
# Headers go to $(INCLUDEDIR)/tiny3d/ (compile with -I that folder: #include "tiny3d.h"),
# the library to $(LIBDIR), tiny3d.pc to $(PKGCONFIGDIR). The .pc names the final paths
# (PREFIX); DESTDIR only prefixes where the files are copied (packaging, staged installs).
# The flags serve C and C++ programs alike: no -std= in Cflags (C++ programs add -std=c++20),
# and Libs name the C++ runtime, libm and threads, which a C program linked by gcc needs.
PREFIX       ?= /usr/local
LIBDIR       ?= $(PREFIX)/lib
INCLUDEDIR   ?= $(PREFIX)/include
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
TINY3D_VERSION := 0.9.0
PUBLIC_HEADERS := $(patsubst include/%,%,$(sort $(shell find include -name '*.h')))

.PHONY: install uninstall
install: $(LIB)
	install -d $(DESTDIR)$(INCLUDEDIR)/tiny3d $(DESTDIR)$(LIBDIR) $(DESTDIR)$(PKGCONFIGDIR)
	for h in $(PUBLIC_HEADERS); do install -D -m 644 include/$$h $(DESTDIR)$(INCLUDEDIR)/tiny3d/$$h || exit 1; done
	install -m 644 $(LIB) $(DESTDIR)$(LIBDIR)/libtiny3d.a
	printf '%s\n' 'prefix=$(PREFIX)' 'libdir=$(LIBDIR)' 'includedir=$(INCLUDEDIR)' '' \
	  'Name: tiny3d' 'Description: libtiny3d, a small software 3D renderer with a C and a C++20 API (static library)' \
	  'Version: $(TINY3D_VERSION)' 'Cflags: -I$${includedir}/tiny3d' \
	  'Libs: -L$${libdir} -ltiny3d -lstdc++ -lm -pthread' > $(DESTDIR)$(PKGCONFIGDIR)/tiny3d.pc

uninstall:
	rm -rf $(DESTDIR)$(INCLUDEDIR)/tiny3d
	rm -f $(DESTDIR)$(LIBDIR)/libtiny3d.a $(DESTDIR)$(PKGCONFIGDIR)/tiny3d.pc

clean:
	rm -rf $(BUILD)

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
