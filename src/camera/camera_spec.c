/*
 * camera_spec.c - building a rayo_camera from its settings
 * (camera_spec.h).  Validation stays in camera.c, so a scene file and
 * the command line get the same limits and messages.
 */
#include "rayo/camera_spec.h"

#include "rayo/seed.h"

void rayo_camera_spec_init(rayo_camera_spec *spec)
{
    spec->width = RAYO_SEED_WIDTH;
    spec->height = RAYO_SEED_HEIGHT;
    spec->fov_degrees = RAYO_SEED_FOV;
    spec->origin = rayo_vec3_make(0, 0, 0);
    spec->aimed = 0;
    spec->look_at = rayo_vec3_make(0, 0, 1);
    spec->up = rayo_vec3_make(0, 1, 0);
}

rayo_status rayo_camera_spec_build(const rayo_camera_spec *spec,
                                   rayo_camera *camera, rayo_error *err)
{
    rayo_status status =
        rayo_camera_init(camera, spec->width, spec->height,
                         spec->fov_degrees, spec->origin, err);
    if (status != RAYO_OK || !spec->aimed)
        return status;
    return rayo_camera_look_at(camera, spec->look_at, spec->up, err);
}
