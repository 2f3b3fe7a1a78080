/* SPDX-License-Identifier: MIT */
/*
 * test_korder.c - vor_raster_nearest, the K nearest sites of every pixel,
 * against a brute-force K-nearest search written here: per rank, the
 * first site of smallest distance among those not yet ranked, by the
 * reference's own exact comparisons (raster_reference.c,
 * ref_rank_compare). Every kind (the K labels, the K-th label, its
 * boundaries and distance, the k-set picture, the areas), both methods,
 * every metric, K = 1 (against vor_raster itself), 2, 3, 8, the largest K
 * and K past the site count, degenerate sets (a lattice, collinear and
 * coincident sites, ties), every band height of a frame, a flush that
 * stops the frame, and every argument error (nothing written).
 */
#include "raster_reference.h"
#include "test.h"
#include "vor_raster.h"

#define MAX_W 30u
#define MAX_H 22u
#define MAX_PIXELS (MAX_W * MAX_H)
#define MAX_SITES 26u
#define MAX_K VOR_RASTER_MAX_NEAREST

static vor_point_t points[4u * MAX_SITES];
static int32_t mult[MAX_SITES], add[MAX_SITES];
static int64_t power[MAX_SITES];
static uint32_t offsets[MAX_SITES + 1u];
static uint16_t palette[MAX_SITES];
static uint32_t palette888[MAX_SITES];
/* the reference: per pixel, MAX_K ranks */
static uint32_t expect[MAX_PIXELS * MAX_K];
/* the captured frame: per pixel, up to MAX_K values */
static uint32_t got[MAX_PIXELS * MAX_K];
static uint32_t band_memory[MAX_PIXELS * MAX_K];
/* the frames above, and the pool case's 320 x 2 frame with K = 2 */
#define WORK_FRAMES VOR_RASTER_NEAREST_WORK_BYTES(MAX_SITES, MAX_W, MAX_K)
#define WORK_POOL VOR_RASTER_NEAREST_WORK_BYTES(3, 320, 2)
static uint8_t work[WORK_FRAMES > WORK_POOL ? WORK_FRAMES : WORK_POOL] __attribute__((aligned(8)));
static uint32_t areas[MAX_SITES];

static const char *const metric_names[] = {"euclid",   "l1",        "linf",    "lp",
                                           "ellip",    "mult",      "add",     "comp",
                                           "farthest", "hausdorff", "segment", "polygon",
                                           "polyline", "power"};

/* ------------------------------------------------------------ reference */

/* The ranks of (qx, qy): rank r is the first site (smallest index) of
 * those not ranked yet that no other such site ranks strictly before;
 * VOR_RASTER_NO_SITE past the site count. */
static void reference_ranks(const vor_raster_sites_t *set, int32_t qx, int32_t qy, uint32_t k,
                            uint32_t *ranks, int *undecided)
{
    uint8_t taken[MAX_SITES] = {0};
    for (uint32_t r = 0; r < k; r++) {
        uint32_t best = VOR_RASTER_NO_SITE;
        for (uint32_t s = 0; s < set->count; s++) {
            if (!taken[s] &&
                (best == VOR_RASTER_NO_SITE || ref_rank_compare(set, s, best, qx, qy, undecided) < 0)) {
                best = s;
            }
        }
        if (best != VOR_RASTER_NO_SITE) {
            taken[best] = 1;
        }
        ranks[r] = best;
    }
}

static void reference_frame(const vor_raster_frame_t *f, const vor_raster_sites_t *set,
                            uint32_t k, const char *name)
{
    int undecided = 0;
    for (uint32_t j = 0; j < f->height; j++) {
        for (uint32_t i = 0; i < f->width; i++) {
            reference_ranks(set, ref_centre_x(f, i), ref_centre_y(f, j), k,
                            &expect[(j * f->width + i) * MAX_K], &undecided);
        }
    }
    CHECK(!undecided, "%s %s: the reference could not decide", metric_names[set->metric], name);
}

/* The K'-th ranked site of pixel p (K' = min(K, count)). */
static uint32_t kth(uint32_t p, uint32_t k, uint32_t count)
{
    return expect[p * MAX_K + (k < count ? k : count) - 1u];
}

/* The reference k-set of pixel p, sorted, into set; returns its size. */
static uint32_t kset(uint32_t p, uint32_t k, uint32_t count, uint32_t *set)
{
    uint32_t d = k < count ? k : count;
    for (uint32_t r = 0; r < d; r++) {
        uint32_t v = expect[p * MAX_K + r], at = r;
        while (at > 0u && set[at - 1u] > v) {
            set[at] = set[at - 1u];
            at--;
        }
        set[at] = v;
    }
    return d;
}

static int same_kset(uint32_t p, uint32_t q, uint32_t k, uint32_t count)
{
    uint32_t a[MAX_K], b[MAX_K];
    uint32_t d = kset(p, k, count, a);
    kset(q, k, count, b);
    for (uint32_t r = 0; r < d; r++) {
        if (a[r] != b[r]) {
            return 0;
        }
    }
    return 1;
}

/* The KSETS colour: the mean of the members' colours per channel. */
static uint16_t kset_colour(uint32_t p, uint32_t k, uint32_t count)
{
    uint32_t set[MAX_K], red = 0, green = 0, blue = 0;
    uint32_t d = kset(p, k, count, set);
    for (uint32_t r = 0; r < d; r++) {
        red += palette[set[r]] >> 11;
        green += (palette[set[r]] >> 5) & 63u;
        blue += palette[set[r]] & 31u;
    }
    return (uint16_t)((red / d) << 11 | (green / d) << 5 | (blue / d));
}

/* -------------------------------------------------------------- capture */

typedef struct capture {
    uint32_t next_row;
    uint32_t width;
    uint32_t values; /* values per pixel */
    uint32_t bytes;  /* bytes per value: 1, 2 or 4 */
    uint32_t stop_at; /* flush number that returns nonzero (0: none) */
    uint32_t flushes;
    int bad;
} capture_t;

static int capture_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    capture_t *c = user;
    c->flushes++;
    if (first_row != c->next_row) {
        c->bad = 1;
    }
    uint32_t n = rows * c->width * c->values;
    for (uint32_t v = 0; v < n; v++) {
        const uint8_t *b = (const uint8_t *)pixels + 3u * v;
        uint32_t x = c->bytes == 1u   ? ((const uint8_t *)pixels)[v]
                     : c->bytes == 2u ? ((const uint16_t *)pixels)[v]
                     : c->bytes == 3u ? (uint32_t)b[0] << 16 | (uint32_t)b[1] << 8 | b[2]
                                      : ((const uint32_t *)pixels)[v];
        got[first_row * c->width * c->values + v] = x;
    }
    c->next_row = first_row + rows;
    return c->flushes == c->stop_at ? 7 : 0;
}

static uint32_t case_number;

/* One render of kind with K = k, compared with the reference. */
static void render_kind(const char *name, const vor_raster_frame_t *f,
                        const vor_raster_sites_t *set, uint32_t k, enum vor_raster_method method,
                        uint32_t band_rows, enum vor_raster_kind kind)
{
    uint32_t values = kind == VOR_RASTER_NEAREST ? k : 1u;
    uint32_t bytes = (uint32_t)VOR_RASTER_NEAREST_PIXEL_BYTES(kind, 1u);
    capture_t cap = {0, f->width, values, bytes, 0, 0, 0};
    vor_raster_output_t out = {0};
    out.kind = kind;
    out.band = band_memory;
    out.band_bytes = (size_t)f->width * band_rows * VOR_RASTER_NEAREST_PIXEL_BYTES(kind, k);
    out.band_rows = band_rows;
    out.flush = capture_flush;
    out.user = &cap;
    out.areas = areas;
    out.palette565 = palette;
    out.palette888 = palette888;
    vor_raster_options_t options = {method, 0xFFFFu};
    for (uint32_t s = 0; s < set->count; s++) {
        areas[s] = 0xDEADu;
    }
    int err = vor_raster_nearest(f, set, k, &out, &options, work,
                                 VOR_RASTER_NEAREST_WORK_BYTES(set->count, f->width, k));
    const char *metric = metric_names[set->metric];
    const char *how = method == VOR_RASTER_FAST ? "fast" : "brute";
    if (!CHECK(err == VOR_OK && !cap.bad && cap.next_row == f->height,
               "%s %s k %u kind %d %s rows %u: err %d", metric, name, k, (int)kind, how, band_rows,
               err)) {
        return;
    }
    uint32_t w = f->width, h = f->height, wrong = 0;
    for (uint32_t p = 0; p < w * h; p++) {
        uint32_t i = p % w, j = p / w;
        for (uint32_t v = 0; v < values; v++) {
            uint32_t want = 0;
            if (kind == VOR_RASTER_NEAREST) {
                want = expect[p * MAX_K + v];
            } else if (kind == VOR_RASTER_LABEL32 || kind == VOR_RASTER_LABEL16 ||
                       kind == VOR_RASTER_LABEL8) {
                want = kth(p, k, set->count);
            } else if (kind == VOR_RASTER_RGB565) {
                want = palette[kth(p, k, set->count)];
            } else if (kind == VOR_RASTER_RGB888) {
                want = palette888[kth(p, k, set->count)];
            } else if (kind == VOR_RASTER_BOUNDARY) {
                want = (i + 1u < w && kth(p + 1u, k, set->count) != kth(p, k, set->count)) ||
                       (j + 1u < h && kth(p + w, k, set->count) != kth(p, k, set->count));
            } else if (kind == VOR_RASTER_DISTANCE) {
                want = ref_distance_metric(set, kth(p, k, set->count), ref_centre_x(f, i),
                                           ref_centre_y(f, j));
            } else { /* KSETS */
                int edge = (i + 1u < w && !same_kset(p, p + 1u, k, set->count)) ||
                           (j + 1u < h && !same_kset(p, p + w, k, set->count));
                want = edge ? 0xFFFFu : kset_colour(p, k, set->count);
            }
            uint32_t have = got[p * values + v];
            if (have != want && wrong++ < 3u) {
                CHECK(false, "%s %s k %u kind %d %s rows %u: pixel (%u, %u) value %u = %u, want %u",
                      metric, name, k, (int)kind, how, band_rows, i, j, v, have, want);
            }
        }
    }
    CHECK(wrong == 0, "%s %s k %u kind %d %s rows %u: %u values wrong", metric, name, k, (int)kind,
          how, band_rows, wrong);
    uint32_t bad_area = 0;
    for (uint32_t s = 0; s < set->count; s++) {
        uint32_t count = 0;
        for (uint32_t p = 0; p < w * h; p++) {
            count += kth(p, k, set->count) == s;
        }
        bad_area += count != areas[s];
    }
    CHECK(bad_area == 0, "%s %s k %u kind %d: %u areas wrong", metric, name, k, (int)kind,
          bad_area);
}

/* K = 1: vor_raster_nearest's labels are vor_raster's. */
static void same_as_raster(const vor_raster_frame_t *f, const vor_raster_sites_t *set)
{
    static uint32_t plain[MAX_PIXELS];
    capture_t cap = {0, f->width, 1, 4, 0, 0, 0};
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_LABEL32;
    out.band = band_memory;
    out.band_bytes = (size_t)f->width * 4u * f->height;
    out.band_rows = f->height;
    out.flush = capture_flush;
    out.user = &cap;
    int err = vor_raster(f, set, &out, NULL, work, sizeof work);
    for (uint32_t p = 0; p < f->width * f->height; p++) {
        plain[p] = got[p];
    }
    cap.next_row = 0;
    int err1 = vor_raster_nearest(f, set, 1, &out, NULL, work, sizeof work);
    uint32_t differ = 0;
    for (uint32_t p = 0; p < f->width * f->height; p++) {
        differ += plain[p] != got[p];
    }
    CHECK(err == VOR_OK && err1 == VOR_OK && differ == 0, "%s: k = 1 differs from vor_raster at %u pixels",
          metric_names[set->metric], differ);
}

/* The reference for the largest K asked, then renders of each K in ks
 * (kinds and band heights taking turns). */
static void check_frame(const char *name, const vor_raster_frame_t *f,
                        const vor_raster_sites_t *set, const uint32_t *ks, uint32_t nks)
{
    uint32_t most = 1;
    for (uint32_t q = 0; q < nks; q++) {
        most = ks[q] > most ? ks[q] : most;
    }
    reference_frame(f, set, most, name);
    same_as_raster(f, set);
    static const uint32_t band_heights[] = {1, 5, 16, 2, 7};
    for (uint32_t q = 0; q < nks; q++) {
        uint32_t k = ks[q];
        case_number++;
        render_kind(name, f, set, k, VOR_RASTER_FAST, band_heights[case_number % 5u],
                    VOR_RASTER_NEAREST);
        render_kind(name, f, set, k, VOR_RASTER_BRUTE, band_heights[(case_number + 1u) % 5u],
                    VOR_RASTER_NEAREST);
        render_kind(name, f, set, k, case_number % 2u ? VOR_RASTER_FAST : VOR_RASTER_BRUTE,
                    band_heights[(case_number + 2u) % 5u], VOR_RASTER_KSETS);
        if (case_number % 2u == 0u) {
            render_kind(name, f, set, k, VOR_RASTER_FAST, band_heights[(case_number + 3u) % 5u],
                        VOR_RASTER_LABEL32);
        } else {
            render_kind(name, f, set, k, VOR_RASTER_FAST, band_heights[(case_number + 3u) % 5u],
                        VOR_RASTER_BOUNDARY);
        }
        if (case_number % 3u == 0u) {
            render_kind(name, f, set, k, VOR_RASTER_BRUTE, band_heights[(case_number + 4u) % 5u],
                        VOR_RASTER_DISTANCE);
        }
    }
}

/* -------------------------------------------------------------- inputs */

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

/* n random points (n <= 4 MAX_SITES) around the frame. */
static void random_points(test_rng_t *rng, const vor_raster_frame_t *f, uint32_t n)
{
    for (uint32_t s = 0; s < n; s++) {
        points[s].x = f->origin_x + test_rng_range(rng, -12, (int32_t)f->width * f->step_x + 12);
        points[s].y = f->origin_y + test_rng_range(rng, -12, (int32_t)f->height * f->step_y + 12);
    }
}

/* n <= MAX_SITES random point sites with weights and colours. */
static void random_sites(test_rng_t *rng, const vor_raster_frame_t *f, uint32_t n)
{
    random_points(rng, f, n);
    for (uint32_t s = 0; s < n; s++) {
        mult[s] = 1 + test_rng_range(rng, 0, 4);
        add[s] = test_rng_range(rng, -8, 8);
        power[s] = test_rng_range(rng, -200, 200);
        palette[s] = (uint16_t)test_rng_u32(rng);
        palette888[s] = test_rng_u32(rng) & 0xFFFFFFu;
    }
}

static const enum vor_metric point_metrics[] = {
    VOR_METRIC_EUCLID,   VOR_METRIC_L1,   VOR_METRIC_LINF,     VOR_METRIC_LP,
    VOR_METRIC_ELLIPTIC, VOR_METRIC_MULT, VOR_METRIC_ADD,      VOR_METRIC_COMPOUND,
    VOR_METRIC_FARTHEST, VOR_METRIC_POWER};
#define POINT_METRICS (sizeof point_metrics / sizeof point_metrics[0])

static void random_cases(test_rng_t *rng)
{
    static const uint32_t ks[] = {1, 2, 3, 8};
    for (unsigned m = 0; m < POINT_METRICS; m++) {
        vor_raster_frame_t f = ref_frame(test_rng_range(rng, -30, 30), test_rng_range(rng, -30, 30),
                                         1 + test_rng_range(rng, 0, 1), 1 + test_rng_range(rng, 0, 1),
                                         12u + test_rng_u32(rng) % 19u, 8u + test_rng_u32(rng) % 15u);
        uint32_t n = 9u + test_rng_u32(rng) % 12u;
        random_sites(rng, &f, n);
        vor_raster_sites_t set = point_set(point_metrics[m], n);
        check_frame("random", &f, &set, ks, 4);
    }
}

/* K past the site count: the ranks there are, then VOR_RASTER_NO_SITE;
 * the K-th label is the last ranked (the farthest; for FARTHEST the
 * nearest); one site; the largest K. */
static void few_site_cases(test_rng_t *rng)
{
    static const uint32_t ks[] = {4, 5, VOR_RASTER_MAX_NEAREST};
    vor_raster_frame_t f = ref_frame(-4, -3, 1, 1, 17, 11);
    for (unsigned m = 0; m < POINT_METRICS; m++) {
        random_sites(rng, &f, 3);
        vor_raster_sites_t set = point_set(point_metrics[m], 3);
        check_frame("few", &f, &set, ks, 3);
        set.count = 1;
        check_frame("one", &f, &set, ks, 1);
    }
    /* the largest K with more sites than that */
    random_sites(rng, &f, MAX_SITES);
    vor_raster_sites_t set = point_set(VOR_METRIC_EUCLID, MAX_SITES);
    check_frame("most", &f, &set, &ks[2], 1);
}

/* A lattice (ties along diagonals and at cell corners), collinear sites,
 * coincident sites (ties by index): every metric. */
static void degenerate_cases(test_rng_t *rng)
{
    static const uint32_t ks[] = {2, 3, 8};
    vor_raster_frame_t f = ref_frame(0, 0, 1, 1, 24, 18);
    for (unsigned m = 0; m < POINT_METRICS; m++) {
        uint32_t n = 0;
        for (int32_t y = 0; y <= 18; y += 6) {
            for (int32_t x = 0; x <= 24; x += 8) {
                points[n].x = x;
                points[n].y = y;
                mult[n] = 2;
                add[n] = 3;
                power[n] = 10;
                palette[n] = (uint16_t)(n * 2777u);
                n++;
            }
        }
        vor_raster_sites_t set = point_set(point_metrics[m], n);
        set.form_a = 1;
        set.form_b = 0;
        set.form_c = 1;
        check_frame("lattice", &f, &set, ks, 3);
        /* collinear, evenly spaced, with a coincident pair */
        for (uint32_t s = 0; s < 9u; s++) {
            points[s].x = -3 + 4 * (int32_t)s;
            points[s].y = 9;
        }
        points[8] = points[2];
        check_frame("collinear", &f, &set, ks, 3);
        /* every site at one point: the ranks are the indices */
        random_sites(rng, &f, 6);
        for (uint32_t s = 0; s < 6u; s++) {
            points[s].x = 11;
            points[s].y = 7;
            mult[s] = 3;
            add[s] = 1;
            power[s] = 0;
        }
        set.count = 6;
        check_frame("coincident", &f, &set, ks, 3);
    }
}

/* The shaped sites rank the same way (a case each). */
static void shaped_cases(test_rng_t *rng)
{
    static const uint32_t ks[] = {2, 3};
    vor_raster_frame_t f = ref_frame(-10, -8, 1, 1, 20, 14);
    random_sites(rng, &f, 8);
    random_points(rng, &f, 4u * 8u);
    for (uint32_t s = 0; s <= 8u; s++) {
        offsets[s] = 4u * s;
    }
    vor_raster_sites_t set = point_set(VOR_METRIC_HAUSDORFF, 8);
    check_frame("shaped", &f, &set, ks, 2);
    set.metric = VOR_METRIC_POLYGON;
    check_frame("shaped", &f, &set, ks, 2);
    set.metric = VOR_METRIC_POLYLINE;
    check_frame("shaped", &f, &set, ks, 2);
    set.metric = VOR_METRIC_SEGMENT;
    check_frame("shaped", &f, &set, ks, 2);
}

/* Every band height of one frame, for the kinds written one row late
 * (KSETS, BOUNDARY) and in place (NEAREST). */
static void band_height_cases(test_rng_t *rng)
{
    vor_raster_frame_t f = ref_frame(3, -2, 2, 1, 13, 9);
    random_sites(rng, &f, 12);
    vor_raster_sites_t set = point_set(VOR_METRIC_EUCLID, 12);
    reference_frame(&f, &set, 3, "bands");
    for (uint32_t rows = 1; rows <= f.height + 1u; rows++) {
        render_kind("bands", &f, &set, 3, VOR_RASTER_FAST, rows, VOR_RASTER_KSETS);
        render_kind("bands", &f, &set, 3, VOR_RASTER_FAST, rows, VOR_RASTER_NEAREST);
        render_kind("bands", &f, &set, 2, VOR_RASTER_BRUTE, rows, VOR_RASTER_BOUNDARY);
    }
    /* the K-th label in every label and colour kind */
    static const enum vor_raster_kind kinds[] = {VOR_RASTER_LABEL8, VOR_RASTER_LABEL16,
                                                 VOR_RASTER_RGB565, VOR_RASTER_RGB888};
    for (unsigned q = 0; q < 4u; q++) {
        render_kind("kinds", &f, &set, 3, VOR_RASTER_FAST, 4, kinds[q]);
    }
}

/* A frame wide enough that the tile lists of far sites (whose bounds
 * overlap) overflow the culling pool: those tiles take every site. */
static void pool_case(void)
{
    vor_raster_frame_t f = ref_frame(0, 0, 1, 1, 320, 2);
    static const enum vor_metric metrics[] = {VOR_METRIC_EUCLID, VOR_METRIC_L1,
                                              VOR_METRIC_FARTHEST};
    for (unsigned m = 0; m < 3u; m++) {
        for (uint32_t s = 0; s < 3u; s++) {
            points[s].x = 160;
            points[s].y = 100000 + (int32_t)s;
            palette[s] = (uint16_t)(0x0841u * (s + 1u));
        }
        vor_raster_sites_t set = point_set(metrics[m], 3);
        reference_frame(&f, &set, 2, "pool");
        render_kind("pool", &f, &set, 2, VOR_RASTER_FAST, 1, VOR_RASTER_NEAREST);
        render_kind("pool", &f, &set, 2, VOR_RASTER_FAST, 2, VOR_RASTER_KSETS);
    }
}

/* A flush that stops the frame: VOR_ERR_STOPPED after the bands before
 * it, for the in-place and the late kinds. */
static void stop_cases(test_rng_t *rng)
{
    vor_raster_frame_t f = ref_frame(0, 0, 1, 1, 10, 9);
    random_sites(rng, &f, 7);
    vor_raster_sites_t set = point_set(VOR_METRIC_L1, 7);
    static const enum vor_raster_kind kinds[] = {VOR_RASTER_NEAREST, VOR_RASTER_KSETS,
                                                 VOR_RASTER_LABEL32};
    for (unsigned q = 0; q < 3u; q++) {
        capture_t cap = {0, f.width, kinds[q] == VOR_RASTER_NEAREST ? 2u : 1u,
                         kinds[q] == VOR_RASTER_KSETS ? 2u : 4u, 2, 0, 0};
        vor_raster_output_t out = {0};
        out.kind = kinds[q];
        out.band = band_memory;
        out.band_bytes = sizeof band_memory;
        out.band_rows = 3;
        out.flush = capture_flush;
        out.user = &cap;
        out.palette565 = palette;
        int err = vor_raster_nearest(&f, &set, 2, &out, NULL, work, sizeof work);
        CHECK(err == VOR_ERR_STOPPED && cap.flushes == 2u && cap.next_row == 6u,
              "kind %d: stop gave %d after %u flushes", (int)kinds[q], err, cap.flushes);
    }
}

/* KSETS without options: boundaries black (0). */
static void default_boundary_case(test_rng_t *rng)
{
    vor_raster_frame_t f = ref_frame(-2, 1, 1, 2, 14, 9);
    random_sites(rng, &f, 7);
    vor_raster_sites_t set = point_set(VOR_METRIC_LINF, 7);
    reference_frame(&f, &set, 2, "default");
    capture_t cap = {0, f.width, 1, 2, 0, 0, 0};
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_KSETS;
    out.band = band_memory;
    out.band_bytes = sizeof band_memory;
    out.band_rows = 4;
    out.flush = capture_flush;
    out.user = &cap;
    out.palette565 = palette;
    int err = vor_raster_nearest(&f, &set, 2, &out, NULL, work, sizeof work);
    uint32_t wrong = 0, w = f.width, h = f.height, edges = 0;
    for (uint32_t p = 0; p < w * h; p++) {
        uint32_t i = p % w, j = p / w;
        int edge = (i + 1u < w && !same_kset(p, p + 1u, 2, 7)) || (j + 1u < h && !same_kset(p, p + w, 2, 7));
        edges += (uint32_t)edge;
        wrong += got[p] != (edge ? 0u : kset_colour(p, 2, 7));
    }
    CHECK(err == VOR_OK && wrong == 0 && edges > 0, "default boundary: err %d, %u pixels wrong", err,
          wrong);
}

/* Every argument error, with nothing written. */
static void error_cases(void)
{
    vor_raster_frame_t f = ref_frame(0, 0, 1, 1, 8, 4);
    for (uint32_t s = 0; s < 5u; s++) {
        points[s].x = (int32_t)s * 2;
        points[s].y = 1;
        palette[s] = 0x1234u;
        mult[s] = 1;
    }
    vor_raster_sites_t set = point_set(VOR_METRIC_EUCLID, 5);
    capture_t cap = {0, 8, 1, 4, 0, 0, 0};
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_NEAREST;
    out.band = band_memory;
    out.band_bytes = 8u * 4u * 4u * 3u; /* K = 3, 4 rows */
    out.band_rows = 4;
    out.flush = capture_flush;
    out.user = &cap;
    out.areas = areas;
    size_t need = VOR_RASTER_NEAREST_WORK_BYTES(5, 8, 3);
    for (uint32_t p = 0; p < 96u; p++) {
        band_memory[p] = 0xA5A5A5A5u;
    }
    for (uint32_t s = 0; s < 5u; s++) {
        areas[s] = 0xBEEFu;
    }
    vor_raster_options_t bad_method = {(enum vor_raster_method)2, 0};
    vor_raster_frame_t zero = f;
    zero.width = 0;
    struct {
        int want;
        int got;
    } r[20];
    unsigned n = 0;
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster_nearest(&f, &set, 0, &out, NULL, work, need);
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster_nearest(&f, &set, VOR_RASTER_MAX_NEAREST + 1u, &out, NULL, work, sizeof work);
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster_nearest(NULL, &set, 3, &out, NULL, work, need);
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster_nearest(&f, NULL, 3, &out, NULL, work, need);
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster_nearest(&f, &set, 3, NULL, NULL, work, need);
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster_nearest(&f, &set, 3, &out, NULL, NULL, need);
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster_nearest(&zero, &set, 3, &out, NULL, work, need);
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster_nearest(&f, &set, 3, &out, &bad_method, work, need);
    /* too small a band for 3 labels a pixel, too little work, misaligned */
    out.band_bytes--;
    r[n].want = VOR_ERR_NOMEM;
    r[n++].got = vor_raster_nearest(&f, &set, 3, &out, NULL, work, need);
    out.band_bytes++;
    r[n].want = VOR_ERR_NOMEM;
    r[n++].got = vor_raster_nearest(&f, &set, 3, &out, NULL, work, need - 1u);
    r[n].want = VOR_ERR_NOMEM;
    r[n++].got = vor_raster_nearest(&f, &set, 3, &out, NULL, work, VOR_RASTER_WORK_BYTES(5, 8) - 1u);
    r[n].want = VOR_ERR_ALIGN;
    r[n++].got = vor_raster_nearest(&f, &set, 3, &out, NULL, work + 4, need);
    /* KSETS without a palette; an unknown kind; vor_raster refuses the
     * k-order kinds */
    out.kind = VOR_RASTER_KSETS;
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster_nearest(&f, &set, 3, &out, NULL, work, need);
    out.kind = (enum vor_raster_kind)9;
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster_nearest(&f, &set, 3, &out, NULL, work, need);
    out.kind = VOR_RASTER_NEAREST;
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster(&f, &set, &out, NULL, work, need);
    /* a metric's field out of range; no sites */
    set.metric = VOR_METRIC_LP;
    set.lp_exponent = 0;
    r[n].want = VOR_ERR_ARG;
    r[n++].got = vor_raster_nearest(&f, &set, 3, &out, NULL, work, need);
    set.metric = VOR_METRIC_EUCLID;
    set.count = 0;
    r[n].want = VOR_ERR_EMPTY;
    r[n++].got = vor_raster_nearest(&f, &set, 3, &out, NULL, work, need);
    for (unsigned q = 0; q < n; q++) {
        CHECK(r[q].got == r[q].want, "error case %u: %d, want %d", q, r[q].got, r[q].want);
    }
    uint32_t touched = cap.flushes;
    for (uint32_t p = 0; p < 96u; p++) {
        touched += band_memory[p] != 0xA5A5A5A5u;
    }
    for (uint32_t s = 0; s < 5u; s++) {
        touched += areas[s] != 0xBEEFu;
    }
    CHECK(touched == 0, "a failing call wrote %u values", touched);
    /* exactly the documented memory works */
    set.count = 5;
    out.band_bytes = 8u * 4u * 4u * 3u;
    CHECK(vor_raster_nearest(&f, &set, 3, &out, NULL, work, need) == VOR_OK, "exact memory");
}

void test_korder(void)
{
    test_rng_t rng;
    TEST_CASE("errors") error_cases();
    TEST_CASE("random") random_cases(test_rng_seed(&rng, 2727));
    TEST_CASE("few_sites") few_site_cases(test_rng_seed(&rng, 2727));
    TEST_CASE("degenerate") degenerate_cases(test_rng_seed(&rng, 2727));
    TEST_CASE("shaped") shaped_cases(test_rng_seed(&rng, 2727));
    TEST_CASE("band_heights") band_height_cases(test_rng_seed(&rng, 2727));
    TEST_CASE("stop") stop_cases(test_rng_seed(&rng, 2727));
    TEST_CASE("pool") pool_case();
    TEST_CASE("default_boundary") default_boundary_case(test_rng_seed(&rng, 2727));
}
