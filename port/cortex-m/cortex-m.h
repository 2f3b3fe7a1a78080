/* SPDX-License-Identifier: MIT */
/*
 * port/cortex-m/cortex-m.h - private declarations shared by the Cortex-M
 * port files (not part of vor's interface; see port/port.h for that).
 */
#ifndef VOR_PORT_CORTEX_M_H
#define VOR_PORT_CORTEX_M_H

#include <stddef.h>
#include <stdint.h>

#include "../common/fault_line.h"

/* SysTick ticks since vor_port_init(), 64 bits, monotonic (systick.c),
 * scaled into vor_port_counter() there. */
uint64_t vor__cm_systick_ticks(void);

/* Keeps the compiler from moving memory accesses across a counter read. */
#if defined(__GNUC__)
#define VOR_PORT_BARRIER() __asm__ volatile("" ::: "memory")
#else
#define VOR_PORT_BARRIER() ((void)0)
#endif

#endif
