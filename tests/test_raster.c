/* SPDX-License-Identifier: MIT */
/*
 * test_raster.c - vor_raster against the brute-force reference of
 * raster_reference.c, pixel by pixel, for every output kind, both
 * methods, and several band heights; random and adversarial sites (on
 * pixel centres, exact ties, duplicates, mirror pairs across band seams,
 * far and huge coordinates); and every documented error.
 */
#include "raster_reference.h"
#include "test.h"
#include "vor_raster.h"

#define MAX_W 41u
#define MAX_H 40u
#define MAX_SITES 72u

static vor_point_t sites[MAX_SITES];
static uint32_t expect_label[MAX_W * MAX_H];
static uint8_t frame_pixels[MAX_W * MAX_H * 4u];
static uint8_t band_memory[MAX_W * MAX_H * 4u] __attribute__((aligned(8)));
static uint8_t work[VOR_RASTER_WORK_BYTES(MAX_SITES, MAX_W)] __attribute__((aligned(8)));
static uint16_t palette565[MAX_SITES];
static uint32_t palette888[MAX_SITES];
static uint32_t areas[MAX_SITES];

/* Collects the bands into frame_pixels and checks their order. */
typedef struct capture {
    uint32_t next_row;
    uint32_t band_rows;
    size_t row_bytes;
    uint32_t flushes;
    int bad_order;
    uint32_t stop_after; /* return nonzero on this flush (0: never) */
} capture_t;

static int capture_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    capture_t *c = user;
    c->flushes++;
    if (first_row != c->next_row || rows == 0u || rows > c->band_rows) {
        c->bad_order = 1;
        return 0;
    }
    const uint8_t *src = pixels;
    for (size_t b = 0; b < rows * c->row_bytes; b++) {
        frame_pixels[first_row * c->row_bytes + b] = src[b];
    }
    c->next_row = first_row + rows;
    if (c->stop_after != 0u && c->flushes == c->stop_after) {
        return 77;
    }
    return 0;
}

static const char *const kind_names[] = {"label8", "label16", "label32", "rgb565",
                                         "rgb888", "boundary", "distance"};

static uint32_t expected_value(const vor_raster_frame_t *f, const vor_raster_sites_t *set,
                               enum vor_raster_kind kind, uint32_t i, uint32_t j)
{
    uint32_t w = f->width, label = expect_label[j * w + i];
    switch (kind) {
    case VOR_RASTER_RGB565:
        return palette565[label];
    case VOR_RASTER_RGB888:
        return palette888[label];
    case VOR_RASTER_BOUNDARY:
        return (i + 1u < w && expect_label[j * w + i + 1u] != label) ||
               (j + 1u < f->height && expect_label[(j + 1u) * w + i] != label);
    case VOR_RASTER_DISTANCE:
        return ref_distance(set, label,
                            ref_centre_x(f, i),
                            ref_centre_y(f, j));
    default:
        return label;
    }
}

static uint32_t got_value(enum vor_raster_kind kind, size_t pixel)
{
    const uint8_t *p = frame_pixels;
    switch (kind) {
    case VOR_RASTER_LABEL8:
    case VOR_RASTER_BOUNDARY:
        return p[pixel];
    case VOR_RASTER_LABEL16:
    case VOR_RASTER_RGB565:
        return ((const uint16_t *)(const void *)p)[pixel];
    case VOR_RASTER_RGB888:
        return ((uint32_t)p[3u * pixel] << 16) | ((uint32_t)p[3u * pixel + 1u] << 8) |
               p[3u * pixel + 2u];
    default:
        return ((const uint32_t *)(const void *)p)[pixel];
    }
}

/* Renders with one method, kind and band height, and compares every
 * pixel and the areas with the reference labels. */
static void render_and_compare(const char *name, const vor_raster_frame_t *f,
                               const vor_raster_sites_t *set, enum vor_raster_method method,
                               enum vor_raster_kind kind, uint32_t band_rows)
{
    capture_t cap = {0, band_rows, 0, 0, 0, 0};
    cap.row_bytes = (size_t)f->width * VOR_RASTER_PIXEL_BYTES(kind);
    vor_raster_output_t out = {0};
    out.kind = kind;
    out.band = band_memory;
    out.band_bytes = cap.row_bytes * band_rows;
    out.band_rows = band_rows;
    out.flush = capture_flush;
    out.user = &cap;
    out.palette565 = palette565;
    out.palette888 = palette888;
    out.areas = areas;
    vor_raster_options_t options = {method, 0};
    for (uint32_t k = 0; k < set->count; k++) {
        areas[k] = 0xDEADu;
    }
    int err = vor_raster(f, set, &out, &options, work, sizeof work);
    const char *how = method == VOR_RASTER_FAST ? "fast" : "brute";
    if (!CHECK(err == VOR_OK && !cap.bad_order && cap.next_row == f->height,
               "%s %s %s rows %u: err %d, order %d, rows %u", name, how, kind_names[kind],
               band_rows, err, cap.bad_order, cap.next_row)) {
        return;
    }
    uint32_t wrong = 0;
    for (uint32_t j = 0; j < f->height; j++) {
        for (uint32_t i = 0; i < f->width; i++) {
            uint32_t want = expected_value(f, set, kind, i, j);
            uint32_t got = got_value(kind, (size_t)j * f->width + i);
            if (want != got && wrong++ < 3u) {
                CHECK(false, "%s %s %s rows %u: pixel (%u, %u) = %u, reference %u", name, how,
                      kind_names[kind], band_rows, i, j, got, want);
            }
        }
    }
    CHECK(wrong == 0, "%s %s %s rows %u: %u pixels wrong", name, how, kind_names[kind], band_rows,
          wrong);
    uint32_t bad_area = 0;
    for (uint32_t k = 0; k < set->count; k++) {
        uint32_t count = 0;
        for (uint32_t p = 0; p < f->width * f->height; p++) {
            count += expect_label[p] == k;
        }
        bad_area += count != areas[k];
    }
    CHECK(bad_area == 0, "%s %s %s: %u areas wrong", name, how, kind_names[kind], bad_area);
}

static uint32_t case_number;

/* The reference labels of the frame, then every kind and method. */
static void check_frame(const char *name, const vor_raster_frame_t *f, uint32_t n)
{
    vor_raster_sites_t set = {0};
    set.metric = VOR_METRIC_EUCLID;
    set.points = sites;
    set.count = n;
    for (uint32_t j = 0; j < f->height; j++) {
        for (uint32_t i = 0; i < f->width; i++) {
            expect_label[j * f->width + i] =
                ref_nearest(&set, ref_centre_x(f, i),
                            ref_centre_y(f, j));
        }
    }
    for (uint32_t k = 0; k < n; k++) {
        palette565[k] = (uint16_t)(0x1234u * (k + 1u));
        palette888[k] = (0x9E3779u * (k + 1u)) & 0xFFFFFFu;
    }
    static const uint32_t band_heights[] = {1, 3, 16, 40};
    case_number++;
    for (int kind = VOR_RASTER_LABEL8; kind <= VOR_RASTER_DISTANCE; kind++) {
        if ((kind == VOR_RASTER_LABEL8 && n > 256u) || (kind == VOR_RASTER_DISTANCE && case_number % 4u != 1u)) {
            continue; /* distances: a quarter of the cases (the reference is slow) */
        }
        uint32_t rows = band_heights[(case_number + (uint32_t)kind) % 4u];
        render_and_compare(name, f, &set, VOR_RASTER_FAST, (enum vor_raster_kind)kind, rows);
        if (kind == VOR_RASTER_LABEL32 || kind == VOR_RASTER_BOUNDARY) {
            render_and_compare(name, f, &set, VOR_RASTER_BRUTE, (enum vor_raster_kind)kind, rows);
        }
    }
}

static void random_cases(test_rng_t *rng)
{
    for (uint32_t round = 0; round < 12u; round++) {
        uint32_t n = 1u + test_rng_u32(rng) % MAX_SITES;
        uint32_t w = 1u + test_rng_u32(rng) % MAX_W, h = 1u + test_rng_u32(rng) % MAX_H;
        int32_t sx = 1 + (int32_t)(test_rng_u32(rng) % 5u), sy = 1 + (int32_t)(test_rng_u32(rng) % 5u);
        vor_raster_frame_t f = ref_frame(test_rng_range(rng, -50, 50), test_rng_range(rng, -50, 50),
                                          sx, sy, w, h);
        /* sites around the frame, some outside it */
        for (uint32_t k = 0; k < n; k++) {
            sites[k].x = f.origin_x + test_rng_range(rng, -20, (int32_t)w * sx + 20);
            sites[k].y = f.origin_y + test_rng_range(rng, -20, (int32_t)h * sy + 20);
        }
        check_frame("random", &f, n);
    }
}

static void adversarial_cases(test_rng_t *rng)
{
    /* sites on pixel centres, with duplicates */
    vor_raster_frame_t f = ref_frame(-7, 11, 3, 2, 33, 37);
    for (uint32_t k = 0; k < 60u; k++) {
        sites[k].x = f.origin_x + 3 * test_rng_range(rng, 0, 32);
        sites[k].y = f.origin_y + 2 * test_rng_range(rng, 0, 36);
    }
    for (uint32_t k = 60; k < MAX_SITES; k++) {
        sites[k] = sites[k - 60u]; /* duplicates: the smaller index owns the pixels */
    }
    check_frame("centres", &f, MAX_SITES);

    /* a square lattice, indices reversed: bisectors through pixel centres,
     * four-way ties at cell corners */
    f = ref_frame(0, 0, 1, 1, 41, 40);
    uint32_t n = 0;
    for (int32_t y = 0; y <= 40; y += 8) {
        for (int32_t x = 0; x <= 40; x += 8) {
            sites[MAX_SITES - 1u - n].x = x;
            sites[MAX_SITES - 1u - n].y = y;
            n++;
        }
    }
    for (uint32_t k = 0; k < MAX_SITES - n; k++) {
        sites[k].x = 4; /* far-off ties: equal to lattice points */
        sites[k].y = 1000 + (int32_t)k;
    }
    check_frame("lattice", &f, MAX_SITES);
    /* shifted by half a cell: the ties fall on the corners of the
     * culling bands (rows 0, 16, 32; columns 0 and 40) */
    for (uint32_t k = MAX_SITES - n; k < MAX_SITES; k++) {
        sites[k].x += 4;
        sites[k].y += 4;
    }
    check_frame("lattice-corners", &f, MAX_SITES);

    /* pairs mirrored across the rows at band seams (rows 15, 16, 31, 32):
     * equal lines along the edges of culling bands */
    f = ref_frame(0, 0, 1, 1, 30, 40);
    n = 0;
    static const int32_t seams[] = {15, 16, 31, 32, 0, 39};
    for (uint32_t s = 0; s < 6u; s++) {
        for (int32_t t = 1; t <= 4; t++) {
            int32_t x = test_rng_range(rng, -5, 35);
            sites[n].x = x;
            sites[n++].y = seams[s] + t;
            sites[n].x = x;
            sites[n++].y = seams[s] - t;
        }
    }
    check_frame("mirrors", &f, n);
    /* the same, mirrored across columns, and with larger indices first */
    for (uint32_t k = 0; k < n; k++) {
        int32_t t = sites[k].x;
        sites[k].x = sites[k].y - 5;
        sites[k].y = t;
    }
    for (uint32_t k = 0; k < n / 2u; k++) {
        vor_point_t t = sites[k];
        sites[k] = sites[n - 1u - k];
        sites[n - 1u - k] = t;
    }
    check_frame("mirrors-x", &f, n);

    /* collinear sites: a vertical line (equal slopes), then a horizontal one */
    f = ref_frame(-3, -3, 1, 1, 20, 20);
    for (uint32_t k = 0; k < 16u; k++) {
        sites[k].x = 7;
        sites[k].y = test_rng_range(rng, -10, 30);
    }
    check_frame("vertical", &f, 16);
    for (uint32_t k = 0; k < 16u; k++) {
        sites[k].y = 7;
        sites[k].x = test_rng_range(rng, -10, 30);
    }
    check_frame("horizontal", &f, 16);

    /* one site; one pixel; one row; one column */
    sites[0].x = 5;
    sites[0].y = -9;
    check_frame("one-site", &f, 1);
    for (uint32_t k = 0; k < 10u; k++) {
        sites[k].x = test_rng_range(rng, -30, 30);
        sites[k].y = test_rng_range(rng, -30, 30);
    }
    f = ref_frame(2, 2, 7, 9, 1, 1);
    check_frame("one-pixel", &f, 10);
    f = ref_frame(-20, 2, 1, 9, 41, 1);
    check_frame("one-row", &f, 10);
    f = ref_frame(2, -20, 9, 1, 1, 40);
    check_frame("one-column", &f, 10);

    /* far sites, inside the fast path's budget (2^29) */
    f = ref_frame(1000, -2000, 17, 13, 30, 30);
    for (uint32_t k = 0; k < 40u; k++) {
        int32_t far = (k % 3u == 0u) ? 500000000 : 300;
        sites[k].x = f.origin_x + test_rng_range(rng, -far, far);
        sites[k].y = f.origin_y + test_rng_range(rng, -far, far);
    }
    check_frame("far", &f, 40);

    /* the mid envelope tier: coordinates between 2^14 and 2^19 */
    f = ref_frame(-20000, 30000, 997, 1009, 41, 40);
    for (uint32_t k = 0; k < 50u; k++) {
        sites[k].x = f.origin_x + test_rng_range(rng, -200000, 240000);
        sites[k].y = f.origin_y + test_rng_range(rng, -200000, 240000);
    }
    check_frame("mid", &f, 50);
    /* a lattice with four-way ties at pixel centres, in the mid tier */
    f = ref_frame(0, 0, 1000, 1000, 41, 40);
    n = 0;
    for (int32_t y = 0; y <= 40; y += 8) {
        for (int32_t x = 4; x <= 44; x += 8) {
            sites[MAX_SITES - 1u - n].x = x * 1000;
            sites[MAX_SITES - 1u - n].y = y * 1000 + 4000;
            n++;
        }
    }
    for (uint32_t k = 0; k < MAX_SITES - n; k++) {
        sites[k].x = 300000 + (int32_t)k;
        sites[k].y = -200000;
    }
    check_frame("mid-lattice", &f, MAX_SITES);

    /* the whole int32 range: the exact fallback */
    f = ref_frame(INT32_MIN, INT32_MIN, 107374182, 110127366, 41, 40);
    for (uint32_t k = 0; k < 30u; k++) {
        sites[k].x = (int32_t)test_rng_u32(rng);
        sites[k].y = (int32_t)test_rng_u32(rng);
    }
    sites[30].x = INT32_MAX;
    sites[30].y = INT32_MIN;
    sites[31].x = INT32_MIN;
    sites[31].y = INT32_MAX;
    check_frame("huge", &f, 32);
    /* huge steps just inside the budget: (w - 1) * step < 2^29 */
    f = ref_frame(-268435456, -268435456, 13421772, 13765920, 41, 40);
    for (uint32_t k = 0; k < 30u; k++) {
        sites[k].x = f.origin_x + test_rng_range(rng, 0, 536870911);
        sites[k].y = f.origin_y + test_rng_range(rng, 0, 536870911);
    }
    check_frame("budget", &f, 30);
}

/* ---- many bands: the fast path's band-to-band selection ------------ */

#define BIG_W 96u
#define BIG_H 100u
#define BIG_SITES 260u

static vor_point_t big_sites[BIG_SITES];
static uint32_t big_labels[BIG_W * BIG_H];
static uint8_t bands_work[VOR_RASTER_WORK_BYTES(BIG_SITES, BIG_W)] __attribute__((aligned(8)));

typedef struct big_capture {
    uint32_t width, next_row;
    int bad_order;
} big_capture_t;

static int big_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    big_capture_t *c = user;
    if (first_row != c->next_row) {
        c->bad_order = 1;
        return 0;
    }
    const uint32_t *px = pixels;
    for (uint32_t k = 0; k < rows * c->width; k++) {
        big_labels[first_row * c->width + k] = px[k];
    }
    c->next_row = first_row + rows;
    return 0;
}

/* The nearest site by plain int64 squares (coordinates below 2^30 here,
 * so squares and their sums stay below 2^63), ties to the smaller index:
 * a brute force of its own, cheaper than the multi-word reference. */
static uint32_t plain_nearest(uint32_t n, int64_t qx, int64_t qy)
{
    uint32_t best = 0;
    int64_t best_d = -1;
    for (uint32_t k = 0; k < n; k++) {
        int64_t dx = qx - big_sites[k].x, dy = qy - big_sites[k].y;
        int64_t d = dx * dx + dy * dy;
        if (best_d < 0 || d < best_d) {
            best_d = d;
            best = k;
        }
    }
    return best;
}

/* Renders labels with the fast path in bands of band_rows and compares
 * every pixel with plain_nearest. */
static void check_bands(const char *name, const vor_raster_frame_t *f, uint32_t n,
                        uint32_t band_rows)
{
    static uint32_t band[BIG_W * 20u];
    /* the fast path's budget (vor_raster.h, SPEED): every site within
     * 2^29 of the first pixel, the frame less than 2^29 across */
    const int64_t budget = (int64_t)1 << 29;
    bool fast = (int64_t)(f->width - 1u) * f->step_x < budget &&
                (int64_t)(f->height - 1u) * f->step_y < budget;
    for (uint32_t k = 0; k < n; k++) {
        int64_t a = (int64_t)big_sites[k].x - f->origin_x, b = (int64_t)big_sites[k].y - f->origin_y;
        fast = fast && a > -budget && a < budget && b > -budget && b < budget;
    }
    CHECK(fast, "%s: the case is within the fast path's budget", name);
    big_capture_t cap = {f->width, 0, 0};
    vor_raster_sites_t set = {.metric = VOR_METRIC_EUCLID, .points = big_sites, .count = n};
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_LABEL32;
    out.band = band;
    out.band_bytes = sizeof band;
    out.band_rows = band_rows;
    out.flush = big_flush;
    out.user = &cap;
    int err = vor_raster(f, &set, &out, NULL, bands_work, sizeof bands_work);
    if (!CHECK(err == VOR_OK && !cap.bad_order && cap.next_row == f->height,
               "%s: err %d, rows %u", name, err, cap.next_row)) {
        return;
    }
    uint32_t wrong = 0;
    for (uint32_t j = 0; j < f->height; j++) {
        for (uint32_t i = 0; i < f->width; i++) {
            uint32_t want = plain_nearest(n, f->origin_x + (int64_t)i * f->step_x,
                                          f->origin_y + (int64_t)j * f->step_y);
            uint32_t got = big_labels[j * f->width + i];
            if (want != got && wrong++ < 3u) {
                CHECK(false, "%s: pixel (%u, %u) = %u, brute force %u", name, i, j, got, want);
            }
        }
    }
    CHECK(wrong == 0, "%s: %u of %u pixels wrong", name, wrong, f->width * f->height);
}

static void band_cases(test_rng_t *rng)
{
    /* uniform random sites, some outside, over seven culling bands */
    vor_raster_frame_t f = ref_frame(-40, 25, 1, 1, BIG_W, BIG_H);
    for (uint32_t k = 0; k < BIG_SITES; k++) {
        big_sites[k].x = f.origin_x + test_rng_range(rng, -15, (int32_t)BIG_W + 15);
        big_sites[k].y = f.origin_y + test_rng_range(rng, -15, (int32_t)BIG_H + 15);
    }
    check_bands("bands-uniform", &f, BIG_SITES, 16);

    /* sparse sites, large empty regions: cells that reach up across
     * several bands from far below, and down from above the frame */
    f = ref_frame(0, 0, 3, 2, BIG_W, BIG_H);
    for (uint32_t k = 0; k < 9u; k++) {
        big_sites[k].x = test_rng_range(rng, -30, 3 * (int32_t)BIG_W + 30);
        big_sites[k].y = (k < 3u) ? test_rng_range(rng, -40, 10)
                                  : test_rng_range(rng, 2 * (int32_t)BIG_H - 10, 2 * (int32_t)BIG_H + 300);
    }
    check_bands("bands-sparse", &f, 9, 7);
    /* five sites above and below an empty frame (found by search): the
     * cells that reach a band's bottom edge from below come from farther
     * than the largest distance to a site on the last row above: the
     * search radius must be measured at the edge itself */
    f = ref_frame(0, 0, 1, 1, BIG_W, BIG_H);
    static const int32_t gap_sites[5][2] = {{-16, 153}, {99, -5}, {11, -18}, {-16, 136}, {52, 145}};
    for (uint32_t k = 0; k < 5u; k++) {
        big_sites[k].x = gap_sites[k][0];
        big_sites[k].y = gap_sites[k][1];
    }
    check_bands("bands-gap", &f, 5, 16);
    /* one site far below, all others in one cluster near the top */
    f = ref_frame(0, 0, 3, 2, BIG_W, BIG_H);
    for (uint32_t k = 0; k < 40u; k++) {
        big_sites[k].x = test_rng_range(rng, 100, 140);
        big_sites[k].y = test_rng_range(rng, 0, 12);
    }
    big_sites[40].x = 150;
    big_sites[40].y = 900;
    check_bands("bands-cluster", &f, 41, 16);

    /* sites in a row above the frame and a row below it: long vertical
     * cells, whose pieces of the left and right frame edges each span
     * several bands */
    f = ref_frame(-42, 44, 1, 1, BIG_W, BIG_H);
    for (uint32_t k = 0; k < BIG_SITES; k++) {
        big_sites[k].x = f.origin_x + test_rng_range(rng, -(int32_t)BIG_W, 2 * (int32_t)BIG_W);
        big_sites[k].y = f.origin_y + ((k % 2u == 0u) ? test_rng_range(rng, -5, -1)
                                                      : test_rng_range(rng, 103, 107));
    }
    check_bands("bands-strips", &f, BIG_SITES, 16);
    /* three sites (found by search): the cell of (116, 0) enters through
     * the right frame edge at v = 51.9, in the fourth band, below its top
     * edge, and leaves it at v = 69.8: that band must take its piece of
     * the right edge's envelope, though the pieces before it ended in
     * earlier bands */
    f = ref_frame(0, 0, 1, 1, BIG_W, BIG_H);
    big_sites[0].x = 116;
    big_sites[0].y = 0;
    big_sites[1].x = 106;
    big_sites[1].y = -3;
    big_sites[2].x = 38;
    big_sites[2].y = 115;
    check_bands("bands-side-wedge", &f, 3, 16);

    /* a lattice whose bisectors run along the band seams (rows 16k) and
     * through pixel centres and midpoints, indices reversed, duplicates */
    f = ref_frame(0, 0, 1, 1, BIG_W, BIG_H);
    uint32_t n = 0;
    for (int32_t y = -8; y <= (int32_t)BIG_H + 8 && n + 1u < BIG_SITES; y += 16) {
        for (int32_t x = -3; x <= (int32_t)BIG_W + 3 && n + 1u < BIG_SITES; x += 7) {
            big_sites[BIG_SITES - 1u - n].x = x;
            big_sites[BIG_SITES - 1u - n].y = y;
            n++;
        }
    }
    uint32_t lattice = n;
    for (uint32_t k = 0; k < BIG_SITES - lattice; k++) { /* duplicates, larger first */
        big_sites[k] = big_sites[BIG_SITES - 1u - (k * 7u) % lattice];
    }
    check_bands("bands-lattice", &f, BIG_SITES, 16);
    /* mirror pairs across the seam rows: equal lines on bottom edges */
    n = 0;
    for (int32_t seam = 16; seam < (int32_t)BIG_H && n + 6u <= BIG_SITES; seam += 16) {
        for (int32_t t = 1; t <= 3; t++) {
            int32_t x = test_rng_range(rng, -5, (int32_t)BIG_W + 5);
            big_sites[n].x = x;
            big_sites[n++].y = seam + t * 5;
            big_sites[n].x = x;
            big_sites[n++].y = seam - t * 5;
        }
    }
    check_bands("bands-mirrors", &f, n, 16);
    /* columns of sites (equal slopes), with equal x across many rows */
    for (uint32_t k = 0; k < 120u; k++) {
        big_sites[k].x = 4 + 11 * (int32_t)(k % 9u);
        big_sites[k].y = test_rng_range(rng, -20, (int32_t)BIG_H + 20);
    }
    check_bands("bands-columns", &f, 120, 5);

    /* the mid tier, the demo's scale: a 100 m floor in millimetres */
    f = ref_frame(-49844, -49792, 1247, 1011, BIG_W, BIG_H);
    for (uint32_t k = 0; k < 200u; k++) {
        big_sites[k].x = test_rng_range(rng, -50000, 70000);
        big_sites[k].y = test_rng_range(rng, -50000, 60000);
    }
    check_bands("bands-mid", &f, 200, 16);
    /* the wide tier: quotients of more than 32 bits (Cortex-M3 and
     * RISC-V then divide step by step), few sites, far apart */
    f = ref_frame(-200000000, -100000000, 3000001, 4100003, 80, BIG_H);
    for (uint32_t k = 0; k < 60u; k++) {
        big_sites[k].x = test_rng_range(rng, -260000000, 260000000);
        big_sites[k].y = test_rng_range(rng, -260000000, 260000000);
    }
    check_bands("bands-wide", &f, 60, 16);
    /* wide, with sites on pixel centres (exact ties at pixels) */
    for (uint32_t k = 0; k < 60u; k++) {
        big_sites[k].x = f.origin_x + 3000001 * test_rng_range(rng, 0, 79);
        big_sites[k].y = f.origin_y + 4100003 * test_rng_range(rng, 0, (int32_t)BIG_H - 1);
    }
    check_bands("bands-wide-centres", &f, 60, 11);
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
    for (uint32_t k = 0; k < MAX_SITES; k++) {
        sites[k].x = (int32_t)k;
        sites[k].y = (int32_t)(k * 7u % 13u);
    }
    vor_raster_frame_t f = ref_frame(0, 0, 1, 1, 10, 10);
    vor_raster_sites_t set = {0};
    set.points = sites;
    set.count = 5;
    uint32_t flushes = 0;
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_LABEL8;
    out.band = band_memory;
    out.band_bytes = 10u * 4u;
    out.band_rows = 4;
    out.flush = quiet_flush;
    out.user = &flushes;
    out.areas = areas;
    for (uint32_t k = 0; k < MAX_SITES; k++) {
        areas[k] = 12345u;
    }
    CHECK(vor_raster(&f, &set, &out, NULL, work, sizeof work) == VOR_OK && flushes == 3u,
          "errors: the valid base request works (%u flushes)", flushes);
    for (uint32_t k = 0; k < MAX_SITES; k++) {
        areas[k] = 12345u;
    }
    flushes = 0;

    vor_raster_frame_t bad = f;
    CHECK(vor_raster(NULL, &set, &out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: NULL frame");
    CHECK(vor_raster(&f, NULL, &out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: NULL sites");
    CHECK(vor_raster(&f, &set, NULL, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: NULL output");
    CHECK(vor_raster(&f, &set, &out, NULL, NULL, sizeof work) == VOR_ERR_ARG, "errors: NULL work");
    bad.width = 0;
    CHECK(vor_raster(&bad, &set, &out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: width 0");
    bad = f;
    bad.step_y = 0;
    CHECK(vor_raster(&bad, &set, &out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: step 0");
    bad.step_y = -1;
    CHECK(vor_raster(&bad, &set, &out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: step < 0");
    bad = f;
    bad.origin_x = INT32_MAX - 8; /* the last centre is INT32_MAX + 1 */
    CHECK(vor_raster(&bad, &set, &out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: centre > int32");
    bad.origin_x = INT32_MAX - 9;
    CHECK(vor_raster(&bad, &set, &out, NULL, work, sizeof work) == VOR_OK, "errors: last centre INT32_MAX");
    for (uint32_t k = 0; k < MAX_SITES; k++) {
        areas[k] = 12345u;
    }
    flushes = 0;

    vor_raster_sites_t bad_set = set;
    bad_set.count = 0;
    CHECK(vor_raster(&f, &bad_set, &out, NULL, work, sizeof work) == VOR_ERR_EMPTY, "errors: no sites");
    bad_set = set;
    bad_set.points = NULL;
    CHECK(vor_raster(&f, &bad_set, &out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: NULL points");
    bad_set = set;
    bad_set.metric = (enum vor_metric)99;
    CHECK(vor_raster(&f, &bad_set, &out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: metric");

    vor_raster_output_t bad_out = out;
    bad_out.kind = (enum vor_raster_kind)42;
    CHECK(vor_raster(&f, &set, &bad_out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: kind");
    vor_raster_options_t bad_method = {(enum vor_raster_method)3, 0};
    CHECK(vor_raster(&f, &set, &out, &bad_method, work, sizeof work) == VOR_ERR_ARG, "errors: method");
    bad_out = out;
    bad_out.kind = VOR_RASTER_RGB565;
    bad_out.band_bytes = 10u * 4u * 2u;
    CHECK(vor_raster(&f, &set, &bad_out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: no palette");
    bad_out = out;
    bad_out.flush = NULL;
    CHECK(vor_raster(&f, &set, &bad_out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: no flush");
    bad_out = out;
    bad_out.band_rows = 0;
    CHECK(vor_raster(&f, &set, &bad_out, NULL, work, sizeof work) == VOR_ERR_ARG, "errors: 0 band rows");
    bad_out = out;
    bad_out.band_bytes = 10u * 4u - 1u;
    CHECK(vor_raster(&f, &set, &bad_out, NULL, work, sizeof work) == VOR_ERR_NOMEM, "errors: small band");
    CHECK(vor_raster(&f, &set, &out, NULL, work, VOR_RASTER_WORK_BYTES(5, 10) - 1u) == VOR_ERR_NOMEM,
          "errors: small work");
    CHECK(vor_raster(&f, &set, &out, NULL, work + 4, VOR_RASTER_WORK_BYTES(5, 10)) == VOR_ERR_ALIGN,
          "errors: misaligned work");
    bad_set = set;
    bad_set.count = 257;
    vor_point_t many[257];
    for (uint32_t k = 0; k < 257u; k++) {
        many[k].x = (int32_t)k;
        many[k].y = 0;
    }
    bad_set.points = many;
    static uint8_t big_work[VOR_RASTER_WORK_BYTES(257, 10)] __attribute__((aligned(8)));
    CHECK(vor_raster(&f, &bad_set, &out, NULL, big_work, sizeof big_work) == VOR_ERR_ARG,
          "errors: label8 with 257 sites");
    uint32_t untouched = 0;
    for (uint32_t k = 0; k < MAX_SITES; k++) {
        untouched += areas[k] == 12345u;
    }
    CHECK(flushes == 0 && untouched == MAX_SITES, "errors: a failed call wrote %u flushes, %u areas",
          flushes, MAX_SITES - untouched);
    bad_out = out;
    bad_out.kind = VOR_RASTER_LABEL16;
    bad_out.band_bytes = 10u * 4u * 2u;
    bad_out.areas = NULL;
    CHECK(vor_raster(&f, &bad_set, &bad_out, NULL, big_work, sizeof big_work) == VOR_OK,
          "errors: label16 takes 257 sites");

    /* a flush that stops the render (returning 77): VOR_ERR_STOPPED, never
     * the flush's own code, after the bands before it */
    capture_t cap = {0, 4, 10, 0, 0, 2};
    bad_out = out;
    bad_out.flush = capture_flush;
    bad_out.user = &cap;
    int stopped = vor_raster(&f, &set, &bad_out, NULL, work, sizeof work);
    CHECK(stopped == VOR_ERR_STOPPED && cap.flushes == 2u,
          "errors: a stopping flush gives %d after %u flushes", stopped, cap.flushes);
}

/* The fast path's budget (2^29) broken one way at a time: the frame's
 * height alone, then one site past it on each side of a small frame. */
static void budget_edges(test_rng_t *rng)
{
    const int32_t budget = 536870912; /* 2^29 */
    vor_raster_frame_t f = ref_frame(0, 0, 1000, 13765921, 20, 40); /* 39 step_y >= 2^29 */
    for (uint32_t k = 0; k < 20u; k++) {
        sites[k].x = test_rng_range(rng, -100, 20000);
        sites[k].y = test_rng_range(rng, -100, budget);
    }
    check_frame("height past the budget", &f, 20);
    static const int32_t off[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (unsigned side = 0; side < 4u; side++) {
        f = ref_frame(-30, 40, 3, 3, 20, 20);
        for (uint32_t k = 0; k < 15u; k++) {
            sites[k].x = f.origin_x + test_rng_range(rng, -10, 70);
            sites[k].y = f.origin_y + test_rng_range(rng, -10, 70);
        }
        sites[15].x = f.origin_x + off[side][0] * budget;
        sites[15].y = f.origin_y + off[side][1] * budget;
        check_frame("a site past the budget", &f, 16);
    }
}

void test_raster(void)
{
    test_rng_t rng;
    TEST_CASE("errors") error_cases();
    TEST_CASE("random") random_cases(test_rng_seed(&rng, 2024));
    TEST_CASE("adversarial") adversarial_cases(test_rng_seed(&rng, 2024));
    TEST_CASE("bands") band_cases(test_rng_seed(&rng, 2024));
    TEST_CASE("budget_edges") budget_edges(test_rng_seed(&rng, 2025));
}
