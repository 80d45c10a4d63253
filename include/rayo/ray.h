/*
 * ray.h - a half-line r(t) = origin + t * direction, t >= 0.
 *
 * Directions handed out by the camera are unit vectors, as the assignment
 * assumes (a = d.d = 1 in its quadratic); shapes rely on that.
 */
#ifndef RAYO_RAY_H
#define RAYO_RAY_H

#include "rayo/vec3.h"

typedef struct rayo_ray {
    rayo_vec3 origin;
    rayo_vec3 direction; /* unit length */
} rayo_ray;

static inline rayo_vec3 rayo_ray_at(const rayo_ray *ray, double t)
{
    return rayo_vec3_add(ray->origin, rayo_vec3_scale(ray->direction, t));
}

#endif
