/*
 * camera.c - building and orienting the pinhole camera of camera.h.
 *
 * Validation lives here so every caller (the command, scene files, the
 * assignment's API) gets the same limits and the same messages.
 */
#include "rayo/camera.h"

#include "rayo/limits.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

rayo_status rayo_camera_init(rayo_camera *camera, uint32_t width,
                             uint32_t height, double fov_degrees,
                             rayo_vec3 origin, rayo_error *err)
{
    if (width < 1 || width > RAYO_MAX_DIMENSION)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "width %lu is out of range; expected 1 to %u",
                              (unsigned long)width, RAYO_MAX_DIMENSION);
    if (height < 1 || height > RAYO_MAX_DIMENSION)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "height %lu is out of range; expected 1 to %u",
                              (unsigned long)height, RAYO_MAX_DIMENSION);
    if ((uint64_t)width * height > RAYO_MAX_PIXELS)
        return rayo_error_set(
            err, RAYO_ERR_INVALID,
            "%lux%lu is %llu pixels; expected at most %lu (2^30)",
            (unsigned long)width, (unsigned long)height,
            (unsigned long long)width * height, RAYO_MAX_PIXELS);
    if (!(fov_degrees > 0.0 && fov_degrees < 180.0))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "field of view %g is out of range; expected "
                              "degrees strictly between 0 and 180",
                              fov_degrees);
    if (!rayo_vec3_is_finite(origin))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "camera origin is not finite");
    camera->width = width;
    camera->height = height;
    camera->fov_degrees = fov_degrees;
    camera->focal = (double)width / (2.0 * tan(fov_degrees * M_PI / 360.0));
    camera->origin = origin;
    camera->right = rayo_vec3_make(1, 0, 0);
    camera->up = rayo_vec3_make(0, 1, 0);
    camera->forward = rayo_vec3_make(0, 0, 1);
    return RAYO_OK;
}

rayo_status rayo_camera_look_at(rayo_camera *camera, rayo_vec3 target,
                                rayo_vec3 up, rayo_error *err)
{
    rayo_vec3 forward = rayo_vec3_sub(target, camera->origin);
    rayo_vec3 right;
    if (!rayo_vec3_is_finite(target) || !rayo_vec3_is_finite(up))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "look-at point and up vector must be finite");
    if (rayo_vec3_length(forward) == 0.0)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "look-at point equals the camera origin");
    forward = rayo_vec3_normalize(forward);
    right = rayo_vec3_cross(up, forward);
    if (!(rayo_vec3_length(right) > 1e-12 * rayo_vec3_length(up)))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "up vector is zero or parallel to the view "
                              "direction");
    right = rayo_vec3_normalize(right);
    camera->forward = forward;
    camera->right = right;
    camera->up = rayo_vec3_cross(forward, right);
    return RAYO_OK;
}
