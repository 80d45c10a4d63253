/*
 * triangle.c - ray-triangle intersection by the Moller-Trumbore method
 * (derived in triangle.h), the triangle's normal and its validity test.
 *
 * Edges and corners count as inside (u >= 0, v >= 0, u + v <= 1), so a
 * ray through the shared edge of two triangles meets at least one of
 * them up to rounding; this is not a watertight intersector.
 */
#include "rayo/triangle.h"

double rayo_triangle_intersect(const rayo_triangle *tri, const rayo_ray *ray,
                               double t_min, double t_max)
{
    rayo_vec3 e1 = rayo_vec3_sub(tri->b, tri->a);
    rayo_vec3 e2 = rayo_vec3_sub(tri->c, tri->a);
    rayo_vec3 p = rayo_vec3_cross(ray->direction, e2);
    double det = rayo_vec3_dot(e1, p);
    rayo_vec3 s, q;
    double inv, u, v, t;
    if (det == 0.0)
        return INFINITY;
    inv = 1.0 / det;
    s = rayo_vec3_sub(ray->origin, tri->a);
    u = rayo_vec3_dot(s, p) * inv;
    if (!(u >= 0.0 && u <= 1.0))
        return INFINITY;
    q = rayo_vec3_cross(s, e1);
    v = rayo_vec3_dot(ray->direction, q) * inv;
    if (!(v >= 0.0 && u + v <= 1.0))
        return INFINITY;
    t = rayo_vec3_dot(e2, q) * inv;
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
