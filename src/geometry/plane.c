/*
 * plane.c - ray-plane intersection (the formula is in plane.h).
 *
 * Only the arithmetic of one plane; which side is lit, which plane is
 * nearest and what colour it has are the scene's and the shading's
 * business.
 */
#include "rayo/plane.h"

double rayo_plane_intersect(const rayo_plane *plane, const rayo_ray *ray,
                            double t_min, double t_max)
{
    double denom = rayo_vec3_dot(ray->direction, plane->normal);
    double t;
    if (denom == 0.0)
        return INFINITY;
    t = rayo_vec3_dot(rayo_vec3_sub(plane->point, ray->origin),
                      plane->normal) /
        denom;
    if (!(t > t_min && t < t_max))
        return INFINITY;
    return t;
}

rayo_vec3 rayo_plane_facing_normal(const rayo_plane *plane,
                                   const rayo_ray *ray)
{
    if (rayo_vec3_dot(ray->direction, plane->normal) > 0.0)
        return rayo_vec3_scale(plane->normal, -1.0);
    return plane->normal;
}
