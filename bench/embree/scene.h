/*
 * scene.h - the Embree program's view of a scene file (bench/embree/):
 * the subset bench/field_scene.py and bench/scan/scan_mesh.c write, as
 * the program needs it (the camera's settings, the first point light,
 * planes, the spheres as Embree's float4 vertices, and the triangles of
 * `mesh FILE` lines), in rayo's own double vectors (rayo/vec3.h, all
 * inline), so its camera is computed as rayo's is.  scene.c reads it.
 */
#ifndef EMBREE_RAYS_SCENE_H
#define EMBREE_RAYS_SCENE_H

#include <stddef.h>

#include "rayo/vec3.h" /* header-only: the program links no rayo */

#define MAX_PLANES 64

typedef struct scene {
    unsigned width, height;
    double fov;
    rayo_vec3 origin, look_at, up;
    int aimed;
    int has_light;
    rayo_vec3 light;
    size_t sphere_count, sphere_cap;
    float *spheres; /* x, y, z, r */
    size_t triangle_count;
    float *corners; /* 9 a triangle, from the `mesh` lines (mesh.c) */
    size_t plane_count;
    rayo_vec3 plane_point[MAX_PLANES], plane_normal[MAX_PLANES];
} scene;

/*
 * Reads path into *s.  Bad input: one line on stderr naming the file and
 * line, exit 2; I/O failures: the file and strerror, exit 1 (this is a
 * benchmark tool, not the library: it may exit).
 */
void read_scene(const char *path, scene *s);

#endif
