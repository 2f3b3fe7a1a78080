/* SPDX-License-Identifier: MIT */
/*
 * vor cells [--box X0 Y0 X1 Y1 | --clip POLY] [--order K] [--exact] [--scale S] SITES
 *
 * For each site i of SITES (counted like `vor delaunay`) that is not a
 * duplicate of an earlier one, one line "c i m x1 y1 ... xm ym": its
 * Voronoi cell clipped to the box [X0, X1] x [Y0, Y1] (vor_cell), or one
 * such line per piece of the cell clipped to the simple polygon of POLY
 * (vor_clip_begin: a non-convex room can cut a cell in several pieces),
 * counterclockwise from the lowest vertex, computed exactly and rounded
 * to the nearest integer (halves up); m = 0 when the cell meets the
 * region in no area. --exact prints each vertex as "xn yn w", the exact
 * coordinates xn / w, yn / w in lowest terms (w > 0), instead.
 * --order K (K > 1): the order-K cells instead, each set of K sites
 * whose cell meets the region in an area once (vor_order_cells_begin's
 * walk), one line "o K s1 ... sK m x1 y1 ... xm ym" per piece, s1 < ...
 * < sK, the sets in increasing order (lexicographic), each set's pieces
 * in the order of their lowest vertices.
 * Bad input: "error: FILE:N: reason" (or "error: reason" for the
 * arguments, the room), exit 2, nothing on stdout.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define USAGE "usage: vor cells (--box X0 Y0 X1 Y1 | --clip POLY) [--order K] [--exact] [--scale S] SITES"

const char cli_cells_help[] =
    USAGE "\n"
    "\n"
    "The Voronoi cell of each site of SITES ('-': stdin), clipped to the box\n"
    "[X0, X1] x [Y0, Y1] (int32, X0 <= X1, Y0 <= Y1, in the units after --scale),\n"
    "or to the simple polygon of the file POLY: its vertices, one \"x y\" line\n"
    "each, in order (either orientation; read like SITES).\n"
    "\n"
    "input:  one site per line, \"x y\" or \"x,y\" (CSV, optional header line);\n"
    "        decimal int32, or decimal numbers with --scale S (times S, rounded\n"
    "        to nearest, ties away from zero); blank and '#' lines skipped; site i\n"
    "        is the i-th site line, from 0. An empty file: no output.\n"
    "output: \"c i m x1 y1 ... xm ym\" per site i that repeats no earlier site:\n"
    "        its cell counterclockwise from the lowest vertex, each vertex exact\n"
    "        and rounded to the nearest integer, halves up; m = 0 when the cell\n"
    "        meets the box or polygon in no area. With --clip, one such line\n"
    "        per piece (a non-convex polygon can cut a cell in several), the\n"
    "        pieces in the order of their lowest vertices.\n"
    "        --exact: each vertex as \"xn yn w\", the exact point (xn/w, yn/w)\n"
    "        in lowest terms, w > 0.\n"
    "        --order K (2 <= K < the number of distinct sites): the order-K\n"
    "        cells, the regions whose K nearest sites are one set, instead:\n"
    "        \"o K s1 ... sK m x1 y1 ... xm ym\" per piece of every set whose\n"
    "        cell meets the region in an area (they tile it), s1 < ... < sK\n"
    "        (ids of first occurrences), the sets in increasing order.\n"
    "        --order 1 is the default, the \"c\" lines above.\n"
    "\n"
    "example:\n"
    "  $ printf '0 0\\n10 0\\n30 0\\n10 0\\n' | vor cells --box -10 -10 50 10 -\n"
    "  c 0 4 -10 -10 5 -10 5 10 -10 10\n"
    "  c 1 4 5 -10 20 -10 20 10 5 10\n"
    "  c 2 4 20 -10 50 -10 50 10 20 10\n"
    "  $ printf '0 0\\n60 0\\n60 30\\n30 30\\n30 60\\n0 60\\n' > L.poly\n"
    "  $ printf '40 40\\n20 20\\n' | vor cells --clip L.poly -\n"
    "  c 0 3 60 0 60 30 30 30\n"
    "  c 0 3 30 30 30 60 0 60\n"
    "  c 1 3 0 0 60 0 0 60\n"
    "  $ printf '0 0\\n20 0\\n40 0\\n' | vor cells --box 0 -10 40 10 --order 2 -\n"
    "  o 2 0 1 4 0 -10 20 -10 20 10 0 10\n"
    "  o 2 1 2 4 20 -10 40 -10 40 10 20 10\n";

/* One piece's line of an order-K cell, kept with its set to be sorted. */
typedef struct {
    uint32_t *set;
    uint32_t k;
    size_t serial; /* the walk's order: pieces of a set stay in theirs */
    char *text;
} order_line_t;

static int compare_lines(const void *pa, const void *pb)
{
    const order_line_t *a = pa, *b = pb;
    for (uint32_t i = 0; i < a->k; i++) {
        if (a->set[i] != b->set[i]) {
            return (a->set[i] < b->set[i]) ? -1 : 1;
        }
    }
    return (a->serial > b->serial) - (a->serial < b->serial);
}

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

static void append_vertex(cli_output_t *out, const vor_exact_point_t *v, bool exact);

/* The order-k cells of the room, sorted by their sets. */
static void order_cells(const vor_t *d, uint32_t k, const vor_point_t *room, uint32_t m,
                        uint32_t distinct, bool exact, cli_output_t *out)
{
    if (k >= distinct) {
        cli_error("--order: K must be below the number of distinct sites");
    }
    size_t cells = VOR_ORDER_MAX_CELLS(distinct, k);
    uint32_t *sets = malloc(VOR_ORDER_SETS_WORDS(cells, k) * sizeof *sets);
    size_t scratch_bytes = VOR_ORDER_SCRATCH_BYTES(m, distinct, k);
    void *scratch = malloc(scratch_bytes);
    uint32_t most = VOR_CLIP_MAX_VERTICES(m, (size_t)k * (distinct - k) + 1u);
    vor_exact_point_t *piece = malloc((size_t)most * sizeof *piece);
    uint32_t *set = malloc((size_t)k * sizeof *set);
    if (sets == NULL || scratch == NULL || piece == NULL || set == NULL || cells > UINT32_MAX) {
        cli_error("out of memory");
    }
    vor_order_iter_t it;
    int err = vor_order_cells_begin(&it, d, k, room, m, sets, (uint32_t)cells, scratch, scratch_bytes);
    if (err == VOR_ERR_POLYGON) {
        cli_error("--clip: the polygon is not simple (edges cross, touch or overlap, or a "
                  "vertex repeats)");
    }
    if (err != VOR_OK) {
        cli_library_error("vor_order_cells_begin", err);
    }
    order_line_t *lines = NULL;
    size_t count_lines = 0, capacity_lines = 0;
    vor_clip_t clip;
    while (vor_order_cells_next(&it, set, &clip)) {
        uint32_t *kept = malloc((size_t)k * sizeof *kept);
        if (kept == NULL) {
            cli_error("out of memory");
        }
        memcpy(kept, set, (size_t)k * sizeof *kept);
        uint32_t count;
        while (vor_clip_next(&clip, piece, most, &count)) {
            cli_output_t one = {NULL, 0, 0};
            cli_append(&one, "o %u", k);
            for (uint32_t i = 0; i < k; i++) {
                cli_append(&one, " %u", set[i]);
            }
            cli_append(&one, " %u", count);
            for (uint32_t i = 0; i < count; i++) {
                append_vertex(&one, &piece[i], exact);
            }
            cli_append(&one, "\n");
            if (count_lines == capacity_lines) {
                capacity_lines = (capacity_lines == 0) ? 64 : 2 * capacity_lines;
                lines = realloc(lines, capacity_lines * sizeof *lines);
                if (lines == NULL) {
                    cli_error("out of memory");
                }
            }
            lines[count_lines] = (order_line_t){kept, k, count_lines, one.data};
            count_lines++;
        }
        if (vor_clip_error(&clip) != VOR_OK) {
            cli_library_error("vor_clip_next", vor_clip_error(&clip));
        }
    }
    if (vor_order_cells_error(&it) != VOR_OK) {
        cli_library_error("vor_order_cells_next", vor_order_cells_error(&it));
    }
    if (count_lines > 0) {
        qsort(lines, count_lines, sizeof *lines, compare_lines);
    }
    for (size_t i = 0; i < count_lines; i++) {
        cli_append(out, "%s", lines[i].text);
        free(lines[i].text);
    }
    /* each set's array is shared by its pieces, which sorted together */
    for (size_t i = 0; i < count_lines; i++) {
        if (i + 1 == count_lines || lines[i + 1].set != lines[i].set) {
            free(lines[i].set);
        }
    }
    free(lines);
    free(set);
    free(piece);
    free(scratch);
    free(sets);
}

/* One vertex: rounded, or exact "xn yn w". */
static void append_vertex(cli_output_t *out, const vor_exact_point_t *v, bool exact)
{
    if (!exact) {
        cli_append(out, " %d %d", v->point.x, v->point.y);
        return;
    }
    const uint32_t *numbers[3] = {v->x, v->y, v->w};
    for (unsigned k = 0; k < 3u; k++) {
        /* four 32-bit limbs, two's complement, least significant first */
        __extension__ unsigned __int128 u = 0;
        for (unsigned i = VOR_EXACT_LIMBS; i-- > 0;) {
            u = (u << 32) | numbers[k][i];
        }
        cli_append(out, " ");
        cli_append_wide(out, (cli_wide_t)u);
    }
}

int cli_cells(int argc, char **argv)
{
    vor_box_t box = {0, 0, 0, 0};
    bool have_box = false, exact = false;
    uint32_t order = 1;
    const char *path = NULL, *room_path = NULL;
    static const cli_option_t options[] = {{"--box", 4}, {"--clip", 1}, {"--exact", 0}, {"--order", 1}};
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, "cells", USAGE, options, sizeof options / sizeof options[0]);
    for (int o; (o = cli_next_argument(&args)) != CLI_END;) {
        if (o == 0) {
            box.x0 = box_field(args.values[0]);
            box.y0 = box_field(args.values[1]);
            box.x1 = box_field(args.values[2]);
            box.y1 = box_field(args.values[3]);
            have_box = true;
        } else if (o == 1) {
            room_path = args.values[0];
        } else if (o == 2) {
            exact = true;
        } else if (o == 3) {
            const char *cursor = args.values[0], *why = "";
            int32_t value;
            if (!cli_int32_field(&cursor, &value, &why) || !cli_at_end(cursor) || value < 1 ||
                (uint32_t)value > VOR_ORDER_MAX) {
                fprintf(stderr, "error: --order: expected K from 1 to %u, got '%s'\n", VOR_ORDER_MAX,
                        args.values[0]);
                exit(2);
            }
            order = (uint32_t)value;
        } else if (path == NULL) {
            path = args.values[0];
        } else {
            cli_usage_error("cells", USAGE, "unexpected argument", args.values[0]);
        }
    }
    if (have_box == (room_path != NULL)) {
        cli_usage_error("cells", USAGE, have_box ? "--box and --clip together" : "missing --box X0 Y0 X1 Y1 or --clip POLY", NULL);
    }
    if (path == NULL) {
        cli_usage_error("cells", USAGE, "missing SITES", NULL);
    }
    if (box.x0 > box.x1 || box.y0 > box.y1) {
        cli_error("--box: X0 > X1 or Y0 > Y1");
    }
    /* the region as a room: the polygon, or the box's corners when its
     * exact vertices are asked for (a flat box has no cells with area) */
    uint32_t m = 0;
    vor_point_t *room = NULL;
    bool flat = (box.x0 == box.x1) || (box.y0 == box.y1);
    if (room_path != NULL) {
        room = cli_read_sites(room_path, &m);
    } else if ((exact || order > 1u) && !flat) {
        room = malloc(4u * sizeof *room);
        if (room == NULL) {
            cli_error("out of memory");
        }
        room[0] = (vor_point_t){box.x0, box.y0};
        room[1] = (vor_point_t){box.x1, box.y0};
        room[2] = (vor_point_t){box.x1, box.y1};
        room[3] = (vor_point_t){box.x0, box.y1};
        m = 4;
    } else {
        /* vor_cell's rounded cells */
    }
    if (room_path != NULL && (m < 3u || m > VOR_CLIP_MAX_ROOM)) {
        cli_error("--clip: the polygon needs 3 vertices or more");
    }
    uint32_t n;
    vor_point_t *sites = cli_read_sites(path, &n);
    uint32_t capacity = (n < 1u) ? 1u : n;
    uint32_t *duplicate_of = malloc((size_t)capacity * sizeof *duplicate_of);
    vor_point_t *vertices = malloc((size_t)VOR_CELL_MAX_VERTICES(capacity) * sizeof *vertices);
    size_t scratch_bytes = (room != NULL) ? VOR_CLIP_SCRATCH_BYTES(m, capacity) : 1u;
    uint32_t most = (room != NULL) ? VOR_CLIP_MAX_VERTICES(m, capacity) : 1u;
    void *scratch = malloc(scratch_bytes);
    vor_exact_point_t *piece = malloc((size_t)most * sizeof *piece);
    if (duplicate_of == NULL || vertices == NULL || scratch == NULL || piece == NULL) {
        cli_error("out of memory");
    }
    vor_t d;
    void *arena = cli_diagram(&d, capacity);
    int err = vor_build(&d, sites, n, NULL, duplicate_of);
    if (err != VOR_OK) {
        cli_library_error("vor_build", err);
    }
    cli_output_t out = {NULL, 0, 0};
    uint32_t distinct = 0;
    for (uint32_t i = 0; i < n; i++) {
        distinct += (duplicate_of[i] == i) ? 1u : 0u;
    }
    if (order > 1u && (order >= distinct)) {
        cli_error("--order: K must be below the number of distinct sites");
    }
    if (order > 1u && room != NULL) {
        order_cells(&d, order, room, m, distinct, exact, &out);
    }
    for (uint32_t i = 0; i < n && order == 1u; i++) {
        if (duplicate_of[i] != i) {
            continue;
        }
        uint32_t count;
        if (room == NULL) {
            err = vor_cell(&d, i, &box, vertices, VOR_CELL_MAX_VERTICES(capacity), &count);
            if (err != VOR_OK) {
                cli_library_error("vor_cell", err);
            }
            cli_append(&out, "c %u %u", i, count);
            for (uint32_t k = 0; k < count; k++) {
                cli_append(&out, " %d %d", vertices[k].x, vertices[k].y);
            }
            cli_append(&out, "\n");
            continue;
        }
        vor_clip_t clip;
        err = vor_clip_begin(&clip, &d, i, room, m, scratch, scratch_bytes);
        if (err == VOR_ERR_POLYGON) {
            cli_error("--clip: the polygon is not simple (edges cross, touch or overlap, or a "
                      "vertex repeats)");
        }
        if (err != VOR_OK) {
            cli_library_error("vor_clip_begin", err);
        }
        if (clip.pieces == 0u) {
            cli_append(&out, "c %u 0\n", i);
        }
        while (vor_clip_next(&clip, piece, most, &count)) {
            cli_append(&out, "c %u %u", i, count);
            for (uint32_t k = 0; k < count; k++) {
                append_vertex(&out, &piece[k], exact);
            }
            cli_append(&out, "\n");
        }
        if (vor_clip_error(&clip) != VOR_OK) {
            cli_library_error("vor_clip_next", vor_clip_error(&clip));
        }
    }
    cli_flush(&out);
    free(piece);
    free(scratch);
    free(room);
    free(vertices);
    free(duplicate_of);
    free(arena);
    free(sites);
    return 0;
}
