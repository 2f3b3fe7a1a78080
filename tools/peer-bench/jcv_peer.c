/* SPDX-License-Identifier: MIT */
/*
 * tools/peer-bench/jcv_peer.c - jc_voronoi (../shared/peers/jc_voronoi, float
 * Fortune sweep) behind one C function, for the benchmarks that compare
 * vor with it: the host's `make bench` (tools/peer-bench/delaunay.cpp) and the
 * Cortex-M4F firmware (tools/peer-bench/jcv_firmware.c). Compiled as C, the
 * language jc_voronoi is written in; only built when the peer sources are
 * there (tools/peer-bench/bench.mk).
 */
#define JC_VORONOI_IMPLEMENTATION
#include "jc_voronoi.h"

#include "jcv_peer.h"

/* The allocator jc_voronoi calls, counting live and peak bytes. Each block
 * carries its size in front, aligned for any type jc_voronoi stores. */
typedef union {
    size_t size;
    double align_double;
    void *align_pointer;
} block_header;

static void *counting_alloc(void *context, size_t size)
{
    jcv_peer_heap *heap = (jcv_peer_heap *)context;
    block_header *block = (block_header *)malloc(sizeof(block_header) + size);
    if (block == NULL) {
        return NULL;
    }
    block->size = size;
    heap->live += size;
    heap->peak = (heap->live > heap->peak) ? heap->live : heap->peak;
    return block + 1;
}

static void counting_free(void *context, void *pointer)
{
    jcv_peer_heap *heap = (jcv_peer_heap *)context;
    if (pointer != NULL) {
        block_header *block = (block_header *)pointer - 1;
        heap->live -= block->size;
        free(block);
    }
}

/* jcv_point is two jcv_real: the caller's (x, y) float pairs are its array */
typedef char jcv_peer_layout_check[(sizeof(jcv_point) == 2 * sizeof(float)) ? 1 : -1];

int jcv_peer_build(const float *xy, int count, jcv_peer_heap *heap)
{
    jcv_diagram diagram;
    memset(&diagram, 0, sizeof diagram);
    jcv_diagram_generate_useralloc(count, (const jcv_point *)xy, NULL, NULL, heap, counting_alloc,
                                   counting_free, &diagram);
    int sites = diagram.numsites;
    jcv_diagram_free(&diagram);
    return sites;
}
