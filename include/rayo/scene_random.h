/*
 * scene_random.h - seeded random scenes of many spheres, for benchmarks
 * and for testing the bounding volume hierarchy against brute force.
 *
 * The numbers come from a 64-bit linear congruential generator (Knuth's
 * MMIX constants), whose top 53 bits make a double in [0, 1): the same
 * seed gives the same scene on every machine.  Both layouts scale the
 * radii with the count, so that a scene of ten and a scene of 100000 are
 * the same picture in coarse and fine grain, and their times per pixel
 * can be compared.  Not for anything that needs good randomness.
 */
#ifndef RAYO_SCENE_RANDOM_H
#define RAYO_SCENE_RANDOM_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/export.h"
#include "rayo/scene.h"
#include "rayo/status.h"

/*
 * The generator: x' = 6364136223846793005 x + 1442695040888963407 mod
 * 2^64.  10 or 100000 spheres cover about the same share of the ground
 * (field) or of the default camera's view (cloud).  The default camera
 * (origin, looking down +z) sees the field as a band below the horizon; a
 * camera at (0, 5, -10) looking at (0, -1, 35) sees it fill most of the
 * picture.
 */

#ifdef __cplusplus
extern "C" {
#endif

/* The generator's state; any value is a valid seed. */
typedef struct rayo_lcg {
    uint64_t state;
} rayo_lcg;

RAYO_API void rayo_lcg_seed(rayo_lcg *lcg, uint64_t seed);

/* The next number, uniform in [0, 1). */
RAYO_API double rayo_lcg_next(rayo_lcg *lcg);

/*
 * The benchmark scene: a field of spheres lying on a ground plane, as in
 * most many-object test scenes.  Adds 9 materials (a gray ground and 8
 * colours), the plane y = -1 (object 0, when the scene was empty) and
 * `count` spheres, materials in turn.  Sphere i draws, in this order,
 * x uniform in [-50, 50], z uniform in [5, 105] and u uniform in [0, 1),
 * and gets radius r = 0.3 s (0.5 + 0.5 u) with s = sqrt(10000 / count)
 * (the mean spacing of the centres) and centre (x, r - 1, z): it rests
 * on the ground.  Spheres may overlap.  RAYO_ERR_LIMIT when the scene
 * would pass RAYO_MAX_OBJECTS; RAYO_ERR_INVALID for count 0.
 */
RAYO_API rayo_status rayo_scene_random_spheres(rayo_scene *scene, size_t count,
                                               uint64_t seed, rayo_error *err);

/*
 * The hard case: a cloud of spheres filling the view in depth, so that a
 * ray that misses them all crosses the whole cloud.  Adds 8 coloured
 * materials and `count` spheres, materials in turn; sphere i draws z
 * uniform in [10, 100], x uniform in [-z, z], y uniform in
 * [-0.5625 z, 0.5625 z] and u uniform in [0.001, 0.0035], and gets
 * radius z u sqrt(100000 / count).  About half the picture is covered.
 * Errors as above.
 */
RAYO_API rayo_status rayo_scene_random_cloud(rayo_scene *scene, size_t count,
                                             uint64_t seed, rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
