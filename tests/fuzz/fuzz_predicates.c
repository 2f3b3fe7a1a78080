/* SPDX-License-Identifier: MIT */
/*
 * fuzz_predicates.c - libFuzzer harness: orient2d, incircle, closer and the
 * power test and power distance on random and structured operands (int32
 * corners, near-degenerate runs, cocircular lattice points, int64 weight
 * corners and equal or nearly equal weights) against the textbook
 * determinants in fuzz_common.h's integers. The _sos variants must agree
 * with the exact sign where it is not 0, never return 0 for distinct
 * indices, and change sign when two indices swap (a transposition of
 * rows); with equal weights the power test is the incircle test.
 */
#include "fuzz_common.h"

static void check_sos(const vor_point_t *p)
{
    int exact = fuzz_orient(p[0], p[1], p[2]);
    int sos = vor_orient2d_sos(p, 0, 1, 2);
    FUZZ_REQUIRE(sos == 1 || sos == -1, "orient2d_sos returned 0");
    FUZZ_REQUIRE(exact == 0 || sos == exact, "orient2d_sos disagrees with the exact sign");
    FUZZ_REQUIRE(vor_orient2d_sos(p, 1, 0, 2) == -sos &&
                     vor_orient2d_sos(p, 1, 2, 0) == sos,
                 "orient2d_sos: not alternating in its indices");

    exact = fuzz_incircle(p[0], p[1], p[2], p[3]);
    sos = vor_incircle_sos(p, 0, 1, 2, 3);
    FUZZ_REQUIRE(sos == 1 || sos == -1, "incircle_sos returned 0");
    FUZZ_REQUIRE(exact == 0 || sos == exact, "incircle_sos disagrees with the exact sign");
    FUZZ_REQUIRE(vor_incircle_sos(p, 0, 1, 3, 2) == -sos &&
                     vor_incircle_sos(p, 1, 2, 0, 3) == sos,
                 "incircle_sos: not alternating in its indices");

    unsigned __int128 da = fuzz_distance2(p[0].x, p[0].y, p[1]);
    unsigned __int128 db = fuzz_distance2(p[0].x, p[0].y, p[2]);
    exact = (da > db) - (da < db);
    sos = vor_closer_sos(p, 0, 1, 2);
    FUZZ_REQUIRE(sos == 1 || sos == -1, "closer_sos returned 0");
    FUZZ_REQUIRE(exact == 0 || sos == exact, "closer_sos disagrees with the exact sign");
    FUZZ_REQUIRE(vor_closer_sos(p, 0, 2, 1) == -sos, "closer_sos: not antisymmetric");
    FUZZ_REQUIRE(vor_orient2d_sos(p, 0, 0, 1) == 0 && vor_orient2d_sos(NULL, 0, 1, 2) == 0,
                 "orient2d_sos: equal indices or NULL not 0");
}

static void check_power(const vor_point_t *p, const int64_t *w)
{
    int exact = fuzz_power(p[0], w[0], p[1], w[1], p[2], w[2], p[3], w[3]);
    FUZZ_REQUIRE(vor_power_test(p[0], w[0], p[1], w[1], p[2], w[2], p[3], w[3]) == exact,
                 "power test wrong");
    int sos = vor_power_test_sos(p, w, 0, 1, 2, 3);
    FUZZ_REQUIRE(sos == 1 || sos == -1, "power_test_sos returned 0");
    FUZZ_REQUIRE(exact == 0 || sos == exact, "power_test_sos disagrees with the exact sign");
    FUZZ_REQUIRE(vor_power_test_sos(p, w, 0, 1, 3, 2) == -sos &&
                     vor_power_test_sos(p, w, 1, 2, 0, 3) == sos,
                 "power_test_sos: not alternating in its indices");
    if (w[0] == w[3] && w[1] == w[3] && w[2] == w[3]) {
        FUZZ_REQUIRE(sos == vor_incircle_sos(p, 0, 1, 2, 3),
                     "power_test_sos of equal weights is not incircle_sos");
    }
    /* power distance: |q - a|^2 - wa against |q - b|^2 - wb, q = p[3] */
    fuzz_big_t da = fuzz_big_sub(fuzz_big_from((__int128)fuzz_distance2(p[3].x, p[3].y, p[0])),
                                 fuzz_big_from(w[0]));
    fuzz_big_t db = fuzz_big_sub(fuzz_big_from((__int128)fuzz_distance2(p[3].x, p[3].y, p[1])),
                                 fuzz_big_from(w[1]));
    FUZZ_REQUIRE(vor_power_closer(p[3], p[0], w[0], p[1], w[1]) ==
                     fuzz_big_sign(fuzz_big_sub(da, db)),
                 "power closer wrong");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_reader_t r = {data, size, 0};
    vor_point_t previous = {0, 0};
    int64_t previous_weight = 0;
    while (!fuzz_done(&r)) {
        vor_point_t p[4];
        int64_t w[4];
        for (int i = 0; i < 4; i++)
            p[i] = fuzz_point(&r, &previous);
        for (int i = 0; i < 4; i++)
            w[i] = fuzz_weight(&r, &previous_weight);
        FUZZ_REQUIRE(vor_orient2d(p[0], p[1], p[2]) == fuzz_orient(p[0], p[1], p[2]),
                     "orient2d wrong");
        FUZZ_REQUIRE(vor_incircle(p[0], p[1], p[2], p[3]) ==
                         fuzz_incircle(p[0], p[1], p[2], p[3]),
                     "incircle wrong");
        unsigned __int128 da = fuzz_distance2(p[3].x, p[3].y, p[0]);
        unsigned __int128 db = fuzz_distance2(p[3].x, p[3].y, p[1]);
        FUZZ_REQUIRE(vor_closer(p[3], p[0], p[1]) == (da > db) - (da < db),
                     "closer wrong");
        check_sos(p);
        check_power(p, w);
    }
    return 0;
}
