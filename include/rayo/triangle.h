/*
 * triangle.h - the triangle and its ray intersection.
 *
 * The intersection is watertight (Woop, Benthin and Wald, 2013): a ray
 * never slips between two triangles that share an edge or a corner.
 * Edges and corners count as inside; a triangle seen edge-on is never
 * met.  triangle.c says why it is watertight; docs/geometry.md works an
 * example through.  This file knows nothing of pixels or of materials.
 */
#ifndef RAYO_TRIANGLE_H
#define RAYO_TRIANGLE_H

#include "rayo/export.h"
#include "rayo/ray.h"

typedef struct rayo_triangle {
    rayo_vec3 a, b, c; /* corners; not collinear */
} rayo_triangle;

/*
 * The t with t_min < t < t_max at which the ray meets the triangle, or
 * INFINITY when there is none.
 */
RAYO_API double rayo_triangle_intersect(const rayo_triangle *triangle,
                                        const rayo_ray *ray, double t_min,
                                        double t_max);

/* The unit normal (b - a) x (c - a) / |...|; the corners' winding sets
 * its side. */
RAYO_API rayo_vec3 rayo_triangle_normal(const rayo_triangle *triangle);

/*
 * 1 when the corners span a real triangle: finite, and the sine of the
 * angle between its edges at a above 1e-12 (not collinear, no two
 * corners equal).
 */
RAYO_API int rayo_triangle_is_valid(const rayo_triangle *triangle);

#endif
