/*
 * scene_file.c - the grammar of scene files (docs/scene-format.md): one
 * statement per line, a keyword and its values, turned into calls on the
 * scene (scene.h) and a camera description (camera_spec.h).
 *
 * Each statement has a small function; they share helpers that read one
 * number, a vector or a colour and say precisely what they found and what
 * they expected.  Errors from the scene itself (too many objects,
 * collinear triangle corners) are re-issued with the file, line and
 * column of the statement.  Splitting text into words is scene_lexer.c's
 * job, reading numbers core/decimal.c's, reading the file from disk
 * scene_file_load.c's; the text comes a window at a time
 * (scene_file_impl.h: the reader), and a long window's sphere lines are
 * read ahead on several threads by scene_file_split.c and taken here in
 * file order (take_parts).
 */
#include "rayo/scene_file.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/limits.h"
#include "scene_file_impl.h"
#include "scene_file_split.h"
#include "scene_lexer.h"
#include "../core/decimal.h"

/* Spheres added at once: enough that a batch costs little per sphere,
 * few enough that the batch stays in the first-level cache. */
#define SPHERE_BATCH 256

typedef struct material_name {
    char text[RAYO_SCENE_MAX_NAME + 1];
    size_t length;
    unsigned id;
    unsigned long line;
} material_name;

typedef struct parser {
    scene_lexer lx;
    rayo_scene_file *file;
    material_name *names;
    size_t name_count, name_capacity;
    size_t *slots; /* hash table of names: position + 1, 0 when empty */
    size_t slot_capacity; /* a power of two, at least twice name_count */
    unsigned long camera_line, shade_line, samples_line, depth_line;
    unsigned long ambient_line, background_line;
    unsigned long base; /* lines before the window the lexer reads */
    unsigned parts;     /* threads a long window is read on */
    split_set split;    /* its parts, kept for the next window */
    /* Spheres read ahead, consecutive lines of a part, waiting to be
       added together (rayo_scene_add_spheres). */
    rayo_sphere batch[SPHERE_BATCH];
    unsigned batch_material[SPHERE_BATCH];
    size_t batch_count;
} parser;

#define WORD_SHOW 48

/* The word in quotes, printable, for messages. */
static const char *quoted(const scene_word *word, char *buffer, size_t size)
{
    char shown[WORD_SHOW];
    snprintf(buffer, size, "'%s'",
             scene_word_show(word, shown, sizeof shown));
    return buffer;
}

/* "found 'word'" or "found the end of the line" into buffer. */
static const char *found(const scene_word *word, int have, char *buffer,
                         size_t size)
{
    char q[WORD_SHOW + 4];
    if (!have)
        snprintf(buffer, size, "found the end of the line");
    else
        snprintf(buffer, size, "found %s", quoted(word, q, sizeof q));
    return buffer;
}

/* Reads a word that must be there; what names the value expected. */
static rayo_status need_word(parser *p, scene_word *word, const char *what)
{
    char text[WORD_SHOW + 32];
    size_t column = scene_lexer_column(&p->lx);
    if (scene_lexer_word(&p->lx, word))
        return RAYO_OK;
    return scene_lexer_fail(&p->lx, column, RAYO_ERR_FORMAT, "%s; expected %s",
                            found(word, 0, text, sizeof text), what);
}

static int word_to_double(const scene_word *word, double *value)
{
    return decimal_read(word->text, word->length, value);
}

/*
 * What a number stands for, in messages: "the sphere's radius", or with
 * axis set "the x of the sphere's centre".  Written out only when a
 * message needs it: formatting it for every number was a tenth of
 * reading a large scene.
 */
typedef struct number_name {
    const char *what;
    char axis; /* 'x', 'y', 'z', or 0 */
} number_name;

static const char *number_name_text(const number_name *name, char *buffer,
                                    size_t size)
{
    if (name->axis == 0)
        return name->what;
    snprintf(buffer, size, "the %c of %s", name->axis, name->what);
    return buffer;
}

static rayo_status read_number(parser *p, const number_name *name,
                               double *value, size_t *column)
{
    scene_word word;
    char text[WORD_SHOW + 32], label[160], what[128];
    size_t at = scene_lexer_column(&p->lx);
    if (!scene_lexer_word(&p->lx, &word)) {
        snprintf(label, sizeof label, "%s (a number)",
                 number_name_text(name, what, sizeof what));
        return scene_lexer_fail(&p->lx, at, RAYO_ERR_FORMAT,
                                "%s; expected %s",
                                found(&word, 0, text, sizeof text), label);
    }
    if (column != NULL)
        *column = word.column;
    if (!word_to_double(&word, value))
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                                "%s; expected %s (a finite decimal number)",
                                found(&word, 1, text, sizeof text),
                                number_name_text(name, what, sizeof what));
    if (fabs(*value) > RAYO_SCENE_MAX_NUMBER)
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_LIMIT,
                                "%s is out of range; expected %s between "
                                "-1e12 and 1e12",
                                quoted(&word, text, sizeof text),
                                number_name_text(name, what, sizeof what));
    return RAYO_OK;
}

/* One number; what names it ("the sphere's radius"). */
static rayo_status need_number(parser *p, const char *what, double *value,
                               size_t *column)
{
    number_name name;
    name.what = what;
    name.axis = 0;
    return read_number(p, &name, value, column);
}

/* Three numbers: the x, y and z of what ("the sphere's centre"). */
static rayo_status need_vector(parser *p, const char *what, rayo_vec3 *v,
                               size_t *column)
{
    static const char axes[3] = {'x', 'y', 'z'};
    double c[3];
    int i;
    for (i = 0; i < 3; i++) {
        number_name name;
        rayo_status status;
        name.what = what;
        name.axis = axes[i];
        status = read_number(p, &name, &c[i], i == 0 ? column : NULL);
        if (status != RAYO_OK)
            return status;
    }
    *v = rayo_vec3_make(c[0], c[1], c[2]);
    return RAYO_OK;
}

/* A vector that must not be zero (a direction or a normal). */
static rayo_status need_direction(parser *p, const char *what, rayo_vec3 *v)
{
    size_t column = 0;
    rayo_status status = need_vector(p, what, v, &column);
    if (status != RAYO_OK)
        return status;
    if (v->x == 0.0 && v->y == 0.0 && v->z == 0.0)
        return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                "%s 0 0 0 has zero length; expected a "
                                "non-zero vector",
                                what);
    return RAYO_OK;
}

/* A number in [min, max]. */
static rayo_status need_ranged(parser *p, const char *what, double min,
                               double max, double *value)
{
    size_t column = 0;
    rayo_status status = need_number(p, what, value, &column);
    if (status != RAYO_OK)
        return status;
    if (*value < min || *value > max) {
        if (max >= RAYO_SCENE_MAX_NUMBER)
            return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                    "%s %g is not accepted; expected a "
                                    "number >= %g",
                                    what, *value, min);
        return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                "%s %g is not accepted; expected a number "
                                "from %g to %g",
                                what, *value, min, max);
    }
    return RAYO_OK;
}

/* A whole number in [min, max]. */
static rayo_status need_count(parser *p, const char *what, unsigned long min,
                              unsigned long max, unsigned long *value)
{
    size_t column = 0;
    double v;
    rayo_status status = need_number(p, what, &v, &column);
    if (status != RAYO_OK)
        return status;
    if (v != floor(v))
        return scene_lexer_fail(&p->lx, column, RAYO_ERR_FORMAT,
                                "%s %g is not a whole number; expected %lu "
                                "to %lu",
                                what, v, min, max);
    if (v < (double)min || v > (double)max)
        return scene_lexer_fail(&p->lx, column, RAYO_ERR_LIMIT,
                                "%s %g is out of range; expected %lu to %lu",
                                what, v, min, max);
    *value = (unsigned long)v;
    return RAYO_OK;
}

/*
 * A colour: one number (a gray, copied to all three channels) or three.
 * Each channel must lie in [0, max].
 */
static rayo_status need_color(parser *p, const char *what, double max,
                              rayo_vec3 *color)
{
    double c[3];
    int i;
    rayo_status status = need_ranged(p, what, 0.0, max, &c[0]);
    if (status != RAYO_OK)
        return status;
    {
        scene_word next;
        scene_lexer save = p->lx;
        double probe;
        if (!scene_lexer_word(&p->lx, &next) ||
            !word_to_double(&next, &probe)) {
            p->lx = save;
            *color = rayo_vec3_make(c[0], c[0], c[0]);
            return RAYO_OK;
        }
        p->lx = save;
    }
    for (i = 1; i < 3; i++) {
        status = need_ranged(p, what, 0.0, max, &c[i]);
        if (status != RAYO_OK)
            return status;
    }
    *color = rayo_vec3_make(c[0], c[1], c[2]);
    return RAYO_OK;
}

static rayo_status need_end(parser *p, const char *statement,
                            const char *options)
{
    scene_word word;
    char text[WORD_SHOW + 32];
    if (!scene_lexer_word(&p->lx, &word))
        return RAYO_OK;
    return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                            "%s; expected %s%sthe end of the '%s' line",
                            found(&word, 1, text, sizeof text),
                            options ? options : "", options ? " or " : "",
                            statement);
}

/* A statement that may appear once: fails on the second. */
static rayo_status once(parser *p, unsigned long *line, const char *keyword)
{
    if (*line != 0)
        return scene_lexer_fail(&p->lx, 1, RAYO_ERR_INVALID,
                                "a second '%s' line; expected one (the "
                                "first is on line %lu)",
                                keyword, *line);
    *line = p->lx.line;
    return RAYO_OK;
}

/* Re-issues a scene error at the statement's first column. */
static rayo_status scene_failed(parser *p, const rayo_error *inner)
{
    char copy[RAYO_ERROR_MESSAGE_SIZE];
    memcpy(copy, inner->message, sizeof copy);
    return scene_lexer_fail(&p->lx, 1, inner->status, "%s", copy);
}

/* ---- camera ---------------------------------------------------------- */

static rayo_status camera_size(parser *p, rayo_camera_spec *spec,
                               const scene_word *key)
{
    unsigned long v;
    rayo_status status;
    if (scene_word_is(key, "size") || scene_word_is(key, "width")) {
        status = need_count(p, "the image width", 1, RAYO_MAX_DIMENSION, &v);
        if (status != RAYO_OK)
            return status;
        spec->width = (uint32_t)v;
    }
    if (scene_word_is(key, "size") || scene_word_is(key, "height")) {
        status =
            need_count(p, "the image height", 1, RAYO_MAX_DIMENSION, &v);
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
        rayo_status status = need_number(p, "the field of view in degrees",
                                         &spec->fov_degrees, &column);
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
        return need_vector(p, "the camera origin", &spec->origin, NULL);
    if (scene_word_is(key, "look-at")) {
        spec->aimed = 1;
        return need_vector(p, "the look-at point", &spec->look_at, NULL);
    }
    if (scene_word_is(key, "up")) {
        spec->aimed = 1;
        return need_direction(p, "the up vector", &spec->up);
    }
    {
        char text[WORD_SHOW + 32];
        return scene_lexer_fail(&p->lx, key->column, RAYO_ERR_FORMAT,
                                "%s; expected size, width, height, fov, "
                                "origin, look-at, up or the end of the "
                                "'camera' line",
                                found(key, 1, text, sizeof text));
    }
}

static rayo_status parse_camera(parser *p)
{
    rayo_camera_spec *spec = &p->file->camera;
    rayo_camera camera;
    rayo_error inner;
    scene_word key;
    rayo_status status = once(p, &p->camera_line, "camera");
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
            rayo_status status = need_number(p, "epsilon", &reading->epsilon,
                                             &column);
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
                                    found(&word, 1, text, sizeof text));
        }
    }
    return RAYO_OK;
}

static rayo_status parse_shade(parser *p)
{
    scene_word word;
    char name[32], text[WORD_SHOW + 32];
    rayo_status status = once(p, &p->shade_line, "shade");
    if (status == RAYO_OK)
        status = need_word(p, &word, "a shading mode (hit, course-gray, "
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
                                found(&word, 1, text, sizeof text));
    p->file->shade_given = 1;
    if (p->file->shade == RAYO_SHADE_COURSE_TP1)
        return tp1_readings(p, &p->file->tp1);
    return need_end(p, "shade", NULL);
}

static rayo_status parse_samples(parser *p)
{
    unsigned long v = 0;
    rayo_status status = once(p, &p->samples_line, "samples");
    if (status == RAYO_OK)
        status = need_count(p, "the samples per pixel side", 1,
                            RAYO_MAX_SAMPLES, &v);
    if (status != RAYO_OK)
        return status;
    p->file->samples = (unsigned)v;
    return need_end(p, "samples", NULL);
}

static rayo_status parse_depth(parser *p)
{
    unsigned long v = 0;
    rayo_status status = once(p, &p->depth_line, "depth");
    if (status == RAYO_OK)
        status = need_count(p, "the reflection depth", 0, RAYO_MAX_DEPTH, &v);
    if (status != RAYO_OK)
        return status;
    p->file->depth = (unsigned)v;
    return need_end(p, "depth", NULL);
}

static rayo_status parse_background(parser *p)
{
    rayo_vec3 c;
    rayo_status status = once(p, &p->background_line, "background");
    if (status == RAYO_OK)
        status = need_color(p, "the background colour", RAYO_SCENE_MAX_NUMBER,
                            &c);
    if (status != RAYO_OK)
        return status;
    rayo_scene_set_background(p->file->scene, c);
    return need_end(p, "background", NULL);
}

static rayo_status parse_ambient(parser *p)
{
    rayo_vec3 c;
    rayo_status status = once(p, &p->ambient_line, "ambient");
    if (status == RAYO_OK)
        status = need_color(p, "the ambient light", RAYO_SCENE_MAX_NUMBER, &c);
    if (status != RAYO_OK)
        return status;
    rayo_scene_set_ambient(p->file->scene, c);
    return need_end(p, "ambient", NULL);
}

/* ---- lights ---------------------------------------------------------- */

static rayo_status parse_light(parser *p)
{
    rayo_light light;
    scene_word word;
    rayo_error inner;
    char text[WORD_SHOW + 32];
    rayo_status status =
        need_word(p, &word, "the kind of light (directional or point)");
    if (status != RAYO_OK)
        return status;
    if (scene_word_is(&word, "directional")) {
        light.kind = RAYO_LIGHT_DIRECTIONAL;
        status = need_direction(p, "the direction towards the light",
                                &light.vector);
    } else if (scene_word_is(&word, "point")) {
        light.kind = RAYO_LIGHT_POINT;
        status = need_vector(p, "the light's position", &light.vector, NULL);
    } else {
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                                "%s; expected the kind of light "
                                "(directional or point)",
                                found(&word, 1, text, sizeof text));
    }
    if (status != RAYO_OK)
        return status;
    light.color = rayo_vec3_make(1, 1, 1);
    if (scene_lexer_word(&p->lx, &word)) {
        if (!scene_word_is(&word, "color"))
            return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                                    "%s; expected 'color' or the end of the "
                                    "'light' line",
                                    found(&word, 1, text, sizeof text));
        status = need_color(p, "the light's colour", RAYO_SCENE_MAX_NUMBER,
                            &light.color);
        if (status != RAYO_OK)
            return status;
    }
    status = need_end(p, "light", NULL);
    if (status != RAYO_OK)
        return status;
    if (rayo_scene_add_light(p->file->scene, &light, &inner) != RAYO_OK)
        return scene_failed(p, &inner);
    return RAYO_OK;
}

/* ---- materials ------------------------------------------------------- */

static int valid_name(const scene_word *word)
{
    size_t i;
    unsigned char c0 = (unsigned char)word->text[0];
    if (word->length > RAYO_SCENE_MAX_NAME ||
        !((c0 >= 'a' && c0 <= 'z') || (c0 >= 'A' && c0 <= 'Z') || c0 == '_'))
        return 0;
    for (i = 1; i < word->length; i++) {
        unsigned char c = (unsigned char)word->text[i];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
              (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.'))
            return 0;
    }
    return 1;
}

/* The slot that holds the name, or the empty slot where it would go.
   Names are looked up in a hash table, so 2^20 materials and 2^24
   objects naming them parse in linear time. */
static size_t *name_slot(const parser *p, const char *text, size_t length)
{
    size_t mask = p->slot_capacity - 1;
    size_t i = scene_word_hash(text, length) & mask;
    for (;; i = (i + 1) & mask) {
        const material_name *m;
        if (p->slots[i] == 0)
            return &p->slots[i];
        m = &p->names[p->slots[i] - 1];
        if (m->length == length && memcmp(m->text, text, length) == 0)
            return &p->slots[i];
    }
}

/* Doubles the table (rehashing every name) when one more name would
   fill it past half; 0 when out of memory. */
static int reserve_slot(parser *p)
{
    size_t capacity = p->slot_capacity ? 2 * p->slot_capacity : 64;
    size_t *old = p->slots;
    size_t i;
    if (2 * (p->name_count + 1) <= p->slot_capacity)
        return 1;
    if (capacity > (size_t)-1 / sizeof *p->slots)
        return 0;
    p->slots = calloc(capacity, sizeof *p->slots);
    if (p->slots == NULL) {
        p->slots = old;
        return 0;
    }
    p->slot_capacity = capacity;
    for (i = 0; i < p->name_count; i++) {
        const material_name *m = &p->names[i];
        *name_slot(p, m->text, m->length) = i + 1;
    }
    free(old);
    return 1;
}

static material_name *find_name(const parser *p, const char *text,
                                size_t length)
{
    size_t *slot;
    if (p->slot_capacity == 0)
        return NULL;
    slot = name_slot(p, text, length);
    return *slot ? &p->names[*slot - 1] : NULL;
}

static rayo_status remember_name(parser *p, const scene_word *word,
                                 unsigned id)
{
    material_name *m;
    if (!reserve_slot(p))
        return scene_lexer_fail(&p->lx, 1, RAYO_ERR_NOMEM,
                                "out of memory for material names");
    if (p->name_count == p->name_capacity) {
        size_t capacity = p->name_capacity ? 2 * p->name_capacity : 16;
        material_name *grown;
        if (capacity > (size_t)-1 / sizeof *grown)
            return scene_lexer_fail(&p->lx, 1, RAYO_ERR_NOMEM,
                                    "out of memory for material names");
        grown = realloc(p->names, capacity * sizeof *grown);
        if (grown == NULL)
            return scene_lexer_fail(&p->lx, 1, RAYO_ERR_NOMEM,
                                    "out of memory for material names");
        p->names = grown;
        p->name_capacity = capacity;
    }
    m = &p->names[p->name_count++];
    memcpy(m->text, word->text, word->length);
    m->text[word->length] = '\0';
    m->length = word->length;
    m->id = id;
    m->line = p->lx.line;
    *name_slot(p, m->text, word->length) = p->name_count;
    return RAYO_OK;
}

static rayo_status material_field(parser *p, rayo_material *m,
                                  const scene_word *key)
{
    char text[WORD_SHOW + 32];
    if (scene_word_is(key, "color"))
        return need_color(p, "the material's colour", 1.0, &m->color);
    if (scene_word_is(key, "ka"))
        return need_ranged(p, "ka", 0.0, RAYO_SCENE_MAX_NUMBER, &m->ka);
    if (scene_word_is(key, "kd"))
        return need_ranged(p, "kd", 0.0, RAYO_SCENE_MAX_NUMBER, &m->kd);
    if (scene_word_is(key, "ks"))
        return need_ranged(p, "ks", 0.0, RAYO_SCENE_MAX_NUMBER, &m->ks);
    if (scene_word_is(key, "shininess"))
        return need_ranged(p, "the shininess", 0.0, RAYO_SCENE_MAX_NUMBER,
                           &m->shininess);
    if (scene_word_is(key, "reflect"))
        return need_ranged(p, "the reflectivity", 0.0, 1.0,
                           &m->reflectivity);
    return scene_lexer_fail(&p->lx, key->column, RAYO_ERR_FORMAT,
                            "%s; expected color, ka, kd, ks, shininess, "
                            "reflect or the end of the 'material' line",
                            found(key, 1, text, sizeof text));
}

static rayo_status parse_material(parser *p)
{
    rayo_material m;
    scene_word name, key;
    rayo_error inner;
    material_name *known;
    unsigned id;
    char text[WORD_SHOW + 32];
    rayo_status status = need_word(p, &name, "a material name");
    if (status != RAYO_OK)
        return status;
    if (!valid_name(&name))
        return scene_lexer_fail(&p->lx, name.column, RAYO_ERR_FORMAT,
                                "%s; expected a material name (a letter or "
                                "'_', then letters, digits, '_', '-' or "
                                "'.'; at most %u bytes)",
                                found(&name, 1, text, sizeof text),
                                RAYO_SCENE_MAX_NAME);
    known = find_name(p, name.text, name.length);
    if (known != NULL)
        return scene_lexer_fail(&p->lx, name.column, RAYO_ERR_INVALID,
                                "material '%s' is defined again; expected a "
                                "new name (the first is on line %lu)",
                                known->text, known->line);
    m.color = rayo_vec3_make(1, 1, 1);
    m.ka = 1.0;
    m.kd = 1.0;
    m.ks = 0.0;
    m.shininess = 32.0;
    m.reflectivity = 0.0;
    while (scene_lexer_word(&p->lx, &key)) {
        status = material_field(p, &m, &key);
        if (status != RAYO_OK)
            return status;
    }
    if (rayo_scene_add_material(p->file->scene, &m, &id, &inner) != RAYO_OK)
        return scene_failed(p, &inner);
    return remember_name(p, &name, id);
}

/* ---- objects --------------------------------------------------------- */

/* The optional "material NAME" at the end of an object's line. */
static rayo_status object_material(parser *p, const char *statement,
                                   unsigned *id)
{
    scene_word word;
    material_name *m;
    char text[WORD_SHOW + 32];
    rayo_status status;
    *id = 0;
    if (!scene_lexer_word(&p->lx, &word))
        return RAYO_OK;
    if (!scene_word_is(&word, "material"))
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                                "%s; expected 'material' or the end of the "
                                "'%s' line",
                                found(&word, 1, text, sizeof text),
                                statement);
    status = need_word(p, &word, "a material name");
    if (status != RAYO_OK)
        return status;
    m = find_name(p, word.text, word.length);
    if (m == NULL)
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_INVALID,
                                "unknown material %s; expected a name "
                                "defined on an earlier 'material' line",
                                quoted(&word, text, sizeof text));
    *id = m->id;
    return need_end(p, statement, NULL);
}

static rayo_status parse_sphere(parser *p)
{
    rayo_vec3 center;
    double radius;
    size_t column = 0;
    unsigned material;
    rayo_error inner;
    rayo_status status = need_vector(p, "the sphere's centre", &center, NULL);
    if (status == RAYO_OK)
        status = need_number(p, "the sphere's radius", &radius, &column);
    if (status != RAYO_OK)
        return status;
    if (!(radius > 0.0))
        return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                "radius %g is not accepted; expected a "
                                "number > 0",
                                radius);
    status = object_material(p, "sphere", &material);
    if (status != RAYO_OK)
        return status;
    if (rayo_scene_add_sphere_material(p->file->scene, center, radius,
                                       material, &inner) != RAYO_OK)
        return scene_failed(p, &inner);
    return RAYO_OK;
}

static rayo_status parse_plane(parser *p)
{
    rayo_vec3 point, normal;
    unsigned material;
    rayo_error inner;
    rayo_status status = need_vector(p, "a point of the plane", &point, NULL);
    if (status == RAYO_OK)
        status = need_direction(p, "the plane's normal", &normal);
    if (status == RAYO_OK)
        status = object_material(p, "plane", &material);
    if (status != RAYO_OK)
        return status;
    if (rayo_scene_add_plane(p->file->scene, point, normal, material,
                             &inner) != RAYO_OK)
        return scene_failed(p, &inner);
    return RAYO_OK;
}

static rayo_status parse_triangle(parser *p)
{
    rayo_vec3 a, b, c;
    unsigned material;
    rayo_error inner;
    rayo_triangle t;
    rayo_status status = need_vector(p, "the first corner", &a, NULL);
    if (status == RAYO_OK)
        status = need_vector(p, "the second corner", &b, NULL);
    if (status == RAYO_OK)
        status = need_vector(p, "the third corner", &c, NULL);
    if (status != RAYO_OK)
        return status;
    t.a = a;
    t.b = b;
    t.c = c;
    if (!rayo_triangle_is_valid(&t))
        return scene_lexer_fail(&p->lx, 1, RAYO_ERR_INVALID,
                                "the triangle's corners are collinear; "
                                "expected three corners spanning a "
                                "triangle");
    status = object_material(p, "triangle", &material);
    if (status != RAYO_OK)
        return status;
    if (rayo_scene_add_triangle(p->file->scene, a, b, c, material, &inner) !=
        RAYO_OK)
        return scene_failed(p, &inner);
    return RAYO_OK;
}

/* ---- meshes ------------------------------------------------------------ */

/* The mesh file's path: as written when absolute, else beside the scene
 * file (the folder of its name; the current one for standard input),
 * never "-" (standard input is the scene's, not a mesh). */
static char *mesh_path(const parser *p, const scene_word *word)
{
    const char *name = p->lx.name;
    const char *slash = strrchr(name, '/');
    const char *dir_text = slash != NULL ? name : "./";
    size_t dir = word->text[0] == '/'  ? 0
                 : slash != NULL       ? (size_t)(slash - name) + 1
                                       : 2;
    char *path = malloc(dir + word->length + 1);
    if (path == NULL)
        return NULL;
    memcpy(path, dir_text, dir);
    memcpy(path + dir, word->text, word->length);
    path[dir + word->length] = '\0';
    return path;
}

/* The words after the file: scale, rotate, translate, normals, and the
 * material last. */
static rayo_status mesh_options(parser *p, rayo_mesh_placement *placement,
                                unsigned *material)
{
    static const char options[] = "scale, rotate, translate, normals, "
                                  "material or the end of the 'mesh' line";
    scene_word word;
    char text[WORD_SHOW + 32];
    rayo_status status = RAYO_OK;
    *material = 0;
    while (status == RAYO_OK) {
        size_t column = 0;
        if (!scene_lexer_word(&p->lx, &word))
            return RAYO_OK;
        if (scene_word_is(&word, "scale")) {
            status = need_number(p, "the mesh's scale", &placement->scale,
                                 &column);
            if (status == RAYO_OK && !(placement->scale > 0.0))
                return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                        "scale %g is not accepted; expected "
                                        "a number > 0",
                                        placement->scale);
        } else if (scene_word_is(&word, "rotate")) {
            status = need_vector(p, "the mesh's rotation (degrees)",
                                 &placement->rotate, NULL);
        } else if (scene_word_is(&word, "translate")) {
            status = need_vector(p, "the mesh's translation",
                                 &placement->translate, NULL);
        } else if (scene_word_is(&word, "normals")) {
            status = need_word(p, &word, "file or computed");
            if (status != RAYO_OK)
                return status;
            if (scene_word_is(&word, "file") ||
                scene_word_is(&word, "computed"))
                placement->computed_normals =
                    scene_word_is(&word, "computed");
            else
                return scene_lexer_fail(&p->lx, word.column,
                                        RAYO_ERR_FORMAT,
                                        "%s; expected file or computed",
                                        found(&word, 1, text, sizeof text));
        } else if (scene_word_is(&word, "material")) {
            /* object_material reads the keyword again. */
            p->lx.pos = (size_t)(word.text - p->lx.text);
            return object_material(p, "mesh", material);
        } else {
            return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                                    "%s; expected %s",
                                    found(&word, 1, text, sizeof text),
                                    options);
        }
    }
    return status;
}

static rayo_status parse_mesh(parser *p)
{
    scene_word word;
    rayo_mesh_placement placement;
    rayo_mesh mesh;
    rayo_mesh_report report;
    unsigned material;
    size_t left_out = 0;
    rayo_error inner;
    char *path;
    rayo_status status = need_word(p, &word, "a mesh file (STL or OBJ)");
    if (status != RAYO_OK)
        return status;
    rayo_mesh_placement_init(&placement);
    path = mesh_path(p, &word);
    if (path == NULL)
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_NOMEM,
                                "out of memory");
    status = mesh_options(p, &placement, &material);
    if (status == RAYO_OK &&
        rayo_mesh_read_file(path, &mesh, &report, &inner) != RAYO_OK)
        status = scene_lexer_fail(&p->lx, word.column, inner.status, "%s",
                                  inner.message);
    free(path);
    if (status != RAYO_OK)
        return status;
    if (rayo_scene_add_mesh(p->file->scene, &mesh, &placement, material,
                            &left_out, &inner) != RAYO_OK)
        status = scene_failed(p, &inner);
    p->file->mesh_triangles += mesh.count - left_out;
    p->file->mesh_left_out += left_out;
    p->file->mesh_ignored += report.ignored;
    rayo_mesh_free(&mesh);
    return status;
}

/* ---- statements ------------------------------------------------------ */

typedef struct statement {
    const char *keyword;
    rayo_status (*parse)(parser *p);
} statement;

/* Spheres first: a large scene is mostly their lines. */
static const statement statements[] = {
    {"sphere", parse_sphere},     {"camera", parse_camera},
    {"shade", parse_shade},
    {"samples", parse_samples},   {"depth", parse_depth},
    {"background", parse_background}, {"ambient", parse_ambient},
    {"light", parse_light},       {"material", parse_material},
    {"plane", parse_plane},       {"triangle", parse_triangle},
    {"mesh", parse_mesh},
};
#define STATEMENT_COUNT (sizeof statements / sizeof statements[0])

static rayo_status parse_statement(parser *p)
{
    scene_word word;
    char text[WORD_SHOW + 32];
    size_t i;
    scene_lexer_word(&p->lx, &word);
    for (i = 0; i < STATEMENT_COUNT; i++)
        if (scene_word_is(&word, statements[i].keyword))
            return statements[i].parse(p);
    return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                            "unknown keyword %s; expected camera, shade, "
                            "samples, depth, background, ambient, light, "
                            "material, sphere, plane, triangle or mesh",
                            quoted(&word, text, sizeof text));
}

static void file_defaults(rayo_scene_file *file)
{
    file->scene = NULL;
    rayo_camera_spec_init(&file->camera);
    file->camera_given = 0;
    file->shade = RAYO_SHADE_PHONG;
    file->shade_given = 0;
    file->samples = 1;
    file->depth = 5;
    rayo_tp1_reading_init(&file->tp1);
    file->mesh_triangles = 0;
    file->mesh_left_out = 0;
    file->mesh_ignored = 0;
}

static rayo_status parse_all(parser *p)
{
    for (;;) {
        int more = 0;
        rayo_status status = scene_lexer_next_line(&p->lx, &more);
        if (status != RAYO_OK || !more)
            return status;
        status = parse_statement(p);
        if (status != RAYO_OK)
            return status;
    }
}

/* Reads the line at offset, numbered line, as parse_all does. */
static rayo_status parse_line_at(parser *p, size_t offset,
                                 unsigned long line)
{
    int more = 0;
    rayo_status status;
    p->lx.next_line = offset;
    p->lx.line = line - 1;
    status = scene_lexer_next_line(&p->lx, &more);
    if (status != RAYO_OK || !more)
        return status;
    return parse_statement(p);
}

/* The material of a sphere read ahead (scene_file_split.c), looked up
 * by name once a part (names are never defined twice, so a name found
 * stays found): 1 with *id, or 0 when no earlier line defines it (the
 * line is then read again, to say so). */
static int read_material(const parser *p, split_part *part,
                         const split_line *l, unsigned *id)
{
    split_name *name;
    *id = 0;
    if (l->name == SPLIT_NO_NAME)
        return 1;
    name = &part->names[l->name];
    if (!name->found) {
        const material_name *m = find_name(p, name->text, name->length);
        if (m == NULL)
            return 0;
        name->id = m->id;
        name->found = 1;
    }
    *id = name->id;
    return 1;
}

/*
 * Adds the batch, the spheres of the part's lines from `first` on; when
 * the scene refuses it (the object limit, memory), nothing is added and
 * those lines are read one at a time as parse_all reads them, which says
 * which line fails.
 */
static rayo_status add_batch(parser *p, const split_part *part, size_t first)
{
    size_t j, count = p->batch_count;
    rayo_status status = RAYO_OK;
    p->batch_count = 0;
    if (count == 0 ||
        rayo_scene_add_spheres(p->file->scene, p->batch, p->batch_material,
                               count, NULL) == RAYO_OK)
        return RAYO_OK;
    for (j = first; j < first + count && status == RAYO_OK; j++)
        status = parse_line_at(p, part->lines[j].offset,
                               p->base + part->lines[j].line);
    return status;
}

/*
 * Every line of the window's parts, in order, numbered from p->base: a
 * sphere read ahead joins the batch, added when full and before any
 * other line, which is read as parse_all reads it; so the objects come
 * in file order.
 */
static rayo_status take_parts(parser *p)
{
    size_t i, j;
    for (i = 0; i < p->split.count; i++) {
        split_part *part = &p->split.parts[i];
        size_t first = 0;
        rayo_status status = RAYO_OK;
        for (j = 0; j < part->count && status == RAYO_OK; j++) {
            const split_line *l = &part->lines[j];
            unsigned id;
            if (l->sphere && read_material(p, part, l, &id)) {
                rayo_sphere *s = &p->batch[p->batch_count];
                if (p->batch_count == 0)
                    first = j;
                s->center = rayo_vec3_make(l->center[0], l->center[1],
                                           l->center[2]);
                s->radius = l->radius;
                p->batch_material[p->batch_count++] = id;
                if (p->batch_count == SPHERE_BATCH)
                    status = add_batch(p, part, first);
            } else {
                status = add_batch(p, part, first);
                if (status == RAYO_OK)
                    status = parse_line_at(p, l->offset, p->base + l->line);
            }
        }
        if (status == RAYO_OK)
            status = add_batch(p, part, first);
        if (status != RAYO_OK)
            return status;
        p->base += part->line_count;
    }
    return RAYO_OK;
}

/* ---- the reader: a file's text, a window at a time ------------------- */

struct scene_reader {
    parser p;
};

rayo_status scene_reader_new(scene_reader **result, rayo_scene_file *file,
                             const char *name, unsigned threads,
                             rayo_error *err)
{
    scene_reader *r;
    rayo_status status;
    file_defaults(file);
    *result = NULL;
    r = calloc(1, sizeof *r);
    if (r == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "%s: out of memory reading the scene", name);
    r->p.file = file;
    r->p.parts = threads ? threads : rayo_cpu_count();
    scene_lexer_init(&r->p.lx, name, "", 0, err);
    status = rayo_scene_create(&file->scene, err);
    if (status != RAYO_OK) {
        free(r);
        return status;
    }
    *result = r;
    return RAYO_OK;
}

/*
 * The window's lines, continuing the file: on several threads when it
 * is long enough (scene_file_split.h), then taken in file order; on one
 * when it is short, or when the parts cannot be made (out of memory).
 */
rayo_status scene_reader_take(scene_reader *r, const char *text,
                              size_t length)
{
    parser *p = &r->p;
    rayo_status status;
    scene_lexer_init(&p->lx, p->lx.name, text, length, p->lx.err);
    if (p->parts > 1 && length >= SCENE_SPLIT_MIN_BYTES &&
        scene_split_read(&p->split, p->lx.name, text, length, p->parts))
        return take_parts(p);
    p->lx.line = p->base;
    status = parse_all(p);
    p->base = p->lx.line;
    return status;
}

rayo_status scene_reader_end(scene_reader *r, rayo_status status)
{
    if (r == NULL)
        return status;
    scene_split_free(&r->p.split);
    free(r->p.names);
    free(r->p.slots);
    if (status != RAYO_OK)
        rayo_scene_file_free(r->p.file);
    free(r);
    return status;
}

rayo_status rayo_scene_file_parse(rayo_scene_file *file, const char *name,
                                  const char *text, size_t length,
                                  rayo_error *err)
{
    return rayo_scene_file_parse_threads(file, name, text, length, 0, err);
}

/* Whole lines of the text from `from`: about SCENE_WINDOW bytes, to just
 * after a newline (or the text's end). */
static size_t window_end(const char *text, size_t from, size_t length)
{
    const char *nl;
    if (length - from <= SCENE_WINDOW)
        return length;
    nl = memchr(text + from + SCENE_WINDOW, '\n',
                length - from - SCENE_WINDOW);
    return nl ? (size_t)(nl - text) + 1 : length;
}

rayo_status scene_file_read_text(rayo_scene_file *file, const char *name,
                                 const char *text, size_t length,
                                 unsigned threads, rayo_error *err)
{
    scene_reader *r;
    size_t from = 0;
    rayo_status status = scene_reader_new(&r, file, name, threads, err);
    if (status != RAYO_OK)
        return status;
    /* One window when it would not be split: the lexer takes any text. */
    if (r->p.parts < 2)
        status = scene_reader_take(r, text, length);
    else
        while (status == RAYO_OK && from < length) {
            size_t end = window_end(text, from, length);
            status = scene_reader_take(r, text + from, end - from);
            from = end;
        }
    return scene_reader_end(r, status);
}

rayo_status rayo_scene_file_parse_threads(rayo_scene_file *file,
                                          const char *name, const char *text,
                                          size_t length, unsigned threads,
                                          rayo_error *err)
{
    rayo_status status =
        scene_file_read_text(file, name, text, length, threads, err);
    if (status == RAYO_OK)
        status = scene_file_prepare(file, threads, err);
    return status;
}

rayo_status scene_file_prepare(rayo_scene_file *file, unsigned threads,
                               rayo_error *err)
{
    rayo_status status =
        rayo_scene_prepare_threads(file->scene, threads, err);
    if (status != RAYO_OK)
        rayo_scene_file_free(file);
    return status;
}

void rayo_scene_file_free(rayo_scene_file *file)
{
    if (file == NULL)
        return;
    rayo_scene_free(file->scene);
    file->scene = NULL;
}
