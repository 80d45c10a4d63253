/*
 * scene.h - what the rays can hit, what it is made of, and what lights it.
 *
 * A scene owns its objects (spheres, planes, triangles), its materials and
 * its lights, plus an ambient light and a background colour.  It answers
 * the renderer's two questions: what does this ray meet first (with the
 * point, normal, object and material), and is anything in the way (shadow
 * rays).  It knows nothing of pixels, cameras or shading formulas.
 *
 * Its life cycle, when it builds a hierarchy, and the conventions the
 * shading code relies on are said after the includes.
 */
#ifndef RAYO_SCENE_H
#define RAYO_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/export.h"
#include "rayo/plane.h"
#include "rayo/ray.h"
#include "rayo/sphere.h"
#include "rayo/status.h"
#include "rayo/mesh.h"
#include "rayo/triangle.h"

/*
 * Life cycle: create, add everything, rayo_scene_prepare (builds the
 * bounding volume hierarchy), then query from any number of threads.
 * Queries never modify the scene.  A scene that was never prepared, or
 * that had an add after its last prepare (an add drops the hierarchy),
 * answers every query by testing every object in turn: correct, slow on
 * big scenes.  Benchmarks compare the two this way.
 *
 * Scenes of at most 12 spheres and triangles get no hierarchy (testing
 * each is faster) but count as prepared.  docs/geometry.md explains the
 * shapes' arithmetic and the hierarchy.
 *
 * Conventions (the shading code relies on these):
 *   - object indices count every object in insertion order, whatever its
 *     kind: the first sphere, plane or triangle added is object 0;
 *   - material 0 exists in every scene: white, ka = kd = 1, ks = 0,
 *     shininess 0, reflectivity 0; rayo_scene_add_sphere uses it;
 *   - a hit's normal is unit length: for a sphere the outward normal
 *     (P - C) / R, even when the ray starts inside; for a plane or a
 *     triangle the side facing the ray (normal . direction <= 0);
 *   - t ranges are open: t_min < t < t_max; pass INFINITY for no bound.
 */

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rayo_scene rayo_scene;

typedef struct rayo_material {
    rayo_vec3 color;     /* M, RGB, each in [0, 1] */
    double ka, kd, ks;   /* ambient, diffuse, specular; finite, >= 0 */
    double shininess;    /* Phong exponent; finite, >= 0 */
    double reflectivity; /* mirror reflection, in [0, 1] */
} rayo_material;

typedef enum rayo_light_kind {
    RAYO_LIGHT_DIRECTIONAL,
    RAYO_LIGHT_POINT
} rayo_light_kind;

typedef struct rayo_light {
    rayo_light_kind kind;
    /* directional: direction TOWARDS the light (stored normalised);
     * point: the light's position */
    rayo_vec3 vector;
    rayo_vec3 color; /* intensity per channel; finite, >= 0 (may be > 1) */
} rayo_light;

typedef enum rayo_object_kind {
    RAYO_OBJECT_SPHERE,
    RAYO_OBJECT_PLANE,
    RAYO_OBJECT_TRIANGLE
} rayo_object_kind;

typedef struct rayo_hit {
    double t;
    rayo_vec3 point;  /* ray origin + t * direction */
    rayo_vec3 normal; /* unit; see the conventions above */
    size_t object;    /* index over all objects, in insertion order */
    unsigned material;
} rayo_hit;

/* Counters a query adds to (rayo_scene_intersect_counted). */
typedef struct rayo_scene_stats {
    uint64_t rays;       /* queries answered */
    uint64_t node_tests; /* ray-box tests against hierarchy nodes */
    uint64_t prim_tests; /* ray-object intersection tests */
} rayo_scene_stats;

/* Passed as `skip` when no object is to be ignored. */
#define RAYO_NO_OBJECT ((size_t)-1)

RAYO_API rayo_status rayo_scene_create(rayo_scene **scene, rayo_error *err);

/* Frees the scene and everything in it; NULL is allowed. */
RAYO_API void rayo_scene_free(rayo_scene *scene);

/*
 * Adds a material; *id receives its number (the first added is 1).
 * RAYO_ERR_INVALID names the first field out of range; RAYO_ERR_LIMIT
 * past RAYO_MAX_MATERIALS.
 */
RAYO_API rayo_status rayo_scene_add_material(rayo_scene *scene,
                                             const rayo_material *material,
                                             unsigned *id, rayo_error *err);

/*
 * Adds a sphere with material 0.  RAYO_ERR_INVALID when the centre is not
 * finite or the radius is not a finite number > 0; RAYO_ERR_LIMIT past
 * RAYO_MAX_OBJECTS.
 */
RAYO_API rayo_status rayo_scene_add_sphere(rayo_scene *scene, rayo_vec3 center,
                                           double radius, rayo_error *err);

/* The same with a material; RAYO_ERR_INVALID for an unknown material. */
RAYO_API rayo_status rayo_scene_add_sphere_material(rayo_scene *scene,
                                                    rayo_vec3 center,
                                                    double radius,
                                                    unsigned material,
                                                    rayo_error *err);

/*
 * Adds count spheres in order, as count calls of
 * rayo_scene_add_sphere_material would (spheres[i] with materials[i], or
 * material 0 for all when materials is NULL), but all or none: when one
 * would be refused, or would pass RAYO_MAX_OBJECTS, nothing is added and
 * the status and message are those rayo_scene_add_sphere_material gives
 * for the first refused.  Room is made once for the whole batch: what a
 * reader of large scene files uses.
 */
RAYO_API rayo_status rayo_scene_add_spheres(rayo_scene *scene,
                                            const rayo_sphere *spheres,
                                            const unsigned *materials,
                                            size_t count, rayo_error *err);

/*
 * Adds the plane through point with the given normal (any non-zero
 * finite length; stored normalised).
 */
RAYO_API rayo_status rayo_scene_add_plane(rayo_scene *scene, rayo_vec3 point,
                                          rayo_vec3 normal, unsigned material,
                                          rayo_error *err);

/* Adds a triangle; RAYO_ERR_INVALID when its corners are collinear.
 * It is shaded with its corners' normal (rayo_triangle_normal). */
RAYO_API rayo_status rayo_scene_add_triangle(rayo_scene *scene, rayo_vec3 a,
                                             rayo_vec3 b, rayo_vec3 c,
                                             unsigned material,
                                             rayo_error *err);

/*
 * The same, shaded with the given normal (any finite length, stored
 * normalised; turned towards the ray as every triangle's), as a mesh
 * file's facet normal asks; a zero normal means the corners'.
 */
RAYO_API rayo_status rayo_scene_add_triangle_normal(rayo_scene *scene,
                                                    rayo_vec3 a, rayo_vec3 b,
                                                    rayo_vec3 c,
                                                    rayo_vec3 normal,
                                                    unsigned material,
                                                    rayo_error *err);

/* Where a mesh goes: scaled about the origin, rotated about x, then y,
 * then z (degrees), then moved. */
typedef struct rayo_mesh_placement {
    double scale;          /* > 0; 1 */
    rayo_vec3 rotate;      /* degrees; 0, 0, 0 */
    rayo_vec3 translate;   /* 0, 0, 0 */
    int computed_normals;  /* 1: shade with the corners' normals, not the
                              file's; 0 */
} rayo_mesh_placement;

/* The defaults above. */
RAYO_API void rayo_mesh_placement_init(rayo_mesh_placement *placement);

/*
 * Adds every triangle of mesh, placed, in material, shaded with the
 * file's normal (turned with the mesh) unless computed_normals or the
 * file gives none or a zero one.  Triangles whose placed corners are on
 * one line are left out and counted in *left_out (may be NULL).
 * RAYO_ERR_INVALID for a placement that is not finite or a scale <= 0;
 * RAYO_ERR_LIMIT past RAYO_MAX_OBJECTS objects (the triangles added so
 * far stay).
 */
RAYO_API rayo_status rayo_scene_add_mesh(rayo_scene *scene,
                                         const rayo_mesh *mesh,
                                         const rayo_mesh_placement *placement,
                                         unsigned material, size_t *left_out,
                                         rayo_error *err);

/* The same, placing the triangles on up to `threads` threads (0: one a
 * CPU); the scene is the same for any number. */
RAYO_API rayo_status rayo_scene_add_mesh_threads(
    rayo_scene *scene, const rayo_mesh *mesh,
    const rayo_mesh_placement *placement, unsigned material,
    unsigned threads, size_t *left_out, rayo_error *err);

/*
 * Adds a light.  RAYO_ERR_INVALID for an unknown kind, a non-finite
 * vector, a zero direction, or a negative or non-finite colour;
 * RAYO_ERR_LIMIT past RAYO_MAX_LIGHTS.
 */
RAYO_API rayo_status rayo_scene_add_light(rayo_scene *scene,
                                          const rayo_light *light,
                                          rayo_error *err);

/* Ambient light (default 0, 0, 0) and background colour (default black);
 * the caller validates the values. */
RAYO_API void rayo_scene_set_ambient(rayo_scene *scene, rayo_vec3 ambient);
RAYO_API rayo_vec3 rayo_scene_ambient(const rayo_scene *scene);
RAYO_API void rayo_scene_set_background(rayo_scene *scene, rayo_vec3 colour);
RAYO_API rayo_vec3 rayo_scene_background(const rayo_scene *scene);

RAYO_API size_t rayo_scene_object_count(const rayo_scene *scene);
RAYO_API rayo_object_kind rayo_scene_object_kind(const rayo_scene *scene,
                                                 size_t i);
RAYO_API size_t rayo_scene_sphere_count(const rayo_scene *scene);
/* The i-th sphere added (counting spheres only), i < sphere count. */
RAYO_API const rayo_sphere *rayo_scene_sphere(const rayo_scene *scene,
                                              size_t i);

RAYO_API size_t rayo_scene_light_count(const rayo_scene *scene);
RAYO_API const rayo_light *rayo_scene_light(const rayo_scene *scene, size_t i);
/* Number of materials, material 0 included (so at least 1). */
RAYO_API size_t rayo_scene_material_count(const rayo_scene *scene);
/* Material id; NULL when id >= rayo_scene_material_count(). */
RAYO_API const rayo_material *rayo_scene_material(const rayo_scene *scene,
                                                  unsigned id);

/*
 * Builds the bounding volume hierarchy over the spheres and triangles
 * (planes stay outside it).  Call after the last add and before
 * rendering; calling it again rebuilds.  RAYO_ERR_NOMEM on failure, and
 * the scene then keeps answering by brute force.
 */
RAYO_API rayo_status rayo_scene_prepare(rayo_scene *scene, rayo_error *err);

/*
 * The same on at most threads threads (0: one per CPU, as
 * rayo_scene_prepare; 1: the caller's alone).  The hierarchy is the same
 * for any number of threads, so renders are too.
 */
RAYO_API rayo_status rayo_scene_prepare_threads(rayo_scene *scene,
                                                unsigned threads,
                                                rayo_error *err);

/* 1 when rayo_scene_prepare ran after the last add. */
RAYO_API int rayo_scene_is_prepared(const rayo_scene *scene);

/*
 * The nearest hit with t_min < t < t_max, written to *hit; returns 1 if
 * there is one, else 0 (and *hit is left alone).  Ties in t go to the
 * lowest object index.  Sphere hits use rayo_sphere_intersect.
 */
RAYO_API int rayo_scene_intersect(const rayo_scene *scene, const rayo_ray *ray,
                                  double t_min, double t_max, rayo_hit *hit);

/* The same, adding to *stats (never NULL) what the query cost. */
RAYO_API int rayo_scene_intersect_counted(const rayo_scene *scene,
                                          const rayo_ray *ray, double t_min,
                                          double t_max, rayo_hit *hit,
                                          rayo_scene_stats *stats);

/*
 * 1 when some object other than `skip` (RAYO_NO_OBJECT for none) is met
 * with t_min < t < t_max: the shadow-ray test ("no OTHER sphere lies on
 * the ray from P towards L": skip the object P lies on, t_max = INFINITY
 * for a directional light, the distance to a point light otherwise).
 * Stops at the first object found.
 */
RAYO_API int rayo_scene_occluded(const rayo_scene *scene, const rayo_ray *ray,
                                 double t_min, double t_max, size_t skip);

/* The same, adding to *stats (never NULL). */
RAYO_API int rayo_scene_occluded_counted(const rayo_scene *scene,
                                         const rayo_ray *ray, double t_min,
                                         double t_max, size_t skip,
                                         rayo_scene_stats *stats);

/*
 * 1 when the ray (unit direction) meets some object at t > t_min: the
 * assignment's hit test, rayo_scene_occluded(scene, ray, t_min,
 * INFINITY, RAYO_NO_OBJECT).
 */
RAYO_API int rayo_scene_hit_any(const rayo_scene *scene, const rayo_ray *ray,
                                double t_min);

#ifdef __cplusplus
}
#endif

#endif
