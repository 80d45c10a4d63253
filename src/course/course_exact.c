/*
 * course_exact.c - an exercise's correct image, made by the library's own
 * renderer (shade modes hit, course-gray, course-color), so that it is
 * byte for byte what `rayo` and `rayo render examples/ejN.scene` write.
 *
 * The two variations are the camera's: focal_scale multiplies the focal
 * distance rayo_camera_init computes, and literal_rows renders a 640x481
 * frame and drops its first row.  A camera of height 481 puts row j at
 * y = j - 240, the same as a height of 480 does, so rows 1..480 of it
 * are the rows y = -239 .. 240 of the pixel convention, i.e. the
 * statement's vy = 239 down to -240: the picture one row higher.
 */
#include <string.h>

#include "course_impl.h"

static rayo_status render_frame(rayo_course_exercise exercise,
                                const rayo_course_options *options,
                                uint32_t height, rayo_image *frame,
                                rayo_error *err)
{
    const rayo_course_data *data = rayo_course_data_of(exercise);
    rayo_camera camera;
    rayo_scene *scene = NULL;
    rayo_render_options render;
    rayo_status status = rayo_camera_init(
        &camera, RAYO_COURSE_WIDTH, height, RAYO_COURSE_FOV,
        rayo_vec3_make(0, 0, 0), err);
    if (status != RAYO_OK)
        return status;
    camera.focal *= options->focal_scale;
    status = rayo_course_scene_build(exercise, &scene, err);
    if (status != RAYO_OK)
        return status;
    rayo_render_options_init(&render);
    render.shade = data->shade;
    render.threads = 1;
    status = rayo_render_image(&camera, scene, &render, frame, err);
    rayo_scene_free(scene);
    return status;
}

rayo_status rayo_course_render_exact(rayo_course_exercise exercise,
                                     const rayo_course_options *options,
                                     rayo_image *image, rayo_error *err)
{
    rayo_image frame;
    rayo_status status;
    uint32_t j;
    size_t row_bytes;
    if (!options->literal_rows)
        return render_frame(exercise, options, RAYO_COURSE_HEIGHT, image,
                            err);
    status = render_frame(exercise, options, RAYO_COURSE_HEIGHT + 1, &frame,
                          err);
    if (status != RAYO_OK)
        return status;
    frame.info.height = RAYO_COURSE_HEIGHT;
    status = rayo_image_create(image, &frame.info, err);
    if (status == RAYO_OK) {
        row_bytes = rayo_image_info_row_bytes(&frame.info);
        for (j = 0; j < RAYO_COURSE_HEIGHT; j++)
            memcpy(rayo_image_row(image, j), rayo_image_row(&frame, j + 1),
                   row_bytes);
    }
    rayo_image_free(&frame);
    return status;
}
