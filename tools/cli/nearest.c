/* SPDX-License-Identifier: MIT */
/*
 * vor nearest [--k=K] SITES QUERIES
 *
 * For each query line "x y" of QUERIES, one line with the index (as in
 * SITES, counted like `vor delaunay`) of the nearest site by exact
 * distance: ties go to the smaller index, and a duplicated site answers
 * with its first occurrence. With --k=K the line holds the K nearest
 * (fewer if there are fewer sites), nearest first, ties by index. Each
 * query starts its walk at the previous answer, as a moving robot would.
 * A bad line in either file: "error: line N: reason", exit 2, no output.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

int cli_nearest(int argc, char **argv)
{
    static const char usage[] = "usage: vor nearest [--k=K] SITES QUERIES (1 <= K <= 1000)";
    uint32_t k = 1;
    if (argc == 3 && strncmp(argv[0], "--k=", 4) == 0) {
        char *end;
        unsigned long value = strtoul(argv[0] + 4, &end, 10);
        if (*end != '\0' || argv[0][4] == '\0' || value < 1u || value > 1000u) {
            cli_error(usage);
        }
        k = (uint32_t)value;
        argc--;
        argv++;
    }
    if (argc != 2) {
        cli_error(usage);
    }
    uint32_t n, queries;
    vor_point_t *sites = cli_read_sites(argv[0], &n);
    vor_point_t *points = cli_read_sites(argv[1], &queries);
    if (n == 0u && queries > 0u) {
        cli_error("no sites to answer queries with");
    }
    uint32_t capacity = (n < 1u) ? 1u : n;
    void *arena = malloc(VOR_ARENA_BYTES(capacity));
    if (arena == NULL) {
        cli_error("out of memory");
    }
    vor_t d;
    if (vor_init(&d, arena, VOR_ARENA_BYTES(capacity), capacity) != VOR_OK ||
        vor_build(&d, sites, n, NULL, NULL) != VOR_OK) {
        cli_error("cannot build the diagram");
    }
    uint32_t *nearest = malloc(k * sizeof *nearest);
    if (nearest == NULL) {
        cli_error("out of memory");
    }
    cli_output_t out = {NULL, 0, 0};
    uint32_t hint = VOR_NO_HINT;
    for (uint32_t q = 0; q < queries; q++) {
        uint32_t found;
        if (vor_nearest_k(&d, points[q].x, points[q].y, hint, k, nearest, &found) != VOR_OK) {
            cli_error("nearest-site query failed");
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
