/* SPDX-License-Identifier: MIT */
/*
 * port/common/fault_line.h - what the Cortex-M and RISC-V fault handlers
 * share: the exit status, function attributes, and building the one-line
 * "fatal: ..." report without a C library.
 */
#ifndef VOR_PORT_FAULT_LINE_H
#define VOR_PORT_FAULT_LINE_H

#include <stddef.h>
#include <stdint.h>

/* Exit status of a program stopped by a fault, trap or unexpected
 * exception (the harness self-test checks it). */
#define VOR_PORT_FAULT_STATUS 99

#if defined(__GNUC__)
#define VOR_PORT_NORETURN __attribute__((noreturn))
#define VOR_PORT_USED __attribute__((used))
#else
#define VOR_PORT_NORETURN
#define VOR_PORT_USED
#endif

/* Append text to line[0..n), stopping at capacity; returns the new n. */
size_t vor__line_text(char *line, size_t n, size_t capacity, const char *text);

/* Append label, then value as eight hexadecimal digits. */
size_t vor__line_hex(char *line, size_t n, size_t capacity, const char *label,
                     uint32_t value);

#endif
