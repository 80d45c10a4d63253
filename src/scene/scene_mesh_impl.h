/*
 * scene_mesh_impl.h - what the two files that place a mesh in a scene
 * share: scene_mesh.c (the placement's arithmetic, the checks, one
 * triangle at a time) and scene_mesh_ranges.c (the whole mesh at once,
 * by ranges on several threads).  Internal to src/scene.
 */
#ifndef RAYO_SCENE_MESH_IMPL_H
#define RAYO_SCENE_MESH_IMPL_H

#include "scene_impl.h"

/* A placement as the arithmetic uses it. */
typedef struct mesh_frame {
    double m[3][3];            /* the rotation */
    const rayo_mesh_placement *placement;
    const rayo_mesh *mesh;
} mesh_frame;

/* Triangle i of the mesh placed: its corners in *shape and the normal it
 * asks for (zero: the corners') in *normal; 1 when the scene takes it,
 * 0 when its corners are on one line (left out), -1 when adding it
 * would fail (a corner or the normal not finite). */
int scene_mesh_place(const mesh_frame *f, size_t i, rayo_triangle *shape,
                     rayo_vec3 *normal);

/* Places the mesh's triangles [0, count) after the scene's last, in room
 * reserved (scene_reserve_triangles), on up to `threads` threads, in
 * order, leaving out those on one line (*skipped counts them) and
 * stopping before the first refused (*stop; count when none); the
 * triangles set, to be made objects by scene_triangles_added. */
size_t scene_mesh_place_all(rayo_scene *scene, const mesh_frame *f,
                            unsigned threads, size_t *skipped,
                            size_t *stop);

#endif
