/* SPDX-License-Identifier: MIT */
/* port/common/fault_line.c - see fault_line.h. */
#include "fault_line.h"

size_t vor__line_text(char *line, size_t n, size_t capacity, const char *text)
{
    for (; *text != '\0' && n < capacity; text++) { /* bounded by the line */
        line[n++] = *text;
    }
    return n;
}

size_t vor__line_hex(char *line, size_t n, size_t capacity, const char *label,
                     uint32_t value)
{
    static const char digits[] = "0123456789abcdef";
    n = vor__line_text(line, n, capacity, label);
    for (int shift = 28; shift >= 0 && n < capacity; shift -= 4) {
        line[n++] = digits[(value >> (unsigned)shift) & 0xFu];
    }
    return n;
}
