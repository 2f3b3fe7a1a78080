/* SPDX-License-Identifier: MIT */
/*
 * example_io.h - what the example firmwares share: output without a C
 * library, a deterministic random generator, and a brute-force nearest
 * site to check vor's answers against.
 */
#ifndef VOR_EXAMPLE_IO_H
#define VOR_EXAMPLE_IO_H

#include <stdint.h>

#include "vor.h"

void example_print(const char *text);
void example_print_uint(uint64_t value);
void example_print_int(int64_t value);

/* xorshift32: the same sequence on every target; *state must be nonzero. */
uint32_t example_random(uint32_t *state);

/* The nearest of sites[0 .. n) to (x, y) by exact distance, ties to the
 * smaller index; sites i with first_of[i] != i are skipped (first_of may
 * be NULL). Coordinate differences must stay below 2^31. */
uint32_t example_brute_nearest(const vor_point_t *sites, uint32_t n, const uint32_t *first_of,
                               int32_t x, int32_t y);

#endif
