/*
 * port/cortex-m0/board.c - the instruction counter on QEMU's microbit
 * board (nRF51).
 */
#include "../port.h"

#include "../cortex-m/cortex-m.h"

const char vor_port_counter_unit[] = "instructions";

/* QEMU gives the nRF51 a SysTick on its 16 MHz HCLK (real nRF51 silicon
 * has none: use TIMER0 there): 62.5 ns per tick, and under -icount shift=0
 * one instruction takes 1 ns, so 62.5 instructions per tick (calibrated
 * with a loop of known length: exact to one tick). */
uint64_t vor_port_counter(void)
{
    uint64_t ticks;
    VOR_PORT_BARRIER();
    ticks = vor__cm_systick_ticks();
    VOR_PORT_BARRIER();
    return (ticks * 125u) >> 1;
}
