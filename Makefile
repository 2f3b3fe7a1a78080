# SPDX-License-Identifier: MIT
# vor - build, test and benchmark.
#
#   make                    host library build/host/libvor.a and CLI build/host/vor
#   make PORT=cortex-m3     cross-build the library and test firmware for a target
#                           (cortex-m0, cortex-m3, cortex-m4f, riscv32)
#   make test               every test, on the host and under QEMU on every target
#                           (ONLY=dynamic,mesh/tiny: those cases; docs/testing.md)
#   make run-tests          the test suite of PORT (ONLY=..., V=1; make list-tests)
#   make demo               the main job on the emulated Cortex-M3
#   make size               flash, static RAM and worst stack depth per target,
#                           and per feature set a firmware links (bench/size/)
#   make bench              Delaunay build: vor against CGAL and Boost.Polygon,
#                           and target instructions per inserted site; then
#                           make bench-cdt
#   make bench-predicates   predicate speed: host ns and target instructions
#   make bench-query        nearest-site queries: vor against nanoflann and CGAL,
#                           and target instructions per coherent query
#   make run-example-contours  contour interpolation (host): build/contours.png
#   make coverage           Lloyd coverage control of 64 robots on the
#                           emulated Cortex-M3: build/coverage.svg
#   make dual               vor_build_dc_forked on the two Cortex-M33 cores of
#                           QEMU's mps2-an521 (examples/dual): each core's
#                           instructions, the speedup over one core, and
#                           whether the diagram is the one-core build's
#   make field              a field of 50 sensors interpolated (Sibson) into a
#                           320x240 RGB565 frame on the emulated Cortex-M3:
#                           build/field.png, checked by tools/check_field.py
#   make coverage-report    line and branch coverage of src/ by the host
#                           suites: build/coverage-report/index.html
#   make pictures           README's pictures: docs/diagram.png, docs/raster.png,
#                           docs/room.png
#   make bench-cdt          constraints: vor_constrain against CGAL, CDT and
#                           delaunay32, and Cortex-M3 instructions per constraint
#   make bench-power        weighted sites: vor_power_build and vor_power_insert
#                           against CGAL's regular triangulation, and Cortex-M3
#                           instructions per site
#   make bench-interpolate  natural-neighbour interpolation: vor_interpolate and
#                           vor_interpolate_laplace against CGAL, and Cortex-M3
#                           instructions per query
#   make bench-raster       vor_raster: host Mpx/s and target instructions per
#                           pixel, against the brute-force path
#   make fuzz               the libFuzzer harnesses, FUZZ_SECONDS (600) each
#                           (tests/fuzz/, docs/testing.md)
#   make soak               10^7 random inserts, removes, moves and queries on
#                           one diagram, checked against fresh builds
#   make mutants            mutation testing of the predicates, the multi-word
#                           arithmetic, the perturbation and the mesh updates
#                           against the host suite (tools/mutants.py,
#                           docs/testing.md); MUTANTS_EVERY=N: about one in N
#   make prove              Frama-C EVA: no runtime error in the public calls
#                           over their inputs (tools/prove/, docs/testing.md)
#   make misra              cppcheck's MISRA C:2012 addon over the library: no
#                           finding outside tools/misra-deviations.txt (docs/misra.md)
#   make docs               the API reference from the headers (Doxygen):
#                           build/docs/html/index.html; fails on any warning
#
# Everything a build needs (compilers, QEMU, python3, libstb-dev, xmllint,
# rsvg-convert, doxygen, gcovr, frama-c, cppcheck) is installed on demand by
# tools/install-deps.sh, so these work on a fresh Debian machine.

PORT ?= host
TARGETS := cortex-m0 cortex-m3 cortex-m4f riscv32

# SANITIZE=1 builds the host tests with AddressSanitizer and UBSan, and
# fills every local with a pattern before its first write, so that a read of
# an unwritten local gives garbage rather than what an earlier call left in
# that stack slot (which can be the right value by luck).
ifeq ($(SANITIZE),1)
B := build/$(PORT)-sanitize
SAN_FLAGS := -fsanitize=address,undefined,bounds-strict -fno-sanitize-recover=all -fno-omit-frame-pointer \
             -ftrivial-auto-var-init=pattern
else
B := build/$(PORT)
SAN_FLAGS :=
endif
# LIMB_BITS=32 builds for the host with the 32-bit limbs of the targets'
# wide arithmetic (their mid incircle filter included), so that the
# sanitizers see it too.
LIMB_FLAGS :=
ifeq ($(LIMB_BITS),32)
B := $(B)-limb32
LIMB_FLAGS := -DVOR_LIMB_BITS=32
endif
# COVERAGE=1 builds the host tests with gcov's counters, at -O0 and with
# no forced inlining (VOR__COVERAGE, src/multiword.h), so that each line
# and branch counted is one of the source (make coverage-report).
COV_FLAGS :=
ifeq ($(COVERAGE),1)
B := $(B)-gcov
COV_FLAGS := --coverage -DVOR__COVERAGE
endif
GEN := build/gen

include port/$(PORT)/port.mk
include tools/peer-bench/bench.mk

.SECONDEXPANSION:

WARNINGS := -Wall -Wextra -Werror -pedantic -Wconversion -Wsign-conversion \
            -Wcast-align -Wundef -Wshadow
OPT := $(if $(COV_FLAGS),-O0,-O2)
# VOR_INDEX_BITS defaults to 16 everywhere; the host builds everything
# with 32-bit ids, explicitly: its benchmarks and the CLI take more than
# 32,767 sites, and the suite then covers both widths (the targets run it
# with 16).
WIDTH_DEFS := $(if $(filter host,$(PORT)),-DVOR_INDEX_BITS=32)
LIB_CFLAGS := -std=c99 -ffreestanding $(WARNINGS) $(OPT) -ffunction-sections \
              -fdata-sections -fstack-usage -Iinclude $(ARCH_CFLAGS) $(SAN_FLAGS) $(LIMB_FLAGS) \
              $(COV_FLAGS) $(WIDTH_DEFS)
# Test builds of the library trap on a failed internal assertion.
CHECKED_DEFS := '-DVOR_ASSERT(x)=do { if (!(x)) __builtin_trap(); } while (0)'
# The tests, the fault tests and the benchmarks that count predicate calls
# build the library and themselves with the counters (VOR_STATS).
STATS_DEFS := -DVOR_STATS=1
TEST_CFLAGS := -std=c99 $(WARNINGS) $(OPT) -ffunction-sections -fdata-sections \
               -Iinclude -Isrc -Iport -Itests -Itests/vectors $(ARCH_CFLAGS) $(SAN_FLAGS) \
               $(LIMB_FLAGS) $(COV_FLAGS) $(WIDTH_DEFS)
HOST_TOOL_CFLAGS := -std=c99 -D_POSIX_C_SOURCE=200809L $(WARNINGS) -O2 -Iinclude -Isrc \
                    -DVOR_INDEX_BITS=32 -DVOR_STATS=1

# sources.txt is the one list of library sources (CMake reads it too).
LIB_SRCS := $(filter src/%.c,$(file < sources.txt))
LIB_HDRS := $(wildcard include/*.h src/*.h)
LIB_OBJS := $(LIB_SRCS:src/%.c=$(B)/lib/%.o)
CHECKED_OBJS := $(LIB_SRCS:src/%.c=$(B)/checked/%.o)
FAULTY_OBJS := $(LIB_SRCS:src/%.c=$(B)/faulty/%.o)
TEST_SRCS := $(wildcard tests/*.c)
TEST_OBJS := $(TEST_SRCS:tests/%.c=$(B)/tests/%.o) $(B)/tests/predicate_vectors.o $(B)/tests/crossing_vectors.o
PORT_OBJS := $(addprefix $(B)/port/,$(addsuffix .o,$(basename $(notdir $(PORT_SRCS)))))
TEST_EXE := $(B)/vor-tests$(EXE)

.PHONY: all lib tests run-tests fault-tests run-fault-tests config-tests run-config-tests test demo coverage dual field coverage-report pictures size bench-predicates bench-raster docs prove misra mutants clean
.DELETE_ON_ERROR:

ifeq ($(PORT),host)
all: lib $(B)/vor
else
all: lib tests
endif

lib: $(B)/libvor.a
tests: $(TEST_EXE)

$(B)/libvor.a: $(LIB_OBJS)
	$(AR) rcs $@ $^

$(B)/libvor-checked.a: $(CHECKED_OBJS)
	$(AR) rcs $@ $^

$(B)/lib/%.o: src/%.c $(LIB_HDRS) | $(B)/lib
	$(CC) $(LIB_CFLAGS) -c $< -o $@

$(B)/checked/%.o: src/%.c $(LIB_HDRS) | $(B)/checked
	$(CC) $(LIB_CFLAGS) $(CHECKED_DEFS) $(STATS_DEFS) -c $< -o $@

# Fault injection (tests/faults): predicates that lie, never in a release.
$(B)/libvor-faulty.a: $(FAULTY_OBJS)
	$(AR) rcs $@ $^

$(B)/faulty/%.o: src/%.c $(LIB_HDRS) | $(B)/faulty
	$(CC) $(LIB_CFLAGS) $(CHECKED_DEFS) $(STATS_DEFS) -DVOR_FAULT_INJECTION -c $< -o $@

$(B)/vor-fault-tests$(EXE): tests/faults/test_faults.c $(B)/tests/harness.o $(PORT_OBJS) $(B)/libvor-faulty.a $(B)/tests/select.stamp
	$(CC) $(TEST_CFLAGS) $(SELECT_DEFS) $(STATS_DEFS) -DVOR_FAULT_INJECTION $< $(B)/tests/harness.o $(PORT_OBJS) $(B)/libvor-faulty.a $(FW_LDFLAGS) $(FW_LDLIBS) -o $@

fault-tests: $(B)/vor-fault-tests$(EXE)
run-fault-tests: $(B)/vor-fault-tests$(EXE)
	$(RUN) $<

$(B)/tests/%.o: tests/%.c $(LIB_HDRS) $(wildcard tests/*.h tests/vectors/*.h) port/port.h | $(B)/tests
	$(CC) $(TEST_CFLAGS) $(STATS_DEFS) -c $< -o $@

# The oracle's table is generated, never edited: rebuilt when the generator changes.
$(GEN)/predicate_vectors.c: tools/gen_predicate_vectors.py tests/vectors/predicate_vectors.h
	@mkdir -p $(GEN)
	@tools/install-deps.sh python
	python3 tools/gen_predicate_vectors.py --out $@

$(B)/tests/predicate_vectors.o: $(GEN)/predicate_vectors.c | $(B)/tests
	$(CC) $(TEST_CFLAGS) $(STATS_DEFS) -c $< -o $@

$(GEN)/crossing_vectors.c: tools/gen_crossing_vectors.py tools/gen_predicate_vectors.py tests/vectors/crossing_vectors.h
	@mkdir -p $(GEN)
	@tools/install-deps.sh python
	python3 tools/gen_crossing_vectors.py --out $@

$(B)/tests/crossing_vectors.o: $(GEN)/crossing_vectors.c | $(B)/tests
	$(CC) $(TEST_CFLAGS) $(STATS_DEFS) -c $< -o $@

vpath %.c $(sort $(dir $(PORT_SRCS)))
vpath %.S $(sort $(dir $(PORT_SRCS)))
$(B)/port/%.o: %.c port/port.h | $(B)/port
	$(CC) $(TEST_CFLAGS) $(PORT_CFLAGS) -c $< -o $@
$(B)/port/%.o: %.S | $(B)/port
	$(CC) $(TEST_CFLAGS) -c $< -o $@

# Test case selection (docs/testing.md): ONLY=PATTERN[,PATTERN...] runs the
# cases a pattern names ("dynamic", "dynamic/trackers"), V=1 prints every
# case with its number of checks, LIST=1 lists the cases and runs none.
# They are compiled into the test programs' main, so they work the same on
# every target; the stamp holds them, so that main is rebuilt when they change.
ifneq ($(ONLY),)
ifneq ($(shell printf '%s' '$(ONLY)' | tr -d 'A-Za-z0-9_/,.-'),)
$(error ONLY holds letters, digits and _ / , . - only)
endif
endif
SELECT := $(ONLY)|$(V)|$(LIST)
SELECT_DEFS := -DTEST_ONLY='"$(ONLY)"' \
               -DTEST_MODE='($(if $(V),TEST_VERBOSE,0u) | $(if $(LIST),TEST_LIST,0u))'
$(B)/tests/select.stamp: FORCE | $(B)/tests
	@[ "$$(cat $@ 2>/dev/null)" = '$(SELECT)' ] || printf '%s\n' '$(SELECT)' >$@
$(B)/tests/main.o: $(B)/tests/select.stamp
$(B)/tests/main.o: TEST_CFLAGS += $(SELECT_DEFS)
.PHONY: FORCE list-tests
FORCE:

# The names of the test cases (ONLY narrows them).
list-tests:
	+@$(MAKE) -s run-tests LIST=1

$(TEST_EXE): $(TEST_OBJS) $(PORT_OBJS) $(B)/libvor-checked.a
	$(CC) $(TEST_CFLAGS) $(TEST_OBJS) $(PORT_OBJS) $(B)/libvor-checked.a $(FW_LDFLAGS) $(FW_LDLIBS) -o $@

run-tests: $(TEST_EXE)
	$(RUN) $(TEST_EXE)

# Harness self-tests: programs that must fail (tools/run-tests.sh).
$(B)/selftest-%$(EXE): tests/selftest/%.c $(B)/tests/harness.o $(PORT_OBJS)
	$(CC) $(TEST_CFLAGS) $< $(B)/tests/harness.o $(PORT_OBJS) $(FW_LDFLAGS) $(FW_LDLIBS) -o $@

run-selftest-%: $(B)/selftest-%$(EXE)
	$(RUN) $<

# Configuration contract (tests/config): application objects compiled
# with other vor_config.h options than their library, which is the release
# build with VOR_TRACKER_EDGES=24. Each case changes one option.
CONTRACT_LIB_DEFS := -DVOR_TRACKER_EDGES=24
OTHER_INDEX_BITS := $(if $(filter host,$(PORT)),16,32)
CONFIG_CASES := same tracker_edges index_bits sites_per_bucket stats
CONFIG_DEFS_same := $(CONTRACT_LIB_DEFS) -DCONFIG_EXPECT=VOR_OK
CONFIG_DEFS_tracker_edges := -DCONFIG_EXPECT=VOR_ERR_CONFIG
CONFIG_DEFS_index_bits := $(CONTRACT_LIB_DEFS) -DVOR_INDEX_BITS=$(OTHER_INDEX_BITS) \
                          -DCONFIG_EXPECT=VOR_ERR_CONFIG
CONFIG_DEFS_sites_per_bucket := $(CONTRACT_LIB_DEFS) -DVOR_SITES_PER_BUCKET=16u \
                                -DCONFIG_EXPECT=VOR_ERR_CONFIG
CONFIG_DEFS_stats := $(CONTRACT_LIB_DEFS) $(STATS_DEFS) -DCONFIG_EXPECT=VOR_ERR_CONFIG
CONTRACT_OBJS := $(LIB_SRCS:src/%.c=$(B)/contract/%.o)

$(B)/libvor-contract.a: $(CONTRACT_OBJS)
	$(AR) rcs $@ $^

$(B)/contract/%.o: src/%.c $(LIB_HDRS) | $(B)/contract
	$(CC) $(LIB_CFLAGS) $(CONTRACT_LIB_DEFS) -c $< -o $@

# (the case's width replaces the host's WIDTH_DEFS)
$(B)/config/%.o: tests/config/mismatch.c $(LIB_HDRS) tests/test.h | $(B)/config
	$(CC) $(if $(filter index_bits,$*),$(filter-out $(WIDTH_DEFS),$(TEST_CFLAGS)),$(TEST_CFLAGS)) \
	    $(CONFIG_DEFS_$*) -DCONFIG_CASE=config_$* -c $< -o $@

$(B)/config-tests$(EXE): tests/config/main.c $(CONFIG_CASES:%=$(B)/config/%.o) $(B)/tests/harness.o $(PORT_OBJS) $(B)/libvor-contract.a $(B)/tests/select.stamp
	$(CC) $(TEST_CFLAGS) $(SELECT_DEFS) $< $(CONFIG_CASES:%=$(B)/config/%.o) $(B)/tests/harness.o $(PORT_OBJS) $(B)/libvor-contract.a $(FW_LDFLAGS) $(FW_LDLIBS) -o $@

config-tests: $(B)/config-tests$(EXE)
run-config-tests: $(B)/config-tests$(EXE)
	$(RUN) $<

$(B)/contract $(B)/config:
	@mkdir -p $@

# Benchmarks link the release library, like a user's firmware would; the
# two that count predicate calls link it built with the counters.
BENCH_ROUNDS_host := 20000
BENCH_CFLAGS := $(TEST_CFLAGS) -DBENCH_ROUNDS=$(or $(BENCH_ROUNDS_$(PORT)),8)
BENCH_COUNTING := dynamic predicates
bench_lib = $(if $(filter $(1),$(BENCH_COUNTING)),$(B)/libvor-stats.a,$(B)/libvor.a)
$(B)/bench-%$(EXE): bench/%.c $(B)/tests/harness.o $(B)/tests/counters.o $(PORT_OBJS) $$(call bench_lib,$$*)
	$(CC) $(BENCH_CFLAGS) $(if $(filter $*,$(BENCH_COUNTING)),$(STATS_DEFS)) $< $(B)/tests/harness.o $(B)/tests/counters.o $(PORT_OBJS) $(call bench_lib,$*) $(FW_LDFLAGS) $(FW_LDLIBS) -o $@

STATS_OBJS := $(LIB_SRCS:src/%.c=$(B)/stats/%.o)
$(B)/libvor-stats.a: $(STATS_OBJS)
	$(AR) rcs $@ $^

$(B)/stats/%.o: src/%.c $(LIB_HDRS) | $(B)/stats
	$(CC) $(LIB_CFLAGS) $(STATS_DEFS) -c $< -o $@

run-bench-%: $(B)/bench-%$(EXE)
	$(RUN) $<

# Examples: examples/NAME/*.c and examples/common/*.c, linked with the port
# and the release library.
$(B)/example-%$(EXE): $$(wildcard examples/%/*.c) $(wildcard examples/common/*) $(PORT_OBJS) $(B)/libvor.a
	$(CC) $(TEST_CFLAGS) -Iexamples/common $(wildcard examples/$*/*.c) $(wildcard examples/common/*.c) $(PORT_OBJS) $(B)/libvor.a $(FW_LDFLAGS) $(FW_LDLIBS) -o $@

# examples/field at every 4th pixel of its frame (80x60, FIELD_STEP=4),
# written to build/field-quick.*: make test's run of it on every port.
$(B)/example-field-quick$(EXE): $(wildcard examples/field/*.c) $(wildcard examples/common/*) $(PORT_OBJS) $(B)/libvor.a
	$(CC) $(TEST_CFLAGS) -DFIELD_STEP=4 -Iexamples/common $(wildcard examples/field/*.c) $(wildcard examples/common/*.c) $(PORT_OBJS) $(B)/libvor.a $(FW_LDFLAGS) $(FW_LDLIBS) -o $@

run-example-%: $(B)/example-%$(EXE)
	$(RUN) $<

# The reference of the constrained triangulation's tests (host only):
# CGAL's, with exact constructions and intersections.
$(B)/cgal-cdt: tests/reference/cgal_cdt.cpp
	@tools/install-deps.sh bench
	g++ -O1 -std=c++17 $< -o $@ -lmpfr -lgmpxx -lgmp

# The reference of the power diagram's tests (host only): CGAL's regular
# triangulation with exact constructions.
$(B)/cgal-power: tests/reference/cgal_power.cpp
	@tools/install-deps.sh bench
	g++ -O1 -std=c++17 $< -o $@ -lmpfr -lgmpxx -lgmp

# The reference of the interpolation's tests (host only): CGAL's natural
# neighbour coordinates with exact constructions, and vor's side of the
# comparison (every coordinate, unreduced).
$(B)/cgal-interpolate: tests/reference/cgal_interpolate.cpp
	@tools/install-deps.sh bench
	g++ -O1 -std=c++17 $< -o $@ -lmpfr -lgmpxx -lgmp

$(B)/vor-interpolate: tests/reference/vor_interpolate.c $(B)/libvor.a
	$(CC) $(TEST_CFLAGS) $< $(B)/libvor.a -o $@

# Host command-line tool.
CLI_SRCS := $(wildcard tools/cli/*.c)
# It takes more than 32,767 sites and prints predicate counters (--stats):
# its own build of the library, with 32-bit ids and VOR_STATS.
CLI_LIB_OBJS := $(LIB_SRCS:src/%.c=$(B)/cli-lib/%.o)
$(B)/libvor-cli.a: $(CLI_LIB_OBJS)
	$(AR) rcs $@ $^

$(B)/cli-lib/%.o: src/%.c $(LIB_HDRS) | $(B)/cli-lib
	gcc -std=c99 -ffreestanding $(WARNINGS) -O2 -ffunction-sections -fdata-sections -Iinclude \
	    -DVOR_INDEX_BITS=32 -DVOR_STATS=1 -c $< -o $@

$(B)/vor: $(CLI_SRCS) $(wildcard tools/cli/*.h) tools/png_write.h $(B)/libvor-cli.a
	gcc $(HOST_TOOL_CFLAGS) -Itools/cli $(CLI_SRCS) $(B)/libvor-cli.a -o $@

$(B)/lib $(B)/checked $(B)/faulty $(B)/tests $(B)/port $(B)/stats $(B)/cli-lib:
	@mkdir -p $@

# On demand, before the first object: the port's compiler
# (tools/install-deps.sh); a quiet check when it is there.
.PHONY: install-deps
install-deps:
	@tools/install-deps.sh $(if $(filter host,$(PORT)),host,toolchains)
$(B)/lib $(B)/checked $(B)/faulty $(B)/tests $(B)/port $(B)/stats $(B)/cli-lib: | install-deps

# The host programs that write PNGs require stb_image_write.h; when it is
# missing this rule installs it (after install-deps: one apt-get at a time).
STB_HEADER := /usr/include/stb/stb_image_write.h
$(STB_HEADER): | install-deps
	@tools/install-deps.sh cli
$(B)/vor $(B)/example-contours$(EXE): $(STB_HEADER)

# ---------------------------------------------------------------- top level

# The main job: examples/voronoi on the emulated Cortex-M3.
DEMO_PORT ?= cortex-m3
# It also renders a 320x240 RGB565 frame in 16-row bands and streams it
# to build/demo.rgb565 through semihosting; the host turns it into
# build/demo.png. Its cells go as text to build/demo.cells, which
# `vor draw --cells` turns into build/demo.svg.
demo: $(B)/vor
	@tools/install-deps.sh toolchains python
	@mkdir -p build
	+@$(MAKE) -s PORT=$(DEMO_PORT) run-example-voronoi
	@python3 tools/rgb565_to_png.py build/demo.rgb565 320 240 build/demo.png
	@echo "frame:     build/demo.png"
	@$(B)/vor draw --cells build/demo.cells -o build/demo.svg
	@echo "diagram:   build/demo.svg"

# examples/coverage (Lloyd coverage control of 64 robots, then of 32 in an
# L-shaped hall) on the emulated Cortex-M3; their final cells go to
# build/coverage.cells and build/coverage-room.cells, drawn into
# build/coverage.svg and build/coverage-room.svg.
coverage: $(B)/vor
	@tools/install-deps.sh toolchains
	@mkdir -p build
	+@$(MAKE) -s PORT=$(DEMO_PORT) run-example-coverage
	@$(B)/vor draw --cells build/coverage.cells -o build/coverage.svg
	@echo "picture: build/coverage.svg"
	@$(B)/vor draw --cells build/coverage-room.cells -o build/coverage-room.svg
	@echo "picture: build/coverage-room.svg (the L-shaped hall)"

# examples/dual on the two cores of the emulated mps2-an521 (PORT
# cortex-m33): vor_build_dc_forked with core 1 building one half through
# the fork/join hook of examples/dual/fork_join_an521.c; fails unless each
# forked diagram is the one-core build's.
dual:
	@tools/install-deps.sh toolchains
	+@$(MAKE) -s PORT=cortex-m33 run-example-dual

# examples/field (50 sensors, their Sibson interpolant rendered into a
# 320x240 RGB565 frame in 16-row bands, every pixel checked on the target)
# on the emulated Cortex-M3: the frame streams to build/field.rgb565, drawn
# into build/field.png, and its values to build/field.values, of which
# tools/check_field.py checks every 8th row and column against an exact
# brute force (Python fractions). About 2 minutes of CPU for QEMU (three
# frames of some 495,000 instructions a pixel: the picture, the VALUE
# frame its checks compare, the linear frame) and 35 s for the script:
# not part of make demo, which takes seconds.
field:
	@tools/install-deps.sh toolchains python
	@mkdir -p build
	+@$(MAKE) -s PORT=$(DEMO_PORT) RUN_TIMEOUT=1800 run-example-field
	@python3 tools/rgb565_to_png.py build/field.rgb565 320 240 build/field.png
	@python3 tools/check_field.py
	@echo "picture:   build/field.png"

# README's pictures of the sites in docs/pictures.sites: docs/diagram.png
# (vor draw, rendered by rsvg-convert) and docs/raster.png (vor raster,
# L1 metric), both y up with the same colour for each site; and
# docs/room.png, examples/room's floor plan drawn by vor draw --domain.
pictures: $(B)/vor $(B)/example-room$(EXE)
	@tools/install-deps.sh svg
	@$(B)/vor draw --box 0 0 480 320 --size 480 320 --triangles --hull docs/pictures.sites \
		-o $(B)/pictures-diagram.svg
	@rsvg-convert $(B)/pictures-diagram.svg -o docs/diagram.png
	@$(B)/vor raster --size 480 320 --origin 0 0 --step 1 1 --metric l1 --dots docs/pictures.sites \
		--png docs/raster.png
	@$(B)/example-room$(EXE) >/dev/null
	@$(B)/vor draw --size 480 320 --constraints build/room.walls --domain build/room.sites \
		-o $(B)/pictures-room.svg
	@rsvg-convert $(B)/pictures-room.svg -o docs/room.png
	@echo "pictures:  docs/diagram.png docs/raster.png docs/room.png"

# The API reference: docs/Doxyfile reads include/*.h (through
# tools/doxygen-filter.py) with README.md as the main page. Doxygen exits
# non-zero on any warning (FAIL_ON_WARNINGS); the log is printed so the
# warning shows.
VOR_VERSION = $(shell sed -n 's/^\#define VOR_VERSION_\(MAJOR\|MINOR\|PATCH\) *\([0-9]*\).*/\2/p' include/vor.h | paste -sd. -)
docs:
	@tools/install-deps.sh doxygen python
	@rm -rf build/docs && mkdir -p build/docs
	@VOR_VERSION=$(VOR_VERSION) doxygen docs/Doxyfile || { cat build/docs/warnings.log; exit 1; }
	@if [ -s build/docs/warnings.log ]; then cat build/docs/warnings.log; exit 1; fi
	@echo "docs:      build/docs/html/index.html"

# Line and branch coverage of src/ by the host suites (gcov, gcovr):
# build/coverage-report/index.html (docs/testing.md, "Coverage").
coverage-report:
	@tools/install-deps.sh host python gcovr
	+@tools/coverage-report.sh

test:
	@tools/install-deps.sh host cli python toolchains clang cmake svg doxygen gcovr analyzer misra prove
	+@tools/run-tests.sh

size:
	@tools/install-deps.sh python toolchains
	+@tools/size-report.sh $(TARGETS)
	+@tools/size-features.sh cortex-m0 cortex-m3 riscv32

prove:
	@tools/install-deps.sh prove
	@tools/prove/prove.sh

# Every mutant of the files tools/mutants.py names, each compiled and run
# against the host suite; the report is build/mutants/report.txt. It fails
# below 95 % killed or on a survivor tools/mutants-equivalent.txt does not
# show equivalent. MUTANTS_EVERY=N runs about one mutant in N, chosen by
# its own text (make test's sample).
MUTANTS_EVERY ?= 1
mutants:
	@tools/install-deps.sh host python
	@$(MAKE) -s $(GEN)/predicate_vectors.c $(GEN)/crossing_vectors.c
	@nice -n 10 python3 tools/mutants.py --every $(MUTANTS_EVERY)

misra:
	@tools/install-deps.sh misra
	@tools/misra.sh --counts

bench-predicates:
	@tools/install-deps.sh host python toolchains
	+@tools/bench-predicates.sh

bench-raster:
	@tools/install-deps.sh host python toolchains
	+@tools/bench-raster.sh

clean:
	rm -rf build

include tests/fuzz/fuzz.mk

include tests/soak/soak.mk
