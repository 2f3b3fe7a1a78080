# SPDX-License-Identifier: MIT
# tools/size-features.mk - rules for tools/size-features.sh: the
# Makefile's own variables and rules, plus the bench/size/ firmwares
# linked with a map against a library with call graphs (-fcallgraph-info).
#   make -f tools/size-features.mk PORT=cortex-m3 OPT=-Os B=DIR vor-features
include Makefile

VOR_FEATURES := $(basename $(notdir $(wildcard bench/size/*.c)))
vor-feature-objs := $(LIB_SRCS:src/%.c=$(B)/lib/%.o)
$(vor-feature-objs): LIB_CFLAGS += -fcallgraph-info=su

.PHONY: vor-features
vor-features: $(patsubst %,$(B)/size-%$(EXE),$(VOR_FEATURES))

$(B)/size-lib.a: $(vor-feature-objs)
	@rm -f $@
	$(AR) rcs $@ $^

$(B)/size-%.o: bench/size/%.c $(wildcard bench/size/*.h) $(LIB_HDRS) | $(B)/lib
	$(CC) $(TEST_CFLAGS) -c $< -o $@

$(B)/size-%$(EXE): $(B)/size-%.o $(PORT_OBJS) $(B)/size-lib.a
	$(CC) $(TEST_CFLAGS) $< $(PORT_OBJS) $(B)/size-lib.a $(FW_LDFLAGS) \
	    -Wl,-Map=$(B)/size-$*.map $(FW_LDLIBS) -o $@

# kept: tools/size-features.sh reads which public calls each program makes
.SECONDARY: $(patsubst %,$(B)/size-%.o,$(VOR_FEATURES))
