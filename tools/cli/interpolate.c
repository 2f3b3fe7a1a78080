/* SPDX-License-Identifier: MIT */
/*
 * vor interpolate [--laplace] [--scale S] SITES QUERIES
 *
 * Natural-neighbour interpolation of integer site values, exact, over
 * Sibson's coordinates (or Laplace's, with --laplace):
 * SITES holds "x y value" lines (value an int32; a repeated point keeps
 * its first value), QUERIES "x y" lines. For each query one line,
 * "q X Y VALUE NUM DEN": VALUE the interpolant rounded once, halves away
 * from zero, NUM / DEN its exact value in lowest terms (DEN > 0, decimal
 * integers of any size); or "q X Y outside" outside the sites' convex
 * hull. The exact fraction is reduced here, with host arithmetic: the
 * library gives it over its common denominator.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define USAGE "usage: vor interpolate [--laplace] [--scale S] SITES QUERIES"

const char cli_interpolate_help[] =
    USAGE "\n"
    "\n"
    "Natural-neighbour interpolation of the values of SITES at each point of\n"
    "QUERIES (either '-': stdin), exact, over Sibson's coordinates.\n"
    "\n"
    "input:  SITES: \"x y value\" or \"x,y,value\" lines, value a decimal int32\n"
    "        (a repeated point keeps its first line's value); QUERIES: \"x y\"\n"
    "        or \"x,y\" lines. Coordinates decimal int32, or decimal numbers\n"
    "        with --scale S; blank and '#' lines skipped.\n"
    "output: one line per query: \"q X Y VALUE NUM DEN\", VALUE the exact value\n"
    "        NUM/DEN (lowest terms, DEN > 0) rounded to the nearest integer,\n"
    "        halves away from zero; \"q X Y outside\" outside the convex hull of\n"
    "        the sites. At a site: its value; on a hull edge: the linear\n"
    "        interpolation of the edge's ends.\n"
    "  --laplace     over Laplace's (non-Sibsonian) coordinates instead\n"
    "  --scale S     read decimal coordinates, times S\n"
    "\n"
    "example:\n"
    "  $ printf '0 0 0\\n4 0 40\\n4 4 80\\n0 4 40\\n' > sites; printf '1 1\\n9 9\\n' | vor interpolate sites -\n"
    "  q 1 1 20 20 1\n"
    "  q 9 9 outside\n";

/* A site's value for cli_read_points: a decimal int32. */
static bool value_field(const char **cursor, void *value, const char **why)
{
    return cli_int32_field(cursor, (int32_t *)value, why);
}

/* Non-negative integers of n 32-bit words, least significant first: just
 * what reducing a fraction and printing it needs. */
static bool big_zero(const uint32_t *a, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        if (a[i] != 0u) {
            return false;
        }
    }
    return true;
}

static int big_compare(const uint32_t *a, const uint32_t *b, size_t n)
{
    for (size_t i = n; i-- > 0;) {
        if (a[i] != b[i]) {
            return (a[i] > b[i]) ? 1 : -1;
        }
    }
    return 0;
}

static void big_sub(uint32_t *a, const uint32_t *b, size_t n) /* a >= b */
{
    uint64_t borrow = 0;
    for (size_t i = 0; i < n; i++) {
        uint64_t d = (uint64_t)a[i] - b[i] - borrow;
        a[i] = (uint32_t)d;
        borrow = (d >> 63) & 1u;
    }
}

static void big_shr1(uint32_t *a, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        a[i] = (a[i] >> 1) | ((i + 1 < n) ? (a[i + 1] << 31) : 0u);
    }
}

static void big_shl1(uint32_t *a, size_t n)
{
    for (size_t i = n; i-- > 0;) {
        a[i] = (a[i] << 1) | ((i > 0) ? (a[i - 1] >> 31) : 0u);
    }
}

/* g = gcd(a, b) for a, b not both 0 (binary: shifts and subtractions). */
static void big_gcd(uint32_t *g, const uint32_t *a_in, const uint32_t *b_in, size_t n)
{
    uint32_t *a = malloc(n * 4u), *b = malloc(n * 4u);
    if ((a == NULL) || (b == NULL)) {
        cli_error("out of memory");
    }
    memcpy(a, a_in, n * 4u);
    memcpy(b, b_in, n * 4u);
    unsigned twos = 0;
    if (big_zero(a, n) || big_zero(b, n)) {
        memcpy(g, big_zero(a, n) ? b : a, n * 4u);
        free(a);
        free(b);
        return;
    }
    while (((a[0] | b[0]) & 1u) == 0u) {
        big_shr1(a, n);
        big_shr1(b, n);
        twos++;
    }
    while ((a[0] & 1u) == 0u) {
        big_shr1(a, n);
    }
    while (!big_zero(b, n)) {
        while ((b[0] & 1u) == 0u) {
            big_shr1(b, n);
        }
        if (big_compare(a, b, n) > 0) {
            uint32_t *t = a;
            a = b;
            b = t;
        }
        big_sub(b, a, n);
    }
    for (unsigned i = 0; i < twos; i++) {
        big_shl1(a, n);
    }
    memcpy(g, a, n * 4u);
    free(a);
    free(b);
}

/* a = a / g exactly (g > 0), by shift and subtract. */
static void big_divide(uint32_t *a, const uint32_t *g, size_t n)
{
    uint32_t *rest = calloc(n, 4u), *q = calloc(n, 4u);
    if ((rest == NULL) || (q == NULL)) {
        cli_error("out of memory");
    }
    for (size_t bit = n * 32u; bit-- > 0;) {
        big_shl1(rest, n);
        rest[0] |= (a[bit / 32u] >> (bit % 32u)) & 1u;
        if (big_compare(rest, g, n) >= 0) {
            big_sub(rest, g, n);
            q[bit / 32u] |= 1u << (bit % 32u);
        }
    }
    memcpy(a, q, n * 4u);
    free(rest);
    free(q);
}

/* Appends a in decimal (destroys it). */
static void append_decimal(cli_output_t *out, uint32_t *a, size_t n)
{
    uint32_t *chunks = malloc((n * 32u / 29u + 2u) * 4u);
    size_t count = 0;
    if (chunks == NULL) {
        cli_error("out of memory");
    }
    do {
        uint64_t rest = 0;
        for (size_t i = n; i-- > 0;) {
            uint64_t cur = (rest << 32) | a[i];
            a[i] = (uint32_t)(cur / 1000000000u);
            rest = cur % 1000000000u;
        }
        chunks[count++] = (uint32_t)rest;
    } while (!big_zero(a, n));
    cli_append(out, "%u", chunks[count - 1]);
    while (count-- > 1) {
        cli_append(out, "%09u", chunks[count - 1]);
    }
    free(chunks);
}

int cli_interpolate(int argc, char **argv)
{
    const char *paths[2] = {NULL, NULL};
    int path_count = 0;
    bool laplace = false;
    static const cli_option_t options[] = {{"--laplace", 0}};
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, "interpolate", USAGE, options, sizeof options / sizeof options[0]);
    for (int o; (o = cli_next_argument(&args)) != CLI_END;) {
        const char *value = args.values[0];
        if (o == 0) {
            laplace = true;
        } else if (path_count == 2) {
            cli_usage_error("interpolate", USAGE, "unexpected argument", value);
        } else {
            paths[path_count++] = value;
        }
    }
    if (path_count < 2) {
        cli_usage_error("interpolate", USAGE,
                        path_count == 0 ? "missing SITES and QUERIES" : "missing QUERIES", NULL);
    }
    if (strcmp(paths[0], "-") == 0 && strcmp(paths[1], "-") == 0) {
        cli_usage_error("interpolate", USAGE, "SITES and QUERIES cannot both be stdin", NULL);
    }
    uint32_t n, queries;
    vor_point_t *sites;
    void *fields;
    n = cli_read_points(paths[0], "value", value_field, sizeof(int32_t), &sites, &fields);
    int32_t *values = fields;
    vor_point_t *points;
    vor_t d;
    void *arena = cli_query_diagram(&d, sites, n, paths[0], paths[1], "no sites to interpolate", &points, &queries);
    size_t scratch_bytes = VOR_SIBSON_SCRATCH_BYTES(16);
    void *scratch = malloc(scratch_bytes);
    if (scratch == NULL) {
        cli_error("out of memory");
    }
    cli_output_t out = {NULL, 0, 0};
    int (*const call)(const vor_t *, const int32_t *, vor_point_t, uint32_t, void *, size_t,
                      vor_interpolation_t *) = laplace ? vor_interpolate_laplace : vor_interpolate;
    const char *call_name = laplace ? "vor_interpolate_laplace" : "vor_interpolate";
    uint32_t hint = VOR_NO_HINT;
    for (uint32_t i = 0; i < queries; i++) {
        vor_interpolation_t v;
        vor_point_t q = points[i];
        int err = call(&d, values, q, hint, scratch, scratch_bytes, &v);
        if (err == VOR_ERR_NOMEM) { /* more neighbours than ever before */
            free(scratch);
            scratch_bytes = VOR_SIBSON_SCRATCH_BYTES(v.neighbours);
            scratch = malloc(scratch_bytes);
            if (scratch == NULL) {
                cli_error("out of memory");
            }
            err = call(&d, values, q, hint, scratch, scratch_bytes, &v);
        }
        if (err == VOR_ERR_OUTSIDE) {
            cli_append(&out, "q %d %d outside\n", q.x, q.y);
            continue;
        }
        if (err != VOR_OK) {
            cli_library_error(call_name, err);
        }
        size_t words = v.limbs;
        uint32_t *num = malloc(words * 4u), *den = malloc(words * 4u), *g = malloc(words * 4u);
        if ((num == NULL) || (den == NULL) || (g == NULL)) {
            cli_error("out of memory");
        }
        memcpy(num, v.numerator, words * 4u);
        memcpy(den, v.denominator, words * 4u);
        big_gcd(g, num, den, words);
        big_divide(num, g, words);
        big_divide(den, g, words);
        cli_append(&out, "q %d %d %d %s", q.x, q.y, v.value, (v.sign < 0) ? "-" : "");
        append_decimal(&out, num, words);
        cli_append(&out, " ");
        append_decimal(&out, den, words);
        cli_append(&out, "\n");
        free(num);
        free(den);
        free(g);
        (void)vor_nearest(&d, q, hint, &hint);
    }
    cli_flush(&out);
    free(scratch);
    free(arena);
    free(points);
    free(values);
    free(sites);
    return 0;
}
