/* SPDX-License-Identifier: MIT */
/*
 * raster_scan.c - the raster's entry points. Each sets a request up the
 * same way (the core's checks, the family's own, the core's start, the
 * family's state) and scans the rows top down: the family produces a row
 * of runs, and DISTANCE pixels when asked, the core's band writer takes
 * it. The families never call each other or the scan; vor_raster hands
 * Euclidean point sites to vor_raster_euclid, which links none of the
 * other metrics.
 */
#include "raster.h"
#include "raster_euclid.h"
#include "raster_metrics.h"

int vor_raster_euclid(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
                      const vor_raster_output_t *out, void *work, size_t work_bytes)
{
    vor__raster_t r;
    int status = vor__raster_check(&r, frame, sites, out, work, work_bytes);
    if (status != VOR_OK) {
        return status;
    }
    if (sites->metric != VOR_METRIC_EUCLID) {
        return VOR_ERR_ARG;
    }
    vor__raster_start(&r);
    vor__euclid_t euclid;
    vor__euclid_prepare(&euclid, &r);
    for (uint32_t j = 0; j <= frame->height; j++) { /* j = height: the end */
        uint32_t count = 0;
        if (j < frame->height) {
            vor__run_t *runs = vor__bands_runs(&r.bands);
            count = vor__euclid_row(&euclid, j, runs);
            if (out->kind == VOR_RASTER_DISTANCE) {
                vor__euclid_distances(&euclid, j, runs, count, vor__bands_pixels(&r.bands));
            }
        }
        status = vor__bands_put_flush(&r.bands, count);
        if (status != 0) {
            return status;
        }
    }
    return VOR_OK;
}

int vor_raster(const vor_raster_frame_t *frame, const vor_raster_sites_t *sites,
               const vor_raster_output_t *out, void *work, size_t work_bytes)
{
    if (sites != NULL && sites->metric == VOR_METRIC_EUCLID) {
        return vor_raster_euclid(frame, sites, out, work, work_bytes);
    }
    vor__raster_t r;
    int status = vor__raster_check(&r, frame, sites, out, work, work_bytes);
    if (status != VOR_OK) {
        return status;
    }
    if (vor__metric_check(sites) != VOR_OK) {
        return VOR_ERR_ARG;
    }
    vor__raster_start(&r);
    vor__metric_t metric;
    vor__metric_prepare(&metric, &r);
    for (uint32_t j = 0; j <= frame->height; j++) { /* j = height: the end */
        uint32_t count = 0;
        if (j < frame->height) {
            vor__run_t *runs = vor__bands_runs(&r.bands);
            count = vor__metric_row(&metric, j, runs);
            if (out->kind == VOR_RASTER_DISTANCE) {
                vor__metric_distances(&metric, j, runs, count, vor__bands_pixels(&r.bands));
            }
        }
        status = vor__bands_put_flush(&r.bands, count);
        if (status != 0) {
            return status;
        }
    }
    return VOR_OK;
}
