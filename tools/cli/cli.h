/* SPDX-License-Identifier: MIT */
/*
 * cli.h - shared pieces of the host command-line tool build/host/vor:
 * input lines, strict integer fields, error exits, buffered output.
 * Host-only code: it may use the C library freely.
 */
#ifndef VOR_CLI_H
#define VOR_CLI_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "vor.h"

/* Input read line by line; blank lines and lines starting with '#' are
 * skipped, and line numbers count every physical line from 1. */
typedef struct {
    FILE *file;
    const char *name;
    unsigned long line_number;
    char *buffer;
    size_t capacity;
} cli_input_t;

/* Opens path ("-" is standard input); exits with status 2 when it cannot. */
void cli_open(cli_input_t *in, const char *path);
void cli_close(cli_input_t *in);

/* The next non-blank, non-comment line, or NULL at the end of the input.
 * The line stays valid until the next call. */
const char *cli_next_line(cli_input_t *in);

/* Parses one decimal int32 field at *cursor, skipping leading blanks, and
 * advances the cursor. Returns false (input unchanged) when there is no
 * field, it is not a decimal integer, or it is out of the int32 range;
 * *why then says which. */
bool cli_int32_field(const char **cursor, int32_t *value, const char **why);

/* True when only blanks remain at cursor. */
bool cli_at_end(const char *cursor);

/* Prints "error: line N: reason" to stderr and exits with status 2. */
void cli_line_error(const cli_input_t *in, const char *reason)
#if defined(__GNUC__)
    __attribute__((noreturn))
#endif
    ;

/* Prints "error: message" to stderr and exits with status 2. */
void cli_error(const char *message)
#if defined(__GNUC__)
    __attribute__((noreturn))
#endif
    ;

/* Output collected in memory and written only once the whole input was
 * valid, so a bad line leaves stdout empty. */
typedef struct {
    char *data;
    size_t length;
    size_t capacity;
} cli_output_t;

void cli_append(cli_output_t *out, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* Writes everything to stdout and frees the buffer. */
void cli_flush(cli_output_t *out);

/* Reads a site file ("x y" per line, blank and '#' lines skipped; site i
 * is the i-th site line) from path ("-": stdin). Exits with status 2 on a
 * bad line. The array is malloc'd; *count receives the number of sites. */
vor_point_t *cli_read_sites(const char *path, uint32_t *count);

/* Seconds from a monotonic clock, for --stats. */
double cli_seconds(void);

/* Subcommands: each takes its arguments after the subcommand name and
 * returns the process exit status. */
int cli_predicates(int argc, char **argv);
int cli_delaunay(int argc, char **argv);
int cli_nearest(int argc, char **argv);
int cli_raster(int argc, char **argv);
int cli_cells(int argc, char **argv);
int cli_ops(int argc, char **argv);

#endif
