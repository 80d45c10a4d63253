/*
 * sphere.h - the ray-sphere intersection of the assignment, in general form.
 *
 * The assignment's note derives it: with a unit direction d and
 * L = C - O, beta = L.d and delta = beta^2 - L.L + R^2; the ray meets the
 * sphere when delta >= 0, at t = beta - sqrt(delta) if that is ahead of the
 * origin, else at t = beta + sqrt(delta), and not at all when both are
 * behind.  So a sphere behind the camera is not drawn and a camera inside
 * a sphere sees its inner wall.  This file knows nothing of pixels.
 */
#ifndef RAYO_SPHERE_H
#define RAYO_SPHERE_H

#include "rayo/ray.h"

typedef struct rayo_sphere {
    rayo_vec3 center;
    double radius; /* > 0 */
} rayo_sphere;

/*
 * The smallest t > t_min at which ray (unit direction) meets sphere, or
 * INFINITY when there is none.  t_min = 0 gives the assignment's test.
 * A tangent ray (delta == 0) counts as a hit, as in the assignment's >= 0.
 */
static inline double rayo_sphere_intersect(const rayo_sphere *sphere,
                                           const rayo_ray *ray, double t_min)
{
    rayo_vec3 l = rayo_vec3_sub(sphere->center, ray->origin);
    double beta = rayo_vec3_dot(l, ray->direction);
    double delta = beta * beta - rayo_vec3_dot(l, l) +
                   sphere->radius * sphere->radius;
    double root;
    if (!(delta >= 0.0))
        return INFINITY;
    root = sqrt(delta);
    if (beta - root > t_min)
        return beta - root;
    if (beta + root > t_min)
        return beta + root;
    return INFINITY;
}

/* 1 when the ray meets the sphere at some t > t_min. */
static inline int rayo_sphere_hit(const rayo_sphere *sphere,
                                  const rayo_ray *ray, double t_min)
{
    return rayo_sphere_intersect(sphere, ray, t_min) < INFINITY;
}

#endif
