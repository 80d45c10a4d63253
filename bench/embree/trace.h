/*
 * trace.h - the Embree program's rays (trace.c): rayo's camera as the
 * program computes it, the job a pass casts (the scene, Embree's scene,
 * the mode) and what it counts, and the two ways to cast them, one ray at
 * a time or in 16-ray packets.  embree_rays.c builds the job and times
 * the passes.
 */
#ifndef EMBREE_RAYS_TRACE_H
#define EMBREE_RAYS_TRACE_H

#include <embree3/rtcore.h>

#include "scene.h"

/* The camera of camera.h: focal distance and orthonormal basis. */
typedef struct camera {
    rayo_vec3 origin, right, up, forward;
    double focal;
} camera;

typedef struct pass {
    unsigned long long rays, hits, lit;
} pass;

typedef struct job {
    const scene *s;
    camera cam;
    RTCScene es;
    int shadow, packet, planes_first;
    float plane_n[MAX_PLANES][3], plane_d[MAX_PLANES]; /* n.x = d */
    unsigned char *mask; /* w x h, 1 where the primary ray hit; or NULL */
} job;

/* rayo_camera_ray: the direction through pixel (i, j). */
rayo_vec3 pixel_direction(const camera *c, const scene *s, unsigned i,
                          unsigned j);

/* One pass over every pixel: single rays (rtcIntersect1/rtcOccluded1) or
 * 4x4 tiles of 16-ray packets, counted into *out. */
void trace_single(const job *jb, pass *out);
void trace_packets(const job *jb, pass *out);

#endif
