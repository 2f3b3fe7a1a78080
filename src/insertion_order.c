/* SPDX-License-Identifier: MIT */
/*
 * insertion_order.c - which site vor_build inserts when, and from where
 * its search starts: duplicate detection and the bucket quadtree order of
 * Ohya, Iri and Murota.
 *
 * The bounding square of the sites is cut into 4^k buckets, k =
 * floor(log4 n), so a bucket holds about one site. The buckets are ranked
 * by Ohya, Iri and Murota's recurrence for (I(r), J(r)): a quadtree order in which
 * every run of 4^(k-l) consecutive buckets is one square of level l. Each
 * square's representative is the first site in that order inside it (stored
 * from the buckets up to the root). Sites are then inserted level by
 * level from the root:
 * a square's representative, unless its parent square already inserted
 * it, with the search starting at the parent's representative, a site
 * close by. The remaining sites of each bucket follow, starting at the
 * bucket's representative. Every walk is then short, and insertion takes
 * expected O(n) time for uniform sites.
 *
 * All scratch arrays live in the arena's still unused triangle slots
 * (see vor__plan for the budget).
 */
#include "insertion_order.h"
#include "mesh.h"
#include "multiword.h"

/* Is the highest set bit of a below that of b? */
static inline bool lower_top_bit(uint32_t a, uint32_t b)
{
    return (a < b) && (a < (a ^ b));
}

/* Z-order (Morton order) of sites, ids breaking ties: consecutive sites
 * are close to each other, and equal points end up adjacent with the
 * smallest id (the first occurrence) first. The coordinate whose values
 * differ in the higher bit decides (Chan's comparison, no interleaving). */
static inline bool z_less(const vor_point_t *sites, vor_index_t a, vor_index_t b)
{
    /* flipping the sign bit maps int32 order onto uint32 order */
    uint32_t ax = (uint32_t)sites[a].x ^ 0x80000000u;
    uint32_t ay = (uint32_t)sites[a].y ^ 0x80000000u;
    uint32_t bx = (uint32_t)sites[b].x ^ 0x80000000u;
    uint32_t by = (uint32_t)sites[b].y ^ 0x80000000u;
    if ((ax == bx) && (ay == by)) {
        return a < b;
    }
    if (lower_top_bit(ax ^ bx, ay ^ by)) {
        return ay < by;
    }
    return ax < bx;
}

/* Lexicographic (x, y), ids breaking ties (the divide-and-conquer order). */
static inline bool lex_less_id(const vor_point_t *s, vor_index_t a, vor_index_t b)
{
    if (s[a].x != s[b].x) {
        return s[a].x < s[b].x;
    }
    if (s[a].y != s[b].y) {
        return s[a].y < s[b].y;
    }
    return a < b;
}

/* The sort's comparison, chosen by a constant rather than a function
 * pointer: the call graph stays static, so the stack depth stays known
 * (tools/stack-depth.py), and each branch inlines. */
static inline bool site_less(const vor_point_t *sites, vor_index_t a, vor_index_t b,
                             enum vor__sort_key key)
{
    return (key == VOR__SORT_LEX) ? lex_less_id(sites, a, b) : z_less(sites, a, b);
}

static void sift_down(const vor_point_t *sites, vor_index_t *ids, uint32_t root_in,
                      uint32_t n, enum vor__sort_key key)
{
    uint32_t root = root_in;
    /* each step at least doubles root, so this ends */
    for (;;) {
        uint32_t child = (2u * root) + 1u;
        if (child >= n) {
            return;
        }
        if (((child + 1u) < n) && site_less(sites, ids[child], ids[child + 1u], key)) {
            child++;
        }
        if (!site_less(sites, ids[root], ids[child], key)) {
            return;
        }
        vor_index_t t = ids[root];
        ids[root] = ids[child];
        ids[child] = t;
        root = child;
    }
}

/* Heapsort of ids[0..n) by site_less: O(n log n) worst case, in place.
 * n is at least 1 (the introsort hands it ranges of 16 or more), so
 * n - 1 does not wrap. */
static void heap_sort(const vor_point_t *sites, vor_index_t *ids, uint32_t n,
                      enum vor__sort_key key)
{
    VOR_ASSERT(n > 0u);
    for (uint32_t i = n / 2u; i-- > 0u;) {
        sift_down(sites, ids, i, n, key);
    }
    for (uint32_t end = n - 1u; end > 0u; end--) {
        vor_index_t t = ids[0];
        ids[0] = ids[end];
        ids[end] = t;
        sift_down(sites, ids, 0, end, key);
    }
}

static void swap_ids(vor_index_t *ids, uint32_t a, uint32_t b)
{
    vor_index_t t = ids[a];
    ids[a] = ids[b];
    ids[b] = t;
}

/* Introsort of ids[0..n) by site_less (a total order: ids break ties;
 * the divide-and-conquer builder sorts with it too):
 * median-of-three quicksort on an explicit stack, smaller part first so
 * the stack holds at most log2(n) + 2 <= 34 ranges (each range below the
 * top is the larger sibling of an ancestor of the range being sorted, and
 * those ancestors at least halve in size); insertion sort below 16; and
 * heapsort for a range that goes deeper than 2 log2(n), so the worst case
 * stays O(n log n) (crowded buckets of clustered sites hold thousands). */
void vor__sort_ids(const vor_point_t *sites, vor_index_t *ids, uint32_t n,
                   enum vor__sort_key key)
{
    struct range {
        uint32_t first;
        uint32_t count;
        uint32_t depth;
    } stack[34];
    unsigned top = 0;
    unsigned log2n = 0;
    while (vor__shl_u64(1u, log2n) < n) {
        log2n++;
    }
    stack[top] = (struct range){0, n, 0};
    top++;
    while (top > 0u) {
        top--;
        struct range r = stack[top];
        vor_index_t *a = ids + r.first;
        if (r.count < 16u) {
            for (uint32_t i = 1; i < r.count; i++) {
                vor_index_t v = a[i];
                uint32_t j = i;
                while ((j > 0u) && site_less(sites, v, a[j - 1u], key)) {
                    a[j] = a[j - 1u];
                    j--;
                }
                a[j] = v;
            }
            continue;
        }
        if (r.depth > (2u * log2n)) {
            heap_sort(sites, a, r.count, key);
            continue;
        }
        /* median of three to a[0], then Hoare partition around it */
        uint32_t mid = r.count / 2u;
        uint32_t last = r.count - 1u;
        if (site_less(sites, a[mid], a[0], key)) {
            swap_ids(a, mid, 0);
        }
        if (site_less(sites, a[last], a[0], key)) {
            swap_ids(a, last, 0);
        }
        if (site_less(sites, a[last], a[mid], key)) {
            swap_ids(a, last, mid);
        }
        swap_ids(a, 0, mid);
        vor_index_t pivot = a[0];
        uint32_t i = 0;
        uint32_t j = r.count;
        for (;;) { /* i and j move toward each other: ends within count steps */
            do {
                i++;
            } while ((i < r.count) && site_less(sites, a[i], pivot, key));
            do {
                j--;
            } while (site_less(sites, pivot, a[j], key));
            if (i >= j) {
                break;
            }
            swap_ids(a, i, j);
        }
        swap_ids(a, 0, j);
        /* [0, j) before the pivot, [j + 1, count) after: push the larger
         * first so that the smaller is sorted next */
        struct range left = {r.first, j, r.depth + 1u};
        struct range right = {r.first + j + 1u, r.count - j - 1u, r.depth + 1u};
        VOR_ASSERT((top + 2u) <= (sizeof(stack) / sizeof(stack[0])));
        if (left.count > right.count) {
            stack[top] = left;
            top++;
            stack[top] = right;
            top++;
        } else {
            stack[top] = right;
            top++;
            stack[top] = left;
            top++;
        }
    }
}

/* Ohya, Iri and Murota's recurrence for the cells (I(r), J(r)) of a
 * 2^k x 2^k grid, r < 4^k. A transcription we read prints I(r - k) in
 * the first inner loop; I(r - m) is meant (with it the sequence visits
 * every cell once, which tests check). */
static void quadtree_cells(unsigned k, vor_index_t *cell_i, vor_index_t *cell_j)
{
    /* c = floor(2^k / 3) without a division: c(t+1) = 2 c(t) + (t odd) */
    int32_t c = 0;
    for (unsigned t = 0; t < k; t++) {
        c = (2 * c) + (((t % 2u) != 0u) ? 1 : 0);
    }
    int32_t u = ((k % 2u) == 1u) ? 1 : -1; /* (-1)^(k+1) */
    int32_t s = (2 * c) + u;
    uint32_t m = 1;
    uint32_t r = 0;
    cell_i[0] = (vor_index_t)c;
    cell_j[0] = (vor_index_t)c;
    for (unsigned t = 1; t <= k; t++) {
        for (uint32_t p = 0; p < m; p++) {
            r++;
            int32_t mirrored = s - (int32_t)cell_i[r - m];
            cell_i[r] = (vor_index_t)mirrored;
            cell_j[r] = cell_j[r - m];
        }
        m *= 2u;
        for (uint32_t p = 0; p < m; p++) {
            r++;
            cell_i[r] = cell_i[r - m];
            int32_t mirrored = s - (int32_t)cell_j[r - m];
            cell_j[r] = (vor_index_t)mirrored;
        }
        m *= 2u;
        u *= -2;
        s += u;
    }
}

/* Small inputs: duplicates by comparing all pairs, input order. */
static uint32_t plan_small(const vor_t *d, uint32_t n, vor_index_t *plan,
                           uint32_t *duplicate_of)
{
    uint32_t count = 0;
    uint32_t dups = 0;
    vor_index_t previous = VOR__NONE;
    for (uint32_t s = 0; s < n; s++) {
        uint32_t first = s;
        for (uint32_t e = 0; (e < s) && (first == s); e++) {
            if ((d->sites[e].x == d->sites[s].x) && (d->sites[e].y == d->sites[s].y)) {
                first = e;
            }
        }
        if (duplicate_of != NULL) {
            duplicate_of[s] = first;
        }
        if (first == s) {
            plan[2u * count] = (vor_index_t)s;
            plan[(2u * count) + 1u] = previous;
            previous = (vor_index_t)s;
            count++;
        } else {
            dups++;
        }
    }
    /* duplicates after the sites, with their first occurrence */
    uint32_t at = count;
    for (uint32_t s = 0; (s < n) && (dups > 0u); s++) {
        uint32_t first = s;
        for (uint32_t e = 0; (e < s) && (first == s); e++) {
            if ((d->sites[e].x == d->sites[s].x) && (d->sites[e].y == d->sites[s].y)) {
                first = e;
            }
        }
        if (first != s) {
            plan[2u * at] = (vor_index_t)s;
            plan[(2u * at) + 1u] = (vor_index_t)first;
            at++;
        }
    }
    return count;
}

/* The plan's bucket grid: 2^k x 2^k buckets numbered by rows
 * (VOR__CELL_ROWS), the sites sorted by bucket, and the scratch arrays
 * its phases share. */
typedef struct {
    const vor_point_t *sites;
    unsigned k;
    uint32_t buckets;
    vor_index_t *start;     /* [buckets + 1]: where each bucket's run begins */
    vor_index_t *sorted;    /* [n]: the sites, bucket by bucket */
    vor_index_t *rep;       /* [n]: each site's first occurrence */
    vor_index_t *bucket_at; /* [buckets]: the bucket of each quadtree rank */
    vor_index_t *cell_j;    /* [buckets]: scratch for the ranks' rows */
    vor_index_t *next;      /* [buckets + 1]: the first non-empty rank >= r */
} plan_grid_t;

/* Duplicates: equal points are adjacent once each bucket is sorted; each
 * site's rep is the first of its equal points. */
static void find_duplicates(const plan_grid_t *g)
{
    const vor_index_t *start = g->start;
    vor_index_t *sorted = g->sorted;
    uint32_t n = start[g->buckets];
    uint32_t asked = 0;
    for (uint32_t b = 0; b < g->buckets; b++) {
        /* coordinates are read by id, at random places: the next buckets'
         * are asked for while this one is sorted */
        uint32_t ahead = ((n - start[b + 1u]) > 32u) ? (start[b + 1u] + 32u) : n;
        for (; VOR__PREFETCHING && (asked < ahead); asked++) {
            VOR__PREFETCH(&g->sites[sorted[asked]]);
        }
        vor__sort_ids(g->sites, &sorted[start[b]], (uint32_t)(start[b + 1u] - start[b]),
                      VOR__SORT_Z);
        for (uint32_t e = start[b]; e < start[b + 1u]; e++) {
            vor_index_t s = sorted[e];
            bool same = (e > start[b]) &&
                        (g->sites[sorted[e - 1u]].x == g->sites[s].x) &&
                        (g->sites[sorted[e - 1u]].y == g->sites[s].y);
            g->rep[s] = same ? g->rep[sorted[e - 1u]] : s;
        }
    }
}

/* VOR_ORDER_INPUT: the distinct sites in input order, each search from
 * the previous one. Returns their number. */
static uint32_t plan_input(const plan_grid_t *g, uint32_t n, vor_index_t *plan)
{
    uint32_t count = 0;
    vor_index_t previous = VOR__NONE;
    for (uint32_t s = 0; s < n; s++) {
        if (g->rep[s] == s) {
            plan[2u * count] = (vor_index_t)s;
            plan[(2u * count) + 1u] = previous;
            previous = (vor_index_t)s;
            count++;
        }
    }
    return count;
}

/* The representative of the square of ranks [r0, r0 + size): the first
 * site in quadtree order inside it, or VOR__NONE. */
static inline vor_index_t square_site(const plan_grid_t *g, uint32_t r0, uint32_t size)
{
    vor_index_t r = g->next[r0];
    return (r < (r0 + size)) ? g->sorted[g->start[g->bucket_at[r]]] : VOR__NONE;
}

/* Ranks the buckets in quadtree order (bucket_at, next), then plans the
 * squares' representatives level by level from the root, each search
 * from its parent square's representative. Returns the number planned. */
static uint32_t plan_squares(const plan_grid_t *g, vor_index_t *plan)
{
    uint32_t buckets = g->buckets;
    vor_index_t *bucket_at = g->bucket_at;
    vor_index_t *next = g->next;
    quadtree_cells(g->k, bucket_at, g->cell_j); /* (I(r), J(r)), I in place */
    for (uint32_t r = 0; r < buckets; r++) {
        bucket_at[r] = (vor_index_t)(((uint32_t)bucket_at[r] << g->k) | g->cell_j[r]);
    }
    next[buckets] = (vor_index_t)buckets;
    for (uint32_t r = buckets; r-- > 0u;) {
        uint32_t b = bucket_at[r];
        next[r] = (g->start[b + 1u] > g->start[b]) ? (vor_index_t)r : next[r + 1u];
    }
    uint32_t count = 0;
    for (unsigned level = 0; level <= g->k; level++) {
        uint32_t size = 1u << (2u * (g->k - level));
        for (uint32_t r0 = 0; r0 < buckets; r0 += size) {
            vor_index_t s = square_site(g, r0, size);
            if (s == VOR__NONE) {
                continue;
            }
            vor_index_t parent = VOR__NONE;
            if (level > 0u) {
                uint32_t psize = size * 4u;
                parent = square_site(g, r0 & ~(psize - 1u), psize);
            }
            if (s != parent) {
                plan[2u * count] = s;
                plan[(2u * count) + 1u] = parent;
                count++;
            }
        }
    }
    return count;
}

/* The other sites of each bucket, after the squares' `count`, coarse to
 * fine along its Z-order as the levels above did across buckets:
 * positions step, 3 step, 5 step, ... for halving steps, each walking
 * from the site one step back, already inserted (a crowded bucket, as
 * with clustered sites, then gets short walks and small cavities too).
 * Returns the new count. */
static uint32_t plan_buckets(const plan_grid_t *g, vor_index_t *plan, uint32_t count_in)
{
    uint32_t count = count_in;
    const vor_index_t *rep = g->rep;
    for (uint32_t r = 0; r < g->buckets; r++) {
        uint32_t b = g->bucket_at[r];
        uint32_t size = (uint32_t)(g->start[b + 1u] - g->start[b]);
        const vor_index_t *in = &g->sorted[g->start[b]];
        uint32_t step = 1;
        while ((2u * step) < size) {
            step *= 2u;
        }
        for (; (step > 0u) && (size > 1u); step /= 2u) {
            for (uint32_t pos = step; pos < size; pos += 2u * step) {
                vor_index_t s = in[pos];
                vor_index_t from = in[pos - step];
                if (rep[s] != s) {
                    continue;
                }
                plan[2u * count] = s;
                /* a duplicate is not in the mesh: start at the bucket's
                 * representative instead */
                plan[(2u * count) + 1u] = (rep[from] == from) ? from : in[0];
                count++;
            }
        }
    }
    return count;
}

uint32_t vor__plan(const vor_t *d, uint32_t n, enum vor_order order,
                   vor_index_t *scratch, vor_index_t *plan, uint32_t *duplicate_of)
{
    if (n < 8u) {
        return plan_small(d, n, plan, duplicate_of);
    }
    /* grid: 2^k x 2^k buckets, 4^k <= n < 4^(k+1) */
    plan_grid_t g;
    g.sites = d->sites;
    g.k = 0;
    while (vor__shl_u64(4u, 2u * g.k) <= n) {
        g.k++;
    }
    g.buckets = 1u << (2u * g.k);
    /* scratch: 4 buckets + 2 n + 2 <= 6 n + 2 entries (insertion_order.h) */
    g.start = scratch;
    g.sorted = g.start + g.buckets + 1u;
    g.rep = g.sorted + n;
    g.bucket_at = g.rep + n;
    g.cell_j = g.bucket_at + g.buckets;
    g.next = g.cell_j + g.buckets;
    vor__grid_square_t square;
    vor__grid_square(d, false, &square);
    vor__grid_sort(d, n, g.k, &square, VOR__CELL_ROWS, g.start, g.sorted);
    find_duplicates(&g);
    if (duplicate_of != NULL) {
        for (uint32_t s = 0; s < n; s++) {
            duplicate_of[s] = g.rep[s];
        }
    }
    uint32_t count = (order == VOR_ORDER_INPUT)
                         ? plan_input(&g, n, plan)
                         : plan_buckets(&g, plan, plan_squares(&g, plan));
    /* the duplicates last, with their first occurrence */
    uint32_t at = count;
    for (uint32_t s = 0; s < n; s++) {
        if (g.rep[s] != s) {
            plan[2u * at] = (vor_index_t)s;
            plan[(2u * at) + 1u] = g.rep[s];
            at++;
        }
    }
    VOR_ASSERT(at == n);
    return count;
}
