/* SPDX-License-Identifier: MIT */
/*
 * test_predicates.c - the exact predicates against the independent oracle
 * (tools/gen_predicate_vectors.py, Python big integers), plus properties
 * the oracle does not state: sign changes under row swaps, tier coverage
 * and counters, and the multiply helpers against the compiler's own.
 */
#include "test.h"

#include "multiword.h"
#include "predicate_vectors.h"
#include "vor.h"

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

/* The exact predicate of v with its points in the order given by perm. */
static int exact_sign(const struct predicate_vector *v, const unsigned perm[4],
                      vor_predicate_stats_t *stats)
{
    vor_point_t p[4];
    for (unsigned k = 0; k < 4; k++) {
        p[k] = point_of(v, perm[k]);
    }
    switch (v->op) {
    case PV_ORIENT2D:
        return vor_orient2d(&p[0], &p[1], &p[2], stats);
    case PV_INCIRCLE:
        return vor_incircle(&p[0], &p[1], &p[2], &p[3], stats);
    default:
        return vor_closer(&p[0], &p[1], &p[2], stats);
    }
}

/* The perturbed predicate of v: site rank_of(k) holds point k. */
static int perturbed_sign(const struct predicate_vector *v,
                          const unsigned perm[4], vor_predicate_stats_t *stats)
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
    if (v->op == PV_ORIENT2D) {
        return vor_orient2d_sos(sites, id[0], id[1], id[2], stats);
    }
    return vor_incircle_sos(sites, id[0], id[1], id[2], id[3], stats);
}

static void check_vectors(void)
{
    static const unsigned identity[4] = {0, 1, 2, 3};
    static const unsigned swap01[4] = {1, 0, 2, 3};   /* one transposition */
    static const unsigned swap12[4] = {0, 2, 1, 3};   /* closer: a <-> b */
    static const unsigned rotate[4] = {1, 2, 0, 3};   /* even permutation */
    vor_predicate_stats_t stats = {0};
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
                int s = vor_orient2d_sos(sites, i, j, k, NULL);
                bad += (s == 0 || vor_orient2d_sos(sites, j, i, k, NULL) != -s ||
                        vor_orient2d_sos(sites, j, k, i, NULL) != s)
                           ? 1u
                           : 0u;
                for (uint32_t l = 0; l < 10; l += 3) {
                    if (l == i || l == j || l == k) {
                        continue;
                    }
                    int c = vor_incircle_sos(sites, i, j, k, l, NULL);
                    bad += (c == 0 || vor_incircle_sos(sites, j, i, k, l, NULL) != -c ||
                            vor_incircle_sos(sites, i, j, l, k, NULL) != -c ||
                            vor_incircle_sos(sites, l, k, j, i, NULL) != c)
                               ? 1u
                               : 0u;
                    count++;
                }
            }
        }
    }
    CHECK(bad == 0 && count > 1000, "grid antisymmetry: %u of %u wrong", bad, count);
}

void test_predicates(void)
{
    check_multiply();
    check_shift();
    check_vectors();
    check_grid_antisymmetry();
}
