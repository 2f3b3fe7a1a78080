/* SPDX-License-Identifier: MIT */
/*
 * port/cortex-m/systick.c - vor_port_init and vor_port_counter for every
 * Cortex-M target: a 64-bit SysTick tick count, scaled to instructions.
 *
 * DWT CYCCNT reads 0 in QEMU, so the counter is SysTick on the processor
 * clock (CLKSOURCE = 1) with the longest reload, 2^24 ticks a period, and
 * an exception handler that counts periods. QEMU run with
 * -icount shift=0,align=off,sleep=off advances its virtual clock by exactly
 * 1 ns per executed instruction, so
 *     instructions = ticks * (ns per tick)
 * where ns per tick = 10^9 / SysTick clock. Each target's port.mk gives it,
 * in half nanoseconds, as VOR_PORT_HALF_NS_PER_TICK (mps2: 25 MHz, 40 ns;
 * nRF51 in QEMU: 16 MHz, 62.5 ns), so the count moves in steps of one tick:
 * 40 or 62.5 instructions, repeatable run to run (calibrated with loops of
 * known length: exact to one tick).
 *
 * On real silicon the ticks are core clock cycles: report them unscaled
 * with the unit "cycles" there (see port/template/port.c).
 */
#include "../port.h"

#include "cortex-m.h"

#ifndef VOR_PORT_HALF_NS_PER_TICK
#error "the target's port.mk must define VOR_PORT_HALF_NS_PER_TICK"
#endif

const char vor_port_counter_unit[] = "instructions";

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SCB_ICSR (*(volatile uint32_t *)0xE000ED04u)
#define SYST_CSR_ENABLE (1u << 0)
#define SYST_CSR_TICKINT (1u << 1)
#define SYST_CSR_CLKSOURCE (1u << 2)
#define SCB_ICSR_PENDSTSET (1u << 26)

/* Reload value; a smaller one (e.g. -DVOR_PORT_SYSTICK_RELOAD=0xFFF) makes
 * the period-counting path easy to exercise in a test. */
#ifndef VOR_PORT_SYSTICK_RELOAD
#define VOR_PORT_SYSTICK_RELOAD 0xFFFFFFu
#endif
#define PERIOD ((uint64_t)VOR_PORT_SYSTICK_RELOAD + 1u)

/* Completed SysTick periods, counted by the exception handler. */
static volatile uint32_t periods = 0u;
static int started = 0;

void SysTick_Handler(void)
{
    periods = periods + 1u;
}

void vor_port_init(void)
{
    if (started) { /* idempotent: the counter keeps running */
        return;
    }
    started = 1;
    SYST_CSR = 0u;
    SYST_RVR = VOR_PORT_SYSTICK_RELOAD;
    SYST_CVR = 0u; /* any write clears the current value */
    SYST_CSR = SYST_CSR_CLKSOURCE | SYST_CSR_TICKINT | SYST_CSR_ENABLE;
    /* The cleared counter reads 0 until the first tick reloads it; wait for
     * that so that the first period is a whole one. At most one tick. */
    while (SYST_CVR == 0u) {
    }
}

/* Ticks since vor_port_init. Read race-free with interrupts masked: if the counter has wrapped but
 * the handler has not run yet (PENDSTSET), re-read the value, which now
 * belongs to the new period, and count that period here. */
uint64_t vor__cm_systick_ticks(void)
{
    uint32_t primask;
    uint32_t n;
    uint32_t value;

    __asm__ volatile("mrs %0, primask" : "=r"(primask));
    __asm__ volatile("cpsid i" ::: "memory");
    n = periods;
    value = SYST_CVR;
    if ((SCB_ICSR & SCB_ICSR_PENDSTSET) != 0u) {
        value = SYST_CVR;
        n++;
    }
    if ((primask & 1u) == 0u) {
        __asm__ volatile("cpsie i" ::: "memory");
    }
    /* The exception pends as the value reaches 0, so 0 starts a period:
     * 0, RELOAD, RELOAD - 1, ..., 1 are ticks 0, 1, 2, ..., RELOAD of it. */
    return (uint64_t)n * PERIOD
           + (value == 0u ? 0u : PERIOD - (uint64_t)value);
}

uint64_t vor_port_counter(void)
{
    uint64_t ticks;
    VOR_PORT_BARRIER();
    ticks = vor__cm_systick_ticks();
    VOR_PORT_BARRIER();
    return (ticks * VOR_PORT_HALF_NS_PER_TICK) >> 1;
}
