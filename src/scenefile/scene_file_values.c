/*
 * scene_file_values.c - the values a statement reads after its keyword:
 * numbers, whole numbers, vectors, directions, colours, a word that must
 * be there, the end of the line; and the messages that say precisely
 * what was found and what was expected ("FILE:LINE:COL: found 'x';
 * expected the z of the sphere's centre (a finite decimal number)").
 * Reading the digits is core/decimal.c's job, splitting the line into
 * words scene_lexer.c's; which values a statement takes is the
 * statement's (scene_file_settings.c, scene_file_objects.c,
 * scene_file_mesh.c).
 */
#include "scene_file_parser.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../core/decimal.h"
#include "rayo/lang.h"

/* The word in quotes, printable, for messages. */
const char *scene_quoted(const scene_word *word, char *buffer, size_t size)
{
    char shown[WORD_SHOW];
    snprintf(buffer, size, "'%s'",
             scene_word_show(word, shown, sizeof shown));
    return buffer;
}

/*
 * A phrase of the caller's (what a value stands for, marked with the
 * helpers' keywords in scripts/update_pot.sh) in the error's language.
 */
static const char *scene_phrase(const parser *p, const char *what)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format_arg(2)))
#endif
    ;
static const char *scene_phrase(const parser *p, const char *what)
{
    return rayo_gettext(rayo_error_lang(p->lx.err), what);
}

/* "found 'word'" or "found the end of the line" into buffer, in the
 * error's language. */
const char *scene_found(const parser *p, const scene_word *word, int have,
                        char *buffer, size_t size)
{
    rayo_lang lang = rayo_error_lang(p->lx.err);
    char q[WORD_SHOW + 4];
    if (!have)
        snprintf(buffer, size, "%s",
                 rayo_gettext(lang, "found the end of the line"));
    else
        snprintf(buffer, size, rayo_gettext(lang, "found %s"),
                 scene_quoted(word, q, sizeof q));
    return buffer;
}

/* Reads a word that must be there; what names the value expected. */
rayo_status scene_need_word(parser *p, scene_word *word, const char *what)
{
    char text[WORD_SHOW + 32];
    size_t column = scene_lexer_column(&p->lx);
    if (scene_lexer_word(&p->lx, word))
        return RAYO_OK;
    return scene_lexer_fail(&p->lx, column, RAYO_ERR_FORMAT, "%s; expected %s",
                            scene_found(p, word, 0, text, sizeof text),
                            scene_phrase(p, what));
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

static const char *number_name_text(const parser *p,
                                    const number_name *name, char *buffer,
                                    size_t size)
{
    rayo_lang lang = rayo_error_lang(p->lx.err);
    if (name->axis == 0)
        return scene_phrase(p, name->what);
    /* TRANSLATORS: %c is the axis (x, y or z), %s what the vector stands
       for ("the sphere's centre"); "%2$s, coordenada %1$c" may reorder. */
    snprintf(buffer, size, rayo_gettext(lang, "the %c of %s"), name->axis,
             scene_phrase(p, name->what));
    return buffer;
}

static rayo_status read_number(parser *p, const number_name *name,
                               double *value, size_t *column)
{
    scene_word word;
    char text[WORD_SHOW + 32], label[160], what[128];
    size_t at = scene_lexer_column(&p->lx);
    if (!scene_lexer_word(&p->lx, &word)) {
        rayo_lang lang = rayo_error_lang(p->lx.err);
        /* TRANSLATORS: %s is what the number stands for. */
        snprintf(label, sizeof label, rayo_gettext(lang, "%s (a number)"),
                 number_name_text(p, name, what, sizeof what));
        return scene_lexer_fail(&p->lx, at, RAYO_ERR_FORMAT, "%s; expected %s",
                                scene_found(p, &word, 0, text, sizeof text),
                                label);
    }
    if (column != NULL)
        *column = word.column;
    if (!word_to_double(&word, value))
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                                "%s; expected %s (a finite decimal number)",
                                scene_found(p, &word, 1, text, sizeof text),
                                number_name_text(p, name, what, sizeof what));
    if (fabs(*value) > RAYO_SCENE_MAX_NUMBER)
        return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_LIMIT,
                                "%s is out of range; expected %s between "
                                "-1e12 and 1e12",
                                scene_quoted(&word, text, sizeof text),
                                number_name_text(p, name, what, sizeof what));
    return RAYO_OK;
}

/* One number; what names it ("the sphere's radius"). */
rayo_status scene_need_number(parser *p, const char *what, double *value,
                              size_t *column)
{
    number_name name;
    name.what = what;
    name.axis = 0;
    return read_number(p, &name, value, column);
}

/* Three numbers: the x, y and z of what ("the sphere's centre"). */
rayo_status scene_need_vector(parser *p, const char *what, rayo_vec3 *v,
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
rayo_status scene_need_direction(parser *p, const char *what, rayo_vec3 *v)
{
    size_t column = 0;
    rayo_status status = scene_need_vector(p, what, v, &column);
    if (status != RAYO_OK)
        return status;
    if (v->x == 0.0 && v->y == 0.0 && v->z == 0.0)
        return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                "%s 0 0 0 has zero length; expected a "
                                "non-zero vector",
                                scene_phrase(p, what));
    return RAYO_OK;
}

/* A number in [min, max]. */
rayo_status scene_need_ranged(parser *p, const char *what, double min,
                              double max, double *value)
{
    size_t column = 0;
    rayo_status status = scene_need_number(p, what, value, &column);
    if (status != RAYO_OK)
        return status;
    if (*value < min || *value > max) {
        if (max >= RAYO_SCENE_MAX_NUMBER)
            return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                    "%s %g is not accepted; expected a "
                                    "number >= %g",
                                    scene_phrase(p, what), *value, min);
        return scene_lexer_fail(&p->lx, column, RAYO_ERR_INVALID,
                                "%s %g is not accepted; expected a number "
                                "from %g to %g",
                                scene_phrase(p, what), *value, min, max);
    }
    return RAYO_OK;
}

/* A whole number in [min, max]. */
rayo_status scene_need_count(parser *p, const char *what, unsigned long min,
                             unsigned long max, unsigned long *value)
{
    size_t column = 0;
    double v;
    rayo_status status = scene_need_number(p, what, &v, &column);
    if (status != RAYO_OK)
        return status;
    if (v != floor(v))
        return scene_lexer_fail(&p->lx, column, RAYO_ERR_FORMAT,
                                "%s %g is not a whole number; expected %lu "
                                "to %lu",
                                scene_phrase(p, what), v, min, max);
    if (v < (double)min || v > (double)max)
        return scene_lexer_fail(&p->lx, column, RAYO_ERR_LIMIT,
                                "%s %g is out of range; expected %lu to %lu",
                                scene_phrase(p, what), v, min, max);
    *value = (unsigned long)v;
    return RAYO_OK;
}

/*
 * A colour: one number (a gray, copied to all three channels) or three.
 * Each channel must lie in [0, max].
 */
rayo_status scene_need_color(parser *p, const char *what, double max,
                             rayo_vec3 *color)
{
    double c[3];
    int i;
    rayo_status status = scene_need_ranged(p, what, 0.0, max, &c[0]);
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
        status = scene_need_ranged(p, what, 0.0, max, &c[i]);
        if (status != RAYO_OK)
            return status;
    }
    *color = rayo_vec3_make(c[0], c[1], c[2]);
    return RAYO_OK;
}

rayo_status scene_need_end(parser *p, const char *statement,
                           const char *options)
{
    scene_word word;
    char text[WORD_SHOW + 32];
    if (!scene_lexer_word(&p->lx, &word))
        return RAYO_OK;
    return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                            "%s; expected %s%sthe end of the '%s' line",
                            scene_found(p, &word, 1, text, sizeof text),
                            options ? options : "", options ? " or " : "",
                            statement);
}

/* A statement that may appear once: fails on the second. */
rayo_status scene_once(parser *p, unsigned long *line, const char *keyword)
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
rayo_status scene_failed(parser *p, const rayo_error *inner)
{
    char copy[RAYO_ERROR_MESSAGE_SIZE];
    memcpy(copy, inner->message, sizeof copy);
    return scene_lexer_fail(&p->lx, 1, inner->status, "%s", copy);
}
