/* SPDX-License-Identifier: MIT */
/*
 * port/common/semihost.h - the architecture's half of semihosting.
 *
 * port/common/semihost.c implements output, exit status and host files
 * (the port.h functions) with ARM's semihosting operations, which RISC-V
 * semihosting reuses. Each architecture supplies the trap that performs one
 * operation, and what to do if the host ignores SYS_EXIT_EXTENDED.
 */
#ifndef VOR_PORT_SEMIHOST_H
#define VOR_PORT_SEMIHOST_H

#include <stdint.h>

/* One semihosting operation: op in r0/a0, the argument block's address in
 * r1/a1; returns r0/a0. Must act as a compiler memory barrier. */
uint32_t vor__semihost_call(uint32_t op, const void *block);

/* Called if SYS_EXIT_EXTENDED returned (no semihosting host): stop the
 * machine some other way, or wait forever. */
void vor__semihost_no_exit(int status)
#if defined(__GNUC__)
    __attribute__((noreturn))
#endif
    ;

#endif
