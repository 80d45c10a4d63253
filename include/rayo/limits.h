/*
 * limits.h - the largest things rayo agrees to make or read.
 *
 * Every reader and every allocation checks against these before it asks
 * for memory, so a hostile header cannot make rayo allocate gigabytes.
 * They are documented in docs/limits.md and in the man page.
 */
#ifndef RAYO_LIMITS_H
#define RAYO_LIMITS_H

/* Largest width or height of any image, in pixels. */
#define RAYO_MAX_DIMENSION 65536u

/* Largest number of pixels in one image (2^30). */
#define RAYO_MAX_PIXELS (1ul << 30)

/* Largest number of objects in one scene. */
#define RAYO_MAX_OBJECTS (1ul << 24)

/* Largest number of materials and of lights in one scene. */
#define RAYO_MAX_MATERIALS (1ul << 20)
#define RAYO_MAX_LIGHTS 4096ul

/* Largest number of rendering threads. */
#define RAYO_MAX_THREADS 256u

#endif
