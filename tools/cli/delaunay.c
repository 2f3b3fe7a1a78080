/* SPDX-License-Identifier: MIT */
/*
 * vor delaunay [--stats] [--order=quadtree|input] [--algo=incremental|dc|dc-quadtree] [--scale S] FILE
 *
 * The Delaunay triangulation of the sites in FILE ("-": stdin): one line
 * "t i j k" per finite triangle, counterclockwise, rotated to start at its
 * smallest id and sorted; then "d i j" for each site i that duplicates an
 * earlier site j. --stats prints sizes, time and predicate tiers to stderr.
 * --algo picks the builder (the output is the same for every one).
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define USAGE "usage: vor delaunay [--stats] [--order=quadtree|input] [--algo=incremental|dc|dc-quadtree] [--scale S] FILE"

const char cli_delaunay_help[] =
    USAGE "\n"
    "\n"
    "The Delaunay triangulation of the sites in FILE ('-': stdin).\n"
    "\n"
    "input:  one site per line, \"x y\" or \"x,y\" (CSV, optional header line);\n"
    "        decimal int32, or decimal numbers with --scale S (times S, rounded\n"
    "        to nearest, ties away from zero); blank and '#' lines skipped; site i\n"
    "        is the i-th site line, from 0. An empty file is 0 sites: no output.\n"
    "output: \"t i j k\" per triangle, counterclockwise, from its smallest id,\n"
    "        sorted; then \"d i j\" per site i that repeats an earlier site j.\n"
    "        Collinear sites have no triangle.\n"
    "  --stats       sizes, time and predicate counters on stderr\n"
    "  --order=      insertion order of vor_build (default quadtree)\n"
    "  --algo=       builder: incremental (vor_build), dc or dc-quadtree\n"
    "                (vor_build_dc); the output is the same\n"
    "  --scale S     read decimal coordinates, times S\n"
    "\n"
    "example:\n"
    "  $ printf '0 0\\n10 0\\n0 10\\n10 10\\n10 0\\n' | vor delaunay -\n"
    "  t 0 1 3\n"
    "  t 0 3 2\n"
    "  d 4 1\n";

int cli_delaunay(int argc, char **argv)
{
    bool stats = false;
    vor_build_options_t options = {VOR_ORDER_QUADTREE, VOR_DC_QUADTREE, 0};
    bool dc = false; /* vor_build_dc instead of vor_build */
    const char *path = NULL;
    enum { STATS, ORDER, ALGO };
    static const cli_option_t flags[] = {[STATS] = {"--stats", 0}, [ORDER] = {"--order", 1}, [ALGO] = {"--algo", 1}};
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, "delaunay", USAGE, flags, sizeof flags / sizeof flags[0]);
    for (int o; (o = cli_next_argument(&args)) != CLI_END;) {
        const char *value = args.values[0];
        if (o == STATS) {
            stats = true;
        } else if (o == ORDER && strcmp(value, "quadtree") == 0) {
            options.order = VOR_ORDER_QUADTREE;
        } else if (o == ORDER && strcmp(value, "input") == 0) {
            options.order = VOR_ORDER_INPUT;
        } else if (o == ORDER) {
            cli_usage_error("delaunay", USAGE, "--order takes quadtree or input, not", value);
        } else if (o == ALGO && strcmp(value, "incremental") == 0) {
            dc = false;
        } else if (o == ALGO && strcmp(value, "dc") == 0) {
            dc = true;
            options.split = VOR_DC_XSPLIT;
        } else if (o == ALGO && strcmp(value, "dc-quadtree") == 0) {
            dc = true;
            options.split = VOR_DC_QUADTREE;
        } else if (o == ALGO) {
            cli_usage_error("delaunay", USAGE, "--algo takes incremental, dc or dc-quadtree, not", value);
        } else if (path == NULL) {
            path = value;
        } else {
            cli_usage_error("delaunay", USAGE, "unexpected argument", value);
        }
    }
    if (path == NULL) {
        cli_usage_error("delaunay", USAGE, "missing FILE", NULL);
    }
    uint32_t n;
    vor_point_t *sites = cli_read_sites(path, &n);
    uint32_t capacity = (n < 1u) ? 1u : n;
    uint32_t *duplicate_of = malloc((size_t)capacity * sizeof *duplicate_of);
    if (duplicate_of == NULL) {
        cli_error("out of memory");
    }
    vor_t d;
    void *arena = cli_diagram(&d, capacity);
    double start = cli_seconds();
    int built = dc ? vor_build_dc(&d, sites, n, &options, duplicate_of)
                   : vor_build(&d, sites, n, &options, duplicate_of);
    if (built != VOR_OK) {
        cli_library_error(dc ? "vor_build_dc" : "vor_build", built);
    }
    double seconds = cli_seconds() - start;

    cli_output_t out = {NULL, 0, 0};
    size_t count = cli_append_triangles(&d, &out);
    for (uint32_t i = 0; i < n; i++) {
        if (duplicate_of[i] != i) {
            cli_append(&out, "d %u %u\n", i, duplicate_of[i]);
        }
    }
    cli_flush(&out);
    if (stats) {
        vor_memory_t memory;
        vor_memory(&d, &memory);
        vor_stats_t counters = {0}; /* zeros from a library without VOR_STATS */
        (void)vor_stats(&d, &counters);
        const vor_stats_t *s = &counters;
        fprintf(stderr, "sites=%u triangles=%zu bytes=%zu bytes_per_site=%u.%02u seconds=%.6f\n",
                n, count, memory.used_bytes, memory.bytes_per_site_x100 / 100u,
                memory.bytes_per_site_x100 % 100u, seconds);
        fprintf(stderr,
                "orient2d narrow=%u wide=%u perturbed=%u incircle narrow=%u mid=%u wide=%u "
                "perturbed=%u closer narrow=%u wide=%u perturbed=%u\n",
                s->orient2d[VOR_TIER_NARROW], s->orient2d[VOR_TIER_WIDE], s->orient2d_perturbed,
                s->incircle[VOR_TIER_NARROW], s->incircle[VOR_TIER_MID],
                s->incircle[VOR_TIER_WIDE], s->incircle_perturbed, s->closer[VOR_TIER_NARROW],
                s->closer[VOR_TIER_WIDE], s->closer_perturbed);
    }
    free(duplicate_of);
    free(arena);
    free(sites);
    return 0;
}
