# SPDX-License-Identifier: MIT
# tools/bench/bench.mk - the host benchmarks against other libraries, each
# with its target figures (tools/bench/run.sh runs both halves):
#   make bench         the Delaunay build of vor against CGAL,
#                      Boost.Polygon, delaunay32 (1 and 2 threads) and
#                      jc_voronoi, and instructions per inserted site on
#                      Cortex-M0, Cortex-M3 and RISC-V 32 (bench/delaunay.c
#                      under QEMU);
#   make bench-query   nearest-site queries (coherent and random) against
#                      nanoflann's kd-tree and CGAL's nearest_vertex, and
#                      instructions per coherent query on Cortex-M3
#                      (examples/robot_nearest under QEMU);
#   make bench-dynamic removing and moving sites against CGAL's remove and
#                      move, and instructions per remove and move on
#                      Cortex-M3 (bench/dynamic.c under QEMU).
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

.PHONY: bench bench-query bench-dynamic

bench:
	@tools/install-deps.sh bench host python toolchains
	+@tools/bench/run.sh delaunay

bench-query:
	@tools/install-deps.sh bench-query host python toolchains
	+@tools/bench/run.sh query

bench-dynamic:
	@tools/install-deps.sh bench host python toolchains
	+@tools/bench/run.sh dynamic

# The peers of `make bench` (docs/benchmarks.md): delaunay32 and jc_voronoi,
# compiled from their unmodified sources in $(PEERS) when it holds them (a
# developer's or CI's machine); without them their columns say "skipped".
PEERS ?= ../shared/peers
PEER_D32 := $(wildcard $(PEERS)/delaunay32/src/*.cpp)
PEER_JCV := $(wildcard $(PEERS)/jc_voronoi/jc_voronoi.h)
PEER_OBJS := $(PEER_D32:$(PEERS)/delaunay32/src/%.cpp=build/bench/peers/delaunay32/%.o) \
             $(if $(PEER_JCV),build/bench/peers/jcv_peer.o)
PEER_FLAGS := $(if $(PEER_D32),-DVOR_BENCH_DELAUNAY32 -I$(PEERS)/delaunay32/include) \
              $(if $(PEER_JCV),-DVOR_BENCH_JCV)

# A host program, build/bench/NAME-host from tools/bench/NAME.cpp, links the
# host release library, so it is built with PORT=host (run.sh does that);
# other ports have no rule for it. The Delaunay benchmark also links the peers.
ifeq ($(B),build/host)
build/bench/%-host: tools/bench/%.cpp tools/bench/bench_common.hpp $(LIB_HDRS_BENCH) $(B)/libvor.a
	@mkdir -p $(@D)
	$(BENCH_CXX) $(BENCH_CXXFLAGS) $(BENCH_PEERS_$*) -Iinclude tools/bench/$*.cpp $(B)/libvor.a \
	    $(if $(BENCH_PEERS_$*),$(PEER_OBJS) -pthread -lm) $(BENCH_LDLIBS) -o $@

BENCH_PEERS_delaunay = $(PEER_FLAGS)
build/bench/delaunay-host: $(PEER_OBJS) tools/bench/jcv_peer.h

# The peers' own build flags (their README's), warnings theirs to keep.
build/bench/peers/delaunay32/%.o: $(PEERS)/delaunay32/src/%.cpp
	@mkdir -p $(@D)
	$(BENCH_CXX) -std=c++17 -O2 -DNDEBUG -I$(PEERS)/delaunay32/include -pthread -c $< -o $@

build/bench/peers/jcv_peer.o: tools/bench/jcv_peer.c tools/bench/jcv_peer.h $(PEER_JCV)
	@mkdir -p $(@D)
	gcc -std=c99 -O2 -DNDEBUG -I$(PEERS)/jc_voronoi -c $< -o $@
endif
LIB_HDRS_BENCH = $(wildcard include/*.h)

.DEFAULT_GOAL := $(BENCH_SAVED_GOAL)
