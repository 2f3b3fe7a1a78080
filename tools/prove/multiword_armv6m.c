/* SPDX-License-Identifier: MIT */
/*
 * multiword_armv6m.c - the multi-word harness (multiword.c) on the
 * Cortex-M0 (ARMv6-M) code of src/multiword.h: its 32x32 and 64x32
 * multiplies from 16-bit halves, which no other harness reaches.
 */
#define __ARM_ARCH_6M__ 1

#include "multiword.c"
