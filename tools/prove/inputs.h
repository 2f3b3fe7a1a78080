/* SPDX-License-Identifier: MIT */
/*
 * inputs.h - the inputs the harnesses of `make prove` share: any uint32
 * and any point of the int32 plane, as Frama-C intervals (each call a
 * fresh value, so EVA covers the whole domain at once).
 */
#ifndef PROVE_INPUTS_H
#define PROVE_INPUTS_H

#include <__fc_builtin.h>

#include "vor.h"

static uint32_t any_u32(void)
{
    return Frama_C_unsigned_int_interval(0u, UINT32_MAX);
}

static vor_point_t any_point(void)
{
    vor_point_t p;
    p.x = Frama_C_interval(INT32_MIN, INT32_MAX);
    p.y = Frama_C_interval(INT32_MIN, INT32_MAX);
    return p;
}

/* Any int64 weight (the power diagram's). */
static int64_t any_weight(void)
{
    return (int64_t)Frama_C_long_long_interval(INT64_MIN, INT64_MAX);
}

/* Site ids in turn: i below n gives id i, i == n any other uint32
 * (VOR_NO_HINT included). Callers unroll the loop over i, so that a walk
 * or a fan starts from one concrete site in each state: from an id
 * anywhere, EVA could not tell a duplicate's id (which the mesh check
 * turns away by reading its slot) from a site's. */
static uint32_t id_or_any(uint32_t i, uint32_t n)
{
    return (i < n) ? i : Frama_C_unsigned_int_interval(n, UINT32_MAX);
}

#endif
