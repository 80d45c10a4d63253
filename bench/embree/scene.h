/*
 * scene.h - the Embree program's view of a scene file (bench/embree/):
 * the subset bench/field_scene.py writes, as the program needs it (the
 * camera's settings, the first point light, planes, and the spheres as
 * Embree's float4 vertices), and the double vector arithmetic rayo's
 * camera is computed in.  scene.c reads it.
 */
#ifndef EMBREE_RAYS_SCENE_H
#define EMBREE_RAYS_SCENE_H

#include <math.h>
#include <stddef.h>

#define MAX_PLANES 64

typedef struct vec3 {
    double x, y, z;
} vec3;

typedef struct scene {
    unsigned width, height;
    double fov;
    vec3 origin, look_at, up;
    int aimed;
    int has_light;
    vec3 light;
    size_t sphere_count, sphere_cap;
    float *spheres; /* x, y, z, r */
    size_t plane_count;
    vec3 plane_point[MAX_PLANES], plane_normal[MAX_PLANES];
} scene;

static inline vec3 v3(double x, double y, double z)
{
    vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}
static inline vec3 add(vec3 a, vec3 b)
{
    return v3(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline vec3 sub(vec3 a, vec3 b)
{
    return v3(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline vec3 scale(vec3 a, double s)
{
    return v3(a.x * s, a.y * s, a.z * s);
}
static inline double dot(vec3 a, vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
static inline vec3 cross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
              a.x * b.y - a.y * b.x);
}
static inline vec3 normalize(vec3 a)
{
    return scale(a, 1.0 / sqrt(dot(a, a)));
}

/*
 * Reads path into *s.  Bad input: one line on stderr naming the file and
 * line, exit 2; I/O failures: the file and strerror, exit 1 (this is a
 * benchmark tool, not the library: it may exit).
 */
void read_scene(const char *path, scene *s);

#endif
