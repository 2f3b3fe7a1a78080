/* SPDX-License-Identifier: MIT */
/*
 * soak.c - `make soak`: a long randomized run of one dynamic diagram.
 *
 *   build/soak/soak [OPERATIONS [LIVE_SITES [SEED]]]   (default 10^7, 20,000, 1)
 *
 * Inserts, removes, moves (small steps and jumps) and nearest-site queries
 * on a diagram that grows to LIVE_SITES sites and then stays near that
 * size. Every call's result is checked against a model kept here: the ids
 * (vor_insert reuses the most recently freed one), duplicates (a point or
 * a move onto another site), and one query in 1,000 against brute force
 * over the live sites with exact distances. Every tenth of the run:
 * vor_validate, and the triangles compared with a fresh vor_build of the
 * live sites in id order (by coordinates: the fresh build numbers them
 * from 0). Prints operations per second (checks included, full
 * validations not) and exits 1 at the first divergence.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "vor.h"

#define SPAN (1 << 20) /* coordinates in [-SPAN, SPAN): duplicates happen */

static uint64_t rng_state = 1;
static uint32_t next_random(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (uint32_t)(rng_state >> 16);
}

static int32_t random_coordinate(void)
{
    return (int32_t)(next_random() % (2u * SPAN)) - SPAN;
}

typedef struct {
    vor_t d;
    vor_point_t *point; /* by id */
    uint8_t *alive;     /* by id */
    uint32_t *live;     /* the live ids, in no order */
    uint32_t *slot;     /* by id: its index in live[] */
    uint32_t live_count;
    uint32_t *freed;    /* freed ids, the most recent last */
    uint32_t freed_count;
    uint32_t next_id;   /* ids below it have been handed out */
} model_t;

static void fail(const char *what, unsigned long long op)
{
    printf("soak: divergence at operation %llu: %s\n", op, what);
    exit(1);
}

static double seconds_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* The site at (x, y) per the model, by the library's nearest (whose
 * answers are checked separately), or VOR_NO_HINT. */
static uint32_t site_at(const model_t *m, int32_t x, int32_t y)
{
    uint32_t id;
    if (m->live_count == 0 || vor_nearest(&m->d, (vor_point_t){x, y}, VOR_NO_HINT, &id) != VOR_OK)
        return VOR_NO_HINT;
    return m->point[id].x == x && m->point[id].y == y ? id : VOR_NO_HINT;
}

static void add_live(model_t *m, uint32_t id, int32_t x, int32_t y)
{
    m->point[id].x = x;
    m->point[id].y = y;
    m->alive[id] = 1;
    m->slot[id] = m->live_count;
    m->live[m->live_count++] = id;
}

static void drop_live(model_t *m, uint32_t id)
{
    uint32_t last = m->live[--m->live_count];
    m->live[m->slot[id]] = last;
    m->slot[last] = m->slot[id];
    m->alive[id] = 0;
    m->freed[m->freed_count++] = id;
}

static void do_insert(model_t *m, unsigned long long op)
{
    int32_t x = random_coordinate(), y = random_coordinate();
    if (next_random() % 50u == 0u && m->live_count) { /* onto a site on purpose */
        uint32_t other = m->live[next_random() % m->live_count];
        x = m->point[other].x;
        y = m->point[other].y;
    }
    uint32_t existing = site_at(m, x, y), id = VOR_NO_HINT;
    int result = vor_insert(&m->d, (vor_point_t){x, y}, &id);
    if (existing != VOR_NO_HINT) {
        if (result != VOR_ERR_DUPLICATE || id != existing)
            fail("insert onto a site: not its duplicate", op);
        return;
    }
    uint32_t expected = m->freed_count ? m->freed[m->freed_count - 1u] : m->next_id;
    if (result != VOR_OK || id != expected)
        fail("insert: failed or not the most recently freed id", op);
    if (m->freed_count)
        m->freed_count--;
    else
        m->next_id++;
    add_live(m, id, x, y);
}

static void do_remove(model_t *m, unsigned long long op)
{
    uint32_t id = m->live[next_random() % m->live_count];
    if (vor_remove(&m->d, id) != VOR_OK)
        fail("remove failed", op);
    drop_live(m, id);
    if (vor_remove(&m->d, id) != VOR_ERR_ARG)
        fail("remove of a freed id accepted", op);
}

static void do_move(model_t *m, unsigned long long op)
{
    uint32_t id = m->live[next_random() % m->live_count];
    int32_t x, y;
    uint32_t kind = next_random() % 8u;
    if (kind < 5u) { /* a small step, as a robot moves */
        x = m->point[id].x + (int32_t)(next_random() % 65u) - 32;
        y = m->point[id].y + (int32_t)(next_random() % 65u) - 32;
    } else if (kind < 7u) {
        x = random_coordinate();
        y = random_coordinate();
    } else { /* onto another site */
        uint32_t other = m->live[next_random() % m->live_count];
        x = m->point[other].x;
        y = m->point[other].y;
    }
    uint32_t existing = site_at(m, x, y), reported = VOR_NO_HINT;
    int result = vor_move(&m->d, id, (vor_point_t){x, y}, &reported);
    if (existing != VOR_NO_HINT && existing != id) {
        if (result != VOR_ERR_DUPLICATE || reported != existing)
            fail("move onto another site: not its duplicate", op);
        return;
    }
    if (result != VOR_OK)
        fail("move failed", op);
    m->point[id].x = x;
    m->point[id].y = y;
}

static void do_query(model_t *m, unsigned long long op)
{
    int32_t x = random_coordinate(), y = random_coordinate();
    uint32_t id;
    if (vor_nearest(&m->d, (vor_point_t){x, y}, VOR_NO_HINT, &id) != VOR_OK || !m->alive[id])
        fail("nearest failed or answered a free id", op);
    if (op % 1000u != 0u)
        return;
    uint32_t best = VOR_NO_HINT;
    uint64_t best_distance = 0; /* |dx|, |dy| < 2^22: exact */
    for (uint32_t i = 0; i < m->live_count; i++) {
        uint32_t s = m->live[i];
        int64_t dx = (int64_t)x - m->point[s].x, dy = (int64_t)y - m->point[s].y;
        uint64_t distance = (uint64_t)(dx * dx) + (uint64_t)(dy * dy);
        if (best == VOR_NO_HINT || distance < best_distance ||
            (distance == best_distance && s < best)) {
            best = s;
            best_distance = distance;
        }
    }
    if (id != best)
        fail("nearest differs from brute force", op);
}

typedef struct {
    vor_point_t p[3];
} triangle_t;

static int point_less(vor_point_t a, vor_point_t b)
{
    return a.x < b.x || (a.x == b.x && a.y < b.y);
}

/* A triangle by coordinates, rotated to start at its smallest corner. */
static triangle_t canonical(const vor_t *d, const uint32_t ids[3])
{
    triangle_t t;
    uint32_t first = 0;
    for (uint32_t i = 1; i < 3; i++)
        if (point_less(d->sites[ids[i]], d->sites[ids[first]]))
            first = i;
    for (uint32_t i = 0; i < 3; i++)
        t.p[i] = d->sites[ids[(first + i) % 3u]];
    return t;
}

static int compare_triangles(const void *a, const void *b)
{
    return memcmp(a, b, sizeof(triangle_t));
}

static uint32_t collect(const vor_t *d, triangle_t *out)
{
    vor_triangle_iter_t it;
    uint32_t ids[3], n = 0;
    vor_triangles_begin(&it, d);
    while (vor_triangles_next(&it, ids))
        out[n++] = canonical(d, ids);
    qsort(out, n, sizeof *out, compare_triangles);
    return n;
}

static int compare_ids(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* vor_validate, then the triangles against a fresh build in id order. */
static void full_check(model_t *m, vor_t *fresh, void *fresh_arena, size_t fresh_bytes,
                       uint32_t capacity, unsigned long long op)
{
    vor_violation_t violation;
    if (vor_validate(&m->d, &violation) != VOR_OK)
        fail("vor_validate", op);
    uint32_t *ids = malloc(sizeof *ids * (m->live_count + 1u));
    vor_point_t *points = malloc(sizeof *points * (m->live_count + 1u));
    triangle_t *a = malloc(sizeof *a * 2u * (capacity + 1u));
    triangle_t *b = malloc(sizeof *b * 2u * (capacity + 1u));
    if (!ids || !points || !a || !b)
        fail("out of host memory", op);
    memcpy(ids, m->live, sizeof *ids * m->live_count);
    qsort(ids, m->live_count, sizeof *ids, compare_ids);
    for (uint32_t i = 0; i < m->live_count; i++)
        points[i] = m->point[ids[i]];
    if (vor_init(fresh, fresh_arena, fresh_bytes, capacity) != VOR_OK ||
        vor_build(fresh, points, m->live_count, NULL, NULL) != VOR_OK)
        fail("fresh build failed", op);
    uint32_t na = collect(&m->d, a), nb = collect(fresh, b);
    if (na != nb || memcmp(a, b, sizeof *a * na) != 0)
        fail("triangles differ from a fresh build", op);
    free(ids);
    free(points);
    free(a);
    free(b);
}

int main(int argc, char **argv)
{
    unsigned long long operations = argc > 1 ? strtoull(argv[1], NULL, 10) : 10000000ull;
    uint32_t target = argc > 2 ? (uint32_t)strtoul(argv[2], NULL, 10) : 20000u;
    rng_state = argc > 3 ? strtoull(argv[3], NULL, 10) | 1u : 1u;
    uint32_t capacity = target + target / 8u + 16u;
    if (target < 2u || capacity > VOR_MAX_SITES) {
        fprintf(stderr, "usage: soak [OPERATIONS [LIVE_SITES (2 .. %u) [SEED]]]\n",
                (unsigned)(VOR_MAX_SITES * 8u / 9u));
        return 2;
    }
    size_t bytes = VOR_ARENA_BYTES(capacity);
    void *arena = malloc(bytes), *fresh_arena = malloc(bytes); /* malloc aligns to 8 */
    model_t m = {0};
    m.point = calloc(capacity, sizeof *m.point);
    m.alive = calloc(capacity, 1);
    m.live = calloc(capacity, sizeof *m.live);
    m.slot = calloc(capacity, sizeof *m.slot);
    m.freed = calloc(capacity, sizeof *m.freed);
    vor_t fresh;
    if (!arena || !fresh_arena || !m.point || !m.alive || !m.live || !m.slot || !m.freed ||
        vor_init(&m.d, arena, bytes, capacity) != VOR_OK) {
        fprintf(stderr, "soak: no memory\n");
        return 2;
    }
    unsigned long long counts[4] = {0, 0, 0, 0}, period = operations / 10u + 1u;
    double busy = 0, start = seconds_now();
    unsigned checks = 0;
    uint32_t fewest = UINT32_MAX, most = 0; /* live sites once the target was reached */
    for (unsigned long long op = 1; op <= operations; op++) {
        uint32_t r = next_random() % 100u;
        /* grow to the target, then hover around it */
        uint32_t kind = m.live_count < 2u                 ? 0u
                        : m.live_count < target && r < 60u ? 0u
                        : r < 25u                         ? 0u
                        : r < 50u                         ? 1u
                        : r < 80u                         ? 2u
                                                          : 3u;
        if (kind == 1u && m.live_count <= target / 2u)
            kind = 0u;
        if (kind == 0u && m.next_id >= capacity && m.freed_count == 0u)
            kind = 1u;
        switch (kind) {
        case 0: do_insert(&m, op); break;
        case 1: do_remove(&m, op); break;
        case 2: do_move(&m, op); break;
        default: do_query(&m, op); break;
        }
        counts[kind]++;
        if (most >= target || m.live_count >= target) {
            fewest = m.live_count < fewest ? m.live_count : fewest;
            most = m.live_count > most ? m.live_count : most;
        }
        if (op % period == 0u || op == operations) {
            double now = seconds_now();
            busy += now - start;
            full_check(&m, &fresh, fresh_arena, bytes, capacity, op);
            checks++;
            printf("soak: %llu operations, %u live sites, full check %u passed\n", op,
                   m.live_count, checks);
            fflush(stdout);
            start = seconds_now();
        }
    }
    printf("soak: %llu operations (%llu inserts, %llu removes, %llu moves, %llu queries) "
           "at %u-%u live sites: %.0f operations/s, %u full checks, no divergence\n",
           operations, counts[0], counts[1], counts[2], counts[3], fewest, most,
           (double)operations / busy, checks);
    return 0;
}
