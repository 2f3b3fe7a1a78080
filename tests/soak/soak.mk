# SPDX-License-Identifier: MIT
# make soak: tests/soak/soak.c, a long randomized run of one dynamic
# diagram against a model and fresh builds (included by the Makefile).
#   make soak SOAK_OPERATIONS=10000000 SOAK_SITES=20000 SOAK_SEED=1

SOAK_OPERATIONS ?= 10000000
SOAK_SITES ?= 20000
SOAK_SEED ?= 1

.PHONY: soak
# 32-bit ids: SOAK_SITES may pass 32,767
build/soak/soak: tests/soak/soak.c $(LIB_SRCS) $(LIB_HDRS) tests/soak/soak.mk
	@mkdir -p build/soak
	$(CC) -std=c99 $(WARNINGS) -O2 $(CHECKED_DEFS) -DVOR_INDEX_BITS=32 -Iinclude -Isrc $< $(LIB_SRCS) -o $@

soak: build/soak/soak
	build/soak/soak $(SOAK_OPERATIONS) $(SOAK_SITES) $(SOAK_SEED)
