/*
 * scene_mesh.c - a mesh (mesh.h) placed in a scene: each triangle scaled,
 * rotated and moved as the placement says, and added as a triangle of the
 * scene with the file's facet normal or its corners' own.  Triangles whose
 * corners end up on one line (a scan's slivers, or a scale that crushes
 * them) are left out and counted, not refused: one bad facet in a million
 * should not stop a render.  Reading the file is mesh.h's job, parsing the
 * scene line scenefile/scene_file.c's.
 */
#include <math.h>

#include "rayo/scene.h"

void rayo_mesh_placement_init(rayo_mesh_placement *placement)
{
    placement->scale = 1.0;
    placement->rotate = rayo_vec3_make(0.0, 0.0, 0.0);
    placement->translate = rayo_vec3_make(0.0, 0.0, 0.0);
    placement->computed_normals = 0;
}

typedef struct matrix {
    double m[3][3];
} matrix;

/* The rotation about x, then y, then z, by the angles in degrees. */
static void rotation(rayo_vec3 degrees, matrix *r)
{
    double (*m)[3] = r->m;
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

static rayo_vec3 turn(const matrix *r, const float *v)
{
    const double (*m)[3] = r->m;
    return rayo_vec3_make(m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
                          m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
                          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]);
}

static rayo_vec3 place(const matrix *m,
                       const rayo_mesh_placement *placement, const float *v)
{
    return rayo_vec3_add(rayo_vec3_scale(turn(m, v), placement->scale),
                         placement->translate);
}

rayo_status rayo_scene_add_mesh(rayo_scene *scene, const rayo_mesh *mesh,
                                const rayo_mesh_placement *placement,
                                unsigned material, size_t *left_out,
                                rayo_error *err)
{
    matrix m;
    size_t i, skipped = 0;
    if (!(placement->scale > 0.0) || !isfinite(placement->scale) ||
        !rayo_vec3_is_finite(placement->rotate) ||
        !rayo_vec3_is_finite(placement->translate))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "mesh placement is not accepted; expected a "
                              "finite scale > 0 and finite angles and "
                              "offsets");
    rotation(placement->rotate, &m);
    for (i = 0; i < mesh->count; i++) {
        const float *c = mesh->corners + i * 9;
        rayo_triangle t;
        rayo_vec3 normal = rayo_vec3_make(0.0, 0.0, 0.0);
        rayo_status status;
        t.a = place(&m, placement, c);
        t.b = place(&m, placement, c + 3);
        t.c = place(&m, placement, c + 6);
        if (!rayo_triangle_is_valid(&t)) {
            skipped++;
            continue;
        }
        if (mesh->normals != NULL && !placement->computed_normals)
            normal = turn(&m, mesh->normals + i * 3);
        status = rayo_scene_add_triangle_normal(scene, t.a, t.b, t.c, normal,
                                                material, err);
        if (status != RAYO_OK)
            return status;
    }
    if (left_out != NULL)
        *left_out = skipped;
    return RAYO_OK;
}
