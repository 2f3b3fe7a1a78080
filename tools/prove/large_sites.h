/* SPDX-License-Identifier: MIT */
/*
 * large_sites.h - the larger concrete diagram of `make prove` (large.c):
 * 39 points: a centre (0) with 20 neighbours on a ring of radius 300
 * around it (1 to 20), a cluster of 10 within 40 x 40 (21 to 30, a crowded
 * quadtree bucket), 7 scattered over 4000 x 4000 (31 to 37) and a
 * duplicate of 21 (38: the forked quadtree build's first half then uses
 * fewer triangle slots than it was given); and the 7 scaled by 2^10.
 */
#ifndef PROVE_LARGE_SITES_H
#define PROVE_LARGE_SITES_H

#include "vor.h"

#define LN 39u
static const vor_point_t large_sites[LN] = {
    {2000, 2000}, {2299, 2030}, {2275, 2121}, {2224, 2200}, {2151, 2259}, {2064, 2293},
    {1970, 2299}, {1879, 2275}, {1800, 2224}, {1741, 2151}, {1707, 2064}, {1701, 1970},
    {1725, 1879}, {1776, 1800}, {1849, 1741}, {1936, 1707}, {2030, 1701}, {2121, 1725},
    {2200, 1776}, {2259, 1849}, {2293, 1936}, {220, 309},   {225, 303},   {204, 334},
    {206, 323},   {237, 303},   {232, 313},   {202, 305},   {227, 326},   {204, 315},
    {205, 335},   {1738, 242},  {3386, 2316}, {507, 3880},  {914, 2583},  {2569, 2387},
    {3881, 253},  {2363, 2398}, {220, 309}};

/* the scattered ones 2^10 times further apart (large.c: the motion cache) */
#define MN 7u
static const vor_point_t motion_sites[MN] = {{1779712, 247808},  {3467264, 2371584},
                                             {519168, 3973120},  {935936, 2644992},
                                             {2630656, 2444288}, {3974144, 259072},
                                             {2419712, 2455552}};

static uint32_t large_arena[(VOR_ARENA_BYTES(LN) + 3u) / 4u];

#endif
