/*
 * tp1_source.c - what TP1's statement fixes in the sources, read from
 * the submission's .c and .h files (comments and string literals blanked
 * out, spaces normalised): the two prototypes it gives verbatim,
 * objeto_distancia and computar_intensidad (with profundidad), must be
 * there exactly; and the lookup-table rule (no switch or if on the
 * geometry's kind to choose a function) is looked for and, where broken,
 * reported as a note for the teacher, who judges the design: it fails
 * nothing.  A prototype is its return type and its parameters' types:
 * the parameters' names do not change a C function's type, so another
 * name (nivel for profundidad) is the statement's prototype.
 *
 * A reading of the text, not a compilation: it does not call the
 * functions (the harness that would is not written yet).
 */
#define _POSIX_C_SOURCE 200809L

#include <ctype.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grade_impl.h"
#include "tp1.h"

#define SOURCE_BYTES ((uint64_t)4 << 20)

static const char *const prototypes[][2] = {
    {"objeto_distancia",
     "float objeto_distancia(const objeto_t *objeto, vector_t o, "
     "vector_t d, vector_t *punto, vector_t *normal)"},
    {"computar_intensidad",
     "color_t computar_intensidad(int profundidad, const arreglo_t "
     "*objetos, const arreglo_t *luces, color_t ambiente, vector_t o, "
     "vector_t d)"}};
#define PROTOTYPES (sizeof prototypes / sizeof prototypes[0])

static int word_char(int c)
{
    return isalnum((unsigned char)c) || c == '_';
}

/* Comments, string and character literals and preprocessor lines become
   spaces; newlines stay, so that lines keep their numbers. */
static void blank(char *s)
{
    char *p = s;
    while (*p != '\0') {
        if (p[0] == '/' && p[1] == '*') {
            for (; *p != '\0' && !(p[0] == '*' && p[1] == '/'); p++)
                if (*p != '\n')
                    *p = ' ';
            if (*p != '\0') {
                p[0] = p[1] = ' ';
                p += 2;
            }
        } else if (p[0] == '/' && p[1] == '/') {
            for (; *p != '\0' && *p != '\n'; p++)
                *p = ' ';
        } else if (*p == '"' || *p == '\'') {
            char quote = *p;
            *p++ = ' ';
            for (; *p != '\0' && *p != quote && *p != '\n'; p++) {
                if (*p == '\\' && p[1] != '\0' && p[1] != '\n')
                    *p++ = ' ';
                *p = ' ';
            }
            if (*p == quote)
                *p++ = ' ';
        } else
            p++;
    }
}

/* The text with spaces only between two word characters, one each. */
static char *squeeze(const char *s)
{
    char *out = malloc(strlen(s) + 1), *q = out;
    int space = 0;
    if (out == NULL)
        return NULL;
    for (; *s != '\0'; s++) {
        if (isspace((unsigned char)*s)) {
            space = 1;
            continue;
        }
        if (space && q > out && word_char(q[-1]) && word_char(*s))
            *q++ = ' ';
        space = 0;
        *q++ = *s;
    }
    *q = '\0';
    return out;
}

/* A switch or an if on the kind of geometry, in one file's blanked text:
   its line, or 0. */
static unsigned kind_condition(const char *text, char *shown, size_t room)
{
    const char *p;
    static const char *const keys[] = {"switch", "if"};
    size_t k;
    for (p = text; *p != '\0'; p++) {
        if (p > text && word_char(p[-1]))
            continue;
        for (k = 0; k < 2; k++) {
            size_t n = strlen(keys[k]), depth = 0, length;
            const char *q = p + n, *open;
            char *cond;
            if (strncmp(p, keys[k], n) != 0 || word_char(*q))
                continue;
            while (isspace((unsigned char)*q))
                q++;
            if (*q != '(')
                continue;
            for (open = q; *q != '\0'; q++) {
                depth += *q == '(';
                if (*q == ')' && --depth == 0)
                    break;
            }
            length = (size_t)(q - open);
            cond = malloc(length + 1);
            if (cond == NULL)
                return 0;
            memcpy(cond, open, length);
            cond[length] = '\0';
            if ((strstr(cond, "geometr") != NULL ||
                 strstr(cond, "tipo") != NULL) &&
                (k == 0 || strstr(cond, "==") != NULL)) {
                const char *c;
                unsigned line = 1;
                char *tidy = squeeze(cond);
                snprintf(shown, room, "%s %.60s)", keys[k],
                         tidy != NULL ? tidy : "(");
                free(tidy);
                free(cond);
                for (c = text; c < p; c++)
                    line += *c == '\n';
                return line;
            }
            free(cond);
        }
    }
    return 0;
}

/* The next prototype of the function called name in text (squeezed),
   from *cursor on, with its parameters' names left out:
   "float(const objeto_t*,vector_t,...)" for "float objeto_distancia(const
   objeto_t *objeto, vector_t o, ...": into out (room bytes), 1 when one
   was found (a name followed by a parameter list and preceded by a word:
   a call's "return" too, which then matches no prototype), 0 at the
   end. */
static int next_type(const char *text, const char **cursor,
                     const char *name, char *out, size_t room)
{
    size_t n = strlen(name), used;
    const char *at, *ret, *p;
    int depth = 0;
    for (at = *cursor; (at = strstr(at, name)) != NULL; at += n) {
        if ((at > text && word_char(at[-1])) || at[n] != '(')
            continue;
        ret = at - (at > text && at[-1] == ' ');
        for (p = ret; p > text && word_char(p[-1]); p--)
            ;
        if (p != ret && (size_t)(ret - p) + 2 < room)
            break;
    }
    if (at == NULL)
        return 0;
    *cursor = at + n;
    used = (size_t)(ret - p);
    memcpy(out, p, used);
    /* Each parameter copied without its last word when that is a name:
       a word after a type's word or its '*', ending the parameter. */
    for (p = at + n; *p != '\0' && used + 2 < room; p++) {
        depth += *p == '(';
        depth -= *p == ')';
        if (word_char(*p) && (p[-1] == ' ' || p[-1] == '*')) {
            const char *e = p;
            while (word_char(*e))
                e++;
            if (depth == 1 && (*e == ',' || *e == ')') &&
                strncmp(p, "const", 5) != 0) {
                if (out[used - 1] == ' ')
                    used--;
                p = e - 1;
                continue;
            }
        }
        out[used++] = *p;
        if (depth == 0)
            break;
    }
    out[used] = '\0';
    return 1;
}

/* 1 when text declares or defines name with the type want. */
static int has_type(const char *text, const char *name, const char *want)
{
    const char *cursor = text;
    char type[256];
    while (next_type(text, &cursor, name, type, sizeof type))
        if (strcmp(type, want) == 0)
            return 1;
    return 0;
}

static int is_source(const char *name)
{
    size_t n = strlen(name);
    return name[0] != '.' && n > 2 && name[n - 2] == '.' &&
           (name[n - 1] == 'c' || name[n - 1] == 'h');
}

rayo_status grade_tp1_sources(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    DIR *d = opendir(ctx->work);
    struct dirent *entry;
    int found[PROTOTYPES] = {0}, named[PROTOTYPES] = {0};
    char *wanted[PROTOTYPES] = {NULL};
    char want_type[PROTOTYPES][256] = {{0}};
    size_t i;
    rayo_status status = RAYO_OK;
    if (d == NULL)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: cannot be read",
                              ctx->work);
    for (i = 0; i < PROTOTYPES; i++)
        if ((wanted[i] = squeeze(prototypes[i][1])) == NULL)
            status = rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of "
                                                         "memory");
        else {
            const char *cursor = wanted[i];
            next_type(wanted[i], &cursor, prototypes[i][0], want_type[i],
                      sizeof want_type[i]);
        }
    item->result = RAYO_GRADE_PASS;
    while (status == RAYO_OK && (entry = readdir(d)) != NULL) {
        char *path, *text = NULL, *tight;
        size_t size;
        char shown[96];
        unsigned line;
        if (!is_source(entry->d_name))
            continue;
        path = grade_path_join(ctx->work, entry->d_name);
        if (path == NULL ||
            grade_read_file(path, SOURCE_BYTES, &text, &size, err) != RAYO_OK) {
            free(path);
            continue;
        }
        free(path);
        blank(text);
        tight = squeeze(text);
        for (i = 0; tight != NULL && i < PROTOTYPES; i++) {
            named[i] |= strstr(tight, wanted[i]) != NULL;
            found[i] |= has_type(tight, prototypes[i][0], want_type[i]);
        }
        line = entry->d_name[strlen(entry->d_name) - 1] == 'c'
                   ? kind_condition(text, shown, sizeof shown)
                   : 0;
        if (line > 0)
            status = grade_say(item, err,
                               "note: %s:%u chooses by the geometry's kind "
                               "with '%s'; the statement asks for lookup "
                               "tables (arrays of functions indexed by the "
                               "kind), for the teacher to judge",
                               entry->d_name, line, shown);
        free(tight);
        free(text);
    }
    closedir(d);
    if (status == RAYO_OK)
        rayo_error_clear(err);
    for (i = 0; status == RAYO_OK && i < PROTOTYPES; i++)
        status = found[i] && named[i]
                     ? grade_say(item, err, "%s has the statement's prototype",
                                 prototypes[i][0])
                 : found[i]
                     ? grade_say(item, err,
                                 "%s has the statement's prototype, with "
                                 "other names for its parameters (the names "
                                 "do not change a function's type): %s",
                                 prototypes[i][0], prototypes[i][1])
                          : grade_fail(item, err,
                                       "no %s with the statement's "
                                       "prototype, %s",
                                       prototypes[i][0], prototypes[i][1]);
    for (i = 0; i < PROTOTYPES; i++)
        free(wanted[i]);
    return status;
}
