/*
 * ej3_probe.c - Ejercicio obligatorio 3's types and signatures, probed
 * before anything is called: each type must exist as a typedef with
 * the statement's members, types and layout (_Generic and offsetof
 * against a copy of the statement's struct; the compiler's message
 * names the member); then the prototypes, declared after the student's
 * #include, where a different definition is "conflicting types".  A
 * function is called only when its signature and every type it uses
 * are the statement's.
 */
#define _POSIX_C_SOURCE 200809L

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ej3.h"

/* ---- the statement's types ---- */


static const char *const type_names[T_COUNT] = {
    "vector_t", "color_t", "esfera_t", "luz_t", "arreglo_t"};

static const char *const type_texts[T_COUNT] = {
    "typedef struct { float x, y, z; } vector_t;",
    "typedef struct { float r, g, b; } color_t;",
    "typedef struct { vector_t centro; float radio; color_t color; "
    "float ka, kd; } esfera_t;",
    "typedef struct { vector_t posicion; color_t color; bool es_puntual; } "
    "luz_t;",
    "typedef struct { void **v; size_t n; } arreglo_t;"};

/* Each type's members: name and type as _Generic spells it. */
typedef struct member {
    const char *name, *type;
} member;

static const member members[T_COUNT][5] = {
    {{"x", "float"}, {"y", "float"}, {"z", "float"}},
    {{"r", "float"}, {"g", "float"}, {"b", "float"}},
    {{"centro", "vector_t"},
     {"radio", "float"},
     {"color", "color_t"},
     {"ka", "float"},
     {"kd", "float"}},
    {{"posicion", "vector_t"}, {"color", "color_t"}, {"es_puntual", "_Bool"}},
    {{"v", "void **"}, {"n", "size_t"}}};

/* The harness's (and the probe's mirror) definitions. */
static const char mirror_types[] =
    "struct rayo_vector_t { float x, y, z; };\n"
    "struct rayo_color_t { float r, g, b; };\n"
    "struct rayo_esfera_t { struct rayo_vector_t centro; float radio;\n"
    "    struct rayo_color_t color; float ka, kd; };\n"
    "struct rayo_luz_t { struct rayo_vector_t posicion;\n"
    "    struct rayo_color_t color; _Bool es_puntual; };\n"
    "struct rayo_arreglo_t { void **v; size_t n; };\n";

/* The prototype with bool spelled _Bool (the student may not include
   <stdbool.h> before a declaration of ours). */
static void put_prototype(harness_text *t, unsigned f, const char *suffix)
{
    const char *p = ej3_functions[f].prototype, *b;
    while ((b = strstr(p, "bool ")) != NULL &&
           (b == p || b[-1] == ' ' || b[-1] == '(')) {
        harness_append(t, "%.*s_Bool ", (int)(b - p), p);
        p = b + 5;
    }
    harness_append(t, "%s%s;\n", p, suffix);
}

/* ---- probing the types and the signatures ---- */

enum { TYPE_MISSING, TYPE_OK, TYPE_WRONG };

/* The probe text after the #include for type t. */
static void type_probe(harness_text *t, unsigned type)
{
    const char *name = type_names[type];
    unsigned i;
    harness_append(t, "\n%stypedef %s rayo_probe_type;\n", mirror_types,
                   name);
    for (i = 0; i < 5 && members[type][i].name != NULL; i++)
        harness_append(t, "typedef char rayo_check_%s_%s[_Generic(((%s *)0)"
                          "->%s, %s: 1, default: -1)];\n",
                       name, members[type][i].name, name,
                       members[type][i].name, members[type][i].type);
    harness_append(t, "typedef char rayo_layout_%s[sizeof(%s) == "
                      "sizeof(struct rayo_%s)",
                   name, name, name);
    for (i = 0; i < 5 && members[type][i].name != NULL; i++)
        harness_append(t, " && offsetof(%s, %s) == offsetof(struct rayo_%s, "
                          "%s)",
                       name, members[type][i].name, name,
                       members[type][i].name);
    harness_append(t, " ? 1 : -1];\n");
}

/* Probes the types in source i: state[t] for each. */
static rayo_status probe_types(grade_context *ctx, size_t i, int *state,
                               char reasons[][HARNESS_REASON],
                               rayo_error *err)
{
    unsigned t;
    rayo_status status = RAYO_OK;
    for (t = 0; t < T_COUNT && status == RAYO_OK; t++) {
        harness_text text = {NULL, 0, 0, 0};
        char reason[HARNESS_REASON];
        int ok;
        if ((t == T_ESFERA || t == T_LUZ) &&
            (state[T_VECTOR] != TYPE_OK || state[T_COLOR] != TYPE_OK)) {
            state[t] = TYPE_MISSING;
            snprintf(reasons[t], HARNESS_REASON, "it uses vector_t and "
                                                 "color_t");
            continue;
        }
        type_probe(&text, t);
        if (text.failed) {
            free(text.data);
            return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
        }
        status = harness_probe(ctx, i, "#include <stddef.h>\n", text.data,
                               &ok, reason, sizeof reason, err);
        free(text.data);
        if (status != RAYO_OK)
            break;
        if (ok) {
            state[t] = TYPE_OK;
        } else {
            /* gcc: unknown type name; clang: also "must use 'struct'
               tag" for a struct of that name without its typedef. */
            state[t] = strstr(reason, "unknown type name") != NULL ||
                               strstr(reason, "undeclared") != NULL ||
                               strstr(reason, "must use 'struct'") != NULL
                           ? TYPE_MISSING
                           : TYPE_WRONG;
            memcpy(reasons[t], reason, sizeof reason);
        }
    }
    return status;
}

static rayo_status say_type(rayo_grade_item *item, unsigned t, int state,
                            const char *reason, rayo_error *err)
{
    const char *p = strstr(reason, "rayo_check_");
    char member_name[32] = "";
    if (state == TYPE_MISSING)
        return grade_fail(item, err, "%s: not defined as the statement's "
                                     "type (the compiler says: %s); the "
                                     "statement gives %s (a struct declared "
                                     "without the typedef is struct NAME, "
                                     "not %s)",
                          type_names[t], reason, type_texts[t],
                          type_names[t]);
    if (p != NULL &&
        sscanf(p + strlen("rayo_check_") + strlen(type_names[t]) + 1,
               "%31[a-z_]", member_name) == 1)
        return grade_fail(item, err, "%s: its member %s is not of the "
                                     "statement's type; the statement gives "
                                     "%s",
                          type_names[t], member_name, type_texts[t]);
    if (strstr(reason, "rayo_layout_") != NULL)
        return grade_fail(item, err, "%s: its members are not the "
                                     "statement's, in its order; the "
                                     "statement gives %s",
                          type_names[t], type_texts[t]);
    return grade_fail(item, err, "%s: differs from the statement's %s (the "
                                 "compiler says: %s)",
                      type_names[t], type_texts[t], reason);
}

/* Probes the prototypes of the functions in which[] in source i. */
static rayo_status probe_functions(grade_context *ctx, size_t i,
                                   const unsigned *which, size_t count,
                                   int *ok, char *reason, rayo_error *err)
{
    harness_text t = {NULL, 0, 0, 0};
    char *messages = NULL, type[200];
    size_t k;
    rayo_status status;
    harness_append(&t, "\n");
    for (k = 0; k < count; k++)
        put_prototype(&t, which[k], "");
    if (t.failed) {
        free(t.data);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    status = harness_probe_full(ctx, i, "#include <stddef.h>\n", t.data,
                                ok, reason, HARNESS_REASON, &messages, err);
    /* Our declaration comes second, so the compiler's "have" is ours;
       the student's type is in its note, when it gives one. */
    if (status == RAYO_OK && !*ok && count == 1) {
        char said[HARNESS_REASON];
        harness_previous_type(messages, ej3_functions[which[0]].name, type,
                              sizeof type);
        if (strstr(reason, "; have ") != NULL)
            *strstr(reason, "; have ") = '\0';
        memcpy(said, reason, sizeof said);
        if (type[0] != '\0')
            snprintf(reason, HARNESS_REASON, "the file has %s", type);
        else {
            harness_shorten(said, 300);
            snprintf(reason, HARNESS_REASON, "the compiler says: %s", said);
        }
    }
    free(messages);
    free(t.data);
    return status;
}

typedef struct probing {
    int type_state[T_COUNT];
    char type_reasons[T_COUNT][HARNESS_REASON];
    int usable[F_COUNT];
    char reasons[F_COUNT][HARNESS_REASON]; /* "" when usable */
} probing;

static rayo_status probe_all(grade_context *ctx, probing *p,
                             rayo_error *err)
{
    int state[T_COUNT];
    char reasons[T_COUNT][HARNESS_REASON];
    unsigned f, t, which[F_COUNT];
    size_t i, n;
    int ok;
    rayo_status status = RAYO_OK;
    memset(p, 0, sizeof *p);
    for (i = 0; i < ctx->source_count && status == RAYO_OK; i++) {
        status = probe_types(ctx, i, state, reasons, err);
        for (t = 0; t < T_COUNT && status == RAYO_OK; t++) {
            if (state[t] == TYPE_WRONG ||
                (state[t] == TYPE_OK && p->type_state[t] == TYPE_MISSING) ||
                (i == 0 && state[t] == TYPE_MISSING)) {
                if (p->type_state[t] != TYPE_WRONG) {
                    p->type_state[t] = state[t];
                    memcpy(p->type_reasons[t], reasons[t],
                           sizeof reasons[t]);
                }
            }
        }
    }
    for (f = 0; f < F_COUNT; f++) {
        p->usable[f] = 1;
        for (t = 0; t < T_COUNT; t++)
            if ((ej3_function_types[f] & TB(t)) &&
                p->type_state[t] != TYPE_OK)
                p->usable[f] = 0;
    }
    /* The signatures, in the sources where their types are visible:
       one probe for all, one each when that fails. */
    for (i = 0; i < ctx->source_count && status == RAYO_OK; i++) {
        status = probe_types(ctx, i, state, reasons, err);
        n = 0;
        for (f = 0; f < F_COUNT && status == RAYO_OK; f++) {
            int visible = p->usable[f];
            for (t = 0; t < T_COUNT; t++)
                if ((ej3_function_types[f] & TB(t)) && state[t] != TYPE_OK)
                    visible = 0;
            if (visible)
                which[n++] = f;
        }
        if (status != RAYO_OK || n == 0)
            continue;
        status = probe_functions(ctx, i, which, n, &ok, p->reasons[0], err);
        p->reasons[0][0] = '\0';
        for (f = 0; f < n && status == RAYO_OK && !ok; f++) {
            int one;
            status = probe_functions(ctx, i, &which[f], 1, &one,
                                     p->reasons[which[f]], err);
            if (status == RAYO_OK && !one)
                p->usable[which[f]] = 0;
            else if (status == RAYO_OK)
                p->reasons[which[f]][0] = '\0';
        }
    }
    return status;
}

/* The report of the probes: types first, then the functions not called
   because of a type, then each wrong signature. */
static rayo_status say_probes(rayo_grade_item *item, const probing *p,
                              rayo_error *err)
{
    harness_text list = {NULL, 0, 0, 0};
    unsigned t, f, bad_types = 0;
    rayo_status status = RAYO_OK;
    for (t = 0; t < T_COUNT && status == RAYO_OK; t++) {
        if (p->type_state[t] == TYPE_OK)
            continue;
        bad_types |= TB(t);
        if ((t == T_ESFERA || t == T_LUZ) &&
            (p->type_state[T_VECTOR] != TYPE_OK ||
             p->type_state[T_COLOR] != TYPE_OK))
            continue; /* not checkable; said with vector_t or color_t */
        status = say_type(item, t, p->type_state[t], p->type_reasons[t],
                          err);
    }
    for (f = 0; f < F_COUNT; f++)
        if (ej3_function_types[f] & bad_types)
            harness_append(&list, "%s%s", list.length > 0 ? ", " : "",
                           ej3_functions[f].name);
    if (list.failed)
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    else if (status == RAYO_OK && list.length > 0)
        status = grade_fail(item, err, "not called, as they use a type that "
                                       "is not the statement's: %s",
                            list.data);
    free(list.data);
    for (f = 0; f < F_COUNT && status == RAYO_OK; f++)
        if (!p->usable[f] && !(ej3_function_types[f] & bad_types))
            status = grade_fail(item, err, "%s: the signature differs from "
                                           "the statement's %s (%s); not "
                                           "called",
                                ej3_functions[f].name,
                                    ej3_functions[f].prototype,
                                p->reasons[f]);
    return status;
}

/* The exercise's own probe: types, then signatures; its findings
   said, the functions to call in usable. */
rayo_status ej3_probe(grade_context *ctx, int *usable, rayo_error *err)
{
    probing *p = malloc(sizeof *p);
    unsigned f;
    rayo_status status;
    if (p == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    status = probe_all(ctx, p, err);
    for (f = 0; f < F_COUNT; f++)
        usable[f] = p->usable[f];
    if (status == RAYO_OK)
        status = say_probes(&ctx->report->items[RAYO_GRADE_FUNCTIONS], p,
                            err);
    free(p);
    return status;
}

