/*
 * camera.h - the pinhole camera: which ray passes through which pixel.
 *
 * The pixel convention (DEVELOPERS.md, README): column i and row j of a
 * w x h image are the point x = i - floor(w/2), y = j - floor(h/2), rows
 * from the top.  The ray through it leaves the origin with direction
 * x * right - y * up + f * forward, normalised, where the focal distance
 * f = w / (2 tan(fov/2)).  With the default basis (right = +x, up = +y,
 * forward = +z) that is (x, -y, f): the scene's y axis points up, so a
 * sphere with positive y sits in the upper half of the picture.  The camera
 * knows nothing of what the rays hit.
 */
#ifndef RAYO_CAMERA_H
#define RAYO_CAMERA_H

#include <stdint.h>

#include "rayo/export.h"
#include "rayo/ray.h"
#include "rayo/status.h"

typedef struct rayo_camera {
    uint32_t width, height; /* pixels, 1..RAYO_MAX_DIMENSION */
    double fov_degrees;     /* horizontal field of view, (0, 180) */
    double focal;           /* w / (2 tan(fov/2)), in pixels */
    rayo_vec3 origin;
    rayo_vec3 right, up, forward; /* orthonormal basis */
} rayo_camera;

/*
 * A camera at origin looking down +z with +y up.  Fails with
 * RAYO_ERR_INVALID (and says which value) for sizes out of range, more
 * than RAYO_MAX_PIXELS pixels, a field of view outside (0, 180) or a
 * non-finite origin.
 */
RAYO_API rayo_status rayo_camera_init(rayo_camera *camera, uint32_t width,
                                      uint32_t height, double fov_degrees,
                                      rayo_vec3 origin, rayo_error *err);

/*
 * Turns the camera to look at target with the given up hint.  Fails when
 * target equals the origin or up is parallel to the view direction.
 */
RAYO_API rayo_status rayo_camera_look_at(rayo_camera *camera, rayo_vec3 target,
                                         rayo_vec3 up, rayo_error *err);

/*
 * The ray through image position (px, py), in pixel units: (i, j) is the
 * pixel of column i and row j; fractions give points between pixels
 * (anti-aliasing samples).
 */
static inline rayo_ray rayo_camera_ray(const rayo_camera *camera, double px,
                                       double py)
{
    double x = px - (double)(camera->width / 2);
    double y = py - (double)(camera->height / 2);
    rayo_vec3 d = rayo_vec3_add(
        rayo_vec3_add(rayo_vec3_scale(camera->right, x),
                      rayo_vec3_scale(camera->up, -y)),
        rayo_vec3_scale(camera->forward, camera->focal));
    rayo_ray ray;
    ray.origin = camera->origin;
    ray.direction = rayo_vec3_normalize(d);
    return ray;
}

#endif
