/* SPDX-License-Identifier: MIT */
/*
 * vor nearest [--k=K] [--scale S] SITES QUERIES
 *
 * For each query line "x y" of QUERIES, one line with the index (as in
 * SITES, counted like `vor delaunay`) of the nearest site by exact
 * distance: ties go to the smaller index, and a duplicated site answers
 * with its first occurrence. With --k=K the line holds the K nearest
 * (fewer if there are fewer sites), nearest first, ties by index. Each
 * query starts its walk at the previous answer, as a moving robot would.
 * A bad line in either file: "error: FILE:N: reason", exit 2, no output.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define USAGE "usage: vor nearest [--k=K] [--scale S] SITES QUERIES"

const char cli_nearest_help[] =
    USAGE "\n"
    "\n"
    "For each query point of QUERIES, the nearest site of SITES (either '-':\n"
    "stdin).\n"
    "\n"
    "input:  one point per line in both files, \"x y\" or \"x,y\" (CSV, optional\n"
    "        header line); decimal int32, or decimal numbers with --scale S\n"
    "        (times S, rounded to nearest, ties away from zero); blank and '#'\n"
    "        lines skipped; site i is the i-th site line, from 0.\n"
    "output: one line per query: the index of the nearest site by exact\n"
    "        distance, ties to the smaller index, a repeated site answered by\n"
    "        its first occurrence. No queries: no output.\n"
    "  --k=K         the K nearest (1 <= K <= 1000), nearest first, ties by\n"
    "                index; fewer when SITES has fewer distinct points\n"
    "  --scale S     read decimal coordinates, times S\n"
    "\n"
    "example:\n"
    "  $ printf '0 0\\n10 0\\n0 10\\n' > sites; printf '9 1\\n1 1\\n' | vor nearest --k=2 sites -\n"
    "  1 0\n"
    "  0 1\n";

int cli_nearest(int argc, char **argv)
{
    uint32_t k = 1;
    const char *paths[2] = {NULL, NULL};
    int path_count = 0;
    static const cli_option_t options[] = {{"--k", 1}};
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, "nearest", USAGE, options, sizeof options / sizeof options[0]);
    for (int o; (o = cli_next_argument(&args)) != CLI_END;) {
        const char *value = args.values[0];
        if (o == 0) {
            char *end;
            unsigned long number = strtoul(value, &end, 10);
            if (*end != '\0' || value[0] == '\0' || value[0] == '-' || number < 1u || number > 1000u) {
                cli_usage_error("nearest", USAGE, "--k K needs an integer K from 1 to 1000, got", value);
            }
            k = (uint32_t)number;
        } else if (path_count == 2) {
            cli_usage_error("nearest", USAGE, "unexpected argument", value);
        } else {
            paths[path_count++] = value;
        }
    }
    if (path_count < 2) {
        cli_usage_error("nearest", USAGE, path_count == 0 ? "missing SITES and QUERIES" : "missing QUERIES",
                        NULL);
    }
    if (strcmp(paths[0], "-") == 0 && strcmp(paths[1], "-") == 0) {
        cli_usage_error("nearest", USAGE, "SITES and QUERIES cannot both be stdin", NULL);
    }
    uint32_t n, queries;
    vor_point_t *sites = cli_read_sites(paths[0], &n);
    vor_point_t *points;
    vor_t d;
    void *arena = cli_query_diagram(&d, sites, n, paths[0], paths[1], "no sites to answer the queries with",
                                    &points, &queries);
    uint32_t *nearest = malloc(k * sizeof *nearest);
    if (nearest == NULL) {
        cli_error("out of memory");
    }
    cli_output_t out = {NULL, 0, 0};
    uint32_t hint = VOR_NO_HINT;
    for (uint32_t q = 0; q < queries; q++) {
        uint32_t found;
        int err = vor_nearest_k(&d, points[q], hint, k, nearest, &found);
        if (err != VOR_OK) {
            cli_library_error("vor_nearest_k", err);
        }
        for (uint32_t i = 0; i < found; i++) {
            cli_append(&out, (i + 1u < found) ? "%u " : "%u\n", nearest[i]);
        }
        hint = nearest[0];
    }
    cli_flush(&out);
    free(nearest);
    free(arena);
    free(points);
    free(sites);
    return 0;
}
