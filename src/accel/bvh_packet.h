/*
 * bvh_packet.h - four coherent rays down the hierarchy at once (a
 * packet): the binary tree's boxes tested for the four rays in the four
 * lanes of an AVX2 register, its spheres (from the wide copy's arrays,
 * bvh_wide_impl.h) likewise; internal to the library.
 *
 * Neighbouring pixels' rays, and their shadow rays towards one light,
 * mostly cross the same nodes, so a packet loads and tests each node once
 * for four rays.  Each ray still gets exactly its own answer (see
 * simd/bvh_packet_avx2.c).  The packet walks exist where the processor has
 * AVX2 and the scene has the wide copy; elsewhere, or when turned off
 * (RAYO_PACKETS=0, or rayo_bvh_packets_set), the callers ask one ray at a
 * time, with the same answers.
 */
#ifndef RAYO_ACCEL_BVH_PACKET_H
#define RAYO_ACCEL_BVH_PACKET_H

#include <stdint.h>

#include "bvh.h"

#define RAYO_BVH_PACKET 4

/* 1 when packet walks run for bvh (AVX2, the wide copy, not off). */
int rayo_bvh_packets_on(const rayo_bvh *bvh);

/* Turns the packet walks off (0) or back on (1) for later queries;
 * RAYO_PACKETS=0 in the environment starts them off.  Not while queries
 * run (tests, the bench). */
void rayo_bvh_packets_set(int on);

/*
 * rayo_bvh_nearest for rays[k], k < RAYO_BVH_PACKET, where bit k of lanes
 * is set, all with t_min and t_max; best_t[k] and best_id[k] as in
 * rayo_bvh_nearest.  Only where rayo_bvh_packets_on.
 */
void rayo_bvh_packet_nearest(const rayo_bvh *bvh, const rayo_ray *rays,
                             unsigned lanes, double t_min, double t_max,
                             rayo_bvh_prim_fn test, const void *context,
                             double *best_t, uint32_t *best_id);

/*
 * rayo_bvh_any for rays[k] with bit k of lanes, within (t_min[k],
 * t_max[k]), never blocked by primitive skip[k] (UINT32_MAX: none; test is
 * not called for it): the bit mask of the blocked rays.  Only where
 * rayo_bvh_packets_on.
 */
unsigned rayo_bvh_packet_any(const rayo_bvh *bvh, const rayo_ray *rays,
                             unsigned lanes, const double *t_min,
                             const double *t_max, const uint32_t *skip,
                             rayo_bvh_prim_fn test, const void *context);

#endif
