/* SPDX-License-Identifier: MIT */
/*
 * multiword.c - the harness of `make prove` for the multi-word arithmetic
 * of src/multiword.h on its own: Frama-C's EVA runs main() with every
 * operand anywhere in its documented domain (the whole width of its type
 * unless the helper's comment states a bound, then that bound), limb
 * counts from 1 to the widest the predicates use, so that no input of a
 * helper's contract can reach undefined behaviour, whatever the caller.
 * multiword_armv6m.c runs it again on the Cortex-M0 multiplies.
 */
#include <__fc_builtin.h>

#include "multiword.h"

/* Limbs of the widest number the predicates use (VOR__WIDE_LIMBS). */
#define LIMBS VOR__WIDE_LIMBS

static uint64_t sink;

static uint32_t any_u32(void)
{
    return Frama_C_unsigned_int_interval(0u, UINT32_MAX);
}

static int32_t any_i32(void)
{
    return Frama_C_int_interval(INT32_MIN, INT32_MAX);
}

static uint64_t any_u64(void)
{
    uint64_t v;
    Frama_C_make_unknown((char *)&v, sizeof v);
    return v;
}

static int64_t any_i64(void)
{
    return Frama_C_long_long_interval(INT64_MIN, INT64_MAX);
}

/* Any value in [lo, hi]. */
static int64_t any_in(int64_t lo, int64_t hi)
{
    return Frama_C_long_long_interval(lo, hi);
}

static void any_limbs(vor__limb a[LIMBS])
{
    Frama_C_make_unknown((char *)a, LIMBS * sizeof a[0]);
}

static void any_u128(vor__mw_u128_t *a)
{
    a->lo = any_u64();
    a->hi = any_u64();
}

/* The 32x32 and 64-bit multiplies, shifts and word helpers. */
static void words(void)
{
    sink += vor__mul_u32(any_u32(), any_u32());
    sink += (uint64_t)vor__mul_i32(any_i32(), any_i32());
    /* a product that fits int64, as its callers guarantee: a 33-bit
     * difference times any int32, or a wider factor times a smaller one */
    const int64_t d33 = ((int64_t)1 << 32) - 1;
    sink += (uint64_t)vor__mul_i64_i32(any_in(-d33, d33), any_i32());
    sink += (uint64_t)vor__mul_i64_i32(any_in(-((int64_t)1 << 47), (int64_t)1 << 47),
                                       (int32_t)any_in(-32768, 32767));
    sink += (uint64_t)vor__mul_limb(any_u32(), any_u32());
    uint64_t high;
    sink += vor__mul_u64(any_u64(), any_u64(), &high) + high;
    unsigned s = Frama_C_unsigned_int_interval(0u, 63u);
    sink += vor__shl_u64(any_u64(), s) + vor__shr_u64(any_u64(), s);
    int64_t d = any_i64();
    sink += vor__mw_sign_mask(d) + vor__mw_bound(d) + (uint64_t)vor__mw_sign64(d);
    sink += (uint64_t)vor__mw_unbound(any_u64(), any_i64());
    /* |d| of a difference of two int32 values */
    sink += vor__mw_magnitude(any_in(-d33, d33));
    sink += vor__mw_bit_length32(any_u32()) + vor__mw_bit_length(any_u64());
}

/* The limb arrays, n limbs of any value: every caller passes a constant
 * count, so each count is analysed on its own. */
static void limbs(size_t n)
{
    vor__limb r[LIMBS], a[LIMBS];
    any_limbs(r);
    any_limbs(a);
    vor__mw_from_u64(r, n, any_u64());
    vor__mw_from_i64(a, n, any_i64());
    vor__mw_add(r, a, n);
    vor__mw_sub(r, a, n);
    vor__mw_neg(r, n);
    vor__mw_shl1(r, n);
    vor__mw_shr1(r, n);
    vor__mw_copy(a, r, n);
    vor__mw_times4(r, a, n);
    sink += (uint64_t)vor__mw_sign(r, n) + (uint64_t)vor__mw_compare(r, a, n);
    sink += vor__mw_bit_length_limbs(r, n);
}

/* The product of na and nb limbs into nr (r distinct from a and b). */
static void product(size_t nr, size_t na, size_t nb)
{
    vor__limb r[LIMBS], a[LIMBS], b[LIMBS];
    any_limbs(a);
    any_limbs(b);
    vor__mw_mul(r, nr, a, na, b, nb);
    sink += r[0];
}

/* The 128-, 96- and 192-bit helpers. */
static void fixed(void)
{
    vor__mw_u128_t x, y, z;
    any_u128(&x);
    any_u128(&y);
    vor__mw_u128_set(&z, any_u64());
    vor__mw_u128_copy(&z, &x);
    vor__mw_u128_mul(&z, any_u64(), any_u64());
    vor__mw_u128_mul64(&z, &x, any_u64());
    vor__mw_u128_add(&z, &x, &y);
    vor__mw_u128_add_product(&z, any_u64(), any_u64());
    vor__mw_u128_sub(&z, &x, &y);
    vor__mw_u128_shr(&z, &x, Frama_C_unsigned_int_interval(1u, 63u));
    sink += (uint64_t)vor__mw_u128_compare(&x, &y) + (uint64_t)vor__mw_u128_is_zero(&z);
    vor__limb w[LIMBS];
    vor__mw_from_u128(w, LIMBS, &x);
    vor__mw_to_u128(&z, w);
    sink += z.lo;

    /* factors below 2^32 in magnitude */
    const int64_t d33 = ((int64_t)1 << 32) - 1;
    vor__mw_s128_t p, q, sum;
    vor__mw_s128_product(&p, any_in(-d33, d33), any_in(-d33, d33));
    vor__mw_s128_product(&q, any_in(-d33, d33), any_in(-d33, d33));
    vor__mw_s128_add(&sum, &p, &q);
    any_u128(&p.mag);
    p.neg = Frama_C_interval(0, 1);
    any_u128(&q.mag);
    q.neg = Frama_C_interval(0, 1);
    vor__mw_s128_add(&sum, &p, &q);
    sink += sum.mag.lo + (uint64_t)sum.neg;

    /* |x| < 2^62, y < 2^31 */
    const int64_t x62 = ((int64_t)1 << 62) - 1;
    vor__mw_i96_t u, v;
    vor__mw_i96_mul(&u, any_in(-x62, x62), Frama_C_unsigned_int_interval(0u, INT32_MAX));
    v.hi = any_i64();
    v.lo = any_u32();
    sink += (uint64_t)vor__mw_i96_greater(&u, &v) + (uint64_t)vor__mw_i96_greater(&v, &u);

    /* high parts 0 or 1 */
    vor__mw_u192_t acc, other;
    acc.w[0] = any_u64();
    acc.w[1] = any_u64();
    acc.w[2] = any_u64();
    other.w[0] = any_u64();
    other.w[1] = any_u64();
    other.w[2] = any_u64();
    vor__mw_u192_add_product(&acc, any_u64(), (uint64_t)Frama_C_interval(0, 1), any_u64(),
                             (uint64_t)Frama_C_interval(0, 1));
    sink += (uint64_t)vor__mw_u192_compare(&acc, &other);
}

int main(void)
{
    words();
    /* every count from 1 to LIMBS, one at a time */
    /*@ loop unroll LIMBS; */
    for (size_t n = 1; n <= LIMBS; n++) {
        limbs(n);
    }
    /*@ loop unroll LIMBS; */
    for (size_t nr = 1; nr <= LIMBS; nr++) {
        /*@ loop unroll LIMBS; */
        for (size_t na = 1; na <= LIMBS; na++) {
            /*@ loop unroll LIMBS; */
            for (size_t nb = 1; nb <= LIMBS; nb++) {
                product(nr, na, nb);
            }
        }
    }
    fixed();
    return (int)(sink & 1u);
}
