/* SPDX-License-Identifier: MIT */
/*
 * vor ops [--capacity N] [--scale S] FILE
 *
 * Drives a dynamic diagram from a script, one operation a line (FILE "-"
 * is stdin; blank and '#' lines skipped), one result line per operation:
 *
 *   i X Y      insert: the new id, or "d ID" when (X, Y) is site ID
 *   r ID       remove: "ok"
 *   m ID X Y   move: "ok", or "d ID" when (X, Y) is another site ID
 *   n X Y      nearest site: its id (exact, ties to the smaller id)
 *   t          every triangle of the true Delaunay triangulation as
 *              "t i j k" (counterclockwise, from its smallest id, lines
 *              sorted), then "end"
 *
 * --capacity N: the most sites at once (default: the number of operation
 * lines). --scale S scales X and Y as every command's coordinates. A bad
 * line, an unknown id, a full diagram or a query on no sites: "error:
 * FILE:N: reason" on stderr, exit 2, nothing on stdout.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define USAGE "usage: vor ops [--capacity N] [--scale S] FILE"

const char cli_ops_help[] =
    USAGE "\n"
    "\n"
    "Drives a dynamic diagram from a script FILE ('-': stdin), one operation a\n"
    "line, and prints one result line per operation. --capacity N: the most\n"
    "sites at once (default: the number of operation lines).\n"
    "\n"
    "input:  one operation per line (blank and '#' lines skipped):\n"
    "          i X Y      insert the site (X, Y)\n"
    "          r ID       remove site ID\n"
    "          m ID X Y   move site ID to (X, Y)\n"
    "          n X Y      the site nearest to (X, Y)\n"
    "          t          the triangles\n"
    "        fields separated by blanks or commas (i,0,0); X, Y decimal int32,\n"
    "        or decimal numbers with --scale S (times S, rounded to nearest,\n"
    "        ties away from zero); ids stay integers. A removed site's id is\n"
    "        reused by a later insert, the most recently freed first.\n"
    "output: i: the new id, or \"d ID\" when (X, Y) is site ID; r: \"ok\";\n"
    "        m: \"ok\", or \"d ID\" when (X, Y) is another site ID; n: the id,\n"
    "        by exact distance, ties to the smaller id; t: \"t i j k\" for every\n"
    "        triangle of the true Delaunay triangulation (counterclockwise,\n"
    "        from its smallest id, lines sorted), then \"end\". An unknown id,\n"
    "        a full diagram or a query on no sites is an error on its line.\n"
    "\n"
    "example:\n"
    "  $ printf 'i 0 0\\ni 10 0\\ni 0 10\\nr 1\\ni 5 5\\nn 9 1\\nt\\n' | vor ops -\n"
    "  0\n"
    "  1\n"
    "  2\n"
    "  ok\n"
    "  1\n"
    "  1\n"
    "  t 0 1 2\n"
    "  end\n";

typedef struct {
    char *text;
    unsigned long line_number;
} op_line_t;

/* The rest of the line after the operation letter: n fields, then
 * nothing. An operation's coordinates are its last pair of fields (read
 * with --scale as every command's); an odd first field is an id. */
static void fields(const cli_input_t *in, const char *cursor, int32_t *values, unsigned n)
{
    for (unsigned k = 0; k < n; k++) {
        const char *why;
        if (!(k < n % 2u ? cli_int32_field(&cursor, &values[k], &why)
                         : cli_coordinate_field(&cursor, &values[k], &why))) {
            cli_line_error(in, why);
        }
    }
    if (!cli_at_end(cursor)) {
        cli_line_error(in, "too many fields");
    }
}

int cli_ops(int argc, char **argv)
{
    uint32_t capacity = 0; /* 0: the number of operation lines */
    const char *path = NULL;
    static const cli_option_t options[] = {{"--capacity", 1}};
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, "ops", USAGE, options, sizeof options / sizeof options[0]);
    for (int o; (o = cli_next_argument(&args)) != CLI_END;) {
        const char *text = args.values[0];
        if (o == 0) {
            char *end;
            unsigned long value = strtoul(text, &end, 10);
            if (*end != '\0' || text[0] < '0' || text[0] > '9' || value < 1u || value > VOR_MAX_SITES) {
                cli_usage_error("ops", USAGE, "--capacity must be 1 to VOR_MAX_SITES", text);
            }
            capacity = (uint32_t)value;
        } else if (path != NULL) {
            cli_usage_error("ops", USAGE, "unexpected argument", text);
        } else {
            path = text;
        }
    }
    if (path == NULL) {
        cli_usage_error("ops", USAGE, "no script FILE", NULL);
    }
    /* the whole script first: the default capacity is its length */
    cli_input_t in;
    cli_open(&in, path);
    op_line_t *lines = NULL;
    size_t count = 0, room = 0;
    const char *text;
    while ((text = cli_next_line(&in)) != NULL) {
        if (count == room) {
            room = room ? 2u * room : 64u;
            lines = realloc(lines, room * sizeof *lines);
            if (lines == NULL) {
                cli_error("out of memory");
            }
        }
        lines[count].text = malloc(strlen(text) + 1u);
        if (lines[count].text == NULL) {
            cli_error("out of memory");
        }
        strcpy(lines[count].text, text);
        lines[count].line_number = in.line_number;
        count++;
    }
    if (capacity == 0u) {
        capacity = count == 0u ? 1u : (count > VOR_MAX_SITES ? VOR_MAX_SITES : (uint32_t)count);
    }
    vor_t d;
    void *arena = cli_diagram(&d, capacity);
    cli_output_t out = {NULL, 0, 0};
    for (size_t k = 0; k < count; k++) {
        in.line_number = lines[k].line_number; /* for cli_line_error */
        const char *cursor = lines[k].text;
        while (*cursor == ' ' || *cursor == '\t') {
            cursor++;
        }
        char op = *cursor++;
        if (op != '\0' && *cursor != '\0' && *cursor != ' ' && *cursor != '\t') {
            op = '?'; /* a longer word */
        }
        int32_t v[3];
        uint32_t id;
        int err;
        switch (op) {
        case 'i':
            fields(&in, cursor, v, 2);
            err = vor_insert(&d, (vor_point_t){v[0], v[1]}, &id);
            if (err == VOR_ERR_FULL) {
                cli_line_error(&in, "the diagram is full (--capacity)");
            }
            cli_append(&out, err == VOR_ERR_DUPLICATE ? "d %u\n" : "%u\n", id);
            break;
        case 'r':
            fields(&in, cursor, v, 1);
            if (v[0] < 0 || vor_remove(&d, (uint32_t)v[0]) != VOR_OK) {
                cli_line_error(&in, "unknown site id");
            }
            cli_append(&out, "ok\n");
            break;
        case 'm':
            fields(&in, cursor, v, 3);
            if (v[0] < 0) {
                cli_line_error(&in, "unknown site id");
            }
            err = vor_move(&d, (uint32_t)v[0], (vor_point_t){v[1], v[2]}, &id);
            if (err == VOR_ERR_DUPLICATE) {
                cli_append(&out, "d %u\n", id);
            } else if (err != VOR_OK) {
                cli_line_error(&in, "unknown site id");
            } else {
                cli_append(&out, "ok\n");
            }
            break;
        case 'n':
            fields(&in, cursor, v, 2);
            if (vor_nearest(&d, (vor_point_t){v[0], v[1]}, VOR_NO_HINT, &id) != VOR_OK) {
                cli_line_error(&in, "no sites to answer with");
            }
            cli_append(&out, "%u\n", id);
            break;
        case 't':
            if (!cli_at_end(cursor)) {
                cli_line_error(&in, "too many fields");
            }
            (void)cli_append_triangles(&d, &out);
            cli_append(&out, "end\n");
            break;
        default:
            cli_line_error(&in, "expected 'i', 'r', 'm', 'n' or 't'");
        }
    }
    cli_flush(&out);
    for (size_t k = 0; k < count; k++) {
        free(lines[k].text);
    }
    free(lines);
    free(arena);
    cli_close(&in);
    return 0;
}
