/*
 * query_packet.h - the scene's questions (query.c) for up to four rays at
 * once, for the renderer's neighbouring pixels and their shadow rays;
 * internal to the library.
 *
 * The answers are, ray by ray, those of rayo_scene_intersect and
 * rayo_scene_occluded: where the packet walks run (src/accel/bvh_packet.h)
 * the rays share the walk down the hierarchy, elsewhere they are asked one
 * by one.
 */
#ifndef RAYO_SCENE_QUERY_PACKET_H
#define RAYO_SCENE_QUERY_PACKET_H

#include <stddef.h>

#include "rayo/scene.h"

#define RAYO_SCENE_PACKET 4

/*
 * rayo_scene_intersect(scene, &rays[k], t_min, INFINITY, &hits[k]) for
 * each k < count (count <= RAYO_SCENE_PACKET): the bit mask of the rays
 * that hit.
 */
unsigned rayo_scene_intersect_packet(const rayo_scene *scene,
                                     const rayo_ray *rays, unsigned count,
                                     double t_min, rayo_hit *hits);

/*
 * rayo_scene_occluded(scene, &rays[k], t_min[k], t_max[k], skip[k]) for
 * each k whose bit is set in lanes: the bit mask of the blocked rays.
 */
unsigned rayo_scene_occluded_packet(const rayo_scene *scene,
                                    const rayo_ray *rays, unsigned lanes,
                                    const double *t_min, const double *t_max,
                                    const size_t *skip);

#endif
