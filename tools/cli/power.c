/* SPDX-License-Identifier: MIT */
/*
 * vor power [--scale S] SITES
 *
 * The regular triangulation (dual of the power diagram) of the weighted
 * sites in SITES, "x y w" lines: "t I J K" per triangle, "h I" per hidden
 * site, "d I J" per site that repeats an earlier one (point and weight).
 * --scale S scales the coordinates by S and the weights, squared radii,
 * by S^2 (cli_squared_field), so that the diagram scales with them.
 */
#include <stdlib.h>

#include "cli.h"
#include "vor_power.h"

#define USAGE "usage: vor power [--scale S] SITES"

const char cli_power_help[] =
    USAGE "\n"
    "\n"
    "The regular triangulation of weighted sites: the dual of their power\n"
    "diagram, where the power distance of q to site (p, w) is |q - p|^2 - w.\n"
    "\n"
    "input:  one site per line, \"x y w\" or \"x,y,w\" (CSV, optional header);\n"
    "        x and y decimal int32 (or decimal numbers with --scale S, as for\n"
    "        vor delaunay), w a decimal int64 (a squared radius: with --scale\n"
    "        S, a decimal number times S^2, as vor raster --metric power reads\n"
    "        it); blank and '#' lines skipped; site i is the i-th site line,\n"
    "        from 0.\n"
    "output: \"t i j k\" per triangle, counterclockwise, from its smallest id,\n"
    "        sorted; then \"h i\" per hidden site (its power cell is empty),\n"
    "        sorted; then \"d i j\" per site i with the point and weight of an\n"
    "        earlier site j. Sites at one point: the largest weight is the\n"
    "        vertex, the others are hidden.\n"
    "  --scale S     read decimal coordinates, times S\n"
    "\n"
    "example:\n"
    "  $ printf '0 0 0\\n10 0 0\\n0 10 0\\n10 10 0\\n4 4 -50\\n' | vor power -\n"
    "  t 0 1 3\n"
    "  t 0 3 2\n"
    "  h 4\n";

/* A site's weight for cli_read_points: a squared length (cli_squared_field). */
static bool weight_field(const char **cursor, void *value, const char **why)
{
    return cli_squared_field(cursor, (int64_t *)value, why);
}

void *cli_power_diagram(const char *path, vor_power_t *pd, cli_weighted_t *sites)
{
    void *fields;
    sites->n = cli_read_points(path, "w", weight_field, sizeof(int64_t), &sites->points, &fields);
    sites->weights = fields;
    uint32_t capacity = (sites->n < 1u) ? 1u : sites->n;
    sites->duplicate_of = malloc((size_t)capacity * sizeof *sites->duplicate_of);
    size_t bytes = VOR_POWER_ARENA_BYTES(capacity);
    void *arena = malloc(bytes); /* malloc's alignment is VOR_POWER_ARENA_ALIGN's at least */
    if ((sites->duplicate_of == NULL) || (arena == NULL)) {
        cli_error("out of memory");
    }
    int err = vor_power_init(pd, arena, bytes, capacity);
    if (err != VOR_OK) {
        cli_library_error("vor_power_init", err);
    }
    err = vor_power_build(pd, sites->points, sites->weights, sites->n, sites->duplicate_of);
    if (err != VOR_OK) {
        cli_library_error("vor_power_build", err);
    }
    return arena;
}

int cli_power(int argc, char **argv)
{
    const char *path = NULL;
    enum { SCALE };
    static const cli_option_t flags[] = {[SCALE] = {"--scale", 1}};
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, "power", USAGE, flags, sizeof flags / sizeof flags[0]);
    for (int o; (o = cli_next_argument(&args)) != CLI_END;) {
        if (o == SCALE) {
            cli_set_scale(args.values[0]);
        } else if (path == NULL) {
            path = args.values[0];
        } else {
            cli_usage_error("power", USAGE, "unexpected argument", args.values[0]);
        }
    }
    if (path == NULL) {
        cli_usage_error("power", USAGE, "missing SITES", NULL);
    }
    vor_power_t pd;
    cli_weighted_t sites;
    void *arena = cli_power_diagram(path, &pd, &sites);
    uint32_t n = sites.n, capacity = (n < 1u) ? 1u : n;
    cli_output_t out = {NULL, 0, 0};
    vor_triangle_iter_t it;
    (void)vor_power_triangles_begin(&it, &pd);
    (void)cli_append_triangle_iter(&it, 2u * (size_t)capacity, &out);
    for (uint32_t i = 0; i < n; i++) {
        if (vor_power_hidden(&pd, i) == 1) {
            cli_append(&out, "h %u\n", i);
        }
    }
    for (uint32_t i = 0; i < n; i++) {
        if (sites.duplicate_of[i] != i) {
            cli_append(&out, "d %u %u\n", i, sites.duplicate_of[i]);
        }
    }
    cli_flush(&out);
    free(arena);
    free(sites.duplicate_of);
    free(sites.weights);
    free(sites.points);
    return 0;
}
