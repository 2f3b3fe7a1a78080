# SPDX-License-Identifier: MIT
# tools/peer-bench/bench.mk - the host benchmarks against other libraries, each
# with its target figures (tools/peer-bench/run.sh runs both halves):
#   make bench         the Delaunay build of vor against CGAL,
#                      Boost.Polygon, delaunay32 (1 and 2 threads) and
#                      jc_voronoi, and instructions per inserted site on
#                      Cortex-M0, Cortex-M3 and RISC-V 32 (bench/delaunay.c
#                      under QEMU), then make bench-cdt's constrained rows;
#   make bench-query   nearest-site queries (coherent and random) against
#                      nanoflann's kd-tree and CGAL's nearest_vertex, and
#                      instructions per coherent query on Cortex-M3
#                      (examples/robot_nearest under QEMU);
#   make bench-dynamic removing and moving sites against CGAL's remove and
#                      move, and instructions per remove and move on
#                      Cortex-M3 (bench/dynamic.c under QEMU);
#   make bench-cdt     constrained Delaunay: vor_constrain against CGAL's
#                      Constrained_Delaunay_triangulation_2, CDT (artem-ogre)
#                      and delaunay32, and instructions per constraint on
#                      Cortex-M3 (bench/cdt.c under QEMU);
#   make bench-power   weighted sites: vor_power_build and vor_power_insert
#                      against CGAL's Regular_triangulation_2, and
#                      instructions per site on Cortex-M3 (bench/power.c
#                      under QEMU);
#   make bench-interpolate natural-neighbour interpolation: vor_interpolate
#                      and vor_interpolate_laplace against CGAL's
#                      natural_neighbor_coordinates_2 (Epick and Epeck), and
#                      instructions per query on Cortex-M3
#                      (bench/interpolate.c under QEMU);
#   make bench-jcv     vor beside jc_voronoi on the emulated Cortex-M4F:
#                      instructions, RAM and stack per build
#                      (tools/peer-bench/jcv_firmware.c); make bench runs it too.
# Included by the top-level Makefile after the port's port.mk.
#
# CGAL, Boost and nanoflann are used by these host benchmarks only, never by
# the library. tools/install-deps.sh installs them (groups bench and
# bench-query: libcgal-dev, libboost-dev, libnanoflann-dev).

# Keep the Makefile's own default goal: this file is included before it.
BENCH_SAVED_GOAL := $(.DEFAULT_GOAL)

BENCH_CXX ?= g++
BENCH_CXXFLAGS ?= -std=c++17 -O2 -DNDEBUG -Wall -Wextra
# CGAL 5 is header-only; Epick's exact fallback may pull in GMP and MPFR.
BENCH_LDLIBS ?= -lgmp -lmpfr

.PHONY: bench bench-query bench-dynamic bench-cdt bench-power bench-interpolate bench-jcv

bench:
	@tools/install-deps.sh bench host python toolchains
	+@tools/peer-bench/run.sh delaunay
	+@$(MAKE) -s --no-print-directory PORT=cortex-m4f bench-jcv
	+@tools/peer-bench/run.sh cdt

bench-query:
	@tools/install-deps.sh bench-query host python toolchains
	+@tools/peer-bench/run.sh query

bench-dynamic:
	@tools/install-deps.sh bench host python toolchains
	+@tools/peer-bench/run.sh dynamic

bench-cdt:
	@tools/install-deps.sh bench host python toolchains
	+@tools/peer-bench/run.sh cdt

bench-power:
	@tools/install-deps.sh bench host python toolchains
	+@tools/peer-bench/run.sh power

bench-interpolate:
	@tools/install-deps.sh bench host python toolchains
	+@tools/peer-bench/run.sh interpolate

# The peers of `make bench` and `make bench-cdt` (docs/benchmarks.md):
# delaunay32, jc_voronoi and CDT (header-only),
# compiled from their unmodified sources in $(PEERS) when it holds them (a
# developer's or CI's machine); without them their columns say "skipped".
PEERS ?= ../shared/peers
PEER_D32 := $(wildcard $(PEERS)/delaunay32/src/*.cpp)
PEER_JCV := $(wildcard $(PEERS)/jc_voronoi/jc_voronoi.h)
PEER_CDT := $(wildcard $(PEERS)/CDT/CDT/include/CDT.h)
PEER_OBJS := $(PEER_D32:$(PEERS)/delaunay32/src/%.cpp=build/bench/peers/delaunay32/%.o) \
             $(if $(PEER_JCV),build/bench/peers/jcv_peer.o)
PEER_FLAGS := $(if $(PEER_D32),-DVOR_BENCH_DELAUNAY32 -I$(PEERS)/delaunay32/include) \
              $(if $(PEER_JCV),-DVOR_BENCH_JCV)

# A host program, build/bench/NAME-host from tools/peer-bench/NAME.cpp, links the
# host release library (32-bit ids: up to 10^6 sites), so it is built with
# PORT=host (run.sh does that); other ports have no rule for it. The Delaunay
# benchmark also links the peers, and the library with predicate counters
# (VOR_STATS), which it reports per site.
ifeq ($(B),build/host)
bench_peer_lib = $(if $(filter delaunay,$(1)),$(B)/libvor-stats.a,$(B)/libvor.a)
build/bench/%-host: tools/peer-bench/%.cpp tools/peer-bench/bench_common.hpp \
                    tools/peer-bench/bench_memory.hpp $(LIB_HDRS_BENCH) $(B)/libvor.a $(B)/libvor-stats.a
	@mkdir -p $(@D)
	$(BENCH_CXX) $(BENCH_CXXFLAGS) $(BENCH_PEERS_$*) -Iinclude -DVOR_INDEX_BITS=32 \
	    $(if $(filter delaunay,$*),-DVOR_STATS=1) tools/peer-bench/$*.cpp $(call bench_peer_lib,$*) \
	    $(if $(BENCH_PEERS_$*),$(PEER_OBJS) -pthread -lm) $(BENCH_THREADS_$*) $(BENCH_LDLIBS) -o $@

BENCH_PEERS_delaunay = $(PEER_FLAGS)
# vor_build_dc_forked's std::thread hook
BENCH_THREADS_delaunay = -pthread
build/bench/delaunay-host: $(PEER_OBJS) tools/peer-bench/jcv_peer.h
BENCH_PEERS_cdt = $(PEER_FLAGS) $(if $(PEER_CDT),-DVOR_BENCH_CDT -I$(PEERS)/CDT/CDT/include)
build/bench/cdt-host: $(PEER_OBJS) $(PEER_CDT)

# The peers' own build flags (their README's), warnings theirs to keep.
build/bench/peers/delaunay32/%.o: $(PEERS)/delaunay32/src/%.cpp
	@mkdir -p $(@D)
	$(BENCH_CXX) -std=c++17 -O2 -DNDEBUG -I$(PEERS)/delaunay32/include -pthread -c $< -o $@

build/bench/peers/jcv_peer.o: tools/peer-bench/jcv_peer.c tools/peer-bench/jcv_peer.h $(PEER_JCV)
	@mkdir -p $(@D)
	gcc -std=c99 -O2 -DNDEBUG -I$(PEERS)/jc_voronoi -c $< -o $@
endif
LIB_HDRS_BENCH = $(wildcard include/*.h)

# The embedded peer: jc_voronoi on the Cortex-M4F beside vor
# (tools/peer-bench/jcv_firmware.c), with picolibc's malloc and libm, which the
# jcv group installs. picolibc's sbrk hands out RAM from the end of
# .bss to the end of RAM (4 MB on mps2-an386). jc_voronoi is compiled with
# its own flags: it is the peer's code, not ours to hold to our warnings.
ifeq ($(PORT),cortex-m4f)
ifneq ($(PEER_JCV),)
# the Makefile's PORT_OBJS, which is set after this file is read
BENCH_PORT_OBJS = $(addprefix $(B)/port/,$(addsuffix .o,$(basename $(notdir $(PORT_SRCS)))))

bench-jcv:
	@tools/install-deps.sh toolchains jcv
	@$(MAKE) -s PORT=cortex-m4f SANITIZE= $(B)/bench-jcv.elf
	$(RUN) $(B)/bench-jcv.elf

$(B)/bench-jcv.elf: tools/peer-bench/jcv_firmware.c tools/peer-bench/jcv_peer.c tools/peer-bench/jcv_peer.h \
                    $(PEER_JCV) $(B)/tests/harness.o $(BENCH_PORT_OBJS) $(B)/libvor.a
	$(CC) $(CPU_CFLAGS) --specs=picolibc.specs $(OPT) -ffunction-sections -fdata-sections \
	    -DNDEBUG -I$(PEERS)/jc_voronoi -c tools/peer-bench/jcv_peer.c -o $(B)/jcv_peer.o
	$(CC) $(TEST_CFLAGS) -Itools/peer-bench -c tools/peer-bench/jcv_firmware.c -o $(B)/jcv_firmware.o
	$(CC) $(CPU_CFLAGS) --specs=picolibc.specs -nostartfiles -T port/cortex-m4f/link.ld \
	    -Wl,--gc-sections -Wl,--defsym=__heap_start=__end -Wl,--defsym=__heap_end=0x20400000 \
	    $(B)/jcv_firmware.o $(B)/jcv_peer.o $(B)/tests/harness.o $(BENCH_PORT_OBJS) $(B)/libvor.a \
	    -lm -o $@
else
bench-jcv:
	@echo "bench-jcv: skipped: peer sources not found ($(PEERS)/jc_voronoi)"
endif
else
bench-jcv:
	@$(MAKE) -s PORT=cortex-m4f bench-jcv
endif

.DEFAULT_GOAL := $(BENCH_SAVED_GOAL)
