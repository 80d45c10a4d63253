/*
 * fuzz_mesh.c - fuzz target: the mesh readers by content.
 *
 * The input is handed whole to rayo_mesh_read_memory, which picks binary
 * STL, ASCII STL or OBJ from the first bytes.  A refusal must be one
 * line; a mesh that is accepted must hold finite corners, no more
 * triangles than the limit, and (for binary STL) no more than the input
 * can hold; it is then placed in a scene, which exercises the code that
 * trusts a reader's output.  Not a conformance test: tests/unit/t_mesh.c
 * checks what is read.
 */
#include <math.h>
#include <stdlib.h>

#include "fuzz.h"
#include "rayo/limits.h"
#include "rayo/mesh.h"
#include "rayo/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rayo_mesh mesh;
    rayo_mesh_report report;
    rayo_mesh_placement placement;
    rayo_scene *scene;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    size_t i, left_out = 0;
    rayo_error_clear(&err);
    status = rayo_mesh_read_memory(data, size, "fuzz", &mesh, &report, &err);
    if (status != RAYO_OK) {
        fuzz_check_refusal(status, &err);
        return 0;
    }
    if (mesh.count > RAYO_MAX_OBJECTS ||
        (report.format == RAYO_MESH_STL_BINARY &&
         84 + (uint64_t)mesh.count * 50 > size))
        abort();
    for (i = 0; i < mesh.count * 9; i++)
        if (!isfinite(mesh.corners[i]))
            abort();
    if (rayo_scene_create(&scene, &err) == RAYO_OK) {
        rayo_mesh_placement_init(&placement);
        status = rayo_scene_add_mesh(scene, &mesh, &placement, 0, &left_out,
                                     &err);
        if (status != RAYO_OK)
            fuzz_check_refusal(status, &err);
        else if (rayo_scene_object_count(scene) + left_out != mesh.count)
            abort();
        rayo_scene_free(scene);
    }
    rayo_mesh_free(&mesh);
    return 0;
}
