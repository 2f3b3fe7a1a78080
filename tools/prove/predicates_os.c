/* SPDX-License-Identifier: MIT */
/*
 * predicates_os.c - the predicates harness (predicates.c) over the
 * library as compiled at -Os, where the filters of the mid tier and of
 * the perturbed incircle's first term are left out. The library source
 * is included here, so that the compiler's macro reaches it.
 */
#define __OPTIMIZE_SIZE__ 1

#include "../../src/predicates.c"
#include "predicates.c"
