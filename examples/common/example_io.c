/* SPDX-License-Identifier: MIT */
/* example_io.c - see example_io.h. */
#include "example_io.h"

#include "port.h"

void example_print(const char *text)
{
    size_t n = 0;
    while (text[n] != '\0') {
        n++;
    }
    vor_port_write(text, n);
}

void example_print_uint(uint64_t value)
{
    char buf[24];
    size_t n = sizeof buf;
    do {
        buf[--n] = (char)('0' + (int)(value % 10u));
        value /= 10u;
    } while (value != 0u);
    vor_port_write(buf + n, sizeof buf - n);
}

void example_print_int(int64_t value)
{
    if (value < 0) {
        example_print("-");
        example_print_uint(0u - (uint64_t)value);
    } else {
        example_print_uint((uint64_t)value);
    }
}

uint32_t example_random(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

uint32_t example_brute_nearest(const vor_point_t *sites, uint32_t n, const uint32_t *first_of,
                               int32_t x, int32_t y)
{
    uint32_t best = 0;
    uint64_t best_d = UINT64_MAX;
    for (uint32_t i = 0; i < n; i++) {
        int64_t dx = (int64_t)sites[i].x - x, dy = (int64_t)sites[i].y - y;
        uint64_t d = (uint64_t)(dx * dx + dy * dy);
        if ((first_of == NULL || first_of[i] == i) && d < best_d) {
            best = i;
            best_d = d;
        }
    }
    return best;
}
