/* SPDX-License-Identifier: MIT */
/*
 * fuzz_predicates.c - libFuzzer harness: orient2d, incircle and closer on
 * random and structured operands (int32 corners, near-degenerate runs,
 * cocircular lattice points) against the textbook determinants evaluated
 * in 256-bit integers (fuzz_common.h). The _sos variants must agree with
 * the exact sign where it is not 0, never return 0 for distinct indices,
 * and change sign when two indices swap (a transposition of rows).
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

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_reader_t r = {data, size, 0};
    vor_point_t previous = {0, 0};
    while (!fuzz_done(&r)) {
        vor_point_t p[4];
        for (int i = 0; i < 4; i++)
            p[i] = fuzz_point(&r, &previous);
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
    }
    return 0;
}
