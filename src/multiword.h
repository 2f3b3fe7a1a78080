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
 */
#ifndef VOR_MULTIWORD_H
#define VOR_MULTIWORD_H

#include <stddef.h>
#include <stdint.h>

#include "vor_config.h"

/* The helpers below run with constant limb counts on the predicates' hot
 * paths; forcing them inline lets the compiler unroll the loops. The wider
 * tiers are kept out of line (VOR__NOINLINE) so that the narrow path does
 * not pay for their registers and stack. */
#if defined(__GNUC__)
#define VOR__ALWAYS_INLINE static inline __attribute__((always_inline))
#define VOR__NOINLINE __attribute__((noinline))
#else
#define VOR__ALWAYS_INLINE static inline
#define VOR__NOINLINE
#endif
/* At -Os the compiler weighs size, so it decides what to inline (a third
 * less flash for the predicates). Helpers that take or return structures
 * by value use VOR__ALWAYS_INLINE: out of line, their copies would be
 * memcpy calls. */
#if defined(__OPTIMIZE_SIZE__)
#define VOR__INLINE static inline
#else
#define VOR__INLINE VOR__ALWAYS_INLINE
#endif

#if VOR_LIMB_BITS == 64
typedef uint64_t vor__limb;
__extension__ typedef unsigned __int128 vor__dlimb;
#elif VOR_LIMB_BITS == 32
typedef uint32_t vor__limb;
typedef uint64_t vor__dlimb;
#else
#error "VOR_LIMB_BITS must be 32 or 64"
#endif

/* Limbs needed to hold a value of the given number of bits (sign included). */
#define VOR__LIMBS(bits) (((bits) + VOR_LIMB_BITS - 1) / VOR_LIMB_BITS)

/* Limbs of the widest value any predicate needs: 3x3 determinants whose
 * entries are up to 66 bits wide (docs/design.md, "perturbation"). */
#define VOR__WIDE_LIMBS VOR__LIMBS(160)

/* 32x32->64 unsigned multiply. ARMv6-M (Cortex-M0) has only a 32x32->32
 * multiply, and the compiler would call a generic 64x64 library routine;
 * four 16x16 products are cheaper there. */
VOR__INLINE uint64_t vor__mul_u32(uint32_t a, uint32_t b)
{
#if defined(__ARM_ARCH_6M__)
    uint32_t al = a & 0xFFFFu, ah = a >> 16;
    uint32_t bl = b & 0xFFFFu, bh = b >> 16;
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
 * ARMv6-M (no 64-bit multiply call). */
VOR__INLINE int64_t vor__mul_i64_i32(int64_t a, int32_t b)
{
#if defined(__ARM_ARCH_6M__)
    uint64_t ma = (a < 0) ? 0u - (uint64_t)a : (uint64_t)a;
    uint32_t mb = (b < 0) ? 0u - (uint32_t)b : (uint32_t)b;
    uint64_t m = vor__mul_u32((uint32_t)ma, mb) + (vor__mul_u32((uint32_t)(ma >> 32), mb) << 32);
    return ((a < 0) != (b < 0)) ? -(int64_t)m : (int64_t)m;
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
    uint32_t a0 = (uint32_t)a, a1 = (uint32_t)(a >> 32);
    uint32_t b0 = (uint32_t)b, b1 = (uint32_t)(b >> 32);
    uint64_t p00 = vor__mul_u32(a0, b0), p01 = vor__mul_u32(a0, b1);
    uint64_t p10 = vor__mul_u32(a1, b0), p11 = vor__mul_u32(a1, b1);
    /* three values below 2^32 each: no overflow */
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10;
    *high = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return (mid << 32) | (uint32_t)p00;
#endif
}

/* v << s and v >> s for 0 <= s < 64. On a 32-bit machine a 64-bit shift by
 * a variable amount becomes a runtime call (__aeabi_llsl, __ashldi3, ...)
 * at -Os, and with clang always on ARMv6-M, so it is done here on the two
 * 32-bit halves; with 64-bit limbs the machine shifts natively. */
VOR__INLINE uint64_t vor__shl_u64(uint64_t v, unsigned s)
{
#if VOR_LIMB_BITS == 64
    return v << s;
#else
    uint32_t lo = (uint32_t)v, hi = (uint32_t)(v >> 32);
    if (s >= 32u) {
        hi = lo << (s - 32u);
        lo = 0;
    } else if (s != 0u) { /* lo >> 32 would be undefined */
        hi = (hi << s) | (lo >> (32u - s));
        lo <<= s;
    }
    return ((uint64_t)hi << 32) | lo;
#endif
}

VOR__INLINE uint64_t vor__shr_u64(uint64_t v, unsigned s)
{
#if VOR_LIMB_BITS == 64
    return v >> s;
#else
    uint32_t lo = (uint32_t)v, hi = (uint32_t)(v >> 32);
    if (s >= 32u) {
        lo = hi >> (s - 32u);
        hi = 0;
    } else if (s != 0u) {
        lo = (lo >> s) | (hi << (32u - s));
        hi >>= s;
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
        v = (i == 0) ? v >> 32 : 0u;
#else
        r[i] = (i == 0) ? v : 0u;
#endif
    }
}

/* r[0..n) = v, sign-extended. */
VOR__INLINE void vor__mw_from_i64(vor__limb *r, size_t n, int64_t v)
{
    vor__limb fill = (v < 0) ? (vor__limb)~(vor__limb)0 : 0u;
    vor__mw_from_u64(r, n, (uint64_t)v);
    /* 64 bits fill one 64-bit limb or two 32-bit limbs; the rest is sign */
    for (size_t i = 64 / VOR_LIMB_BITS; i < n; i++) {
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
    for (size_t i = 0; i < na && i < nr; i++) {
        vor__limb carry = 0;
        for (size_t j = 0; j < nb && i + j < nr; j++) {
            vor__dlimb t = vor__mul_limb(a[i], b[j]) + r[i + j] + carry;
            r[i + j] = (vor__limb)t;
            carry = (vor__limb)(t >> VOR_LIMB_BITS);
        }
        if (i + nb < nr) {
            r[i + nb] = carry;
        }
    }
}

/* Sign of a two's complement number: -1, 0 or 1. */
VOR__INLINE int vor__mw_sign(const vor__limb *a, size_t n)
{
    if ((a[n - 1] >> (VOR_LIMB_BITS - 1)) != 0u) {
        return -1;
    }
    for (size_t i = 0; i < n; i++) {
        if (a[i] != 0u) {
            return 1;
        }
    }
    return 0;
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
        r[i] = (vor__limb)((r[i] << 1) | (r[i - 1] >> (VOR_LIMB_BITS - 1)));
    }
    r[0] = (vor__limb)(r[0] << 1);
}

/* r >>= 1 over n limbs, as an unsigned number. */
VOR__INLINE void vor__mw_shr1(vor__limb *r, size_t n)
{
    for (size_t i = 0; i + 1 < n; i++) {
        r[i] = (vor__limb)((r[i] >> 1) | (r[i + 1] << (VOR_LIMB_BITS - 1)));
    }
    r[n - 1] >>= 1;
}

/* Bit length of v: the least k with v < 2^k, 0 for 0. By halving, not a
 * count-leading-zeros builtin: ARMv6-M has no such instruction, and the
 * builtin becomes a runtime call there. */
VOR__INLINE unsigned vor__bit_length_u32(uint32_t v)
{
    unsigned k = 0;
    for (unsigned half = 16; half > 0u; half >>= 1) {
        if ((v >> half) != 0u) {
            v >>= half;
            k += half;
        }
    }
    return k + v; /* v is 0 or 1 now */
}

VOR__INLINE unsigned vor__bit_length_u64(uint64_t v)
{
    uint32_t high = (uint32_t)(v >> 32);
    return (high != 0u) ? 32u + vor__bit_length_u32(high) : vor__bit_length_u32((uint32_t)v);
}

/* Bit length of a[0..n) as an unsigned number, 0 for 0. */
VOR__INLINE unsigned vor__mw_bit_length(const vor__limb *a, size_t n)
{
    for (size_t i = n; i-- > 0;) {
        if (a[i] != 0u) {
            return (unsigned)(i * VOR_LIMB_BITS) + vor__bit_length_u64((uint64_t)a[i]);
        }
    }
    return 0;
}

#endif
