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

#endif
