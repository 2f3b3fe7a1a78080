/* SPDX-License-Identifier: MIT */
/*
 * example_io.h - what the example firmwares share: output without a C
 * library, a tally of their checks, a deterministic random generator, and
 * a brute-force nearest site to check vor's answers against.
 */
#ifndef VOR_EXAMPLE_IO_H
#define VOR_EXAMPLE_IO_H

#include <stdbool.h>
#include <stdint.h>

#include "vor.h"

void example_print(const char *text);
void example_print_uint(uint64_t value);
void example_print_int(int64_t value);

/* Counts a check, printing "FAIL what" when it fails. */
void example_check(bool ok, const char *what);
/* Prints "N passed, N failed" (an example's last line); returns the
 * exit status: 0 when every check passed. */
int example_print_tally(void);

/* xorshift32: the same sequence on every target; *state must be nonzero. */
uint32_t example_random(uint32_t *state);

/* The nearest of sites[0 .. n) to (x, y) by exact distance, ties to the
 * smaller index; sites i with first_of[i] != i are skipped (first_of may
 * be NULL). Coordinate differences must stay below 2^31. */
uint32_t example_brute_nearest(const vor_point_t *sites, uint32_t n, const uint32_t *first_of,
                               int32_t x, int32_t y);

/* A text file on the host (through semihosting; without one, writes are
 * dropped), buffered: semihosting calls are slow. */
typedef struct example_file {
    int handle; /* negative: no host file */
    uint32_t used;
    char buffer[512];
} example_file_t;

void example_file_open(example_file_t *f, const char *path);
void example_file_text(example_file_t *f, const char *text);
/* Writes " VALUE" in decimal. */
void example_file_int(example_file_t *f, int32_t value);
/* Writes what is buffered and closes the file. */
void example_file_close(example_file_t *f);

/* Writes path (a host file, through semihosting) as `vor draw --cells`
 * reads it: "box X0 Y0 X1 Y1", one "s X Y" line per site of sites[0 .. n)
 * (site i is the i-th), and one "c I M X1 Y1 ..." line per cell of the
 * diagram clipped to box, as `vor cells` prints them. Returns the number
 * of cells written, or -1 when a cell failed. Without a host file the
 * cells are still computed and counted. */
int32_t example_dump_cells(const char *path, const vor_t *diagram, const vor_point_t *sites,
                           uint32_t n, const vor_box_t *box);

#endif
