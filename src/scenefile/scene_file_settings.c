/*
 * scene_file_settings.c - the statements that set up the picture rather
 * than fill the scene: camera (its size, field of view and aim, checked
 * by building it), shade (with course-tp1's readings), samples, depth,
 * background and ambient.  Each may appear once; a second is refused
 * with the line of the first.  What the settings mean is render's and
 * camera's business (render.h, camera_spec.h); here they are only read.
 */
#include "scene_file_parser.h"

#include <stdint.h>
#include <string.h>

#include "rayo/limits.h"

/* ---- camera ---------------------------------------------------------- */

static rayo_status camera_size(parser *p, rayo_camera_spec *spec,
                               const scene_word *key)
{
    unsigned long v;
    rayo_status status;
    if (scene_word_is(key, "size") || scene_word_is(key, "width")) {
        status =
            scene_need_count(p, "the image width", 1, RAYO_MAX_DIMENSION, &v);
        if (status != RAYO_OK)
            return status;
        spec->width = (uint32_t)v;
    }
    if (scene_word_is(key, "size") || scene_word_is(key, "height")) {
        status =
            scene_need_count(p, "the image height", 1, RAYO_MAX_DIMENSION, &v);
        if (status != RAYO_OK)
            return status;
        spec->height = (uint32_t)v;
    }
    return RAYO_OK;
}

static rayo_status camera_field(parser *p, rayo_camera_spec *spec,
                                const scene_word *key)
{
    if (scene_word_is(key, "size") || scene_word_is(key, "width") ||
        scene_word_is(key, "height"))
        return camera_size(p, spec, key);
    if (scene_word_is(key, "fov")) {
        size_t column = 0;
        rayo_status status = scene_need_number(
            p, "the field of view in degrees", &spec->fov_degrees, &column);
        if (status == RAYO_OK &&
            !(spec->fov_degrees > 0.0 && spec->fov_degrees < 180.0))
            return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                    "field of view %g is not accepted; "
                                    "expected degrees strictly between 0 "
                                    "and 180",
                                    spec->fov_degrees);
        return status;
    }
    if (scene_word_is(key, "origin"))
        return scene_need_vector(p, "the camera origin", &spec->origin, NULL);
    if (scene_word_is(key, "look-at")) {
        spec->aimed = 1;
        return scene_need_vector(p, "the look-at point", &spec->look_at, NULL);
    }
    if (scene_word_is(key, "up")) {
        spec->aimed = 1;
        return scene_need_direction(p, "the up vector", &spec->up);
    }
    {
        char text[WORD_SHOW + 32];
        return scene_lexer_fail(&p->lx, key->column, RAYO_ERR_FORMAT,
                                "%s; expected size, width, height, fov, "
                                "origin, look-at, up or the end of the "
                                "'camera' line",
                                scene_found(p, key, 1, text, sizeof text));
    }
}

rayo_status scene_parse_camera(parser *p)
{
    rayo_camera_spec *spec = &p->file->camera;
    rayo_camera camera;
    rayo_error inner = RAYO_ERROR_INIT(rayo_error_lang(p->lx.err));
    scene_word key;
    rayo_status status = scene_once(p, &p->camera_line, "camera");
    if (status != RAYO_OK)
        return status;
    while (scene_lexer_word(&p->lx, &key)) {
        status = camera_field(p, spec, &key);
        if (status != RAYO_OK)
            return status;
    }
    p->file->camera_given = 1;
    if ((uint64_t)spec->width * spec->height > RAYO_MAX_PIXELS)
        return scene_lexer_fail(&p->lx, 1, RAYO_ERR_LIMIT,
                                "%lux%lu is too many pixels; expected at "
                                "most 2^30",
                                (unsigned long)spec->width,
                                (unsigned long)spec->height);
    if (rayo_camera_spec_build(spec, &camera, &inner) != RAYO_OK)
        return scene_failed(p, &inner);
    return RAYO_OK;
}

/* ---- render settings ------------------------------------------------- */

/* course-tp1's readings of its statement: tinted-reflections,
 * shadows-to-light, epsilon E (docs/shading.md). */
static rayo_status tp1_readings(parser *p, rayo_tp1_reading *reading)
{
    scene_word word;
    while (scene_lexer_word(&p->lx, &word)) {
        size_t column = word.column;
        if (scene_word_is(&word, "tinted-reflections")) {
            reading->tinted_reflection = 1;
        } else if (scene_word_is(&word, "shadows-to-light")) {
            reading->shadows_to_light = 1;
        } else if (scene_word_is(&word, "epsilon")) {
            rayo_status status =
                scene_need_number(p, "epsilon", &reading->epsilon, &column);
            if (status != RAYO_OK)
                return status;
            if (!(reading->epsilon >= 0.0 && reading->epsilon <= 1.0))
                return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                        "epsilon %g is not accepted; "
                                        "expected a number from 0 to 1",
                                        reading->epsilon);
        } else {
            char text[WORD_SHOW + 32];
            return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                                    "%s; expected tinted-reflections, "
                                    "shadows-to-light, epsilon or the end "
                                    "of the 'shade' line",
                                    scene_found(p, &word, 1, text,
                                                sizeof text));
        }
    }
    return RAYO_OK;
}

rayo_status scene_parse_shade(parser *p)
{
    scene_word word;
    char name[32], text[WORD_SHOW + 32];
    rayo_status status = scene_once(p, &p->shade_line, "shade");
    if (status == RAYO_OK)
        status = scene_need_word(p, &word, "a shading mode (hit, course-gray, "
                                 "course-color, phong or course-tp1)");
    if (status != RAYO_OK)
        return status;
    if (word.length < sizeof name) {
        memcpy(name, word.text, word.length);
        name[word.length] = '\0';
    } else {
        name[0] = '\0';
    }
    if (rayo_shade_mode_parse(name, &p->file->shade, NULL) != RAYO_OK)
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                                "%s; expected a shading mode: hit, "
                                "course-gray, course-color, phong or "
                                "course-tp1",
                                scene_found(p, &word, 1, text, sizeof text));
    p->file->shade_given = 1;
    if (p->file->shade == RAYO_SHADE_COURSE_TP1)
        return tp1_readings(p, &p->file->tp1);
    return scene_need_end(p, "shade", NULL);
}

rayo_status scene_parse_samples(parser *p)
{
    unsigned long v = 0;
    rayo_status status = scene_once(p, &p->samples_line, "samples");
    if (status == RAYO_OK)
        status = scene_need_count(p, "the samples per pixel side", 1,
                                  RAYO_MAX_SAMPLES, &v);
    if (status != RAYO_OK)
        return status;
    p->file->samples = (unsigned)v;
    return scene_need_end(p, "samples", NULL);
}

rayo_status scene_parse_depth(parser *p)
{
    unsigned long v = 0;
    rayo_status status = scene_once(p, &p->depth_line, "depth");
    if (status == RAYO_OK)
        status =
            scene_need_count(p, "the reflection depth", 0, RAYO_MAX_DEPTH, &v);
    if (status != RAYO_OK)
        return status;
    p->file->depth = (unsigned)v;
    return scene_need_end(p, "depth", NULL);
}

rayo_status scene_parse_background(parser *p)
{
    rayo_vec3 c;
    rayo_status status = scene_once(p, &p->background_line, "background");
    if (status == RAYO_OK)
        status = scene_need_color(p, "the background colour",
                                  RAYO_SCENE_MAX_NUMBER, &c);
    if (status != RAYO_OK)
        return status;
    rayo_scene_set_background(p->file->scene, c);
    return scene_need_end(p, "background", NULL);
}

rayo_status scene_parse_ambient(parser *p)
{
    rayo_vec3 c;
    rayo_status status = scene_once(p, &p->ambient_line, "ambient");
    if (status == RAYO_OK)
        status = scene_need_color(p, "the ambient light",
                                  RAYO_SCENE_MAX_NUMBER, &c);
    if (status != RAYO_OK)
        return status;
    rayo_scene_set_ambient(p->file->scene, c);
    return scene_need_end(p, "ambient", NULL);
}
