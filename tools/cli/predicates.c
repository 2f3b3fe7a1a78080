/* SPDX-License-Identifier: MIT */
/*
 * vor predicates: exact unperturbed signs of orient2d and incircle for
 * lines read from standard input:
 *
 *   o ax ay bx by cx cy          -> sign of vor_orient2d(a, b, c)
 *   c ax ay bx by cx cy dx dy    -> sign of vor_incircle(a, b, c, d)
 *
 * One output line (-1, 0 or 1) per input line; blank and '#' lines are
 * skipped. Any malformed line: "error: line N: reason", exit 2, no output.
 */
#include "cli.h"

#include "vor.h"

int cli_predicates(int argc, char **argv)
{
    if (argc != 0) {
        (void)argv;
        cli_error("usage: vor predicates < LINES");
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
        vor_point_t v[4];
        for (unsigned k = 0; k < points; k++) {
            const char *why;
            if (!cli_int32_field(&p, &v[k].x, &why) || !cli_int32_field(&p, &v[k].y, &why)) {
                cli_line_error(&in, why);
            }
        }
        if (!cli_at_end(p)) {
            cli_line_error(&in, "too many fields");
        }
        int sign = (op == 'o') ? vor_orient2d(&v[0], &v[1], &v[2], NULL)
                               : vor_incircle(&v[0], &v[1], &v[2], &v[3], NULL);
        cli_append(&out, "%d\n", sign);
    }
    cli_close(&in);
    cli_flush(&out);
    return 0;
}
