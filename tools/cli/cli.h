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
#include "vor_power.h"

/* Input read line by line; a UTF-8 byte-order mark opening the input is
 * dropped, blank lines and lines starting with '#' are skipped, and line
 * numbers count every physical line from 1. A line with
 * a comma is CSV: its commas become blanks, after checking that no field is
 * empty or holds a blank. While header_allowed (cli_open sets it), a first
 * CSV line every field of which starts with a letter or '"' is a header and
 * skipped: no record of any format is such a line, so none is dropped. */
typedef struct {
    FILE *file;
    const char *name;
    unsigned long line_number;
    char *buffer;
    size_t capacity;
    bool header_allowed;
} cli_input_t;

/* Opens path ("-" is standard input); exits with status 2, naming the path
 * and the system's reason, when it cannot or when path is a directory. */
void cli_open(cli_input_t *in, const char *path);
void cli_close(cli_input_t *in);

/* The next non-blank, non-comment line, or NULL at the end of the input.
 * The line stays valid until the next call. A NUL byte, a read error or a
 * malformed CSV line is an error exit naming the file and line. */
const char *cli_next_line(cli_input_t *in);

/* Parses one decimal int32 field at *cursor, skipping leading blanks, and
 * advances the cursor. Returns false (input unchanged) when there is no
 * field, it is not a decimal integer, or it is out of the int32 range;
 * *why then says which, quoting the field (valid until the next call). */
bool cli_int32_field(const char **cursor, int32_t *value, const char **why);

/* Like cli_int32_field for a coordinate (or a distance in the same units):
 * after cli_set_scale, a decimal number times the scale, rounded to the
 * nearest integer, ties away from zero, computed exactly. */
bool cli_coordinate_field(const char **cursor, int32_t *value, const char **why);

/* A decimal int64 for a squared length (a power weight, the square of a
 * radius): after cli_set_scale, a decimal number times the scale squared,
 * rounded to the nearest integer, ties away from zero, computed exactly,
 * so that the weights scale with the coordinates. */
bool cli_squared_field(const char **cursor, int64_t *value, const char **why);

/* Sets the scale of cli_coordinate_field from the text of --scale S (a
 * positive decimal); exits with status 2 when it is not one. */
void cli_set_scale(const char *text);

/* True when only blanks remain at cursor. */
bool cli_at_end(const char *cursor);

/* An option of a command: its name ("--k", "-o") and how many values
 * follow it (0: a flag, at most CLI_MOST_VALUES). */
typedef struct {
    const char *name;
    unsigned values;
} cli_option_t;

#define CLI_MOST_VALUES 4
#define CLI_POSITIONAL (-1)
#define CLI_END (-2)

/* A command's arguments, walked by cli_next_argument: the one option
 * parser of every command. */
typedef struct {
    int argc;
    char **argv;
    int next;
    const char *command, *usage; /* for cli_usage_error */
    const cli_option_t *options;
    size_t option_count;
    const char *values[CLI_MOST_VALUES]; /* the option's values, or the positional argument */
} cli_arguments_t;

void cli_arguments_begin(cli_arguments_t *a, int argc, char **argv, const char *command, const char *usage,
                         const cli_option_t *options, size_t option_count);

/* The next argument: the index of its option in options, its values in
 * a->values; CLI_POSITIONAL for an argument that is not an option ("-"
 * included), in a->values[0]; CLI_END after the last. "--name V1 V2" and
 * "--name=V1,V2" are the same (one value: everything after '=', commas
 * included, as in --metric=ellip:1,0,1). --scale S is every command's and
 * handled here (cli_set_scale). An unknown option, a missing value or a
 * value given to a flag is a usage error (cli_usage_error). The strings
 * of argv may be modified (C99 5.1.2.2.1 allows it). */
int cli_next_argument(cli_arguments_t *a);

/* Prints "error: FILE:N: reason" to stderr and exits with status 2 (FILE
 * "<stdin>" for "-"). */
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

/* Prints "error: CALL: VOR_ERR_X: meaning" for a library error code and
 * exits with status 2. */
void cli_library_error(const char *call, int err)
#if defined(__GNUC__)
    __attribute__((noreturn))
#endif
    ;

/* "VOR_ERR_X: meaning" for a library error code. */
const char *cli_error_text(int err);

/* Prints "error: vor COMMAND: problem", the usage and a pointer to
 * `vor COMMAND --help` to stderr and exits with status 2. */
void cli_usage_error(const char *command, const char *usage, const char *problem, const char *argument)
#if defined(__GNUC__)
    __attribute__((noreturn))
#endif
    ;

/* Output files are written to a temporary file beside path and renamed
 * over it only by cli_commit_output, so a failing run leaves path as it
 * was. Both exit with status 2, naming path and the system's reason. */
FILE *cli_create_output(const char *path);
void cli_commit_output(FILE *file, const char *path);

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
/* The decimal digits of a 128-bit integer (exact coordinates). */
__extension__ typedef __int128 cli_wide_t;
void cli_append_wide(cli_output_t *out, cli_wide_t v);
/* Sets d up for max_sites sites (at least 1) in a malloc'd arena, which
 * it returns for the caller to free; exits with status 2 on failure. */
void *cli_diagram(vor_t *d, uint32_t max_sites);

/* The common part of the SITES QUERIES commands (vor nearest, vor
 * interpolate), after reading the n sites of sites_path: reads the query
 * points of queries_path (cli_read_sites) into *queries and *query_count,
 * exits with status 2, "error: SITES_PATH: NO_SITES", when there are
 * queries but no sites, and builds the sites into d (cli_diagram,
 * vor_build; an error exits). Returns the arena, for the caller to free. */
void *cli_query_diagram(vor_t *d, const vor_point_t *sites, uint32_t n, const char *sites_path,
                        const char *queries_path, const char *no_sites, vor_point_t **queries,
                        uint32_t *query_count);

/* Appends "t i j k" for every triangle of d's true Delaunay triangulation
 * (the triangle iterator), counterclockwise from its smallest id, lines
 * sorted; returns how many. */
size_t cli_append_triangles(const vor_t *d, cli_output_t *out);
/* The same for the triangles an iterator begun on up to `most` triangles
 * yields (vor_power_triangles_begin). */
size_t cli_append_triangle_iter(vor_triangle_iter_t *it, size_t most, cli_output_t *out);

/* Writes everything to stdout and frees the buffer. */
void cli_flush(cli_output_t *out);

/* Reads a site file ("x y" or "x,y" per line, coordinates read by
 * cli_coordinate_field, blank and '#' lines and a CSV header skipped; site
 * i is the i-th site line) from path ("-": stdin). Exits with status 2 on
 * a bad line. An empty file gives 0 sites. The array is malloc'd; *count
 * receives the number of sites. */
vor_point_t *cli_read_sites(const char *path, uint32_t *count);

/* The one reader of point files: cli_read_sites's "x y" lines, or with a
 * parser "x y F" (or "x,y,F") lines, F named `third` in messages ("expected
 * x y value or x,y,value") and read by parse into *value (at most 8 bytes,
 * `size` of them kept), the parser returning false with *why as the
 * fields' parsers do (cli_int32_field). *points and, with a parser,
 * *fields (fields[i] of `size` bytes; NULL for none) are malloc'd; returns
 * the number of lines read. */
typedef bool cli_field_parser_t(const char **cursor, void *value, const char **why);
uint32_t cli_read_points(const char *path, const char *third, cli_field_parser_t *parse, size_t size,
                         vor_point_t **points, void **fields);

/* Site i's colour in every picture of the tool (vor draw, vor raster
 * --png), as 0xRRGGBB: c = (i * 2654435761) mod 2^21 (a bijection on 21
 * bits, so ids below 2^21 get distinct colours), RR = 128 + (c & 127),
 * GG = 128 + ((c >> 7) & 127), BB = 128 + (c >> 14). */
uint32_t cli_site_colour(uint32_t site);

/* Seconds from a monotonic clock, for --stats. */
double cli_seconds(void);

/* The text of `vor COMMAND --help`: usage, input and output formats, an
 * example. */
extern const char cli_predicates_help[], cli_delaunay_help[], cli_nearest_help[],
    cli_raster_help[], cli_cells_help[], cli_draw_help[], cli_ops_help[], cli_cdt_help[],
    cli_power_help[], cli_interpolate_help[], cli_locate_help[], cli_within_help[];

/* Subcommands: each takes its arguments after the subcommand name and
 * returns the process exit status. */
int cli_predicates(int argc, char **argv);
int cli_delaunay(int argc, char **argv);
int cli_nearest(int argc, char **argv);
int cli_raster(int argc, char **argv);
int cli_cells(int argc, char **argv);
int cli_draw(int argc, char **argv);
int cli_ops(int argc, char **argv);
int cli_cdt(int argc, char **argv);
int cli_power(int argc, char **argv);
int cli_interpolate(int argc, char **argv);
int cli_locate(int argc, char **argv);
int cli_within(int argc, char **argv);

/* vor cdt's parts, for vor draw too (cdt.c): the constraints of a file as
 * pairs of site ids mapped through first[] (a point's first site; a site
 * to itself dropped), an error exit naming the line for a bad one; the
 * constraint memory attached to d (built from capacity sites) and every
 * pair constrained, grown until they fit (free it; *crossings its crossing
 * limit: crossing ids are capacity + 0 .. *crossings - 1); and a crossing
 * vertex's point to the nearest thousandth, for pictures. */
uint32_t (*cli_read_constraints(const char *path, const uint32_t *first, uint32_t n,
                                size_t *count))[2];
void *cli_constrain_all(vor_t *d, uint32_t capacity, uint32_t (*pairs)[2], size_t count,
                        uint32_t *crossings);
void cli_crossing_point(const vor_point_t *sites, const uint32_t s[4], double *x, double *y);

/* vor power's parts, for vor draw --power too (power.c): the weighted
 * sites of a file ("x y w" lines, coordinates by cli_coordinate_field, w
 * by cli_squared_field) and their power diagram, built in a malloc'd arena
 * that it returns for the caller to free, with duplicate_of (malloc'd,
 * at least one entry) as vor_power_build gives it; exits with status 2 on
 * a bad line or a failure. */
typedef struct cli_weighted {
    vor_point_t *points;
    int64_t *weights;
    uint32_t n;
    uint32_t *duplicate_of;
} cli_weighted_t;
void *cli_power_diagram(const char *path, vor_power_t *pd, cli_weighted_t *sites);

#endif
