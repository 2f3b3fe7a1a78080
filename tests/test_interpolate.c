/* SPDX-License-Identifier: MIT */
/*
 * test_interpolate.c - vor_sibson and vor_interpolate against independent
 * references:
 *   - tests/vectors/interpolate_vectors.h: Sibson coordinates by exact
 *     rational clipping in Python (tools/gen_interpolate_vectors.py),
 *     cocircular squares, grids and circles, collinear hull sites, wide
 *     coordinates, points outside, at sites and on hull edges;
 *   - invariants on random sites, small and up to the int32 limits, in
 *     the test's own 4096-bit integers: the weights are positive and add
 *     up to the denominator, sum w_i p_i = D q (linear precision); a
 *     quarter turn of sites and query (other triangles under the
 *     perturbation, other denominators) gives the same fractions;
 *     vor_interpolate's exact value is sum v_i w_i / D and its rounding
 *     is checked as exact inequalities;
 *   - a site gives its value, a hull edge the linear interpolation of its
 *     ends, a point outside VOR_ERR_OUTSIDE;
 *   - bad arguments, a scratch too small, any alignment: failing calls
 *     leave the outputs as they were.
 */
#include "test.h"
#include "vor.h"
#include "interpolate_vectors.h"

#define WIDE_LIMBS 128u
#include "wide.h"

#define IP_SITES 24u
#define IP_K 24u

static vor_point_t ip_points[IP_SITES];
static vor_point_t ip_turned[IP_SITES];
static uint32_t ip_first[IP_SITES];
static uint8_t ip_arena[VOR_ARENA_BYTES(IP_SITES)] __attribute__((aligned(8)));
static uint8_t ip_arena2[VOR_ARENA_BYTES(IP_SITES)] __attribute__((aligned(8)));
static uint8_t ip_scratch[VOR_SIBSON_SCRATCH_BYTES(IP_K) + 8u];
static uint8_t ip_scratch2[VOR_SIBSON_SCRATCH_BYTES(IP_K) + 8u];
static int32_t ip_values[IP_SITES];

/* ------------------------------------------------------------------ */
/* 4096-bit two's complement integers (tests/wide.h)                   */

static wide_t big_a;
static wide_t big_b;
static wide_t big_c;
static wide_t big_d;
static wide_t big_e;

/* ------------------------------------------------------------------ */

static bool ip_build(vor_t *d, uint8_t *arena, const vor_point_t *points, uint32_t n)
{
    return (vor_init(d, arena, VOR_ARENA_BYTES(IP_SITES), IP_SITES) == VOR_OK) &&
           (vor_build(d, points, n, NULL, ip_first) == VOR_OK);
}

/* The invariants of one answer: positive weights adding up to the
 * denominator, linear precision, at most one listing of each site. */
static bool ip_invariants(const vor_t *d, const vor_coordinates_t *s, vor_point_t q)
{
    bool ok = (s->count >= 1u) && (s->limbs >= 1u);
    wide_words(&big_a, s->denominator, s->limbs);
    ok = ok && !wide_zero(&big_a);
    wide_set(&big_b, 0); /* sum w */
    wide_set(&big_c, 0); /* sum w (p - q).x */
    wide_set(&big_d, 0); /* sum w (p - q).y */
    for (uint32_t i = 0; i < s->count; i++) {
        wide_words(&big_e, s->weights + ((size_t)i * s->limbs), s->limbs);
        ok = ok && !wide_zero(&big_e);
        wide_add(&big_b, &big_e);
        static wide_t t;
        static wide_t f;
        vor_point_t p = d->sites[s->sites[i]];
        wide_set(&f, (int64_t)p.x - q.x);
        wide_mul(&t, &big_e, &f);
        wide_add(&big_c, &t);
        wide_set(&f, (int64_t)p.y - q.y);
        wide_mul(&t, &big_e, &f);
        wide_add(&big_d, &t);
        for (uint32_t j = 0; j < i; j++) {
            ok = ok && (s->sites[j] != s->sites[i]);
        }
    }
    return ok && wide_equal(&big_a, &big_b) && wide_zero(&big_c) && wide_zero(&big_d);
}

/* The brute force's coordinates of one query (Sibson's or Laplace's). */
static uint32_t ip_vector_weights(const vor_coordinates_t *s, const ipv_weight_t *weights, uint32_t count)
{
    uint32_t bad = 0;
    wide_words(&big_a, s->denominator, s->limbs);
    for (uint32_t j = 0; j < count; j++) {
        const ipv_weight_t *w = &weights[j];
        uint32_t k = 0;
        while ((k < s->count) && (s->sites[k] != w->site)) {
            k++;
        }
        if (k == s->count) {
            return bad + 1u;
        }
        /* w_k / D == num / den */
        wide_words(&big_b, s->weights + ((size_t)k * s->limbs), s->limbs);
        wide_words(&big_c, w->den, w->den_words);
        wide_mul(&big_d, &big_b, &big_c);
        wide_words(&big_b, w->num, w->num_words);
        wide_mul(&big_e, &big_b, &big_a);
        bad += wide_equal(&big_d, &big_e) ? 0u : 1u;
    }
    return bad;
}

static void check_vectors(bool laplace)
{
    vor_t d;
    uint32_t bad = 0;
    uint32_t config = 0xFFFFFFFFu;
    for (size_t i = 0; i < sizeof ipv_queries / sizeof ipv_queries[0]; i++) {
        const ipv_query_t *v = &ipv_queries[i];
        const ipv_config_t *c = &ipv_configs[v->config];
        if (v->config != config) {
            config = v->config;
            bad += ip_build(&d, ip_arena, c->sites, c->n) ? 0u : 1u;
        }
        vor_coordinates_t s;
        int err = (laplace ? vor_laplace : vor_sibson)(&d, v->q, VOR_NO_HINT, ip_scratch,
                                                      sizeof ip_scratch, &s);
        if (v->outside) {
            bad += (err == VOR_ERR_OUTSIDE) ? 0u : 1u;
            continue;
        }
        if ((err != VOR_OK) || (s.count != v->count) || !ip_invariants(&d, &s, v->q)) {
            bad++;
            continue;
        }
        bad += ip_vector_weights(&s, laplace ? v->laplace : v->weights, v->count);
    }
    CHECK(bad == 0u, "%u vectors differ from the brute force", bad);
}

/* A random point set: a grid (cocircular squares) or uniform, in
 * coordinates up to `range`. */
static uint32_t ip_random_sites(test_rng_t *rng, int32_t range, bool grid)
{
    uint32_t n = 3u + (test_rng_u32(rng) % (IP_SITES - 3u));
    for (uint32_t i = 0; i < n; i++) {
        if (grid) {
            int32_t step = range / 4;
            ip_points[i].x = test_rng_range(rng, -4, 4) * step;
            ip_points[i].y = test_rng_range(rng, -4, 4) * step;
        } else {
            ip_points[i].x = test_rng_range(rng, -range, range);
            ip_points[i].y = test_rng_range(rng, -range, range);
        }
        ip_values[i] = test_rng_range(rng, INT32_MIN, INT32_MAX);
    }
    return n;
}

/* Same fractions after a quarter turn (x, y) -> (-y, x), where the
 * triangles and denominators differ. */
static bool ip_turn_agrees(const vor_coordinates_t *s, const vor_coordinates_t *t)
{
    if (s->count != t->count) {
        return false;
    }
    wide_words(&big_a, s->denominator, s->limbs);
    wide_words(&big_b, t->denominator, t->limbs);
    for (uint32_t i = 0; i < s->count; i++) {
        uint32_t j = 0;
        while ((j < t->count) && (t->sites[j] != s->sites[i])) {
            j++;
        }
        if (j == t->count) {
            return false;
        }
        wide_words(&big_c, s->weights + ((size_t)i * s->limbs), s->limbs);
        wide_mul(&big_d, &big_c, &big_b);
        wide_words(&big_c, t->weights + ((size_t)j * t->limbs), t->limbs);
        wide_mul(&big_e, &big_c, &big_a);
        if (!wide_equal(&big_d, &big_e)) {
            return false;
        }
    }
    return true;
}

/* vor_interpolate's answer against sum v_i w_i / D from vor_sibson, and
 * its rounding, halves away from zero, as exact inequalities:
 * |2 N - 2 value D| <= D, and = D only away from zero. */
static bool ip_value_agrees(const vor_t *d, const vor_coordinates_t *s, const vor_interpolation_t *v)
{
    wide_set(&big_a, 0);
    for (uint32_t i = 0; i < s->count; i++) {
        static wide_t t;
        wide_words(&big_b, s->weights + ((size_t)i * s->limbs), s->limbs);
        wide_set(&big_c, ip_values[s->sites[i]]);
        wide_mul(&t, &big_b, &big_c);
        wide_add(&big_a, &t);
    }
    (void)d;
    wide_words(&big_b, s->denominator, s->limbs);
    /* the exact value as given: sign |N| / D' with N / D' = sum / D */
    wide_words(&big_c, v->numerator, v->limbs);
    if (v->sign < 0) {
        wide_neg(&big_c);
    }
    wide_words(&big_d, v->denominator, v->limbs);
    wide_mul(&big_e, &big_c, &big_b);
    static wide_t t;
    wide_mul(&t, &big_a, &big_d);
    if (!wide_equal(&big_e, &t) || (wide_zero(&big_c) != (v->sign == 0))) {
        return false;
    }
    /* e = 2 N - 2 value D' */
    big_e = big_c;
    wide_add(&big_e, &big_c);
    wide_set(&t, 2 * (int64_t)v->value);
    static wide_t u;
    wide_mul(&u, &t, &big_d);
    wide_sub(&big_e, &u);
    /* |e| <= D'; at a half (|e| = D') away from zero: e = -D' for
     * N > 0, e = D' for N < 0 */
    bool negative = wide_negative(&big_e);
    if (negative) {
        wide_neg(&big_e);
    }
    wide_sub(&big_e, &big_d); /* |e| - D' <= 0 */
    if (!wide_negative(&big_e) && !wide_zero(&big_e)) {
        return false;
    }
    if (wide_zero(&big_e)) { /* a half: rounded away from zero */
        return negative ? (v->sign > 0) : (v->sign < 0);
    }
    return true;
}

/* The point turned a quarter: (x, y) -> (-y, x), for coordinates whose
 * negation fits (never INT32_MIN). */
static vor_point_t ip_turn(vor_point_t p)
{
    vor_point_t r = {-p.y, p.x};
    return r;
}

static void check_random(test_rng_t *rng, int32_t range, bool grid, uint32_t rounds)
{
    uint32_t bad = 0;
    uint32_t inside = 0;
    for (uint32_t round = 0; round < rounds; round++) {
        uint32_t n = ip_random_sites(rng, range, grid);
        for (uint32_t i = 0; i < n; i++) {
            ip_turned[i] = ip_turn(ip_points[i]);
        }
        vor_t d;
        vor_t e;
        if (!ip_build(&d, ip_arena, ip_points, n) || !ip_build(&e, ip_arena2, ip_turned, n)) {
            bad++;
            continue;
        }
        for (uint32_t j = 0; j < 8u; j++) {
            vor_point_t q = {test_rng_range(rng, -range, range), test_rng_range(rng, -range, range)};
            if (j == 0u) { /* a midpoint of two sites: often on an edge */
                vor_point_t a = ip_points[test_rng_u32(rng) % n];
                vor_point_t b = ip_points[test_rng_u32(rng) % n];
                q.x = (int32_t)(((int64_t)a.x + b.x) / 2);
                q.y = (int32_t)(((int64_t)a.y + b.y) / 2);
            }
            vor_coordinates_t s;
            vor_coordinates_t t;
            int err = vor_sibson(&d, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &s);
            int err2 = vor_sibson(&e, ip_turn(q), VOR_NO_HINT, ip_scratch2, sizeof ip_scratch2, &t);
            if ((err != err2) || ((err != VOR_OK) && (err != VOR_ERR_OUTSIDE))) {
                bad++;
                continue;
            }
            if (err != VOR_OK) {
                continue;
            }
            inside++;
            bad += (ip_invariants(&d, &s, q) && ip_turn_agrees(&s, &t)) ? 0u : 1u;
            vor_interpolation_t v;
            err = vor_interpolate(&d, ip_values, q, VOR_NO_HINT, ip_scratch2, sizeof ip_scratch2, &v);
            bad += ((err == VOR_OK) && (v.neighbours == s.count) && ip_value_agrees(&d, &s, &v)) ? 0u : 1u;
            /* Laplace's: the same neighbours, the same invariants */
            err = vor_laplace(&d, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &s);
            err2 = vor_laplace(&e, ip_turn(q), VOR_NO_HINT, ip_scratch2, sizeof ip_scratch2, &t);
            bad += ((err == VOR_OK) && (err2 == VOR_OK) && ip_invariants(&d, &s, q) &&
                    ip_turn_agrees(&s, &t)) ? 0u : 1u;
            err = vor_interpolate_laplace(&d, ip_values, q, VOR_NO_HINT, ip_scratch2, sizeof ip_scratch2, &v);
            bad += ((err == VOR_OK) && (v.neighbours == s.count) && ip_value_agrees(&d, &s, &v)) ? 0u : 1u;
        }
    }
    CHECK(bad == 0u, "%u random answers broke an invariant", bad);
    CHECK(inside > rounds, "only %u queries inside the hull", inside);
}

/* A site gives its value; a hull edge the linear interpolation of its
 * ends; outside the hull, VOR_ERR_OUTSIDE. */
static void check_special(void)
{
    static const vor_point_t square[] = {{0, 0}, {10, 0}, {20, 0}, {20, 20}, {0, 20}, {7, 9}};
    static const int32_t values[] = {0, 100, -300, 7, 1000, 55};
    vor_t d;
    vor_coordinates_t s;
    vor_interpolation_t v;
    CHECK(ip_build(&d, ip_arena, square, 6u), "built");
    for (uint32_t i = 0; i < 6u; i++) {
        CHECK(vor_interpolate(&d, values, square[i], i, ip_scratch, sizeof ip_scratch, &v) == VOR_OK &&
                  (v.value == values[i]) && (v.neighbours == 1u),
              "site %u: its value", i);
    }
    /* (15, 0) halfway between sites 1 and 2 (collinear on the hull) */
    vor_point_t q = {15, 0};
    CHECK(vor_interpolate(&d, values, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &v) == VOR_OK &&
              (v.value == -100) && (v.neighbours == 2u) && (v.sign < 0),
          "hull edge: -100, got %d", (int)v.value);
    CHECK(vor_interpolate_laplace(&d, values, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &v) == VOR_OK &&
              (v.value == -100) && (v.neighbours == 2u),
          "hull edge, Laplace: -100, got %d", (int)v.value);
    CHECK(vor_interpolate_laplace(&d, values, square[5], VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &v) == VOR_OK &&
              (v.value == 55),
          "site, Laplace: its value");
    q.x = 3; /* 3/10 of the way from 0 to 100 */
    CHECK(vor_interpolate(&d, values, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &v) == VOR_OK &&
              (v.value == 30) && (v.numerator[0] * 1u == 30u * v.denominator[0]) && (v.limbs == 1u),
          "hull edge: 30 exactly");
    q.x = 20; /* right edge x = 20: from (20, 0) -300 to (20, 20) 7 */
    q.y = 5;
    CHECK(vor_interpolate(&d, values, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &v) == VOR_OK &&
              (v.value == -223),
          "hull edge: -223.25 rounds to -223, got %d", (int)v.value);
    static const vor_point_t outside[] = {{-1, 0}, {21, 0}, {10, -1}, {10, 21}, {30, 0}, {INT32_MIN, INT32_MAX}};
    for (uint32_t i = 0; i < 6u; i++) {
        CHECK(vor_sibson(&d, outside[i], VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &s) == VOR_ERR_OUTSIDE,
              "outside %u", i);
    }
    /* collinear sites: the segment between neighbours, nothing off it */
    static const vor_point_t line[] = {{0, 0}, {6, 3}, {2, 1}, {-4, -2}};
    static const int32_t line_values[] = {0, 60, 20, -40};
    CHECK(ip_build(&d, ip_arena, line, 4u), "built");
    q.x = 4;
    q.y = 2;
    CHECK(vor_interpolate(&d, line_values, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &v) == VOR_OK &&
              (v.value == 40) && (v.neighbours == 2u),
          "collinear: 40");
    q.x = -1;
    q.y = 0;
    CHECK(vor_sibson(&d, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &s) == VOR_ERR_OUTSIDE, "off the line");
    q.x = 8;
    q.y = 4;
    CHECK(vor_sibson(&d, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &s) == VOR_ERR_OUTSIDE, "past the end");
    /* one site */
    CHECK(ip_build(&d, ip_arena, line, 1u), "built");
    CHECK(vor_sibson(&d, line[0], VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &s) == VOR_OK && s.count == 1u,
          "one site: itself");
    CHECK(vor_sibson(&d, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &s) == VOR_ERR_OUTSIDE, "one site: else outside");
}

/* Bad arguments, scratch too small, any alignment; failures leave the
 * outputs unchanged (VOR_ERR_NOMEM: only the count). */
static void check_errors(void)
{
    static const vor_point_t grid[] = {{0, 0}, {8, 0}, {8, 8}, {0, 8}, {3, 4}, {5, 3}, {4, 6}};
    static const int32_t values[] = {1, 2, 3, 4, 5, 6, 7};
    vor_t d;
    vor_t empty;
    vor_coordinates_t s;
    vor_coordinates_t keep;
    vor_interpolation_t v;
    vor_interpolation_t keep_v;
    vor_point_t q = {4, 4};
    CHECK(ip_build(&d, ip_arena, grid, 7u), "built");
    CHECK(vor_init(&empty, ip_arena2, VOR_ARENA_BYTES(IP_SITES), IP_SITES) == VOR_OK, "init");
    for (unsigned i = 0; i < sizeof s; i++) {
        ((uint8_t *)&s)[i] = 0xA5u;
        ((uint8_t *)&keep)[i] = 0xA5u;
    }
    for (unsigned i = 0; i < sizeof v; i++) {
        ((uint8_t *)&v)[i] = 0x5Au;
        ((uint8_t *)&keep_v)[i] = 0x5Au;
    }
    CHECK(vor_sibson(NULL, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &s) == VOR_ERR_ARG, "NULL d");
    CHECK(vor_sibson(&d, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, NULL) == VOR_ERR_ARG, "NULL out");
    CHECK(vor_sibson(&d, q, VOR_NO_HINT, NULL, 8u, &s) == VOR_ERR_ARG, "NULL scratch");
    CHECK(vor_sibson(&d, q, 99u, ip_scratch, sizeof ip_scratch, &s) == VOR_ERR_ARG, "bad hint");
    CHECK(vor_sibson(&empty, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &s) == VOR_ERR_EMPTY, "empty");
    CHECK(vor_interpolate(&d, NULL, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &v) == VOR_ERR_ARG, "NULL values");
    CHECK(vor_laplace(NULL, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &s) == VOR_ERR_ARG, "Laplace: NULL d");
    CHECK(vor_interpolate_laplace(&d, NULL, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &v) == VOR_ERR_ARG,
          "Laplace: NULL values");
    CHECK(vor_interpolate(&d, values, q, 99u, ip_scratch, sizeof ip_scratch, &v) == VOR_ERR_ARG, "bad hint");
    q.x = 9;
    CHECK(vor_interpolate(&d, values, q, VOR_NO_HINT, ip_scratch, sizeof ip_scratch, &v) == VOR_ERR_OUTSIDE, "outside");
    CHECK(test_same_bytes(&s, &keep, sizeof s) && test_same_bytes(&v, &keep_v, sizeof v), "outputs unchanged");
    /* too small: the count only, then enough at every alignment */
    q.x = 4;
    CHECK(vor_sibson(&d, q, VOR_NO_HINT, ip_scratch, 0u, &s) == VOR_ERR_NOMEM && (s.count >= 3u),
          "no scratch: NOMEM with k");
    uint32_t k = s.count;
    s.count = 0;
    CHECK(vor_laplace(&d, q, VOR_NO_HINT, NULL, 0u, &s) == VOR_ERR_NOMEM && (s.count == k),
          "no scratch at all (NULL): NOMEM with k");
    CHECK(vor_sibson(&d, q, VOR_NO_HINT, ip_scratch, VOR_SIBSON_SCRATCH_BYTES(k) - 9u, &s) == VOR_ERR_NOMEM,
          "too small by one");
    CHECK(vor_interpolate(&d, values, q, VOR_NO_HINT, NULL, 0u, &v) == VOR_ERR_NOMEM && (v.neighbours == k),
          "interpolate: NOMEM with k");
    vor_point_t edge = {4, 0}; /* on the hull edge from (0, 0) to (8, 0) */
    CHECK(vor_sibson(&d, edge, VOR_NO_HINT, ip_scratch, VOR_SIBSON_SCRATCH_BYTES(2) - 9u, &s) == VOR_ERR_NOMEM &&
              (s.count == 2u),
          "hull edge: NOMEM with 2");
    for (unsigned offset = 0; offset < 8u; offset++) {
        CHECK(vor_sibson(&d, q, VOR_NO_HINT, ip_scratch + offset, VOR_SIBSON_SCRATCH_BYTES(k), &s) == VOR_OK &&
                  (s.count == k) && ip_invariants(&d, &s, q),
              "alignment %u", offset);
    }
}

void test_interpolate(void)
{
    test_rng_t rng;
    TEST_CASE("vectors") check_vectors(false);
    TEST_CASE("laplace_vectors") check_vectors(true);
    TEST_CASE("special") check_special();
    TEST_CASE("errors") check_errors();
    TEST_CASE("small") check_random(test_rng_seed(&rng, 26u), 6, false, 40u);
    TEST_CASE("grid") check_random(test_rng_seed(&rng, 27u), 16, true, 40u);
    TEST_CASE("wide") check_random(test_rng_seed(&rng, 28u), INT32_MAX, false, 20u);
    TEST_CASE("wide_grid") check_random(test_rng_seed(&rng, 29u), INT32_MAX - 3, true, 20u);
}
