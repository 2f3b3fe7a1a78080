/* SPDX-License-Identifier: MIT */
/*
 * test_field.c - vor_field_raster against independent references:
 *   - tests/vectors/field_vectors.h: whole 20 x 12 frames (random sites,
 *     a cocircular grid with ties and halves, collinear sites, steps > 1
 *     with values near 2^30, a hull with collinear sides), every pixel the
 *     Sibson and the Laplace interpolant at its centre from coordinates by
 *     exact rational clipping in Python (tools/gen_interpolate_vectors.py
 *     --field), with each pixel's count of natural neighbours;
 *   - RGB565: the ramp index floor(256 (v - low) / (high - low + 1)),
 *     computed here by a 64-bit division from the brute force's values;
 *   - bands of 1, 5 (the last one partial), 7, 12 and 13 rows, every
 *     band's rows checked as delivered, the buffer past the band intact;
 *   - every error of the contract: argument errors write nothing (band,
 *     max_neighbours, no flush); a flush's stop; a scratch too small
 *     stops at the first pixel with more neighbours, after the bands
 *     before it, with *max_neighbours.
 */
#include "test.h"
#include "vor_raster.h"
#include "field_vectors.h"

#define FT_SITES 16u
#define FT_PIXELS 240u      /* 20 x 12 */
#define FT_GUARD 16u        /* pixels past the band, which must stay */

static uint8_t ft_arena[VOR_ARENA_BYTES(FT_SITES)] __attribute__((aligned(8)));
static uint8_t ft_scratch[VOR_SIBSON_SCRATCH_BYTES(8) + 8u];
static uint32_t ft_first[FT_SITES];
static int32_t ft_band[(13u * 20u) + FT_GUARD]; /* up to 13 rows */
static int32_t ft_frame_px[FT_PIXELS];     /* the rows the flushes delivered */
static uint16_t ft_ramp[256];

/* What the flush saw. */
typedef struct {
    const vor_raster_frame_t *frame;
    size_t pixel_bytes;
    uint32_t calls;
    uint32_t next_row;  /* the rows must come in order, without gaps */
    uint32_t band_rows;
    uint32_t bad;
    uint32_t stop_at;   /* the call that returns nonzero (0: none) */
} ft_sink_t;

static int ft_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    ft_sink_t *s = user;
    uint32_t w = s->frame->width;
    s->calls++;
    bool last = (first_row + rows) == s->frame->height;
    if ((first_row != s->next_row) || (rows == 0u) || (pixels != (const void *)ft_band) ||
        ((rows != s->band_rows) && !last) || (rows > s->band_rows)) {
        s->bad++;
    }
    for (uint32_t k = 0; (k < rows * w) && ((first_row * w) + k) < FT_PIXELS; k++) {
        ft_frame_px[(first_row * w) + k] = (s->pixel_bytes == 4u)
                                               ? ((const int32_t *)pixels)[k]
                                               : (int32_t)((const uint16_t *)pixels)[k];
    }
    s->next_row = first_row + rows;
    return (s->calls == s->stop_at) ? 7 : 0;
}

static bool ft_build(vor_t *d, const fv_frame_t *f)
{
    return (vor_init(d, ft_arena, sizeof ft_arena, FT_SITES) == VOR_OK) &&
           (vor_build(d, f->sites, f->n, NULL, ft_first) == VOR_OK);
}

static void ft_fill(void *p, size_t n, uint8_t byte)
{
    for (size_t i = 0; i < n; i++) {
        ((uint8_t *)p)[i] = byte;
    }
}

static bool ft_filled(const void *p, size_t n, uint8_t byte)
{
    for (size_t i = 0; i < n; i++) {
        if (((const uint8_t *)p)[i] != byte) {
            return false;
        }
    }
    return true;
}

/* An output of the kind into ft_band, band_rows rows, flushed to s. */
static vor_field_output_t ft_output(enum vor_field_kind kind, uint32_t band_rows, const fv_frame_t *f,
                                    ft_sink_t *s, uint32_t *most)
{
    vor_field_output_t out = {0};
    size_t pixel_bytes = (kind == VOR_FIELD_VALUE) ? 4u : 2u;
    out.kind = kind;
    out.band = ft_band;
    out.band_bytes = (size_t)band_rows * f->frame.width * pixel_bytes;
    out.band_rows = band_rows;
    out.flush = ft_flush;
    out.user = s;
    out.outside = FV_OUTSIDE;
    out.ramp565 = ft_ramp;
    out.outside565 = 0xF81Fu;
    out.max_neighbours = most;
    s->frame = &f->frame;
    s->pixel_bytes = pixel_bytes;
    s->calls = 0;
    s->next_row = 0;
    s->band_rows = band_rows;
    s->bad = 0;
    s->stop_at = 0;
    ft_fill(ft_band, sizeof ft_band, 0x5Au);
    ft_fill(ft_frame_px, sizeof ft_frame_px, 0xC3u);
    return out;
}

/* The largest count of a frame's pixels [0, upto). */
static uint32_t ft_most(const uint8_t *count, uint32_t upto)
{
    uint32_t most = 0;
    for (uint32_t k = 0; k < upto; k++) {
        most = (count[k] > most) ? count[k] : most;
    }
    return most;
}

/* Every pixel of frame f (VALUE) against the brute force, in bands of
 * band_rows; Sibson's or Laplace's. */
static void check_frame(const fv_frame_t *f, bool laplace, uint32_t band_rows)
{
    vor_t d;
    ft_sink_t s;
    uint32_t most = 0xDEADu;
    CHECK(ft_build(&d, f), "built");
    vor_field_output_t out = ft_output(VOR_FIELD_VALUE, band_rows, f, &s, &most);
    vor_field_options_t options = {laplace ? VOR_FIELD_LAPLACE : VOR_FIELD_SIBSON};
    int err = vor_field_raster(&d, f->values, &f->frame, &out, &options, ft_scratch, sizeof ft_scratch);
    const int32_t *want = laplace ? f->laplace : f->sibson;
    uint32_t bad = 0;
    uint32_t inside = 0;
    for (uint32_t k = 0; k < FT_PIXELS; k++) {
        bad += (ft_frame_px[k] == want[k]) ? 0u : 1u;
        inside += (want[k] != FV_OUTSIDE) ? 1u : 0u;
        if ((ft_frame_px[k] != want[k]) && (bad < 4u)) {
            test_printf("  pixel (%u, %u): %d, brute force %d\n", (unsigned)(k % 20u),
                        (unsigned)(k / 20u), (int)ft_frame_px[k], (int)want[k]);
        }
    }
    uint32_t bands = (f->frame.height + band_rows - 1u) / band_rows;
    CHECK(err == VOR_OK, "%s: %d", f->name, err);
    CHECK(bad == 0u, "%s: %u of %u pixels differ (%u inside)", f->name, bad, FT_PIXELS, inside);
    CHECK((s.bad == 0u) && (s.calls == bands) && (s.next_row == f->frame.height),
          "%s: %u bands in order, got %u calls, %u bad", f->name, bands, s.calls, s.bad);
    CHECK(most == ft_most(laplace ? f->laplace_count : f->sibson_count, FT_PIXELS),
          "%s: max_neighbours %u", f->name, most);
    CHECK(ft_filled(ft_band + (band_rows * f->frame.width), sizeof ft_band - (band_rows * f->frame.width * 4u), 0x5Au),
          "%s: nothing written past the band", f->name);
}

/* An index of the ramp, independently: the formula with a division. */
static uint32_t ft_index(int32_t v, int32_t low, int32_t high)
{
    int64_t i = (256 * ((int64_t)v - low)) / ((int64_t)high - low + 1);
    return (v < low) ? 0u : (i > 255) ? 255u : (uint32_t)i;
}

static void check_rgb565(const fv_frame_t *f, int32_t low, int32_t high, uint32_t band_rows)
{
    vor_t d;
    ft_sink_t s;
    CHECK(ft_build(&d, f), "built");
    for (uint32_t i = 0; i < 256u; i++) {
        ft_ramp[i] = (uint16_t)((i * 0x9E37u) ^ 0x1234u); /* all different */
    }
    vor_field_output_t out = ft_output(VOR_FIELD_RGB565, band_rows, f, &s, NULL);
    out.low = low;
    out.high = high;
    int err = vor_field_raster(&d, f->values, &f->frame, &out, NULL, ft_scratch, sizeof ft_scratch);
    uint32_t bad = 0;
    uint32_t clamped = 0;
    for (uint32_t k = 0; k < FT_PIXELS; k++) {
        int32_t v = f->sibson[k];
        uint16_t want = (v == FV_OUTSIDE) ? 0xF81Fu : ft_ramp[ft_index(v, low, high)];
        bad += (ft_frame_px[k] == (int32_t)want) ? 0u : 1u;
        clamped += ((v != FV_OUTSIDE) && ((v < low) || (v > high))) ? 1u : 0u;
    }
    CHECK(err == VOR_OK, "%s: %d", f->name, err);
    CHECK(bad == 0u, "%s: %u of %u colours differ (%u clamped)", f->name, bad, FT_PIXELS, clamped);
    CHECK(s.bad == 0u, "%s: bands in order", f->name);
}

/* The ramp index at the ends of its range and of int32: every boundary of
 * floor(256 (v - low) / (high - low + 1)) on one-pixel frames of a single
 * site (the value of the site itself). */
static void check_ramp_edges(void)
{
    static const vor_point_t one[] = {{3, 2}};
    static const struct {
        int32_t v, low, high;
    } cases[] = {
        {0, 0, 1},   {1, 0, 1},   {-1, 0, 1},  {2, 0, 1},   {5, 0, 255}, {255, 0, 255},
        {256, 0, 255}, {99, 0, 99}, {100, 0, 299}, {INT32_MAX, INT32_MIN, INT32_MAX},
        {INT32_MIN, INT32_MIN, INT32_MAX}, {0, INT32_MIN, INT32_MAX}, {-1, INT32_MIN, INT32_MAX},
        {INT32_MAX - 1, INT32_MAX - 2, INT32_MAX}, {INT32_MIN, INT32_MIN + 1, INT32_MAX},
        {16777215, 0, 16777215}, {16777216, 0, 1073741823}, {-7, -10, -3},
    };
    fv_frame_t f = {"one", 1u, one, NULL, {3, 2, 1, 1, 1u, 1u}, NULL, NULL, NULL, NULL};
    vor_t d;
    ft_sink_t s;
    CHECK(ft_build(&d, &f), "built");
    for (uint32_t i = 0; i < 256u; i++) {
        ft_ramp[i] = (uint16_t)i;
    }
    uint32_t bad = 0;
    for (uint32_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        vor_field_output_t out = ft_output(VOR_FIELD_RGB565, 1u, &f, &s, NULL);
        out.low = cases[c].low;
        out.high = cases[c].high;
        int err = vor_field_raster(&d, &cases[c].v, &f.frame, &out, NULL, ft_scratch, sizeof ft_scratch);
        uint32_t want = ft_index(cases[c].v, cases[c].low, cases[c].high);
        if ((err != VOR_OK) || (ft_frame_px[0] != (int32_t)want)) {
            bad++;
            test_printf("  case %u: index %d, want %u\n", c, (int)ft_frame_px[0], want);
        }
    }
    CHECK(bad == 0u, "%u ramp indices differ", bad);
}

/* One site: its pixel its value, every other pixel outside. */
static void check_one_site(void)
{
    static const vor_point_t one[] = {{3, 2}};
    static const int32_t value[] = {-42};
    fv_frame_t f = {"one", 1u, one, value, {0, 0, 1, 1, 20u, 12u}, NULL, NULL, NULL, NULL};
    vor_t d;
    ft_sink_t s;
    uint32_t most = 0;
    CHECK(ft_build(&d, &f), "built");
    vor_field_output_t out = ft_output(VOR_FIELD_VALUE, 12u, &f, &s, &most);
    out.outside = 77;
    CHECK(vor_field_raster(&d, value, &f.frame, &out, NULL, ft_scratch, sizeof ft_scratch) == VOR_OK, "rendered");
    uint32_t bad = 0;
    for (uint32_t k = 0; k < FT_PIXELS; k++) {
        bad += (ft_frame_px[k] == ((k == (2u * 20u) + 3u) ? -42 : 77)) ? 0u : 1u;
    }
    CHECK((bad == 0u) && (most == 1u) && (s.calls == 1u), "%u pixels wrong, max_neighbours %u", bad, most);
}

/* Every argument error: VOR_ERR_ARG / EMPTY / NOMEM, and nothing written
 * (band, max_neighbours), no flush called. */
static void check_errors(void)
{
    const fv_frame_t *f = &fv_frames[0];
    vor_t d;
    vor_t empty;
    ft_sink_t s;
    uint32_t most = 0xDEADu;
    CHECK(ft_build(&d, f), "built");
    static uint8_t empty_arena[VOR_ARENA_BYTES(4)] __attribute__((aligned(8)));
    CHECK(vor_init(&empty, empty_arena, sizeof empty_arena, 4u) == VOR_OK, "init");
    vor_field_output_t good = ft_output(VOR_FIELD_VALUE, 5u, f, &s, &most);
    vor_field_options_t bad_method = {(enum vor_field_method)2};
    vor_raster_frame_t frame;
    vor_field_output_t out;
    uint32_t wrong = 0;
    for (unsigned c = 0; c < 24u; c++) {
        const vor_t *dp = &d;
        const int32_t *values = f->values;
        const vor_raster_frame_t *fp = &frame;
        const vor_field_output_t *op = &out;
        const vor_field_options_t *options = NULL;
        void *scratch = ft_scratch;
        size_t scratch_bytes = sizeof ft_scratch;
        int want = VOR_ERR_ARG;
        frame = f->frame;
        out = good;
        switch (c) {
        case 0: dp = NULL; break;
        case 1: values = NULL; break;
        case 2: fp = NULL; break;
        case 3: op = NULL; break;
        case 4: out.band = NULL; break;
        case 5: out.flush = NULL; break;
        case 6: out.band_rows = 0; break;
        case 7: frame.width = 0; break;
        case 8: frame.height = 0; break;
        case 9: frame.step_x = 0; break;
        case 10: frame.step_y = -1; break;
        case 11: frame.origin_x = INT32_MAX - 18; break; /* the last centre past int32 */
        case 12: frame.origin_y = INT32_MAX; frame.step_y = 3; break;
        case 13: out.kind = (enum vor_field_kind)2; break;
        case 14: options = &bad_method; break;
        case 15: out.kind = VOR_FIELD_RGB565; out.ramp565 = NULL; break;
        case 16: out.kind = VOR_FIELD_RGB565; out.low = 5; out.high = 5; break;
        case 17: scratch = NULL; break;
        case 18: dp = &empty; want = VOR_ERR_EMPTY; break;
        case 19: out.band_bytes--; want = VOR_ERR_NOMEM; break;
        case 20: out.kind = VOR_FIELD_RGB565; out.low = 0; out.high = 1;
                 out.band_bytes = (5u * 20u * 2u) - 1u; want = VOR_ERR_NOMEM; break;
        case 21: frame.width = 0x08000000u; frame.origin_x = INT32_MIN; break; /* too wide to size */
        case 22: out.kind = (enum vor_field_kind)-1; break;
        default: out.band_bytes = 0; out.band_rows = 0xFFFFFFFFu; want = VOR_ERR_NOMEM; break;
        }
        most = 0xDEADu;
        s.calls = 0;
        ft_fill(ft_band, sizeof ft_band, 0x5Au);
        int err = vor_field_raster(dp, values, fp, op, options, scratch, scratch_bytes);
        bool ok = (err == want) && ft_filled(ft_band, sizeof ft_band, 0x5Au) && (most == 0xDEADu) &&
                  (s.calls == 0u);
        if (!ok) {
            wrong++;
            test_printf("  case %u: %d, want %d\n", c, err, want);
        }
    }
    CHECK(wrong == 0u, "%u argument errors wrong or wrote something", wrong);
}

/* A flush returning nonzero stops the render: VOR_ERR_STOPPED after it,
 * the bands before it delivered, max_neighbours of the rows done. */
static void check_stopped(void)
{
    const fv_frame_t *f = &fv_frames[3];
    vor_t d;
    ft_sink_t s;
    uint32_t most = 0;
    CHECK(ft_build(&d, f), "built");
    vor_field_output_t out = ft_output(VOR_FIELD_VALUE, 5u, f, &s, &most);
    s.stop_at = 2;
    int err = vor_field_raster(&d, f->values, &f->frame, &out, NULL, ft_scratch, sizeof ft_scratch);
    uint32_t bad = 0;
    for (uint32_t k = 0; k < 200u; k++) {
        bad += (ft_frame_px[k] == f->sibson[k]) ? 0u : 1u;
    }
    CHECK((err == VOR_ERR_STOPPED) && (s.calls == 2u) && (s.next_row == 10u) && (bad == 0u),
          "stopped after the second band: %d, %u calls, %u bad", err, s.calls, bad);
    CHECK(most == ft_most(f->sibson_count, 200u), "max_neighbours of the rows done: %u", most);
}

/* Scratch for k neighbours only: VOR_ERR_NOMEM at the first pixel that
 * has more (in row-major order), after the bands before its row, with
 * *max_neighbours its count (the largest so far). */
static void check_nomem(const fv_frame_t *f, uint32_t k, uint32_t band_rows, bool null_scratch)
{
    vor_t d;
    ft_sink_t s;
    uint32_t most = 0;
    CHECK(ft_build(&d, f), "built");
    vor_field_output_t out = ft_output(VOR_FIELD_VALUE, band_rows, f, &s, &most);
    uint32_t first = 0;
    while ((first < FT_PIXELS) && (f->sibson_count[first] <= k)) {
        first++;
    }
    int err = vor_field_raster(&d, f->values, &f->frame, &out, NULL, null_scratch ? NULL : ft_scratch,
                               null_scratch ? 0u : VOR_SIBSON_SCRATCH_BYTES(k));
    uint32_t row = first / f->frame.width;
    uint32_t delivered = (row / band_rows) * band_rows;
    uint32_t bad = 0;
    for (uint32_t p = 0; p < delivered * f->frame.width; p++) {
        bad += (ft_frame_px[p] == f->sibson[p]) ? 0u : 1u;
    }
    CHECK(first < FT_PIXELS, "%s: a pixel with more than %u neighbours", f->name, k);
    CHECK((err == VOR_ERR_NOMEM) && (s.calls == row / band_rows) && (s.next_row == delivered) && (bad == 0u),
          "%s, k = %u: NOMEM at row %u after %u rows: %d, %u calls, %u bad", f->name, k, row, delivered,
          err, s.calls, bad);
    CHECK(most == f->sibson_count[first], "%s: max_neighbours %u, want %u", f->name, most,
          (unsigned)f->sibson_count[first]);
}

void test_field(void)
{
    static const uint32_t band_rows[] = {1u, 5u, 7u, 12u, 13u};
    for (uint32_t i = 0; i < sizeof fv_frames / sizeof fv_frames[0]; i++) {
        const fv_frame_t *f = &fv_frames[i];
        TEST_CASE("vectors/%s", f->name) check_frame(f, false, band_rows[i % 5u]);
        TEST_CASE("laplace/%s", f->name) check_frame(f, true, band_rows[(i + 2u) % 5u]);
    }
    TEST_CASE("rgb565/random") check_rgb565(&fv_frames[0], -500, 700, 5u);
    TEST_CASE("rgb565/narrow") check_rgb565(&fv_frames[1], 0, 2, 3u);  /* most clamped, span < 256 */
    TEST_CASE("rgb565/wide") check_rgb565(&fv_frames[3], INT32_MIN, INT32_MAX, 12u);
    TEST_CASE("rgb565/line") check_rgb565(&fv_frames[2], -20, 1000, 1u);
    TEST_CASE("ramp_edges") check_ramp_edges();
    TEST_CASE("one_site") check_one_site();
    TEST_CASE("errors") check_errors();
    TEST_CASE("stopped") check_stopped();
    TEST_CASE("nomem/grid") check_nomem(&fv_frames[1], 4u, 5u, false);
    TEST_CASE("nomem/steps") check_nomem(&fv_frames[3], 5u, 1u, false);
    TEST_CASE("nomem/none") check_nomem(&fv_frames[0], 0u, 2u, true);
}
