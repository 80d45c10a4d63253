/*
 * plane.h - the infinite plane and its ray intersection.
 *
 * A plane is a point P0 on it and a unit normal n.  The ray o + t d meets
 * it where (o + t d - P0).n = 0, that is t = (P0 - o).n / (d.n); a ray
 * parallel to the plane (d.n == 0) never meets it, even when it lies in
 * it.  Planes are unbounded, so the scene keeps them outside its
 * bounding volume hierarchy.  This file knows nothing of pixels or of
 * materials.
 */
#ifndef RAYO_PLANE_H
#define RAYO_PLANE_H

#include "rayo/export.h"
#include "rayo/ray.h"

typedef struct rayo_plane {
    rayo_vec3 point;  /* any point of the plane */
    rayo_vec3 normal; /* unit length */
} rayo_plane;

/*
 * The t with t_min < t < t_max at which the ray meets the plane, or
 * INFINITY when there is none (parallel ray, or the crossing lies outside
 * the interval).
 */
RAYO_API double rayo_plane_intersect(const rayo_plane *plane,
                                     const rayo_ray *ray, double t_min,
                                     double t_max);

/* The plane's normal turned to face the ray (so that n.d <= 0). */
RAYO_API rayo_vec3 rayo_plane_facing_normal(const rayo_plane *plane,
                                            const rayo_ray *ray);

#endif
