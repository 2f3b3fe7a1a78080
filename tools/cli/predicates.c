/* SPDX-License-Identifier: MIT */
/*
 * vor predicates: exact unperturbed signs of orient2d and incircle for
 * lines read from standard input:
 *
 *   o ax ay bx by cx cy          -> sign of vor_orient2d(a, b, c)
 *   c ax ay bx by cx cy dx dy    -> sign of vor_incircle(a, b, c, d)
 *
 * One output line (-1, 0 or 1) per input line; blank and '#' lines are
 * skipped. Any malformed line: "error: <stdin>:N: reason", exit 2, no output.
 */
#include "cli.h"

#include "vor.h"

#define USAGE "usage: vor predicates [--scale S] < LINES"

const char cli_predicates_help[] =
    USAGE "\n"
    "\n"
    "Exact signs of orient2d and incircle for the lines of stdin.\n"
    "\n"
    "input:  \"o ax ay bx by cx cy\"        orient2d(a, b, c)\n"
    "        \"c ax ay bx by cx cy dx dy\"  incircle(a, b, c, d)\n"
    "        fields separated by blanks or by commas (o,0,0,1,0,0,1); decimal\n"
    "        int32, or decimal numbers with --scale S (times S, rounded to\n"
    "        nearest, ties away from zero); blank and '#' lines skipped.\n"
    "output: one line per input line: -1, 0 or 1 (orient2d: 1 when a, b, c\n"
    "        turn counterclockwise; incircle: 1 when d is inside the circle\n"
    "        through a, b, c counterclockwise).\n"
    "\n"
    "example:\n"
    "  $ printf 'o 0 0 1 0 0 1\\nc 0 0 2 0 0 2 2 2\\n' | vor predicates\n"
    "  1\n"
    "  0\n";

int cli_predicates(int argc, char **argv)
{
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, "predicates", USAGE, NULL, 0);
    if (cli_next_argument(&args) != CLI_END) {
        cli_usage_error("predicates", USAGE, "unexpected argument", args.values[0]);
    }
    cli_input_t in;
    cli_output_t out = {NULL, 0, 0};
    cli_open(&in, "-");
    const char *line;
    while ((line = cli_next_line(&in)) != NULL) {
        const char *p = line;
        while (*p == ' ' || *p == '\t') {
            p++;
        }
        char op = *p;
        if ((op != 'o' && op != 'c') || (p[1] != ' ' && p[1] != '\t')) {
            cli_line_error(&in, "expected 'o' or 'c' followed by coordinates");
        }
        p++;
        unsigned points = (op == 'o') ? 3u : 4u;
        const char *shape = (op == 'o') ? "o ax ay bx by cx cy" : "c ax ay bx by cx cy dx dy";
        vor_point_t v[4];
        for (unsigned k = 0; k < points; k++) {
            const char *why;
            if (!cli_coordinate_field(&p, &v[k].x, &why) || !cli_coordinate_field(&p, &v[k].y, &why)) {
                char reason[300];
                snprintf(reason, sizeof reason, "%s (expected %s)", why, shape);
                cli_line_error(&in, reason);
            }
        }
        if (!cli_at_end(p)) {
            char reason[120];
            snprintf(reason, sizeof reason, "too many fields (expected %s)", shape);
            cli_line_error(&in, reason);
        }
        int sign = (op == 'o') ? vor_orient2d(v[0], v[1], v[2])
                               : vor_incircle(v[0], v[1], v[2], v[3]);
        cli_append(&out, "%d\n", sign);
    }
    cli_close(&in);
    cli_flush(&out);
    return 0;
}
