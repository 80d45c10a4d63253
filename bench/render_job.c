/*
 * render_job.c - the job `rayo render` does, in process, for the rows
 * that time it (seed.c into a pipe or a file, large.c into /dev/null):
 * writer, render, finish, commit, with the same clean-up on a failure.
 */
#include "bench.h"

int bench_render_into(rayo_output *out, const rayo_camera *camera,
                      const rayo_scene *scene,
                      const rayo_render_options *options, rayo_format format,
                      int plain)
{
    rayo_image_info info = rayo_render_image_info(camera, options);
    rayo_write_options write_options;
    rayo_writer *writer;
    rayo_error err;
    write_options.format = format;
    write_options.plain = plain;
    if (rayo_writer_open(&writer, out, &info, &write_options, &err) !=
        RAYO_OK) {
        rayo_output_abort(out);
        return -1;
    }
    if (rayo_render(camera, scene, options, rayo_writer_row_sink, writer,
                    &err) != RAYO_OK) {
        rayo_writer_discard(writer);
        rayo_output_abort(out);
        return -1;
    }
    if (rayo_writer_finish(writer, &err) != RAYO_OK) {
        rayo_output_abort(out);
        return -1;
    }
    return rayo_output_commit(out, &err) == RAYO_OK ? 0 : -1;
}
