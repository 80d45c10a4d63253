/*
 * bvh_wide_walk.h - the two walks of the wide copy (bvh_wide_impl.h),
 * written once and compiled once per instruction set: the including file
 * defines WIDE_NEAREST and WIDE_ANY (the functions' names), and the lane
 * code they use,
 *
 *   lane_ray      a ray with its origin, reciprocal direction and, per
 *                 axis, which side of a box it meets first;
 *   lane_ray_init(lane_ray *, const rayo_ray *);
 *   lane_boxes    (node, ray, t_min, t_max, double entry[4]): the bit mask
 *                 of children whose box the ray enters within [t_min,
 *                 t_max], and where;
 *   lane_spheres  (wide, first, count, ray, t_min, double t[8]): the bit
 *                 mask of the leaf's spheres met at some t > t_min, and
 *                 those t.
 *
 * Exact: lane_boxes does, lane by lane, the arithmetic of bvh.c's slab()
 * (the float plane widened to double, minus the origin, times the
 * reciprocal; maxpd and minpd keep the running bound when the product is
 * NaN, as slab() does), so each child's box test answers what the binary
 * walk's test of that box answers; lane_spheres does, lane by lane, the
 * operations of rayo_sphere_intersect in its order (l = centre - origin;
 * beta = (lx dx + ly dy) + lz dz; delta = (beta beta - ((lx lx + ly ly)
 * + lz lz)) + r r; sqrt correctly rounded; beta - root, else beta + root,
 * against t_min), with no fused multiply-add (the SIMD files never enable
 * FMA and turn contraction off).  The walks then keep, as bvh.c does, the
 * smallest t below t_max with ties to the smallest primitive number, so
 * the order in which children are visited changes the work, never the
 * answer.
 */

typedef struct wide_entry {
    double t;       /* where the ray enters the child's box */
    uint32_t child; /* as in bvh_wide_node */
    uint32_t count;
} wide_entry;

/* The children of mask, nearest entry first, into e; how many. */
static inline unsigned wide_sorted(const bvh_wide_node *n, unsigned mask,
                                   const double *entry, wide_entry *e)
{
    unsigned c = 0;
    while (mask) {
        unsigned k = (unsigned)__builtin_ctz(mask), j = c++;
        wide_entry x;
        mask &= mask - 1;
        x.t = entry[k];
        x.child = n->child[k];
        x.count = n->count[k];
        while (j > 0 && e[j - 1].t > x.t) {
            e[j] = e[j - 1];
            j--;
        }
        e[j] = x;
    }
    return c;
}

void WIDE_NEAREST(const struct bvh_wide *wide, const rayo_ray *ray,
                  double t_min, double t_max, rayo_bvh_prim_fn test,
                  const void *context, double *best_t, uint32_t *best_id,
                  rayo_bvh_cost *cost)
{
    wide_entry stack[BVH_WIDE_STACK];
    size_t sp = 0;
    lane_ray r;
    uint32_t child = 0, count = 0;
    lane_ray_init(&r, ray);
    for (;;) {
        if (count == 0) {
            const bvh_wide_node *n = &wide->nodes[child];
            double entry[BVH_WIDE_LANES];
            double reach = bvh_reach(*best_t);
            double limit = reach < t_max ? reach : t_max;
            unsigned mask =
                lane_boxes(n, &r, t_min, limit, entry) & n->lanes;
            cost->node_tests += n->lane_count;
            if (mask != 0) {
                /* the nearest child next, the others stacked farthest
                 * first when there are two of them */
                unsigned k = (unsigned)__builtin_ctz(mask);
                unsigned m = mask & (mask - 1);
                if (m == 0) {
                    child = n->child[k];
                    count = n->count[k];
                    continue;
                }
                if ((m & (m - 1)) == 0) {
                    unsigned j = (unsigned)__builtin_ctz(m);
                    unsigned a = entry[j] < entry[k] ? j : k, b = a ^ j ^ k;
                    stack[sp].t = entry[b];
                    stack[sp].child = n->child[b];
                    stack[sp].count = n->count[b];
                    sp++;
                    child = n->child[a];
                    count = n->count[a];
                    continue;
                }
                {
                    wide_entry e[BVH_WIDE_LANES];
                    unsigned c = wide_sorted(n, mask, entry, e), j;
                    for (j = c; j-- > 1;)
                        stack[sp++] = e[j];
                    child = e[0].child;
                    count = e[0].count;
                    continue;
                }
            }
        } else if (!(count & BVH_WIDE_MIXED)) {
            double t[2 * BVH_WIDE_LANES];
            unsigned mask = lane_spheres(wide, child, count, &r, t_min, t);
            cost->prim_tests += count;
            while (mask) {
                unsigned k = (unsigned)__builtin_ctz(mask);
                uint32_t id = wide->ids[child + k];
                mask &= mask - 1;
                if (t[k] < t_max &&
                    (t[k] < *best_t || (t[k] == *best_t && id < *best_id))) {
                    *best_t = t[k];
                    *best_id = id;
                }
            }
        } else {
            /* bvh.c's test_leaf */
            uint32_t k, n = count & BVH_WIDE_COUNT;
            for (k = 0; k < n; k++) {
                uint32_t id = wide->ids[child + k];
                double hi =
                    *best_t < t_max ? nextafter(*best_t, INFINITY) : t_max;
                double t = test(context, id, ray, t_min, hi);
                cost->prim_tests++;
                if (t < *best_t ||
                    (t == *best_t && t < INFINITY && id < *best_id)) {
                    *best_t = t;
                    *best_id = id;
                }
            }
        }
        for (;;) {
            if (sp == 0)
                return;
            sp--;
            if (stack[sp].t <= bvh_reach(*best_t))
                break;
        }
        child = stack[sp].child;
        count = stack[sp].count;
    }
}

int WIDE_ANY(const struct bvh_wide *wide, const rayo_ray *ray, double t_min,
             double t_max, uint32_t skip, rayo_bvh_prim_fn test,
             const void *context, rayo_bvh_cost *cost)
{
    wide_entry stack[BVH_WIDE_STACK];
    size_t sp = 0;
    lane_ray r;
    uint32_t child = 0, count = 0;
    lane_ray_init(&r, ray);
    for (;;) {
        if (count == 0) {
            const bvh_wide_node *n = &wide->nodes[child];
            double entry[BVH_WIDE_LANES];
            unsigned mask =
                lane_boxes(n, &r, t_min, t_max, entry) & n->lanes;
            cost->node_tests += n->lane_count;
            if (mask != 0) {
                unsigned k = (unsigned)__builtin_ctz(mask);
                mask &= mask - 1;
                child = n->child[k];
                count = n->count[k];
                while (mask) {
                    unsigned j = 31u - (unsigned)__builtin_clz(mask);
                    mask &= ~(1u << j);
                    stack[sp].child = n->child[j];
                    stack[sp].count = n->count[j];
                    sp++;
                }
                continue;
            }
        } else if (!(count & BVH_WIDE_MIXED)) {
            double t[2 * BVH_WIDE_LANES];
            unsigned mask = lane_spheres(wide, child, count, &r, t_min, t);
            cost->prim_tests += count;
            while (mask) {
                unsigned k = (unsigned)__builtin_ctz(mask);
                mask &= mask - 1;
                if (t[k] < t_max && wide->ids[child + k] != skip)
                    return 1;
            }
        } else {
            uint32_t k, n = count & BVH_WIDE_COUNT;
            for (k = 0; k < n; k++) {
                cost->prim_tests++;
                if (test(context, wide->ids[child + k], ray, t_min, t_max) <
                    INFINITY)
                    return 1;
            }
        }
        if (sp == 0)
            return 0;
        sp--;
        child = stack[sp].child;
        count = stack[sp].count;
    }
}
