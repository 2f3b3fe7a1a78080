/* SPDX-License-Identifier: MIT */
/*
 * vor cells --box X0 Y0 X1 Y1 [--scale S] SITES
 *
 * For each site i of SITES (counted like `vor delaunay`) that is not a
 * duplicate of an earlier one, one line "c i m x1 y1 ... xm ym": its
 * Voronoi cell clipped to the box [X0, X1] x [Y0, Y1], counterclockwise
 * from the lowest vertex, computed exactly and rounded to the nearest
 * integer (halves up); m = 0 when the cell meets the box in no area.
 * Bad input: "error: FILE:N: reason" (or "error: reason" for the
 * arguments), exit 2, nothing on stdout.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define USAGE "usage: vor cells --box X0 Y0 X1 Y1 [--scale S] SITES"

const char cli_cells_help[] =
    USAGE "\n"
    "\n"
    "The Voronoi cell of each site of SITES ('-': stdin), clipped to the box\n"
    "[X0, X1] x [Y0, Y1] (int32, X0 <= X1, Y0 <= Y1, in the units after --scale).\n"
    "\n"
    "input:  one site per line, \"x y\" or \"x,y\" (CSV, optional header line);\n"
    "        decimal int32, or decimal numbers with --scale S (times S, rounded\n"
    "        to nearest, ties away from zero); blank and '#' lines skipped; site i\n"
    "        is the i-th site line, from 0. An empty file: no output.\n"
    "output: \"c i m x1 y1 ... xm ym\" per site i that repeats no earlier site:\n"
    "        its cell counterclockwise from the lowest vertex, each vertex exact\n"
    "        and rounded to the nearest integer, halves up; m = 0 when the cell\n"
    "        meets the box in no area.\n"
    "\n"
    "example:\n"
    "  $ printf '0 0\\n10 0\\n30 0\\n10 0\\n' | vor cells --box -10 -10 50 10 -\n"
    "  c 0 4 -10 -10 5 -10 5 10 -10 10\n"
    "  c 1 4 5 -10 20 -10 20 10 5 10\n"
    "  c 2 4 20 -10 50 -10 50 10 20 10\n";

static int32_t box_field(const char *text)
{
    const char *cursor = text, *why = "";
    int32_t value;
    if (!cli_int32_field(&cursor, &value, &why) || !cli_at_end(cursor)) {
        fprintf(stderr, "error: --box: expected four int32 values X0 Y0 X1 Y1, got '%s'\n", text);
        exit(2);
    }
    return value;
}

int cli_cells(int argc, char **argv)
{
    vor_box_t box = {0, 0, 0, 0};
    bool have_box = false;
    const char *path = NULL;
    static const cli_option_t options[] = {{"--box", 4}};
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, "cells", USAGE, options, sizeof options / sizeof options[0]);
    for (int o; (o = cli_next_argument(&args)) != CLI_END;) {
        if (o == 0) {
            box.x0 = box_field(args.values[0]);
            box.y0 = box_field(args.values[1]);
            box.x1 = box_field(args.values[2]);
            box.y1 = box_field(args.values[3]);
            have_box = true;
        } else if (path == NULL) {
            path = args.values[0];
        } else {
            cli_usage_error("cells", USAGE, "unexpected argument", args.values[0]);
        }
    }
    if (!have_box) {
        cli_usage_error("cells", USAGE, "missing --box X0 Y0 X1 Y1", NULL);
    }
    if (path == NULL) {
        cli_usage_error("cells", USAGE, "missing SITES", NULL);
    }
    if (box.x0 > box.x1 || box.y0 > box.y1) {
        cli_error("--box: X0 > X1 or Y0 > Y1");
    }
    uint32_t n;
    vor_point_t *sites = cli_read_sites(path, &n);
    uint32_t capacity = (n < 1u) ? 1u : n;
    uint32_t *duplicate_of = malloc((size_t)capacity * sizeof *duplicate_of);
    vor_point_t *vertices = malloc((size_t)VOR_CELL_MAX_VERTICES(capacity) * sizeof *vertices);
    if (duplicate_of == NULL || vertices == NULL) {
        cli_error("out of memory");
    }
    vor_t d;
    void *arena = cli_diagram(&d, capacity);
    int err = vor_build(&d, sites, n, NULL, duplicate_of);
    if (err != VOR_OK) {
        cli_library_error("vor_build", err);
    }
    cli_output_t out = {NULL, 0, 0};
    for (uint32_t i = 0; i < n; i++) {
        if (duplicate_of[i] != i) {
            continue;
        }
        uint32_t count;
        err = vor_cell(&d, i, &box, vertices, VOR_CELL_MAX_VERTICES(capacity), &count);
        if (err != VOR_OK) {
            cli_library_error("vor_cell", err);
        }
        cli_append(&out, "c %u %u", i, count);
        for (uint32_t k = 0; k < count; k++) {
            cli_append(&out, " %d %d", vertices[k].x, vertices[k].y);
        }
        cli_append(&out, "\n");
    }
    cli_flush(&out);
    free(vertices);
    free(duplicate_of);
    free(arena);
    free(sites);
    return 0;
}
