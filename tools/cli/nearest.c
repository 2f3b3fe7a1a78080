/*
 * vor nearest SITES QUERIES
 *
 * For each query line "x y" of QUERIES, one line with the index (as in
 * SITES, counted like `vor delaunay`) of the nearest site by exact
 * distance: ties go to the smaller index, and a duplicated site answers
 * with its first occurrence. Each query starts its walk at the previous
 * answer, as a moving robot would. A bad line in either file: "error:
 * line N: reason", exit 2, no output.
 */
#include <stdlib.h>

#include "cli.h"

int cli_nearest(int argc, char **argv)
{
    if (argc != 2) {
        cli_error("usage: vor nearest SITES QUERIES");
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
    cli_output_t out = {NULL, 0, 0};
    uint32_t hint = VOR_NO_HINT;
    for (uint32_t q = 0; q < queries; q++) {
        uint32_t site;
        if (vor_nearest(&d, points[q].x, points[q].y, hint, &site) != VOR_OK) {
            cli_error("nearest-site query failed");
        }
        cli_append(&out, "%u\n", site);
        hint = site;
    }
    cli_flush(&out);
    free(arena);
    free(points);
    free(sites);
    return 0;
}
