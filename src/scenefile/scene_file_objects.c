/*
 * scene_file_objects.c - the statements that fill the scene: light,
 * material (its name kept in a hash table, so that millions of objects
 * naming a million materials parse in linear time), sphere, plane and
 * triangle, each turned into a call on the scene (scene.h) whose
 * refusals are re-issued at the statement's line.  A large file's clean
 * sphere lines are also read ahead on several threads
 * (scene_file_split.c, taken in order by scene_file.c); the sphere
 * statement here reads every other one, and the two keep one rule.
 */
#include "scene_file_parser.h"

#include <stdlib.h>
#include <string.h>

/* ---- lights ---------------------------------------------------------- */

rayo_status scene_parse_light(parser *p)
{
    rayo_light light;
    scene_word word;
    rayo_error inner = RAYO_ERROR_INIT(rayo_error_lang(p->lx.err));
    char text[WORD_SHOW + 32];
    rayo_status status =
        scene_need_word(p, &word, "the kind of light (directional or point)");
    if (status != RAYO_OK)
        return status;
    if (scene_word_is(&word, "directional")) {
        light.kind = RAYO_LIGHT_DIRECTIONAL;
        status = scene_need_direction(p, "the direction towards the light",
                                      &light.vector);
    } else if (scene_word_is(&word, "point")) {
        light.kind = RAYO_LIGHT_POINT;
        status =
            scene_need_vector(p, "the light's position", &light.vector, NULL);
    } else {
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                                "%s; expected the kind of light "
                                "(directional or point)",
                                scene_found(p, &word, 1, text, sizeof text));
    }
    if (status != RAYO_OK)
        return status;
    light.color = rayo_vec3_make(1, 1, 1);
    if (scene_lexer_word(&p->lx, &word)) {
        if (!scene_word_is(&word, "color"))
            return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                                    "%s; expected 'color' or the end of the "
                                    "'light' line",
                                    scene_found(p, &word, 1, text,
                                                sizeof text));
        status = scene_need_color(p, "the light's colour",
                                  RAYO_SCENE_MAX_NUMBER, &light.color);
        if (status != RAYO_OK)
            return status;
    }
    status = scene_need_end(p, "light", NULL);
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

material_name *scene_find_name(const parser *p, const char *text,
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
        return scene_need_color(p, "the material's colour", 1.0, &m->color);
    if (scene_word_is(key, "ka"))
        return scene_need_ranged(p, "ka", 0.0, RAYO_SCENE_MAX_NUMBER, &m->ka);
    if (scene_word_is(key, "kd"))
        return scene_need_ranged(p, "kd", 0.0, RAYO_SCENE_MAX_NUMBER, &m->kd);
    if (scene_word_is(key, "ks"))
        return scene_need_ranged(p, "ks", 0.0, RAYO_SCENE_MAX_NUMBER, &m->ks);
    if (scene_word_is(key, "shininess"))
        return scene_need_ranged(p, "the shininess", 0.0,
                                 RAYO_SCENE_MAX_NUMBER, &m->shininess);
    if (scene_word_is(key, "reflect"))
        return scene_need_ranged(p, "the reflectivity", 0.0, 1.0,
                                 &m->reflectivity);
    return scene_lexer_fail(&p->lx, key->column, RAYO_ERR_FORMAT,
                            "%s; expected color, ka, kd, ks, shininess, "
                            "reflect or the end of the 'material' line",
                            scene_found(p, key, 1, text, sizeof text));
}

rayo_status scene_parse_material(parser *p)
{
    rayo_material m;
    scene_word name, key;
    rayo_error inner = RAYO_ERROR_INIT(rayo_error_lang(p->lx.err));
    material_name *known;
    unsigned id;
    char text[WORD_SHOW + 32];
    rayo_status status = scene_need_word(p, &name, "a material name");
    if (status != RAYO_OK)
        return status;
    if (!valid_name(&name))
        return scene_lexer_fail(&p->lx, name.column, RAYO_ERR_FORMAT,
                                "%s; expected a material name (a letter or "
                                "'_', then letters, digits, '_', '-' or "
                                "'.'; at most %u bytes)",
                                scene_found(p, &name, 1, text, sizeof text),
                                RAYO_SCENE_MAX_NAME);
    known = scene_find_name(p, name.text, name.length);
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
rayo_status scene_object_material(parser *p, const char *statement,
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
                                scene_found(p, &word, 1, text, sizeof text),
                                statement);
    status = scene_need_word(p, &word, "a material name");
    if (status != RAYO_OK)
        return status;
    m = scene_find_name(p, word.text, word.length);
    if (m == NULL)
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_INVALID,
                                "unknown material %s; expected a name "
                                "defined on an earlier 'material' line",
                                scene_quoted(&word, text, sizeof text));
    *id = m->id;
    return scene_need_end(p, statement, NULL);
}

rayo_status scene_parse_sphere(parser *p)
{
    rayo_vec3 center;
    double radius;
    size_t column = 0;
    unsigned material;
    rayo_error inner = RAYO_ERROR_INIT(rayo_error_lang(p->lx.err));
    rayo_status status =
        scene_need_vector(p, "the sphere's centre", &center, NULL);
    if (status == RAYO_OK)
        status = scene_need_number(p, "the sphere's radius", &radius, &column);
    if (status != RAYO_OK)
        return status;
    if (!(radius > 0.0))
        return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                "radius %g is not accepted; expected a "
                                "number > 0",
                                radius);
    status = scene_object_material(p, "sphere", &material);
    if (status != RAYO_OK)
        return status;
    if (rayo_scene_add_sphere_material(p->file->scene, center, radius,
                                       material, &inner) != RAYO_OK)
        return scene_failed(p, &inner);
    return RAYO_OK;
}

rayo_status scene_parse_plane(parser *p)
{
    rayo_vec3 point, normal;
    unsigned material;
    rayo_error inner = RAYO_ERROR_INIT(rayo_error_lang(p->lx.err));
    rayo_status status =
        scene_need_vector(p, "a point of the plane", &point, NULL);
    if (status == RAYO_OK)
        status = scene_need_direction(p, "the plane's normal", &normal);
    if (status == RAYO_OK)
        status = scene_object_material(p, "plane", &material);
    if (status != RAYO_OK)
        return status;
    if (rayo_scene_add_plane(p->file->scene, point, normal, material,
                             &inner) != RAYO_OK)
        return scene_failed(p, &inner);
    return RAYO_OK;
}

rayo_status scene_parse_triangle(parser *p)
{
    rayo_vec3 a, b, c;
    unsigned material;
    rayo_error inner = RAYO_ERROR_INIT(rayo_error_lang(p->lx.err));
    rayo_triangle t;
    rayo_status status = scene_need_vector(p, "the first corner", &a, NULL);
    if (status == RAYO_OK)
        status = scene_need_vector(p, "the second corner", &b, NULL);
    if (status == RAYO_OK)
        status = scene_need_vector(p, "the third corner", &c, NULL);
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
    status = scene_object_material(p, "triangle", &material);
    if (status != RAYO_OK)
        return status;
    if (rayo_scene_add_triangle(p->file->scene, a, b, c, material, &inner) !=
        RAYO_OK)
        return scene_failed(p, &inner);
    return RAYO_OK;
}
