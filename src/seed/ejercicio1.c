/*
 * ejercicio1.c - the assignment's three functions, written on top of the
 * general library so that they and `rayo` can never disagree.
 *
 * intersecta_esfera uses the full test of the assignment's note (smallest
 * t > 0), which for the assignment's sphere, in front of the origin, is
 * the same as its simplified (C.d)^2 - C.C + R^2 >= 0.
 */
#include "rayo/ejercicio1.h"

#include "rayo/seed.h"
#include "rayo/sphere.h"

float producto_interno(float x1, float y1, float z1, float x2, float y2,
                       float z2)
{
    return (float)rayo_vec3_dot(rayo_vec3_make(x1, y1, z1),
                                rayo_vec3_make(x2, y2, z2));
}

float norma(float x, float y, float z)
{
    return (float)rayo_vec3_length(rayo_vec3_make(x, y, z));
}

int intersecta_esfera(float dx, float dy, float dz)
{
    rayo_sphere sphere;
    rayo_ray ray;
    sphere.center = rayo_vec3_make(RAYO_SEED_CENTER_X, RAYO_SEED_CENTER_Y,
                                   RAYO_SEED_CENTER_Z);
    sphere.radius = RAYO_SEED_RADIUS;
    ray.origin = rayo_vec3_make(0, 0, 0);
    ray.direction = rayo_vec3_make(dx, dy, dz);
    return rayo_sphere_hit(&sphere, &ray, 0.0);
}
