/* SPDX-License-Identifier: MIT */
/*
 * build/host/vor - the host command-line tool (docs/api.md, "CLI").
 *
 *   vor predicates            exact orient2d / incircle signs of stdin lines
 *   vor delaunay FILE         the Delaunay triangulation of a site file
 *   vor nearest SITES QUERIES the nearest (or --k=K nearest) sites to each query
 *   vor raster ... SITES      the discrete Voronoi diagram of a frame
 *   vor cells --box X0 Y0 X1 Y1 SITES   Voronoi cells clipped to a box
 *   vor ops [--capacity N] FILE   a dynamic diagram driven by a script
 *   vor --version             the library version the tool was built with
 */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "vor.h"

static const struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} commands[] = {
    {"predicates", cli_predicates, "exact orient2d/incircle signs of stdin lines"},
    {"delaunay", cli_delaunay, "Delaunay triangles of a site file (--stats, --order=)"},
    {"nearest", cli_nearest, "nearest (--k=K: K nearest) sites to each query point"},
    {"raster", cli_raster, "discrete Voronoi diagram: --labels OUT.raw or --png OUT.png"},
    {"cells", cli_cells, "Voronoi cells clipped to a box (--box X0 Y0 X1 Y1 SITES)"},
    {"ops", cli_ops, "insert/remove/move/nearest/triangles script ([--capacity N] FILE)"},
};

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--version") == 0) {
        printf("vor %s\n", VOR_VERSION_STRING);
        return 0;
    }
    if (argc >= 2) {
        for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
            if (strcmp(argv[1], commands[i].name) == 0) {
                return commands[i].run(argc - 2, argv + 2);
            }
        }
    }
    fprintf(stderr, "usage: vor COMMAND [ARGS]\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        fprintf(stderr, "  %-12s %s\n", commands[i].name, commands[i].summary);
    }
    fprintf(stderr, "  %-12s %s\n", "--version", "print the library version");
    return 2;
}
