/*
 * vec3.h - three-component vectors of doubles, the arithmetic every other
 * layer is written in.
 *
 * Everything here is a static inline function on a small struct passed by
 * value: the compiler keeps the components in registers, and the header
 * stays valid C99 for code built with the course's flags.  Doubles, not
 * floats: the library computes in double precision and the assignment's
 * float API (ejercicio1.h) is a thin layer on top.
 */
#ifndef RAYO_VEC3_H
#define RAYO_VEC3_H

#include <math.h>

typedef struct rayo_vec3 {
    double x, y, z;
} rayo_vec3;

static inline rayo_vec3 rayo_vec3_make(double x, double y, double z)
{
    rayo_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static inline rayo_vec3 rayo_vec3_add(rayo_vec3 a, rayo_vec3 b)
{
    return rayo_vec3_make(a.x + b.x, a.y + b.y, a.z + b.z);
}

static inline rayo_vec3 rayo_vec3_sub(rayo_vec3 a, rayo_vec3 b)
{
    return rayo_vec3_make(a.x - b.x, a.y - b.y, a.z - b.z);
}

static inline rayo_vec3 rayo_vec3_scale(rayo_vec3 a, double s)
{
    return rayo_vec3_make(a.x * s, a.y * s, a.z * s);
}

/* Component-by-component product (colours: C ⊙ M). */
static inline rayo_vec3 rayo_vec3_mul(rayo_vec3 a, rayo_vec3 b)
{
    return rayo_vec3_make(a.x * b.x, a.y * b.y, a.z * b.z);
}

static inline double rayo_vec3_dot(rayo_vec3 a, rayo_vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static inline rayo_vec3 rayo_vec3_cross(rayo_vec3 a, rayo_vec3 b)
{
    return rayo_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                          a.x * b.y - a.y * b.x);
}

static inline double rayo_vec3_length(rayo_vec3 a)
{
    return sqrt(rayo_vec3_dot(a, a));
}

/* a / |a|; the caller makes sure a is not the zero vector. */
static inline rayo_vec3 rayo_vec3_normalize(rayo_vec3 a)
{
    double n = rayo_vec3_length(a);
    return rayo_vec3_make(a.x / n, a.y / n, a.z / n);
}

/* 1 when every component is a finite number. */
static inline int rayo_vec3_is_finite(rayo_vec3 a)
{
    return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
}

#endif
