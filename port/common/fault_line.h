/*
 * port/common/fault_line.h - building the one-line "fatal: ..." report of a
 * fault handler without a C library (shared by the Cortex-M and RISC-V
 * startups).
 */
#ifndef VOR_PORT_FAULT_LINE_H
#define VOR_PORT_FAULT_LINE_H

#include <stddef.h>
#include <stdint.h>

/* Append text to line[0..n), stopping at capacity; returns the new n. */
size_t vor__line_text(char *line, size_t n, size_t capacity, const char *text);

/* Append label, then value as eight hexadecimal digits. */
size_t vor__line_hex(char *line, size_t n, size_t capacity, const char *label,
                     uint32_t value);

#endif
