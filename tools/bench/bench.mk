# tools/bench/bench.mk - `make bench`: the Delaunay build of vor against
# CGAL and Boost.Polygon on the host, and instructions per inserted site on
# Cortex-M0, Cortex-M3 and RISC-V 32 (bench/delaunay.c under QEMU).
# Included by the top-level Makefile after the port's port.mk.
#
# CGAL and Boost are used by this host benchmark only, never by the library.
# tools/bench/install-deps.sh installs them (libcgal-dev, libboost-dev).

# Keep the Makefile's own default goal: this file is included before it.
BENCH_SAVED_GOAL := $(.DEFAULT_GOAL)

BENCH_HOST := build/bench/delaunay-host
BENCH_CXX ?= g++
BENCH_CXXFLAGS ?= -std=c++17 -O2 -DNDEBUG -Wall -Wextra
# CGAL 5 is header-only; Epick's exact fallback may pull in GMP and MPFR.
BENCH_LDLIBS ?= -lgmp -lmpfr

.PHONY: bench

bench:
	@tools/bench/install-deps.sh
	@tools/install-toolchain.sh
	+@tools/bench/run.sh

# The host program links the host release library, so it is built with
# PORT=host (run.sh does that); other ports have no rule for it.
ifeq ($(B),build/host)
$(BENCH_HOST): tools/bench/delaunay.cpp $(LIB_HDRS_BENCH) $(B)/libvor.a
	@mkdir -p $(@D)
	$(BENCH_CXX) $(BENCH_CXXFLAGS) -Iinclude $< $(B)/libvor.a $(BENCH_LDLIBS) -o $@
endif
LIB_HDRS_BENCH = $(wildcard include/*.h)

.DEFAULT_GOAL := $(BENCH_SAVED_GOAL)
