/* SPDX-License-Identifier: MIT */
/*
 * mismatch.c - one side of the configuration contract (include/vor_config.h),
 * compiled once per case with the application's options on the command
 * line (Makefile, "Configuration contract"), all linked into one program
 * against a library built with -DVOR_TRACKER_EDGES=24:
 *   CONFIG_CASE     the name of this case's function
 *   CONFIG_EXPECT   VOR_ERR_CONFIG when the options differ from the
 *                   library's, VOR_OK when they agree
 * Every object the library could write is surrounded by canary bytes, and
 * the objects themselves hold the same pattern: a refused call must leave
 * every byte as it was; an accepted one must keep the canaries.
 */
#include "test.h"
#include "vor.h"
#include "vor_power.h"

#define CANARY 32u
#define CONFIG_SITES 40u
#define PATTERN 0xC3u

/* An object the library may write, between canary bytes. */
#define GUARDED(name, member)                                                                  \
    static struct {                                                                            \
        uint8_t before[CANARY];                                                                \
        member;                                                                                \
        uint8_t after[CANARY];                                                                 \
    } name __attribute__((aligned(8)))

GUARDED(guarded_diagram, vor_t d);
GUARDED(guarded_arena, uint8_t arena[VOR_ARENA_BYTES(CONFIG_SITES)]);
GUARDED(guarded_tracker, vor_tracker_t t);
GUARDED(guarded_power, vor_power_t pd);
GUARDED(guarded_power_arena, uint8_t arena[VOR_POWER_ARENA_BYTES(CONFIG_SITES)]);

/* Each guarded object: its canaries and its whole size. */
#define GUARD(name) {name.before, name.after, sizeof name}
static const struct {
    uint8_t *start, *after;
    size_t bytes;
} guarded[] = {GUARD(guarded_diagram), GUARD(guarded_arena), GUARD(guarded_tracker),
               GUARD(guarded_power), GUARD(guarded_power_arena)};
#define GUARDED_COUNT (sizeof guarded / sizeof guarded[0])

static void fill(void *to, size_t n)
{
    uint8_t *t = to;
    for (size_t i = 0; i < n; i++) {
        t[i] = PATTERN;
    }
}

/* Bytes of [from, from + n) that are no longer the pattern. */
static uint32_t changed(const void *from, size_t n)
{
    const uint8_t *f = from;
    uint32_t count = 0;
    for (size_t i = 0; i < n; i++) {
        count += (f[i] != PATTERN) ? 1u : 0u;
    }
    return count;
}

/* Bytes changed in the canaries, or (all) anywhere in the guarded objects. */
static uint32_t guarded_changed(bool all)
{
    uint32_t count = 0;
    for (size_t k = 0; k < GUARDED_COUNT; k++) {
        if (all) {
            count += changed(guarded[k].start, guarded[k].bytes);
        } else {
            count += changed(guarded[k].start, CANARY) +
                     changed(guarded[k].after, CANARY);
        }
    }
    return count;
}

void CONFIG_CASE(const char *name)
{
    for (size_t k = 0; k < GUARDED_COUNT; k++) {
        fill(guarded[k].start, guarded[k].bytes);
    }
    int err = vor_init(&guarded_diagram.d, guarded_arena.arena, sizeof guarded_arena.arena,
                       CONFIG_SITES);
    CHECK(err == CONFIG_EXPECT, "%s: vor_init returned %d, expected %d", name, err,
          CONFIG_EXPECT);
    int power_err = vor_power_init(&guarded_power.pd, guarded_power_arena.arena,
                                   sizeof guarded_power_arena.arena, CONFIG_SITES);
    CHECK(power_err == CONFIG_EXPECT, "%s: vor_power_init returned %d, expected %d", name,
          power_err, CONFIG_EXPECT);
    if (CONFIG_EXPECT == VOR_ERR_CONFIG) {
        err = vor_tracker_begin(&guarded_tracker.t, &guarded_diagram.d);
        CHECK(err == VOR_ERR_CONFIG, "%s: vor_tracker_begin returned %d", name, err);
        uint32_t written = guarded_changed(true);
        CHECK(written == 0u, "%s: a refused call wrote %u bytes", name, written);
        return;
    }
    /* weighted sites work too: a ring around a light centre, hidden */
    for (uint32_t i = 0; i < 8u; i++) {
        vor_point_t p = {(int32_t)(i % 3u) * 100 - 100, (int32_t)(i / 3u) * 100 - 100};
        power_err |= vor_power_insert(&guarded_power.pd, p, (i == 4u) ? -50000 : 0, NULL);
    }
    CHECK((power_err == VOR_OK) && (vor_power_validate(&guarded_power.pd, NULL) == VOR_OK) &&
              (vor_power_hidden(&guarded_power.pd, 4) == 1),
          "%s: weighted sites (err %d)", name, power_err);
    /* the options agree: the diagram works, and tracking a point across
     * every cell writes nothing outside the tracker */
    test_rng_t rng;
    test_rng_seed(&rng, 0xC0F1);
    for (uint32_t i = 0; i < CONFIG_SITES; i++) {
        vor_point_t p;
        p.x = test_rng_range(&rng, -1000, 1000);
        p.y = test_rng_range(&rng, -1000, 1000);
        err |= vor_insert(&guarded_diagram.d, p, NULL);
    }
    err |= vor_tracker_begin(&guarded_tracker.t, &guarded_diagram.d);
    uint32_t wrong = 0;
    for (int32_t y = -1100; y <= 1100; y += 50) {
        for (int32_t x = -1100; x <= 1100; x += 50) {
            uint32_t tracked = 0, nearest = 1;
            err |= vor_track(&guarded_tracker.t, (vor_point_t){x, y}, &tracked);
            err |= vor_nearest(&guarded_diagram.d, (vor_point_t){x, y}, VOR_NO_HINT, &nearest);
            wrong += (tracked != nearest) ? 1u : 0u;
        }
    }
    CHECK(err == VOR_OK && wrong == 0u, "%s: %u tracked answers wrong (err %d)", name, wrong,
          err);
    /* the contract library counts nothing (VOR_STATS 0): nothing to read */
    vor_stats_t counters;
    fill(&counters, sizeof counters);
    CHECK(vor_stats(&guarded_diagram.d, &counters) == VOR_ERR_ARG &&
              changed(&counters, sizeof counters) == 0u,
          "%s: vor_stats without VOR_STATS", name);
    CHECK(guarded_changed(false) == 0u, "%s: %u canary bytes overwritten", name,
          guarded_changed(false));
}
