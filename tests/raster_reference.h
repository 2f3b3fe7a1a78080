/* SPDX-License-Identifier: MIT */
/*
 * raster_reference.h - the brute-force reference of the rasterizer tests,
 * written apart from the library: distances are exact values held as
 * unsigned multi-word integers (fractions where a metric divides), and the
 * nearest site is the first of the smallest values. Nothing here calls the
 * library's predicates.
 */
#ifndef VOR_RASTER_REFERENCE_H
#define VOR_RASTER_REFERENCE_H

#include <stdint.h>

#include "vor_raster.h"

/* The frame (origin, steps, size) and its pixel centres, for the tests
 * that set up frames and compare pixels. */
vor_raster_frame_t ref_frame(int32_t ox, int32_t oy, int32_t sx, int32_t sy, uint32_t w,
                             uint32_t h);
int32_t ref_centre_x(const vor_raster_frame_t *f, uint32_t i);
int32_t ref_centre_y(const vor_raster_frame_t *f, uint32_t j);

/* An unsigned integer of REF_LIMBS 32-bit limbs, least significant first. */
#define REF_LIMBS 20
typedef struct {
    uint32_t limb[REF_LIMBS];
} ref_big_t;

void ref_big_set(ref_big_t *r, uint64_t v);
/* r = a * b (the product must fit). */
void ref_big_mul(ref_big_t *r, const ref_big_t *a, const ref_big_t *b);
void ref_big_add(ref_big_t *r, const ref_big_t *a);
/* r -= a (r >= a). */
void ref_big_sub(ref_big_t *r, const ref_big_t *a);
int ref_big_compare(const ref_big_t *a, const ref_big_t *b);

/* Exact squared Euclidean distance between two int32 points. */
void ref_euclid_square(ref_big_t *r, int32_t qx, int32_t qy, const vor_point_t *s);

/* The nearest site to (qx, qy) under sites' metric (the farthest for
 * VOR_METRIC_FARTHEST); ties: smaller index. Every metric of vor_raster.h.
 * *undecided (may be NULL) is set when a weighted comparison could not be
 * decided within the reference's precision (a test must then fail). */
uint32_t ref_nearest_metric(const vor_raster_sites_t *sites, int32_t qx, int32_t qy, int *undecided);

/* Sign of the rank of site a against site b at (qx, qy) under sites'
 * metric: negative when a is nearer (farther for VOR_METRIC_FARTHEST),
 * 0 on a tie. *undecided as for ref_nearest_metric. */
int ref_rank_compare(const vor_raster_sites_t *sites, uint32_t a, uint32_t b, int32_t qx,
                     int32_t qy, int *undecided);

/* The nearest site to (qx, qy), Euclidean point sites; ties: smaller index. */
uint32_t ref_nearest(const vor_raster_sites_t *sites, int32_t qx, int32_t qy);

/* floor of the distance from (qx, qy) to site k, saturated at UINT32_MAX
 * (by search: the largest r with r^2 <= d^2). */
uint32_t ref_distance(const vor_raster_sites_t *sites, uint32_t k, int32_t qx, int32_t qy);

/* The VOR_RASTER_DISTANCE value of site k at (qx, qy) under sites'
 * metric: the largest r of the output range (0 .. UINT32_MAX; ADD and
 * COMPOUND: INT32_MIN .. INT32_MAX, returned as its bit pattern) that the
 * true distance reaches, found by bisection on exact checks "distance >=
 * r" (r^p <= |dx|^p + |dy|^p, r^2 den <= num, (r + w2) w1 <= sqrt(D)). */
uint32_t ref_distance_metric(const vor_raster_sites_t *sites, uint32_t k, int32_t qx, int32_t qy);

#endif
