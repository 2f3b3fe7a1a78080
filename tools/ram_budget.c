/* SPDX-License-Identifier: MIT */
/*
 * tools/ram_budget.c - the most sites whose diagram fits a RAM budget, from
 * VOR_ARENA_BYTES itself so the table in docs/porting.md cannot drift from
 * the macro (tools/memory-tables.py builds it once per VOR_INDEX_BITS).
 *
 *   ram_budget OVERHEAD BUDGET...   one line "BUDGET SITES" per budget
 *
 * OVERHEAD is what the budget holds besides the arena (vor_t, stack). The
 * host's value of VOR_ARENA_BYTES is the target's: the macro uses only
 * fixed-width types (vor_point_t, vor_index_t, VOR_TRIANGLE_BYTES).
 */
#include <stdio.h>
#include <stdlib.h>

#include "vor.h"

/* Largest n <= VOR_MAX_SITES with VOR_ARENA_BYTES(n) <= room, 0 if none;
 * the macro grows with n, so a binary search over [0, VOR_MAX_SITES]. */
static unsigned long most_sites(size_t room)
{
    unsigned long low = 0, high = VOR_MAX_SITES;
    while (low < high) {
        unsigned long mid = low + (high - low + 1u) / 2u;
        if (VOR_ARENA_BYTES(mid) <= room) {
            low = mid;
        } else {
            high = mid - 1u;
        }
    }
    return low;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: ram_budget OVERHEAD BUDGET...\n");
        return 2;
    }
    size_t overhead = strtoul(argv[1], NULL, 10);
    for (int i = 2; i < argc; i++) {
        size_t budget = strtoul(argv[i], NULL, 10);
        printf("%zu %lu\n", budget, budget > overhead ? most_sites(budget - overhead) : 0ul);
    }
    return 0;
}
