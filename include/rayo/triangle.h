/*
 * triangle.h - the triangle and its ray intersection (Moller-Trumbore).
 *
 * With edges e1 = b - a and e2 = c - a, a point of the triangle is
 * a + u e1 + v e2 with u >= 0, v >= 0, u + v <= 1.  Solving
 * o + t d = a + u e1 + v e2 by Cramer's rule gives, with p = d x e2,
 * det = e1.p, s = o - a and q = s x e1:
 *     u = s.p / det,   v = d.q / det,   t = e2.q / det.
 * Edges and corners count as inside.  A ray in the triangle's plane
 * (det == 0) never meets it.  This file knows nothing of pixels or of
 * materials; docs/geometry.md works an example through.
 */
#ifndef RAYO_TRIANGLE_H
#define RAYO_TRIANGLE_H

#include "rayo/ray.h"

typedef struct rayo_triangle {
    rayo_vec3 a, b, c; /* corners; not collinear */
} rayo_triangle;

/*
 * The t with t_min < t < t_max at which the ray meets the triangle, or
 * INFINITY when there is none.
 */
double rayo_triangle_intersect(const rayo_triangle *triangle,
                               const rayo_ray *ray, double t_min,
                               double t_max);

/* The unit normal (b - a) x (c - a) / |...|; the corners' winding sets
 * its side. */
rayo_vec3 rayo_triangle_normal(const rayo_triangle *triangle);

/*
 * 1 when the corners span a real triangle: finite, and the sine of the
 * angle between its edges at a above 1e-12 (not collinear, no two
 * corners equal).
 */
int rayo_triangle_is_valid(const rayo_triangle *triangle);

#endif
