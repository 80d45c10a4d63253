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

/*
 * Largest image file the readers read, in bytes (8 GiB: above the raw
 * raster of the largest image, 2^30 pixels of 16-bit RGB).  A regular
 * file is refused before a byte is read; a pipe once it has delivered
 * more, so endless input (trailing bytes, comments) cannot hang rayo.
 */
#define RAYO_MAX_INPUT_BYTES (1ull << 33)

/* Largest number of objects in one scene. */
#define RAYO_MAX_OBJECTS (1ul << 24)

/* Largest number of materials and of lights in one scene. */
#define RAYO_MAX_MATERIALS (1ul << 20)
#define RAYO_MAX_LIGHTS 4096ul

/* Largest number of rendering threads. */
#define RAYO_MAX_THREADS 256u

#endif
