# SPDX-License-Identifier: MIT
# The libFuzzer harnesses of tests/fuzz/ (included by the Makefile). Each is
# built with clang's libFuzzer, AddressSanitizer and UBSan straight from the
# library sources (sources.txt) with the test builds' trapping assertions.
#   make fuzz            each harness for FUZZ_SECONDS (default 600)
#   make fuzz-harnesses  build them only
# tools/fuzz.sh runs them; make test replays the corpora (tools/run-tests.sh).

FUZZ_CC ?= clang-14
FUZZ_SECONDS ?= 600
FUZZ_DIR := build/fuzz
FUZZ_CFLAGS := -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined \
               -fno-sanitize-recover=all -fno-omit-frame-pointer $(WARNINGS) \
               $(CHECKED_DEFS) -Iinclude -Isrc -Itests -Itests/fuzz
FUZZ_HARNESSES := $(addprefix $(FUZZ_DIR)/fuzz_,api16 api32 predicates predicates32 raster cli)
FUZZ_DEPS := $(LIB_SRCS) $(LIB_HDRS) tests/fuzz/fuzz_common.h tests/fuzz/fuzz.mk
# The CLI's sources, its main renamed and its exits routed through the
# harness (tests/fuzz/fuzz_cli.c says why).
FUZZ_CLI_SRCS := $(wildcard tools/cli/*.c)
FUZZ_CLI_OBJS := $(FUZZ_CLI_SRCS:tools/cli/%.c=$(FUZZ_DIR)/cli/%.o)

.PHONY: fuzz fuzz-harnesses fuzz-deps
fuzz-deps:
	@tools/install-deps.sh fuzz cli

fuzz-harnesses: fuzz-deps $(FUZZ_HARNESSES)

$(FUZZ_DIR)/fuzz_api%: tests/fuzz/fuzz_api.c tests/fuzz/fuzz_hpoint.h $(FUZZ_DEPS) | fuzz-deps
	@mkdir -p $(FUZZ_DIR)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -DVOR_INDEX_BITS=$* $< $(LIB_SRCS) -o $@

$(FUZZ_DIR)/fuzz_predicates: tests/fuzz/fuzz_predicates.c $(FUZZ_DEPS) | fuzz-deps
	@mkdir -p $(FUZZ_DIR)
	$(FUZZ_CC) $(FUZZ_CFLAGS) $< $(LIB_SRCS) -o $@

# The same harness on the targets' 32-bit limbs (their mid incircle filter).
$(FUZZ_DIR)/fuzz_predicates32: tests/fuzz/fuzz_predicates.c $(FUZZ_DEPS) | fuzz-deps
	@mkdir -p $(FUZZ_DIR)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -DVOR_LIMB_BITS=32 $< $(LIB_SRCS) -o $@

$(FUZZ_DIR)/fuzz_raster: tests/fuzz/fuzz_raster.c tests/raster_reference.c tests/raster_reference.h $(FUZZ_DEPS) | fuzz-deps
	@mkdir -p $(FUZZ_DIR)
	$(FUZZ_CC) $(FUZZ_CFLAGS) $< tests/raster_reference.c $(LIB_SRCS) -o $@

$(FUZZ_DIR)/cli/main.o: FUZZ_CLI_MAIN := -Dmain=vor_cli_main
$(FUZZ_DIR)/cli/%.o: tools/cli/%.c $(wildcard tools/cli/*.h) tools/png_write.h $(FUZZ_DEPS) | fuzz-deps
	@mkdir -p $(FUZZ_DIR)/cli
	$(FUZZ_CC) -std=c99 -D_POSIX_C_SOURCE=200809L -g -O1 -fsanitize=fuzzer,address,undefined \
	    -fno-sanitize-recover=all $(FUZZ_CLI_MAIN) -Dexit=vor_fuzz_cli_exit \
	    -Iinclude -Isrc -Itools -Itools/cli -c $< -o $@

$(FUZZ_DIR)/fuzz_cli: tests/fuzz/fuzz_cli.c $(FUZZ_CLI_OBJS) $(FUZZ_DEPS) | fuzz-deps
	$(FUZZ_CC) $(FUZZ_CFLAGS) $< $(FUZZ_CLI_OBJS) $(LIB_SRCS) -lm -o $@

fuzz: fuzz-harnesses
	tools/fuzz.sh --seconds $(FUZZ_SECONDS)
