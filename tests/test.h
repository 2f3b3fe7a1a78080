/* SPDX-License-Identifier: MIT */
/*
 * test.h - the small test harness shared by every target.
 *
 * The same sources run on the host and as firmware under QEMU, so the
 * harness needs nothing but port/port.h: its own formatter, its own
 * pseudo-random generator, and counters. A run ends with the line
 * "N passed, N failed"; main() returns non-zero when anything failed.
 */
#ifndef VOR_TEST_H
#define VOR_TEST_H

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "port.h"
#include "vor.h"

/* printf subset: %d %i %u %x %c %s %%, with l / ll / z length modifiers
 * and an optional width ("%8u", "%08x"). */
void test_printf(const char *format, ...);

/* Record one check. Prints the message (printf-style) when it fails;
 * stops printing after many failures so a broken build stays readable. */
bool test_check(bool ok, const char *file, int line, const char *format, ...);

#define CHECK(ok, ...) test_check((ok), __FILE__, __LINE__, __VA_ARGS__)

/* Prints the closing "N passed, N failed" line. */
void test_summary(void);
unsigned long test_failures(void);

/*
 * Named cases (docs/testing.md). A group function runs each case as
 *
 *     TEST_CASE("brute_force") check_brute_force();
 *     TEST_CASE("sequence/%u", seed) { ... }
 *
 * The case is named "group/name" (the name printf-formatted, '/' nesting
 * it further), and its statement runs only when the filter selects it: a
 * pattern that is the name, or its beginning up to a '/'. A case fails
 * when one of its checks fails, or when it runs no check. Cases do not
 * nest, and no return or break leaves one (its end would not be counted).
 * test_case_begin returns whether to run the case; test_case_end closes it
 * (it returns false, to end TEST_CASE's loop).
 */
bool test_case_begin(const char *format, ...);
bool test_case_end(void);
#define TEST_CASE(...)                                                                          \
    for (bool test_case_runs_ = test_case_begin(__VA_ARGS__); test_case_runs_;                 \
         test_case_runs_ = test_case_end())

/* test_select's flags: V=1 prints every case with its number of checks;
 * LIST=1 prints the names of the selected cases and runs none. */
#define TEST_VERBOSE 1u
#define TEST_LIST 2u

/* The filter: comma-separated patterns, "" for every case. */
void test_select(const char *patterns, unsigned flags);
/* The filter and flags each test program's main passes to test_select,
 * compiled in so that they work on every target: the Makefile's ONLY, V
 * and LIST define them for the objects that hold a main. */
#ifndef TEST_ONLY
#define TEST_ONLY ""
#endif
#ifndef TEST_MODE
#define TEST_MODE 0u
#endif
/* Runs a group function, its cases named "name/...". */
void test_group(const char *name, void (*run)(void));
/* Prints "cases: N passed, N failed" and the closing line, and returns
 * main's status; a filter that selects no case is a failure. */
int test_finish(void);

/* Deterministic xorshift generator: the same sequence on every target. */
typedef struct {
    uint64_t state;
} test_rng_t;

/* Seeds rng and returns it (a case passes test_rng_seed(&rng, seed)). */
test_rng_t *test_rng_seed(test_rng_t *rng, uint64_t seed);
uint32_t test_rng_u32(test_rng_t *rng);
/* Uniform in [lo, hi], inclusive, for hi - lo < 2^32. */
int32_t test_rng_range(test_rng_t *rng, int32_t lo, int32_t hi);

/* Byte-wise comparison and copy of n bytes (the harness uses no libc). */
bool test_same_bytes(const void *a, const void *b, size_t n);
void test_copy_bytes(void *to, const void *from, size_t n);

/* Every predicate call d's statistics counted (all tiers, perturbed
 * included; the test builds count, VOR_STATS): a move that made none took
 * the motion cache's fast path. UINT32_MAX from a library without them. */
uint32_t test_predicate_calls(const vor_t *d);

/* The number of site's neighbours in d (vor_neighbours; 0 when it is no
 * vertex). */
uint32_t test_degree(const vor_t *d, uint32_t site);

/* Builder options with a split and the other fields' defaults, for
 * vor_build_dc and vor_build_dc_forked. */
#define TEST_SPLIT(split)                                                      \
    (&(vor_build_options_t){VOR_ORDER_QUADTREE, (enum vor_dc_split)(split), 0})

/* The groups of tests, one per part of the library. */
/* An order-independent fingerprint of a set of triangles (fingerprint.c):
 * count plus two sums of mixed hashes of the triangles rotated to start at
 * their smallest id. Equal sets give equal fingerprints; a difference is
 * missed with probability about 2^-64. */
typedef struct {
    uint32_t count;
    uint64_t sum1, sum2;
} test_fingerprint_t;

void test_fingerprint_add(test_fingerprint_t *f, const uint32_t ids[3]);
/* The triangles the iterator reports for d, ids mapped through map (NULL:
 * as they are). */
test_fingerprint_t test_fingerprint_of(const vor_t *d, const uint32_t *map);
bool test_same_fingerprint(test_fingerprint_t a, test_fingerprint_t b);

void test_predicates(void);
void test_mesh(void);
void test_queries(void);
void test_raster(void);
void test_geometry(void);
void test_raster_metrics(void);
void test_korder(void);
void test_true_output(void);
void test_api_safety(void);
void test_centroid(void);
void test_dynamic(void);
void test_motion(void);
void test_fork_join(void);
void test_cdt(void);
void test_power(void);
void test_interpolate(void);
void test_field(void);
void test_locate(void);
void test_clip(void);
void test_order(void);

#endif
