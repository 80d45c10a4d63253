/*
 * scene_impl.h - the inside of a rayo_scene, shared by the files of
 * src/scene/ only (storage in scene.c, queries in query.c, the
 * hierarchy's construction in prepare.c).
 *
 * Each kind of object has its own array; `objects` maps an object index
 * (insertion order over all kinds) to its kind and its place in that
 * array, and each entry of a kind's array records its object index and
 * material back.
 */
#ifndef RAYO_SCENE_IMPL_H
#define RAYO_SCENE_IMPL_H

#include "rayo/scene.h"

#include <stdint.h>

#include "../accel/bvh.h"

typedef struct scene_sphere {
    rayo_sphere shape;
    uint32_t object;
    uint32_t material;
} scene_sphere;

typedef struct scene_plane {
    rayo_plane shape;
    uint32_t object;
    uint32_t material;
} scene_plane;

typedef struct scene_triangle {
    rayo_triangle shape;
    rayo_vec3 normal; /* unit; the corners' (rayo_triangle_normal) or a
                         mesh file's own */
    uint32_t object;
    uint32_t material;
} scene_triangle;

typedef struct scene_object {
    uint32_t kind; /* rayo_object_kind */
    uint32_t index; /* in the kind's array */
} scene_object;

struct rayo_scene {
    scene_object *objects;
    size_t object_count, object_capacity;
    scene_sphere *spheres;
    size_t sphere_count, sphere_capacity;
    scene_plane *planes;
    size_t plane_count, plane_capacity;
    scene_triangle *triangles;
    size_t triangle_count, triangle_capacity;
    rayo_material *materials;
    size_t material_count, material_capacity;
    rayo_light *lights;
    size_t light_count, light_capacity;
    rayo_vec3 ambient, background;
    int prepared;  /* rayo_scene_prepare ran since the last add */
    rayo_bvh *bvh; /* the hierarchy, when prepared and worth one */
};

/* A triangle's corners and its unit normal: the given one scaled, or
 * the corners' where it is zero (scene.c). */
void scene_triangle_set(scene_triangle *t, const rayo_triangle *shape,
                        rayo_vec3 normal);

/* Room for `more` triangles after the scene's last, and as many objects,
 * exactly (no doubling); fails as adding them one by one would at the
 * first (a bad material, RAYO_MAX_OBJECTS) without adding any, or
 * RAYO_ERR_NOMEM.  (scene.c) */
rayo_status scene_reserve_triangles(rayo_scene *scene, unsigned material,
                                    size_t more, rayo_error *err);

/* Makes objects of the `added` triangles already set (scene_triangle_set)
 * after the scene's last, in room reserved: their object numbers and
 * material, as adding them one by one would.  (scene.c) */
void scene_triangles_added(rayo_scene *scene, size_t added,
                           unsigned material);

/* Up to this many spheres and triangles, testing each beats a tree. */
#define RAYO_SCENE_BRUTE_MAX 12

/*
 * Tests object `object` against the ray; its t with t_min < t < t_max,
 * or INFINITY.
 */
double rayo_scene_object_t(const rayo_scene *scene, uint32_t object,
                           const rayo_ray *ray, double t_min, double t_max);

/*
 * Gives the hierarchy its fast walks' copy (src/accel/bvh_wide.h), with
 * the scene's spheres; called by rayo_scene_prepare once the tree is
 * built, on up to `threads` threads.  Without memory it makes none:
 * queries then walk the binary tree, with the same answers.  (query.c)
 */
void rayo_scene_prepare_walks(rayo_scene *scene, unsigned threads);

#endif
