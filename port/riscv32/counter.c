/* SPDX-License-Identifier: MIT */
/*
 * port/riscv32/counter.c - vor_port_init and the instruction counter:
 * the minstret CSR, which counts retired instructions exactly on silicon
 * and, under QEMU, when run with -icount (without it QEMU returns host CPU
 * ticks). Granularity: 1 instruction.
 */
#include "../port.h"

#include "riscv32.h"

const char vor_port_counter_unit[] = "instructions";

void vor_port_init(void)
{
    /* minstret runs from reset; startup.c has already set the trap vector.
     * Nothing to do, and so idempotent. */
}

/* 64-bit read on RV32: high, low, high again, and retry if the low half
 * carried into the high half in between. */
uint64_t vor_port_counter(void)
{
    uint32_t hi;
    uint32_t lo;
    uint32_t again;

    do { /* at most twice: a carry happens once per 2^32 instructions */
        VOR_RV_CSR_READ(VOR_RV_CSR_MINSTRETH, hi);
        VOR_RV_CSR_READ(VOR_RV_CSR_MINSTRET, lo);
        VOR_RV_CSR_READ(VOR_RV_CSR_MINSTRETH, again);
    } while (hi != again);
    return ((uint64_t)hi << 32) | lo;
}
