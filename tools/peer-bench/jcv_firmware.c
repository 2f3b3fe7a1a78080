/* SPDX-License-Identifier: MIT */
/*
 * tools/peer-bench/jcv_firmware.c - vor beside jc_voronoi on the same emulated
 * microcontroller (Cortex-M4F, QEMU mps2-an386, `make bench-jcv`).
 *
 * jc_voronoi is the one embeddable C Voronoi library: a float Fortune sweep
 * that allocates through a callback, here picolibc's malloc. Both build the
 * same 1,000 and 2,000 uniform sites in [0, 2^24)^2 (integers a float holds
 * exactly, so both see the same input); per library and size it prints
 *
 *   bench LIBRARY N INSTRUCTIONS-PER-SITE RAM-BYTES-PER-SITE STACK-BYTES
 *
 * where instructions are the vor_port_counter() delta of one build under
 * QEMU -icount, RAM is the peak of memory the build needs besides its
 * stack (vor: VOR_ARENA_BYTES(n), the whole of it; jc_voronoi: the peak of
 * live heap bytes it asked malloc for) divided by n, and STACK the stack
 * high-water mark of the build (the stack is painted before each build and
 * scanned after). vor's result is checked with vor_validate and
 * jc_voronoi's by the number of sites it kept; "bench valid ok" ends a
 * good run.
 */
#include "jcv_peer.h"
#include "test.h"
#include "vor.h"

#define MAX_SITES 2000u
#define STACK_PAINT 0x5A17C0DEu

static vor_point_t points[MAX_SITES];
static float points_float[2u * MAX_SITES];
static uint8_t arena[VOR_ARENA_BYTES(MAX_SITES)] __attribute__((aligned(VOR_ARENA_ALIGN)));
static vor_t diagram;

extern uint32_t __stack_bottom[];

/* Paints the stack from its end up to a little below this frame. */
static __attribute__((noinline)) void stack_paint(void)
{
    volatile uint32_t *word = __stack_bottom;
    uint32_t here;
    uintptr_t below_frame = (uintptr_t)&here - 256u;
    while ((uintptr_t)word < below_frame) {
        *word++ = STACK_PAINT;
    }
}

/* Bytes of stack used since stack_paint, up to this frame. */
static __attribute__((noinline)) uint32_t stack_used(void)
{
    const volatile uint32_t *word = __stack_bottom;
    uint32_t here;
    while (word < (volatile uint32_t *)&here && *word == STACK_PAINT) {
        word++;
    }
    return (uint32_t)((uintptr_t)&here - (uintptr_t)word);
}

static void print_row(const char *library, uint32_t n, uint64_t spent, size_t ram, uint32_t stack)
{
    uint64_t tenths = (spent * 10u + n / 2u) / n;
    uint64_t ram_tenths = ((uint64_t)ram * 10u + n / 2u) / n;
    test_printf("bench %s %u %lu.%lu %lu.%lu %lu\n", library, (unsigned)n,
                (unsigned long)(tenths / 10u), (unsigned long)(tenths % 10u),
                (unsigned long)(ram_tenths / 10u), (unsigned long)(ram_tenths % 10u),
                (unsigned long)stack);
}

static bool bench_vor(uint32_t n)
{
    stack_paint();
    uint64_t start = vor_port_counter();
    bool ok = vor_init(&diagram, arena, sizeof arena, n) == VOR_OK &&
              vor_build(&diagram, points, n, NULL, NULL) == VOR_OK;
    uint64_t spent = vor_port_counter() - start;
    uint32_t stack = stack_used();
    ok = ok && vor_validate(&diagram, NULL) == VOR_OK && diagram.vertex_count == n;
    if (ok) {
        print_row("vor", n, spent, VOR_ARENA_BYTES(n), stack);
    }
    return ok;
}

static bool bench_jcv(uint32_t n)
{
    jcv_peer_heap heap = {0u, 0u};
    stack_paint();
    uint64_t start = vor_port_counter();
    int kept = jcv_peer_build(points_float, (int)n, &heap);
    uint64_t spent = vor_port_counter() - start;
    uint32_t stack = stack_used();
    bool ok = kept == (int)n && heap.live == 0u;
    if (ok) {
        print_row("jc_voronoi", n, spent, heap.peak, stack);
    }
    return ok;
}

int main(void)
{
    vor_port_init();
    static const uint32_t sizes[] = {1000u, MAX_SITES};
    bool ok = true;
    for (unsigned i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        uint32_t n = sizes[i];
        test_rng_t rng;
        test_rng_seed(&rng, 2026u + n);
        for (uint32_t k = 0; k < n; k++) {
            points[k].x = (int32_t)(test_rng_u32(&rng) >> 8);
            points[k].y = (int32_t)(test_rng_u32(&rng) >> 8);
            points_float[2u * k] = (float)points[k].x;
            points_float[2u * k + 1u] = (float)points[k].y;
        }
        ok &= bench_vor(n);
        ok &= bench_jcv(n);
    }
    test_printf("bench valid %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
