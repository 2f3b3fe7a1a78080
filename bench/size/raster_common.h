/* SPDX-License-Identifier: MIT */
/*
 * bench/size/raster_common.h - a 64 x 8 frame in 8-row bands of 8-bit
 * labels, for the raster feature sets of `make size`.
 */
#ifndef SIZE_RASTER_COMMON_H
#define SIZE_RASTER_COMMON_H

#include "common.h"
#include "vor_raster.h"

#define SIZE_WIDTH 64u
#define SIZE_ROWS 8u

static vor_point_t raster_points[SIZE_SITES];
static uint8_t raster_band[SIZE_WIDTH * SIZE_ROWS];
static uint8_t raster_work[VOR_RASTER_WORK_BYTES(SIZE_SITES, SIZE_WIDTH)]
    __attribute__((aligned(VOR_RASTER_WORK_ALIGN)));
static volatile uint32_t raster_sum;

static int raster_flush(void *user, uint32_t first_row, uint32_t rows, const void *pixels)
{
    (void)user;
    raster_sum += first_row + rows + ((const uint8_t *)pixels)[0];
    return 0;
}

/* vor_raster or vor_raster_euclid: the program links the one it passes. */
typedef int (*raster_entry_t)(const vor_raster_frame_t *, const vor_raster_sites_t *,
                              const vor_raster_output_t *, const vor_raster_options_t *,
                              void *, size_t);

static inline int raster_render(raster_entry_t entry, enum vor_metric metric)
{
    for (uint32_t i = 0; i < SIZE_SITES; i++) {
        raster_points[i].x = size_x(i);
        raster_points[i].y = size_y(i);
    }
    vor_raster_frame_t frame = {size_x(0), size_y(0), 1, 1, SIZE_WIDTH, SIZE_ROWS};
    vor_raster_sites_t sites = {0};
    sites.metric = metric;
    sites.points = raster_points;
    sites.count = SIZE_SITES;
    vor_raster_output_t out = {0};
    out.kind = VOR_RASTER_LABEL8;
    out.band = raster_band;
    out.band_bytes = sizeof raster_band;
    out.band_rows = SIZE_ROWS;
    out.flush = raster_flush;
    return entry(&frame, &sites, &out, NULL, raster_work, sizeof raster_work);
}

#endif
