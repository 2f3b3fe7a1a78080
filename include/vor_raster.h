/* SPDX-License-Identifier: MIT */
/*
 * vor_raster.h - exact discrete Voronoi diagrams, rendered in bands.
 *
 * A frame is a grid of pixels with integer world centres: pixel (i, j) is
 * at (origin_x + i * step_x, origin_y + j * step_y), i < width, j < height,
 * steps > 0. Each pixel gets the index of its nearest site; of several at
 * the same distance, the smallest index (Teramoto, Definition 2.2, the
 * discrete Voronoi diagram). Every decision is exact integer arithmetic:
 * no square root, no floating point, no sampling of the distance, so each
 * pixel equals a brute-force search with exact distances.
 *
 *     static uint16_t band[16 * 320];               // 16 rows of RGB565
 *     static uint8_t work[VOR_RASTER_WORK_BYTES(256, 320)]
 *         __attribute__((aligned(VOR_RASTER_WORK_ALIGN)));
 *     vor_raster_frame_t frame = {0, 0, 1, 1, 320, 240};
 *     vor_raster_sites_t set = {0};                // VOR_METRIC_EUCLID
 *     set.points = sites; set.count = 256;
 *     vor_raster_output_t out = {0};
 *     out.kind = VOR_RASTER_RGB565; out.palette565 = colours;
 *     out.band = band; out.band_bytes = sizeof band; out.band_rows = 16;
 *     out.flush = send_to_display; out.user = &lcd;
 *     int err = vor_raster(&frame, &set, &out, NULL, work, sizeof work);
 *
 *   options: NULL (or a zero-initialised vor_raster_options_t) for the
 *   defaults, as for every call of vor that takes options (vor.h).
 *
 * BANDS
 *   The caller's buffer holds band_rows rows of width pixels; the rows are
 *   filled top (j = 0) down and handed to flush(user, first_row, rows,
 *   pixels) once per band, like the partial rendering of display
 *   libraries. No full frame is ever needed. flush returns 0 to go on; any
 *   other value stops the render and vor_raster returns VOR_ERR_STOPPED
 *   (the flush's own codes never mix with vor's errors).
 *
 * OUTPUT KINDS (pixel layout in the band, row-major, row stride = width)
 *   VOR_RASTER_LABEL8 / 16 / 32  the site index as uint8_t / uint16_t /
 *                                uint32_t (8 and 16 need count <= 256 /
 *                                65,536)
 *   VOR_RASTER_RGB565            uint16_t palette565[site] (swap the
 *                                palette's bytes for a big-endian display)
 *   VOR_RASTER_RGB888            3 bytes R, G, B of palette888[site]
 *                                (0xRRGGBB)
 *   VOR_RASTER_BOUNDARY          uint8_t 1 where the right or lower
 *                                neighbour has another label, else 0
 *                                (correct across band seams)
 *   VOR_RASTER_DISTANCE          uint32_t distance to the pixel's site
 *                                under the metric (the one that decided
 *                                the label), rounded down (floor),
 *                                saturated at UINT32_MAX; ADD and
 *                                COMPOUND: int32_t (two's complement),
 *                                saturated at INT32_MAX; POWER: int32_t,
 *                                saturated at both ends (see DISTANCE
 *                                VALUES)
 *   Any kind can also count each site's pixels (areas[count], optional).
 *
 * DISTANCE VALUES (exact integer floors; dx, dy = pixel - site point,
 * D = dx^2 + dy^2, isqrt(x) = floor(sqrt(x)))
 *   EUCLID, FARTHEST    isqrt(D) (FARTHEST: to the pixel's farthest site)
 *   L1                  |dx| + |dy|
 *   LINF                max(|dx|, |dy|)
 *   LP                  floor((|dx|^p + |dy|^p)^(1/p))
 *   ELLIPTIC            isqrt(a dx^2 + 2b dx dy + c dy^2)
 *   MULT                floor(sqrt(D) / w) = floor(isqrt(D) / w)
 *   ADD                 floor(sqrt(D) - w) = isqrt(D) - w, int32
 *   COMPOUND            floor(sqrt(D) / w1 - w2) = floor(isqrt(D) / w1) - w2,
 *                       int32
 *   HAUSDORFF           isqrt of the largest D over the set's points
 *   SEGMENT, POLYGON    the floor of the distance to the segment, or the
 *                       polygon's boundary (0 inside or on it)
 *   POLYLINE            floor(distance to the polyline / w)
 *   POWER               D - w itself (an integer, no rounding), int32,
 *                       clamped to [INT32_MIN, INT32_MAX]
 *   Saturation: unsigned values from 2^32 on read UINT32_MAX (only L1, Lp,
 *   elliptic forms and far Euclidean-type distances reach it); ADD and
 *   COMPOUND values above INT32_MAX read INT32_MAX (they are always above
 *   -2^31, since w2 < 2^31); POWER values clamp at both ends. The value costs a few integer roots per
 *   pixel (docs/design/raster-metrics.md, "Distance output").
 *
 * SPEED
 *   VOR_RASTER_FAST (the default method, vor_raster_options_t) finds, per band of 16 rows, the sites
 *   whose cells can reach the band (exact envelopes of the band's edges),
 *   then per row the lower envelope of their distance functions at the
 *   pixel centres, which is the row's runs (one division per run): O(n)
 *   per band and O(candidates) per row, never a test of every site at
 *   every pixel. It applies when
 *   every site lies within 2^29 of the first pixel and the frame spans
 *   less than 2^29 in each direction; otherwise (and with
 *   VOR_RASTER_BRUTE) each pixel is compared with every site, equally
 *   exact. docs/design/raster.md has the bound arguments.
 *
 * OTHER METRICS
 *   sites->metric also takes L1, L-infinity, Lp (p = 1..8), elliptic
 *   (a dx^2 + 2b dx dy + c dy^2), multiplicative, additive and compound
 *   weights, the farthest-point diagram, Hausdorff point sets, segments,
 *   filled polygons, (weighted) polylines and power diagrams (int64
 *   weights; vor_raster_sites_t says which fields each uses).
 *   Each is compared exactly, over all int32 coordinates and weights
 *   (power weights: all of int64): no valid input is out of budget.
 *   VOR_RASTER_FAST culls sites per tile of 16 x 16 pixels with exact bounds of each site's distance over the
 *   tile; VOR_RASTER_BRUTE compares every site at every pixel.
 *   VOR_RASTER_DISTANCE works with every metric (DISTANCE VALUES).
 *
 * K NEAREST (k-order diagrams, Teramoto section 2.3.4)
 *   vor_raster_nearest ranks the K nearest sites of every pixel (K
 *   farthest for FARTHEST), every metric, the same exact comparisons,
 *   ties to the smaller index; K up to VOR_RASTER_MAX_NEAREST (16).
 *
 *     static uint32_t band[8 * 320 * 3];           // 8 rows of 3 labels
 *     static uint8_t work[VOR_RASTER_NEAREST_WORK_BYTES(256, 320, 3)]
 *         __attribute__((aligned(VOR_RASTER_WORK_ALIGN)));
 *     out.kind = VOR_RASTER_NEAREST;                // nearest first
 *     out.band = band; out.band_bytes = sizeof band; out.band_rows = 8;
 *     int err = vor_raster_nearest(&frame, &set, 3, &out, NULL, work,
 *                                  sizeof work);
 *
 *   VOR_RASTER_NEAREST gives K uint32_t a pixel (VOR_RASTER_NO_SITE past
 *   the site count), VOR_RASTER_KSETS a picture of the k-sets (each the
 *   mean colour of its sites, options->boundary565 between k-sets), and every
 *   other kind the K-th nearest site: the K-th order diagram. A firmware
 *   that never calls it links none of it.
 *
 * FIELDS
 *   vor_field_raster renders a diagram's natural-neighbour interpolant
 *   (vor.h: vor_interpolate, Sibson's; or Laplace's) of int32 site values
 *   through the same bands: each pixel the exact value at its centre,
 *   rounded once, or a colour of a 256-entry RGB565 ramp over [low, high];
 *   pixels outside the sites' convex hull get a colour of their own.
 *
 *     static int32_t band[8 * 160];                 // 8 rows of values
 *     static uint8_t scratch[VOR_SIBSON_SCRATCH_BYTES(12)];
 *     uint32_t most = 0;
 *     vor_field_output_t out = {0};                 // VOR_FIELD_VALUE
 *     out.band = band; out.band_bytes = sizeof band; out.band_rows = 8;
 *     out.flush = send_rows; out.user = &ctx; out.outside = INT32_MIN;
 *     out.max_neighbours = &most;                   // optional
 *     int err = vor_field_raster(&d, values, &frame, &out, NULL,
 *                                scratch, sizeof scratch);
 *
 *   A pixel with more natural neighbours than the scratch holds stops the
 *   render with VOR_ERR_NOMEM, most saying how many it needed. No work
 *   memory: the diagram is the index (docs/design/interpolation.md,
 *   "Field frames", has the cost).
 *
 * MEMORY
 *   vor_raster's work: VOR_RASTER_WORK_BYTES(count, width) bytes, aligned to
 *   VOR_RASTER_WORK_ALIGN, a compile-time constant. Nothing else is used
 *   besides the band buffer and a small stack frame.
 *
 * FLASH
 *   vor_raster links every metric; for Euclidean point sites alone call
 *   vor_raster_euclid instead, the same pixels from much less code
 *   (docs/benchmarks.md, "Code size and stack", has the bytes).
 *
 * API: docs/api.md, "Raster".
 */
#ifndef VOR_RASTER_H
#define VOR_RASTER_H

#include "vor.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The pixel grid: pixel (i, j) has the world centre
 * (origin_x + i * step_x, origin_y + j * step_y). Every centre must be an
 * int32 point; steps and sizes are positive. */
typedef struct vor_raster_frame {
    int32_t origin_x;
    int32_t origin_y;
    int32_t step_x;
    int32_t step_y;
    uint32_t width;
    uint32_t height;
} vor_raster_frame_t;

/* The distance a pixel is assigned by (Teramoto, section 2.3 and chapter
 * 5). Every metric is decided exactly over the whole int32 range of
 * coordinates and weights (POWER: int64 weights); the comparison widths
 * are in docs/design/raster.md and docs/design/raster-metrics.md. */
enum vor_metric {
    VOR_METRIC_EUCLID = 0,    /* point sites, Euclidean distance */
    VOR_METRIC_L1 = 1,        /* point sites, |dx| + |dy| */
    VOR_METRIC_LINF = 2,      /* point sites, max(|dx|, |dy|) */
    VOR_METRIC_LP = 3,        /* point sites, (|dx|^p + |dy|^p)^(1/p), p = lp_exponent */
    VOR_METRIC_ELLIPTIC = 4,  /* point sites, sqrt(a dx^2 + 2b dx dy + c dy^2), form_* */
    VOR_METRIC_MULT = 5,      /* point sites, |q - s| / w, w = mult_weights[k] >= 1 */
    VOR_METRIC_ADD = 6,       /* point sites, |q - s| - w, w = add_weights[k] */
    VOR_METRIC_COMPOUND = 7,  /* point sites, |q - s| / w1 - w2 (both weight arrays) */
    VOR_METRIC_FARTHEST = 8,  /* point sites, the farthest site wins */
    VOR_METRIC_HAUSDORFF = 9, /* point sets, distance to the set's farthest point */
    VOR_METRIC_SEGMENT = 10,  /* line segments, Euclidean distance to the segment */
    VOR_METRIC_POLYGON = 11,  /* filled polygons, 0 inside, else to the boundary */
    VOR_METRIC_POLYLINE = 12, /* open polylines, distance to the nearest point / w */
    VOR_METRIC_POWER = 13     /* point sites, |q - s|^2 - w, w = power_weights[k] */
};

/* The sites of a frame. Fields a metric does not use are ignored, so a
 * zeroed struct with metric, points and count set is a Euclidean frame.
 *
 *   point sites (EUCLID, L1, LINF, LP, ELLIPTIC, MULT, ADD, COMPOUND,
 *   FARTHEST, POWER): site k is points[k].
 *   SEGMENT: site k is the segment points[2k] - points[2k + 1] (equal
 *   ends: a point).
 *   HAUSDORFF, POLYGON, POLYLINE: site k is points[offsets[k]] ..
 *   points[offsets[k+1] - 1], at least one point (offsets has count + 1
 *   increasing entries).
 *   A polygon's vertices go around it in either direction; 1 vertex is a
 *   point, 2 a segment, 3 or more a closed polygon whose inside (nonzero
 *   winding number) and boundary are at distance 0.
 *   POLYLINE: the vertices joined in order, not closed (a closed curve
 *   repeats its first vertex at the end); 1 vertex is a point. With
 *   mult_weights (optional, NULL: every weight 1) the distance to site k
 *   is divided by mult_weights[k] >= 1: multiplicatively weighted curves,
 *   the contour interpolation of Teramoto, chapter 6. */
typedef struct vor_raster_sites {
    enum vor_metric metric;
    const vor_point_t *points;
    uint32_t count;                 /* sites, >= 1 */
    const int32_t *mult_weights;    /* MULT, COMPOUND (, POLYLINE): [count], each >= 1 */
    const int32_t *add_weights;     /* ADD, COMPOUND: [count], any int32 */
    const uint32_t *offsets;        /* HAUSDORFF, POLYGON, POLYLINE: [count + 1] */
    uint32_t lp_exponent;           /* LP: p in 1 .. 8 */
    /* ELLIPTIC: a > 0 and a c > b^2 */
    int32_t form_a;
    int32_t form_b;
    int32_t form_c;
    const int64_t *power_weights;   /* POWER: [count], any int64 */
} vor_raster_sites_t;

enum vor_raster_kind {
    VOR_RASTER_LABEL8 = 0,
    VOR_RASTER_LABEL16 = 1,
    VOR_RASTER_LABEL32 = 2,
    VOR_RASTER_RGB565 = 3,
    VOR_RASTER_RGB888 = 4,
    VOR_RASTER_BOUNDARY = 5,
    VOR_RASTER_DISTANCE = 6,
    VOR_RASTER_NEAREST = 7, /* vor_raster_nearest only: K uint32_t labels a pixel */
    VOR_RASTER_KSETS = 8    /* vor_raster_nearest only: RGB565 of the pixel's k-set */
};

enum vor_raster_method {
    VOR_RASTER_FAST = 0, /* culling and envelopes where the bit budget allows */
    VOR_RASTER_BRUTE = 1 /* every site at every pixel (a baseline) */
};

/* flush(user, first_row, rows, pixels): rows [first_row, first_row + rows)
 * are in pixels (the band buffer). Return 0 to go on; anything else stops
 * the render, and vor_raster returns VOR_ERR_STOPPED. */
typedef int (*vor_raster_flush_t)(void *user, uint32_t first_row, uint32_t rows,
                                  const void *pixels);

/* Where the frame goes. Zero-initialise, then set what is used. */
typedef struct vor_raster_output {
    enum vor_raster_kind kind;
    void *band;          /* band_rows * width pixels of the kind */
    size_t band_bytes;
    uint32_t band_rows;  /* >= 1 */
    vor_raster_flush_t flush;
    void *user;                  /* handed to flush */
    const uint16_t *palette565;  /* RGB565: colour of site k */
    const uint32_t *palette888;  /* RGB888: 0xRRGGBB of site k */
    uint32_t *areas;             /* optional: pixels of each site, [count] */
} vor_raster_output_t;

/* How to render: NULL or a zero-initialised struct for the defaults (a
 * field added later keeps the old behaviour at 0). */
typedef struct vor_raster_options {
    enum vor_raster_method method; /* VOR_RASTER_FAST by default */
    uint16_t boundary565;          /* vor_raster_nearest's KSETS: the colour
                                      of the boundaries between k-sets
                                      (0, black, by default) */
} vor_raster_options_t;

/* Bytes per pixel of a kind (0 for an unknown kind). */
#define VOR_RASTER_PIXEL_BYTES(kind)                                           \
    ((kind) == VOR_RASTER_LABEL8 || (kind) == VOR_RASTER_BOUNDARY ? 1u         \
     : (kind) == VOR_RASTER_LABEL16 || (kind) == VOR_RASTER_RGB565 ? 2u        \
     : (kind) == VOR_RASTER_RGB888                                 ? 3u        \
     : (kind) == VOR_RASTER_LABEL32 || (kind) == VOR_RASTER_DISTANCE ? 4u      \
                                                                     : 0u)

/* vor_raster_nearest: the largest K, the label of a rank past the last
 * site (K > count), and the bytes per pixel of a kind with K ranks (4 K
 * for NEAREST, 2 for KSETS, else VOR_RASTER_PIXEL_BYTES). */
#define VOR_RASTER_MAX_NEAREST 16u
#define VOR_RASTER_NO_SITE 0xFFFFFFFFu
#define VOR_RASTER_NEAREST_PIXEL_BYTES(kind, k)                                \
    (((kind) == VOR_RASTER_NEAREST) ? (4u * (size_t)(k))                      \
     : (((kind) == VOR_RASTER_KSETS) ? 2u : VOR_RASTER_PIXEL_BYTES(kind)))

/* Work memory for up to n sites and frames up to width pixels wide: 48
 * bytes per site (sort orders, candidates, envelopes) and 16 per pixel of
 * width (two rows of runs), plus alignment slack. A constant expression. */
#define VOR_RASTER_WORK_BYTES(n, width)                                        \
    (((size_t)(n) * 48u) + ((size_t)(width) * 16u) + 64u)
#define VOR_RASTER_WORK_ALIGN 8u

/* Work memory of vor_raster_nearest for up to n sites, frames up to width
 * pixels wide and K = k: VOR_RASTER_WORK_BYTES plus 112 bytes per rank
 * and one more (the ranked distances) and 8 k bytes per pixel of width
 * (two rows of k-sets). A constant expression. */
#define VOR_RASTER_NEAREST_WORK_BYTES(n, width, k)                             \
    (VOR_RASTER_WORK_BYTES(n, width) + (((size_t)(k) + 1u) * 112u) +            \
     ((size_t)(width) * (size_t)(k) * 8u))

/*
 * Renders the discrete Voronoi diagram of sites over frame, band by band,
 * into out, with options (NULL: the defaults). Everything is checked
 * before the first pixel:
 *   VOR_ERR_ARG    a NULL pointer (options apart), a zero size or step, a pixel centre
 *                  outside int32, an unknown metric, kind or method, a
 *                  missing palette, LABEL8 with > 256 or LABEL16 with
 *                  > 65,536 sites, a metric's field out of its range or
 *                  a weight array it uses NULL (POWER: power_weights;
 *                  docs/api.md lists them)
 *   VOR_ERR_EMPTY  sites->count == 0
 *   VOR_ERR_NOMEM  band_bytes < band_rows * width * pixel bytes, or
 *                  work_bytes < VOR_RASTER_WORK_BYTES(count, width)
 *   VOR_ERR_ALIGN  work not aligned to VOR_RASTER_WORK_ALIGN
 *   VOR_ERR_STOPPED  a flush returned nonzero (bands before it were
 *                  delivered; areas then hold the rows done so far)
 * On an error before the first pixel, nothing is written (areas included).
 */
int vor_raster(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
               const vor_raster_output_t *out, const vor_raster_options_t *options,
               void *work, size_t work_bytes);

/*
 * vor_raster for Euclidean point sites only (sites->metric must be
 * VOR_METRIC_EUCLID, else VOR_ERR_ARG): the same pixels, errors and
 * memory, and a firmware that calls only this links none of the other
 * metrics. vor_raster hands Euclidean frames to it.
 */
int vor_raster_euclid(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
                      const vor_raster_output_t *out, const vor_raster_options_t *options,
                      void *work, size_t work_bytes);

/*
 * Renders the K = k nearest sites of every pixel of frame (K farthest for
 * VOR_METRIC_FARTHEST, farthest first), ranked by the same exact
 * comparisons as vor_raster, ties to the smaller index, band by band into
 * out, with options (NULL: the defaults). Every metric of vor_raster.
 * The kinds (K' = min(K, count), the ranks there are):
 *   NEAREST         K uint32_t a pixel, the sites nearest first; ranks
 *                   past K' read VOR_RASTER_NO_SITE
 *   KSETS           uint16_t: options->boundary565 (0 without options)
 *                   where the right or the lower
 *                   neighbour has another k-set (the unordered set of its
 *                   K' nearest), else the k-set's colour: per channel, the
 *                   mean (rounded down) of palette565 of its sites
 *   LABEL8 .. BOUNDARY, DISTANCE
 *                   as for vor_raster, of each pixel's K'-th nearest site:
 *                   the K-th order diagram (DISTANCE: the distance to it)
 *   areas (optional) count each site's pixels as the K'-th nearest.
 * k = 1 gives vor_raster's pixels. Work: VOR_RASTER_NEAREST_WORK_BYTES(
 * count, width, k), aligned to VOR_RASTER_WORK_ALIGN. Cost: per pixel,
 * each candidate site (VOR_RASTER_FAST: the sites of its 16-row tile that
 * can rank within K there; VOR_RASTER_BRUTE: every site) is compared once
 * with the K-th ranked and, when it ranks before it, inserted in order:
 * O(candidates + K * insertions) comparisons a pixel.
 *   VOR_ERR_ARG    as vor_raster; also k == 0 or k > VOR_RASTER_MAX_NEAREST,
 *                  KSETS with palette565 NULL
 *   VOR_ERR_EMPTY  sites->count == 0
 *   VOR_ERR_NOMEM  band_bytes < band_rows * width *
 *                  VOR_RASTER_NEAREST_PIXEL_BYTES(kind, k), or work_bytes <
 *                  VOR_RASTER_NEAREST_WORK_BYTES(count, width, k)
 *   VOR_ERR_ALIGN  work not aligned to VOR_RASTER_WORK_ALIGN
 *   VOR_ERR_STOPPED  a flush returned nonzero (as vor_raster)
 * On an error before the first pixel, nothing is written (areas included).
 */
int vor_raster_nearest(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
                       uint32_t k, const vor_raster_output_t *out,
                       const vor_raster_options_t *options, void *work, size_t work_bytes);

/* ================================================================== */
/* Fields: natural-neighbour interpolation rendered in bands          */
/* ================================================================== */

/* What each pixel of a field frame holds (row-major, stride = width). */
enum vor_field_kind {
    VOR_FIELD_VALUE = 0, /* int32_t: the interpolated value, rounded once
                            (halves away from zero); outside the hull: outside */
    VOR_FIELD_RGB565 = 1 /* uint16_t: ramp565[index] of the rounded value v,
                            index = floor(256 (v - low) / (high - low + 1))
                            clamped to 0 .. 255; outside the hull: outside565 */
};

/* Which interpolant (vor.h): Sibson's (C1, vor_interpolate) or Laplace's
 * (C0, vor_interpolate_laplace, cheaper on a small microcontroller). */
enum vor_field_method {
    VOR_FIELD_SIBSON = 0,
    VOR_FIELD_LAPLACE = 1
};

/* Where a field frame goes. Zero-initialise, then set what is used. */
typedef struct vor_field_output {
    enum vor_field_kind kind;
    void *band;                 /* band_rows * width pixels of the kind
                                   (an int32_t or uint16_t array) */
    size_t band_bytes;
    uint32_t band_rows;         /* >= 1 */
    vor_raster_flush_t flush;   /* as for vor_raster */
    void *user;                 /* handed to flush */
    int32_t outside;            /* VALUE: a pixel outside the convex hull */
    const uint16_t *ramp565;    /* RGB565: 256 colours, ramp565[0] for low */
    int32_t low;                /* RGB565: the ramp's range, low < high */
    int32_t high;
    uint16_t outside565;        /* RGB565: a pixel outside the convex hull */
    uint32_t *max_neighbours;   /* optional (NULL): the most natural
                                   neighbours of any pixel rendered, to
                                   size the scratch (vor_field_raster) */
} vor_field_output_t;

/* How to render a field: NULL or a zero-initialised struct for the
 * defaults (Sibson). */
typedef struct vor_field_options {
    enum vor_field_method method;
} vor_field_options_t;

/*
 * Renders the natural-neighbour interpolant of integer site values over
 * frame, band by band, into out: each pixel is exactly what
 * vor_interpolate (or vor_interpolate_laplace) gives at its centre, and
 * the bands go to flush as for vor_raster (top down, the last one maybe
 * shorter). values is indexed by site id, as for vor_interpolate. The
 * diagram is only read. Scratch: VOR_SIBSON_SCRATCH_BYTES(k) for pixels
 * with up to k natural neighbours (any alignment); a pixel at a site has
 * 1, on a hull edge 2, outside the hull none. Cost: one vor_nearest from
 * the previous pixel's nearest site (a step or two) and one
 * vor_interpolate per pixel.
 *   VOR_ERR_ARG    d, values, frame, out or its band or flush NULL
 *                  (options may be), a zero size or step, a pixel centre
 *                  outside int32, a frame 2^27 or more pixels wide, an
 *                  unknown kind or method, band_rows 0, RGB565 with
 *                  ramp565 NULL or low >= high, scratch NULL with
 *                  scratch_bytes > 0
 *   VOR_ERR_EMPTY  the diagram has no sites
 *   VOR_ERR_NOMEM  band_bytes < band_rows * width * pixel bytes (4 VALUE,
 *                  2 RGB565); or, while rendering, a pixel with more
 *                  natural neighbours than the scratch holds
 *   VOR_ERR_STOPPED  a flush returned nonzero
 * The argument errors (ARG, EMPTY, the band's NOMEM) are found before the
 * first pixel, and then nothing is written, *max_neighbours included. A
 * pixel's VOR_ERR_NOMEM and VOR_ERR_STOPPED stop the render after the
 * bands already delivered, like a display's partial refresh. Once
 * rendering began, *max_neighbours (when given) is written on return:
 * the most natural neighbours of any pixel rendered, and on a pixel's
 * VOR_ERR_NOMEM at least that pixel's count (the scratch to retry with).
 */
int vor_field_raster(const vor_t *d, const int32_t *values, const vor_raster_frame_t *frame,
                     const vor_field_output_t *out, const vor_field_options_t *options,
                     void *scratch, size_t scratch_bytes);

#ifdef __cplusplus
}
#endif

#endif
