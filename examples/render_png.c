/*
 * render_png.c - the library's general API in a few lines: load a scene
 * file, build its camera, render it with its own settings, write a PNG.
 * It is what `rayo render SCENE -o OUT.png` does, less the options.
 *
 *   cc -std=c99 -Wall -Werror -pedantic render_png.c \
 *       $(pkg-config --cflags --libs --static rayo) -o render_png
 *   ./render_png examples/showcase.scene showcase.png
 *
 * Every call that can fail returns a rayo_status and fills a rayo_error
 * with one line saying why; the library never prints, so the program
 * does.  `make check` builds this file against build/librayo.a with the
 * course's flags and checks its PNG against `rayo render`'s.
 */
#include <stdio.h>

#include <rayo.h>

/* Prints the error and says which exit status it deserves: 2 for a bad
   scene, 1 for anything else. */
static int fail(const rayo_error *err)
{
    fprintf(stderr, "render_png: %s\n", err->message);
    return err->status == RAYO_ERR_FORMAT || err->status == RAYO_ERR_INVALID
               ? 2
               : 1;
}

int main(int argc, char **argv)
{
    rayo_scene_file file;
    rayo_camera camera;
    rayo_render_options options;
    rayo_image image;
    rayo_write_options png = {RAYO_FORMAT_PNG, 0, 0};
    rayo_output *out;
    rayo_error err;
    int status = 0;

    if (argc != 3) {
        fprintf(stderr, "usage: render_png SCENE OUT.png\n");
        return 2;
    }
    rayo_error_clear(&err);
    /* The scene: its objects, lights and materials, its camera (or the
       default one) and its shading settings. */
    if (rayo_scene_file_load(&file, argv[1], &err) != RAYO_OK)
        return fail(&err);
    if (rayo_camera_spec_build(&file.camera, &camera, &err) != RAYO_OK) {
        rayo_scene_file_free(&file);
        return fail(&err);
    }
    rayo_render_options_init(&options); /* one thread per CPU */
    options.shade = file.shade;
    options.samples = file.samples;
    options.depth = file.depth;

    /* The whole frame in memory, then written: the output file appears
       whole (renamed into place by commit) or not at all. */
    if (rayo_render_image(&camera, file.scene, &options, &image, &err) !=
        RAYO_OK) {
        rayo_scene_file_free(&file);
        return fail(&err);
    }
    if (rayo_output_open(&out, argv[2], &err) != RAYO_OK) {
        status = fail(&err);
    } else if (rayo_image_write(&image, out, &png, &err) != RAYO_OK) {
        rayo_output_abort(out);
        status = fail(&err);
    } else if (rayo_output_commit(out, &err) != RAYO_OK) {
        status = fail(&err);
    }
    rayo_image_free(&image);
    rayo_scene_file_free(&file);
    return status;
}
