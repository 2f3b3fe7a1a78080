/* SPDX-License-Identifier: MIT */
/*
 * vor draw [--box X0 Y0 X1 Y1] [--size W H] [--triangles] [--ids] [--hull]
 *          [--y-down] SITES -o OUT.svg
 * vor draw --power [--box X0 Y0 X1 Y1] [--size W H] [--triangles] [--ids]
 *          [--y-down] SITES -o OUT.svg
 * vor draw --cells DUMP -o OUT.svg
 *
 * An SVG picture of the Voronoi diagram of SITES (counted like
 * `vor delaunay`): every cell clipped to the box and filled with its
 * site's colour, the Voronoi edges, the sites as dots, and optionally the
 * Delaunay triangles, the site ids and the convex hull. The box defaults
 * to the sites' bounding box grown by a twentieth of its larger side (at
 * least 1) on every side; the size to 800 pixels wide and as high as the
 * box's aspect asks. The box fills the whole picture (preserveAspectRatio
 * "none"), so pixel (i, r) of a W x H rendering, row r from the top,
 * covers x in X0 + [i, i+1] (X1-X0)/W and y in Y1 - [r, r+1] (Y1-Y0)/H.
 *
 * Coordinates are the library's, y up: the SVG holds them unchanged inside
 * one group with transform="scale(1 -1)" and a viewBox of
 * "X0 -Y1 X1-X0 Y1-Y0". --y-down draws them in screen order instead
 * (viewBox "X0 Y0 X1-X0 Y1-Y0", no flip): pixel row r then covers
 * y in Y0 + [r, r+1] (Y1-Y0)/H. Every vertex written is a cell vertex exactly as
 * `vor cells` gives it (the exact vertex rounded once); sites are the
 * input integers. The Voronoi edges are the cells' sides that do not lie
 * on the box, each written once (from the cell where it runs from the
 * lexicographically smaller end), rather than vor_edges: its rays would
 * need a second rounding to end at the box.
 *
 * Colours: site i is filled with cli_site_colour(i), as in `vor raster
 * --png`.
 *
 * --constraints FILE (pairs of site ids, as `vor cdt` reads them) draws the
 * constrained Delaunay triangulation over the cells instead of the
 * Delaunay one: its triangles thin, the constrained edges thick, crossing
 * vertices as squares (at their exact point rounded to a thousandth);
 * --domain draws only the triangles inside the constraints, shaded.
 *
 * --power reads weighted sites ("x y w", as `vor power`) and draws their
 * power diagram: every power cell clipped to the box (vor_power_cell), a
 * circle of radius sqrt(w) around each site of positive weight, the
 * vertices as dots and the hidden sites as rings; --triangles adds the
 * regular triangulation.
 *
 * --cells DUMP draws what a firmware computed (examples/voronoi streams it
 * to build/demo.cells): lines "box X0 Y0 X1 Y1" (first), "s X Y" (site i
 * is the i-th s line) and "c I M X1 Y1 ... XM YM" (as `vor cells`).
 * "-o -" writes to standard output.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "vor_cdt.h"

#define USAGE                                                                                      \
    "usage: vor draw [--box X0 Y0 X1 Y1] [--size W H] [--triangles] [--ids] [--hull] [--y-down]\n" \
    "                [--constraints FILE [--domain]] SITES -o OUT.svg\n"                            \
    "       vor draw --power [--box X0 Y0 X1 Y1] [--size W H] [--triangles] [--ids] [--y-down]\n"     \
    "                SITES -o OUT.svg\n"                                                            \
    "       vor draw [--y-down] --cells DUMP -o OUT.svg"

const char cli_draw_help[] =
    USAGE "\n"
    "\n"
    "An SVG picture of the Voronoi diagram of SITES ('-': stdin): every cell\n"
    "clipped to the box and filled with its site's colour, the Voronoi edges\n"
    "and the sites; --triangles adds the Delaunay triangles, --ids the site\n"
    "ids, --hull the convex hull; --constraints FILE the constrained\n"
    "triangulation (as vor cdt: constraints thick, crossing vertices as\n"
    "squares), --domain only its triangles inside them, shaded. --power: the\n"
    "power diagram of weighted sites (\"x y w\", as vor power): power cells,\n"
    "circles of radius sqrt(w), hidden sites as rings; --triangles the\n"
    "regular triangulation.\n"
    "y points up, as in the library and in\n"
    "`vor raster --png`; --y-down draws in screen order (y = Y0 at the top).\n"
    "\n"
    "input:  one site per line, \"x y\" or \"x,y\" (CSV, optional header line);\n"
    "        decimal int32, or decimal numbers with --scale S; site i is the\n"
    "        i-th site line, from 0. --cells DUMP: a firmware's dump instead\n"
    "        (\"box X0 Y0 X1 Y1\", \"s X Y\", \"c I M X1 Y1 ...\" lines).\n"
    "output: OUT.svg ('-': stdout), written only when everything succeeded.\n"
    "        --box: default the sites' bounding box grown by a twentieth;\n"
    "        --size: default 800 pixels wide, as high as the box's aspect.\n"
    "        Every vertex is the cell vertex `vor cells` prints; site i's\n"
    "        colour (the same in `vor raster --png`) is #RRGGBB from\n"
    "        c = (i * 2654435761) mod 2^21:\n"
    "        RR = 128 + (c & 127), GG = 128 + ((c >> 7) & 127), BB = 128 + (c >> 14).\n"
    "\n"
    "example:\n"
    "  $ printf '0 0\\n100 0\\n0 100\\n' | vor draw --ids - -o diagram.svg\n";

#define DEFAULT_WIDTH 800
#define MAX_PIXELS 16384

/* libxml2 (xmllint, rsvg-convert) refuses attributes over 10 MB, so a
 * stroke of many pieces is split into paths of this many pieces each. */
#define PIECES_PER_PATH 4096u

/* Pieces ("M.. L..") of one stroke style, written as consecutive paths. */
typedef struct stroke {
    cli_output_t *out;
    char head[160]; /* the opening of each path, up to d=" */
    uint32_t pieces;
} stroke_t;

/* The picture being written: cell fills go to `svg` as they come, the
 * edges to `edges`, appended after all fills so no fill covers an edge. */
typedef struct drawing {
    vor_box_t box;
    double unit; /* library units per pixel, for stroke widths and radii */
    bool y_down; /* --y-down: screen order, y = Y0 at the top */
    cli_output_t svg;
    cli_output_t edges;
    stroke_t edge_stroke;
} drawing_t;

static void stroke_begin(stroke_t *s, cli_output_t *out, const char *colour, double width)
{
    s->out = out;
    s->pieces = 0;
    snprintf(s->head, sizeof s->head,
             "<path fill=\"none\" stroke=\"%s\" stroke-width=\"%.4g\" stroke-linejoin=\"round\" d=\"", colour,
             width);
}

/* Call before appending each piece. */
static void stroke_piece(stroke_t *s)
{
    if (s->pieces % PIECES_PER_PATH == 0) {
        cli_append(s->out, "%s%s", s->pieces > 0 ? "\"/>\n" : "", s->head);
    }
    s->pieces++;
}

static void stroke_end(stroke_t *s)
{
    if (s->pieces > 0) {
        cli_append(s->out, "\"/>\n");
    }
}

static void site_colour(uint32_t site, char text[8])
{
    snprintf(text, 8, "#%06x", (unsigned)cli_site_colour(site));
}

static int32_t int_argument(const char *text, const char *option)
{
    const char *cursor = text, *why = "not a decimal integer";
    int32_t value;
    if (!cli_int32_field(&cursor, &value, &why) || !cli_at_end(cursor)) {
        fprintf(stderr, "error: %s: %s: %s\n", option, text, why);
        exit(2);
    }
    return value;
}

static void begin_svg(drawing_t *g, uint32_t width, uint32_t height)
{
    const vor_box_t *b = &g->box;
    double box_width = (double)b->x1 - b->x0, box_height = (double)b->y1 - b->y0;
    double unit_x = box_width / width, unit_y = box_height / height;
    g->unit = unit_x > unit_y ? unit_x : unit_y;
    if (g->y_down) {
        cli_append(&g->svg,
                   "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                   "<!-- vor draw, y down: the library's coordinates in screen order;\n"
                   "     the viewBox is the box [%d, %d] x [%d, %d]. -->\n"
                   "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%u\" height=\"%u\" "
                   "viewBox=\"%d %d %lld %lld\" preserveAspectRatio=\"none\">\n"
                   "<g>\n<g stroke=\"none\">\n",
                   b->x0, b->x1, b->y0, b->y1, width, height, b->x0, b->y0, (long long)b->x1 - b->x0,
                   (long long)b->y1 - b->y0);
    } else {
        cli_append(&g->svg,
                   "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                   "<!-- vor draw: the library's coordinates with y up; the group's scale(1 -1) flips y,\n"
                   "     and the viewBox is the box [%d, %d] x [%d, %d] flipped. -->\n"
                   "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%u\" height=\"%u\" "
                   "viewBox=\"%d %lld %lld %lld\" preserveAspectRatio=\"none\">\n"
                   "<g transform=\"scale(1 -1)\">\n<g stroke=\"none\">\n",
                   b->x0, b->x1, b->y0, b->y1, width, height, b->x0, -(long long)b->y1,
                   (long long)b->x1 - b->x0, (long long)b->y1 - b->y0);
    }
    stroke_begin(&g->edge_stroke, &g->edges, "#000", g->unit);
}

static bool on_box_side(const vor_box_t *b, vor_point_t p, vor_point_t q)
{
    return (p.x == q.x && (p.x == b->x0 || p.x == b->x1)) || (p.y == q.y && (p.y == b->y0 || p.y == b->y1));
}

static bool lexicographically_less(vor_point_t p, vor_point_t q)
{
    return p.x < q.x || (p.x == q.x && p.y < q.y);
}

static void add_cell(drawing_t *g, uint32_t site, const vor_point_t *v, uint32_t count)
{
    if (count == 0) {
        return;
    }
    char colour[8];
    site_colour(site, colour);
    cli_append(&g->svg, "<path fill=\"%s\" d=\"M%d %d", colour, v[0].x, v[0].y);
    for (uint32_t k = 1; k < count; k++) {
        cli_append(&g->svg, "L%d %d", v[k].x, v[k].y);
    }
    cli_append(&g->svg, "Z\"/>\n");
    /* the neighbour walks a shared side the other way round (both CCW) */
    for (uint32_t k = 0; k < count; k++) {
        vor_point_t p = v[k], q = v[(k + 1) % count];
        if (lexicographically_less(p, q) && !on_box_side(&g->box, p, q)) {
            stroke_piece(&g->edge_stroke);
            cli_append(&g->edges, "M%d %dL%d %d", p.x, p.y, q.x, q.y);
        }
    }
}

static void end_cells(drawing_t *g)
{
    stroke_end(&g->edge_stroke);
    cli_append(&g->svg, "</g>\n%s", g->edges.length > 0 ? g->edges.data : "");
    free(g->edges.data);
    g->edges.data = NULL;
}

static void add_sites(drawing_t *g, const vor_point_t *sites, uint32_t n, const uint32_t *duplicate_of)
{
    cli_append(&g->svg, "<g fill=\"#000\">\n");
    for (uint32_t i = 0; i < n; i++) {
        if (duplicate_of == NULL || duplicate_of[i] == i) {
            cli_append(&g->svg, "<circle cx=\"%d\" cy=\"%d\" r=\"%.4g\"/>\n", sites[i].x, sites[i].y, 1.5 * g->unit);
        }
    }
    cli_append(&g->svg, "</g>\n");
}

/* The site ids as labels, each flipped back upright about its own site
 * (y up). */
static void add_ids(drawing_t *g, const vor_point_t *sites, uint32_t n, const uint32_t *duplicate_of)
{
    cli_append(&g->svg, "<g font-family=\"sans-serif\" font-size=\"%.4g\" fill=\"#000\">\n", 10 * g->unit);
    for (uint32_t i = 0; i < n; i++) {
        if (duplicate_of[i] == i) {
            cli_append(&g->svg, "<text transform=\"translate(%d %d)%s\" dx=\"%.4g\">%u</text>\n", sites[i].x,
                       sites[i].y, g->y_down ? "" : " scale(1 -1)", 2 * g->unit, i);
        }
    }
    cli_append(&g->svg, "</g>\n");
}

/* The triangles an iterator yields, thin (the Delaunay or the regular
 * triangulation). */
static void add_triangles(drawing_t *g, vor_triangle_iter_t *t, const vor_point_t *sites)
{
    stroke_t stroke;
    stroke_begin(&stroke, &g->svg, "#1f4fbf", 0.5 * g->unit);
    uint32_t abc[3];
    while (vor_triangles_next(t, abc)) {
        stroke_piece(&stroke);
        cli_append(&g->svg, "M%d %dL%d %dL%d %dZ", sites[abc[0]].x, sites[abc[0]].y, sites[abc[1]].x,
                   sites[abc[1]].y, sites[abc[2]].x, sites[abc[2]].y);
    }
    stroke_end(&stroke);
}

/* Writes the finished picture to path ("-": stdout), only now that
 * everything succeeded, so a failure leaves no partial file. */
static void write_svg(drawing_t *g, const char *path)
{
    cli_append(&g->svg, "</g>\n</svg>\n");
    if (strcmp(path, "-") == 0) {
        cli_flush(&g->svg);
        return;
    }
    FILE *f = cli_create_output(path);
    fwrite(g->svg.data, 1, g->svg.length, f);
    cli_commit_output(f, path); /* a short write is an error there */
    free(g->svg.data);
}

/* The sites' bounding box, grown by a twentieth of its larger side (at
 * least 1), kept inside int32. */
static vor_box_t default_box(const vor_point_t *sites, uint32_t n)
{
    int64_t x0 = sites[0].x, y0 = sites[0].y, x1 = x0, y1 = y0;
    for (uint32_t i = 1; i < n; i++) {
        x0 = sites[i].x < x0 ? sites[i].x : x0;
        x1 = sites[i].x > x1 ? sites[i].x : x1;
        y0 = sites[i].y < y0 ? sites[i].y : y0;
        y1 = sites[i].y > y1 ? sites[i].y : y1;
    }
    int64_t side = (x1 - x0 > y1 - y0) ? x1 - x0 : y1 - y0;
    int64_t margin = side / 20 > 1 ? side / 20 : 1;
    x0 -= margin, y0 -= margin, x1 += margin, y1 += margin;
    vor_box_t box = {(int32_t)(x0 < INT32_MIN ? INT32_MIN : x0), (int32_t)(y0 < INT32_MIN ? INT32_MIN : y0),
                     (int32_t)(x1 > INT32_MAX ? INT32_MAX : x1), (int32_t)(y1 > INT32_MAX ? INT32_MAX : y1)};
    return box;
}

/* The coordinates of vertex v of the constrained triangulation, as text:
 * a site's integers, a crossing's point to a thousandth. */
static void vertex_text(const vor_t *d, const vor_point_t *sites, uint32_t v, char text[64])
{
    uint32_t s[4];
    if ((v >= d->max_sites) && (vor_cdt_crossing(d, v, s) == VOR_OK)) {
        double x, y;
        cli_crossing_point(sites, s, &x, &y);
        snprintf(text, 64, "%.3f %.3f", x, y);
    } else {
        snprintf(text, 64, "%d %d", sites[v].x, sites[v].y);
    }
}

/* The constrained triangulation over the picture (--constraints). */
static void draw_constrained(drawing_t *g, vor_t *d, const vor_point_t *sites, bool domain)
{
    char a[64], b[64], c[64];
    if (domain && (vor_cdt_domain(d) != VOR_OK)) {
        cli_library_error("vor_cdt_domain", VOR_ERR_ARG);
    }
    stroke_t stroke;
    stroke_begin(&stroke, &g->svg, "#1f4fbf", 0.5 * g->unit);
    vor_cdt_triangle_iter_t t;
    (void)(domain ? vor_cdt_inside_begin(&t, d) : vor_cdt_triangles_begin(&t, d));
    uint32_t abc[3];
    if (domain) { /* the inside shaded, then outlined */
        cli_append(&g->svg, "<path fill=\"#000\" fill-opacity=\"0.18\" stroke=\"none\" d=\"");
        while (vor_cdt_triangles_next(&t, abc)) {
            vertex_text(d, sites, abc[0], a);
            vertex_text(d, sites, abc[1], b);
            vertex_text(d, sites, abc[2], c);
            cli_append(&g->svg, "M%sL%sL%sZ", a, b, c);
        }
        cli_append(&g->svg, "\"/>\n");
        (void)vor_cdt_inside_begin(&t, d);
    }
    while (vor_cdt_triangles_next(&t, abc)) {
        vertex_text(d, sites, abc[0], a);
        vertex_text(d, sites, abc[1], b);
        vertex_text(d, sites, abc[2], c);
        stroke_piece(&stroke);
        cli_append(&g->svg, "M%sL%sL%sZ", a, b, c);
    }
    stroke_end(&stroke);
    stroke_begin(&stroke, &g->svg, "#202020", 2.5 * g->unit);
    vor_cdt_edge_iter_t e;
    vor_cdt_edges_begin(&e, d);
    uint32_t u, v;
    while (vor_cdt_edges_next(&e, &u, &v)) {
        vertex_text(d, sites, u, a);
        vertex_text(d, sites, v, b);
        stroke_piece(&stroke);
        cli_append(&g->svg, "M%sL%s", a, b);
    }
    stroke_end(&stroke);
    for (uint32_t i = 0; i < VOR_MAX_SITES - d->max_sites; i++) {
        uint32_t s[4];
        if (vor_cdt_crossing(d, d->max_sites + i, s) != VOR_OK) {
            if (i > 0u && vor_cdt_crossing(d, d->max_sites + i - 1u, s) != VOR_OK) {
                break; /* crossing ids are used from the first up */
            }
            continue;
        }
        double x, y;
        cli_crossing_point(sites, s, &x, &y);
        double r = 2.5 * g->unit;
        cli_append(&g->svg, "<rect x=\"%.3f\" y=\"%.3f\" width=\"%.4g\" height=\"%.4g\" fill=\"#202020\"/>\n",
                   x - r, y - r, 2 * r, 2 * r);
    }
}

static void draw_diagram(drawing_t *g, uint32_t width, uint32_t height, const vor_point_t *sites, uint32_t n,
                         bool triangles, bool ids, bool hull, const char *constraints, bool domain)
{
    uint32_t capacity = n;
    uint32_t *duplicate_of = malloc((size_t)capacity * sizeof *duplicate_of);
    vor_point_t *vertices = malloc((size_t)VOR_CELL_MAX_VERTICES(capacity) * sizeof *vertices);
    if (duplicate_of == NULL || vertices == NULL) {
        cli_error("out of memory");
    }
    vor_t d;
    void *arena = cli_diagram(&d, capacity);
    int err = vor_build(&d, sites, n, NULL, duplicate_of);
    if (err != VOR_OK) {
        cli_library_error("vor_build", err);
    }
    begin_svg(g, width, height);
    vor_cell_iter_t cells;
    vor_cells_begin(&cells, &d, &g->box);
    uint32_t site, count;
    int more;
    while ((more = vor_cells_next(&cells, &site, vertices, VOR_CELL_MAX_VERTICES(capacity), &count)) == 1) {
        add_cell(g, site, vertices, count);
    }
    if (more < 0) {
        cli_error("cell computation failed");
    }
    end_cells(g);
    void *memory = NULL;
    uint32_t (*pairs)[2] = NULL;
    if (constraints != NULL) {
        size_t pair_count;
        uint32_t crossings;
        pairs = cli_read_constraints(constraints, duplicate_of, n, &pair_count);
        memory = cli_constrain_all(&d, capacity, pairs, pair_count, &crossings);
        draw_constrained(g, &d, sites, domain);
    }
    if (triangles && (constraints == NULL)) {
        vor_triangle_iter_t t;
        vor_triangles_begin(&t, &d);
        add_triangles(g, &t, sites);
    }
    if (hull) {
        /* one side a piece, from each hull site to the next, closing at the first */
        stroke_t stroke;
        stroke_begin(&stroke, &g->svg, "#d01010", 1.5 * g->unit);
        vor_hull_iter_t h;
        vor_hull_begin(&h, &d);
        uint32_t first, previous;
        if (vor_hull_next(&h, &first)) {
            previous = first;
            while (vor_hull_next(&h, &site)) {
                stroke_piece(&stroke);
                cli_append(&g->svg, "M%d %dL%d %d", sites[previous].x, sites[previous].y, sites[site].x, sites[site].y);
                previous = site;
            }
            stroke_piece(&stroke);
            cli_append(&g->svg, "M%d %dL%d %d", sites[previous].x, sites[previous].y, sites[first].x, sites[first].y);
        }
        stroke_end(&stroke);
    }
    add_sites(g, sites, n, duplicate_of);
    if (ids) {
        add_ids(g, sites, n, duplicate_of);
    }
    free(pairs);
    free(memory);
    free(vertices);
    free(duplicate_of);
    free(arena);
}

/* sqrt(v) for v >= 1 by Newton's iteration from above (no libm): it
 * decreases until it stops changing, at most about 40 steps for v < 2^63. */
static double square_root(double v)
{
    double x = v, next = 0.5 * (v + 1.0);
    while (next < x) {
        x = next;
        next = 0.5 * (x + v / x);
    }
    return x;
}

/* The power diagram of weighted sites (--power). */
static void draw_power(drawing_t *g, uint32_t width, uint32_t height, const vor_power_t *pd,
                       const cli_weighted_t *ws, bool triangles, bool ids)
{
    const vor_point_t *sites = ws->points;
    uint32_t n = ws->n;
    vor_point_t *vertices = malloc((size_t)VOR_CELL_MAX_VERTICES(n) * sizeof *vertices);
    if (vertices == NULL) {
        cli_error("out of memory");
    }
    begin_svg(g, width, height);
    for (uint32_t i = 0; i < n; i++) {
        uint32_t count;
        if (ws->duplicate_of[i] != i) {
            continue;
        }
        int err = vor_power_cell(pd, i, &g->box, vertices, VOR_CELL_MAX_VERTICES(n), &count);
        if (err != VOR_OK) {
            cli_library_error("vor_power_cell", err);
        }
        add_cell(g, i, vertices, count);
    }
    end_cells(g);
    if (triangles) {
        vor_triangle_iter_t t;
        vor_power_triangles_begin(&t, pd);
        add_triangles(g, &t, sites);
    }
    /* the circles |q - p|^2 = w, and the hidden sites as rings */
    cli_append(&g->svg, "<g fill=\"none\" stroke=\"#404040\" stroke-width=\"%.4g\">\n", 0.5 * g->unit);
    for (uint32_t i = 0; i < n; i++) {
        if (ws->duplicate_of[i] == i && ws->weights[i] > 0) {
            cli_append(&g->svg, "<circle cx=\"%d\" cy=\"%d\" r=\"%.17g\"/>\n", sites[i].x, sites[i].y,
                       square_root((double)ws->weights[i]));
        }
    }
    cli_append(&g->svg, "</g>\n<g fill=\"#fff\" stroke=\"#000\" stroke-width=\"%.4g\">\n", 0.75 * g->unit);
    for (uint32_t i = 0; i < n; i++) {
        if (ws->duplicate_of[i] == i && vor_power_hidden(pd, i) == 1) {
            cli_append(&g->svg, "<circle cx=\"%d\" cy=\"%d\" r=\"%.4g\"/>\n", sites[i].x, sites[i].y,
                       2 * g->unit);
        }
    }
    cli_append(&g->svg, "</g>\n<g fill=\"#000\">\n");
    for (uint32_t i = 0; i < n; i++) {
        if (ws->duplicate_of[i] == i && vor_power_hidden(pd, i) == 0) {
            cli_append(&g->svg, "<circle cx=\"%d\" cy=\"%d\" r=\"%.4g\"/>\n", sites[i].x, sites[i].y,
                       1.5 * g->unit);
        }
    }
    cli_append(&g->svg, "</g>\n");
    if (ids) {
        add_ids(g, sites, n, ws->duplicate_of);
    }
    free(vertices);
}

/* Reads the next int32 of a dump line or fails with the line number. */
static int32_t dump_field(const cli_input_t *in, const char **cursor)
{
    int32_t value;
    const char *why;
    if (!cli_int32_field(cursor, &value, &why)) {
        cli_line_error(in, why);
    }
    return value;
}

static void draw_dump(drawing_t *g, uint32_t width, bool have_size, uint32_t height, const char *path)
{
    cli_input_t in;
    cli_open(&in, path);
    const char *line = cli_next_line(&in);
    if (line == NULL || strncmp(line, "box ", 4) != 0) {
        cli_error("--cells: the dump does not start with a \"box X0 Y0 X1 Y1\" line");
    }
    const char *cursor = line + 4;
    g->box.x0 = dump_field(&in, &cursor);
    g->box.y0 = dump_field(&in, &cursor);
    g->box.x1 = dump_field(&in, &cursor);
    g->box.y1 = dump_field(&in, &cursor);
    if (!cli_at_end(cursor) || g->box.x0 >= g->box.x1 || g->box.y0 >= g->box.y1) {
        cli_line_error(&in, "expected a box X0 Y0 X1 Y1 with X0 < X1 and Y0 < Y1");
    }
    if (!have_size) {
        height = (uint32_t)((double)width * ((double)g->box.y1 - g->box.y0) / ((double)g->box.x1 - g->box.x0) + 0.5);
        height = height < 1 ? 1 : height > MAX_PIXELS ? MAX_PIXELS : height;
    }
    begin_svg(g, width, height);
    vor_point_t *sites = NULL, *vertices = NULL;
    size_t n = 0, site_capacity = 0, vertex_capacity = 0;
    while ((line = cli_next_line(&in)) != NULL) {
        cursor = line + 1;
        if (line[0] == 's' && (line[1] == ' ' || line[1] == '\t')) {
            if (n == site_capacity) {
                site_capacity = site_capacity ? 2 * site_capacity : 1024;
                sites = realloc(sites, site_capacity * sizeof *sites);
                if (sites == NULL) {
                    cli_error("out of memory");
                }
            }
            sites[n].x = dump_field(&in, &cursor);
            sites[n].y = dump_field(&in, &cursor);
            n++;
        } else if (line[0] == 'c' && (line[1] == ' ' || line[1] == '\t')) {
            int32_t site = dump_field(&in, &cursor), count = dump_field(&in, &cursor);
            if (site < 0 || count < 0) {
                cli_line_error(&in, "negative site id or vertex count");
            }
            if ((size_t)count > vertex_capacity) {
                vertex_capacity = (size_t)count;
                vertices = realloc(vertices, vertex_capacity * sizeof *vertices);
                if (vertices == NULL) {
                    cli_error("out of memory");
                }
            }
            for (int32_t k = 0; k < count; k++) {
                vertices[k].x = dump_field(&in, &cursor);
                vertices[k].y = dump_field(&in, &cursor);
            }
            add_cell(g, (uint32_t)site, vertices, (uint32_t)count);
        } else {
            cli_line_error(&in, "expected an \"s X Y\" or \"c I M X1 Y1 ...\" line");
        }
        if (!cli_at_end(cursor)) {
            cli_line_error(&in, "too many fields");
        }
    }
    cli_close(&in);
    end_cells(g);
    add_sites(g, sites, (uint32_t)n, NULL);
    free(vertices);
    free(sites);
}

int cli_draw(int argc, char **argv)
{
    drawing_t g;
    memset(&g, 0, sizeof g);
    bool have_box = false, have_size = false, triangles = false, ids = false, hull = false, domain = false;
    bool power = false;
    const char *constraints = NULL;
    int32_t width = DEFAULT_WIDTH, height = 0;
    const char *sites_path = NULL, *dump_path = NULL, *out_path = NULL;
    enum { BOX, SIZE, TRIANGLES, IDS, HULL, Y_DOWN, CELLS, OUT, CONSTRAINTS, DOMAIN, POWER };
    static const cli_option_t options[] = {
        [BOX] = {"--box", 4}, [SIZE] = {"--size", 2},     [TRIANGLES] = {"--triangles", 0}, [IDS] = {"--ids", 0},
        [HULL] = {"--hull", 0}, [Y_DOWN] = {"--y-down", 0}, [CELLS] = {"--cells", 1},       [OUT] = {"-o", 1},
        [CONSTRAINTS] = {"--constraints", 1}, [DOMAIN] = {"--domain", 0}, [POWER] = {"--power", 0}};
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, "draw", USAGE, options, sizeof options / sizeof options[0]);
    for (int o; (o = cli_next_argument(&args)) != CLI_END;) {
        const char *const *v = args.values;
        if (o == BOX) {
            g.box.x0 = int_argument(v[0], "--box");
            g.box.y0 = int_argument(v[1], "--box");
            g.box.x1 = int_argument(v[2], "--box");
            g.box.y1 = int_argument(v[3], "--box");
            have_box = true;
        } else if (o == SIZE) {
            width = int_argument(v[0], "--size");
            height = int_argument(v[1], "--size");
            if (width < 1 || height < 1 || width > MAX_PIXELS || height > MAX_PIXELS) {
                cli_error("--size: width and height must be 1 to 16384 pixels");
            }
            have_size = true;
        } else if (o == TRIANGLES) {
            triangles = true;
        } else if (o == IDS) {
            ids = true;
        } else if (o == HULL) {
            hull = true;
        } else if (o == Y_DOWN) {
            g.y_down = true;
        } else if (o == CELLS) {
            dump_path = v[0];
        } else if (o == CONSTRAINTS) {
            constraints = v[0];
        } else if (o == DOMAIN) {
            domain = true;
        } else if (o == POWER) {
            power = true;
        } else if (o == OUT) {
            out_path = v[0];
        } else if (sites_path == NULL) {
            sites_path = v[0];
        } else {
            cli_usage_error("draw", USAGE, "unexpected argument", v[0]);
        }
    }
    if (out_path == NULL) {
        cli_usage_error("draw", USAGE, "no output file (-o OUT.svg)", NULL);
    }
    if ((sites_path == NULL) == (dump_path == NULL)) {
        cli_usage_error("draw", USAGE, "give either SITES or --cells DUMP", NULL);
    }
    if (dump_path != NULL) {
        if (have_box || triangles || ids || hull || (constraints != NULL) || domain || power) {
            cli_error("--cells takes its box from the dump and has no triangles, ids, hull, constraints or power");
        }
        draw_dump(&g, (uint32_t)width, have_size, (uint32_t)height, dump_path);
        write_svg(&g, out_path);
        return 0;
    }
    if (domain && (constraints == NULL)) {
        cli_usage_error("draw", USAGE, "--domain needs --constraints FILE", NULL);
    }
    if (have_box && (g.box.x0 >= g.box.x1 || g.box.y0 >= g.box.y1)) {
        cli_error("--box: need X0 < X1 and Y0 < Y1");
    }
    if (power && (hull || (constraints != NULL))) {
        cli_error("--power draws no hull and no constraints");
    }
    uint32_t n;
    vor_power_t pd;
    cli_weighted_t weighted = {NULL, NULL, 0, NULL};
    void *power_arena = NULL;
    vor_point_t *sites;
    if (power) {
        power_arena = cli_power_diagram(sites_path, &pd, &weighted);
        sites = weighted.points;
        n = weighted.n;
    } else {
        sites = cli_read_sites(sites_path, &n);
    }
    if (n == 0) {
        fprintf(stderr, "error: %s: no sites\n", sites_path);
        exit(2);
    }
    if (!have_box) {
        g.box = default_box(sites, n);
    }
    if (!have_size) {
        double aspect = ((double)g.box.y1 - g.box.y0) / ((double)g.box.x1 - g.box.x0);
        double h = (double)width * aspect + 0.5;
        height = h < 1 ? 1 : h > MAX_PIXELS ? MAX_PIXELS : (int32_t)h;
    }
    if (power) {
        draw_power(&g, (uint32_t)width, (uint32_t)height, &pd, &weighted, triangles, ids);
        free(power_arena);
        free(weighted.weights);
        free(weighted.duplicate_of);
    } else {
        draw_diagram(&g, (uint32_t)width, (uint32_t)height, sites, n, triangles, ids, hull, constraints, domain);
    }
    free(sites);
    write_svg(&g, out_path);
    return 0;
}
