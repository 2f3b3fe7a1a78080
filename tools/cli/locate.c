/* SPDX-License-Identifier: MIT */
/*
 * vor locate [--scale S] SITES QUERIES
 * vor within --r2 R2 [--scale S] SITES QUERIES
 *
 * The queries robots ask. locate: for each query line "x y", the Delaunay
 * triangle holding the point, "t I J K" (site indices as in SITES,
 * counterclockwise from the smallest, a line of `vor delaunay`), or "outside" (the
 * library's half-open rule for points on edges: vor_locate in vor.h).
 * within: for each query, the indices of the sites within squared
 * distance R2 (|q - site|^2 <= R2), increasing, an empty line when none.
 * Each query starts its walk at the previous answer's site, as a moving
 * robot would. A bad line in either file: "error: FILE:N: reason", exit 2,
 * no output.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define LOCATE_USAGE "usage: vor locate [--scale S] SITES QUERIES"
#define WITHIN_USAGE "usage: vor within --r2 R2 [--scale S] SITES QUERIES"

const char cli_locate_help[] =
    LOCATE_USAGE "\n"
    "\n"
    "For each query point of QUERIES, the triangle of the Delaunay triangulation of\n"
    "SITES that holds it (either '-': stdin).\n"
    "\n"
    "input:  one point per line in both files, \"x y\" or \"x,y\" (CSV, optional\n"
    "        header line); decimal int32, or decimal numbers with --scale S;\n"
    "        blank and '#' lines skipped; site i is the i-th site line, from 0.\n"
    "output: one line per query: \"t I J K\", the triangle's sites\n"
    "        counterclockwise from the smallest index (a line of `vor delaunay`),\n"
    "        or \"outside\" (outside the convex hull; always\n"
    "        for fewer than 3 sites or collinear ones). A point on an edge or at\n"
    "        a site is located as if moved up by an infinitesimal, then right\n"
    "        by a far smaller one: the triangle above an edge, right of a\n"
    "        vertical one; a top or left hull edge is outside.\n"
    "  --scale S     read decimal coordinates, times S\n"
    "\n"
    "example:\n"
    "  $ printf '0 0\\n10 0\\n0 10\\n' > sites; printf '1 1\\n9 9\\n' | vor locate sites -\n"
    "  t 0 1 2\n"
    "  outside\n";

const char cli_within_help[] =
    WITHIN_USAGE "\n"
    "\n"
    "For each query point of QUERIES, the sites of SITES within squared distance\n"
    "R2 of it (either file '-': stdin).\n"
    "\n"
    "input:  as vor locate; R2 a decimal integer from 0 to 2^63 - 1 (with\n"
    "        --scale S a decimal number, times S squared).\n"
    "output: one line per query: the indices of the sites at squared distance\n"
    "        at most R2, exactly, increasing, an empty line when none; a\n"
    "        repeated site counts once, by its first occurrence.\n"
    "  --r2 R2       the squared radius (required)\n"
    "  --scale S     read decimal coordinates, times S (R2 times S^2)\n"
    "\n"
    "example:\n"
    "  $ printf '0 0\\n10 0\\n0 10\\n' > sites; printf '1 1\\n50 50\\n' | vor within --r2 100 sites -\n"
    "  0 1 2\n"
    "\n";

/* The common part: SITES and QUERIES, the diagram built; *r2_text the
 * value of --r2 when `with_r2`. */
typedef struct {
    vor_point_t *sites;
    vor_point_t *points;
    uint32_t queries;
    void *arena;
    vor_t d;
} query_run_t;

static void start(query_run_t *run, int argc, char **argv, const char *command, const char *usage,
                  bool with_r2, int64_t *r2)
{
    const char *paths[2] = {NULL, NULL};
    const char *r2_text = NULL;
    int path_count = 0;
    static const cli_option_t options[] = {{"--r2", 1}};
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, command, usage, options, with_r2 ? 1u : 0u);
    for (int o; (o = cli_next_argument(&args)) != CLI_END;) {
        const char *value = args.values[0];
        if (o == 0) {
            r2_text = value;
        } else if (path_count == 2) {
            cli_usage_error(command, usage, "unexpected argument", value);
        } else {
            paths[path_count++] = value;
        }
    }
    if (with_r2) {
        const char *cursor = r2_text;
        const char *why = "missing";
        int64_t value = -1;
        if (r2_text == NULL || !cli_squared_field(&cursor, &value, &why) || !cli_at_end(cursor) || value < 0) {
            cli_usage_error(command, usage, "--r2 R2 needs a squared distance from 0 to 2^63 - 1, got",
                            r2_text != NULL ? r2_text : "nothing");
        }
        *r2 = value;
    }
    if (path_count < 2) {
        cli_usage_error(command, usage, path_count == 0 ? "missing SITES and QUERIES" : "missing QUERIES",
                        NULL);
    }
    if (strcmp(paths[0], "-") == 0 && strcmp(paths[1], "-") == 0) {
        cli_usage_error(command, usage, "SITES and QUERIES cannot both be stdin", NULL);
    }
    uint32_t n;
    run->sites = cli_read_sites(paths[0], &n);
    run->arena = cli_query_diagram(&run->d, run->sites, n, paths[0], paths[1], "no sites to answer the queries with",
                                   &run->points, &run->queries);
}

static void finish(query_run_t *run, cli_output_t *out)
{
    cli_flush(out);
    free(run->arena);
    free(run->points);
    free(run->sites);
}

int cli_locate(int argc, char **argv)
{
    query_run_t run;
    start(&run, argc, argv, "locate", LOCATE_USAGE, false, NULL);
    cli_output_t out = {NULL, 0, 0};
    uint32_t hint = VOR_NO_HINT;
    for (uint32_t q = 0; q < run.queries; q++) {
        uint32_t ids[3];
        int err = vor_locate(&run.d, run.points[q], hint, ids);
        if (err == VOR_ERR_OUTSIDE) {
            cli_append(&out, "outside\n");
            continue;
        }
        if (err != VOR_OK) {
            cli_library_error("vor_locate", err);
        }
        /* from the smallest id, as vor delaunay prints triangles */
        unsigned first = (ids[1] < ids[0] && ids[1] < ids[2]) ? 1u : (ids[2] < ids[0] && ids[2] < ids[1]) ? 2u : 0u;
        cli_append(&out, "t %u %u %u\n", ids[first], ids[(first + 1u) % 3u], ids[(first + 2u) % 3u]);
        hint = ids[0];
    }
    finish(&run, &out);
    return 0;
}

int cli_within(int argc, char **argv)
{
    query_run_t run;
    int64_t r2 = 0;
    start(&run, argc, argv, "within", WITHIN_USAGE, true, &r2);
    uint32_t capacity = run.d.max_sites;
    uint32_t *ids = malloc(capacity * sizeof *ids);
    if (ids == NULL) {
        cli_error("out of memory");
    }
    cli_output_t out = {NULL, 0, 0};
    uint32_t hint = VOR_NO_HINT;
    for (uint32_t q = 0; q < run.queries; q++) {
        uint32_t count;
        int err = vor_within(&run.d, run.points[q], (uint64_t)r2, hint, ids, capacity, &count);
        if (err != VOR_OK) {
            cli_library_error("vor_within", err);
        }
        for (uint32_t i = 0; i < count; i++) {
            cli_append(&out, (i + 1u < count) ? "%u " : "%u", ids[i]);
        }
        cli_append(&out, "\n");
        hint = (count > 0u) ? ids[0] : hint;
    }
    finish(&run, &out);
    free(ids);
    return 0;
}
