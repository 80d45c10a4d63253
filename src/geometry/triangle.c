/*
 * triangle.c - watertight ray-triangle intersection, the triangle's
 * normal and its validity test.
 *
 * The test is the one of Woop, Benthin and Wald ("Watertight
 * Ray/Triangle Intersection", JCGT 2013), in double precision: the
 * corners moved into a frame where the ray runs along +z from the origin,
 * and the ray meets the triangle where three 2-D edge functions have one
 * sign (zero counts as either: edges and corners are inside).  No ray
 * slips between two triangles that share an edge (why: below).
 */
#include "rayo/triangle.h"

#include <math.h>

/*
 * The frame is a permutation of the axes and a shear; the edge functions
 * are
 *     u = c_x b_y - c_y b_x,  v = a_x c_y - a_y c_x,  w = b_x a_y - b_y a_x.
 * Why no ray slips between two triangles that share an edge: a corner's
 * sheared coordinates depend only on the corner and the ray, so both
 * triangles see the same numbers; the edge function of a shared edge is
 * the same difference of two products with its terms swapped, which IEEE
 * arithmetic negates exactly; and its sign is exact (see edge_function).
 * So a ray through the shared edge is inside or on the edge for at least
 * one of the two.
 */

/* Component k (0, 1, 2 for x, y, z) of v. */
static double axis(rayo_vec3 v, int k)
{
    return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

/*
 * p q - r s with the sign of the exact value.  Rounding is monotonic, so
 * round(p q) > round(r s) implies p q > r s: a nonzero difference of the
 * rounded products has the right sign.  When they round to the same
 * number, the exact difference is that of their rounding errors, which
 * fma gives exactly.  Swapping (p, q) with (r, s) negates the result
 * exactly, whichever branch is taken.
 */
static double edge_function(double p, double q, double r, double s)
{
    double pq = p * q, rs = r * s;
    if (pq != rs)
        return pq - rs;
    return fma(p, q, -pq) - fma(r, s, -rs);
}

double rayo_triangle_intersect(const rayo_triangle *tri, const rayo_ray *ray,
                               double t_min, double t_max)
{
    rayo_vec3 d = ray->direction;
    rayo_vec3 ra = rayo_vec3_sub(tri->a, ray->origin);
    rayo_vec3 rb = rayo_vec3_sub(tri->b, ray->origin);
    rayo_vec3 rc = rayo_vec3_sub(tri->c, ray->origin);
    double adx = fabs(d.x), ady = fabs(d.y), adz = fabs(d.z);
    int kz = adx > ady ? (adx > adz ? 0 : 2) : (ady > adz ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    double dz, sx, sy, sz, ax, ay, bx, by, cx, cy, u, v, w, det, t;
    if (axis(d, kz) < 0.0) { /* keep the frame right-handed */
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    dz = axis(d, kz);
    if (dz == 0.0)
        return INFINITY; /* no direction at all */
    sx = axis(d, kx) / dz;
    sy = axis(d, ky) / dz;
    sz = 1.0 / dz;
    ax = axis(ra, kx) - sx * axis(ra, kz);
    ay = axis(ra, ky) - sy * axis(ra, kz);
    bx = axis(rb, kx) - sx * axis(rb, kz);
    by = axis(rb, ky) - sy * axis(rb, kz);
    cx = axis(rc, kx) - sx * axis(rc, kz);
    cy = axis(rc, ky) - sy * axis(rc, kz);
    u = edge_function(cx, by, cy, bx);
    v = edge_function(ax, cy, ay, cx);
    w = edge_function(bx, ay, by, ax);
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0))
        return INFINITY;
    det = u + v + w;
    if (det == 0.0 || !isfinite(det))
        return INFINITY; /* seen edge-on, or beyond double range */
    t = (u * sz * axis(ra, kz) + v * sz * axis(rb, kz) +
         w * sz * axis(rc, kz)) /
        det;
    if (!(t > t_min && t < t_max))
        return INFINITY;
    return t;
}

rayo_vec3 rayo_triangle_normal(const rayo_triangle *tri)
{
    return rayo_vec3_normalize(rayo_vec3_cross(
        rayo_vec3_sub(tri->b, tri->a), rayo_vec3_sub(tri->c, tri->a)));
}

int rayo_triangle_is_valid(const rayo_triangle *tri)
{
    rayo_vec3 e1 = rayo_vec3_sub(tri->b, tri->a);
    rayo_vec3 e2 = rayo_vec3_sub(tri->c, tri->a);
    double l1 = rayo_vec3_length(e1), l2 = rayo_vec3_length(e2);
    double area2 = rayo_vec3_length(rayo_vec3_cross(e1, e2));
    if (!rayo_vec3_is_finite(tri->a) || !rayo_vec3_is_finite(tri->b) ||
        !rayo_vec3_is_finite(tri->c))
        return 0;
    if (!isfinite(l1) || !isfinite(l2) || !isfinite(area2))
        return 0;
    return area2 > 1e-12 * l1 * l2;
}
