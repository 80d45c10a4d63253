/*
 * fuzz_scene.c - fuzz target: the scene-file parser, from memory.
 *
 * The input is parsed as a scene file (rayo_scene_file_parse).  A
 * refusal must be one line naming FILE:LINE:COL; a scene that is
 * accepted is rendered at 6x4 pixels, one ray each, at most two mirror
 * bounces, on the calling thread, in its own shading mode, so the
 * hierarchy, the intersections and the shading meet whatever geometry
 * the parser lets through.  The size and the bounces are capped to keep
 * thousands of executions a second; the parser's own limits
 * (scene_file.h) are what is being tested, not the renderer's speed.
 */
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

#define FUZZ_NAME "fuzz.scene"

static void render_small(const rayo_scene_file *file)
{
    rayo_camera_spec spec = file->camera;
    rayo_camera camera;
    rayo_render_options options;
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    spec.width = 6;
    spec.height = 4;
    status = rayo_camera_spec_build(&spec, &camera, &err);
    if (status != RAYO_OK) {
        fuzz_check_refusal(status, &err);
        return;
    }
    rayo_render_options_init(&options);
    options.shade = file->shade;
    options.samples = 1;
    options.depth = file->depth < 2 ? file->depth : 2;
    options.threads = 1;
    status = rayo_render_image(&camera, file->scene, &options, &image, &err);
    if (status != RAYO_OK) {
        fuzz_check_refusal(status, &err);
        return;
    }
    rayo_image_free(&image);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rayo_scene_file file;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    rayo_error_clear(&err);
    status = rayo_scene_file_parse(&file, FUZZ_NAME, (const char *)data, size,
                                   &err);
    if (status != RAYO_OK) {
        fuzz_check_refusal(status, &err);
        if (strncmp(err.message, FUZZ_NAME ":", strlen(FUZZ_NAME) + 1) != 0)
            abort();
        return 0;
    }
    if (file.samples < 1 || file.samples > RAYO_MAX_SAMPLES ||
        file.depth > RAYO_MAX_DEPTH)
        abort();
    render_small(&file);
    rayo_scene_file_free(&file);
    return 0;
}
