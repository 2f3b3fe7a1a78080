/* SPDX-License-Identifier: MIT */
/*
 * examples/exact_predicates - the exact predicates on inputs that break
 * floating-point geometry, run as firmware (`make demo` runs it on the
 * emulated Cortex-M3).
 *
 * Copy from here: a predicate call needs nothing but the points, passed
 * by value, and always answers -1, 0 or 1.
 */
#include "example_io.h"
#include "port.h"
#include "vor.h"

static void print_sign(const char *label, int sign)
{
    example_print(label);
    example_print(sign > 0 ? "+1\n" : sign < 0 ? "-1\n" : " 0\n");
}

int main(void)
{
    vor_port_init();
    example_print("vor: exact predicates on inputs that break floating point\n\n");

    /* Four lattice points on the circle x^2 + y^2 = R^2 with R = 1,069,469,830
     * (about 2^30), shifted towards INT32_MAX: exactly cocircular, which
     * doubles cannot tell (the determinant needs 133 bits). */
    const int32_t cx = 1000000000, cy = -1000000000;
    vor_point_t circle[4] = {
        {cx + 1069469830, cy + 0},
        {cx + 0, cy + 1069469830},
        {cx - 1069469830, cy + 0},
        {cx + 641681898, cy - 855575864},
    };
    print_sign("incircle of four cocircular points near 2^31:          ",
               vor_incircle(circle[0], circle[1], circle[2], circle[3]));
    /* moving the fourth point one unit outward puts it outside */
    vor_point_t nudged = {circle[3].x + 1, circle[3].y - 1};
    print_sign("the same with the last point moved one unit outward:  ",
               vor_incircle(circle[0], circle[1], circle[2], nudged));
    /* the perturbation decides the tie the same way every time */
    print_sign("perturbed incircle of the cocircular points:          ",
               vor_incircle_sos(circle, 0, 1, 2, 3));
    print_sign("  ...with indices 0 and 1 swapped (must flip):        ",
               vor_incircle_sos(circle, 1, 0, 2, 3));

    /* three collinear points spanning the whole int32 range */
    vor_point_t line[3] = {{INT32_MIN, INT32_MIN}, {0, 0}, {INT32_MAX, INT32_MAX}};
    print_sign("orient2d of (MIN,MIN), (0,0), (MAX,MAX):              ",
               vor_orient2d(line[0], line[1], line[2]));
    print_sign("perturbed orient2d of the same:                       ",
               vor_orient2d_sos(line, 0, 1, 2));

    /* cost of one full-range incircle */
    uint64_t start = vor_port_counter();
    int sink = 0;
    for (int i = 0; i < 100; i++) {
        sink += vor_incircle(circle[0], circle[1], circle[2], nudged);
    }
    uint64_t spent = vor_port_counter() - start;
    example_print("full-range incircle: ");
    example_print_int((long long)(spent / 100u));
    example_print(" ");
    example_print(vor_port_counter_unit);
    example_print(" per call\n");
    return sink == -100 ? 0 : 1; /* the nudged point is outside every time */
}
