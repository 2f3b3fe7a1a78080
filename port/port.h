/* SPDX-License-Identifier: MIT */
/*
 * port.h - the one narrow interface between vor's tests, examples and
 * benchmarks and the machine they run on.
 *
 * The library itself (src/, include/) never calls the port: it is pure
 * computation over caller memory. Test firmware, examples and benchmarks
 * call these few functions, and each target implements them under
 * port/<target>/ together with its startup code and linker script.
 * port/template/ is the starting point for a new target (docs/porting.md).
 */
#ifndef VOR_PORT_H
#define VOR_PORT_H

#include <stddef.h>
#include <stdint.h>

/* Bring the machine to a state where main() can run: called first by main().
 * Starts the instruction counter. */
void vor_port_init(void);

/* Write n bytes to the host's standard output (semihosting on targets). */
void vor_port_write(const char *text, size_t n);

/* End the program with this exit status; the host shell sees the exact
 * value (semihosting SYS_EXIT_EXTENDED on targets). Never returns. */
void vor_port_exit(int status)
#if defined(__GNUC__)
    __attribute__((noreturn))
#endif
    ;

/* A monotonically increasing count of executed instructions, or the
 * closest repeatable thing the target has (see vor_port_counter_unit).
 * Under QEMU with -icount every target reports instructions. */
uint64_t vor_port_counter(void);

/* What vor_port_counter counts: "instructions" or "ns" (host). */
extern const char vor_port_counter_unit[];

/* Host files, for streaming images and tables out of firmware
 * (semihosting SYS_OPEN/SYS_WRITE/SYS_CLOSE on targets). open creates or
 * truncates a binary file and returns a handle >= 0, or -1; write returns
 * 0 when all n bytes were written, else -1; close returns 0 or -1. */
int vor_port_file_open(const char *path);
int vor_port_file_write(int handle, const void *data, size_t n);
int vor_port_file_close(int handle);

#endif
