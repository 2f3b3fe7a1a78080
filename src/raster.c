/*
 * raster.c - the band driver of vor_raster: checks the request, carves the
 * work memory, asks a row producer (the fast Euclidean path, or the
 * brute-force search) for each row's runs of labels, writes them in the
 * output kind, and flushes full bands. Teramoto renders the discrete
 * Voronoi diagram (section 2.2, Definition 2.2) with distance cones in a Z-buffer;
 * here the same diagram is computed exactly, one row at a time, so that
 * only a band of rows ever needs memory.
 */
#include "raster.h"

#include "multiword.h"

/* ------------------------------------------------------------ distances */

/* floor(sqrt(x)) by the bit-by-bit method (no division). */
static uint32_t isqrt64(uint64_t x)
{
    uint64_t root = 0;
    uint64_t bit = (uint64_t)1 << 62;
    while (bit > x) {
        bit >>= 2;
    }
    while (bit != 0u) { /* 32 steps at most: bit moves 2 places each */
        if (x >= root + bit) {
            x -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return (uint32_t)root;
}

static uint32_t magnitude(int64_t d)
{
    return (uint32_t)(d < 0 ? -d : d); /* |d| < 2^32 for int32 differences */
}

/* floor(|q - s|), saturated at UINT32_MAX. The squared distance is below
 * 2^65; from 2^64 on the root is >= 2^32 and saturates. */
static uint32_t euclid_distance(int32_t qx, int32_t qy, const vor_point_t *s)
{
    uint64_t dx2 = vor__mul_u32(magnitude((int64_t)qx - s->x), magnitude((int64_t)qx - s->x));
    uint64_t dy2 = vor__mul_u32(magnitude((int64_t)qy - s->y), magnitude((int64_t)qy - s->y));
    uint64_t sum = dx2 + dy2;
    if (sum < dx2) {
        return 0xFFFFFFFFu;
    }
    return isqrt64(sum);
}

/* ---------------------------------------------------------- brute force */

static uint32_t brute_nearest(const vor_raster_sites_t *sites, const vor_point_t *q)
{
    uint32_t best = 0;
    for (uint32_t k = 1; k < sites->count; k++) {
        /* strictly closer only: ties stay with the smaller index */
        if (vor_closer(q, &sites->points[k], &sites->points[best], NULL) < 0) {
            best = k;
        }
    }
    return best;
}

static uint32_t brute_row(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
                          uint32_t j, vor__run_t *runs)
{
    vor_point_t q;
    q.y = (int32_t)(frame->origin_y + vor__offset(j, frame->step_y));
    uint32_t count = 0;
    for (uint32_t i = 0; i < frame->width; i++) {
        q.x = (int32_t)(frame->origin_x + vor__offset(i, frame->step_x));
        count = vor__run_push(runs, count, i, brute_nearest(sites, &q));
    }
    return count;
}

/* -------------------------------------------------------------- output */

typedef struct producer {
    const vor_raster_frame_t *frame;
    const vor_raster_sites_t *sites;
    vor__euclid_t *euclid; /* NULL: brute force */
    vor__metric_t *metric; /* the other metrics (raster_metrics.c) */
} producer_t;

static uint32_t produce(producer_t *p, uint32_t j, vor__run_t *runs)
{
    if (p->metric != NULL) {
        return vor__metric_row(p->metric, j, runs);
    }
    if (p->euclid != NULL) {
        return vor__euclid_row(p->euclid, j, runs);
    }
    return brute_row(p->frame, p->sites, j, runs);
}

/* px[from .. to) = value, four pixels per step (the hot loop of RGB565
 * output: a run is usually tens of pixels). */
static void fill16(uint16_t *px, uint32_t from, uint32_t to, uint16_t value)
{
    uint32_t i = from;
    for (; i + 4u <= to; i += 4u) {
        px[i] = value;
        px[i + 1u] = value;
        px[i + 2u] = value;
        px[i + 3u] = value;
    }
    for (; i < to; i++) {
        px[i] = value;
    }
}

/* Writes row j (runs) into dst in the output's kind. below: the runs of
 * row j + 1 (BOUNDARY only; NULL on the last row). metric: the other
 * metrics' state (DISTANCE; NULL for Euclidean point sites). */
static void write_row(const vor_raster_output_t *out, const vor_raster_frame_t *frame,
                      const vor_raster_sites_t *sites, const vor__metric_t *metric, uint32_t j,
                      const vor__run_t *runs, uint32_t count, const vor__run_t *below,
                      uint32_t below_count, void *dst)
{
    uint32_t i = 0;
    switch (out->kind) {
    case VOR_RASTER_LABEL8: {
        uint8_t *px = dst;
        for (uint32_t r = 0; r < count; r++) {
            uint8_t label = (uint8_t)runs[r].site;
            for (; i < runs[r].end; i++) {
                px[i] = label;
            }
        }
        break;
    }
    case VOR_RASTER_LABEL16: {
        uint16_t *px = dst;
        for (uint32_t r = 0; r < count; r++) {
            fill16(px, i, runs[r].end, (uint16_t)runs[r].site);
            i = runs[r].end;
        }
        break;
    }
    case VOR_RASTER_LABEL32: {
        uint32_t *px = dst;
        for (uint32_t r = 0; r < count; r++) {
            for (; i < runs[r].end; i++) {
                px[i] = runs[r].site;
            }
        }
        break;
    }
    case VOR_RASTER_RGB565: {
        uint16_t *px = dst;
        for (uint32_t r = 0; r < count; r++) {
            fill16(px, i, runs[r].end, out->palette565[runs[r].site]);
            i = runs[r].end;
        }
        break;
    }
    case VOR_RASTER_RGB888: {
        uint8_t *px = dst;
        for (uint32_t r = 0; r < count; r++) {
            uint32_t colour = out->palette888[runs[r].site];
            uint8_t red = (uint8_t)(colour >> 16), green = (uint8_t)(colour >> 8),
                    blue = (uint8_t)colour;
            for (; i < runs[r].end; i++) {
                px[3u * i] = red;
                px[3u * i + 1u] = green;
                px[3u * i + 2u] = blue;
            }
        }
        break;
    }
    case VOR_RASTER_BOUNDARY: {
        uint8_t *px = dst;
        for (i = 0; i < frame->width; i++) {
            px[i] = 0;
        }
        /* right neighbour: the last pixel of every run but the final one */
        for (uint32_t r = 0; r + 1u < count; r++) {
            px[runs[r].end - 1u] = 1;
        }
        /* lower neighbour: walk both rows' runs together */
        if (below != NULL) {
            uint32_t r = 0, s = 0;
            i = 0;
            while (i < frame->width) { /* each step ends a run of one row */
                uint32_t end = runs[r].end < below[s].end ? runs[r].end : below[s].end;
                if (runs[r].site != below[s].site) {
                    for (; i < end; i++) {
                        px[i] = 1;
                    }
                }
                i = end;
                if (runs[r].end == end && r + 1u < count) {
                    r++;
                }
                if (below[s].end == end && s + 1u < below_count) {
                    s++;
                }
            }
        }
        break;
    }
    case VOR_RASTER_DISTANCE: {
        uint32_t *px = dst;
        int32_t qy = (int32_t)(frame->origin_y + vor__offset(j, frame->step_y));
        for (uint32_t r = 0; r < count; r++) {
            for (; i < runs[r].end; i++) {
                int32_t qx = (int32_t)(frame->origin_x + vor__offset(i, frame->step_x));
                px[i] = metric != NULL ? vor__metric_distance(metric, runs[r].site, qx, qy)
                                       : euclid_distance(qx, qy, &sites->points[runs[r].site]);
            }
        }
        break;
    }
    }
}

/* -------------------------------------------------------------- checks */

static int frame_ok(const vor_raster_frame_t *f)
{
    if (f->width == 0u || f->height == 0u || f->step_x <= 0 || f->step_y <= 0 ||
        f->width > 0x7FFFFFFFu || f->height > 0x7FFFFFFFu) {
        return 0;
    }
    /* the last centre must be an int32 point: (w - 1) step < 2^62 here */
    int64_t last_x = f->origin_x + vor__offset(f->width - 1u, f->step_x);
    int64_t last_y = f->origin_y + vor__offset(f->height - 1u, f->step_y);
    return last_x <= INT32_MAX && last_y <= INT32_MAX;
}

/* Rounds an offset up to a multiple of 8 (the work memory's alignment). */
static size_t align8(size_t x)
{
    return (x + 7u) & ~(size_t)7u;
}

/* Carves the fast Euclidean path's arrays and the two rows of runs from
 * the work memory: 8-byte arrays first, then 4-byte ones, then bytes, so
 * that every array is aligned (total within VOR_RASTER_WORK_BYTES). */
static void carve_euclid(vor__euclid_t *e, uint8_t *base, uint32_t n, uint32_t width,
                         vor__run_t **rows)
{
    size_t at = 0;
    e->val = (int64_t *)(void *)(base + at);
    at = align8(at + (size_t)n * sizeof(int64_t));
    rows[0] = (vor__run_t *)(void *)(base + at);
    at = align8(at + (size_t)width * sizeof(vor__run_t));
    rows[1] = (vor__run_t *)(void *)(base + at);
    at = align8(at + (size_t)width * sizeof(vor__run_t));
    uint32_t *words = (uint32_t *)(void *)(base + at);
    e->by_x = words;
    e->by_y = words + n;
    e->cand = words + 2u * (size_t)n;
    e->key = (int32_t *)(void *)(words + 3u * (size_t)n);
    e->stack = words + 4u * (size_t)n;
    e->left = words + 5u * (size_t)n;
    e->right = words + 6u * (size_t)n;
    e->sorted_x = (int32_t *)(void *)(words + 7u * (size_t)n);
    e->sorted_y = (int32_t *)(void *)(words + 8u * (size_t)n);
    e->mark = (uint8_t *)(void *)(words + 9u * (size_t)n);
}

/* Produces, writes and flushes every row (everything checked). Inlined
 * into vor_raster, so that the flush callback is called from there (the
 * stack-depth tool counts the caller's callback apart). */
VOR__INLINE int render(const vor_raster_output_t *out, const vor_raster_frame_t *frame,
                  const vor_raster_sites_t *sites, producer_t *producer, vor__run_t *const *rows,
                  size_t row_bytes)
{
    if (out->areas != NULL) {
        for (uint32_t k = 0; k < sites->count; k++) {
            out->areas[k] = 0;
        }
    }
    const int boundary = out->kind == VOR_RASTER_BOUNDARY;
    uint8_t *band = out->band;
    uint32_t cur = 0;
    uint32_t count = produce(producer, 0, rows[cur]);
    uint32_t band_first = 0;
    for (uint32_t j = 0; j < frame->height; j++) {
        uint32_t below_count = 0;
        const vor__run_t *below = NULL;
        if (boundary && j + 1u < frame->height) {
            below_count = produce(producer, j + 1u, rows[cur ^ 1u]);
            below = rows[cur ^ 1u];
        }
        write_row(out, frame, sites, producer->metric, j, rows[cur], count, below, below_count,
                  band + (size_t)(j - band_first) * row_bytes);
        if (out->areas != NULL) {
            uint32_t start = 0;
            for (uint32_t r = 0; r < count; r++) {
                out->areas[rows[cur][r].site] += rows[cur][r].end - start;
                start = rows[cur][r].end;
            }
        }
        if (j + 1u == frame->height || j + 1u - band_first == out->band_rows) {
            int status = out->flush(out->user, band_first, j + 1u - band_first, band);
            if (status != 0) {
                return status;
            }
            band_first = j + 1u;
        }
        if (j + 1u < frame->height) {
            if (boundary) {
                cur ^= 1u;
                count = below_count;
            } else {
                count = produce(producer, j + 1u, rows[cur]);
            }
        }
    }
    return VOR_OK;
}

int vor_raster(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
               const vor_raster_output_t *out, void *work, size_t work_bytes)
{
    if (frame == NULL || sites == NULL || out == NULL || work == NULL || !frame_ok(frame)) {
        return VOR_ERR_ARG;
    }
    if (sites->count == 0u) {
        return VOR_ERR_EMPTY;
    }
    if (sites->points == NULL || out->band == NULL ||
        out->flush == NULL || out->band_rows == 0u ||
        (out->method != VOR_RASTER_FAST && out->method != VOR_RASTER_BRUTE)) {
        return VOR_ERR_ARG;
    }
    const int euclid_metric = sites->metric == VOR_METRIC_EUCLID;
    if (!euclid_metric && vor__metric_check(sites) != VOR_OK) {
        return VOR_ERR_ARG;
    }
    const uint32_t n = sites->count;
    size_t pixel_bytes;
    switch (out->kind) {
    case VOR_RASTER_LABEL8:
        pixel_bytes = 1;
        if (n > 256u) {
            return VOR_ERR_ARG;
        }
        break;
    case VOR_RASTER_LABEL16:
        pixel_bytes = 2;
        if (n > 65536u) {
            return VOR_ERR_ARG;
        }
        break;
    case VOR_RASTER_RGB565:
        pixel_bytes = 2;
        if (out->palette565 == NULL) {
            return VOR_ERR_ARG;
        }
        break;
    case VOR_RASTER_RGB888:
        pixel_bytes = 3;
        if (out->palette888 == NULL) {
            return VOR_ERR_ARG;
        }
        break;
    case VOR_RASTER_BOUNDARY:
        pixel_bytes = 1;
        break;
    case VOR_RASTER_LABEL32:
    case VOR_RASTER_DISTANCE:
        pixel_bytes = 4;
        break;
    default:
        return VOR_ERR_ARG;
    }
    if (n > 0x07FFFFFFu || frame->width > 0x07FFFFFFu) {
        return VOR_ERR_ARG; /* the work size below must not overflow */
    }
    const size_t row_bytes = (size_t)frame->width * pixel_bytes;
    if ((uint64_t)out->band_bytes < vor__mul_u32((uint32_t)row_bytes, out->band_rows)) {
        return VOR_ERR_NOMEM;
    }
    if (work_bytes < VOR_RASTER_WORK_BYTES(n, frame->width)) {
        return VOR_ERR_NOMEM;
    }
    if (((uintptr_t)work & (VOR_RASTER_WORK_ALIGN - 1u)) != 0u) {
        return VOR_ERR_ALIGN;
    }

    uint8_t *base = work;
    producer_t producer;
    producer.frame = frame;
    producer.sites = sites;
    producer.euclid = NULL;
    producer.metric = NULL;
    vor__run_t *rows[2];
    vor__metric_t metric;
    vor__euclid_t euclid;
    if (!euclid_metric) {
        /* the two rows of runs, then the culling pool: at least 12 n + 14
         * words (the macro's 48 n + 64 bytes, less alignment) */
        size_t row_bytes8 = align8((size_t)frame->width * sizeof(vor__run_t));
        rows[0] = (vor__run_t *)(void *)base;
        rows[1] = (vor__run_t *)(void *)(base + row_bytes8);
        vor__metric_prepare(&metric, frame, sites, out->method == VOR_RASTER_BRUTE,
                            (uint32_t *)(void *)(base + 2u * row_bytes8),
                            (work_bytes - 2u * row_bytes8) / sizeof(uint32_t));
        producer.metric = &metric;
    } else {
        carve_euclid(&euclid, base, n, frame->width, rows);
        if (out->method == VOR_RASTER_FAST && vor__euclid_fits(frame, sites->points, n)) {
            euclid.points = sites->points;
            euclid.n = n;
            euclid.width = frame->width;
            euclid.height = frame->height;
            euclid.step_x = frame->step_x;
            euclid.step_y = frame->step_y;
            euclid.origin_x = frame->origin_x;
            euclid.origin_y = frame->origin_y;
            vor__euclid_prepare(&euclid);
            producer.euclid = &euclid;
        }
    }
    return render(out, frame, sites, &producer, rows, row_bytes);
}
