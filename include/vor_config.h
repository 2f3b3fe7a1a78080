/*
 * vor_config.h - build-time configuration of vor.
 *
 * Every option has a default here. Override any of them with -D on the
 * compiler command line, or put your overrides in a header of your own and
 * build with -DVOR_CONFIG_HEADER='"my_vor_config.h"'; that header is read
 * first, so whatever it defines wins.
 */
#ifndef VOR_CONFIG_H
#define VOR_CONFIG_H

#ifdef VOR_CONFIG_HEADER
#include VOR_CONFIG_HEADER
#endif

/* VOR_ASSERT(x): internal consistency checks. Off (compiled out) by
 * default; tests build with it mapped to a trap. It never guards against
 * bad caller input: that is reported with error codes. */
#ifndef VOR_ASSERT
#define VOR_ASSERT(x) ((void)0)
#endif

/* VOR_LIMB_BITS: the word of the multi-word integer arithmetic behind the
 * exact predicates. 64 where the compiler has a native 64x64->128 multiply
 * (unsigned __int128, e.g. x86-64 and AArch64 gcc/clang), else 32. Both give
 * identical results; 32 is always available. */
#ifndef VOR_LIMB_BITS
#if defined(__SIZEOF_INT128__)
#define VOR_LIMB_BITS 64
#else
#define VOR_LIMB_BITS 32
#endif
#endif

#endif
