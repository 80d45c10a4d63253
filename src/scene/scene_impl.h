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

/*
 * Room for `more` spheres (and objects) after the scene's last: the next
 * `more` scene_put_sphere calls need no memory.  Drops the hierarchy, as
 * any add.  RAYO_ERR_LIMIT when the scene would have more than
 * RAYO_MAX_OBJECTS objects (nothing changed then); RAYO_ERR_NOMEM.
 * (scene.c)
 */
rayo_status scene_reserve_spheres(rayo_scene *scene, size_t more,
                                  rayo_error *err);

/* rayo_scene_add_sphere_material for a sphere known good (a finite
 * centre, a finite radius > 0, an existing material), into room that
 * scene_reserve_spheres made: what a file's sphere lines read ahead
 * (scene_file_split.c) take. */
static inline void scene_put_sphere(rayo_scene *scene, const double center[3],
                                    double radius, unsigned material)
{
    scene_sphere *s = &scene->spheres[scene->sphere_count];
    scene_object *o = &scene->objects[scene->object_count];
    s->shape.center.x = center[0];
    s->shape.center.y = center[1];
    s->shape.center.z = center[2];
    s->shape.radius = radius;
    s->object = (uint32_t)scene->object_count;
    s->material = material;
    o->kind = (uint32_t)RAYO_OBJECT_SPHERE;
    o->index = (uint32_t)scene->sphere_count;
    scene->sphere_count++;
    scene->object_count++;
}

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
