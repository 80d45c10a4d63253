/*
 * scene_random.h - seeded random scenes of many spheres, for benchmarks
 * and for testing the bounding volume hierarchy against brute force.
 *
 * The numbers come from a 64-bit linear congruential generator
 * (x' = 6364136223846793005 x + 1442695040888963407 mod 2^64, Knuth's
 * MMIX constants), whose top 53 bits make a double in [0, 1): the same
 * seed gives the same scene on every machine.  Not for anything that
 * needs good randomness.
 */
#ifndef RAYO_SCENE_RANDOM_H
#define RAYO_SCENE_RANDOM_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/scene.h"
#include "rayo/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The generator's state; any value is a valid seed. */
typedef struct rayo_lcg {
    uint64_t state;
} rayo_lcg;

void rayo_lcg_seed(rayo_lcg *lcg, uint64_t seed);

/* The next number, uniform in [0, 1). */
double rayo_lcg_next(rayo_lcg *lcg);

/*
 * Adds 8 coloured materials and `count` spheres to scene, drawn from
 * seed.  Each sphere, in turn: z uniform in [10, 100], x uniform in
 * [-z, z], y uniform in [-0.5625 z, 0.5625 z] (so centres fill the view
 * of the default camera at the origin looking down +z, 90 degrees, 16:9),
 * radius z * s * u with u uniform in [0.001, 0.0035] and
 * s = sqrt(100000 / count), so that spheres cover about the same part of
 * the picture (roughly half) whatever their number; materials in turn.
 * RAYO_ERR_LIMIT when the scene would pass RAYO_MAX_OBJECTS.
 */
rayo_status rayo_scene_random_spheres(rayo_scene *scene, size_t count,
                                      uint64_t seed, rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
