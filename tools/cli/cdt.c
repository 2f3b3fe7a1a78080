/* SPDX-License-Identifier: MIT */
/*
 * vor cdt [--domain] SITES CONSTRAINTS
 *
 * The constrained Delaunay triangulation of the sites in SITES (as `vor
 * delaunay` reads them) with the constraints in CONSTRAINTS, one "a b"
 * pair of site ids a line: "s ID A B C D XN YN W" for each crossing vertex,
 * "t I J K" for each triangle and "c I J" for each constrained edge.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "vor_cdt.h"

#define USAGE "usage: vor cdt [--domain] SITES CONSTRAINTS"

const char cli_cdt_help[] =
    USAGE "\n"
    "\n"
    "The constrained Delaunay triangulation of SITES with CONSTRAINTS.\n"
    "\n"
    "input:  SITES as for vor delaunay (site i is the i-th site line; a repeated\n"
    "        point is its first site); CONSTRAINTS one \"a b\" pair of site ids a\n"
    "        line (blank and '#' lines skipped). A constraint from a site to\n"
    "        itself, or to its repeat, is ignored.\n"
    "output: \"s ID A B C D XN YN W\" per crossing vertex, ids from n (the number\n"
    "        of sites) up: constraints A-B and C-D cross there, at (XN/W, YN/W)\n"
    "        exactly, W > 0, in lowest terms; \"t I J K\" per triangle,\n"
    "        counterclockwise, from its smallest id, sorted; \"c I J\" per\n"
    "        constrained edge, I < J, sorted.\n"
    "  --domain      only the triangles inside the constraints (even-odd)\n"
    "\n"
    "example:\n"
    "  $ printf '0 0\\n10 0\\n10 10\\n0 10\\n' > s; printf '0 2\\n1 3\\n' > c\n"
    "  $ vor cdt s c\n"
    "  s 4 0 2 1 3 5 5 1\n"
    "  t 0 1 4\n"
    "  t 0 4 3\n"
    "  t 1 2 4\n"
    "  t 2 3 4\n"
    "  c 0 4\n"
    "  c 1 4\n"
    "  c 2 4\n"
    "  c 3 4\n";

/* crossing coordinates: |X| < 2^97, W < 2^66 (vor_cdt.h) */
__extension__ typedef __int128 wide_t;
__extension__ typedef unsigned __int128 uwide_t;

static wide_t gcd(wide_t a, wide_t b)
{
    a = (a < 0) ? -a : a;
    b = (b < 0) ? -b : b;
    while (b != 0) {
        wide_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* The crossing of lines a-b and c-d: X / W, Y / W, W > 0, lowest terms. */
static void crossing_point(vor_point_t a, vor_point_t b, vor_point_t c, vor_point_t d, wide_t *x,
                           wide_t *y, wide_t *w)
{
    wide_t bx = (wide_t)b.x - a.x, by = (wide_t)b.y - a.y;
    wide_t dx = (wide_t)d.x - c.x, dy = (wide_t)d.y - c.y;
    *w = bx * dy - by * dx;
    wide_t t = ((wide_t)c.x - a.x) * dy - ((wide_t)c.y - a.y) * dx;
    *x = (wide_t)a.x * *w + bx * t;
    *y = (wide_t)a.y * *w + by * t;
    if (*w < 0) {
        *x = -*x;
        *y = -*y;
        *w = -*w;
    }
    wide_t g = gcd(gcd(*x, *y), *w);
    *x /= g;
    *y /= g;
    *w /= g;
}

/* 256-bit two's complement integers: on_segment's products reach 2^131
 * (a difference of coordinates below 2^33 times w (P - a) below 2^98). */
typedef struct big {
    uint64_t limb[4];
} big_t;

static big_t big_negate(big_t a)
{
    big_t r;
    unsigned carry = 1;
    for (unsigned k = 0; k < 4u; k++) {
        r.limb[k] = ~a.limb[k] + carry;
        carry = (carry != 0u) && (r.limb[k] == 0u);
    }
    return r;
}

static big_t big_add(big_t a, big_t b)
{
    big_t r;
    uint64_t carry = 0;
    for (unsigned k = 0; k < 4u; k++) {
        uwide_t t = (uwide_t)a.limb[k] + b.limb[k] + carry;
        r.limb[k] = (uint64_t)t;
        carry = (uint64_t)(t >> 64);
    }
    return r;
}

/* a b exactly (|a|, |b| < 2^127). */
static big_t big_product(wide_t a, wide_t b)
{
    uwide_t ma = (a < 0) ? -(uwide_t)a : (uwide_t)a, mb = (b < 0) ? -(uwide_t)b : (uwide_t)b;
    uint64_t x[2] = {(uint64_t)ma, (uint64_t)(ma >> 64)}, y[2] = {(uint64_t)mb, (uint64_t)(mb >> 64)};
    big_t r = {{0, 0, 0, 0}};
    for (unsigned i = 0; i < 2u; i++) {
        for (unsigned j = 0; j < 2u; j++) {
            uwide_t t = (uwide_t)x[i] * y[j];
            big_t part = {{0, 0, 0, 0}};
            part.limb[i + j] = (uint64_t)t;
            part.limb[i + j + 1u] = (uint64_t)(t >> 64);
            r = big_add(r, part);
        }
    }
    return ((a < 0) != (b < 0)) ? big_negate(r) : r;
}

/* The sign of a - b. */
static int big_compare(big_t a, big_t b)
{
    big_t d = big_add(a, big_negate(b));
    if ((d.limb[3] >> 63) != 0u) {
        return -1;
    }
    return ((d.limb[0] | d.limb[1] | d.limb[2] | d.limb[3]) != 0u) ? 1 : 0;
}

/* Does the point X / W lie on the closed segment a-b? Exactly: w (P - a)
 * is collinear with b - a, and its projection on b - a lies between 0 and
 * w |b - a|^2. */
static bool on_segment(vor_point_t a, vor_point_t b, wide_t x, wide_t y, wide_t w)
{
    wide_t ux = (wide_t)b.x - a.x, uy = (wide_t)b.y - a.y;
    wide_t px = x - (wide_t)a.x * w, py = y - (wide_t)a.y * w; /* w (P - a), below 2^98 */
    if (big_compare(big_product(ux, py), big_product(uy, px)) != 0) {
        return false;
    }
    big_t along = big_add(big_product(ux, px), big_product(uy, py)); /* w (P - a).(b - a) */
    big_t zero = {{0, 0, 0, 0}};
    return big_compare(along, zero) >= 0 && big_compare(along, big_product(ux * ux + uy * uy, w)) <= 0;
}

static int compare_pairs(const void *p, const void *q)
{
    const uint32_t *a = p, *b = q;
    return (a[0] != b[0]) ? ((a[0] < b[0]) ? -1 : 1) : (a[1] < b[1]) ? -1 : (a[1] > b[1]);
}

static int compare_triples(const void *p, const void *q)
{
    const uint32_t *a = p, *b = q;
    for (unsigned k = 0; k < 3u; k++) {
        if (a[k] != b[k]) {
            return (a[k] < b[k]) ? -1 : 1;
        }
    }
    return 0;
}

uint32_t (*cli_read_constraints(const char *path, const uint32_t *first, uint32_t n,
                                size_t *count))[2]
{
    cli_input_t in;
    cli_open(&in, path);
    uint32_t (*pairs)[2] = NULL;
    size_t room = 0;
    *count = 0;
    for (const char *line; (line = cli_next_line(&in)) != NULL;) {
        int32_t ids[2];
        const char *why = NULL;
        for (unsigned k = 0; k < 2u; k++) {
            if (!cli_int32_field(&line, &ids[k], &why) && (why != NULL)) {
                cli_line_error(&in, why);
            }
            if ((ids[k] < 0) || ((uint32_t)ids[k] >= n)) {
                char reason[96];
                snprintf(reason, sizeof reason, "no site %ld (the sites are 0 .. %ld)", (long)ids[k],
                         (long)n - 1);
                cli_line_error(&in, reason);
            }
        }
        if (!cli_at_end(line)) {
            cli_line_error(&in, "more than two site ids");
        }
        uint32_t a = first[ids[0]];
        uint32_t b = first[ids[1]];
        if (a == b) {
            continue; /* a site to itself: ignored */
        }
        if (*count == room) {
            room = (room == 0u) ? 64u : 2u * room;
            pairs = realloc(pairs, room * sizeof *pairs);
            if (pairs == NULL) {
                cli_error("out of memory");
            }
        }
        pairs[*count][0] = a;
        pairs[*count][1] = b;
        (*count)++;
    }
    cli_close(&in);
    return pairs;
}

void *cli_constrain_all(vor_t *d, uint32_t capacity, uint32_t (*pairs)[2], size_t count,
                        uint32_t *crossings)
{
    vor_cdt_limits_t limits = {3u * (capacity + 64u), 64u, 0};
    void *memory = NULL;
    for (;;) {
        limits.cut = (2u * (capacity + limits.crossings)) + 2u;
        size_t bytes = VOR_CDT_BYTES(capacity, limits.edges, limits.crossings, limits.cut);
        free(memory);
        memory = malloc(bytes); /* malloc's alignment is VOR_CDT_ALIGN's at least */
        if (memory == NULL) {
            cli_error("out of memory");
        }
        int err = vor_cdt_attach(d, memory, bytes, &limits);
        if (err != VOR_OK) {
            cli_library_error("vor_cdt_attach", err);
        }
        size_t k = 0;
        while ((k < count) && ((err = vor_constrain(d, pairs[k][0], pairs[k][1])) == VOR_OK)) {
            k++;
        }
        if (k == count) {
            *crossings = limits.crossings;
            return memory;
        }
        if ((err != VOR_ERR_NOMEM) || (limits.crossings >= VOR_MAX_SITES - capacity)) {
            cli_library_error("vor_constrain", err);
        }
        limits.crossings = (limits.crossings > (VOR_MAX_SITES - capacity) / 2u)
                               ? VOR_MAX_SITES - capacity
                               : 2u * limits.crossings;
        limits.edges = 3u * (capacity + limits.crossings);
    }
}

void cli_crossing_point(const vor_point_t *sites, const uint32_t s[4], double *x, double *y)
{
    wide_t xn, yn, w;
    crossing_point(sites[s[0]], sites[s[1]], sites[s[2]], sites[s[3]], &xn, &yn, &w);
    /* to the nearest thousandth, exactly, then to double */
    wide_t half = w / 2;
    wide_t xs = (xn * 1000 + ((xn < 0) ? -half : half)) / w;
    wide_t ys = (yn * 1000 + ((yn < 0) ? -half : half)) / w;
    *x = (double)(long long)xs / 1000.0;
    *y = (double)(long long)ys / 1000.0;
}

int cli_cdt(int argc, char **argv)
{
    bool domain = false;
    const char *paths[2] = {NULL, NULL};
    enum { DOMAIN };
    static const cli_option_t flags[] = {[DOMAIN] = {"--domain", 0}};
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, "cdt", USAGE, flags, sizeof flags / sizeof flags[0]);
    for (int o; (o = cli_next_argument(&args)) != CLI_END;) {
        if (o == DOMAIN) {
            domain = true;
        } else if (paths[0] == NULL) {
            paths[0] = args.values[0];
        } else if (paths[1] == NULL) {
            paths[1] = args.values[0];
        } else {
            cli_usage_error("cdt", USAGE, "unexpected argument", args.values[0]);
        }
    }
    if (paths[1] == NULL) {
        cli_usage_error("cdt", USAGE, "missing SITES or CONSTRAINTS", NULL);
    }
    uint32_t n;
    vor_point_t *sites = cli_read_sites(paths[0], &n);
    uint32_t capacity = (n < 1u) ? 1u : n;
    uint32_t *first = malloc((size_t)capacity * sizeof *first);
    if (first == NULL) {
        cli_error("out of memory");
    }
    vor_t d;
    void *arena = cli_diagram(&d, capacity);
    int built = vor_build(&d, sites, n, NULL, first);
    if (built != VOR_OK) {
        cli_library_error("vor_build", built);
    }
    size_t count;
    uint32_t (*pairs)[2] = cli_read_constraints(paths[1], first, n, &count);
    vor_cdt_limits_t limits = {0, 0, 0};
    void *memory = cli_constrain_all(&d, capacity, pairs, count, &limits.crossings);
    limits.edges = 3u * (capacity + limits.crossings);
    if (domain && (vor_cdt_domain(&d) != VOR_OK)) {
        cli_library_error("vor_cdt_domain", VOR_ERR_ARG);
    }
    /* crossing ids renumbered from n, in increasing order */
    uint32_t *rename = calloc((size_t)limits.crossings + 1u, sizeof *rename);
    if (rename == NULL) {
        cli_error("out of memory");
    }
    cli_output_t out = {NULL, 0, 0};
    uint32_t next_id = n;
    for (uint32_t i = 0; i < limits.crossings; i++) {
        uint32_t s[4];
        if (vor_cdt_crossing(&d, capacity + i, s) != VOR_OK) {
            continue;
        }
        rename[i] = next_id++;
        wide_t x, y, w;
        crossing_point(sites[s[0]], sites[s[1]], sites[s[2]], sites[s[3]], &x, &y, &w);
        /* the first two constraints of the file through the point */
        uint32_t through[2][2] = {{0, 0}, {0, 0}};
        unsigned found = 0;
        for (size_t k = 0; (k < count) && (found < 2u); k++) {
            if (on_segment(sites[pairs[k][0]], sites[pairs[k][1]], x, y, w)) {
                through[found][0] = pairs[k][0];
                through[found][1] = pairs[k][1];
                found++;
            }
        }
        cli_append(&out, "s %u %u %u %u %u ", rename[i], through[0][0], through[0][1],
                   through[1][0], through[1][1]);
        cli_append_wide(&out, x);
        cli_append(&out, " ");
        cli_append_wide(&out, y);
        cli_append(&out, " ");
        cli_append_wide(&out, w);
        cli_append(&out, "\n");
    }
#define RENAME(v) (((v) >= capacity) ? rename[(v) - capacity] : (v))
    /* triangles, rotated to their smallest id and sorted */
    size_t cap_t = 2u * ((size_t)capacity + limits.crossings) + 2u;
    uint32_t (*tri)[3] = malloc(cap_t * sizeof *tri);
    if (tri == NULL) {
        cli_error("out of memory");
    }
    size_t nt = 0;
    vor_cdt_triangle_iter_t it;
    uint32_t ids[3];
    (void)(domain ? vor_cdt_inside_begin(&it, &d) : vor_cdt_triangles_begin(&it, &d));
    while ((nt < cap_t) && vor_cdt_triangles_next(&it, ids)) {
        for (unsigned k = 0; k < 3u; k++) {
            ids[k] = RENAME(ids[k]);
        }
        unsigned lo = (ids[1] < ids[0]) ? 1u : 0u;
        lo = (ids[2] < ids[lo]) ? 2u : lo;
        for (unsigned k = 0; k < 3u; k++) {
            tri[nt][k] = ids[(lo + k) % 3u];
        }
        nt++;
    }
    qsort(tri, nt, sizeof *tri, compare_triples);
    for (size_t t = 0; t < nt; t++) {
        cli_append(&out, "t %u %u %u\n", tri[t][0], tri[t][1], tri[t][2]);
    }
    /* constrained edges, sorted */
    size_t cap_e = (size_t)limits.edges;
    uint32_t (*edges)[2] = malloc((cap_e + 1u) * sizeof *edges);
    if (edges == NULL) {
        cli_error("out of memory");
    }
    size_t ne = 0;
    vor_cdt_edge_iter_t ei;
    uint32_t a, b;
    vor_cdt_edges_begin(&ei, &d);
    while ((ne < cap_e) && vor_cdt_edges_next(&ei, &a, &b)) {
        a = RENAME(a);
        b = RENAME(b);
        edges[ne][0] = (a < b) ? a : b;
        edges[ne][1] = (a < b) ? b : a;
        ne++;
    }
    qsort(edges, ne, sizeof *edges, compare_pairs);
    for (size_t e = 0; e < ne; e++) {
        cli_append(&out, "c %u %u\n", edges[e][0], edges[e][1]);
    }
    cli_flush(&out);
    free(edges);
    free(tri);
    free(rename);
    free(memory);
    free(pairs);
    free(arena);
    free(first);
    free(sites);
    return 0;
}
