/* SPDX-License-Identifier: MIT */
/*
 * build/host/vor - the host command-line tool (docs/api.md, "CLI").
 *
 *   vor predicates            exact orient2d / incircle signs of stdin lines
 *   vor delaunay FILE         the Delaunay triangulation of a site file
 *   vor nearest SITES QUERIES the nearest (or --k=K nearest) sites to each query
 *   vor raster ... SITES      the discrete Voronoi diagram of a frame
 *   vor cells --box X0 Y0 X1 Y1 SITES   Voronoi cells clipped to a box (or --clip POLY)
 *   vor ops [--capacity N] FILE   a dynamic diagram driven by a script
 *   vor interpolate SITES QUERIES  exact natural-neighbour interpolation
 *                             (Sibson's; --laplace: Laplace's)
 *   vor locate SITES QUERIES  the Delaunay triangle holding each query
 *   vor within --r2 R2 SITES QUERIES  the sites within a squared distance
 *   vor --version             the library version the tool was built with
 *   vor --help, vor help [COMMAND], vor COMMAND --help   help on stdout
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
    {"raster", cli_raster, "discrete Voronoi diagram: --labels OUT.raw or --png OUT.png (y up)"},
    {"cells", cli_cells, "Voronoi cells clipped to a box or polygon (--box X0 Y0 X1 Y1 | --clip POLY) SITES"},
    {"draw", cli_draw, "SVG picture of the diagram (SITES -o OUT.svg; --triangles --ids --hull)"},
    {"ops", cli_ops, "insert/remove/move/nearest/triangles script ([--capacity N] FILE)"},
    {"cdt", cli_cdt, "constrained Delaunay triangulation (SITES CONSTRAINTS; --domain)"},
    {"power", cli_power, "regular triangulation and hidden sites of weighted sites (x y w)"},
    {"interpolate", cli_interpolate, "exact natural-neighbour interpolation (SITES: x y value; QUERIES; --laplace)"},
    {"locate", cli_locate, "the Delaunay triangle holding each query point, or outside"},
    {"within", cli_within, "the sites within squared distance R2 of each query (--r2 R2)"},
};

/* The help of each command (cli.h); a command without one shows its
 * summary. */
static const struct {
    const char *name;
    const char *text;
} helps[] = {
    {"predicates", cli_predicates_help},
    {"delaunay", cli_delaunay_help},
    {"nearest", cli_nearest_help},
    {"raster", cli_raster_help},
    {"cells", cli_cells_help},
    {"draw", cli_draw_help},
    {"ops", cli_ops_help},
    {"cdt", cli_cdt_help},
    {"power", cli_power_help},
    {"interpolate", cli_interpolate_help},
    {"locate", cli_locate_help},
    {"within", cli_within_help},
};

static void print_usage(FILE *out)
{
    fprintf(out, "usage: vor COMMAND [OPTIONS] FILES...\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        fprintf(out, "  %-12s %s\n", commands[i].name, commands[i].summary);
    }
    fprintf(out, "  %-12s %s\n", "--version", "print the library version");
    fprintf(out, "  %-12s %s\n", "--help", "this text; vor COMMAND --help: formats and an example");
}

static int print_help(void)
{
    print_usage(stdout);
    printf("\n"
           "Input: one point per line, \"x y\" (blanks between the fields) or \"x,y\"\n"
           "(CSV; a first line whose every field starts with a letter or '\"', such\n"
           "as \"x,y\", is a header: no point or operation line is one).\n"
           "Coordinates are decimal int32; with --scale S they may be decimal numbers\n"
           "(12.5, -3e-2), multiplied by S and rounded to the nearest integer, ties\n"
           "away from zero, exactly. Blank lines and lines starting with '#' are\n"
           "skipped, and so is a UTF-8 byte-order mark opening a file; point i is\n"
           "the i-th remaining line, from 0. FILE '-' is stdin.\n"
           "Options: \"--k 3\" or \"--k=3\", \"--size 4 2\" or \"--size=4,2\", in any order\n"
           "with the files; --scale S works with every command.\n"
           "Output: text on stdout, written only when the whole input was valid.\n"
           "Errors: \"error: FILE:LINE: reason\" on stderr, exit status 2.\n"
           "\n"
           "example:\n"
           "  printf '0 0\\n10 0\\n0 10\\n' | vor delaunay -\n");
    return 0;
}

/* Prints the help of command name on stdout; false if there is no such
 * command. */
static bool command_help(const char *name)
{
    for (size_t i = 0; i < sizeof helps / sizeof helps[0]; i++) {
        if (strcmp(name, helps[i].name) == 0) {
            fputs(helps[i].text, stdout);
            return true;
        }
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        if (strcmp(name, commands[i].name) == 0) {
            printf("vor %s: %s\n", commands[i].name, commands[i].summary);
            return true;
        }
    }
    return false;
}

static int unknown_command(const char *name)
{
    fprintf(stderr, "error: unknown %s '%s'\nrun 'vor --help' for the list of commands\n",
            name[0] == '-' ? "option" : "command", name);
    return 2;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--version") == 0) {
        printf("vor %s\n", VOR_VERSION_STRING);
        return 0;
    }
    if (argc < 2) {
        print_usage(stderr);
        return 2;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        (strcmp(argv[1], "help") == 0 && argc == 2)) {
        return print_help();
    }
    if (strcmp(argv[1], "help") == 0) {
        return command_help(argv[2]) ? 0 : unknown_command(argv[2]);
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        if (strcmp(argv[1], commands[i].name) != 0) {
            continue;
        }
        /* --help anywhere is the same for every command (and --scale S,
         * which cli_next_argument handles) */
        for (int a = 2; a < argc; a++) {
            if (strcmp(argv[a], "--help") == 0 || strcmp(argv[a], "-h") == 0) {
                command_help(commands[i].name);
                return 0;
            }
        }
        return commands[i].run(argc - 2, argv + 2);
    }
    return unknown_command(argv[1]);
}
