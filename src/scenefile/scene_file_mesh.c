/*
 * scene_file_mesh.c - the 'mesh' statement: a mesh file's path (beside
 * the scene file unless absolute), its placement (scale, rotate,
 * translate), whose normals shade it, and its material.  Reading the
 * STL or OBJ file is formats/'s job (mesh.h), placing its triangles in
 * the scene scene.h's (rayo_scene_add_mesh); here the line is read and
 * the counts the command warns about are kept.
 */
#include "scene_file_parser.h"

#include <stdlib.h>
#include <string.h>

/* ---- meshes ------------------------------------------------------------ */

/* The mesh file's path: as written when absolute, else beside the scene
 * file (the folder of its name; the current one for standard input),
 * never "-" (standard input is the scene's, not a mesh). */
static char *mesh_path(const parser *p, const scene_word *word)
{
    const char *name = p->lx.name;
    const char *slash = strrchr(name, '/');
    const char *dir_text = slash != NULL ? name : "./";
    size_t dir = word->text[0] == '/'  ? 0
                 : slash != NULL       ? (size_t)(slash - name) + 1
                                       : 2;
    char *path = malloc(dir + word->length + 1);
    if (path == NULL)
        return NULL;
    memcpy(path, dir_text, dir);
    memcpy(path + dir, word->text, word->length);
    path[dir + word->length] = '\0';
    return path;
}

/* The words after the file: scale, rotate, translate, normals, and the
 * material last. */
static rayo_status mesh_options(parser *p, rayo_mesh_placement *placement,
                                unsigned *material)
{
    scene_word word;
    char text[WORD_SHOW + 32];
    rayo_status status = RAYO_OK;
    *material = 0;
    while (status == RAYO_OK) {
        size_t column = 0;
        if (!scene_lexer_word(&p->lx, &word))
            return RAYO_OK;
        if (scene_word_is(&word, "scale")) {
            status = scene_need_number(p, "the mesh's scale",
                                       &placement->scale, &column);
            if (status == RAYO_OK && !(placement->scale > 0.0))
                return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                        "scale %g is not accepted; expected "
                                        "a number > 0",
                                        placement->scale);
        } else if (scene_word_is(&word, "rotate")) {
            status = scene_need_vector(p, "the mesh's rotation (degrees)",
                                       &placement->rotate, NULL);
        } else if (scene_word_is(&word, "translate")) {
            status = scene_need_vector(p, "the mesh's translation",
                                       &placement->translate, NULL);
        } else if (scene_word_is(&word, "normals")) {
            status = scene_need_word(p, &word, "file or computed");
            if (status != RAYO_OK)
                return status;
            if (scene_word_is(&word, "file") ||
                scene_word_is(&word, "computed"))
                placement->computed_normals =
                    scene_word_is(&word, "computed");
            else
                return scene_lexer_fail(
                    &p->lx, word.column, RAYO_ERR_FORMAT,
                    "%s; expected file or computed",
                    scene_found(p, &word, 1, text, sizeof text));
        } else if (scene_word_is(&word, "material")) {
            /* object_material reads the keyword again. */
            p->lx.pos = (size_t)(word.text - p->lx.text);
            return scene_object_material(p, "mesh", material);
        } else {
            return scene_lexer_fail(
                &p->lx, word.column, RAYO_ERR_FORMAT,
                "%s; expected scale, rotate, translate, normals, material or "
                "the end of the 'mesh' line",
                scene_found(p, &word, 1, text, sizeof text));
        }
    }
    return status;
}

rayo_status scene_parse_mesh(parser *p)
{
    scene_word word;
    rayo_mesh_placement placement;
    rayo_mesh mesh;
    rayo_mesh_report report;
    unsigned material;
    size_t left_out = 0;
    rayo_error inner = RAYO_ERROR_INIT(rayo_error_lang(p->lx.err));
    char *path;
    rayo_status status = scene_need_word(p, &word, "a mesh file (STL or OBJ)");
    if (status != RAYO_OK)
        return status;
    rayo_mesh_placement_init(&placement);
    path = mesh_path(p, &word);
    if (path == NULL)
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_NOMEM,
                                "out of memory");
    status = mesh_options(p, &placement, &material);
    if (status == RAYO_OK &&
        rayo_mesh_read_file(path, &mesh, &report, &inner) != RAYO_OK)
        status = scene_lexer_fail(&p->lx, word.column, inner.status, "%s",
                                  inner.message);
    free(path);
    if (status != RAYO_OK)
        return status;
    if (rayo_scene_add_mesh_threads(p->file->scene, &mesh, &placement,
                                    material, p->parts, &left_out,
                                    &inner) != RAYO_OK)
        status = scene_failed(p, &inner);
    p->file->mesh_triangles += mesh.count - left_out;
    p->file->mesh_left_out += left_out;
    p->file->mesh_ignored += report.ignored;
    rayo_mesh_free(&mesh);
    return status;
}
