/* SPDX-License-Identifier: MIT */
/*
 * test_raster_metrics.c - vor_raster with every metric but Euclidean
 * point sites, against the brute-force reference of raster_reference.c
 * (ref_nearest_metric: its own arithmetic and formulas), pixel by pixel
 * and area by area, with both methods (culled and brute force) and
 * several band heights; random and adversarial inputs per metric (sites on
 * pixel centres, exact ties, equal weights, duplicates, zero-length
 * segments, degenerate and overlapping polygons, the full int32 range,
 * power weights over all of int64, hidden power sites);
 * a culling pool too small for the tiles; and the metric errors.
 */
#include "raster_reference.h"
#include "test.h"
#include "vor_raster.h"

#define MAX_W 40u
#define MAX_H 36u
#define MAX_PIXELS 1440u
#define MAX_SITES 40u
#define MAX_POINTS 160u

static vor_point_t points[MAX_POINTS];
static int32_t mult[MAX_SITES], add[MAX_SITES];
static int64_t power[MAX_SITES];
static uint32_t offsets[MAX_SITES + 1u];
static uint32_t expect_label[MAX_PIXELS];
static uint32_t expect_distance[MAX_PIXELS];
static uint32_t frame_labels[MAX_PIXELS];
static uint8_t band_memory[MAX_PIXELS * 4u] __attribute__((aligned(8)));
static uint8_t work[VOR_RASTER_WORK_BYTES(MAX_SITES, 400u)] __attribute__((aligned(8)));
static uint32_t areas[MAX_SITES];

static const char *const metric_names[] = {"euclid", "l1",       "linf",      "lp",
                                           "ellip",  "mult",     "add",       "comp",
                                           "farthest", "hausdorff", "segment", "polygon",
                                           "polyline", "power"};

typedef struct capture {
    uint32_t next_row;
    uint32_t width;
    int bad;
    int boundary;
} capture_t;

static int capture_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    capture_t *c = user;
    if (first_row != c->next_row) {
        c->bad = 1;
        return 0;
    }
    for (uint32_t p = 0; p < rows * c->width; p++) {
        frame_labels[first_row * c->width + p] =
            c->boundary ? ((const uint8_t *)pixels)[p] : ((const uint32_t *)pixels)[p];
    }
    c->next_row = first_row + rows;
    return 0;
}

/* One render of kind LABEL32, BOUNDARY or DISTANCE, compared with the
 * reference (expect_distance: the reference's distances). */
static void render_and_compare(const char *name, const vor_raster_frame_t *f,
                               const vor_raster_sites_t *set, enum vor_raster_method method,
                               uint32_t band_rows, enum vor_raster_kind kind)
{
    int boundary = kind == VOR_RASTER_BOUNDARY;
    capture_t cap = {0, f->width, 0, boundary};
    vor_raster_output_t out = {0};
    out.kind = kind;
    out.band = band_memory;
    out.band_bytes = (size_t)f->width * band_rows * (boundary ? 1u : 4u);
    out.band_rows = band_rows;
    out.flush = capture_flush;
    out.user = &cap;
    out.areas = areas;
    vor_raster_options_t options = {method, 0};
    for (uint32_t k = 0; k < set->count; k++) {
        areas[k] = 0xDEADu;
    }
    /* exactly the documented work memory */
    int err = vor_raster(f, set, &out, &options, work, VOR_RASTER_WORK_BYTES(set->count, f->width));
    const char *how = method == VOR_RASTER_FAST ? "fast" : "brute";
    const char *metric = metric_names[set->metric];
    if (!CHECK(err == VOR_OK && !cap.bad && cap.next_row == f->height,
               "%s %s %s rows %u: err %d", metric, name, how, band_rows, err)) {
        return;
    }
    uint32_t wrong = 0, w = f->width;
    for (uint32_t j = 0; j < f->height; j++) {
        for (uint32_t i = 0; i < w; i++) {
            uint32_t label = expect_label[j * w + i];
            uint32_t want = label;
            if (boundary) {
                want = (i + 1u < w && expect_label[j * w + i + 1u] != label) ||
                       (j + 1u < f->height && expect_label[(j + 1u) * w + i] != label);
            } else if (kind == VOR_RASTER_DISTANCE) {
                want = expect_distance[j * w + i];
            }
            uint32_t got = frame_labels[j * w + i];
            if (want != got && wrong++ < 3u) {
                CHECK(false, "%s %s %s rows %u: pixel (%u, %u) = %u, reference %u", metric, name,
                      how, band_rows, i, j, got, want);
            }
        }
    }
    CHECK(wrong == 0, "%s %s %s rows %u%s: %u pixels wrong", metric, name, how, band_rows,
          boundary ? " boundary" : kind == VOR_RASTER_DISTANCE ? " distance" : "", wrong);
    uint32_t bad_area = 0;
    for (uint32_t k = 0; k < set->count; k++) {
        uint32_t count = 0;
        for (uint32_t p = 0; p < w * f->height; p++) {
            count += expect_label[p] == k;
        }
        bad_area += count != areas[k];
    }
    CHECK(bad_area == 0, "%s %s %s: %u areas wrong", metric, name, how, bad_area);
}

static uint32_t case_number;

/* Every pixel's reference distance to its reference site. */
static void reference_distances(const vor_raster_frame_t *f, const vor_raster_sites_t *set)
{
    for (uint32_t j = 0; j < f->height; j++) {
        for (uint32_t i = 0; i < f->width; i++) {
            uint32_t p = j * f->width + i;
            expect_distance[p] =
                ref_distance_metric(set, expect_label[p], ref_centre_x(f, i), ref_centre_y(f, j));
        }
    }
}

/* Set by a case that must check distances at every frame (adversarial
 * values); otherwise every other frame does (the reference is slow). */
static int always_distance;

/* The reference labels, then the fast and brute renders (and DISTANCE). */
static void check_frame(const char *name, const vor_raster_frame_t *f,
                        const vor_raster_sites_t *set)
{
    int undecided = 0;
    for (uint32_t j = 0; j < f->height; j++) {
        for (uint32_t i = 0; i < f->width; i++) {
            expect_label[j * f->width + i] =
                ref_nearest_metric(set, ref_centre_x(f, i), ref_centre_y(f, j), &undecided);
        }
    }
    CHECK(!undecided, "%s %s: the reference could not decide a comparison",
          metric_names[set->metric], name);
    static const uint32_t band_heights[] = {1, 5, 16, 36};
    case_number++;
    uint32_t rows = band_heights[case_number % 4u];
    render_and_compare(name, f, set, VOR_RASTER_FAST, rows, VOR_RASTER_LABEL32);
    render_and_compare(name, f, set, VOR_RASTER_BRUTE, band_heights[(case_number + 1u) % 4u],
                       VOR_RASTER_LABEL32);
    if (case_number % 3u == 0u) {
        render_and_compare(name, f, set, VOR_RASTER_FAST, band_heights[(case_number + 2u) % 4u],
                           VOR_RASTER_BOUNDARY);
    }
    if (always_distance || case_number % 2u == 0u) {
        reference_distances(f, set);
        render_and_compare(name, f, set, case_number % 4u < 2u ? VOR_RASTER_FAST : VOR_RASTER_BRUTE,
                           band_heights[(case_number + 3u) % 4u], VOR_RASTER_DISTANCE);
    }
}

static vor_raster_sites_t point_set(enum vor_metric metric, uint32_t n)
{
    vor_raster_sites_t set = {0};
    set.metric = metric;
    set.points = points;
    set.count = n;
    set.mult_weights = mult;
    set.add_weights = add;
    set.power_weights = power;
    set.offsets = offsets;
    set.lp_exponent = 3;
    set.form_a = 2;
    set.form_b = 1;
    set.form_c = 3;
    return set;
}

/* n random points in the frame's box widened by margin. */
static void random_points(test_rng_t *rng, const vor_raster_frame_t *f, uint32_t n, int32_t margin)
{
    for (uint32_t k = 0; k < n; k++) {
        points[k].x = f->origin_x + test_rng_range(rng, -margin, (int32_t)f->width * f->step_x + margin);
        points[k].y = f->origin_y + test_rng_range(rng, -margin, (int32_t)f->height * f->step_y + margin);
    }
}

/* Pixel centres only, with repeats. */
static void centre_points(test_rng_t *rng, const vor_raster_frame_t *f, uint32_t n)
{
    for (uint32_t k = 0; k < n; k++) {
        points[k].x = ref_centre_x(f, (uint32_t)test_rng_range(rng, 0, (int32_t)f->width - 1));
        points[k].y = ref_centre_y(f, (uint32_t)test_rng_range(rng, 0, (int32_t)f->height - 1));
    }
}

static void random_frame(test_rng_t *rng, vor_raster_frame_t *f)
{
    uint32_t w = 8u + test_rng_u32(rng) % 27u, h = 6u + test_rng_u32(rng) % 23u;
    *f = ref_frame(test_rng_range(rng, -60, 60), test_rng_range(rng, -60, 60),
                    1 + (int32_t)(test_rng_u32(rng) % 3u), 1 + (int32_t)(test_rng_u32(rng) % 3u),
                    w, h);
}

/* ------------------------------------------------------- point metrics */

static void point_metric_cases(test_rng_t *rng)
{
    static const enum vor_metric metrics[] = {VOR_METRIC_L1,       VOR_METRIC_LINF,
                                              VOR_METRIC_LP,       VOR_METRIC_ELLIPTIC,
                                              VOR_METRIC_MULT,     VOR_METRIC_ADD,
                                              VOR_METRIC_COMPOUND, VOR_METRIC_FARTHEST};
    vor_raster_frame_t f;
    for (unsigned m = 0; m < sizeof metrics / sizeof metrics[0]; m++) {
        for (uint32_t round = 0; round < 3u; round++) {
            random_frame(rng, &f);
            uint32_t n = 1u + test_rng_u32(rng) % 24u;
            random_points(rng, &f, n, 30);
            for (uint32_t k = 0; k < n; k++) {
                mult[k] = 1 + test_rng_range(rng, 0, 6);
                add[k] = test_rng_range(rng, -15, 15);
            }
            vor_raster_sites_t set = point_set(metrics[m], n);
            set.lp_exponent = 3u + round;
            set.form_b = test_rng_range(rng, -3, 3);
            set.form_a = 1 + test_rng_range(rng, 0, 4);
            set.form_c = (set.form_b * set.form_b) / set.form_a + 1 + test_rng_range(rng, 0, 3);
            check_frame("random", &f, &set);

            /* on pixel centres, with duplicates and equal weights */
            centre_points(rng, &f, n);
            for (uint32_t k = 0; k < n; k++) {
                mult[k] = 1 + (int32_t)(k % 2u);
                add[k] = 3 * (int32_t)(k % 3u);
            }
            if (n > 2u) {
                points[n - 1u] = points[0];
                mult[n - 1u] = mult[0];
                add[n - 1u] = add[0];
            }
            check_frame("centres", &f, &set);
        }
    }

    /* Lp for every exponent, 1 (= L1) and 2 (= Euclid) included */
    f = ref_frame(-5, -4, 1, 1, 31, 23);
    for (uint32_t p = 1; p <= 8u; p++) {
        random_points(rng, &f, 20, 10);
        vor_raster_sites_t set = point_set(VOR_METRIC_LP, 20);
        set.lp_exponent = p;
        check_frame("exponent", &f, &set);
    }
    /* a lattice: ties along the diagonals and at cell corners */
    uint32_t n = 0;
    for (int32_t y = 0; y <= 36; y += 6) {
        for (int32_t x = 0; x <= 40; x += 10) {
            points[n].x = x;
            points[n].y = y;
            mult[n] = 2;
            add[n] = 5;
            n++;
        }
    }
    f = ref_frame(0, 0, 1, 1, 40, 36);
    static const enum vor_metric lattice[] = {VOR_METRIC_L1, VOR_METRIC_LINF, VOR_METRIC_LP,
                                              VOR_METRIC_ELLIPTIC, VOR_METRIC_MULT, VOR_METRIC_ADD,
                                              VOR_METRIC_COMPOUND, VOR_METRIC_FARTHEST};
    for (unsigned m = 0; m < sizeof lattice / sizeof lattice[0]; m++) {
        vor_raster_sites_t set = point_set(lattice[m], n);
        set.form_a = 1;
        set.form_b = 0;
        set.form_c = 1;
        check_frame("lattice", &f, &set);
    }
}

/* Exact ties of weighted distances on pixel centres: 3-4-5 triangles
 * make sqrt(D) integers, so d - w and d / w tie exactly. */
static void weighted_tie_cases(test_rng_t *rng)
{
    vor_raster_frame_t f = ref_frame(-20, -20, 1, 1, 40, 36);
    /* additive: |q - a| - wa = |q - b| - wb at the pixels where the
     * difference of distances is wa - wb; sites at integer distances */
    static const int32_t xs[] = {0, 3, -4, 0, 12, -5, 8, 0};
    static const int32_t ys[] = {0, 4, 3, -5, 5, 12, -6, 10};
    for (uint32_t k = 0; k < 8u; k++) {
        points[k].x = xs[k];
        points[k].y = ys[k];
        add[k] = (int32_t)(k % 3u) * 5;
        mult[k] = 1 + (int32_t)(k % 2u);
    }
    vor_raster_sites_t set = point_set(VOR_METRIC_ADD, 8);
    check_frame("ties", &f, &set);
    set.metric = VOR_METRIC_MULT;
    check_frame("ties", &f, &set);
    set.metric = VOR_METRIC_COMPOUND;
    check_frame("ties", &f, &set);
    /* weights that swallow sites: one weight beats every distance */
    random_points(rng, &f, 16, 10);
    for (uint32_t k = 0; k < 16u; k++) {
        add[k] = test_rng_range(rng, -3, 3);
        mult[k] = 1 + test_rng_range(rng, 0, 2);
    }
    add[7] = 60;
    mult[9] = 50;
    set = point_set(VOR_METRIC_ADD, 16);
    check_frame("dominant", &f, &set);
    set.metric = VOR_METRIC_MULT;
    check_frame("dominant", &f, &set);
    set.metric = VOR_METRIC_COMPOUND;
    check_frame("dominant", &f, &set);
    /* negative additive weights and weights equal everywhere */
    for (uint32_t k = 0; k < 16u; k++) {
        add[k] = -7;
        mult[k] = 3;
    }
    set.metric = VOR_METRIC_ADD;
    check_frame("equal-weights", &f, &set);
    set.metric = VOR_METRIC_COMPOUND;
    check_frame("equal-weights", &f, &set);
}

/* --------------------------------------------------------- shaped sites */

static void hausdorff_cases(test_rng_t *rng)
{
    vor_raster_frame_t f;
    for (uint32_t round = 0; round < 4u; round++) {
        random_frame(rng, &f);
        uint32_t n = 1u + test_rng_u32(rng) % 16u, at = 0;
        for (uint32_t k = 0; k < n; k++) {
            offsets[k] = at;
            uint32_t size = 1u + test_rng_u32(rng) % 4u;
            int32_t cx = ref_centre_x(&f, test_rng_u32(rng) % f.width);
            int32_t cy = ref_centre_y(&f, test_rng_u32(rng) % f.height);
            for (uint32_t i = 0; i < size; i++) {
                points[at].x = cx + test_rng_range(rng, -12, 12);
                points[at].y = cy + test_rng_range(rng, -12, 12);
                at++;
            }
        }
        offsets[n] = at;
        vor_raster_sites_t set = point_set(VOR_METRIC_HAUSDORFF, n);
        check_frame(round % 2u ? "random" : "random-b", &f, &set);
    }
    /* single points (= farthest-free Euclid) and mirrored pairs: ties */
    f = ref_frame(0, 0, 1, 1, 33, 30);
    for (uint32_t k = 0; k < 10u; k++) {
        offsets[k] = 2u * k;
        int32_t x = test_rng_range(rng, 0, 32), y = test_rng_range(rng, 0, 29);
        points[2u * k].x = x;
        points[2u * k].y = y;
        points[2u * k + 1u].x = 32 - x;
        points[2u * k + 1u].y = 29 - y;
    }
    offsets[10] = 20;
    vor_raster_sites_t set = point_set(VOR_METRIC_HAUSDORFF, 10);
    check_frame("mirrored", &f, &set);
}

static void segment_cases(test_rng_t *rng)
{
    vor_raster_frame_t f;
    for (uint32_t round = 0; round < 4u; round++) {
        random_frame(rng, &f);
        uint32_t n = 1u + test_rng_u32(rng) % 20u;
        random_points(rng, &f, 2u * n, 20);
        vor_raster_sites_t set = point_set(VOR_METRIC_SEGMENT, n);
        check_frame("random", &f, &set);
    }
    /* zero-length, shared ends, collinear overlaps, axis-parallel, on
     * pixel centres */
    f = ref_frame(0, 0, 1, 1, 40, 36);
    static const int32_t s[][4] = {
        {5, 5, 5, 5},     {5, 5, 20, 5},   {20, 5, 20, 25}, {10, 5, 30, 5},  {0, 30, 39, 30},
        {39, 30, 0, 30},  {3, 12, 12, 21}, {12, 21, 3, 12}, {30, 10, 36, 4}, {25, 18, 25, 18},
        {-40, 0, 80, 36}, {15, 15, 16, 16}};
    for (uint32_t k = 0; k < 12u; k++) {
        points[2u * k].x = s[k][0];
        points[2u * k].y = s[k][1];
        points[2u * k + 1u].x = s[k][2];
        points[2u * k + 1u].y = s[k][3];
    }
    vor_raster_sites_t set = point_set(VOR_METRIC_SEGMENT, 12);
    check_frame("degenerate", &f, &set);
    /* a grid of unit segments: equal distances everywhere */
    uint32_t n = 0;
    for (int32_t y = 2; y < 36 && n < MAX_SITES; y += 7) {
        for (int32_t x = 2; x < 40 && n < MAX_SITES; x += 9) {
            points[2u * n].x = x;
            points[2u * n].y = y;
            points[2u * n + 1u].x = x + (int32_t)(n % 2u) * 3;
            points[2u * n + 1u].y = y + (int32_t)((n + 1u) % 2u) * 3;
            n++;
        }
    }
    set.count = n;
    check_frame("grid", &f, &set);
}

static void polygon_cases(test_rng_t *rng)
{
    vor_raster_frame_t f;
    for (uint32_t round = 0; round < 4u; round++) {
        random_frame(rng, &f);
        uint32_t n = 1u + test_rng_u32(rng) % 12u, at = 0;
        for (uint32_t k = 0; k < n; k++) {
            offsets[k] = at;
            uint32_t size = 1u + test_rng_u32(rng) % 6u; /* 1 .. 6 vertices, any shape */
            int32_t cx = ref_centre_x(&f, test_rng_u32(rng) % f.width);
            int32_t cy = ref_centre_y(&f, test_rng_u32(rng) % f.height);
            for (uint32_t i = 0; i < size; i++) {
                points[at].x = cx + test_rng_range(rng, -10, 10);
                points[at].y = cy + test_rng_range(rng, -10, 10);
                at++;
            }
        }
        offsets[n] = at;
        vor_raster_sites_t set = point_set(VOR_METRIC_POLYGON, n);
        check_frame("random", &f, &set);
    }
    /* squares overlapping (ties at 0 go to the smaller index), nested,
     * clockwise and counterclockwise; a bowtie; a collinear triangle; a
     * polygon with repeated vertices; a point; a segment */
    f = ref_frame(0, 0, 1, 1, 40, 36);
    static const int32_t v[] = {
        /* site 0: square, counterclockwise */ 4, 4, 16, 4, 16, 16, 4, 16,
        /* site 1: overlapping square, clockwise */ 10, 10, 10, 22, 22, 22, 22, 10,
        /* site 2: nested inside site 1 */ 12, 12, 14, 12, 14, 14,
        /* site 3: bowtie */ 26, 2, 38, 14, 38, 2, 26, 14,
        /* site 4: collinear triangle */ 2, 30, 10, 30, 20, 30,
        /* site 5: repeated vertices */ 30, 20, 30, 20, 36, 26, 36, 26, 30, 32,
        /* site 6: a point */ 24, 30,
        /* site 7: a segment */ 0, 35, 39, 35,
        /* site 8: a concave polygon with a pocket */ 20, 24, 28, 24, 28, 34, 24, 28, 20, 34};
    static const uint32_t sizes[] = {4, 4, 3, 4, 3, 5, 1, 2, 5};
    uint32_t at = 0;
    for (uint32_t i = 0; i < sizeof v / sizeof v[0] / 2u; i++) {
        points[i].x = v[2u * i];
        points[i].y = v[2u * i + 1u];
    }
    for (uint32_t k = 0; k < 9u; k++) {
        offsets[k] = at;
        at += sizes[k];
    }
    offsets[9] = at;
    vor_raster_sites_t set = point_set(VOR_METRIC_POLYGON, 9);
    check_frame("shapes", &f, &set);
    /* the frame inside one polygon: every pixel at distance 0 */
    f = ref_frame(6, 6, 1, 1, 9, 9);
    check_frame("inside", &f, &set);
}

/* Weighted polylines (contour interpolation, seed 002 chapter 6): random
 * ones with and without weights; nested closed curves and open ones with
 * the ratios 1 : 3, 2 : 2, 3 : 1 whose boundaries pass through pixel
 * centres (exact ties); a point and repeated vertices. */
static void polyline_cases(test_rng_t *rng)
{
    vor_raster_frame_t f;
    for (uint32_t round = 0; round < 6u; round++) {
        random_frame(rng, &f);
        uint32_t n = 1u + test_rng_u32(rng) % 10u, at = 0;
        for (uint32_t k = 0; k < n; k++) {
            offsets[k] = at;
            uint32_t size = 1u + test_rng_u32(rng) % 8u;
            int32_t x = ref_centre_x(&f, test_rng_u32(rng) % f.width);
            int32_t y = ref_centre_y(&f, test_rng_u32(rng) % f.height);
            for (uint32_t i = 0; i < size; i++) {
                points[at].x = x;
                points[at].y = y;
                x += test_rng_range(rng, -12, 12);
                y += test_rng_range(rng, -12, 12);
                at++;
            }
            mult[k] = 1 + (int32_t)(test_rng_u32(rng) % 7u);
        }
        offsets[n] = at;
        vor_raster_sites_t set = point_set(VOR_METRIC_POLYLINE, n);
        if (round % 3u == 2u) {
            set.mult_weights = NULL;
        }
        check_frame("random", &f, &set);
    }
    /* nested squares 2 .. 37 and 14 .. 25 (closed by repeating the first
     * vertex), a horizontal open line, a point, a repeated vertex */
    f = ref_frame(0, 0, 1, 1, 40, 36);
    static const int32_t v[] = {
        /* site 0 */ 2, 2, 37, 2, 37, 33, 2, 33, 2, 2,
        /* site 1 */ 14, 14, 25, 14, 25, 25, 14, 25, 14, 14,
        /* site 2 */ 18, 18,
        /* site 3 */ 0, 35, 20, 35, 20, 35, 39, 35};
    static const uint32_t sizes[] = {5, 5, 1, 4};
    for (uint32_t i = 0; i < sizeof v / sizeof v[0] / 2u; i++) {
        points[i].x = v[2u * i];
        points[i].y = v[2u * i + 1u];
    }
    uint32_t at = 0;
    for (uint32_t k = 0; k < 4u; k++) {
        offsets[k] = at;
        at += sizes[k];
    }
    offsets[4] = at;
    vor_raster_sites_t set = point_set(VOR_METRIC_POLYLINE, 4);
    static const int32_t ratios[][4] = {{1, 3, 2, 1}, {2, 2, 1, 5}, {3, 1, 4, 4}, {6, 2, 1, 3}};
    for (uint32_t r = 0; r < 4u; r++) {
        for (uint32_t k = 0; k < 4u; k++) {
            mult[k] = ratios[r][k];
        }
        check_frame("nested", &f, &set);
    }
    /* only the two squares: the interpolation's pairwise diagram */
    set.count = 2;
    mult[0] = 1;
    mult[1] = 3;
    check_frame("pair", &f, &set);
}

/* ----------------------------------------------- huge and overflowing */

/* Coordinates and weights over the whole int32 range: the widest
 * comparisons of every metric. */
static void huge_cases(test_rng_t *rng)
{
    vor_raster_frame_t f = ref_frame(INT32_MIN, INT32_MIN, 390451572, 477218588, 12, 10);
    static const enum vor_metric metrics[] = {
        VOR_METRIC_L1,       VOR_METRIC_LINF,     VOR_METRIC_LP,       VOR_METRIC_ELLIPTIC,
        VOR_METRIC_MULT,     VOR_METRIC_ADD,      VOR_METRIC_COMPOUND, VOR_METRIC_FARTHEST,
        VOR_METRIC_HAUSDORFF, VOR_METRIC_SEGMENT, VOR_METRIC_POLYGON, VOR_METRIC_POLYLINE,
        VOR_METRIC_POWER};
    for (unsigned m = 0; m < sizeof metrics / sizeof metrics[0]; m++) {
        uint32_t n = 12;
        for (uint32_t k = 0; k < 3u * n; k++) {
            points[k].x = (int32_t)test_rng_u32(rng);
            points[k].y = (int32_t)test_rng_u32(rng);
        }
        points[0].x = INT32_MAX;
        points[0].y = INT32_MIN;
        points[1].x = INT32_MIN;
        points[1].y = INT32_MAX;
        for (uint32_t k = 0; k < n; k++) {
            mult[k] = (int32_t)(test_rng_u32(rng) >> 1) | 1;
            add[k] = (int32_t)test_rng_u32(rng);
            offsets[k] = 3u * k;
        }
        for (uint32_t k = 0; k < n; k++) {
            /* int64 weights, some within a few squared distances of each other */
            power[k] = (int64_t)(((uint64_t)test_rng_u32(rng) << 32) | test_rng_u32(rng));
        }
        power[5] = INT64_MIN;
        power[6] = INT64_MAX;
        power[7] = (int64_t)1 << 62;
        power[8] = INT64_MAX - (int64_t)test_rng_u32(rng);
        mult[2] = INT32_MAX;
        add[3] = INT32_MIN;
        add[4] = INT32_MAX;
        offsets[n] = 3u * n;
        vor_raster_sites_t set = point_set(metrics[m], n);
        set.lp_exponent = 8;
        set.form_a = INT32_MAX;
        set.form_b = -2147483000;
        set.form_c = INT32_MAX;
        check_frame("huge", &f, &set);
    }
    /* weights large against small distances: the compound comparison's
     * widest terms in a small frame */
    f = ref_frame(-10, -10, 1, 1, 24, 20);
    random_points(rng, &f, 10, 5);
    for (uint32_t k = 0; k < 10u; k++) {
        mult[k] = (int32_t)(test_rng_u32(rng) >> 1) | 1;
        add[k] = (int32_t)(test_rng_u32(rng) >> 20) - 2048;
    }
    vor_raster_sites_t set = point_set(VOR_METRIC_COMPOUND, 10);
    check_frame("heavy", &f, &set);
}

/* ------------------------------------------------- distance values */

static uint32_t one_pixel;

static int one_pixel_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    (void)user;
    (void)first_row;
    (void)rows;
    one_pixel = *(const uint32_t *)pixels;
    return 0;
}

/* The DISTANCE value of site 0 (the only one) at the single pixel (qx, qy). */
static uint32_t distance_at(const vor_raster_sites_t *set, int32_t qx, int32_t qy)
{
    vor_raster_frame_t f = ref_frame(qx, qy, 1, 1, 1, 1);
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_DISTANCE;
    out.band = band_memory;
    out.band_bytes = 4;
    out.band_rows = 1;
    out.flush = one_pixel_flush;
    one_pixel = 0xDEADBEEFu;
    int err = vor_raster(&f, set, &out, NULL, work, sizeof work);
    return err == VOR_OK ? one_pixel : 0xDEADBEEFu;
}

/* Values worked out by hand (and the saturation points): the pixel
 * (3, 4) against a site at the origin, |q - s| = 5. */
static void distance_value_cases(void)
{
    static const struct {
        enum vor_metric metric;
        uint32_t p;                /* LP exponent */
        int32_t a, b, c;           /* ELLIPTIC form */
        int32_t w1, w2;            /* weights */
        int32_t sx, sy, qx, qy;    /* site and pixel */
        uint32_t want;
    } cases[] = {
        {VOR_METRIC_L1, 3, 1, 0, 1, 1, 0, 0, 0, 3, 4, 7},
        {VOR_METRIC_LINF, 3, 1, 0, 1, 1, 0, 0, 0, 3, 4, 4},
        {VOR_METRIC_LP, 1, 1, 0, 1, 1, 0, 0, 0, 3, 4, 7},
        {VOR_METRIC_LP, 2, 1, 0, 1, 1, 0, 0, 0, 3, 4, 5},
        {VOR_METRIC_LP, 3, 1, 0, 1, 1, 0, 0, 0, 3, 4, 4},            /* 91^(1/3) = 4.50 */
        {VOR_METRIC_ELLIPTIC, 3, 1, 0, 1, 1, 0, 0, 0, 3, 4, 5},
        {VOR_METRIC_ELLIPTIC, 3, 2, 1, 3, 1, 0, 0, 0, 3, 4, 9},      /* sqrt(90) */
        {VOR_METRIC_MULT, 3, 1, 0, 1, 2, 0, 0, 0, 3, 4, 2},          /* 2.5 */
        {VOR_METRIC_MULT, 3, 1, 0, 1, 5, 0, 0, 0, 3, 4, 1},          /* exactly 1 */
        {VOR_METRIC_ADD, 3, 1, 0, 1, 1, 7, 0, 0, 3, 4, 0xFFFFFFFEu}, /* -2 */
        {VOR_METRIC_ADD, 3, 1, 0, 1, 1, -3, 0, 0, 3, 4, 8},
        {VOR_METRIC_COMPOUND, 3, 1, 0, 1, 2, -1, 0, 0, 3, 4, 3},     /* 3.5 */
        {VOR_METRIC_COMPOUND, 3, 1, 0, 1, 2, 3, 0, 0, 3, 4, 0xFFFFFFFFu}, /* floor(-0.5) */
        {VOR_METRIC_FARTHEST, 3, 1, 0, 1, 1, 0, 0, 0, 3, 4, 5},
        {VOR_METRIC_HAUSDORFF, 3, 1, 0, 1, 1, 0, 0, 0, 3, 4, 5},
        /* on the site */
        {VOR_METRIC_ADD, 3, 1, 0, 1, 1, 9, 7, 7, 7, 7, 0xFFFFFFF7u},
        {VOR_METRIC_LP, 8, 1, 0, 1, 1, 0, 7, 7, 7, 7, 0},
        /* saturation and the largest exact values */
        {VOR_METRIC_L1, 3, 1, 0, 1, 1, 0, INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX, 0xFFFFFFFFu},
        {VOR_METRIC_L1, 3, 1, 0, 1, 1, 0, INT32_MIN, 0, INT32_MAX, 0, 0xFFFFFFFFu},
        {VOR_METRIC_LINF, 3, 1, 0, 1, 1, 0, INT32_MIN, 5, INT32_MAX, 0, 0xFFFFFFFFu},
        {VOR_METRIC_LP, 8, 1, 0, 1, 1, 0, INT32_MIN, INT32_MIN, 0, 0, 2341847523u},
        {VOR_METRIC_LP, 8, 1, 0, 1, 1, 0, INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX, 0xFFFFFFFFu},
        {VOR_METRIC_LP, 8, 1, 0, 1, 1, 0, INT32_MIN, 0, INT32_MAX, 0, 0xFFFFFFFFu},
        {VOR_METRIC_LP, 3, 1, 0, 1, 1, 0, INT32_MIN, 0, INT32_MAX, 0, 0xFFFFFFFFu},
        {VOR_METRIC_FARTHEST, 3, 1, 0, 1, 1, 0, INT32_MIN, 0, INT32_MAX, 0, 0xFFFFFFFFu},
        {VOR_METRIC_FARTHEST, 3, 1, 0, 1, 1, 0, INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX,
         0xFFFFFFFFu},
        {VOR_METRIC_MULT, 3, 1, 0, 1, 2, 0, INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX,
         3037000499u}, /* floor((2^32 - 1) sqrt(2) / 2) */
        {VOR_METRIC_ELLIPTIC, 3, INT32_MAX, -2147483000, INT32_MAX, 1, 0, 0, 0, 1000, 1000, 35972},
        {VOR_METRIC_ELLIPTIC, 3, INT32_MAX, -2147483000, INT32_MAX, 1, 0, INT32_MIN, INT32_MAX,
         INT32_MAX, INT32_MIN, 0xFFFFFFFFu},
        {VOR_METRIC_ADD, 3, 1, 0, 1, 1, INT32_MIN, 0, 0, 0, 0, 0x7FFFFFFFu},
        {VOR_METRIC_ADD, 3, 1, 0, 1, 1, INT32_MAX, 0, 0, 0, 0, 0x80000001u},
        {VOR_METRIC_ADD, 3, 1, 0, 1, 1, -1, INT32_MIN, 0, INT32_MAX, 0, 0x7FFFFFFFu},
        {VOR_METRIC_COMPOUND, 3, 1, 0, 1, INT32_MAX, INT32_MIN, 0, 0, 0, 0, 0x7FFFFFFFu},
        {VOR_METRIC_COMPOUND, 3, 1, 0, 1, 3, INT32_MAX, INT32_MIN, 0, INT32_MAX, 0,
         0xD5555556u}, /* floor((2^32 - 1) / 3) - (2^31 - 1) = -715827882 */
    };
    for (uint32_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        points[0].x = cases[c].sx;
        points[0].y = cases[c].sy;
        mult[0] = cases[c].w1;
        add[0] = cases[c].w2;
        offsets[0] = 0;
        offsets[1] = 1;
        vor_raster_sites_t set = point_set(cases[c].metric, 1);
        set.lp_exponent = cases[c].p;
        set.form_a = cases[c].a;
        set.form_b = cases[c].b;
        set.form_c = cases[c].c;
        uint32_t got = distance_at(&set, cases[c].qx, cases[c].qy);
        uint32_t ref = ref_distance_metric(&set, 0, cases[c].qx, cases[c].qy);
        CHECK(got == cases[c].want && ref == cases[c].want,
              "distance value %u (%s): %u, reference %u, by hand %u", c,
              metric_names[cases[c].metric], got, ref, cases[c].want);
    }
    /* shaped sites: a segment (0, 0)-(10, 0), the polyline of it weighted
     * 3, a square around the pixel (inside: 0), a point polygon */
    static const vor_point_t shapes[] = {{0, 0}, {10, 0}, {-1, -1}, {9, -1}, {9, 9}, {-1, 9}};
    for (uint32_t i = 0; i < 6u; i++) {
        points[i] = shapes[i];
    }
    vor_raster_sites_t set = point_set(VOR_METRIC_SEGMENT, 1);
    CHECK(distance_at(&set, 3, 4) == 4u, "distance value: segment");
    CHECK(distance_at(&set, 13, 4) == 5u, "distance value: segment end");
    set.metric = VOR_METRIC_POLYLINE;
    offsets[0] = 0;
    offsets[1] = 2;
    mult[0] = 3;
    CHECK(distance_at(&set, 3, 4) == 1u, "distance value: weighted polyline 4 / 3");
    CHECK(distance_at(&set, -6, -8) == 3u, "distance value: weighted polyline 10 / 3");
    set.metric = VOR_METRIC_POLYGON;
    offsets[0] = 2;
    offsets[1] = 6;
    CHECK(distance_at(&set, 3, 4) == 0u, "distance value: inside a polygon");
    CHECK(distance_at(&set, 9, 4) == 0u, "distance value: on a polygon's edge");
    CHECK(distance_at(&set, 12, 13) == 5u, "distance value: outside a polygon (3-4-5)");
    /* power: D - w, exact, clamped to int32 */
    static const struct {
        int32_t sx, sy, qx, qy;
        int64_t w;
        uint32_t want;
    } powers[] = {
        {0, 0, 3, 4, 0, 25u},
        {0, 0, 3, 4, 30, 0xFFFFFFFBu},               /* -5 */
        {0, 0, 3, 4, -100, 125u},
        {7, 7, 7, 7, INT64_MIN, 0x7FFFFFFFu},
        {7, 7, 7, 7, INT64_MAX, 0x80000000u},
        {7, 7, 7, 7, (int64_t)1 << 31, 0x80000000u}, /* exactly -2^31 */
        {7, 7, 7, 7, ((int64_t)1 << 31) - 1, 0x80000001u},
        {0, 0, 46341, 0, 0, 0x7FFFFFFFu},           /* 2147488281 clamped */
        {0, 0, 46340, 0, -88048, 0x7FFFFFFFu},      /* 2147395600 + 88048 = 2^31 */
        {0, 0, 46340, 0, -88047, 0x7FFFFFFFu},      /* 2^31 - 1 exactly */
        {0, 0, 46340, 0, -88046, 0x7FFFFFFEu},
        {INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX, INT64_MAX, 0x7FFFFFFFu}, /* 2^65 - ... */
        {INT32_MIN, 0, INT32_MAX, 0, INT64_MAX, 0x7FFFFFFFu}, /* (2^32 - 1)^2 - (2^63 - 1) */
        {INT32_MIN, 0, 0, 0, INT64_MAX, 0x80000000u},         /* 2^62 - 2^63 + 1 */
    };
    for (uint32_t c = 0; c < sizeof powers / sizeof powers[0]; c++) {
        points[0].x = powers[c].sx;
        points[0].y = powers[c].sy;
        power[0] = powers[c].w;
        vor_raster_sites_t pset = point_set(VOR_METRIC_POWER, 1);
        uint32_t got = distance_at(&pset, powers[c].qx, powers[c].qy);
        uint32_t ref = ref_distance_metric(&pset, 0, powers[c].qx, powers[c].qy);
        CHECK(got == powers[c].want && ref == powers[c].want,
              "power distance value %u: %u, reference %u, by hand %u", c, got, ref, powers[c].want);
    }
    /* a slanted segment: the perpendicular distance 7 sqrt(2) / 2 = 4.95 */
    points[0].x = 0;
    points[0].y = 0;
    points[1].x = 10;
    points[1].y = 10;
    set = point_set(VOR_METRIC_SEGMENT, 1);
    CHECK(distance_at(&set, 1, 8) == 4u, "distance value: slanted segment");
}

/* A wide frame with few sites that all stay candidates everywhere: the
 * pool of the documented work memory cannot list every tile, and tiles
 * fall back to all sites. */
static void pool_overflow_case(void)
{
    vor_raster_frame_t f = ref_frame(0, 0, 1, 1, 400, 3);
    vor_raster_sites_t set = point_set(VOR_METRIC_L1, 3);
    for (uint32_t k = 0; k < 3u; k++) {
        points[k].x = 200;
        points[k].y = 100000 + (int32_t)k; /* far away: bounds overlap */
    }
    check_frame("pool", &f, &set);
    set.metric = VOR_METRIC_FARTHEST;
    check_frame("pool", &f, &set);
}

static int quiet_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    (void)first_row;
    (void)rows;
    (void)pixels;
    (*(uint32_t *)user)++;
    return 0;
}

static void error_cases(void)
{
    vor_raster_frame_t f = ref_frame(0, 0, 1, 1, 10, 10);
    for (uint32_t k = 0; k < 8u; k++) {
        points[k].x = (int32_t)k;
        points[k].y = (int32_t)(k * 3u % 7u);
        mult[k] = 1;
        add[k] = 0;
        offsets[k] = k;
    }
    offsets[8] = 8;
    uint32_t flushes = 0;
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_LABEL8;
    out.band = band_memory;
    out.band_bytes = 100;
    out.band_rows = 10;
    out.flush = quiet_flush;
    out.user = &flushes;
    size_t bytes = VOR_RASTER_WORK_BYTES(8, 10);
    for (int m = VOR_METRIC_L1; m <= VOR_METRIC_POWER; m++) {
        vor_raster_sites_t set = point_set((enum vor_metric)m, 4);
        CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_OK, "errors %s: valid base",
              metric_names[m]);
        vor_raster_output_t d = out;
        d.kind = VOR_RASTER_DISTANCE;
        d.band_bytes = 400;
        CHECK(vor_raster(&f, &set, &d, NULL, work, bytes) == VOR_OK, "errors %s: DISTANCE kind",
              metric_names[m]);
        set.points = NULL;
        CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors %s: NULL points",
              metric_names[m]);
        set.points = points;
        CHECK(vor_raster(&f, &set, &out, NULL, work, VOR_RASTER_WORK_BYTES(4, 10) - 1u) ==
                  VOR_ERR_NOMEM,
              "errors %s: small work", metric_names[m]);
    }
    flushes = 0;
    vor_raster_sites_t set = point_set(VOR_METRIC_LP, 4);
    set.lp_exponent = 0;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: p = 0");
    set.lp_exponent = 9;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: p = 9");
    set.lp_exponent = 8;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_OK, "errors: p = 8");
    flushes = 0;
    set = point_set(VOR_METRIC_ELLIPTIC, 4);
    set.form_a = 0;
    set.form_b = 0;
    set.form_c = 1;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: a = 0");
    set.form_a = 2;
    set.form_b = 2;
    set.form_c = 2;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: ac = b^2");
    set.form_a = -1;
    set.form_b = 0;
    set.form_c = -1;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: negative definite");
    set.form_a = INT32_MAX;
    set.form_b = INT32_MIN;
    set.form_c = INT32_MAX;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: b = INT32_MIN");
    set = point_set(VOR_METRIC_MULT, 4);
    mult[2] = 0;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: weight 0");
    set.metric = VOR_METRIC_COMPOUND;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: compound weight 0");
    mult[2] = -5;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: negative weight");
    mult[2] = 1;
    set.add_weights = NULL;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: compound without w2");
    set.metric = VOR_METRIC_ADD;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: add without weights");
    set.add_weights = add;
    set.mult_weights = NULL;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_OK, "errors: add needs no w1");
    flushes = 0;
    set.metric = VOR_METRIC_MULT;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: mult without weights");
    set = point_set(VOR_METRIC_POLYGON, 4);
    offsets[2] = offsets[1];
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: empty polygon");
    set.metric = VOR_METRIC_HAUSDORFF;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: empty point set");
    set.metric = VOR_METRIC_POLYLINE;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: empty polyline");
    offsets[2] = 2;
    mult[3] = 0;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: polyline weight 0");
    set.mult_weights = NULL;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_OK, "errors: polyline needs no weights");
    flushes = 0;
    mult[3] = 1;
    set.offsets = NULL;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: no offsets");
    set = point_set(VOR_METRIC_POWER, 4);
    set.power_weights = NULL;
    for (uint32_t k = 0; k < 4u; k++) {
        areas[k] = 0xA5A5u + k;
    }
    for (size_t b = 0; b < 100u; b++) {
        band_memory[b] = (uint8_t)(b ^ 0x5Au);
    }
    vor_raster_output_t counted = out;
    counted.areas = areas;
    CHECK(vor_raster(&f, &set, &counted, NULL, work, bytes) == VOR_ERR_ARG,
          "errors: power without weights");
    uint32_t touched = 0;
    for (uint32_t k = 0; k < 4u; k++) {
        touched += areas[k] != 0xA5A5u + k;
    }
    for (size_t b = 0; b < 100u; b++) {
        touched += band_memory[b] != (uint8_t)(b ^ 0x5Au);
    }
    CHECK(touched == 0, "errors: power without weights wrote %u words", touched);
    set.power_weights = power;
    set.mult_weights = NULL; /* power uses no other weights */
    set.add_weights = NULL;
    power[0] = INT64_MIN;
    power[1] = INT64_MAX;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_OK, "errors: power, any int64");
    flushes = 0;
    set.metric = (enum vor_metric)14;
    CHECK(vor_raster(&f, &set, &out, NULL, work, bytes) == VOR_ERR_ARG, "errors: metric 14");
    CHECK(flushes == 0, "errors: a failed call flushed %u bands", flushes);
}

/* ------------------------------------------------------------- power */

/* The pixels the reference gives site k (after check_frame). */
static uint32_t reference_area(const vor_raster_frame_t *f, uint32_t k)
{
    uint32_t count = 0;
    for (uint32_t p = 0; p < f->width * f->height; p++) {
        count += expect_label[p] == k;
    }
    return count;
}

/* Power diagrams (VOR_METRIC_POWER): random weights, equal weights (the
 * Euclidean labels of ref_nearest, a reference of its own), hidden sites,
 * coincident sites, exact ties, int64 extremes, every band height. */
static void power_cases(test_rng_t *rng)
{
    vor_raster_frame_t f;
    for (uint32_t round = 0; round < 6u; round++) {
        random_frame(rng, &f);
        uint32_t n = 1u + test_rng_u32(rng) % 30u;
        random_points(rng, &f, n, 20);
        int32_t spread = (round < 3u) ? 100 : 3000; /* 3000: many hidden sites */
        for (uint32_t k = 0; k < n; k++) {
            power[k] = test_rng_range(rng, -spread, spread);
        }
        vor_raster_sites_t set = point_set(VOR_METRIC_POWER, n);
        check_frame("random", &f, &set);
        /* on pixel centres, coincident with other weights */
        centre_points(rng, &f, n);
        for (uint32_t k = 0; k + 1u < n; k += 2u) {
            points[k + 1u] = points[k];
            power[k + 1u] = power[k] + test_rng_range(rng, -2, 2);
        }
        check_frame("coincident", &f, &set);
    }

    /* equal weights: exactly the Euclidean labels, whatever the weight */
    static const int64_t equal[] = {0, -7, 123456789, (int64_t)1 << 62, INT64_MAX, INT64_MIN};
    f = ref_frame(-13, -9, 1, 1, 37, 31);
    for (unsigned e = 0; e < sizeof equal / sizeof equal[0]; e++) {
        uint32_t n = 25;
        centre_points(rng, &f, n / 2u); /* duplicates and ties */
        for (uint32_t k = n / 2u; k < n; k++) {
            points[k].x = test_rng_range(rng, -20, 30);
            points[k].y = test_rng_range(rng, -15, 25);
        }
        for (uint32_t k = 0; k < n; k++) {
            power[k] = equal[e];
        }
        vor_raster_sites_t set = point_set(VOR_METRIC_POWER, n);
        for (uint32_t j = 0; j < f.height; j++) {
            for (uint32_t i = 0; i < f.width; i++) {
                expect_label[j * f.width + i] = ref_nearest(&set, ref_centre_x(&f, i), ref_centre_y(&f, j));
            }
        }
        render_and_compare("equal-weights", &f, &set, VOR_RASTER_FAST, 1u + e * 7u, VOR_RASTER_LABEL32);
        render_and_compare("equal-weights", &f, &set, VOR_RASTER_BRUTE, 16, VOR_RASTER_LABEL32);
    }

    /* a heavy site hides light ones: site 3 at the centre, squared radius
     * 40000, owns the pixels of the light sites around it (empty cells) */
    f = ref_frame(0, 0, 2, 2, 30, 30);
    static const int32_t ring[][2] = {{28, 30}, {32, 30}, {30, 26}, {30, 30}, {30, 35}, {25, 25}, {36, 34}, {100, 100}};
    for (uint32_t k = 0; k < 8u; k++) {
        points[k].x = ring[k][0];
        points[k].y = ring[k][1];
        power[k] = (k == 3u) ? 40000 : (int64_t)k;
    }
    power[7] = 45000; /* far away and heavier: owns the far corner */
    {
        vor_raster_sites_t set = point_set(VOR_METRIC_POWER, 8);
        check_frame("hidden", &f, &set);
        uint32_t hidden = 0;
        for (uint32_t k = 0; k < 7u; k++) {
            hidden += (k != 3u) && reference_area(&f, k) == 0u;
        }
        CHECK(hidden == 6u && reference_area(&f, 7) > 0u && reference_area(&f, 3) > 0u,
              "power hidden: %u of 6 light sites hidden", hidden);
    }

    /* exact ties: sites (0, 0) w 0 and (10, 0) w 100 - 20 x0 have the
     * bisector x = x0, a column of pixel centres; the smaller index takes
     * it, in both orders */
    f = ref_frame(-5, -6, 1, 1, 22, 13);
    for (int32_t x0 = -3; x0 <= 14; x0 += 4) {
        for (uint32_t order = 0; order < 2u; order++) {
            uint32_t a = order, b = 1u - order;
            points[a].x = 0;
            points[a].y = 0;
            power[a] = 0;
            points[b].x = 10;
            points[b].y = 0;
            power[b] = 100 - 20 * (int64_t)x0;
            points[2].x = 5;
            points[2].y = 40; /* a third site, far and light */
            power[2] = -1000;
            vor_raster_sites_t set = point_set(VOR_METRIC_POWER, 3);
            check_frame("tie column", &f, &set);
            uint32_t column = (uint32_t)(x0 + 5), wrong = 0;
            for (uint32_t j = 0; j < f.height; j++) {
                wrong += expect_label[j * f.width + column] != 0u;
            }
            CHECK(wrong == 0, "power tie column x = %d: %u pixels not to index 0", x0, wrong);
        }
    }
    /* a small lattice with small weights: ties everywhere */
    f = ref_frame(0, 0, 1, 1, 24, 20);
    for (uint32_t k = 0; k < 30u; k++) {
        points[k].x = 4 * (int32_t)(k % 6u);
        points[k].y = 4 * (int32_t)(k / 6u);
        power[k] = 4 * (int64_t)(k % 3u);
    }
    {
        vor_raster_sites_t set = point_set(VOR_METRIC_POWER, 30);
        check_frame("lattice", &f, &set);
    }

    /* weights near 2^62 and the int64 ends, differing by squared pixel
     * distances, so the differences decide the labels */
    static const int64_t bases[] = {(int64_t)1 << 62, INT64_MAX - 5000, INT64_MIN + 5000,
                                    -((int64_t)1 << 62)};
    f = ref_frame(-10, -10, 1, 1, 21, 21);
    for (unsigned b = 0; b < sizeof bases / sizeof bases[0]; b++) {
        random_points(rng, &f, 12, 5);
        for (uint32_t k = 0; k < 12u; k++) {
            power[k] = bases[b] + test_rng_range(rng, -400, 400);
        }
        vor_raster_sites_t set = point_set(VOR_METRIC_POWER, 12);
        check_frame("int64 ends", &f, &set);
    }
    /* the ends against each other: INT64_MAX owns everything, INT64_MIN
     * nothing; far corners with weights 0 against 2^62 */
    f = ref_frame(INT32_MIN, INT32_MIN, 429496729, 429496729, 11, 11);
    points[0].x = INT32_MAX;
    points[0].y = INT32_MAX;
    power[0] = INT64_MIN;
    points[1].x = INT32_MIN;
    points[1].y = INT32_MIN;
    power[1] = 0;
    points[2].x = 0;
    points[2].y = 0;
    power[2] = (int64_t)1 << 62;
    points[3].x = INT32_MAX;
    points[3].y = INT32_MIN;
    power[3] = INT64_MAX;
    {
        vor_raster_sites_t set = point_set(VOR_METRIC_POWER, 3);
        check_frame("int32 corners", &f, &set);
        set.count = 4;
        check_frame("int32 corners", &f, &set);
        /* D + 2^63 >= 2^63 > 2^62 >= D - 2^62 of site 2 (D <= 2^63) */
        CHECK(reference_area(&f, 0) == 0u, "power: the INT64_MIN site owns no pixel");
    }

    /* every band height on one frame */
    f = ref_frame(-7, 3, 1, 2, 23, 19);
    random_points(rng, &f, 20, 4);
    for (uint32_t k = 0; k < 20u; k++) {
        power[k] = test_rng_range(rng, -300, 300);
    }
    vor_raster_sites_t set = point_set(VOR_METRIC_POWER, 20);
    check_frame("bands", &f, &set);
    for (uint32_t rows = 1; rows <= f.height; rows++) {
        render_and_compare("bands", &f, &set, VOR_RASTER_FAST, rows,
                           (rows % 3u == 0u) ? VOR_RASTER_BOUNDARY : VOR_RASTER_LABEL32);
    }
}

/* One site and a frame 480 pixels wide: the documented work memory's
 * pool (12 n + 16 words) holds no count word per 16-column tile (30
 * tiles), so the tiles widen (32 columns); every pixel is the site's. */
static void wide_tiles_case(void)
{
    vor_raster_frame_t f = ref_frame(-240, 0, 1, 1, 480, 3);
    typedef char fits[(VOR_RASTER_WORK_BYTES(1, 480) <= sizeof work && 480u * 3u <= MAX_PIXELS) ? 1 : -1];
    (void)sizeof(fits);
    static const enum vor_metric metrics[3] = {VOR_METRIC_L1, VOR_METRIC_LINF,
                                               VOR_METRIC_FARTHEST};
    for (unsigned k = 0; k < 3u; k++) {
        vor_raster_sites_t set = point_set(metrics[k], 1);
        points[0].x = 17;
        points[0].y = -5;
        check_frame("wide tiles", &f, &set);
    }
}

void test_raster_metrics(void)
{
    test_rng_t rng;
    TEST_CASE("errors") error_cases();
    TEST_CASE("distance_values") distance_value_cases();
    TEST_CASE("point_metrics") point_metric_cases(test_rng_seed(&rng, 5005));
    TEST_CASE("weighted_ties") {
        always_distance = 1; /* exact ties and integer distances */
        weighted_tie_cases(test_rng_seed(&rng, 5005));
        always_distance = 0;
    }
    TEST_CASE("hausdorff") hausdorff_cases(test_rng_seed(&rng, 5005));
    TEST_CASE("segments") segment_cases(test_rng_seed(&rng, 5005));
    TEST_CASE("polygons") polygon_cases(test_rng_seed(&rng, 5005));
    TEST_CASE("polylines") polyline_cases(test_rng_seed(&rng, 5005));
    TEST_CASE("huge") {
        always_distance = 1; /* saturation and the widest values */
        huge_cases(test_rng_seed(&rng, 5005));
        always_distance = 0;
    }
    TEST_CASE("power") {
        always_distance = 1; /* negative values and both clamps */
        power_cases(test_rng_seed(&rng, 5005));
        always_distance = 0;
    }
    TEST_CASE("pool_overflow") pool_overflow_case();
    TEST_CASE("wide_tiles") wide_tiles_case();
}
