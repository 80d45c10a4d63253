/*
 * camera_spec.h - a camera described by its settings (size, field of
 * view, origin, and optionally a point to look at with an up vector),
 * before it is built into a rayo_camera.
 *
 * Scene files produce one and the command overrides single settings of it
 * (-W, -H, --fov, --origin) before building: an overridden origin keeps
 * looking at the scene's look-at point.  It does no ray arithmetic; that
 * is camera.h.
 */
#ifndef RAYO_CAMERA_SPEC_H
#define RAYO_CAMERA_SPEC_H

#include <stdint.h>

#include "rayo/camera.h"
#include "rayo/export.h"
#include "rayo/status.h"
#include "rayo/vec3.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rayo_camera_spec {
    uint32_t width, height;
    double fov_degrees;
    rayo_vec3 origin;
    int aimed;         /* 1: look_at and up orient the camera */
    rayo_vec3 look_at; /* a point the camera looks at */
    rayo_vec3 up;      /* which way is up in the picture */
} rayo_camera_spec;

/*
 * The assignment's camera: 640x480, field of view 90, at the origin,
 * looking down +z with +y up, not aimed.
 */
RAYO_API void rayo_camera_spec_init(rayo_camera_spec *spec);

/*
 * Builds the camera: rayo_camera_init, then rayo_camera_look_at when
 * aimed.  Their errors (RAYO_ERR_INVALID) come back unchanged.
 */
RAYO_API rayo_status rayo_camera_spec_build(const rayo_camera_spec *spec,
                                            rayo_camera *camera,
                                            rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
