/*
 * rayo.h - the whole rayo library in one include, grouped by layer in the
 * order data flows: math, camera, scene, render, images and formats.
 *
 * The assignment's own API (producto_interno, norma, intersecta_esfera
 * and its #defines) is not included here: include <rayo/ejercicio1.h>
 * for it, so its short macro names (R, CX, ...) never leak into programs
 * that did not ask for them.
 */
#ifndef RAYO_H
#define RAYO_H

#define RAYO_VERSION "0.1.0"

#include "rayo/status.h"
#include "rayo/lang.h"
#include "rayo/limits.h"
#include "rayo/cpu.h"
#include "rayo/seed.h"

#include "rayo/vec3.h"
#include "rayo/ray.h"
#include "rayo/sphere.h"
#include "rayo/plane.h"
#include "rayo/triangle.h"
#include "rayo/mesh.h"
#include "rayo/camera.h"
#include "rayo/camera_spec.h"
#include "rayo/scene.h"
#include "rayo/scene_random.h"
#include "rayo/scene_file.h"
#include "rayo/render.h"

#include "rayo/image.h"
#include "rayo/row_sink.h"
#include "rayo/output.h"
#include "rayo/writer.h"
#include "rayo/reader.h"
#include "rayo/image_convert.h"
#include "rayo/compare.h"
#include "rayo/preview.h"

#include "rayo/course.h"
#include "rayo/grade.h"
#include "rayo/pbm_check.h"

#endif
