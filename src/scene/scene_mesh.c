/*
 * scene_mesh.c - a mesh (mesh.h) placed in a scene: each triangle scaled,
 * rotated and moved as the placement says, and added as a triangle of the
 * scene with the file's facet normal or its corners' own.  Triangles whose
 * corners end up on one line (a scan's slivers, or a scale that crushes
 * them) are left out and counted, not refused: one bad facet in a million
 * should not stop a render.  Reading the file is mesh.h's job, parsing the
 * scene line scenefile/scene_file.c's.  The whole mesh is placed at
 * once, by ranges on threads, by scene_mesh_ranges.c.
 */
#include "scene_mesh_impl.h"

#include <math.h>

#include "rayo/cpu.h"

void rayo_mesh_placement_init(rayo_mesh_placement *placement)
{
    placement->scale = 1.0;
    placement->rotate = rayo_vec3_make(0.0, 0.0, 0.0);
    placement->translate = rayo_vec3_make(0.0, 0.0, 0.0);
    placement->computed_normals = 0;
}

/* The rotation about x, then y, then z, by the angles in degrees. */
static void rotation(rayo_vec3 degrees, double m[3][3])
{
    const double k = 3.14159265358979323846 / 180.0;
    double cx = cos(degrees.x * k), sx = sin(degrees.x * k);
    double cy = cos(degrees.y * k), sy = sin(degrees.y * k);
    double cz = cos(degrees.z * k), sz = sin(degrees.z * k);
    /* Rz Ry Rx */
    m[0][0] = cz * cy;
    m[0][1] = cz * sy * sx - sz * cx;
    m[0][2] = cz * sy * cx + sz * sx;
    m[1][0] = sz * cy;
    m[1][1] = sz * sy * sx + cz * cx;
    m[1][2] = sz * sy * cx - cz * sx;
    m[2][0] = -sy;
    m[2][1] = cy * sx;
    m[2][2] = cy * cx;
}

static rayo_vec3 turn(const double m[3][3], const float *v)
{
    return rayo_vec3_make(m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
                          m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
                          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]);
}

static rayo_vec3 place(const mesh_frame *f, const float *v)
{
    return rayo_vec3_add(rayo_vec3_scale(turn(f->m, v), f->placement->scale),
                         f->placement->translate);
}

int scene_mesh_place(const mesh_frame *f, size_t i, rayo_triangle *shape,
                     rayo_vec3 *normal)
{
    const float *c = f->mesh->corners + i * 9;
    shape->a = place(f, c);
    shape->b = place(f, c + 3);
    shape->c = place(f, c + 6);
    if (!rayo_triangle_is_valid(shape))
        return 0;
    *normal = rayo_vec3_make(0.0, 0.0, 0.0);
    if (f->mesh->normals != NULL && !f->placement->computed_normals)
        *normal = turn(f->m, f->mesh->normals + i * 3);
    /* rayo_scene_add_triangle_normal's refusals, but for one on a line */
    if (!rayo_vec3_is_finite(shape->a) || !rayo_vec3_is_finite(shape->b) ||
        !rayo_vec3_is_finite(shape->c) || !rayo_vec3_is_finite(*normal))
        return -1;
    return 1;
}

/* One triangle at a time, as rayo_scene_add_triangle_normal adds them:
 * where the scene refuses the whole mesh at once (a bad material, too
 * many objects, no memory for all), so that it fails where that says. */
static rayo_status add_one_by_one(rayo_scene *scene, const mesh_frame *f,
                                  unsigned material, size_t *skipped,
                                  rayo_error *err)
{
    size_t i;
    for (i = 0; i < f->mesh->count; i++) {
        rayo_triangle t;
        rayo_vec3 normal;
        rayo_status status;
        if (scene_mesh_place(f, i, &t, &normal) == 0) {
            ++*skipped;
            continue;
        }
        status = rayo_scene_add_triangle_normal(scene, t.a, t.b, t.c, normal,
                                                material, err);
        if (status != RAYO_OK)
            return status;
    }
    return RAYO_OK;
}

rayo_status rayo_scene_add_mesh_threads(rayo_scene *scene,
                                        const rayo_mesh *mesh,
                                        const rayo_mesh_placement *placement,
                                        unsigned material, unsigned threads,
                                        size_t *left_out, rayo_error *err)
{
    mesh_frame f;
    size_t skipped = 0, stop, added;
    rayo_status status;
    rayo_error quiet = RAYO_ERROR_INIT(rayo_error_lang(err));
    if (!(placement->scale > 0.0) || !isfinite(placement->scale) ||
        !rayo_vec3_is_finite(placement->rotate) ||
        !rayo_vec3_is_finite(placement->translate))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "mesh placement is not accepted; expected a "
                              "finite scale > 0 and finite angles and "
                              "offsets");
    rotation(placement->rotate, f.m);
    f.placement = placement;
    f.mesh = mesh;
    if (scene_reserve_triangles(scene, material, mesh->count, &quiet) !=
        RAYO_OK)
        status = add_one_by_one(scene, &f, material, &skipped, err);
    else {
        if (threads == 0)
            threads = rayo_cpu_count();
        added = scene_mesh_place_all(scene, &f, threads, &skipped, &stop);
        scene_triangles_added(scene, added, material);
        status = RAYO_OK;
        if (stop < mesh->count) { /* its error, as one by one gives it */
            rayo_triangle t;
            rayo_vec3 normal;
            scene_mesh_place(&f, stop, &t, &normal);
            status = rayo_scene_add_triangle_normal(scene, t.a, t.b, t.c,
                                                    normal, material, err);
        }
    }
    if (status == RAYO_OK && left_out != NULL)
        *left_out = skipped;
    return status;
}

rayo_status rayo_scene_add_mesh(rayo_scene *scene, const rayo_mesh *mesh,
                                const rayo_mesh_placement *placement,
                                unsigned material, size_t *left_out,
                                rayo_error *err)
{
    return rayo_scene_add_mesh_threads(scene, mesh, placement, material, 1,
                                       left_out, err);
}
