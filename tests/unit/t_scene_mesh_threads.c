/*
 * t_scene_mesh_threads.c - a mesh placed in a scene on several threads
 * (rayo_scene_add_mesh_threads, src/scene/scene_mesh_ranges.c) makes the
 * scene one thread makes, byte for byte: its triangles, their normals,
 * object numbers and materials, and the object table, on 1, 2, 3 and 8
 * threads.  The mesh (a wavy sheet of 100,000 triangles) has triangles
 * crushed to a line in several ranges, so ranges must close up; one
 * with a normal that is not finite stops the mesh where adding one by
 * one stops, with the triangles before it kept.  What is
 * left out and what stays is counted here from how the mesh was made.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

#include "../../src/scene/scene_impl.h"

#define COUNT 100000

/* A sheet of triangles, every 7919th crushed (two corners one) (left out). */
static int make_mesh(rayo_mesh *mesh, size_t *crushed)
{
    size_t i;
    mesh->count = COUNT;
    mesh->corners = malloc(COUNT * 9 * sizeof *mesh->corners);
    mesh->normals = malloc(COUNT * 3 * sizeof *mesh->normals);
    if (mesh->corners == NULL || mesh->normals == NULL)
        return 0;
    *crushed = 0;
    for (i = 0; i < COUNT; i++) {
        float *c = mesh->corners + i * 9, *n = mesh->normals + i * 3;
        float x = (float)(i % 400), y = (float)(i / 400);
        c[0] = x;
        c[1] = y;
        c[2] = (float)sin(0.1 * (double)i);
        c[3] = x + 1.0f;
        c[4] = y;
        c[5] = (float)cos(0.07 * (double)i);
        c[6] = x;
        c[7] = y + 1.0f;
        c[8] = 0.25f;
        n[0] = 0.0f;
        n[1] = (i % 3 == 0) ? 0.0f : 0.5f; /* some zero: the corners' */
        n[2] = (i % 3 == 0) ? 0.0f : 1.0f;
        if (i % 7919 == 5) { /* third corner on the first */
            c[6] = c[0];
            c[7] = c[1];
            c[8] = c[2];
            ++*crushed;
        }
    }
    return 1;
}

static rayo_scene *placed(const rayo_mesh *mesh, unsigned threads,
                          unsigned material, size_t *left_out,
                          rayo_status *status)
{
    rayo_scene *scene;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_mesh_placement placement;
    rayo_material m = {{0.5, 0.5, 0.5}, 0.1, 0.8, 0.0, 0.0, 0.0};
    unsigned id;
    if (rayo_scene_create(&scene, &err) != RAYO_OK)
        return NULL;
    rayo_scene_add_material(scene, &m, &id, &err);
    rayo_scene_add_sphere(scene, rayo_vec3_make(0, 0, -5), 1.0, &err);
    rayo_mesh_placement_init(&placement);
    placement.scale = 1.5;
    placement.rotate = rayo_vec3_make(10, 20, 30);
    placement.translate = rayo_vec3_make(1, -2, 3);
    *left_out = 12345;
    *status = rayo_scene_add_mesh_threads(scene, mesh, &placement, material,
                                          threads, left_out, &err);
    return scene;
}

static int same_scene(const rayo_scene *a, const rayo_scene *b)
{
    return a->triangle_count == b->triangle_count &&
           a->object_count == b->object_count &&
           memcmp(a->triangles, b->triangles,
                  a->triangle_count * sizeof *a->triangles) == 0 &&
           memcmp(a->objects, b->objects,
                  a->object_count * sizeof *a->objects) == 0;
}

int main(void)
{
    static const unsigned threads[] = {2, 3, 8};
    rayo_mesh mesh;
    size_t crushed, left_out, i, t, stop = 61234;
    rayo_status status;
    rayo_scene *one;
    if (!make_mesh(&mesh, &crushed)) {
        ok(0, "memory");
        return tap_done();
    }
    one = placed(&mesh, 1, 1, &left_out, &status);
    ok(one != NULL && status == RAYO_OK && left_out == crushed &&
           one->triangle_count == COUNT - crushed &&
           one->object_count == 1 + COUNT - crushed,
       "one thread: %lu triangles, %lu crushed ones left out",
       (unsigned long)(COUNT - crushed), (unsigned long)crushed);
    for (i = 0; one != NULL && i < one->triangle_count; i++)
        if (one->triangles[i].object != i + 1 ||
            one->triangles[i].material != 1 ||
            one->objects[i + 1].index != i)
            break;
    ok(one != NULL && i == one->triangle_count,
       "  each triangle its object number, material and table entry");
    for (t = 0; t < sizeof threads / sizeof threads[0]; t++) {
        rayo_scene *s = placed(&mesh, threads[t], 1, &left_out, &status);
        ok(s != NULL && one != NULL && status == RAYO_OK &&
               left_out == crushed && same_scene(one, s),
           "%u threads: the same scene, byte for byte", threads[t]);
        rayo_scene_free(s);
    }
    rayo_scene_free(one);
    /* A normal not finite (no reader makes one, a caller may): the mesh
     * stops there. */
    mesh.normals[stop * 3 + 1] = INFINITY;
    one = placed(&mesh, 1, 1, &left_out, &status);
    ok(one != NULL && status == RAYO_ERR_INVALID && left_out == 12345 &&
           one->triangle_count == stop - stop / 7919 - (stop % 7919 > 5),
       "a normal not finite: refused, the %lu triangles before it "
       "kept",
       (unsigned long)(stop - stop / 7919 - (stop % 7919 > 5)));
    for (t = 0; t < sizeof threads / sizeof threads[0]; t++) {
        rayo_scene *s = placed(&mesh, threads[t], 1, &left_out, &status);
        ok(s != NULL && one != NULL && status == RAYO_ERR_INVALID &&
               same_scene(one, s),
           "  %u threads: refused too, the same triangles kept", threads[t]);
        rayo_scene_free(s);
    }
    rayo_scene_free(one);
    /* A material that does not exist: refused before any triangle. */
    for (t = 0; t < sizeof threads / sizeof threads[0]; t++) {
        rayo_scene *s = placed(&mesh, threads[t], 9, &left_out, &status);
        ok(s != NULL && status == RAYO_ERR_INVALID && s->triangle_count == 0,
           "material 9 on %u threads: refused, no triangle added",
           threads[t]);
        rayo_scene_free(s);
    }
    free(mesh.corners);
    free(mesh.normals);
    return tap_done();
}
