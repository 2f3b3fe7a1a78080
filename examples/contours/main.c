/* SPDX-License-Identifier: MIT */
/*
 * examples/contours - contour-map interpolation (seed 002 chapter 6) on
 * the host: reads contour polylines with heights, draws alpha - 1
 * intermediate contours between each pair of adjacent contours as
 * boundaries of multiplicatively weighted Voronoi diagrams of the
 * contours (VOR_METRIC_POLYLINE with mult_weights), and writes a PNG.
 *
 *   make run-example-contours           sample.txt -> build/contours.png
 *   build/host/example-contours CONTOURS OUT.png [--size W H]
 *       [--origin OX OY] [--step SX SY] [--alpha A] [--labels OUT.txt]
 *
 * CONTOURS (blank and '#' lines skipped): per contour a line
 * "contour HEIGHT" followed by its vertices, one "x y" line each (int32),
 * at least one. A closed contour repeats its first vertex at the end.
 * Contours are taken in increasing height (stable for equal heights);
 * there must be at least two.
 *
 * The rule (docs/design/raster-metrics.md, "Contour interpolation"): a pixel p lies
 * between two adjacent contours c_j and c_(j+1) (of the height order),
 * chosen from its nearest contour c_k (exact, unweighted) and one of
 * c_(k-1), c_(k+1): when c_k is closed, the neighbour on p's side of c_k
 * (inside or outside, by winding number); when both or neither are there
 * (a closed extreme contour: p is beyond the last one, so no pair), or c_k
 * is open, the nearer neighbour (ties: the lower). For i = 1 .. alpha - 1,
 * the pixel's label is the winner of the two-site diagram of c_j with
 * weight i and c_(j+1) with weight alpha - i (ties: c_j): the boundary
 * between them is where d(p, c_j) : d(p, c_(j+1)) = i : (alpha - i), the
 * i-th of the alpha - 1 intermediate contours. A pixel with no pair keeps
 * label k. Boundary pixels: the right or lower neighbour has another label
 * (as VOR_RASTER_BOUNDARY).
 *
 * --labels writes, per i, a line "step i" and H lines of W labels: the
 * check of tests/cli/test_cli.py against an exact Python brute force.
 * The PNG: white, intermediate contours light blue, input contours black.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "vor.h"
#include "vor_raster.h"

#include "../../tools/png_write.h"

#define BAND_ROWS 16u
#define NO_PAIR 0xFFFFFFFFu

static void fail(const char *what)
{
    fprintf(stderr, "error: %s\n", what);
    exit(2);
}

static void *allocate(size_t bytes)
{
    void *p = calloc(bytes > 0u ? bytes : 1u, 1);
    if (p == NULL) {
        fail("out of memory");
    }
    return p;
}

/* ------------------------------------------------------------- input */

typedef struct contour {
    long height;
    uint32_t first, count; /* into the read order's vertex list */
} contour_t;

typedef struct map {
    vor_point_t *points;   /* vertices, contours in height order */
    uint32_t *offsets;     /* [n + 1] */
    uint32_t n;
} map_t;

static void read_map(const char *path, map_t *m)
{
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        fail("cannot open the contour file");
    }
    size_t cap_p = 256, cap_c = 16, np = 0, nc = 0;
    vor_point_t *raw = allocate(cap_p * sizeof *raw);
    contour_t *c = allocate(cap_c * sizeof *c);
    char line[256];
    unsigned long number = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        number++;
        char *s = line;
        while (*s == ' ' || *s == '\t') {
            s++;
        }
        if (*s == '\n' || *s == '\r' || *s == '#' || *s == '\0') {
            continue;
        }
        long a, b;
        char extra;
        if (sscanf(s, "contour %ld %c", &a, &extra) == 1) {
            if (nc == cap_c) {
                cap_c *= 2;
                c = realloc(c, cap_c * sizeof *c);
                if (c == NULL) {
                    fail("out of memory");
                }
            }
            c[nc].height = a;
            c[nc].first = (uint32_t)np;
            c[nc].count = 0;
            nc++;
        } else if (sscanf(s, "%ld %ld %c", &a, &b, &extra) == 2 && nc > 0u &&
                   a >= INT32_MIN && a <= INT32_MAX && b >= INT32_MIN && b <= INT32_MAX) {
            if (np == cap_p) {
                cap_p *= 2;
                raw = realloc(raw, cap_p * sizeof *raw);
                if (raw == NULL) {
                    fail("out of memory");
                }
            }
            raw[np].x = (int32_t)a;
            raw[np].y = (int32_t)b;
            np++;
            c[nc - 1u].count++;
        } else {
            fprintf(stderr, "error: line %lu: expected \"contour HEIGHT\" or \"x y\" (int32) "
                            "after a contour line\n", number);
            exit(2);
        }
    }
    fclose(f);
    if (nc < 2u) {
        fail("at least two contours are needed");
    }
    /* stable insertion sort of the contours by height */
    for (size_t i = 1; i < nc; i++) {
        contour_t t = c[i];
        size_t j = i;
        while (j > 0u && c[j - 1u].height > t.height) {
            c[j] = c[j - 1u];
            j--;
        }
        c[j] = t;
    }
    m->n = (uint32_t)nc;
    m->points = allocate(np * sizeof *m->points);
    m->offsets = allocate((nc + 1u) * sizeof *m->offsets);
    uint32_t at = 0;
    for (size_t k = 0; k < nc; k++) {
        if (c[k].count == 0u) {
            fail("a contour without vertices");
        }
        m->offsets[k] = at;
        for (uint32_t i = 0; i < c[k].count; i++) {
            m->points[at++] = raw[c[k].first + i];
        }
    }
    m->offsets[nc] = at;
    free(raw);
    free(c);
}

/* ------------------------------------------------------------ render */

typedef struct sink {
    uint32_t *labels; /* the full frame */
    uint32_t width;
} sink_t;

static int collect(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    sink_t *s = user;
    memcpy(s->labels + (size_t)first_row * s->width, pixels, (size_t)rows * s->width * 4u);
    return 0;
}

/* Labels of the polyline diagram of sites (weights optional) into
 * labels[width * height], rendered in bands of BAND_ROWS rows. */
static void render(const vor_raster_frame_t *frame, const vor_point_t *points,
                   const uint32_t *offsets, uint32_t count, const int32_t *weights,
                   uint32_t *labels)
{
    vor_raster_sites_t sites = {0};
    sites.metric = VOR_METRIC_POLYLINE;
    sites.points = points;
    sites.offsets = offsets;
    sites.count = count;
    sites.mult_weights = weights;
    static uint32_t *band;
    static void *work;
    static size_t work_bytes;
    if (band == NULL) {
        band = allocate((size_t)BAND_ROWS * frame->width * 4u);
    }
    size_t need = VOR_RASTER_WORK_BYTES(count, frame->width);
    if (need > work_bytes) {
        free(work);
        work = allocate(need); /* malloc's alignment is at least 8 */
        work_bytes = need;
    }
    sink_t sink = {labels, frame->width};
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_LABEL32;
    out.band = band;
    out.band_bytes = (size_t)BAND_ROWS * frame->width * 4u;
    out.band_rows = BAND_ROWS;
    out.flush = collect;
    out.user = &sink;
    int err = vor_raster(frame, &sites, &out, NULL, work, work_bytes);
    if (err != VOR_OK) {
        fprintf(stderr, "error: vor_raster returned %d\n", err);
        exit(2);
    }
}

/* The two-site diagram of contours a and b (weights wa, wb; 0: none). */
static void render_pair(const vor_raster_frame_t *frame, const map_t *m, uint32_t a, uint32_t b,
                        int32_t wa, int32_t wb, vor_point_t *scratch, uint32_t *labels)
{
    uint32_t offsets[3], at = 0;
    uint32_t which[2] = {a, b};
    for (int s = 0; s < 2; s++) {
        offsets[s] = at;
        for (uint32_t i = m->offsets[which[s]]; i < m->offsets[which[s] + 1u]; i++) {
            scratch[at++] = m->points[i];
        }
    }
    offsets[2] = at;
    int32_t weights[2] = {wa, wb};
    render(frame, scratch, offsets, 2, wa > 0 ? weights : NULL, labels);
}

/* Is contour k closed (first vertex repeated at the end, 4+ vertices)? */
static int is_closed(const map_t *m, uint32_t k)
{
    uint32_t first = m->offsets[k], last = m->offsets[k + 1u] - 1u;
    return last >= first + 3u && m->points[first].x == m->points[last].x &&
           m->points[first].y == m->points[last].y;
}

/* Nonzero winding number of closed contour k around q (exact: orient2d). */
static int inside(const map_t *m, uint32_t k, const vor_point_t *q)
{
    long winding = 0;
    for (uint32_t i = m->offsets[k]; i + 1u < m->offsets[k + 1u]; i++) {
        const vor_point_t *a = &m->points[i], *b = &m->points[i + 1u];
        if (a->y <= q->y) {
            if (b->y > q->y && vor_orient2d(*a, *b, *q) > 0) {
                winding++;
            }
        } else if (b->y <= q->y && vor_orient2d(*a, *b, *q) < 0) {
            winding--;
        }
    }
    return winding != 0;
}

/* ---------------------------------------------------------- drawing */

static void plot(uint8_t *rgb, uint32_t w, uint32_t h, long x, long y, uint8_t shade)
{
    if (x >= 0 && y >= 0 && (unsigned long)x < w && (unsigned long)y < h) {
        uint8_t *p = rgb + 3u * ((size_t)y * w + (size_t)x);
        p[0] = p[1] = p[2] = shade;
    }
}

/* The input contours as 1-pixel lines (drawing only: rounded DDA). */
static void draw_contours(const map_t *m, const vor_raster_frame_t *f, uint8_t *rgb)
{
    for (uint32_t k = 0; k < m->n; k++) {
        for (uint32_t i = m->offsets[k]; i < m->offsets[k + 1u]; i++) {
            const vor_point_t *a = &m->points[i];
            const vor_point_t *b = i + 1u < m->offsets[k + 1u] ? &m->points[i + 1u] : a;
            double ax = (double)((long)a->x - f->origin_x) / f->step_x;
            double ay = (double)((long)a->y - f->origin_y) / f->step_y;
            double bx = (double)((long)b->x - f->origin_x) / f->step_x;
            double by = (double)((long)b->y - f->origin_y) / f->step_y;
            double dx = bx - ax, dy = by - ay;
            double len = (dx < 0 ? -dx : dx) > (dy < 0 ? -dy : dy) ? (dx < 0 ? -dx : dx)
                                                                    : (dy < 0 ? -dy : dy);
            long steps = (long)len + 1;
            for (long s = 0; s <= steps; s++) {
                double t = (double)s / (double)steps;
                plot(rgb, f->width, f->height, (long)(ax + t * dx + 0.5), (long)(ay + t * dy + 0.5), 0);
            }
        }
    }
}

/* -------------------------------------------------------------- main */

static long number_arg(char **argv, int at, int argc)
{
    if (at >= argc) {
        fail("an option is missing its value");
    }
    char *end;
    long v = strtol(argv[at], &end, 10);
    if (*end != '\0' || end == argv[at] || v < INT32_MIN || v > INT32_MAX) {
        fail("an option's value is not an int32");
    }
    return v;
}

int main(int argc, char **argv)
{
    const char *in_path = "examples/contours/sample.txt", *png_path = "build/contours.png";
    const char *labels_path = NULL;
    vor_raster_frame_t frame = {0, 0, 1, 1, 256, 256};
    long alpha = 4;
    int positional = 0;
    for (int a = 1; a < argc; a++) {
        if (strcmp(argv[a], "--size") == 0) {
            long w = number_arg(argv, a + 1, argc), h = number_arg(argv, a + 2, argc);
            if (w < 1 || h < 1 || w * h > (1L << 26)) {
                fail("--size: W and H from 1, at most 2^26 pixels");
            }
            frame.width = (uint32_t)w;
            frame.height = (uint32_t)h;
            a += 2;
        } else if (strcmp(argv[a], "--origin") == 0) {
            frame.origin_x = (int32_t)number_arg(argv, a + 1, argc);
            frame.origin_y = (int32_t)number_arg(argv, a + 2, argc);
            a += 2;
        } else if (strcmp(argv[a], "--step") == 0) {
            frame.step_x = (int32_t)number_arg(argv, a + 1, argc);
            frame.step_y = (int32_t)number_arg(argv, a + 2, argc);
            a += 2;
        } else if (strcmp(argv[a], "--alpha") == 0) {
            alpha = number_arg(argv, a + 1, argc);
            if (alpha < 2 || alpha > 256) {
                fail("--alpha: from 2 to 256");
            }
            a++;
        } else if (strcmp(argv[a], "--labels") == 0 && a + 1 < argc) {
            labels_path = argv[++a];
        } else if (argv[a][0] != '-' && positional < 2) {
            if (positional++ == 0) {
                in_path = argv[a];
            } else {
                png_path = argv[a];
            }
        } else {
            fail("usage: example-contours [CONTOURS [OUT.png]] [--size W H] [--origin OX OY] "
                 "[--step SX SY] [--alpha A] [--labels OUT.txt]");
        }
    }
    map_t m;
    read_map(in_path, &m);
    size_t pixels = (size_t)frame.width * frame.height;
    uint32_t *near = allocate(pixels * 4u), *pair = allocate(pixels * 4u);
    uint32_t *label = allocate(pixels * 4u), *two = allocate(pixels * 4u);
    vor_point_t *scratch = allocate((size_t)m.offsets[m.n] * sizeof *scratch);

    /* 1. the nearest contour of every pixel (unweighted) */
    render(&frame, m.points, m.offsets, m.n, NULL, near);

    /* 2. the pair (j, j + 1) bracketing each pixel, by its lower index j */
    for (uint32_t k = 0; k < m.n; k++) {
        int has_lower = k > 0u, has_upper = k + 1u < m.n;
        int closed = is_closed(&m, k);
        int lower_side = 0, upper_side = 0;
        if (closed && has_lower) {
            lower_side = inside(&m, k, &m.points[m.offsets[k - 1u]]);
        }
        if (closed && has_upper) {
            upper_side = inside(&m, k, &m.points[m.offsets[k + 1u]]);
        }
        if (has_lower && has_upper) {
            render_pair(&frame, &m, k - 1u, k + 1u, 0, 0, scratch, two); /* the nearer neighbour */
        }
        for (size_t p = 0; p < pixels; p++) {
            if (near[p] != k) {
                continue;
            }
            int take_lower = has_lower, take_upper = has_upper;
            if (closed) {
                vor_point_t q;
                q.x = (int32_t)(frame.origin_x + (long)(p % frame.width) * frame.step_x);
                q.y = (int32_t)(frame.origin_y + (long)(p / frame.width) * frame.step_y);
                int side = inside(&m, k, &q);
                take_lower = has_lower && lower_side == side;
                take_upper = has_upper && upper_side == side;
                if (!take_lower && !take_upper && has_lower && has_upper) {
                    take_lower = take_upper = 1; /* neither on p's side: the nearer */
                } else if (!take_lower && !take_upper) {
                    pair[p] = NO_PAIR; /* beyond an extreme closed contour */
                    continue;
                }
            }
            if (take_lower && take_upper) {
                take_lower = two[p] == 0u;
            }
            pair[p] = take_lower ? k - 1u : k;
        }
    }

    /* 3. per step i, the pairwise weighted diagrams and their boundaries */
    uint8_t *rgb = allocate(pixels * 3u);
    memset(rgb, 255, pixels * 3u);
    FILE *dump = NULL;
    if (labels_path != NULL && (dump = fopen(labels_path, "w")) == NULL) {
        fail("cannot write the labels file");
    }
    for (long i = 1; i < alpha; i++) {
        for (size_t p = 0; p < pixels; p++) {
            label[p] = near[p]; /* pixels without a pair keep their contour */
        }
        for (uint32_t j = 0; j + 1u < m.n; j++) {
            /* d(p, c_j) / i against d(p, c_(j+1)) / (alpha - i): they are
             * equal where d(p, c_j) : d(p, c_(j+1)) = i : (alpha - i) */
            render_pair(&frame, &m, j, j + 1u, (int32_t)i, (int32_t)(alpha - i), scratch, two);
            for (size_t p = 0; p < pixels; p++) {
                if (pair[p] == j) {
                    label[p] = j + two[p];
                }
            }
        }
        for (uint32_t y = 0; y < frame.height; y++) {
            for (uint32_t x = 0; x < frame.width; x++) {
                size_t p = (size_t)y * frame.width + x;
                int edge = (x + 1u < frame.width && label[p + 1u] != label[p]) ||
                           (y + 1u < frame.height && label[p + frame.width] != label[p]);
                if (edge) {
                    rgb[3u * p] = 150;
                    rgb[3u * p + 1u] = 185;
                    rgb[3u * p + 2u] = 235;
                }
            }
        }
        if (dump != NULL) {
            fprintf(dump, "step %ld\n", i);
            for (uint32_t y = 0; y < frame.height; y++) {
                for (uint32_t x = 0; x < frame.width; x++) {
                    fprintf(dump, x + 1u < frame.width ? "%u " : "%u\n",
                            (unsigned)label[(size_t)y * frame.width + x]);
                }
            }
        }
    }
    if (dump != NULL && fclose(dump) != 0) {
        fail("cannot write the labels file");
    }
    draw_contours(&m, &frame, rgb);
    /* row 0 is the frame's lowest y: written last, so the map shows y up
     * like every picture of the vor tool */
    stbi_flip_vertically_on_write(1);
    if (!stbi_write_png(png_path, (int)frame.width, (int)frame.height, 3, rgb, (int)frame.width * 3)) {
        fail("cannot write the PNG");
    }
    printf("contours: %u, alpha %ld: %s\n", (unsigned)m.n, alpha, png_path);
    return 0;
}
