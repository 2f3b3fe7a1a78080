/* SPDX-License-Identifier: MIT */
/*
 * test_predicates.c - the exact predicates against the independent oracle
 * (tools/gen_predicate_vectors.py, Python big integers), plus properties
 * the oracle does not state: sign changes under row swaps, tier coverage
 * and counters, and the multiply helpers against the compiler's own; and
 * the perturbed signs against the perturbation's definition, evaluated
 * here without any of the library's reductions.
 */
#include "test.h"

#include "multiword.h"
#include "predicate_vectors.h"
#include "crossing.h"
#include "crossing_vectors.h"
#include "predicates.h"
#include "vor.h"

/* The test's own integers (tests/wide.h): 256 bits hold every exact value
 * checked here (an incircle determinant of 49-bit differences). */
#define WIDE_LIMBS 8u
#include "wide.h"

static const char *const op_names[] = {"orient2d", "incircle", "closer"};

static vor_point_t point_of(const struct predicate_vector *v, unsigned k)
{
    vor_point_t p = {v->xy[2 * k], v->xy[2 * k + 1]};
    return p;
}

static unsigned rank_of(const struct predicate_vector *v, unsigned k)
{
    return (v->ranks >> (2 * k)) & 3u;
}

/* The exact predicate of v with its points in the order given by perm:
 * the public call, and with stats the library's counted evaluation too
 * (the counters are VOR_STATS's, private to the diagram otherwise), which
 * must agree (9 when it does not). */
static int exact_sign(const struct predicate_vector *v, const unsigned perm[4],
                      vor_stats_t *stats)
{
    vor_point_t p[4];
    for (unsigned k = 0; k < 4; k++) {
        p[k] = point_of(v, perm[k]);
    }
    int sign, counted;
    switch (v->op) {
    case PV_ORIENT2D:
        sign = vor_orient2d(p[0], p[1], p[2]);
        counted = (stats != NULL) ? vor__orient2d_exact(&p[0], &p[1], &p[2], stats) : sign;
        break;
    case PV_INCIRCLE:
        sign = vor_incircle(p[0], p[1], p[2], p[3]);
        counted = (stats != NULL) ? vor__incircle_exact(&p[0], &p[1], &p[2], &p[3], stats) : sign;
        break;
    default:
        sign = vor_closer(p[0], p[1], p[2]);
        counted = (stats != NULL) ? vor__closer_sign(&p[0], &p[1], &p[2], stats) : sign;
        break;
    }
    return (sign == counted) ? sign : 9;
}

/* The perturbed predicate of v: site rank_of(k) holds point k. */
static int perturbed_sign(const struct predicate_vector *v,
                          const unsigned perm[4], vor_stats_t *stats)
{
    unsigned points = (v->op == PV_ORIENT2D) ? 3u : 4u;
    vor_point_t sites[4];
    uint32_t id[4] = {0, 0, 0, 0};
    for (unsigned k = 0; k < points; k++) {
        sites[rank_of(v, k)] = point_of(v, k);
    }
    for (unsigned k = 0; k < points; k++) {
        id[k] = rank_of(v, perm[k]);
    }
    int sign, counted;
    if (v->op == PV_ORIENT2D) {
        sign = vor_orient2d_sos(sites, id[0], id[1], id[2]);
        counted = sign;
        if (stats != NULL) {
            counted = vor__orient2d_exact(&sites[id[0]], &sites[id[1]], &sites[id[2]], stats);
            counted = (counted != 0) ? counted
                                     : vor__orient2d_perturbed(sites, id[0], id[1], id[2], stats);
        }
    } else {
        sign = vor_incircle_sos(sites, id[0], id[1], id[2], id[3]);
        counted = sign;
        if (stats != NULL) {
            counted = vor__incircle_exact(&sites[id[0]], &sites[id[1]], &sites[id[2]],
                                          &sites[id[3]], stats);
            counted = (counted != 0)
                          ? counted
                          : vor__incircle_perturbed(sites, id[0], id[1], id[2], id[3], stats);
        }
    }
    return (sign == counted) ? sign : 9;
}

static void check_vectors(void)
{
    static const unsigned identity[4] = {0, 1, 2, 3};
    static const unsigned swap01[4] = {1, 0, 2, 3};   /* one transposition */
    static const unsigned swap12[4] = {0, 2, 1, 3};   /* closer: a <-> b */
    static const unsigned rotate[4] = {1, 2, 0, 3};   /* even permutation */
    vor_stats_t stats = {0};
    unsigned long calls[3] = {0, 0, 0}, zeros[3] = {0, 0, 0};
    unsigned long families[PF_FAMILIES] = {0};
    unsigned long vector_failures = 0;

    for (size_t n = 0; n < predicate_vector_count; n++) {
        const struct predicate_vector *v = &predicate_vectors[n];
        bool ok = true;
        calls[v->op]++;
        zeros[v->op] += (v->exact == 0) ? 1u : 0u;
        families[v->family]++;
        int exact = exact_sign(v, identity, &stats);
        ok &= CHECK(exact == v->exact, "vector %zu (%s, family %u): exact %d, expected %d",
                    n, op_names[v->op], v->family, exact, v->exact);
        if (v->op == PV_CLOSER) {
            int swapped = exact_sign(v, swap12, NULL);
            ok &= CHECK(swapped == -v->exact, "vector %zu: closer(q,b,a) = %d, expected %d",
                        n, swapped, -v->exact);
        } else {
            int swapped = exact_sign(v, swap01, NULL);
            ok &= CHECK(swapped == -v->exact, "vector %zu: swapped exact %d, expected %d",
                        n, swapped, -v->exact);
            int perturbed = perturbed_sign(v, identity, &stats);
            ok &= CHECK(perturbed == v->perturbed,
                        "vector %zu (%s, family %u): perturbed %d, expected %d",
                        n, op_names[v->op], v->family, perturbed, v->perturbed);
            int p_swapped = perturbed_sign(v, swap01, NULL);
            ok &= CHECK(p_swapped == -v->perturbed,
                        "vector %zu: swapped perturbed %d, expected %d", n, p_swapped,
                        -v->perturbed);
            int p_rotated = perturbed_sign(v, rotate, NULL);
            ok &= CHECK(p_rotated == v->perturbed,
                        "vector %zu: rotated perturbed %d, expected %d", n, p_rotated,
                        v->perturbed);
        }
        vector_failures += ok ? 0u : 1u;
    }

    test_printf("predicate vectors: %zu cases (orient2d %lu, incircle %lu, closer %lu; "
                "exactly zero %lu/%lu/%lu), %lu failing\n",
                predicate_vector_count, calls[0], calls[1], calls[2], zeros[0], zeros[1],
                zeros[2], vector_failures);
    CHECK(predicate_vector_count >= 10000, "only %zu vectors", predicate_vector_count);
    for (unsigned f = 0; f < PF_FAMILIES; f++) {
        CHECK(families[f] > 0, "no vectors of family %u", f);
    }

    /* every tier ran, and the counters add up to the calls made */
    const char *const tier_names[VOR_TIERS] = {"narrow", "mid", "wide"};
    unsigned long counted[3] = {0, 0, 0};
    for (unsigned t = 0; t < VOR_TIERS; t++) {
        counted[0] += stats.orient2d[t];
        counted[1] += stats.incircle[t];
        counted[2] += stats.closer[t];
        CHECK(t == VOR_TIER_MID || stats.orient2d[t] > 100, "orient2d %s tier ran %u times",
              tier_names[t], stats.orient2d[t]);
        CHECK(stats.incircle[t] > 100, "incircle %s tier ran %u times", tier_names[t],
              stats.incircle[t]);
        CHECK(t == VOR_TIER_MID || stats.closer[t] > 100, "closer %s tier ran %u times",
              tier_names[t], stats.closer[t]);
    }
    CHECK(stats.orient2d[VOR_TIER_MID] == 0 && stats.closer[VOR_TIER_MID] == 0,
          "orient2d and closer have no mid tier");
    /* exact calls once, perturbed calls evaluate the exact sign once more */
    CHECK(counted[0] == 2 * calls[0], "orient2d counters %lu for %lu calls", counted[0],
          2 * calls[0]);
    CHECK(counted[1] == 2 * calls[1], "incircle counters %lu for %lu calls", counted[1],
          2 * calls[1]);
    CHECK(counted[2] == calls[2], "closer counters %lu for %lu calls", counted[2], calls[2]);
    CHECK(stats.orient2d_perturbed == zeros[0], "orient2d perturbed %u, exact zeros %lu",
          stats.orient2d_perturbed, zeros[0]);
    CHECK(stats.incircle_perturbed == zeros[1], "incircle perturbed %u, exact zeros %lu",
          stats.incircle_perturbed, zeros[1]);
}

/* The product helpers behind every tier, against the compiler's multiply
 * (on Cortex-M0 that is libgcc's, an independent implementation). */
static void check_multiply(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 7);
    static const uint32_t edges[] = {0u, 1u, 0xFFFFu, 0x10000u, 0x7FFFFFFFu,
                                     0x80000000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
    unsigned bad_u = 0, bad_i = 0;
    for (unsigned n = 0; n < 20000; n++) {
        uint32_t a = (n < 64) ? edges[n % 8] : test_rng_u32(&rng);
        uint32_t b = (n < 64) ? edges[n / 8] : test_rng_u32(&rng);
        volatile uint64_t wa = a, wb = b; /* keep the reference a real 64-bit multiply */
        bad_u += (vor__mul_u32(a, b) != wa * wb) ? 1u : 0u;
        volatile int64_t sa = (int32_t)a, sb = (int32_t)b;
        bad_i += (vor__mul_i32((int32_t)a, (int32_t)b) != sa * sb) ? 1u : 0u;
    }
    CHECK(bad_u == 0, "vor__mul_u32 wrong %u times", bad_u);
    CHECK(bad_i == 0, "vor__mul_i32 wrong %u times", bad_i);
}

/* The helpers the tiers state their bounds with: the bit length against
 * a count of halvings, every difference's bound taken back to it
 * (vor__mw_unbound), and the 64x32 product at the edges of its domain,
 * -2^63 included, against the compiler's own multiply. */
static void check_bounds(void)
{
    unsigned bad_length = 0, bad_unbound = 0, bad_product = 0;
    for (unsigned k = 0; k < 32u; k++) {
        uint32_t v = (uint32_t)1 << k;
        unsigned want = 0;
        for (uint32_t w = v; w != 0u; w >>= 1) {
            want++;
        }
        bad_length += (vor__mw_bit_length32(v) != want) ? 1u : 0u;
        bad_length += (vor__mw_bit_length32(v - 1u) != want - 1u) ? 1u : 0u;
        bad_length += (vor__mw_bit_length32(v | (v - 1u)) != want) ? 1u : 0u;
    }
    bad_length += (vor__mw_bit_length32(0xFFFFFFFFu) != 32u) ? 1u : 0u;
    static const int64_t differences[] = {INT32_MIN, -16385, -16384, -1, 0, 1, 16383, 16384,
                                          INT32_MAX};
    for (unsigned i = 0; i < sizeof differences / sizeof differences[0]; i++) {
        int64_t d = differences[i];
        bad_unbound += (vor__mw_unbound(vor__mw_bound(d), d) != (int32_t)d) ? 1u : 0u;
    }
    static const int64_t wide[] = {(int64_t)1 << 32, -((int64_t)1 << 32), ((int64_t)1 << 32) - 1,
                                   (int64_t)1 << 47, -((int64_t)1 << 47), 3, -3, 0};
    static const int32_t narrow[] = {INT32_MIN, INT32_MAX, -32768, 32767, -1, 1, 0};
    for (unsigned i = 0; i < sizeof wide / sizeof wide[0]; i++) {
        for (unsigned j = 0; j < sizeof narrow / sizeof narrow[0]; j++) {
            int64_t a = wide[i];
            int32_t b = narrow[j];
            /* only products that fit int64 (its domain): |a b| below
             * 2^63, or -2^63 itself */
            uint64_t ma = (a < 0) ? 0u - (uint64_t)a : (uint64_t)a;
            uint64_t mb = (b < 0) ? 0u - (uint64_t)(int64_t)b : (uint64_t)b;
            uint64_t most = ((a < 0) != (b < 0)) ? (uint64_t)1 << 63 : ((uint64_t)1 << 63) - 1u;
            if (mb != 0u && ma > most / mb) {
                continue;
            }
            volatile int64_t wa = a, wb = b; /* the compiler's own multiply */
            bad_product += (vor__mul_i64_i32(a, b) != wa * wb) ? 1u : 0u;
        }
    }
    CHECK(bad_length == 0, "vor__mw_bit_length32 wrong %u times", bad_length);
    CHECK(bad_unbound == 0, "vor__mw_unbound wrong %u times", bad_unbound);
    CHECK(bad_product == 0, "vor__mul_i64_i32 wrong %u times", bad_product);
}

/* The 64-bit shifts on 32-bit halves, against the compiler's own shift
 * (on 32-bit targets a libgcc routine or its inline code), for every
 * amount 0..63 on edge and random values. */
static void check_shift(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 11);
    static const uint64_t edges[] = {0u, 1u, 0xFFFFFFFFu, 0x100000000u, 0x8000000000000000u,
                                     0xFFFFFFFFFFFFFFFFu};
    unsigned bad_left = 0, bad_right = 0;
    for (unsigned n = 0; n < 64; n++) {
        uint64_t v = (n < 6) ? edges[n]
                             : ((uint64_t)test_rng_u32(&rng) << 32) | test_rng_u32(&rng);
        for (unsigned s = 0; s < 64; s++) {
            volatile uint64_t wv = v; /* keep the reference a real variable shift */
            volatile unsigned ws = s;
            bad_left += (vor__shl_u64(v, s) != wv << ws) ? 1u : 0u;
            bad_right += (vor__shr_u64(v, s) != wv >> ws) ? 1u : 0u;
        }
    }
    CHECK(bad_left == 0, "vor__shl_u64 wrong %u times", bad_left);
    CHECK(bad_right == 0, "vor__shr_u64 wrong %u times", bad_right);
}

/* Perturbed signs of every ordered triple and quadruple of a 3x3 grid with
 * a repeated point: antisymmetric in the order of the arguments, the
 * defining property the perturbation must keep for any index order. */
static void check_grid_antisymmetry(void)
{
    vor_point_t sites[10];
    for (unsigned k = 0; k < 9; k++) {
        sites[k].x = (int32_t)(k % 3) * 1000003 - 1000003;
        sites[k].y = (int32_t)(k / 3) * 1000003 - 1000003;
    }
    sites[9] = sites[4]; /* a duplicate of the centre, index 9 */
    unsigned bad = 0, count = 0;
    for (uint32_t i = 0; i < 10; i++) {
        for (uint32_t j = 0; j < 10; j++) {
            for (uint32_t k = 0; k < 10; k++) {
                if (i == j || j == k || i == k) {
                    continue;
                }
                int s = vor_orient2d_sos(sites, i, j, k);
                bad += (s == 0 || vor_orient2d_sos(sites, j, i, k) != -s ||
                        vor_orient2d_sos(sites, j, k, i) != s)
                           ? 1u
                           : 0u;
                for (uint32_t l = 0; l < 10; l += 3) {
                    if (l == i || l == j || l == k) {
                        continue;
                    }
                    int c = vor_incircle_sos(sites, i, j, k, l);
                    bad += (c == 0 || vor_incircle_sos(sites, j, i, k, l) != -c ||
                            vor_incircle_sos(sites, i, j, l, k) != -c ||
                            vor_incircle_sos(sites, l, k, j, i) != c)
                               ? 1u
                               : 0u;
                    count++;
                }
            }
        }
    }
    CHECK(bad == 0 && count > 1000, "grid antisymmetry: %u of %u wrong", bad, count);
}

/* ------------------------------------------------------------------ */
/* The power test and the power distance                               */

static vor_point_t power_point(const struct power_vector *v, unsigned k)
{
    vor_point_t p = {v->xy[2 * k], v->xy[2 * k + 1]};
    return p;
}

/* v's power test with its points in the order perm, weights shifted by
 * `shift` (a common shift keeps the sign): the public call, checked
 * against the counted one (9 when they differ); perturbed: under the
 * perturbation, site rank k holding point k. */
static int power_sign(const struct power_vector *v, const unsigned perm[4], int64_t shift,
                      bool perturbed, vor_stats_t *stats)
{
    vor_point_t p[4];
    int64_t w[4];
    vor_point_t sites[4];
    int64_t weights[4];
    uint32_t id[4];
    for (unsigned k = 0; k < 4; k++) {
        p[k] = power_point(v, perm[k]);
        w[k] = v->w[perm[k]] + shift;
        unsigned rank = (v->ranks >> (2 * k)) & 3u;
        sites[rank] = power_point(v, k);
        weights[rank] = v->w[k] + shift;
    }
    for (unsigned k = 0; k < 4; k++) {
        id[k] = (v->ranks >> (2 * perm[k])) & 3u;
    }
    if (perturbed) {
        int sign = vor_power_test_sos(sites, weights, id[0], id[1], id[2], id[3]);
        const int64_t wid[4] = {weights[id[0]], weights[id[1]], weights[id[2]], weights[id[3]]};
        int counted = vor__power_exact(&sites[id[0]], &sites[id[1]], &sites[id[2]],
                                       &sites[id[3]], wid, stats);
        counted = (counted != 0) ? counted
                                 : vor__power_perturbed(sites, weights, id[0], id[1], id[2],
                                                        id[3], stats);
        return (sign == counted) ? sign : 9;
    }
    int sign = vor_power_test(p[0], w[0], p[1], w[1], p[2], w[2], p[3], w[3]);
    int counted = vor__power_exact(&p[0], &p[1], &p[2], &p[3], w, stats);
    return (sign == counted) ? sign : 9;
}

/* The power vectors (tools/gen_predicate_vectors.py): exact and perturbed
 * signs, a transposition negating them and a rotation keeping them, a
 * common weight shift keeping them, equal weights agreeing with the
 * incircle test, and the counters: equal weights count as incircle
 * tests, the others as power tests. */
static void check_power_vectors(void)
{
    static const unsigned identity[4] = {0, 1, 2, 3};
    static const unsigned swap01[4] = {1, 0, 2, 3};
    static const unsigned rotate[4] = {1, 2, 0, 3};
    vor_stats_t stats = {0};
    unsigned long bad = 0, tests = 0, ties = 0, closers = 0, equal = 0, perturbed_power = 0;
    unsigned long families[PWF_FAMILIES] = {0};
    for (size_t n = 0; n < power_vector_count; n++) {
        const struct power_vector *v = &power_vectors[n];
        families[v->family]++;
        unsigned long before = bad;
        if (v->op == PW_CLOSER) {
            vor_point_t q = power_point(v, 0), a = power_point(v, 1), b = power_point(v, 2);
            int sign = vor_power_closer(q, a, v->w[1], b, v->w[2]);
            bad += (sign != v->exact) ? 1u : 0u;
            bad += (vor_power_closer(q, b, v->w[2], a, v->w[1]) != -v->exact) ? 1u : 0u;
            bad += (vor__power_closer_sign(&q, &a, v->w[1], &b, v->w[2], &stats) != v->exact) ? 1u : 0u;
            closers++;
        } else {
            bool same = v->w[0] == v->w[3] && v->w[1] == v->w[3] && v->w[2] == v->w[3];
            equal += same ? 1u : 0u;
            ties += (v->exact == 0) ? 1u : 0u;
            perturbed_power += (v->exact == 0 && !same) ? 1u : 0u;
            bad += (power_sign(v, identity, 0, false, &stats) != v->exact) ? 1u : 0u;
            bad += (power_sign(v, swap01, 0, false, NULL) != -v->exact) ? 1u : 0u;
            bad += (power_sign(v, rotate, 0, false, NULL) != v->exact) ? 1u : 0u;
            bad += (power_sign(v, identity, 0, true, &stats) != v->perturbed) ? 1u : 0u;
            bad += (power_sign(v, swap01, 0, true, NULL) != -v->perturbed) ? 1u : 0u;
            bad += (power_sign(v, rotate, 0, true, NULL) != v->perturbed) ? 1u : 0u;
            /* a shift that keeps every weight in int64 */
            int64_t low = v->w[0], high = v->w[0];
            for (unsigned k = 1; k < 4; k++) {
                low = (v->w[k] < low) ? v->w[k] : low;
                high = (v->w[k] > high) ? v->w[k] : high;
            }
            int64_t shift = (high <= INT64_MAX - ((int64_t)1 << 40)) ? ((int64_t)1 << 40)
                            : (low >= INT64_MIN + 12345) ? -12345 : 0;
            bad += (power_sign(v, identity, shift, false, NULL) != v->exact) ? 1u : 0u;
            bad += (power_sign(v, identity, shift, true, NULL) != v->perturbed) ? 1u : 0u;
            if (same) {
                vor_point_t p[4] = {power_point(v, 0), power_point(v, 1), power_point(v, 2),
                                    power_point(v, 3)};
                bad += (vor_incircle(p[0], p[1], p[2], p[3]) != v->exact) ? 1u : 0u;
            }
            tests++;
        }
        if (bad != before && before < 5u) {
            test_printf("power vector %zu (op %u, family %u) wrong\n", n, v->op, v->family);
        }
    }
    test_printf("power vectors: %lu tests (%lu exactly zero, %lu with equal weights), %lu "
                "comparisons\n", tests, ties, equal, closers);
    CHECK(bad == 0, "power vectors: %lu wrong", bad);
    for (unsigned f = 0; f < PWF_FAMILIES; f++) {
        CHECK(families[f] > 0, "no power vectors of family %u", f);
    }
#if VOR_STATS
    /* every counted call is one count: the unequal weights' exact tests and
     * comparisons in stats.power, their ties in stats.power_perturbed */
    CHECK(stats.power_perturbed == perturbed_power && stats.power > tests - equal,
          "power counters %u (ties %u), for %lu tests of unequal weights (ties %lu)",
          stats.power, stats.power_perturbed, tests - equal, perturbed_power);
#endif
}

/* ------------------------------------------------------------------ */
/* The perturbation against its definition                            */
/*
 * An independent evaluation of the perturbed signs: straight from the
 * definition in predicates.c, site i moved by dx_i = eps^(4 * 16^i), dy_i =
 * eps^(16^i), with none of the library's reductions (no translation, no
 * minor, no tiers, no closed forms, the dx^2 terms kept). Expanding
 * (x + dx)^2 + (y + dy)^2 gives each site's row as a sum of monomials,
 * whose exponent is a base-16 digit at the site's index: 0 for the point
 * itself, 1 for dy, 2 for dy^2, 4 for dx, 8 for dx^2. The sign is that of
 * the first nonzero determinant in increasing exponent order: digits
 * counted like an odometer, the largest index most significant. The
 * determinants come from the Leibniz formula in 160-bit limbs.
 */
#define REF_LIMBS VOR__LIMBS(160)

/* One row of the perturbed determinant: site (x, y)'s monomial `digit`. */
static void ref_row(int64_t row[4], uint64_t *lift, int orient, int32_t x, int32_t y,
                    unsigned digit)
{
    static const int64_t unit[9][2] = {{0, 0}, {0, 1}, {0, 0}, {0, 0}, {1, 0},
                                       {0, 0}, {0, 0}, {0, 0}, {0, 0}};
    row[0] = (digit == 0) ? x : unit[digit][0];
    row[1] = (digit == 0) ? y : unit[digit][1];
    /* the third column of orient2d is the constant 1; of incircle, the
     * lift: x^2 + y^2 <= 2^63 held apart in *lift (uint64), 2y, 1, 2x, 1 */
    *lift = 0;
    if (orient) {
        row[2] = (digit == 0) ? 1 : 0;
        row[3] = 0;
        return;
    }
    *lift = (digit == 0) ? (uint64_t)((int64_t)x * x) + (uint64_t)((int64_t)y * y) : 0u;
    row[2] = (digit == 1) ? 2 * (int64_t)y : (digit == 4) ? 2 * (int64_t)x
                                           : (digit == 2 || digit == 8) ? 1 : 0;
    row[3] = (digit == 0) ? 1 : 0;
}

/* Sign of the n x n determinant (n = 3 or 4) of rows whose first two
 * entries are x, y, 0 or 1 (products < 2^63), the third a lift (uint64,
 * lifts[r] when nonzero) or |.| <= 2^32, the fourth 0 or 1: each Leibniz
 * product < 2^126, the sum of 24 < 2^131. */
static int ref_det_sign(int64_t rows[4][4], const uint64_t lifts[4], unsigned n)
{
    static const unsigned char perms[24][4] = {
        {0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {0, 3, 2, 1},
        {1, 0, 2, 3}, {1, 0, 3, 2}, {1, 2, 0, 3}, {1, 2, 3, 0}, {1, 3, 0, 2}, {1, 3, 2, 0},
        {2, 0, 1, 3}, {2, 0, 3, 1}, {2, 1, 0, 3}, {2, 1, 3, 0}, {2, 3, 0, 1}, {2, 3, 1, 0},
        {3, 0, 1, 2}, {3, 0, 2, 1}, {3, 1, 0, 2}, {3, 1, 2, 0}, {3, 2, 0, 1}, {3, 2, 1, 0}};
    vor__limb sum[REF_LIMBS], a[REF_LIMBS], b[REF_LIMBS], product[REF_LIMBS];
    vor__mw_from_i64(sum, REF_LIMBS, 0);
    for (unsigned p = 0; p < 24; p++) {
        const unsigned char *s = perms[p];
        if (n == 3 && s[3] != 3) {
            continue; /* the 3 x 3 case: permutations fixing the 4th row */
        }
        unsigned inversions = 0;
        for (unsigned i = 0; i < 4; i++) {
            for (unsigned j = i + 1; j < 4; j++) {
                inversions += (s[i] > s[j]) ? 1u : 0u;
            }
        }
        int64_t last = (n == 4) ? rows[s[3]][3] : 1;
        if (last == 0) {
            continue;
        }
        vor__mw_from_i64(a, REF_LIMBS, rows[s[0]][0] * rows[s[1]][1]);
        if (lifts[s[2]] != 0u) {
            vor__mw_from_u64(b, REF_LIMBS, lifts[s[2]]);
        } else {
            vor__mw_from_i64(b, REF_LIMBS, rows[s[2]][2]);
        }
        vor__mw_mul(product, REF_LIMBS, a, REF_LIMBS, b, REF_LIMBS);
        if (inversions % 2u == 0u) {
            vor__mw_add(sum, product, REF_LIMBS);
        } else {
            vor__mw_sub(sum, product, REF_LIMBS);
        }
    }
    return vor__mw_sign(sum, REF_LIMBS);
}

/* The perturbed sign of orient2d (n = 3) or incircle (n = 4) of the sites
 * ids[0..n) in that argument order, ids a permutation of 0..n-1; *first
 * gets the position of the deciding term in the order (0: exact). */
static int ref_perturbed(const vor_point_t sites[4], const uint32_t ids[4], unsigned n,
                         unsigned *first)
{
    static const unsigned digits_incircle[5] = {0, 1, 2, 4, 8};
    static const unsigned digits_orient[3] = {0, 1, 4};
    const unsigned *digits = (n == 3) ? digits_orient : digits_incircle;
    unsigned radix = (n == 3) ? 3u : 5u;
    unsigned odometer[4] = {0, 0, 0, 0}; /* digit position per site index */
    for (unsigned term = 0;; term++) {
        int64_t rows[4][4];
        uint64_t lifts[4];
        for (unsigned r = 0; r < n; r++) {
            const vor_point_t *p = &sites[ids[r]];
            ref_row(rows[r], &lifts[r], n == 3, p->x, p->y, digits[odometer[ids[r]]]);
        }
        int sign = ref_det_sign(rows, lifts, n);
        if (sign != 0) {
            *first = term;
            return sign;
        }
        unsigned i = 0; /* next term: ends by radix^n terms (all dx^2: unit rows) */
        while (i < n && ++odometer[i] == radix) {
            odometer[i++] = 0;
        }
        if (i == n) {
            return 0;
        }
    }
}

/* A random int32 origin leaving room for a span of `span` (< 2^32). */
static int32_t origin_for(test_rng_t *rng, int64_t span)
{
    return test_rng_range(rng, INT32_MIN, (int32_t)(INT32_MAX - span));
}

/* Four points of a family chosen by `family`, differences below 2^bits
 * (bits <= 32). */
static void degenerate_quad(test_rng_t *rng, unsigned family, unsigned bits, vor_point_t q[4])
{
    int64_t limit = (int64_t)1 << bits; /* spans below it */
    int64_t unit = test_rng_range(rng, 1, (int32_t)((limit - 1) / 4 > 0 ? (limit - 1) / 4 : 1));
    switch (family) {
    case 0: /* rectangle corners on a lattice of random spacing: cocircular */
    case 3:   /* the same with one corner doubled */
    case 5: { /* spacings at the tiers' edges (differences -2^31 and 2^31 - 1) */
        static const int64_t edges[6] = {1, 0x3FFF, 0x4000, 0x7FFFFFFF, 0x80000000,
                                         0xFFFFFFFF};
        int64_t sx = unit * test_rng_range(rng, 1, 4), sy = unit * test_rng_range(rng, 1, 4);
        if (family == 5) {
            sx = edges[test_rng_range(rng, 0, 5)];
            sy = edges[test_rng_range(rng, 0, 5)];
        }
        if (test_rng_u32(rng) & 1u) {
            sy = sx; /* a lattice square, as on a grid */
        }
        int32_t ox = origin_for(rng, sx), oy = origin_for(rng, sy);
        for (unsigned k = 0; k < 4; k++) {
            q[k].x = (int32_t)(ox + ((k & 1u) ? sx : 0));
            q[k].y = (int32_t)(oy + ((k & 2u) ? sy : 0));
        }
        if (family == 3) {
            q[test_rng_range(rng, 0, 3)] = q[test_rng_range(rng, 0, 3)];
        }
        break;
    }
    case 1: { /* four of the twelve lattice points of radius 5 k: cocircular */
        static const int8_t circle[12][2] = {{5, 0},  {0, 5},  {-5, 0}, {0, -5},
                                             {3, 4},  {4, 3},  {-3, 4}, {-4, 3},
                                             {3, -4}, {4, -3}, {-3, -4}, {-4, -3}};
        int64_t k = unit / 3 + 1;
        int32_t cx = (int32_t)(origin_for(rng, 10 * k) + 5 * k);
        int32_t cy = (int32_t)(origin_for(rng, 10 * k) + 5 * k);
        unsigned used = 0;
        for (unsigned n = 0; n < 4;) {
            unsigned c = (unsigned)test_rng_range(rng, 0, 11);
            if ((used >> c) & 1u) {
                continue;
            }
            used |= 1u << c;
            q[n].x = (int32_t)(cx + k * circle[c][0]);
            q[n].y = (int32_t)(cy + k * circle[c][1]);
            n++;
        }
        break;
    }
    case 2: { /* collinear, duplicates allowed; sometimes along an axis */
        int64_t dx = test_rng_range(rng, 0, (int32_t)unit);
        int64_t dy = test_rng_range(rng, 0, (int32_t)unit);
        unsigned axis = test_rng_u32(rng) % 4u;
        dx = (axis == 1u) ? 0 : dx;
        dy = (axis == 2u) ? 0 : dy;
        int32_t ox = origin_for(rng, 4 * dx), oy = origin_for(rng, 4 * dy);
        for (unsigned k = 0; k < 4; k++) {
            int64_t a = test_rng_range(rng, 0, 4);
            q[k].x = (int32_t)(ox + a * dx);
            q[k].y = (int32_t)(oy + a * dy);
        }
        break;
    }
    default: { /* random, in a box of span below 2^bits */
        int32_t ox = origin_for(rng, limit - 1), oy = origin_for(rng, limit - 1);
        for (unsigned k = 0; k < 4; k++) {
            q[k].x = (int32_t)(ox + (int64_t)(test_rng_u32(rng) & (uint32_t)(limit - 1)));
            q[k].y = (int32_t)(oy + (int64_t)(test_rng_u32(rng) & (uint32_t)(limit - 1)));
        }
        break;
    }
    }
}

/* The four points q under the p-th (p < 24) assignment of the indices
 * 0..3: ids[k] is point k's index, and sites[ids[k]] = q[k]. */
static void index_order(unsigned p, const vor_point_t q[4], uint32_t ids[4],
                        vor_point_t sites[4])
{
    for (unsigned k = 0, left = p, used = 0; k < 4; k++) {
        unsigned pick = left % (4u - k); /* the pick-th unused index */
        left /= 4u - k;
        uint32_t id = 0;
        while (((used >> id) & 1u) != 0u || pick-- != 0u) {
            id++;
        }
        used |= 1u << id;
        ids[k] = id;
        sites[id] = q[k];
    }
}

/* vor_orient2d_sos and vor_incircle_sos against ref_perturbed on
 * degenerate and random quads with differences up to 32 bits, under
 * every assignment of the indices 0..3 to the points. */
static void check_perturbation_reference(void)
{
    static const unsigned sizes[] = {8, 14, 15, 20, 30, 31, 32};
    test_rng_t rng;
    test_rng_seed(&rng, 16);
    unsigned long checked = 0, bad = 0, later_terms = 0, perturbed = 0;
    for (unsigned n = 0; n < 420; n++) {
        vor_point_t q[4];
        unsigned bits = sizes[n % 7u];
        degenerate_quad(&rng, (n / 7u) % 6u, bits, q);
        /* every assignment of indices to points (ids[k] holds point k) */
        for (unsigned p = 0; p < 24; p++) {
            uint32_t ids[4];
            vor_point_t sites[4];
            index_order(p, q, ids, sites);
            unsigned first;
            int want = ref_perturbed(sites, ids, 4, &first);
            int got = vor_incircle_sos(sites, ids[0], ids[1], ids[2], ids[3]);
            bad += (got != want || want == 0) ? 1u : 0u;
            perturbed += (first != 0u) ? 1u : 0u;
            later_terms += (first > 1u && bits <= 30u) ? 1u : 0u;
            if (got != want && bad < 5) {
                test_printf("incircle (%d,%d) (%d,%d) (%d,%d) (%d,%d) ids %u %u %u %u: "
                            "%d, expected %d (term %u)\n",
                            (int)q[0].x, (int)q[0].y, (int)q[1].x, (int)q[1].y, (int)q[2].x,
                            (int)q[2].y, (int)q[3].x, (int)q[3].y, (unsigned)ids[0],
                            (unsigned)ids[1], (unsigned)ids[2], (unsigned)ids[3], got, want,
                            first);
            }
            if (ids[3] == 3u) { /* the first three points, all 6 orders */
                want = ref_perturbed(sites, ids, 3, &first);
                got = vor_orient2d_sos(sites, ids[0], ids[1], ids[2]);
                bad += (got != want || want == 0) ? 1u : 0u;
                checked++;
            }
            checked++;
        }
    }
    test_printf("perturbation reference: %lu signs, %lu perturbed incircle, %lu decided "
                "after the first term (differences < 2^31)\n",
                checked, perturbed, later_terms);
    CHECK(bad == 0, "perturbed signs: %lu of %lu differ from the reference", bad, checked);
    /* the mid tier's first term and its later terms both ran */
    CHECK(perturbed > 2000u && later_terms > 100u,
          "perturbed incircle %lu, decided by later terms %lu", perturbed, later_terms);
}

/* vor_incircle_sos against ref_perturbed where the first perturbation
 * term is tiny beside its size, so that no filter or closed form may
 * decide it without proof (the 32-bit-limb filter of the first term,
 * predicates.c first_terms). With p = m + 1, the Gaussian integers
 * (m + i)(p - i) = (mp + 1) + i and (m + i)(p + i) = (mp - 1) + (2m + 1) i
 * have the same norm, so the 16 points (+-a, +-1), (+-1, +-a), (+-c, +-d),
 * (+-d, +-c), a = mp + 1, c = mp - 1, d = 2m + 1, lie on one circle. The first
 * term is 2 (xP yQ - yP xQ) (yL - y_center) relative to the top site, so
 * with L at (+-a, +-1) it is about 2 R^2 against terms of size R^3:
 * R up to 2^29, where the filter sees only about 2^11 of it. */
static void check_first_term_filter(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 73);
    unsigned long checked = 0, bad = 0;
    for (unsigned n = 0; n < 160; n++) {
        int64_t m = test_rng_range(&rng, 2, (n % 2u == 0u) ? 200 : 23000);
        int64_t a = m * (m + 1) + 1, c = m * (m + 1) - 1, d = 2 * m + 1;
        /* |coordinates| <= a < 2^29.1 around a center leaving room */
        int32_t cx = test_rng_range(&rng, -(1 << 30), 1 << 30);
        int32_t cy = test_rng_range(&rng, -(1 << 30), 1 << 30);
        const int64_t base[4][2] = {{a, 1}, {1, a}, {c, d}, {d, c}};
        vor_point_t q[4];
        unsigned used = 0;
        for (unsigned k = 0; k < 4;) {
            /* the first point on (+-a, +-1), where yL - y_center = +-1 */
            unsigned pick = (unsigned)test_rng_range(&rng, 0, (k == 0u) ? 3 : 15);
            if ((used >> pick) & 1u) {
                continue;
            }
            used |= 1u << pick;
            const int64_t *b = base[pick / 4u];
            q[k].x = (int32_t)(cx + ((pick & 1u) ? -b[0] : b[0]));
            q[k].y = (int32_t)(cy + ((pick & 2u) ? -b[1] : b[1]));
            k++;
        }
        for (unsigned p = 0; p < 24; p++) { /* every index order */
            uint32_t ids[4];
            vor_point_t sites[4];
            index_order(p, q, ids, sites);
            unsigned first;
            int want = ref_perturbed(sites, ids, 4, &first);
            int got = vor_incircle_sos(sites, ids[0], ids[1], ids[2], ids[3]);
            bad += (got != want || want == 0 || first == 0u) ? 1u : 0u;
            checked++;
        }
    }
    test_printf("first-term filter: %lu perturbed signs near a circle's extreme\n", checked);
    CHECK(bad == 0, "first-term filter: %lu of %lu signs differ from the reference", bad,
          checked);
}

/* vor_incircle_sos against ref_perturbed where the first perturbation
 * term is +-1, the least it can be without being 0, so that no width of
 * closed form may round it away or read 1 as a tie. P = (n, 1) and
 * Q = (n + 1, 1) span a triangle of area 1/2 with the top site O at 0, so
 * xP yQ - yP xQ = -1; their circle x^2 + y^2 = (2n + 1) x + (1 - 2T) y,
 * T = n (n + 1) / 2, holds L = (n + T + 1, -T) too, whose height is 1/2
 * below the centre's: the term 2 (xP yQ - yP xQ) (yL - y_center) is 1.
 * n up to 30,000 puts the entries (T up to 2^28.7) on every tier; the
 * eight symmetries of the lattice and every index order move the term to
 * every site and sign. */
static void check_unit_first_term(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 29);
    unsigned long checked = 0, bad = 0, first_decided = 0;
    for (unsigned n = 0; n < 96; n++) {
        int64_t m = test_rng_range(&rng, 1, (n % 2u == 0u) ? 200 : 30000);
        int64_t t = m * (m + 1) / 2;
        const int64_t base[4][2] = {{0, 0}, {m, 1}, {m + 1, 1}, {m + t + 1, -t}};
        int32_t ox = test_rng_range(&rng, -(1 << 30), 1 << 30);
        int32_t oy = test_rng_range(&rng, -(1 << 30), 1 << 30);
        unsigned symmetry = n % 8u;
        vor_point_t q[4];
        for (unsigned k = 0; k < 4; k++) {
            int64_t x = (symmetry & 1u) ? -base[k][0] : base[k][0];
            int64_t y = (symmetry & 2u) ? -base[k][1] : base[k][1];
            q[k].x = (int32_t)(ox + ((symmetry & 4u) ? y : x));
            q[k].y = (int32_t)(oy + ((symmetry & 4u) ? x : y));
        }
        for (unsigned p = 0; p < 24; p++) {
            uint32_t ids[4];
            vor_point_t sites[4];
            index_order(p, q, ids, sites);
            unsigned first;
            int want = ref_perturbed(sites, ids, 4, &first);
            int got = vor_incircle_sos(sites, ids[0], ids[1], ids[2], ids[3]);
            bad += (got != want || want == 0 || first == 0u) ? 1u : 0u;
            first_decided += (first == 1u) ? 1u : 0u;
            checked++;
        }
    }
    test_printf("unit first term: %lu perturbed signs, %lu decided by the first term\n", checked,
                first_decided);
    CHECK(bad == 0, "unit first term: %lu of %lu signs differ from the reference", bad, checked);
    CHECK(first_decided > checked / 8u, "unit first term: only %lu of %lu by the first term",
          first_decided, checked);
}

/* The predicates on crossing vertices (src/crossing.c) against the
 * generated table (tools/gen_crossing_vectors.py: exact rationals): the
 * exact sign, and the perturbed one under the table's index ranks. */
static void check_crossing_vectors(void)
{
    unsigned long bad = 0;
    unsigned long zeros = 0;
    for (size_t n = 0; n < crossing_vector_count; n++) {
        const struct crossing_vector *cv = &crossing_vectors[n];
        unsigned count = (cv->op == 0u) ? 3u : 4u;
        vor__hpoint_t h[4];
        const vor__hpoint_t *v[4];
        uint32_t ids[4];
        bool made = true;
        for (unsigned k = 0; k < count; k++) {
            const int32_t *c = cv->xy[k];
            vor_point_t a = {c[0], c[1]};
            if ((cv->crossing >> k) & 1u) {
                vor_point_t b = {c[2], c[3]};
                vor_point_t p = {c[4], c[5]};
                vor_point_t q = {c[6], c[7]};
                made = made && vor__hpoint_crossing(&h[k], a, b, p, q);
            } else {
                vor__hpoint_site(&h[k], a);
            }
            v[k] = &h[k];
            ids[k] = 10u + ((cv->ranks >> (2u * k)) & 3u); /* any ids of these ranks */
        }
        int exact = (count == 3u) ? vor__orient_h(v[0], v[1], v[2])
                                  : vor__incircle_h(v[0], v[1], v[2], v[3]);
        int perturbed = (count == 3u) ? vor__orient_h_sos(v, ids) : vor__incircle_h_sos(v, ids);
        bool ok = made && (exact == cv->exact) && (perturbed == cv->perturbed);
        bad += ok ? 0u : 1u;
        zeros += (cv->exact == 0) ? 1u : 0u;
        if (!ok && bad <= 5u) {
            test_printf("crossing vector %u (op %u): exact %d (want %d), perturbed %d (want %d)\n",
                        (unsigned)n, (unsigned)cv->op, exact, cv->exact, perturbed, cv->perturbed);
        }
    }
    /* parallel lines have no crossing */
    vor__hpoint_t h;
    vor_point_t a = {0, 0}, b = {4, 2}, c = {1, 5}, e = {9, 9};
    bad += vor__hpoint_crossing(&h, a, b, c, e) ? 1u : 0u;
    test_printf("crossing vectors: %u, %lu exact zeros\n", (unsigned)crossing_vector_count, zeros);
    CHECK(bad == 0, "crossing vectors: %lu of %u wrong", bad, (unsigned)crossing_vector_count);
}

/* The exact sign of incircle(q[0], q[1], q[2], q[3]) by the reference. */
static int ref_incircle(const vor_point_t q[4])
{
    int64_t rows[4][4];
    uint64_t lifts[4];
    for (unsigned r = 0; r < 4; r++) {
        ref_row(rows[r], &lifts[r], 0, q[r].x, q[r].y, 0);
    }
    return ref_det_sign(rows, lifts, 4);
}

/* vor_incircle against the reference for points crossing a circle: from
 * inside a random triangle's circumcircle, a point steps along a small
 * vector until it leaves; around the crossing found by bisection, and at
 * distances 2^j from it, the determinant runs from 0 or +-1 up to its
 * full size, so any tier or filter that decides a sign it cannot prove
 * (the 32-bit-limb mid tier's filter) shows here. Triangles of spans
 * 2^15 .. 2^30. */
static void check_near_circles(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 61);
    unsigned long checked = 0, bad = 0, crossings = 0, inside = 0;
    for (unsigned n = 0; n < 160; n++) {
        unsigned bits = 15u + n % 16u;
        int32_t half = (int32_t)1 << (bits - 1u);
        vor_point_t q[4];
        for (unsigned k = 0; k < 3; k++) {
            q[k].x = test_rng_range(&rng, -half, half - 1);
            q[k].y = test_rng_range(&rng, -half, half - 1);
        }
        int64_t gx = ((int64_t)q[0].x + q[1].x + q[2].x) / 3;
        int64_t gy = ((int64_t)q[0].y + q[1].y + q[2].y) / 3;
        int32_t ux = test_rng_range(&rng, -7, 7), uy = test_rng_range(&rng, 1, 7);
        /* steps keep the point within 2^30 of 0: differences below 2^31 */
        int64_t most = ((int64_t)1 << 30) / 8 - half;
        q[3].x = (int32_t)gx;
        q[3].y = (int32_t)gy;
        int start = ref_incircle(q);
        int64_t lo = 0, hi = 1;
        for (;; hi *= 2) { /* the first power of two outside */
            if (hi > most) {
                hi = 0;
                break;
            }
            q[3].x = (int32_t)(gx + hi * ux);
            q[3].y = (int32_t)(gy + hi * uy);
            if (ref_incircle(q) != start) {
                break;
            }
            lo = hi;
        }
        if (hi == 0 || start == 0) {
            continue; /* the circle reaches past the box, or a degenerate triangle */
        }
        while (hi - lo > 1) { /* f(lo) = start, f(hi) != start */
            int64_t mid = lo + (hi - lo) / 2;
            q[3].x = (int32_t)(gx + mid * ux);
            q[3].y = (int32_t)(gy + mid * uy);
            if (ref_incircle(q) == start) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        crossings++;
        for (int j = -40; j <= 40; j++) { /* offsets 0, +-1 .. +-4, +-8, +-16, .. */
            unsigned a = (unsigned)(j < 0 ? -j : j);
            int64_t step = (a <= 4u) ? (int64_t)a : (int64_t)1 << (a - 2u);
            int64_t t = hi + ((j < 0) ? -step : step);
            if (t < 0 || t > most) {
                continue;
            }
            q[3].x = (int32_t)(gx + t * ux);
            q[3].y = (int32_t)(gy + t * uy);
            int want = ref_incircle(q), got = vor_incircle(q[0], q[1], q[2], q[3]);
            if (got != want && bad++ < 5) {
                test_printf("incircle (%d,%d) (%d,%d) (%d,%d) (%d,%d): %d, expected %d\n",
                            (int)q[0].x, (int)q[0].y, (int)q[1].x, (int)q[1].y, (int)q[2].x,
                            (int)q[2].y, (int)q[3].x, (int)q[3].y, got, want);
            }
            inside += (want == start) ? 1u : 0u;
            checked++;
        }
    }
    test_printf("near circles: %lu crossings, %lu signs, %lu on the starting side\n", crossings,
                checked, inside);
    CHECK(crossings >= 100u && bad == 0, "near circles: %lu of %lu signs wrong, %lu crossings",
          bad, checked, crossings);
}

/* The documented tiers at their edges (vor.h): orient2d and closer run
 * narrow while every coordinate difference lies in [-2^31, 2^31 - 1],
 * incircle narrow in [-2^14, 2^14 - 1] and mid in [-2^31, 2^31 - 1]; one
 * step outside, the next tier. The points are placed by their differences
 * E (the largest, one on each side of an edge) and 0 or +-1 (which add no
 * bit the bound does not have, so the bound is exactly the edge): a - c =
 * (E, 0), b - c = (0, E) turn counterclockwise (determinant E^2); c is
 * closer to itself than to a; and d inside the circle through d + (E, 0),
 * d + (0, E), d - (s, s) (s the sign of E), which turn counterclockwise. */
static void check_tier_edges(void)
{
    static const int64_t edges[] = {16383, 16384, -16384, -16385,
                                    2147483647, 2147483648, -2147483648, -2147483649};
    for (unsigned k = 0; k < sizeof edges / sizeof edges[0]; k++) {
        int64_t e = edges[k];
        int32_t s = (e > 0) ? 1 : -1;
        /* a base point from which base + e and base - s fit int32 */
        int32_t base = (int32_t)((e > 0) ? INT32_MAX - e : INT32_MIN - e);
        vor_point_t c = {base, base};
        vor_point_t a = {(int32_t)(base + e), base};
        vor_point_t b = {base, (int32_t)(base + e)};
        vor_point_t third = {base - s, base - s};
        uint64_t magnitude = (uint64_t)(e < 0 ? -(e + 1) : e); /* of [-2^k, 2^k - 1] */
        unsigned narrow32 = magnitude < 0x80000000u, narrow14 = magnitude < 16384u;
        vor_stats_t stats = {0};
        CHECK(vor__orient2d_exact(&a, &b, &c, &stats) == 1 &&
                  stats.orient2d[VOR_TIER_NARROW] == narrow32 &&
                  stats.orient2d[VOR_TIER_WIDE] == 1u - narrow32,
              "orient2d, difference %d%09d: narrow %u, wide %u", (int)(e / 1000000000),
              (int)((e < 0 ? -e : e) % 1000000000), stats.orient2d[VOR_TIER_NARROW],
              stats.orient2d[VOR_TIER_WIDE]);
        CHECK(vor__closer_sign(&c, &a, &c, &stats) == 1 &&
                  stats.closer[VOR_TIER_NARROW] == narrow32 &&
                  stats.closer[VOR_TIER_WIDE] == 1u - narrow32,
              "closer, difference %d%09d: narrow %u, wide %u", (int)(e / 1000000000),
              (int)((e < 0 ? -e : e) % 1000000000), stats.closer[VOR_TIER_NARROW],
              stats.closer[VOR_TIER_WIDE]);
        CHECK(vor__incircle_exact(&a, &b, &third, &c, &stats) == 1 &&
                  stats.incircle[VOR_TIER_NARROW] == narrow14 &&
                  stats.incircle[VOR_TIER_MID] == narrow32 - narrow14 &&
                  stats.incircle[VOR_TIER_WIDE] == 1u - narrow32,
              "incircle, difference %d%09d: narrow %u, mid %u, wide %u", (int)(e / 1000000000),
              (int)((e < 0 ? -e : e) % 1000000000), stats.incircle[VOR_TIER_NARROW],
              stats.incircle[VOR_TIER_MID], stats.incircle[VOR_TIER_WIDE]);
        CHECK(vor_orient2d(a, b, c) == 1 && vor_closer(c, a, c) == 1 &&
                  vor_incircle(a, b, third, c) == 1,
              "public predicates, difference index %u", k);
    }
}

/* r = the incircle determinant of the differences d (a - d, b - d, c - d
 * as x, y pairs): the sum of lift(k) cross(k + 1, k + 2). */
static void exact_incircle(wide_t *r, const int64_t d[6])
{
    wide_t x, y, lift, cross, t;
    wide_set(r, 0);
    for (unsigned k = 0; k < 3u; k++) {
        unsigned u = (k + 1u) % 3u, v = (k + 2u) % 3u;
        wide_set(&x, d[2u * k]);
        wide_set(&y, d[(2u * k) + 1u]);
        wide_mul(&lift, &x, &x);
        wide_mul(&y, &y, &y);
        wide_add(&lift, &y);
        wide_set(&cross, d[2u * u]);
        wide_mul_i64(&cross, &cross, d[(2u * v) + 1u]);
        wide_set(&t, d[(2u * u) + 1u]);
        wide_mul_i64(&t, &t, d[2u * v]);
        wide_sub(&cross, &t);
        wide_mul(&lift, &lift, &cross);
        wide_add(r, &lift);
    }
}

/* r = |r| */
static void wide_abs(wide_t *r)
{
    if (wide_negative(r)) {
        wide_neg(r);
    }
}

/* The mid incircle filter's second error bound against the error it
 * bounds (vor__incircle_point_bound, src/predicates.h), exactly: for
 * differences d = 2^17 u + r, |u| <= 2^14 (the filter's widest shift),
 * |P(d) - 2^68 P(u)| must not exceed 2^68 times the bound of u, for r at
 * each of the 64 corners of [0, 2^17 - 1]^6, where the first-order error
 * is largest. The u: random at five scales (each point at its own), and
 * four where a hill climb on the error over the bound ended; there the
 * error exceeds a bound without its 6abc term, one with a / b or 6 / c
 * for a b or 6 c, and one of sizes without their + 1 (three times it at
 * the first, one point on each diagonal beside the fourth), though it
 * stays below the code's bound (0.12 to 0.71 of it). */
static void check_point_bound(void)
{
    static const int32_t climbed[4][6] = {{-1, 1, 1, -1, 0, 0},
                                          {-2172, -2204, -9523, 9479, 8586, -8592},
                                          {2000, 2002, -13113, 13022, 9495, -9461},
                                          {10891, -10895, 2082, 2089, -9586, 9544}};
    static const int32_t scales[5] = {1, 30, 1000, 1 << 12, 1 << 14};
    test_rng_t rng;
    test_rng_seed(&rng, 4417);
    const int64_t shift = (int64_t)1 << 34; /* 2^68 = shift^2 */
    const int64_t r_max = ((int64_t)1 << 17) - 1;
    unsigned long checked = 0, bad = 0;
    for (unsigned n = 0; n < 64u; n++) {
        int32_t u[6];
        for (unsigned k = 0; k < 6u; k++) {
            int32_t s = scales[test_rng_u32(&rng) % 5u];
            u[k] = (n < 4u) ? climbed[n][k] : test_rng_range(&rng, -s, s - 1);
        }
        wide_t scaled, bound, error;
        wide_set(&scaled, vor__incircle_narrow(u));
        wide_mul_i64(&scaled, &scaled, shift);
        wide_mul_i64(&scaled, &scaled, shift);
        wide_set(&bound, (int64_t)vor__incircle_point_bound(u));
        wide_mul_i64(&bound, &bound, shift);
        wide_mul_i64(&bound, &bound, shift);
        for (unsigned corner = 0; corner < 64u; corner++) {
            int64_t d[6];
            for (unsigned k = 0; k < 6u; k++) {
                d[k] = ((int64_t)u[k] * (r_max + 1)) + (((corner >> k) & 1u) ? r_max : 0);
            }
            exact_incircle(&error, d);
            wide_sub(&error, &scaled);
            wide_abs(&error);
            bool over = wide_compare(&bound, &error) < 0;
            bad += over ? 1u : 0u;
            CHECK(!over || bad > 3u, "point bound: u %d %d %d %d %d %d, corner %u: error above it",
                  u[0], u[1], u[2], u[3], u[4], u[5], corner);
            checked++;
        }
    }
    test_printf("point bound: %lu rounding errors within it\n", checked);
    CHECK(bad == 0u, "point bound: %lu of %lu errors above it", bad, checked);
}

/* Bit length of |a|: the least k with |a| < 2^k. */
static unsigned bit_length(const wide_t *a)
{
    wide_t m = *a;
    wide_abs(&m);
    for (unsigned i = WIDE_LIMBS; i-- > 0;) {
        if (m.v[i] != 0u) {
            unsigned k = 0;
            while ((k < 32u) && ((m.v[i] >> k) != 0u)) {
                k++;
            }
            return (32u * i) + k;
        }
    }
    return 0;
}

static int32_t magnitude_coordinate(test_rng_t *rng, unsigned scale)
{
    switch (scale) {
    case 0: return test_rng_range(rng, -5000, 5000);
    case 1: return test_rng_range(rng, -(1 << 22), 1 << 22);
    case 2: return test_rng_range(rng, -(1 << 30), (1 << 30) - 1);
    case 3: return (int32_t)test_rng_u32(rng);
    default: /* near the range's ends: lifts and cross products near 2^65 */
        return (test_rng_u32(rng) & 1u) ? INT32_MAX - test_rng_range(rng, 0, 1000)
                                         : INT32_MIN + test_rng_range(rng, 0, 1000);
    }
}

/* vor__orient2d_bits and vor__incircle_bits (the motion cache's bounds):
 * the bit length of the exact determinant, against the test's own big
 * integers, for coordinates at each tier's scale, anywhere in int32
 * (differences of 33 bits) and near its ends (determinants near 2^127),
 * with a shared point now and then so that small and zero determinants
 * occur, and two quads whose differences lie just past a tier's edge. The first five wrong cases are printed (as failed checks), then
 * the count. */
static void check_magnitudes(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 2024);
    unsigned bad = 0;
    for (unsigned n = 0; n < 5000u; n++) {
        unsigned scale = n % 5u;
        vor_point_t p[4];
        for (unsigned k = 0; k < 4u; k++) {
            /* every other round, each coordinate at its own scale: one
             * large difference among small ones picks the tier */
            bool mixed = n % 10u >= 5u;
            p[k].x = magnitude_coordinate(&rng, mixed ? test_rng_u32(&rng) % 5u : scale);
            p[k].y = magnitude_coordinate(&rng, mixed ? test_rng_u32(&rng) % 5u : scale);
        }
        if (n % 7u == 0u && n % 10u < 3u) { /* p[2] near the line of p[0], p[1] */
            p[2].x = (int32_t)(p[0].x + ((int64_t)p[0].x - p[1].x) / 2);
            p[2].y = (int32_t)(p[0].y + ((int64_t)p[0].y - p[1].y) / 2);
        }
        if (n % 11u == 0u) {
            p[1] = p[0];
        }
        if (n < 2u) { /* at the tiers' edges (after the draws: the stream stays) */
            static const vor_point_t edge[2][4] = {
                /* p0 - p3 = (2^31, 0), p1 - p3 = (-1, -2^31 - 1), p2 - p3
                 * = (-1, 0): the OR of their bounds is 2^31, one past
                 * int32 */
                {{INT32_MAX, INT32_MAX}, {-2, -2}, {-2, INT32_MAX}, {-1, INT32_MAX}},
                /* differences of 15 bits, past the narrow tier's 14:
                 * p1 - p3 = (-2^15, -2^15) has the lift 2^31 */
                {{32767, -32768}, {-32768, -32768}, {-32768, 1046}, {0, 0}}};
            for (unsigned k = 0; k < 4u; k++) {
                p[k] = edge[n][k];
            }
        }
        int64_t d[6];
        for (unsigned k = 0; k < 3u; k++) {
            d[2u * k] = (int64_t)p[k].x - p[3].x;
            d[(2u * k) + 1u] = (int64_t)p[k].y - p[3].y;
        }
        /* orient2d of p0, p1, p3: (p0 - p3) x (p1 - p3) */
        wide_t orient, t, incircle;
        wide_set(&orient, d[0]);
        wide_mul_i64(&orient, &orient, d[3]);
        wide_set(&t, d[1]);
        wide_mul_i64(&t, &t, d[2]);
        wide_sub(&orient, &t);
        exact_incircle(&incircle, d);
        unsigned got_orient = vor__orient2d_bits(&p[0], &p[1], &p[3]);
        unsigned got_incircle = vor__incircle_bits(&p[0], &p[1], &p[2], &p[3]);
        if (got_orient != bit_length(&orient) || got_incircle != bit_length(&incircle)) {
            bad++;
            CHECK(bad > 5u, "case %u: orient2d %u bits (want %u), incircle %u bits (want %u)", n,
                  got_orient, bit_length(&orient), got_incircle, bit_length(&incircle));
        }
    }
    CHECK(bad == 0u, "%u of 5000 magnitudes wrong", bad);
}

/* vor_closer_sos against the perturbation's definition (vor.h): site i
 * moves by (eps^(4 16^i), eps^(16^i)), and the answer is the sign of
 * |q~ - a~|^2 - |q~ - b~|^2 as eps -> 0+, that of the nonzero coefficient
 * of the lowest power of eps. The polynomial is expanded here term by term
 * (exponents up to 2 4 16^3 for ids 0..3); coordinates on a 5 x 5 grid,
 * so that most exact answers are ties. */
typedef struct {
    uint32_t exponent;
    int64_t coefficient;
} eps_term_t;

static int closer_sos_reference(const vor_point_t s[4], uint32_t q, uint32_t a, uint32_t b)
{
    eps_term_t t[32];
    unsigned n = 0;
    const uint32_t id[3] = {q, a, b};
    for (unsigned axis = 0; axis < 2u; axis++) {
        uint32_t e[3]; /* the exponent of each point's move along this axis */
        int64_t c[3];  /* q, a, b's coordinates along it */
        for (unsigned k = 0; k < 3u; k++) {
            e[k] = (axis == 0u ? 4u : 1u) << (4u * id[k]);
            c[k] = (axis == 0u) ? s[id[k]].x : s[id[k]].y;
        }
        int64_t da = c[0] - c[1], db = c[0] - c[2];
        /* (da + m_q - m_a)^2 - (db + m_q - m_b)^2 */
        t[n++] = (eps_term_t){0, da * da - db * db};
        t[n++] = (eps_term_t){e[0], 2 * da - 2 * db};
        t[n++] = (eps_term_t){e[1], -2 * da};
        t[n++] = (eps_term_t){e[2], 2 * db};
        t[n++] = (eps_term_t){e[0] + e[1], -2};
        t[n++] = (eps_term_t){e[1] + e[1], 1};
        t[n++] = (eps_term_t){e[0] + e[2], 2};
        t[n++] = (eps_term_t){e[2] + e[2], -1};
    }
    uint32_t best = UINT32_MAX;
    int64_t sum = 0;
    for (unsigned i = 0; i < n; i++) {
        int64_t c = 0;
        for (unsigned j = 0; j < n; j++) {
            c += (t[j].exponent == t[i].exponent) ? t[j].coefficient : 0;
        }
        if (c != 0 && t[i].exponent < best) {
            best = t[i].exponent;
            sum = c;
        }
    }
    return (sum > 0) - (sum < 0);
}

static void check_closer_sos_reference(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 4242);
    unsigned bad = 0, ties = 0;
    for (unsigned n = 0; n < 20000u; n++) {
        vor_point_t s[4];
        for (unsigned k = 0; k < 4u; k++) {
            s[k].x = test_rng_range(&rng, -2, 2);
            s[k].y = test_rng_range(&rng, -2, 2);
        }
        uint32_t q = test_rng_u32(&rng) % 4u, a = (q + 1u + test_rng_u32(&rng) % 3u) % 4u;
        uint32_t b = a;
        while (b == a || b == q) {
            b = test_rng_u32(&rng) % 4u;
        }
        int want = closer_sos_reference(s, q, a, b), got = vor_closer_sos(s, q, a, b);
        ties += vor_closer(s[q], s[a], s[b]) == 0;
        if (got != want) {
            bad++;
            CHECK(bad > 5u, "closer_sos(q %u (%d, %d), a %u (%d, %d), b %u (%d, %d)) = %d, want %d",
                  q, s[q].x, s[q].y, a, s[a].x, s[a].y, b, s[b].x, s[b].y, got, want);
        }
    }
    CHECK(bad == 0u && ties > 2000u, "%u of 20000 wrong, %u ties", bad, ties);
}

/* The magnitudes the motion cache sizes its boxes with
 * (vor__orient2d_bits, vor__incircle_bits) when differences take 33 bits:
 * sites at the ends of the int32 range, D = 2^32 - 1 apart, whose
 * determinants have closed forms. Orientation of (D, 0), (0, D) from the
 * corner: D^2 (64 bits), negated when the two swap; along the diagonal,
 * 0; (D, 1), (D - 1, 1): D - (D - 1) = 1. Incircle, offsets from the
 * corner (D, 0), (0, D) and then (1, 1): -2 D^2 (D - 1), 97 bits; (D, D):
 * the corners of a square, 0; (D, 1): -D^2 (D - 1), 96 bits. The signs
 * of the exact predicates agree (zero exactly when the magnitude is). */
static void check_wide_magnitudes(void)
{
    const vor_point_t lo = {INT32_MIN, INT32_MIN}, right = {INT32_MAX, INT32_MIN},
                      up = {INT32_MIN, INT32_MAX}, far = {INT32_MAX, INT32_MAX},
                      centre = {0, 0}, next = {INT32_MIN + 1, INT32_MIN + 1},
                      right1 = {INT32_MAX, INT32_MIN + 1}, left1 = {INT32_MAX - 1, INT32_MIN + 1};
    CHECK(vor__orient2d_bits(&right, &up, &lo) == 64u && vor__orient2d_bits(&up, &right, &lo) == 64u &&
              vor_orient2d(right, up, lo) == 1 && vor_orient2d(up, right, lo) == -1,
          "orient2d magnitude, differences of 2^32 - 1: %u, %u", vor__orient2d_bits(&right, &up, &lo),
          vor__orient2d_bits(&up, &right, &lo));
    CHECK(vor__orient2d_bits(&far, &centre, &lo) == 0u && vor_orient2d(far, centre, lo) == 0,
          "orient2d magnitude, collinear across the range: %u", vor__orient2d_bits(&far, &centre, &lo));
    CHECK(vor__orient2d_bits(&right1, &left1, &lo) == 1u && vor_orient2d(right1, left1, lo) == 1,
          "orient2d magnitude 1 from 33-bit differences: %u", vor__orient2d_bits(&right1, &left1, &lo));
    CHECK(vor__incircle_bits(&right, &up, &next, &lo) == 97u && vor_incircle(right, up, next, lo) != 0,
          "incircle magnitude -2 D^2 (D - 1): %u", vor__incircle_bits(&right, &up, &next, &lo));
    CHECK(vor__incircle_bits(&right, &up, &far, &lo) == 0u && vor_incircle(right, up, far, lo) == 0,
          "incircle magnitude, a square's corners: %u", vor__incircle_bits(&right, &up, &far, &lo));
    CHECK(vor__incircle_bits(&right, &up, &right1, &lo) == 96u &&
              vor_incircle(right, up, right1, lo) != 0,
          "incircle magnitude -D^2 (D - 1): %u", vor__incircle_bits(&right, &up, &right1, &lo));
}

/* vor_closer_sos when a and b coincide and q has the smallest index, from
 * the perturbation's definition (docs/design/predicates.md): with A = a~
 * and B = b~ at one point, |q~ - A|^2 - |q~ - B|^2 =
 * (dx_B - dx_A)(2 X + ...) + (dy_B - dy_A)(2 Y + 2 dy_q - dy_A - dy_B),
 * X, Y = q - a. Its lowest term belongs to the smaller of a and b, m:
 * -+2 Y eps^(16^m) (minus when m = a), so the sign is that of a_y - q_y
 * (m = a) or q_y - b_y (m = b); when Y = 0, -+2 dy_q dy_m, eps^(16^q +
 * 16^m), which precedes dy_m^2 as q < m: -1 (m = a) or 1 (m = b). */
static void check_closer_coincident(void)
{
    const vor_point_t above[3] = {{0, 0}, {5, 3}, {5, 3}}, level[3] = {{0, 0}, {-7, 0}, {-7, 0}};
    CHECK(vor_closer_sos(above, 0, 1, 2) == 1 && vor_closer_sos(above, 0, 2, 1) == -1,
          "closer, coincident a and b above q: %d %d", vor_closer_sos(above, 0, 1, 2),
          vor_closer_sos(above, 0, 2, 1));
    CHECK(vor_closer_sos(level, 0, 1, 2) == -1 && vor_closer_sos(level, 0, 2, 1) == 1,
          "closer, coincident a and b level with q: %d %d", vor_closer_sos(level, 0, 1, 2),
          vor_closer_sos(level, 0, 2, 1));
}

/* Two helpers of src/multiword.h the raster code alone calls, so no
 * predicate vector reaches them: vor__mw_i96_mul against the test's own
 * integers over its domain's edges and random values, and
 * vor__mw_to_u128 on limbs whose every word differs. */
static void check_wide_helpers(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 96);
    static const int64_t xs[] = {0, 1, -1, 0xFFFFFFFF, -0xFFFFFFFFll, 0x100000000ll,
                                 INT64_C(0x3FFFFFFFFFFFFFFF), -INT64_C(0x3FFFFFFFFFFFFFFF)};
    static const uint32_t ys[] = {0u, 1u, 0xFFFFu, 0x7FFFFFFFu};
    unsigned bad = 0;
    for (unsigned n = 0; n < 4000u; n++) {
        int64_t x = (n < 32u) ? xs[n % 8u]
                              : (int64_t)(((uint64_t)test_rng_u32(&rng) << 32) | test_rng_u32(&rng)) /
                                    (int64_t)(1u + (n % 4u) * 3u) / 2;
        uint32_t y = (n < 32u) ? ys[n / 8u] : test_rng_u32(&rng) >> 1;
        vor__mw_i96_t r;
        vor__mw_i96_mul(&r, x, y);
        wide_t got, low, want;
        wide_set(&got, r.hi);
        wide_mul_i64(&got, &got, INT64_C(0x100000000));
        wide_set(&low, (int64_t)r.lo);
        wide_add(&got, &low);
        wide_set(&want, x);
        wide_mul_i64(&want, &want, (int64_t)y);
        if (!wide_equal(&got, &want) && bad++ < 5u) {
            CHECK(false, "vor__mw_i96_mul, case %u: x = %lx %08lx, y = %lu", n,
                  (unsigned long)((uint64_t)x >> 32), (unsigned long)((uint64_t)x & 0xFFFFFFFFu),
                  (unsigned long)y);
        }
    }
    CHECK(bad == 0u, "vor__mw_i96_mul wrong %u times", bad);
    const uint64_t lo = UINT64_C(0x0123456789ABCDEF), hi = UINT64_C(0xFEDCBA9876543210);
#if VOR_LIMB_BITS == 64
    const vor__limb limbs[2] = {lo, hi};
#else
    const vor__limb limbs[4] = {(uint32_t)lo, (uint32_t)(lo >> 32), (uint32_t)hi,
                                (uint32_t)(hi >> 32)};
#endif
    vor__mw_u128_t w;
    vor__mw_to_u128(&w, limbs);
    CHECK(w.lo == lo && w.hi == hi, "vor__mw_to_u128: high word %lx %08lx",
          (unsigned long)(w.hi >> 32), (unsigned long)(w.hi & 0xFFFFFFFFu));
}

/* r = the unsigned number of n library limbs (n * VOR_LIMB_BITS <= 256). */
#define LIMB_WORDS (VOR_LIMB_BITS / 32)
static void wide_of_limbs(wide_t *r, const vor__limb *a, size_t n)
{
    wide_set(r, 0);
    for (size_t i = 0; i < n; i++) {
        for (unsigned k = 0; k < LIMB_WORDS; k++) {
            r->v[(i * LIMB_WORDS) + k] = (uint32_t)(a[i] >> (32u * k));
        }
    }
}

/* Do a and b agree on their low `words` 32-bit words? */
static bool low_words_equal(const wide_t *a, const wide_t *b, size_t words)
{
    bool same = true;
    for (size_t i = 0; i < words; i++) {
        same = same && (a->v[i] == b->v[i]);
    }
    return same;
}

/* The multi-word helpers at the edges of their limbs, against the test's
 * integers: the sign fill of vor__mw_from_i64, the sign of a top limb
 * with only its second bit set, a halving and a multiplication by 4 of
 * values with every limb's top bits set; a guard limb after the n limbs
 * must stay untouched. */
static void check_limb_edges(void)
{
    enum { N = 256 / VOR_LIMB_BITS };
    const vor__limb guard = (vor__limb)0x5A5A5A5Au;
    test_rng_t rng;
    test_rng_seed(&rng, 4);
    vor__limb r[N + 1];
    vor__limb a[N + 1];
    static const int64_t values[] = {0, 1, -1, INT64_MIN, INT64_MAX, -0x123456789ll};
    for (unsigned k = 0; k < 6u; k++) {
        r[N] = guard;
        vor__mw_from_i64(r, N, values[k]);
        wide_t got, want;
        wide_of_limbs(&got, r, N);
        wide_set(&want, values[k]);
        CHECK(r[N] == guard && wide_equal(&got, &want), "vor__mw_from_i64, value %u", k);
    }
    /* the top limb's second bit alone: positive; its top bit: negative */
    for (size_t i = 0; i < N; i++) {
        a[i] = 0u;
    }
    a[N - 1u] = (vor__limb)1u << (VOR_LIMB_BITS - 2);
    CHECK(vor__mw_sign(a, N) == 1, "vor__mw_sign, bit L - 2 of the top limb");
    a[N - 1u] = (vor__limb)1u << (VOR_LIMB_BITS - 1);
    CHECK(vor__mw_sign(a, N) == -1, "vor__mw_sign, the top bit");
    for (unsigned n = 0; n < 200u; n++) {
        for (size_t i = 0; i < N; i++) {
            a[i] = (vor__limb)test_rng_u32(&rng);
#if VOR_LIMB_BITS == 64
            a[i] = (a[i] << 32) | test_rng_u32(&rng);
#endif
            a[i] |= (n % 2u == 0u) ? ((vor__limb)7u << (VOR_LIMB_BITS - 3)) : 0u;
        }
        wide_t before, half, got;
        wide_of_limbs(&before, a, N);
        /* a / 2, unsigned */
        a[N] = guard;
        vor__mw_shr1(a, N);
        for (unsigned i = 0; i < WIDE_LIMBS; i++) {
            half.v[i] = (before.v[i] >> 1) |
                        (((i + 1u) < WIDE_LIMBS) ? (before.v[i + 1u] << 31) : 0u);
        }
        wide_of_limbs(&got, a, N);
        CHECK(a[N] == guard && wide_equal(&got, &half), "vor__mw_shr1, value %u", n);
        /* 4 a modulo 2^256 */
        r[N] = guard;
        vor__mw_times4(r, a, N);
        wide_t four;
        wide_of_limbs(&four, a, N);
        wide_mul_i64(&four, &four, 4);
        wide_of_limbs(&got, r, N);
        CHECK(r[N] == guard && wide_equal(&got, &four), "vor__mw_times4, value %u", n);
    }
}

/* r = the unsigned number of n 64-bit words. */
static void wide_of_words(wide_t *r, const uint64_t *w, unsigned n)
{
    wide_set(r, 0);
    for (unsigned i = 0; i < n; i++) {
        r->v[2u * i] = (uint32_t)w[i];
        r->v[(2u * i) + 1u] = (uint32_t)(w[i] >> 32);
    }
}

/* r = acc + x y for the words acc[0..3), x[0..2), y[0..2). */
static void sum_of_product(wide_t *r, const uint64_t *acc, const uint64_t *x, const uint64_t *y)
{
    wide_t product, factor;
    wide_of_words(&product, x, 2u);
    wide_of_words(&factor, y, 2u);
    wide_mul(&product, &product, &factor);
    wide_of_words(r, acc, 3u);
    wide_add(r, &product);
}

static uint64_t random_u64(test_rng_t *rng)
{
    uint64_t high = test_rng_u32(rng);
    return (high << 32) | test_rng_u32(rng);
}

/* The fixed-width helpers of src/multiword.h at their words' edges,
 * against the test's integers: a 128-bit subtraction that borrows, a
 * 192-bit product sum whose middle word carries, the exact -1 and 1 of
 * the comparisons, the 96-bit comparison on a tie, and the sign mask of
 * values with bit 62 set. */
static void check_word_edges(void)
{
    test_rng_t rng;
    test_rng_seed(&rng, 192);
    unsigned bad_sub = 0;
    unsigned bad_product = 0;
    for (unsigned n = 0; n < 500u; n++) {
        /* a >= b, a.lo < b.lo: the low word borrows */
        vor__mw_u128_t b = {random_u64(&rng) | 1u, random_u64(&rng) >> 2};
        vor__mw_u128_t a = {b.lo - 1u - (random_u64(&rng) % b.lo),
                            b.hi + 1u + (random_u64(&rng) >> 3)};
        vor__mw_u128_t r;
        vor__mw_u128_sub(&r, &a, &b);
        const uint64_t aw[2] = {a.lo, a.hi};
        const uint64_t bw[2] = {b.lo, b.hi};
        const uint64_t rw[2] = {r.lo, r.hi};
        wide_t difference, subtrahend, got;
        wide_of_words(&difference, aw, 2u);
        wide_of_words(&subtrahend, bw, 2u);
        wide_sub(&difference, &subtrahend);
        wide_of_words(&got, rw, 2u);
        if (!low_words_equal(&got, &difference, 4u)) {
            bad_sub++;
        }
        CHECK(vor__mw_u128_compare(&a, &b) == 1 && vor__mw_u128_compare(&b, &a) == -1,
              "vor__mw_u128_compare, case %u", n);
        vor__mw_u128_t same_high = {a.lo, b.hi};
        CHECK(vor__mw_u128_compare(&same_high, &b) == -1 &&
                  vor__mw_u128_compare(&b, &same_high) == 1,
              "vor__mw_u128_compare, equal high words, case %u", n);
        /* acc + (x + xh 2^64)(y + yh 2^64) modulo 2^192, every word's top
         * bits set so that the middle word carries */
        vor__mw_u192_t acc = {
            {random_u64(&rng), random_u64(&rng) | (UINT64_C(3) << 62), random_u64(&rng)}};
        uint64_t x = random_u64(&rng) | (UINT64_C(1) << 63);
        uint64_t y = random_u64(&rng) | (UINT64_C(1) << 63);
        uint64_t xh = n % 2u;
        uint64_t yh = (n / 2u) % 2u;
        const uint64_t xw[2] = {x, xh};
        const uint64_t yw[2] = {y, yh};
        wide_t want;
        sum_of_product(&want, acc.w, xw, yw);
        vor__mw_u192_add_product(&acc, x, xh, y, yh);
        wide_of_words(&got, acc.w, 3u);
        if (!low_words_equal(&got, &want, 6u)) {
            bad_product++;
        }
    }
    /* the carry out of the low word meeting a middle word of all ones:
     * 1 + (1 + 2^64)(2^64 - 1) = 2^128, the carry runs into the top word */
    {
        vor__mw_u192_t acc = {{1u, 0u, 0u}};
        const uint64_t xw[2] = {1u, 1u};
        const uint64_t yw[2] = {UINT64_MAX, 0u};
        wide_t want, got;
        sum_of_product(&want, acc.w, xw, yw);
        vor__mw_u192_add_product(&acc, 1u, 1u, UINT64_MAX, 0u);
        wide_of_words(&got, acc.w, 3u);
        bad_product += low_words_equal(&got, &want, 6u) ? 0u : 1u;
    }
    CHECK(bad_sub == 0u, "vor__mw_u128_sub wrong %u times", bad_sub);
    CHECK(bad_product == 0u, "vor__mw_u192_add_product wrong %u times", bad_product);
    vor__limb one[2] = {1u, 0u};
    vor__limb two[2] = {2u, 0u};
    CHECK(vor__mw_compare(two, one, 2u) == 1 && vor__mw_compare(one, two, 2u) == -1 &&
              vor__mw_compare(one, one, 2u) == 0,
          "vor__mw_compare: %d %d", vor__mw_compare(two, one, 2u), vor__mw_compare(one, two, 2u));
    vor__mw_i96_t p = {-5, 7u};
    vor__mw_i96_t q = {-5, 7u};
    CHECK(vor__mw_i96_greater(&p, &q) == 0, "vor__mw_i96_greater on a tie");
    q.lo = 6u;
    CHECK(vor__mw_i96_greater(&p, &q) != 0 && vor__mw_i96_greater(&q, &p) == 0,
          "vor__mw_i96_greater, low words");
    CHECK(vor__mw_sign_mask(INT64_C(1) << 62) == 0u && vor__mw_sign_mask(-1) == ~UINT64_C(0) &&
              vor__mw_sign_mask(INT64_MIN) == ~UINT64_C(0),
          "vor__mw_sign_mask");
}

void test_predicates(void)
{
    TEST_CASE("multiply") check_multiply();
    TEST_CASE("shift") check_shift();
    TEST_CASE("bounds") check_bounds();
    TEST_CASE("vectors") check_vectors();
    TEST_CASE("power_vectors") check_power_vectors();
    TEST_CASE("grid_antisymmetry") check_grid_antisymmetry();
    TEST_CASE("perturbation_reference") check_perturbation_reference();
    TEST_CASE("first_term_filter") check_first_term_filter();
    TEST_CASE("unit_first_term") check_unit_first_term();
    TEST_CASE("crossing_vectors") check_crossing_vectors();
    TEST_CASE("near_circles") check_near_circles();
    TEST_CASE("tier_edges") check_tier_edges();
    TEST_CASE("magnitudes") check_magnitudes();
    TEST_CASE("point_bound") check_point_bound();
    TEST_CASE("closer_sos_reference") check_closer_sos_reference();
    TEST_CASE("wide_magnitudes") check_wide_magnitudes();
    TEST_CASE("closer_coincident") check_closer_coincident();
    TEST_CASE("limb_edges") check_limb_edges();
    TEST_CASE("word_edges") check_word_edges();
    TEST_CASE("wide_helpers") check_wide_helpers();
}
