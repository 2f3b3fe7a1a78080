/* SPDX-License-Identifier: MIT */
/*
 * tools/peer-bench/jcv_peer.h - jc_voronoi behind one function (jcv_peer.c).
 */
#ifndef VOR_BENCH_JCV_PEER_H
#define VOR_BENCH_JCV_PEER_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Heap bytes jc_voronoi holds: now and at most, since the caller zeroed it. */
typedef struct jcv_peer_heap {
    size_t live, peak;
} jcv_peer_heap;

/* Builds the Voronoi diagram of count sites (x0, y0, x1, y1, ... in
 * jc_voronoi's float) and frees it again. Returns the number of sites
 * jc_voronoi kept (it merges sites equal in float). */
int jcv_peer_build(const float *xy, int count, jcv_peer_heap *heap);

#ifdef __cplusplus
}
#endif

#endif
