/* SPDX-License-Identifier: MIT */
/*
 * multiword.h - fixed-width multi-word integers for the exact predicates
 * (and, later, exact rational geometry). Private to the library.
 *
 * A number is an array of limbs, least significant first. Signed values are
 * two's complement over the whole array, so addition, subtraction and the
 * low half of a product are the same for signed and unsigned operands: the
 * caller picks a width in which the true result fits (each use states its
 * bound), and the arithmetic is then exact modulo nothing.
 *
 * The limb is 32 bits, or 64 where the compiler has a native 64x64->128
 * multiply (VOR_LIMB_BITS in vor_config.h). Widths are given in bits and
 * rounded up to limbs with VOR__LIMBS, so one source serves both.
 *
 * Besides the limb arrays, two fixed widths that stay in registers: the
 * 128-bit unsigned vor__mw_u128_t (with a sign-and-magnitude vor__mw_s128_t)
 * and the 96-bit signed product vor__mw_i96_t. The predicates, the geometry
 * and the raster all take their wide integers from here.
 */
#ifndef VOR_MULTIWORD_H
#define VOR_MULTIWORD_H

#include <stddef.h>
#include <stdint.h>

#include "vor_config.h"

/* The helpers below run with constant limb counts on the predicates' hot
 * paths; forcing them inline lets the compiler unroll the loops. The wider
 * tiers are kept out of line (VOR__NOINLINE) so that the narrow path does
 * not pay for their registers and stack. The coverage build (make
 * coverage-report) defines VOR__COVERAGE: each helper then stays one
 * function, so that gcov counts a branch of the source once, not once per
 * inlined copy. */
#if defined(__GNUC__) && !defined(VOR__COVERAGE)
#define VOR__ALWAYS_INLINE static inline __attribute__((always_inline))
#define VOR__NOINLINE __attribute__((noinline))
#else
#define VOR__ALWAYS_INLINE static inline
#define VOR__NOINLINE
#endif
/* At -Os the compiler weighs size, so it decides what to inline (a third
 * less flash for the predicates). The 128-bit helpers use
 * VOR__ALWAYS_INLINE, so that their operands, passed by pointer, stay in
 * registers. */
#if defined(__OPTIMIZE_SIZE__)
#define VOR__INLINE static inline
#else
#define VOR__INLINE VOR__ALWAYS_INLINE
#endif
/* The reverse, for a small helper several public calls share: forced
 * inline at -Os, where its one out-of-line copy would come with any of
 * them (a firmware iterating triangles would link what only vor_locate
 * needs); left to the compiler otherwise, which inlines it where that
 * pays. */
#if defined(__OPTIMIZE_SIZE__)
#define VOR__SHARED_INLINE VOR__ALWAYS_INLINE
#else
#define VOR__SHARED_INLINE static inline
#endif

/* Loops that only colder code calls: the compiler weighs inlining as for
 * a file's own static function (a header's static inline is inlined far
 * more eagerly, which costs flash at -O2); unused in most includers. */
#if defined(__GNUC__)
#define VOR__HELPER static __attribute__((unused))
#else
#define VOR__HELPER static inline
#endif

#if VOR_LIMB_BITS == 64
typedef uint64_t vor__limb;
__extension__ typedef unsigned __int128 vor__dlimb;
__extension__ typedef __int128 vor__sdlimb;
#elif VOR_LIMB_BITS == 32
typedef uint32_t vor__limb;
typedef uint64_t vor__dlimb;
#else
#error "VOR_LIMB_BITS must be 32 or 64"
#endif

/* The limb width as an unsigned constant, for the arithmetic on limb
 * counts and bit positions (VOR_LIMB_BITS is a plain int for #if). */
#define VOR__LIMB_WIDTH ((unsigned)VOR_LIMB_BITS)

/* Limbs needed to hold a value of the given number of bits (sign included). */
#define VOR__LIMBS(bits) (((bits) + VOR__LIMB_WIDTH - 1u) / VOR__LIMB_WIDTH)

/* Limbs of the widest value any predicate needs: 3x3 determinants whose
 * entries are up to 66 bits wide (docs/design/predicates.md, "Symbolic perturbation"). */
#define VOR__WIDE_LIMBS VOR__LIMBS(160u)

/* 32x32->64 unsigned multiply. ARMv6-M (Cortex-M0) has only a 32x32->32
 * multiply, and the compiler would call a generic 64x64 library routine;
 * four 16x16 products are cheaper there. */
VOR__INLINE uint64_t vor__mul_u32(uint32_t a, uint32_t b)
{
#if defined(__ARM_ARCH_6M__)
    uint32_t al = a & 0xFFFFu;
    uint32_t ah = a >> 16;
    uint32_t bl = b & 0xFFFFu;
    uint32_t bh = b >> 16;
    uint32_t lo = al * bl;
    uint32_t hi = ah * bh;
    uint32_t mid1 = al * bh;
    uint32_t mid2 = ah * bl;
    uint32_t mid = mid1 + mid2;
    /* the two middle products may carry out of 32 bits */
    hi += (mid < mid1) ? 0x10000u : 0u;
    hi += mid >> 16;
    uint32_t mid_lo = mid << 16;
    lo += mid_lo;
    hi += (lo < mid_lo) ? 1u : 0u;
    return ((uint64_t)hi << 32) | lo;
#else
    return (uint64_t)a * b;
#endif
}

/* 32x32->64 signed multiply, through vor__mul_u32 on ARMv6-M. */
VOR__INLINE int64_t vor__mul_i32(int32_t a, int32_t b)
{
#if defined(__ARM_ARCH_6M__)
    uint32_t ma = (a < 0) ? 0u - (uint32_t)a : (uint32_t)a;
    uint32_t mb = (b < 0) ? 0u - (uint32_t)b : (uint32_t)b;
    uint64_t m = vor__mul_u32(ma, mb);
    return ((a < 0) != (b < 0)) ? -(int64_t)m : (int64_t)m;
#else
    return (int64_t)a * b;
#endif
}

/* a * b for a product known to fit int64, via two 32x32 products on
 * ARMv6-M (no 64-bit multiply call). The magnitude is negated unsigned:
 * the product -2^63 has magnitude 2^63, which int64 cannot negate. */
VOR__INLINE int64_t vor__mul_i64_i32(int64_t a, int32_t b)
{
#if defined(__ARM_ARCH_6M__)
    uint64_t ma = (a < 0) ? 0u - (uint64_t)a : (uint64_t)a;
    uint32_t mb = (b < 0) ? 0u - (uint32_t)b : (uint32_t)b;
    uint64_t m = vor__mul_u32((uint32_t)ma, mb) + (vor__mul_u32((uint32_t)(ma >> 32), mb) << 32);
    return (int64_t)(((a < 0) != (b < 0)) ? (0u - m) : m);
#else
    return a * b;
#endif
}

/* Full product of two limbs. */
VOR__INLINE vor__dlimb vor__mul_limb(vor__limb a, vor__limb b)
{
#if VOR_LIMB_BITS == 32
    return vor__mul_u32(a, b);
#else
    return (vor__dlimb)a * b;
#endif
}

/* 64x64->128 unsigned multiply: the low word returned, the high in *high.
 * One instruction with 64-bit limbs; four limb products with 32-bit ones. */
VOR__INLINE uint64_t vor__mul_u64(uint64_t a, uint64_t b, uint64_t *high)
{
#if VOR_LIMB_BITS == 64
    vor__dlimb p = (vor__dlimb)a * b;
    *high = (uint64_t)(p >> 64);
    return (uint64_t)p;
#else
    uint32_t a0 = (uint32_t)a;
    uint32_t a1 = (uint32_t)(a >> 32);
    uint32_t b0 = (uint32_t)b;
    uint32_t b1 = (uint32_t)(b >> 32);
    uint64_t p00 = vor__mul_u32(a0, b0);
    uint64_t p01 = vor__mul_u32(a0, b1);
    uint64_t p10 = vor__mul_u32(a1, b0);
    uint64_t p11 = vor__mul_u32(a1, b1);
    /* three values below 2^32 each: no overflow */
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10;
    *high = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return (mid << 32) | (uint32_t)p00;
#endif
}

#if VOR_LIMB_BITS == 64
/* Sign of p0 q0 + p1 q1 + p2 q2 when each |product| is below 2^125, so
 * that the sum fits a signed double limb: three machine multiplies and
 * no branch on the terms' signs. 64-bit limbs only. */
VOR__INLINE int vor__mw_sign_of_products(int64_t p0, int64_t q0, int64_t p1, int64_t q1,
                                         int64_t p2, int64_t q2)
{
    vor__sdlimb sum = ((vor__sdlimb)p0 * q0) + (vor__sdlimb)p1 * q1 + (vor__sdlimb)p2 * q2;
    return (sum > 0) - (sum < 0);
}
#endif

/* v << s and v >> s for 0 <= s < 64. On a 32-bit machine a 64-bit shift by
 * a variable amount becomes a runtime call (__aeabi_llsl, __ashldi3, ...)
 * at -Os, and with clang always on ARMv6-M, so it is done here on the two
 * 32-bit halves; with 64-bit limbs the machine shifts natively. */
VOR__INLINE uint64_t vor__shl_u64(uint64_t v, unsigned s)
{
#if VOR_LIMB_BITS == 64
    return v << s;
#else
    uint32_t lo = (uint32_t)v;
    uint32_t hi = (uint32_t)(v >> 32);
    if (s >= 32u) {
        hi = lo << (s - 32u);
        lo = 0;
    } else if (s != 0u) { /* lo >> 32 would be undefined */
        hi = (hi << s) | (lo >> (32u - s));
        lo <<= s;
    } else {
        /* s == 0: v as it is */
    }
    return ((uint64_t)hi << 32) | lo;
#endif
}

VOR__INLINE uint64_t vor__shr_u64(uint64_t v, unsigned s)
{
#if VOR_LIMB_BITS == 64
    return v >> s;
#else
    uint32_t lo = (uint32_t)v;
    uint32_t hi = (uint32_t)(v >> 32);
    if (s >= 32u) {
        lo = hi >> (s - 32u);
        hi = 0;
    } else if (s != 0u) {
        lo = (lo >> s) | (hi << (32u - s));
        hi >>= s;
    } else {
        /* s == 0: v as it is */
    }
    return ((uint64_t)hi << 32) | lo;
#endif
}

/* r[0..n) = v, zero-extended. */
VOR__INLINE void vor__mw_from_u64(vor__limb *r, size_t n, uint64_t v)
{
    for (size_t i = 0; i < n; i++) {
#if VOR_LIMB_BITS == 32
        r[i] = (vor__limb)v;
        v = (i == 0u) ? (v >> 32) : 0u;
#else
        r[i] = (i == 0u) ? v : 0u;
#endif
    }
}

/* r[0..n) = v, sign-extended. */
VOR__INLINE void vor__mw_from_i64(vor__limb *r, size_t n, int64_t v)
{
    vor__limb fill = (v < 0) ? (vor__limb)~(vor__limb)0 : 0u;
    vor__mw_from_u64(r, n, (uint64_t)v);
    /* 64 bits fill one 64-bit limb or two 32-bit limbs; the rest is sign */
    for (size_t i = 64u / VOR__LIMB_WIDTH; i < n; i++) {
        r[i] = fill;
    }
}

/* r += a over n limbs (mod 2^(n*VOR_LIMB_BITS)). */
VOR__INLINE void vor__mw_add(vor__limb *r, const vor__limb *a, size_t n)
{
    vor__limb carry = 0;
    for (size_t i = 0; i < n; i++) {
        vor__limb s = r[i] + carry;
        carry = (s < carry) ? 1u : 0u;
        s += a[i];
        carry += (s < a[i]) ? 1u : 0u;
        r[i] = s;
    }
}

/* r -= a over n limbs (mod 2^(n*VOR_LIMB_BITS)). */
VOR__INLINE void vor__mw_sub(vor__limb *r, const vor__limb *a, size_t n)
{
    vor__limb borrow = 0;
    for (size_t i = 0; i < n; i++) {
        vor__limb d = r[i] - a[i];
        vor__limb b1 = (r[i] < a[i]) ? 1u : 0u;
        vor__limb b2 = (d < borrow) ? 1u : 0u;
        r[i] = d - borrow;
        borrow = b1 | b2;
    }
}

/* r[0..nr) = low nr limbs of a[0..na) * b[0..nb). r must not overlap a or b.
 * Exact for signed (two's complement) operands when the true product fits
 * in nr limbs and na, nb >= nr or the operands are non-negative. */
VOR__INLINE void vor__mw_mul(vor__limb *r, size_t nr, const vor__limb *a,
                               size_t na, const vor__limb *b, size_t nb)
{
    for (size_t i = 0; i < nr; i++) {
        r[i] = 0;
    }
    for (size_t i = 0; (i < na) && (i < nr); i++) {
        vor__limb carry = 0;
        for (size_t j = 0; (j < nb) && ((i + j) < nr); j++) {
            vor__dlimb t = vor__mul_limb(a[i], b[j]) + r[i + j] + carry;
            r[i + j] = (vor__limb)t;
            carry = (vor__limb)(t >> VOR_LIMB_BITS);
        }
        if ((i + nb) < nr) {
            r[i + nb] = carry;
        }
    }
}

/* Sign of a two's complement number: -1, 0 or 1. */
VOR__INLINE int vor__mw_sign(const vor__limb *a, size_t n)
{
    VOR_ASSERT(n > 0u);
    if ((a[n - 1u] >> (VOR__LIMB_WIDTH - 1u)) != 0u) {
        return -1;
    }
    for (size_t i = 0; i < n; i++) {
        if (a[i] != 0u) {
            return 1;
        }
    }
    return 0;
}

/* All ones for negative d, else 0 (the sign bit spread by an unsigned
 * shift: compilers emit one arithmetic shift). */
VOR__INLINE uint64_t vor__mw_sign_mask(int64_t d)
{
    return 0u - ((uint64_t)d >> 63);
}

/* |d| rounded down for negative d (~d = -d - 1), two instructions on most
 * machines: vor__mw_bound(d) < 2^k exactly when d lies in [-2^k, 2^k - 1].
 * The OR of bounds is below 2^k exactly when every bound is: one test
 * picks the width a group of differences fits. */
VOR__INLINE uint64_t vor__mw_bound(int64_t d)
{
    return (uint64_t)d ^ vor__mw_sign_mask(d);
}

/* d again from b = vor__mw_bound(d), as int32 when b < 2^31: the same
 * mask undone, which compilers fold to (int32_t)d. For an analyser it ties
 * d's range to b's, which a tier's test of an OR of bounds gives it (it
 * keeps no relation between d and b). */
VOR__INLINE int32_t vor__mw_unbound(uint64_t b, int64_t d)
{
    return (int32_t)b ^ (int32_t)vor__mw_sign_mask(d);
}

/* Sign of v: -1, 0 or 1. */
VOR__INLINE int vor__mw_sign64(int64_t v)
{
    return (v > 0) - (v < 0);
}

/* |d| for the difference of two int32 values: at most 2^32 - 1. */
VOR__ALWAYS_INLINE uint32_t vor__mw_magnitude(int64_t d)
{
    return (uint32_t)((d < 0) ? -d : d);
}

/* r = -r over n limbs (two's complement). */
VOR__INLINE void vor__mw_neg(vor__limb *r, size_t n)
{
    vor__limb carry = 1;
    for (size_t i = 0; i < n; i++) {
        vor__limb v = (vor__limb)~r[i] + carry;
        carry = (v < carry) ? 1u : 0u;
        r[i] = v;
    }
}

/* Compares a and b as unsigned n-limb numbers: -1, 0 or 1. */
VOR__INLINE int vor__mw_compare(const vor__limb *a, const vor__limb *b, size_t n)
{
    for (size_t i = n; i-- > 0;) {
        if (a[i] != b[i]) {
            return (a[i] < b[i]) ? -1 : 1;
        }
    }
    return 0;
}

/* r <<= 1 over n limbs (the top bit is lost). */
VOR__INLINE void vor__mw_shl1(vor__limb *r, size_t n)
{
    for (size_t i = n; i-- > 1;) {
        r[i] = (vor__limb)((r[i] << 1) | (r[i - 1u] >> (VOR__LIMB_WIDTH - 1u)));
    }
    r[0] = (vor__limb)(r[0] << 1);
}

/* r >>= 1 over n limbs, as an unsigned number. */
VOR__INLINE void vor__mw_shr1(vor__limb *r, size_t n)
{
    for (size_t i = 0; (i + 1u) < n; i++) {
        r[i] = (vor__limb)((r[i] >> 1) | (r[i + 1u] << (VOR__LIMB_WIDTH - 1u)));
    }
    r[n - 1u] >>= 1;
}

/* r = a over n limbs. */
VOR__HELPER void vor__mw_copy(vor__limb *r, const vor__limb *a, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        r[i] = a[i];
    }
}

/* r = 4 a over n limbs (the caller's width holds it). */
VOR__HELPER void vor__mw_times4(vor__limb *r, const vor__limb *a, size_t n)
{
    vor__limb carry = 0;
    for (size_t i = 0; i < n; i++) {
        r[i] = (vor__limb)(a[i] << 2) | carry;
        carry = a[i] >> (VOR__LIMB_WIDTH - 2u);
    }
}

/* ------------------------------------------------------------ 128 bits */

/* An unsigned 128-bit value in two words. Its helpers take and write it
 * through pointers, never by value, and no code copies it as a whole:
 * GCC for ARMv6-M copies a 16-byte structure with a call to memcpy at -Og
 * and -O0 (and out of line at -Os), and the library calls nothing
 * outside itself. Forced inline, the helpers' locals still live in
 * registers when optimising. Every helper reads its operands before it
 * writes r, so r may be one of them. */
typedef struct vor__mw_u128 {
    uint64_t lo;
    uint64_t hi;
} vor__mw_u128_t;

/* A signed value below 2^128 in magnitude, as sign and magnitude (neg is
 * 0 for zero): no negation across the words. */
typedef struct vor__mw_s128 {
    vor__mw_u128_t mag;
    int neg;
} vor__mw_s128_t;

/* *r = v. */
VOR__ALWAYS_INLINE void vor__mw_u128_set(vor__mw_u128_t *r, uint64_t v)
{
    r->lo = v;
    r->hi = 0;
}

/* *r = *a, word by word. */
VOR__ALWAYS_INLINE void vor__mw_u128_copy(vor__mw_u128_t *r, const vor__mw_u128_t *a)
{
    r->lo = a->lo;
    r->hi = a->hi;
}

/* *r = a * b, the full product of two words. */
VOR__ALWAYS_INLINE void vor__mw_u128_mul(vor__mw_u128_t *r, uint64_t a, uint64_t b)
{
    uint64_t high; /* not &r->hi: r stays in registers */
    r->lo = vor__mul_u64(a, b, &high);
    r->hi = high;
}

/* *r = *a * b, for a product known to be below 2^128. */
VOR__ALWAYS_INLINE void vor__mw_u128_mul64(vor__mw_u128_t *r, const vor__mw_u128_t *a, uint64_t b)
{
    uint64_t a_hi = a->hi;
    uint64_t high;
    uint64_t ignored;
    uint64_t low = vor__mul_u64(a->lo, b, &high);
    r->lo = low;
    r->hi = high + vor__mul_u64(a_hi, b, &ignored);
}

/* *r = *a + *b, modulo 2^128. */
VOR__ALWAYS_INLINE void vor__mw_u128_add(vor__mw_u128_t *r, const vor__mw_u128_t *a,
                                         const vor__mw_u128_t *b)
{
    uint64_t lo = a->lo + b->lo;
    uint64_t hi = a->hi + b->hi + ((lo < a->lo) ? 1u : 0u);
    r->lo = lo;
    r->hi = hi;
}

/* *acc += a * b, modulo 2^128: the product never leaves registers. */
VOR__ALWAYS_INLINE void vor__mw_u128_add_product(vor__mw_u128_t *acc, uint64_t a, uint64_t b)
{
    uint64_t high;
    uint64_t low = vor__mul_u64(a, b, &high);
    acc->lo += low;
    acc->hi += high + ((acc->lo < low) ? 1u : 0u);
}

/* *r = *a - *b for *a >= *b. */
VOR__ALWAYS_INLINE void vor__mw_u128_sub(vor__mw_u128_t *r, const vor__mw_u128_t *a,
                                         const vor__mw_u128_t *b)
{
    uint64_t lo = a->lo - b->lo;
    uint64_t hi = a->hi - b->hi - ((a->lo < b->lo) ? 1u : 0u);
    r->lo = lo;
    r->hi = hi;
}

/* *r = *a >> s for s in [1, 63]. The 64-bit shifts go through
 * vor__shr_u64 and vor__shl_u64: with a constant s they fold to the plain
 * shifts, and without optimisation, where s stays a variable, they are no
 * runtime call on 32-bit targets. */
VOR__ALWAYS_INLINE void vor__mw_u128_shr(vor__mw_u128_t *r, const vor__mw_u128_t *a, unsigned s)
{
    uint64_t lo = vor__shr_u64(a->lo, s) | vor__shl_u64(a->hi, 64u - s);
    uint64_t hi = vor__shr_u64(a->hi, s);
    r->lo = lo;
    r->hi = hi;
}

/* Sign of *a - *b: -1, 0 or 1. */
VOR__ALWAYS_INLINE int vor__mw_u128_compare(const vor__mw_u128_t *a, const vor__mw_u128_t *b)
{
    if (a->hi != b->hi) {
        return (a->hi < b->hi) ? -1 : 1;
    }
    if (a->lo != b->lo) {
        return (a->lo < b->lo) ? -1 : 1;
    }
    return 0;
}

/* Bit length of v: the least k with v < 2^k, 0 for 0. One CLZ where the
 * core has it (Armv7-M and up); elsewhere by halving, not the builtin,
 * which becomes a runtime call on ARMv6-M and 32-bit RISC-V without Zbb. */
VOR__INLINE unsigned vor__mw_bit_length32(uint32_t v_in)
{
    uint32_t v = v_in;
#if defined(__GNUC__) && defined(__ARM_FEATURE_CLZ)
    return (v == 0u) ? 0u : (32u - (unsigned)__builtin_clz(v));
#else
    unsigned k = 0;
    for (unsigned half = 16; half > 0u; half >>= 1) {
        /* (v >> half) != 0 as a comparison, which an analyser bounds v by */
        if (v >= ((uint32_t)1 << half)) {
            v >>= half;
            k += half;
        }
    }
    return k + v; /* v is 0 or 1 now */
#endif
}

VOR__INLINE unsigned vor__mw_bit_length(uint64_t v)
{
    uint32_t high = (uint32_t)(v >> 32);
    return (high != 0u) ? 32u + vor__mw_bit_length32(high) : vor__mw_bit_length32((uint32_t)v);
}

/* Bit length of a[0..n) as an unsigned number, 0 for 0. */
VOR__INLINE unsigned vor__mw_bit_length_limbs(const vor__limb *a, size_t n)
{
    for (size_t i = n; i-- > 0;) {
        if (a[i] != 0u) {
            return (unsigned)(i * VOR__LIMB_WIDTH) + vor__mw_bit_length((uint64_t)a[i]);
        }
    }
    return 0;
}

VOR__ALWAYS_INLINE int vor__mw_u128_is_zero(const vor__mw_u128_t *a)
{
    return (a->lo == 0u) && (a->hi == 0u);
}

/* r[0..n) = *v, zero-extended (n >= 128 bits of limbs). v by pointer: a
 * structure passed by value to a function left out of line is a memcpy
 * call at -Os. Each limb is chosen by the bits of its index, not by a
 * chain of == tests on it: that would be a case table (a libgcc call on
 * ARMv6-M at -Os). */
VOR__HELPER void vor__mw_from_u128(vor__limb *r, size_t n, const vor__mw_u128_t *v)
{
    for (size_t i = 0; i < n; i++) {
#if VOR_LIMB_BITS == 64
        r[i] = (i >= 2u) ? 0u : (i & 1u) ? v->hi : v->lo;
#else
        uint64_t half = (i & 2u) ? v->hi : v->lo;
        r[i] = (i >= 4u) ? 0u : (i & 1u) ? (uint32_t)(half >> 32) : (uint32_t)half;
#endif
    }
}

/* *r = the low 128 bits of a[]. */
VOR__ALWAYS_INLINE void vor__mw_to_u128(vor__mw_u128_t *r, const vor__limb *a)
{
#if VOR_LIMB_BITS == 64
    r->lo = a[0];
    r->hi = a[1];
#else
    r->lo = a[0] | ((uint64_t)a[1] << 32);
    r->hi = a[2] | ((uint64_t)a[3] << 32);
#endif
}

/* *r = x * y for |x|, |y| < 2^32. */
VOR__ALWAYS_INLINE void vor__mw_s128_product(vor__mw_s128_t *r, int64_t x, int64_t y)
{
    uint64_t mag = vor__mul_u32(vor__mw_magnitude(x), vor__mw_magnitude(y));
    vor__mw_u128_set(&r->mag, mag);
    r->neg = (x < 0) != (y < 0) && (mag != 0u);
}

/* *r = *a + *b, for sums below 2^128 in magnitude. */
VOR__ALWAYS_INLINE void vor__mw_s128_add(vor__mw_s128_t *r, const vor__mw_s128_t *a,
                                         const vor__mw_s128_t *b)
{
    int neg;
    if (a->neg == b->neg) {
        neg = a->neg;
        vor__mw_u128_add(&r->mag, &a->mag, &b->mag);
    } else if (vor__mw_u128_compare(&a->mag, &b->mag) >= 0) {
        neg = a->neg;
        vor__mw_u128_sub(&r->mag, &a->mag, &b->mag);
    } else {
        neg = b->neg;
        vor__mw_u128_sub(&r->mag, &b->mag, &a->mag);
    }
    r->neg = neg && !vor__mw_u128_is_zero(&r->mag);
}

/* ------------------------------------------------------------- 96 bits */

/* A signed 96-bit value hi 2^32 + lo (lo unsigned): the product of a
 * 62-bit signed and a 31-bit unsigned number, without a 64x64 multiply. */
typedef struct vor__mw_i96 {
    int64_t hi;
    uint32_t lo;
} vor__mw_i96_t;

/* *r = x * y for |x| < 2^62 and y < 2^31. Left to the compiler's
 * judgement (VOR__HELPER): forced inline, its two calls in an envelope
 * cost 184 bytes on Cortex-M0. The result goes through a pointer, not the
 * return slot, which GCC for ARMv6-M would copy with memcpy. */
VOR__HELPER void vor__mw_i96_mul(vor__mw_i96_t *r, int64_t x, uint32_t y)
{
    /* x = xh 2^32 + xl with xl in [0, 2^32), |xh| < 2^30 */
    uint32_t xl = (uint32_t)((uint64_t)x & 0xFFFFFFFFu);
    int32_t xh = (int32_t)((x - (int64_t)xl) / 4294967296); /* exact: constant divisor */
    uint64_t low = vor__mul_u32(xl, y);                     /* < 2^63 */
    r->hi = vor__mul_i32(xh, (int32_t)y) + (int64_t)(low >> 32); /* |.| < 2^62 */
    r->lo = (uint32_t)(low & 0xFFFFFFFFu);
}

/* *p > *q. */
VOR__HELPER int vor__mw_i96_greater(const vor__mw_i96_t *p, const vor__mw_i96_t *q)
{
    return (p->hi > q->hi) || ((p->hi == q->hi) && (p->lo > q->lo));
}

/* ------------------------------------------------------------ 192 bits */

/* An unsigned 192-bit value in three words: the incircle's wide-tier
 * sums of products of two 65-bit factors (predicates.c). */
typedef struct vor__mw_u192 {
    uint64_t w[3];
} vor__mw_u192_t;

/* *acc += (a + a_high 2^64) * (b + b_high 2^64), a_high, b_high in {0, 1}. */
VOR__INLINE void vor__mw_u192_add_product(vor__mw_u192_t *acc, uint64_t a, uint64_t a_high,
                                          uint64_t b, uint64_t b_high)
{
    uint64_t w1;
    uint64_t w0 = vor__mul_u64(a, b, &w1);
    uint64_t w2 = a_high & b_high;
    uint64_t add = (0u - a_high) & b;
    w1 += add;
    w2 += (w1 < add) ? 1u : 0u;
    add = (0u - b_high) & a;
    w1 += add;
    w2 += (w1 < add) ? 1u : 0u;
    acc->w[0] += w0;
    uint64_t carry = (acc->w[0] < w0) ? 1u : 0u;
    w1 += carry;
    w2 += (w1 < carry) ? 1u : 0u;
    acc->w[1] += w1;
    acc->w[2] += w2 + ((acc->w[1] < w1) ? 1u : 0u);
}

/* Sign of p - q. */
VOR__INLINE int vor__mw_u192_compare(const vor__mw_u192_t *p, const vor__mw_u192_t *q)
{
    for (int i = 2; i >= 0; i--) {
        if (p->w[i] != q->w[i]) {
            return (p->w[i] > q->w[i]) ? 1 : -1;
        }
    }
    return 0;
}

#endif
