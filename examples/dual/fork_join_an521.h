/* SPDX-License-Identifier: MIT */
/*
 * fork_join_an521.h - a vor_fork_join_t hook for the two Cortex-M33 cores
 * of Arm's SSE-200 subsystem as QEMU's mps2-an521 board models it: the
 * calling core is core 0, the work runs on core 1.
 *
 *     static an521_fork_join_t state;   // zero: run in parallel
 *     vor_fork_join_t hook = {an521_fork, an521_join, &state};
 *     err = vor_build_dc_forked(&d, points, n, &options, NULL, &hook);
 *
 * The first fork releases core 1 from reset (its vector table address in
 * the system control block's INITSVTOR1, then 0 in CPUWAIT); it runs
 * an521_core1_main on its own stack, AN521_CORE1_STACK_BYTES, and waits
 * there for work. Each fork posts work(arg) in a mailbox in shared RAM and
 * signals core 1 through the message handling unit MHU0 (the subsystem's
 * inter-core interrupt); core 1 runs it, publishes a finished count and
 * signals core 0 back through the same MHU. A waiting core sleeps in wfi
 * with the MHU's interrupt enabled but masked (PRIMASK), so the signal
 * wakes it without a handler. Barriers: dmb before each count is
 * published and after it is seen, so everything the work wrote is
 * visible to core 0 once an521_join returns (happens-before). There are
 * no caches on this board; on a part with a data cache see
 * docs/porting.md, "Two cores".
 *
 * With state.measure nonzero, fork waits for core 1 to finish before it
 * returns, so that the two halves run one after the other, each on its
 * own core while the other sleeps: under QEMU's -icount both cores share
 * one clock, and this is how each core's instructions are counted apart
 * (examples/dual/main.c). The result is the same either way.
 */
#ifndef VOR_EXAMPLE_FORK_JOIN_AN521_H
#define VOR_EXAMPLE_FORK_JOIN_AN521_H

#include <stdint.h>

/* Core 1's stack: about vor_build_dc's (docs/benchmarks.md, "Memory: stack
 * and RAM budget") and a wide margin; the example prints what it used. */
#define AN521_CORE1_STACK_BYTES 8192u

typedef struct an521_fork_join {
    uint32_t measure;       /* nonzero: fork returns once core 1 is done */
    /* Written by the hook on core 0 (vor_port_counter's instructions): */
    uint64_t at_fork;       /* fork entered */
    uint64_t at_core1_done; /* measure: core 1 reported its work done */
    uint64_t at_join;       /* join entered */
    uint32_t forks;         /* forks that posted work to core 1 */
    uint32_t joins;
} an521_fork_join_t;

/* vor_fork_join_t's fork: posts work(arg) to core 1 and returns 0, or
 * returns 1 when core 1 is still busy with an earlier work. context: an
 * an521_fork_join_t. Call from core 0 only. */
int an521_fork(void *context, void (*work)(void *arg), void *arg);

/* vor_fork_join_t's join: returns once core 1 has finished every work
 * posted, with its writes visible here. */
void an521_join(void *context);

/* Works core 1 has finished since reset (read on core 0). */
uint32_t an521_core1_runs(void);

/* Bytes of core 1's stack ever used (its unused part is painted before
 * core 1 starts). */
uint32_t an521_core1_stack_used(void);

#endif
