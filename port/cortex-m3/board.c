/*
 * port/cortex-m3/board.c - the instruction counter on QEMU's mps2-an385 board.
 */
#include "../port.h"

#include "../cortex-m/cortex-m.h"

const char vor_port_counter_unit[] = "instructions";

/* SysTick runs on the 25 MHz processor clock of MPS2: 40 ns per tick, and
 * under -icount shift=0 one instruction takes 1 ns, so 40 instructions per
 * tick (calibrated with a loop of known length: exact to one tick). */
uint64_t vor_port_counter(void)
{
    uint64_t ticks;
    VOR_PORT_BARRIER();
    ticks = vor__cm_systick_ticks();
    VOR_PORT_BARRIER();
    return ticks * 40u;
}
