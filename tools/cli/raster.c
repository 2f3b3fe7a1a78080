/* SPDX-License-Identifier: MIT */
/*
 * vor raster --size W H --origin OX OY --step SX SY
 *            [--metric euclid|l1|linf|lp:P|ellip:A,B,C|mult|add|comp|farthest|
 *                      hausdorff|segment|polygon|polyline|power]
 *            [--band R] [--scale S] [--nearest K] SITES (--labels OUT.raw |
 *            --png OUT.png [--y-down] [--dots])
 *
 * Renders the exact discrete Voronoi diagram of SITES with vor_raster in
 * bands of R rows (default 16). SITES has one site per line (blank and
 * '#' lines skipped):
 *   euclid, l1, linf, lp, ellip, farthest   x y
 *   mult, add                               x y w       (mult: w >= 1)
 *   comp                                    x y w1 w2   (w1 >= 1)
 *   segment                                 x1 y1 x2 y2
 *   hausdorff, polygon                      x1 y1 [x2 y2 ...] (a point set;
 *                                           a polygon's vertices in order)
 *   polyline                                w x1 y1 [x2 y2 ...] (w >= 1, the
 *                                           vertices in order, open)
 *   power                                   x y w       (w int64, the squared
 *                                           radius: --scale S multiplies it
 *                                           by S^2)
 * --labels writes W*H little-endian uint32 labels, row-major, row 0
 * (j = 0) first, each the index of the pixel's nearest site (farthest for
 * farthest; ties: the smaller index). --png writes an RGB picture, y up
 * (row j = H-1 at the top; --y-down: row j = 0), site i in the colour
 * `vor draw` gives it (cli_site_colour), black boundaries, and with
 * --dots each site's points as black dots (stb_image_write:
 * tools/png_write.h).
 * --nearest K ranks the K nearest sites of every pixel (vor_raster_nearest;
 * farthest first for farthest): --labels writes K uint32 a pixel, nearest
 * first (VOR_RASTER_NO_SITE, 4294967295, past the site count), --png draws
 * each k-set (the set of a pixel's K nearest) in the mean of its sites'
 * colours (RGB565, VOR_RASTER_KSETS) with black boundaries between
 * k-sets.
 * Fields are separated by blanks or commas; --scale S scales coordinates
 * and additive weights (not multiplicative ones), and power weights by
 * S^2. Bad input: "error:
 * FILE:N: reason" or "error: reason", exit 2, and OUT untouched: it is
 * written to a temporary file renamed over OUT at the end.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "vor_raster.h"

#include "../png_write.h"

#define USAGE                                                                                   \
    "usage: vor raster --size W H [--origin OX OY] [--step SX SY] [--metric M] [--band R]\n"      \
    "                  [--scale S] [--nearest K] SITES (--labels OUT.raw | --png OUT.png [--y-down]\n" \
    "                  [--dots])"

const char cli_raster_help[] =
    USAGE "\n"
    "\n"
    "The exact discrete Voronoi diagram of SITES ('-': stdin) on a frame of\n"
    "W x H pixels: pixel (i, j) is the point (OX + i*SX, OY + j*SY) (default\n"
    "origin 0 0, step 1 1); every pixel must have int32 coordinates.\n"
    "\n"
    "input:  one site per line, fields separated by blanks or commas (CSV,\n"
    "        optional header line); blank and '#' lines skipped:\n"
    "          euclid, l1, linf, lp:P, ellip:A,B,C, farthest   x y\n"
    "          mult, add                    x y w        (mult: w >= 1)\n"
    "          comp                         x y w1 w2    (w1 >= 1)\n"
    "          segment                      x1 y1 x2 y2\n"
    "          hausdorff, polygon           x1 y1 [x2 y2 ...]\n"
    "          polyline                     w x1 y1 [x2 y2 ...]  (w >= 1)\n"
    "          power                        x y w        (w int64: a squared radius)\n"
    "        decimal int32 (power weights: int64); with --scale S, coordinates and\n"
    "        additive weights may be decimal numbers (times S, rounded to nearest,\n"
    "        ties away from zero), power weights too (times S^2, as they are\n"
    "        squared lengths); multiplicative weights stay integers. At least\n"
    "        one site.\n"
    "output: --labels: W*H little-endian uint32, row-major, row j = 0 first,\n"
    "        each the index of the pixel's nearest site (farthest for\n"
    "        farthest; ties: the smaller index).\n"
    "        --png: an RGB picture, y up (row j = H-1 at the top), site i in\n"
    "        the colour `vor draw` gives it, black boundaries.\n"
    "  --metric M    euclid (default), l1, linf, lp:P (1 <= P <= 8), ellip:A,B,C\n"
    "                (A > 0, A*C > B^2), mult, add, comp, farthest, hausdorff,\n"
    "                segment, polygon, polyline, power (the power diagram:\n"
    "                |q - s|^2 - w, ties to the smaller index)\n"
    "  --band R      rows rendered per band (default 16)\n"
    "  --nearest K   the K nearest sites of each pixel (1 <= K <= 16; farthest\n"
    "                first for farthest): --labels writes K uint32 a pixel,\n"
    "                nearest first (4294967295 past the site count); --png\n"
    "                colours each k-set (the set of a pixel's K nearest) with\n"
    "                the mean of its sites' colours, black boundaries between\n"
    "                k-sets\n"
    "  --y-down      --png: row j = 0 at the top (screen order)\n"
    "  --dots        --png: each site's points as black dots\n"
    "\n"
    "example:\n"
    "  $ printf '0 0\\n3 1\\n' | vor raster --size 4 2 - --labels out.raw\n"
    "  $ od -An -v -tu4 out.raw\n"
    "          0          0          1          1\n"
    "          0          0          1          1\n";

typedef struct collect {
    uint8_t *frame;
    size_t row_bytes;
} collect_t;

static int collect_band(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    collect_t *c = user;
    memcpy(c->frame + (size_t)first_row * c->row_bytes, pixels, (size_t)rows * c->row_bytes);
    return 0;
}

/* stb's writer callback: errors stay in the FILE's error flag, which
 * cli_commit_output checks. */
static void write_to_file(void *file, void *data, int size)
{
    fwrite(data, 1, (size_t)size, file);
}

static int32_t int_arg(const char *text, const char *what)
{
    const char *cursor = text, *why = NULL;
    int32_t v;
    if (!cli_int32_field(&cursor, &v, &why) || !cli_at_end(cursor)) {
        fprintf(stderr, "error: %s: expected an int32, got '%s'\n", what, text);
        exit(2);
    }
    return v;
}

/* Renders one kind into a whole frame (the host has the memory), with
 * vor_raster (k = 0) or vor_raster_nearest (K = k). */
static uint8_t *render(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
                       enum vor_raster_kind kind, uint32_t band_rows, const uint32_t *palette888,
                       uint32_t k, const uint16_t *palette565)
{
    size_t bytes = VOR_RASTER_NEAREST_PIXEL_BYTES(kind, k);
    collect_t c;
    c.row_bytes = (size_t)frame->width * bytes;
    c.frame = malloc(c.row_bytes * frame->height);
    void *band = malloc(c.row_bytes * band_rows);
    size_t work_bytes = k != 0u ? VOR_RASTER_NEAREST_WORK_BYTES(sites->count, frame->width, k)
                                : VOR_RASTER_WORK_BYTES(sites->count, frame->width);
    void *work = malloc(work_bytes);
    if (c.frame == NULL || band == NULL || work == NULL) {
        cli_error("out of memory");
    }
    vor_raster_output_t out;
    memset(&out, 0, sizeof out);
    out.kind = kind;
    out.band = band;
    out.band_bytes = c.row_bytes * band_rows;
    out.band_rows = band_rows;
    out.flush = collect_band;
    out.user = &c;
    out.palette888 = palette888;
    out.palette565 = palette565;
    int err = k != 0u ? vor_raster_nearest(frame, sites, k, &out, NULL, work, work_bytes)
                      : vor_raster(frame, sites, &out, NULL, work, work_bytes);
    if (err != VOR_OK) {
        cli_library_error(k != 0u ? "vor_raster_nearest" : "vor_raster", err);
    }
    free(work);
    free(band);
    return c.frame;
}

/* The sites of one metric, read from path. Arrays are malloc'd. */
typedef struct site_file {
    vor_point_t *points;
    size_t point_count, point_capacity;
    int32_t *mult, *add;
    int64_t *power;
    uint32_t *offsets;
    size_t count, capacity;
} site_file_t;

static void push_point(site_file_t *f, int32_t x, int32_t y)
{
    if (f->point_count == f->point_capacity) {
        f->point_capacity = f->point_capacity ? 2 * f->point_capacity : 1024;
        f->points = realloc(f->points, f->point_capacity * sizeof *f->points);
        if (f->points == NULL) {
            cli_error("out of memory");
        }
    }
    f->points[f->point_count].x = x;
    f->points[f->point_count].y = y;
    f->point_count++;
}

/* Reads SITES for metric into f and sets up sites (weights, offsets). */
static void read_metric_sites(const char *path, enum vor_metric metric, site_file_t *f)
{
    cli_input_t in;
    cli_open(&in, path);
    const char *line;
    memset(f, 0, sizeof *f);
    while ((line = cli_next_line(&in)) != NULL) {
        const char *cursor = line, *why = "";
        int32_t v[4];
        if (f->count == f->capacity) {
            f->capacity = f->capacity ? 2 * f->capacity : 1024;
            f->mult = realloc(f->mult, f->capacity * sizeof *f->mult);
            f->add = realloc(f->add, f->capacity * sizeof *f->add);
            f->power = realloc(f->power, f->capacity * sizeof *f->power);
            f->offsets = realloc(f->offsets, (f->capacity + 1) * sizeof *f->offsets);
            if (f->mult == NULL || f->add == NULL || f->power == NULL || f->offsets == NULL) {
                cli_error("out of memory");
            }
        }
        if (f->count >= 0x07FFFFFFu || f->point_count >= 0xFFFFFFF0u) {
            cli_line_error(&in, "too many sites");
        }
        f->offsets[f->count] = (uint32_t)f->point_count;
        f->mult[f->count] = 1;
        f->add[f->count] = 0;
        f->power[f->count] = 0;
        int fields = 2;
        const char *shape = "x y";
        if (metric == VOR_METRIC_MULT || metric == VOR_METRIC_ADD) {
            fields = 3;
            shape = "x y w";
        } else if (metric == VOR_METRIC_POWER) {
            fields = 3;
            shape = "x y w";
        } else if (metric == VOR_METRIC_COMPOUND) {
            fields = 4;
            shape = "x y w1 w2";
        } else if (metric == VOR_METRIC_SEGMENT) {
            fields = 4;
            shape = "x1 y1 x2 y2";
        }
        if (metric == VOR_METRIC_HAUSDORFF || metric == VOR_METRIC_POLYGON ||
            metric == VOR_METRIC_POLYLINE) {
            shape = (metric == VOR_METRIC_POLYLINE) ? "w x1 y1 [x2 y2 ...]" : "x1 y1 [x2 y2 ...]";
            char message[300];
            if (metric == VOR_METRIC_POLYLINE) {
                if (!cli_int32_field(&cursor, &v[0], &why)) {
                    snprintf(message, sizeof message, "%s (expected %s)", why, shape);
                    cli_line_error(&in, message);
                }
                if (v[0] < 1) {
                    cli_line_error(&in, "the multiplicative weight must be >= 1");
                }
                f->mult[f->count] = v[0];
            }
            /* pairs until the end of the line, at least one */
            do {
                if (!cli_coordinate_field(&cursor, &v[0], &why) || !cli_coordinate_field(&cursor, &v[1], &why)) {
                    snprintf(message, sizeof message, "%s (expected %s)", why, shape);
                    cli_line_error(&in, message);
                }
                push_point(f, v[0], v[1]);
            } while (!cli_at_end(cursor));
        } else {
            for (int i = 0; i < fields; i++) {
                /* multiplicative weights are ratios: --scale leaves them be;
                 * a power weight is an int64 squared length: times S^2 */
                bool ratio = i == 2 && (metric == VOR_METRIC_MULT || metric == VOR_METRIC_COMPOUND);
                bool squared = i == 2 && metric == VOR_METRIC_POWER;
                bool read = squared ? cli_squared_field(&cursor, &f->power[f->count], &why)
                            : ratio ? cli_int32_field(&cursor, &v[i], &why)
                                    : cli_coordinate_field(&cursor, &v[i], &why);
                if (!read) {
                    char message[300];
                    snprintf(message, sizeof message, "%s (expected %s)", why, shape);
                    cli_line_error(&in, message);
                }
            }
            if (!cli_at_end(cursor)) {
                char message[120];
                snprintf(message, sizeof message, "too many fields (expected %s)", shape);
                cli_line_error(&in, message);
            }
            push_point(f, v[0], v[1]);
            if (metric == VOR_METRIC_SEGMENT) {
                push_point(f, v[2], v[3]);
            } else if (metric == VOR_METRIC_MULT) {
                f->mult[f->count] = v[2];
            } else if (metric == VOR_METRIC_ADD) {
                f->add[f->count] = v[2];
            } else if (metric == VOR_METRIC_COMPOUND) {
                f->mult[f->count] = v[2];
                f->add[f->count] = v[3];
            }
            if ((metric == VOR_METRIC_MULT || metric == VOR_METRIC_COMPOUND) && f->mult[f->count] < 1) {
                cli_line_error(&in, "the multiplicative weight must be >= 1");
            }
        }
        f->count++;
        f->offsets[f->count] = (uint32_t)f->point_count;
    }
    cli_close(&in);
}

/* Parses "A,B,C" of --metric ellip:A,B,C. */
static void parse_form(const char *text, vor_raster_sites_t *sites)
{
    char buffer[120];
    snprintf(buffer, sizeof buffer, "%s", text);
    for (char *c = buffer; *c != '\0'; c++) {
        if (*c == ',') {
            *c = ' ';
        }
    }
    const char *cursor = buffer, *why;
    int32_t v[3];
    for (int i = 0; i < 3; i++) {
        if (!cli_int32_field(&cursor, &v[i], &why)) {
            cli_error("--metric: ellip:A,B,C needs three int32 coefficients");
        }
    }
    if (!cli_at_end(cursor)) {
        cli_error("--metric: ellip:A,B,C needs three int32 coefficients");
    }
    if (v[0] <= 0 || (int64_t)v[0] * v[2] <= (int64_t)v[1] * v[1]) {
        cli_error("--metric: ellip:A,B,C needs A > 0 and A*C > B^2");
    }
    sites->form_a = v[0];
    sites->form_b = v[1];
    sites->form_c = v[2];
}

/* Sets sites->metric (and its parameters) from the --metric argument. */
static void parse_metric(const char *text, vor_raster_sites_t *sites)
{
    static const struct {
        const char *name;
        enum vor_metric metric;
    } names[] = {{"euclid", VOR_METRIC_EUCLID},       {"l1", VOR_METRIC_L1},
                 {"linf", VOR_METRIC_LINF},           {"mult", VOR_METRIC_MULT},
                 {"add", VOR_METRIC_ADD},             {"comp", VOR_METRIC_COMPOUND},
                 {"farthest", VOR_METRIC_FARTHEST},   {"hausdorff", VOR_METRIC_HAUSDORFF},
                 {"segment", VOR_METRIC_SEGMENT},     {"polygon", VOR_METRIC_POLYGON},
                 {"polyline", VOR_METRIC_POLYLINE},   {"power", VOR_METRIC_POWER}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        if (strcmp(text, names[i].name) == 0) {
            sites->metric = names[i].metric;
            return;
        }
    }
    if (strncmp(text, "lp:", 3) == 0) {
        const char *cursor = text + 3, *why;
        int32_t p;
        if (!cli_int32_field(&cursor, &p, &why) || !cli_at_end(cursor) || p < 1 || p > 8) {
            cli_error("--metric: lp:P needs an integer P from 1 to 8");
        }
        sites->metric = VOR_METRIC_LP;
        sites->lp_exponent = (uint32_t)p;
        return;
    }
    if (strncmp(text, "ellip:", 6) == 0) {
        sites->metric = VOR_METRIC_ELLIPTIC;
        parse_form(text + 6, sites);
        return;
    }
    fprintf(stderr, "error: --metric: expected euclid, l1, linf, lp:P, ellip:A,B,C, mult, add, comp, "
                    "farthest, hausdorff, segment, polygon, polyline or power, got '%s'\n", text);
    exit(2);
}

/* Blackens the pixels within 1.5 pixels of each point, as `vor draw`
 * draws its site dots; rgb's row j is the frame's. */
static void draw_dots(uint8_t *rgb, const vor_raster_frame_t *frame, const vor_point_t *points, size_t count)
{
    for (size_t k = 0; k < count; k++) {
        double u = ((double)points[k].x - frame->origin_x) / frame->step_x;
        double v = ((double)points[k].y - frame->origin_y) / frame->step_y;
        if (u < -2.0 || v < -2.0 || u > (double)frame->width + 1.0 || v > (double)frame->height + 1.0) {
            continue;
        }
        /* u and v lie within the frame's pixels give or take 2: int32 */
        for (int32_t j = (int32_t)(v - 1.5) - 1; j <= (int32_t)(v + 1.5) + 1; j++) {
            for (int32_t i = (int32_t)(u - 1.5) - 1; i <= (int32_t)(u + 1.5) + 1; i++) {
                if (i >= 0 && j >= 0 && (uint32_t)i < frame->width && (uint32_t)j < frame->height &&
                    (i - u) * (i - u) + (j - v) * (j - v) <= 2.25) {
                    memset(rgb + 3u * ((size_t)j * frame->width + (size_t)i), 0, 3);
                }
            }
        }
    }
}

/* Every pixel must be an int32 point (vor_raster returns VOR_ERR_ARG
 * otherwise): said here with the pixel that leaves the range. */
static void check_frame(const vor_raster_frame_t *frame)
{
    int64_t last_x = (int64_t)frame->origin_x + (int64_t)(frame->width - 1u) * frame->step_x;
    int64_t last_y = (int64_t)frame->origin_y + (int64_t)(frame->height - 1u) * frame->step_y;
    if (last_x > INT32_MAX || last_y > INT32_MAX) {
        fprintf(stderr,
                "error: --size/--origin/--step: the last pixel (%lld, %lld) is outside the int32 range "
                "(expected OX + (W-1)*SX and OY + (H-1)*SY <= 2147483647)\n",
                (long long)last_x, (long long)last_y);
        exit(2);
    }
}

int cli_raster(int argc, char **argv)
{
    vor_raster_frame_t frame = {0, 0, 1, 1, 0, 0};
    vor_raster_sites_t sites;
    memset(&sites, 0, sizeof sites);
    sites.metric = VOR_METRIC_EUCLID;
    int have_size = 0;
    bool y_down = false, dots = false;
    uint32_t band_rows = 16, nearest = 0;
    const char *sites_path = NULL, *labels_path = NULL, *png_path = NULL;
    enum { SIZE, ORIGIN, STEP, METRIC, BAND, LABELS, PNG, Y_DOWN, DOTS, NEAREST };
    static const cli_option_t options[] = {
        [SIZE] = {"--size", 2},     [ORIGIN] = {"--origin", 2}, [STEP] = {"--step", 2},
        [METRIC] = {"--metric", 1}, [BAND] = {"--band", 1},     [LABELS] = {"--labels", 1},
        [PNG] = {"--png", 1},       [Y_DOWN] = {"--y-down", 0}, [DOTS] = {"--dots", 0},
        [NEAREST] = {"--nearest", 1}};
    cli_arguments_t args;
    cli_arguments_begin(&args, argc, argv, "raster", USAGE, options, sizeof options / sizeof options[0]);
    for (int o; (o = cli_next_argument(&args)) != CLI_END;) {
        const char *const *v = args.values;
        if (o == SIZE) {
            int32_t w = int_arg(v[0], "--size"), h = int_arg(v[1], "--size");
            if (w <= 0 || h <= 0) {
                cli_error("--size: width and height must be positive");
            }
            frame.width = (uint32_t)w;
            frame.height = (uint32_t)h;
            have_size = 1;
        } else if (o == ORIGIN) {
            frame.origin_x = int_arg(v[0], "--origin");
            frame.origin_y = int_arg(v[1], "--origin");
        } else if (o == STEP) {
            frame.step_x = int_arg(v[0], "--step");
            frame.step_y = int_arg(v[1], "--step");
            if (frame.step_x <= 0 || frame.step_y <= 0) {
                cli_error("--step: steps must be positive");
            }
        } else if (o == METRIC) {
            parse_metric(v[0], &sites);
        } else if (o == BAND) {
            int32_t r = int_arg(v[0], "--band");
            if (r <= 0) {
                cli_error("--band: rows must be positive");
            }
            band_rows = (uint32_t)r;
        } else if (o == NEAREST) {
            int32_t k = int_arg(v[0], "--nearest");
            if (k < 1 || k > (int32_t)VOR_RASTER_MAX_NEAREST) {
                cli_error("--nearest: K must be 1 to 16");
            }
            nearest = (uint32_t)k;
        } else if (o == LABELS) {
            labels_path = v[0];
        } else if (o == PNG) {
            png_path = v[0];
        } else if (o == Y_DOWN) {
            y_down = true;
        } else if (o == DOTS) {
            dots = true;
        } else if (sites_path == NULL) {
            sites_path = v[0];
        } else {
            cli_usage_error("raster", USAGE, "unexpected argument", v[0]);
        }
    }
    if (!have_size) {
        cli_usage_error("raster", USAGE, "missing --size W H", NULL);
    }
    if (sites_path == NULL) {
        cli_usage_error("raster", USAGE, "missing SITES", NULL);
    }
    if ((labels_path == NULL) == (png_path == NULL)) {
        cli_usage_error("raster", USAGE, "expected exactly one of --labels OUT.raw and --png OUT.png", NULL);
    }
    if (png_path == NULL && (y_down || dots)) {
        cli_usage_error("raster", USAGE, "--y-down and --dots are options of --png", NULL);
    }
    check_frame(&frame);
    if (band_rows > frame.height) {
        band_rows = frame.height;
    }
    site_file_t file;
    read_metric_sites(sites_path, sites.metric, &file);
    uint32_t n = (uint32_t)file.count;
    if (n == 0u) {
        fprintf(stderr, "error: %s: no sites (a raster needs at least one)\n",
                strcmp(sites_path, "-") == 0 ? "<stdin>" : sites_path);
        exit(2);
    }
    if ((uint64_t)frame.width * frame.height > 0x10000000u) {
        cli_error("--size: frame larger than 2^28 pixels");
    }
    sites.points = file.points;
    sites.count = n;
    sites.mult_weights = file.mult;
    sites.add_weights = file.add;
    sites.power_weights = file.power;
    sites.offsets = file.offsets;
    size_t pixels = (size_t)frame.width * frame.height;
    if (labels_path != NULL) {
        FILE *f = cli_create_output(labels_path);
        enum vor_raster_kind kind = nearest != 0u ? VOR_RASTER_NEAREST : VOR_RASTER_LABEL32;
        uint8_t *labels = render(&frame, &sites, kind, band_rows, NULL, nearest, NULL);
        size_t values = pixels * (nearest != 0u ? nearest : 1u);
        for (size_t p = 0; p < values; p++) { /* little-endian whatever the host */
            uint32_t v;
            memcpy(&v, labels + 4u * p, 4);
            uint8_t le[4] = {(uint8_t)v, (uint8_t)(v >> 8), (uint8_t)(v >> 16), (uint8_t)(v >> 24)};
            fwrite(le, 1, 4, f);
        }
        cli_commit_output(f, labels_path);
        free(labels);
    } else {
        FILE *f = cli_create_output(png_path);
        uint32_t *palette = malloc((size_t)n * sizeof *palette);
        if (palette == NULL) {
            cli_error("out of memory");
        }
        for (uint32_t k = 0; k < n; k++) {
            palette[k] = cli_site_colour(k);
        }
        uint8_t *rgb, *edges = NULL;
        if (nearest != 0u) { /* the k-sets, boundaries black, RGB565 to RGB888 */
            uint16_t *palette565 = malloc((size_t)n * sizeof *palette565);
            rgb = malloc(3u * pixels);
            if (palette565 == NULL || rgb == NULL) {
                cli_error("out of memory");
            }
            for (uint32_t k = 0; k < n; k++) {
                palette565[k] = (uint16_t)(((palette[k] >> 8) & 0xF800u) | ((palette[k] >> 5) & 0x07E0u) |
                                           ((palette[k] >> 3) & 0x001Fu));
            }
            uint8_t *sets = render(&frame, &sites, VOR_RASTER_KSETS, band_rows, NULL, nearest, palette565);
            for (size_t p = 0; p < pixels; p++) {
                uint16_t c;
                memcpy(&c, sets + 2u * p, 2);
                rgb[3u * p] = (uint8_t)(((c >> 11) * 255u + 15u) / 31u);
                rgb[3u * p + 1u] = (uint8_t)((((c >> 5) & 63u) * 255u + 31u) / 63u);
                rgb[3u * p + 2u] = (uint8_t)(((c & 31u) * 255u + 15u) / 31u);
            }
            free(sets);
            free(palette565);
        } else {
            rgb = render(&frame, &sites, VOR_RASTER_RGB888, band_rows, palette, 0, NULL);
            edges = render(&frame, &sites, VOR_RASTER_BOUNDARY, band_rows, NULL, 0, NULL);
            for (size_t p = 0; p < pixels; p++) {
                if (edges[p] != 0u) {
                    rgb[3u * p] = rgb[3u * p + 1u] = rgb[3u * p + 2u] = 0;
                }
            }
        }
        if (dots) {
            draw_dots(rgb, &frame, file.points, file.point_count);
        }
        /* y up, as vor draw and the library: the last row j at the top */
        size_t row_bytes = 3u * (size_t)frame.width;
        for (uint32_t j = 0; !y_down && j < frame.height / 2u; j++) {
            uint8_t *top = rgb + (size_t)j * row_bytes, *bottom = rgb + (size_t)(frame.height - 1u - j) * row_bytes;
            for (size_t b = 0; b < row_bytes; b++) {
                uint8_t t = top[b];
                top[b] = bottom[b];
                bottom[b] = t;
            }
        }
        if (!stbi_write_png_to_func(write_to_file, f, (int)frame.width, (int)frame.height, 3, rgb,
                                    (int)(frame.width * 3u))) {
            cli_error("PNG encoding failed (out of memory?)");
        }
        cli_commit_output(f, png_path);
        free(edges);
        free(rgb);
        free(palette);
    }
    free(file.points);
    free(file.mult);
    free(file.add);
    free(file.power);
    free(file.offsets);
    return 0;
}
